//! Running LinuxCNC's `rs274` interpreter on a program and reading back the
//! moves it reports, for the tests that check G-code with it
//! (`tests/rs274.rs`, `tests/vcpost_rs274.rs`, the postp tests).
//!
//! Each run happens in its own temporary folder (rs274 keeps a parameter
//! file in the working folder, and its tool table in `$HOME/.tool.mmap`,
//! so HOME is that folder too). A run that rs274 ends by a signal is tried
//! once more: the standalone interpreter has been seen to die that way once
//! under heavy parallel load, and a crash of the referee is not a verdict on
//! the program.

use std::path::{Path, PathBuf};
use std::process::Command;

use postc_ir::event::Plane;

/// rs274 on PATH, if installed (`.ci/run` installs it). Under `CI=true`
/// a missing rs274 fails the test that asks: CI never skips the
/// interpreter.
pub fn find() -> Option<PathBuf> {
    let found = std::env::var_os("PATH")
        .and_then(|path| std::env::split_paths(&path).map(|d| d.join("rs274")).find(|p| p.is_file()));
    if found.is_none() {
        super::referee_missing("the rs274 checks", "rs274");
    }
    found
}

/// What kind of move rs274 reported.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    Traverse,
    Feed,
    /// Centre in the plane's first and second axes; rotation +1 is
    /// counter-clockwise.
    Arc {
        centre: [f64; 2],
        rotation: i32,
    },
}

/// One move: its kind, its end point X Y Z A B C (in the program's units),
/// the active plane, and whether the program's units were inches (the last
/// `USE_LENGTH_UNITS` before it).
#[derive(Debug, Clone, Copy)]
pub struct Motion {
    pub kind: Kind,
    pub end: [f64; 6],
    pub plane: Plane,
    pub inch: bool,
}

impl Motion {
    /// X Y Z of the end point in millimetres.
    pub fn end_mm(&self) -> [f64; 3] {
        let f = if self.inch { 25.4 } else { 1.0 };
        [self.end[0] * f, self.end[1] * f, self.end[2] * f]
    }
}

/// Axis indices of a plane's first and second axes and its normal, as
/// ARC_FEED orders them.
pub fn axes(plane: Plane) -> [usize; 3] {
    match plane {
        Plane::Xy => [0, 1, 2],
        Plane::Yz => [1, 2, 0],
        Plane::Zx => [2, 0, 1],
    }
}

fn numbers(args: &str) -> Vec<f64> {
    args.split(',').filter_map(|a| a.trim().parse().ok()).collect()
}

/// Runs rs274 on a program text with `corpus/tool.tbl`; its moves, or the
/// lines it complained with (and its exit status).
pub fn run(rs274: &Path, program: &str) -> Result<Vec<Motion>, String> {
    run_with_table(rs274, program, &PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("corpus/tool.tbl"))
}

/// Runs rs274 on a program text with the given tool table.
pub fn run_with_table(rs274: &Path, program: &str, table: &Path) -> Result<Vec<Motion>, String> {
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let file = dir.path().join("program.ngc");
    std::fs::write(&file, program).map_err(|e| e.to_string())?;
    let mut output = None;
    for _ in 0..2 {
        // rs274 keeps the tool table in `$HOME/.tool.mmap` (LinuxCNC's
        // libtooldata): runs side by side would share, and overwrite, one
        // table. Each run gets its own.
        let out = Command::new(rs274)
            .current_dir(dir.path())
            .env("HOME", dir.path())
            .args(["-g", "-t"])
            .arg(table)
            .arg(&file)
            .output()
            .map_err(|e| format!("cannot run rs274: {e}"))?;
        let killed = out.status.code().is_none();
        output = Some(out);
        if !killed {
            break;
        }
    }
    let output = output.expect("rs274 ran");
    let (stdout, stderr) = (String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    let (mut moves, mut complaints, mut plane, mut inch) = (Vec::new(), Vec::new(), Plane::Xy, false);
    for line in stdout.lines().chain(stderr.lines()) {
        let line = line.trim();
        // Canonical calls read `<count> N<block or .....> CALL(args)`.
        let mut words = line.splitn(3, char::is_whitespace);
        let call = match (words.next(), words.next(), words.next()) {
            (Some(n), Some(block), Some(call)) if n.bytes().all(|b| b.is_ascii_digit()) && block.starts_with('N') => {
                call.trim()
            }
            _ => {
                if !line.is_empty() && line != "executing" {
                    complaints.push(line.to_string());
                }
                continue;
            }
        };
        let Some((name, args)) = call.trim_end_matches("executing").split_once('(') else { continue };
        let n = numbers(args.trim_end_matches(')'));
        match name {
            "SELECT_PLANE" if args.contains("YZ") => plane = Plane::Yz,
            "SELECT_PLANE" if args.contains("XZ") => plane = Plane::Zx,
            "SELECT_PLANE" => plane = Plane::Xy,
            "USE_LENGTH_UNITS" => inch = args.contains("INCHES"),
            "STRAIGHT_TRAVERSE" | "STRAIGHT_FEED" if n.len() >= 6 => {
                let kind = if name == "STRAIGHT_TRAVERSE" { Kind::Traverse } else { Kind::Feed };
                moves.push(Motion { kind, end: [n[0], n[1], n[2], n[3], n[4], n[5]], plane, inch });
            }
            "ARC_FEED" if n.len() >= 9 => {
                let [u, v, w] = axes(plane);
                let mut end = [0.0, 0.0, 0.0, n[6], n[7], n[8]];
                (end[u], end[v], end[w]) = (n[0], n[1], n[5]);
                moves.push(Motion {
                    kind: Kind::Arc { centre: [n[2], n[3]], rotation: n[4] as i32 },
                    end,
                    plane,
                    inch,
                });
            }
            _ => {}
        }
    }
    if !output.status.success() || !complaints.is_empty() {
        return Err(format!("rs274 exit {:?}: {}", output.status.code(), complaints.join(" | ")));
    }
    Ok(moves)
}
