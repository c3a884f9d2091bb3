//! What the verify tests share: replaying a program against a toolpath
//! file in memory and reading each finding as its code, severity, program
//! line and message.

use std::io::Cursor;
use std::path::Path;

use postc_ir::Severity;
use postc_verify::Settings;

/// A finding: code, severity, line of the program (0 for a finding on the
/// toolpath), message.
#[derive(Debug)]
pub struct Found {
    pub code: &'static str,
    pub severity: Severity,
    pub line: usize,
    pub message: String,
}

/// Verifies `program` against the toolpath file `toolpath`.
pub fn verify(program: &[u8], toolpath: &Path, settings: &Settings) -> Vec<Found> {
    let mut sources = postc_report::source_map();
    let file = sources.add("program.nc", String::from_utf8_lossy(program).into_owned());
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
    let report = postc_verify::verify(&mut Cursor::new(program), file, &mut source, settings);
    report
        .findings
        .iter()
        .map(|d| {
            let span = d.primary_span().unwrap();
            let line = if span.file == file { sources.line_column(file, span.start).unwrap().0 } else { 0 };
            Found { code: d.code, severity: d.severity, line, message: d.message.clone() }
        })
        .collect()
}

/// The errors among `found`.
pub fn errors(found: &[Found]) -> Vec<&Found> {
    found.iter().filter(|f| f.severity == Severity::Error).collect()
}
