//! Printing diagnostics: rendered for people on standard error, or as one
//! JSON array for tools.

use std::io::IsTerminal;

use postc_ir::{Diagnostic, SourceMap};
use postc_report::Render;

/// How `check` prints diagnostics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    Human,
    Json,
}

/// Prints diagnostics for people on standard error.
pub fn eprint(sources: &mut SourceMap, diagnostics: &[Diagnostic]) {
    if diagnostics.is_empty() {
        return;
    }
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    eprint!("{}", sources.render(diagnostics, color));
}

/// The JSON array of `check --format json`.
pub fn json(sources: &SourceMap, diagnostics: &[(String, Diagnostic)]) -> String {
    let items: Vec<_> = diagnostics.iter().map(|(file, d)| sources.to_json(d, file)).collect();
    serde_json::to_string_pretty(&items).unwrap_or_else(|_| "[]".into())
}

/// Writes to standard output; a reader that went away (`| head`) ends the
/// output quietly instead of a panic.
pub fn out(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush());
}
