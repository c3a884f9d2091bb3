//! `postc.toml`: the severity of diagnostics a project chooses, in the
//! post's folder or the nearest folder above it:
//!
//! ```toml
//! [diagnostics]
//! deny = ["PP021"]       # an error: postc check fails, postc post writes nothing
//! warn = ["LN"]          # a prefix: every lint stays a warning
//! allow = ["LN002"]      # hidden
//!
//! [posts]
//! dirs = ["posts", "/shop/posts"]   # the user's post folders (docs/posts.md)
//! ```
//!
//! The command line (`--warn`, `--deny`, `--allow`) wins over the file.
//! The file is read through the [`SourceLoader`] the caller gives, so the
//! command line and the language server read it the same way.

use std::path::{Path, PathBuf};

use postc_ir::codes::{self, Level, LevelRules};
use postc_ir::{Diagnostic, SourceLoader};

/// The file's contents.
#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Config {
    #[serde(default)]
    diagnostics: Lists,
    #[serde(default)]
    posts: Posts,
}

/// The `[posts]` table: the user's post folders.
#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Posts {
    #[serde(default)]
    dirs: Vec<String>,
}

#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Lists {
    #[serde(default)]
    warn: Vec<String>,
    #[serde(default)]
    deny: Vec<String>,
    #[serde(default)]
    allow: Vec<String>,
}

/// The nearest `postc.toml` in the folder of `file` (an absolute path) or
/// a folder above it.
pub fn find(loader: &dyn SourceLoader, file: &Path) -> Option<PathBuf> {
    file.ancestors().skip(1).map(|dir| dir.join("postc.toml")).find(|p| loader.is_file(p))
}

/// Adds the lists in order allow, warn, deny: within one source, for one
/// selector, deny wins over warn over allow.
pub fn add_lists(rules: &mut LevelRules, lists: [(&[String], Level); 3], rank: u8) -> Result<(), String> {
    for (list, level) in lists {
        for selector in list {
            rules.add(selector, level, rank)?;
        }
    }
    Ok(())
}

/// The rules of the `postc.toml` that applies to `file` (an absolute
/// path), at rank 0; none when there is no such file.
pub fn rules_for(loader: &dyn SourceLoader, file: &Path) -> Result<LevelRules, Diagnostic> {
    let mut rules = LevelRules::default();
    let Some(config) = find(loader, file) else { return Ok(rules) };
    let name = config.display().to_string();
    let d = read(loader, &config)?.diagnostics;
    add_lists(&mut rules, [(&d.allow, Level::Allow), (&d.warn, Level::Warn), (&d.deny, Level::Deny)], 0)
        .map_err(|e| Diagnostic::error(codes::IO007, format!("`{name}`: {e}")))?;
    Ok(rules)
}

/// The file at `config`, read.
fn read(loader: &dyn SourceLoader, config: &Path) -> Result<Config, Diagnostic> {
    let name = config.display().to_string();
    let bytes =
        loader.read(config).map_err(|e| Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}")))?;
    let text = String::from_utf8_lossy(&bytes);
    toml::from_str(&text)
        .map_err(|e| Diagnostic::error(codes::IO007, format!("`{name}` does not read: {}", e.message())))
}

/// The post folders of the `postc.toml` that applies to `file` (an
/// absolute path): its `[posts] dirs`, each relative to the file's own
/// folder unless absolute, in the file's order; none when there is no
/// such file.
pub fn post_dirs(loader: &dyn SourceLoader, file: &Path) -> Result<Vec<PathBuf>, Diagnostic> {
    let Some(config) = find(loader, file) else { return Ok(Vec::new()) };
    let base = config.parent().map(Path::to_path_buf).unwrap_or_default();
    Ok(read(loader, &config)?.posts.dirs.iter().map(|d| base.join(d)).collect())
}
