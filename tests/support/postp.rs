//! Helpers of the `postp` tests: post a CL text through a controller and
//! compare the program with a committed snapshot in `tests/snapshots/postp/`
//! (`POSTC_BLESS=1` rewrites the snapshots).

use std::path::{Path, PathBuf};

use postc_postp::{Controller, Settings, post};
use postc_runtime::{Finished, Output};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// What a run gave: the program (empty on failure) and the diagnostics as
/// `CODE message` lines.
pub struct Run {
    pub program: String,
    pub diagnostics: Vec<String>,
    pub ok: bool,
}

impl Run {
    /// The program followed by its diagnostics, as the snapshots hold it.
    pub fn text(&self) -> String {
        let mut s = self.program.clone();
        if !self.diagnostics.is_empty() {
            s.push_str("---- diagnostics\n");
            for d in &self.diagnostics {
                s.push_str(d);
                s.push('\n');
            }
        }
        s
    }

    pub fn has(&self, code: &str) -> bool {
        self.diagnostics.iter().any(|d| d.starts_with(code))
    }
}

/// Posts `cl` (written to a temporary `cl.tap`) with an optional options
/// file text and controller override.
pub fn run_with(cl: &str, options: Option<&str>, machine: Option<Controller>) -> Run {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cl.tap");
    std::fs::write(&path, cl).unwrap();
    let options = options.map(|text| {
        let p = dir.path().join("options.ron");
        std::fs::write(&p, text).unwrap();
        p
    });
    run_file(&path, Settings { options, machine, ..Settings::default() })
}

pub fn run_file(path: &Path, settings: Settings) -> Run {
    let mut sources = postc_report::source_map();
    let line = |d: &postc_ir::Diagnostic| format!("{} {}", d.code, d.message);
    match post(path, &settings, Output::memory(), &mut sources) {
        Ok(r) => {
            let Finished::Memory(parts) = r.output else { panic!("memory output") };
            let program = parts.into_iter().map(|p| String::from_utf8_lossy(&p).into_owned()).collect();
            Run { program, diagnostics: r.warnings.iter().map(line).collect(), ok: true }
        }
        Err(d) => Run { program: String::new(), diagnostics: d.iter().map(line).collect(), ok: false },
    }
}

/// Posts `body` after `MACHIN/<machine>` and `UNITS/MM`, and before `FINI`
/// when the body has none (a CL file ends with FINI; one without it may be
/// cut short, CL024).
pub fn run(machine: &str, body: &str) -> Run {
    let fini = if body.lines().any(|l| l.trim().eq_ignore_ascii_case("FINI")) { "" } else { "\nFINI\n" };
    run_with(&format!("MACHIN/{machine}\nUNITS/MM\n{body}{fini}"), None, None)
}

/// Compares `text`, byte for byte, with the golden
/// `tests/snapshots/postp/<name>.nc` (`POSTC_BLESS=1` rewrites it).
pub fn snapshot(name: &str, text: &str) {
    let path = root().join("tests/snapshots/postp").join(format!("{name}.nc"));
    if let Err(e) = super::check_golden(&path, text.as_bytes()) {
        panic!("{name}: {e}");
    }
}

/// Posts on a controller and compares with the snapshot `<name>.<MACHINE>`.
pub fn check(name: &str, machine: &str, body: &str) -> Run {
    let r = run(machine, body);
    snapshot(&format!("{name}.{machine}"), &r.text());
    r
}

/// LinuxCNC's rs274, when it is on PATH.
pub fn rs274() -> Option<PathBuf> {
    super::rs274::find()
}

/// Runs rs274 on a program: its complaints (empty when it reads cleanly)
/// and the number of moves it made (traverses, feeds, arcs).
pub fn interpret(rs274: &Path, program: &str) -> (Vec<String>, usize) {
    match super::rs274::run(rs274, program) {
        Ok(moves) => (Vec::new(), moves.len()),
        Err(complaint) => (vec![complaint], 0),
    }
}
