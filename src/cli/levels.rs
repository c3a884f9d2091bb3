//! Severity per code: `--warn`, `--deny` and `--allow` on `postc check` and
//! `postc post`, and the `[diagnostics]` table of the nearest `postc.toml`
//! (docs/diagnostics.md, "Changing a code's severity").

use std::path::Path;

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

impl Flags {
    /// The rules for a post or toolpath at `file`: its `postc.toml`, then the flags.
    pub fn rules_for(&self, file: Option<&Path>) -> Result<LevelRules, Diagnostic> {
        let mut rules = match file.and_then(|f| std::path::absolute(f).ok()) {
            Some(file) => postc_lint::config::rules_for(&postc_report::FsLoader, &file)?,
            None => LevelRules::default(),
        };
        postc_lint::config::add_lists(
            &mut rules,
            [(&self.allow, Level::Allow), (&self.warn, Level::Warn), (&self.deny, Level::Deny)],
            1,
        )
        .map_err(|e| Diagnostic::error(codes::IO007, e))?;
        Ok(rules)
    }

    /// Checks the flags alone (before any file is read), so that a misspelt
    /// code is a bad command line whatever the files.
    pub fn check(&self, sources: &mut SourceMap) -> Result<(), super::Failed> {
        self.rules_for(None).map(|_| ()).map_err(|d| super::fail(sources, d))
    }
}
