//! Snapshot tests: every fixture under `tests/fixtures/{valid,invalid}` is
//! parsed, and its tree dump plus every diagnostic (rendered as people
//! see them) must equal `tests/snapshots/<name>.snap`. Run with
//! `POSTC_BLESS=1` to rewrite the snapshots after an intended change.
//!
//! Valid fixtures must parse without any diagnostic. Invalid fixtures must
//! report at least one error, and every code named on their first line
//! (`// expect: JS019 JS007`) must be among the codes reported.

use postc_report::Render as _;
use std::fs;
use std::path::{Path, PathBuf};

use postc_front_cimco::{dump::dump, parse};

fn fixtures(kind: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures").join(kind);
    let mut files: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "js"))
        .collect();
    files.sort();
    files
}

fn name_of(path: &Path) -> String {
    path.file_stem().expect("file name").to_string_lossy().into_owned()
}

/// The snapshot text of one fixture, and the codes it reported.
fn snapshot(kind: &str, path: &Path) -> (String, Vec<String>) {
    let bytes = fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let mut sources = postc_report::source_map();
    let file = sources.add(format!("{kind}/{}.js", name_of(path)), text.clone());
    let (program, diagnostics) = parse(&text, file);
    let codes = diagnostics.iter().map(|d| d.code.to_string()).collect();
    let rendered = sources.render(&diagnostics, false);
    (format!("--- tree\n{}--- diagnostics\n{rendered}", dump(&program, &text)), codes)
}

/// The codes named on the first line of an invalid fixture.
fn expected_codes(path: &Path) -> Vec<String> {
    let text = fs::read_to_string(path).unwrap_or_default();
    let first = text.lines().next().unwrap_or("");
    first
        .strip_prefix("// expect:")
        .map(|rest| rest.split_whitespace().map(str::to_string).collect())
        .unwrap_or_default()
}

/// The first line where two texts differ, for the failure message.
fn first_difference(expected: &str, actual: &str) -> String {
    let mut e = expected.lines();
    let mut a = actual.lines();
    for line in 1.. {
        match (e.next(), a.next()) {
            (None, None) => return "texts differ only in line endings".to_string(),
            (x, y) if x != y => {
                return format!(
                    "line {line}:\n  snapshot: {}\n  actual:   {}",
                    x.unwrap_or("<end>"),
                    y.unwrap_or("<end>")
                );
            }
            _ => {}
        }
    }
    unreachable!()
}

#[test]
fn fixtures_match_snapshots() {
    let bless = std::env::var("POSTC_BLESS").is_ok_and(|v| v == "1");
    let snapshots = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots");
    fs::create_dir_all(&snapshots).expect("snapshot directory");
    let mut failures = Vec::new();
    let mut seen = Vec::new();
    for kind in ["valid", "invalid"] {
        let files = fixtures(kind);
        assert!(!files.is_empty(), "no {kind} fixtures");
        for path in files {
            let name = name_of(&path);
            assert!(!seen.contains(&name), "two fixtures are called {name}");
            seen.push(name.clone());
            let (actual, codes) = snapshot(kind, &path);
            if kind == "valid" && !codes.is_empty() {
                failures.push(format!("{name}: a valid fixture reported {codes:?}"));
            }
            if kind == "invalid" {
                if codes.is_empty() {
                    failures.push(format!("{name}: an invalid fixture reported nothing"));
                }
                for code in expected_codes(&path) {
                    if !codes.contains(&code) {
                        failures.push(format!("{name}: expected {code}, reported {codes:?}"));
                    }
                }
            }
            let snap = snapshots.join(format!("{name}.snap"));
            if bless {
                fs::write(&snap, &actual).expect("write snapshot");
                continue;
            }
            match fs::read_to_string(&snap) {
                Ok(expected) if expected == actual => {}
                Ok(expected) => failures
                    .push(format!("{name}: differs from its snapshot at {}", first_difference(&expected, &actual))),
                Err(_) => failures.push(format!("{name}: no snapshot (run with POSTC_BLESS=1)")),
            }
        }
    }
    for entry in fs::read_dir(&snapshots).expect("snapshot directory") {
        let path = entry.expect("directory entry").path();
        let name = name_of(&path);
        if !seen.contains(&name) {
            failures.push(format!("{}: a snapshot without a fixture", path.display()));
        }
    }
    assert!(failures.is_empty(), "{} snapshot failures:\n{}", failures.len(), failures.join("\n"));
}
