//! Severity per code: `--warn`, `--deny` and `--allow` on `postc check` and
//! `postc post`, and the `[diagnostics]` table of the nearest `postc.toml`
//! (docs/diagnostics.md, "Changing a code's severity").

use std::path::{Path, PathBuf};

use postc_ir::codes::{self, Level, LevelRules};
use postc_ir::{Diagnostic, SourceMap};

/// The flags, as `check` and `post` take them.
#[derive(clap::Args, Debug, Default, Clone)]
pub struct Flags {
    /// Report the warnings of CODE (a code like PP027, a prefix like PP, or `all`) as warnings (repeatable).
    #[arg(long = "warn", value_name = "CODE")]
    warn: Vec<String>,
    /// Turn the warnings of CODE (a code, a prefix, or `all`) into errors (repeatable).
    #[arg(long = "deny", value_name = "CODE")]
    deny: Vec<String>,
    /// Hide the warnings of CODE (a code, a prefix, or `all`) (repeatable).
    #[arg(long = "allow", value_name = "CODE")]
    allow: Vec<String>,
}

/// The `postc.toml` file.
#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Config {
    #[serde(default)]
    diagnostics: Lists,
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

/// The nearest `postc.toml` in `file`'s folder or a folder above it.
pub fn find_config(file: &Path) -> Option<PathBuf> {
    let absolute = std::path::absolute(file).ok()?;
    absolute.ancestors().skip(1).map(|dir| dir.join("postc.toml")).find(|p| p.is_file())
}

/// Adds the lists in order allow, warn, deny: within one source, for one
/// selector, deny wins over warn over allow.
fn add_lists(rules: &mut LevelRules, lists: [(&[String], Level); 3], rank: u8) -> Result<(), String> {
    for (list, level) in lists {
        for selector in list {
            rules.add(selector, level, rank)?;
        }
    }
    Ok(())
}

impl Flags {
    /// The rules for a post or toolpath at `file`: its `postc.toml`, then the flags.
    pub fn rules_for(&self, file: Option<&Path>) -> Result<LevelRules, Diagnostic> {
        let mut rules = LevelRules::default();
        if let Some(config) = file.and_then(find_config) {
            let name = config.display().to_string();
            let text = std::fs::read_to_string(&config)
                .map_err(|e| Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}")))?;
            let parsed: Config = toml::from_str(&text)
                .map_err(|e| Diagnostic::error(codes::IO007, format!("`{name}` does not read: {}", e.message())))?;
            let d = parsed.diagnostics;
            add_lists(&mut rules, [(&d.allow, Level::Allow), (&d.warn, Level::Warn), (&d.deny, Level::Deny)], 0)
                .map_err(|e| Diagnostic::error(codes::IO007, format!("`{name}`: {e}")))?;
        }
        add_lists(&mut rules, [(&self.allow, Level::Allow), (&self.warn, Level::Warn), (&self.deny, Level::Deny)], 1)
            .map_err(|e| Diagnostic::error(codes::IO007, e))?;
        Ok(rules)
    }

    /// Checks the flags alone (before any file is read), so that a misspelt
    /// code is a bad command line whatever the files.
    pub fn check(&self, sources: &mut SourceMap) -> Result<(), super::Failed> {
        self.rules_for(None).map(|_| ()).map_err(|d| super::fail(sources, d))
    }
}
