//! Snapshot tests: every fixture under `tests/fixtures/{valid,invalid}` is
//! parsed, and its tree dump plus every diagnostic (rendered as people
//! see them) must equal the `insta` snapshot `tests/snapshots/<name>.snap`.
//! After an intended change, `cargo insta review` (or
//! `INSTA_UPDATE=always cargo test -p postc-front-cimco --test snapshots`)
//! accepts the new output.
//!
//! Valid fixtures must parse without any diagnostic. Invalid fixtures must
//! report at least one error, and every code named on their first line
//! (`// expect: JS019 JS007`) must be among the codes reported.

use postc_report::Render as _;
use std::fs;
use std::path::Path;

use postc_front_cimco::{dump::dump, parse};

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

#[test]
fn fixtures_match_snapshots() {
    let snapshots = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots");
    let mut failures = Vec::new();
    let mut seen = Vec::new();
    let mut kinds = Vec::new();
    insta::glob!("fixtures/{valid,invalid}/*.js", |path| {
        let kind = path.parent().and_then(Path::file_name).and_then(|k| k.to_str()).unwrap_or_default().to_string();
        let name = name_of(path);
        assert!(!seen.contains(&name), "two fixtures are called {name}");
        seen.push(name.clone());
        let (actual, codes) = snapshot(&kind, path);
        kinds.push(kind.clone());
        if kind == "valid" && !codes.is_empty() {
            failures.push(format!("{name}: a valid fixture reported {codes:?}"));
        }
        if kind == "invalid" {
            if codes.is_empty() {
                failures.push(format!("{name}: an invalid fixture reported nothing"));
            }
            for code in expected_codes(path) {
                if !codes.contains(&code) {
                    failures.push(format!("{name}: expected {code}, reported {codes:?}"));
                }
            }
        }
        // `tests/snapshots/<name>.snap`, whatever folder the fixture is in.
        let mut settings = insta::Settings::clone_current();
        settings.remove_snapshot_suffix();
        settings.set_prepend_module_to_snapshot(false);
        settings.set_omit_expression(true);
        settings.bind(|| insta::assert_snapshot!(name, actual));
    });
    for kind in ["valid", "invalid"] {
        assert!(kinds.iter().any(|k| k == kind), "no {kind} fixtures");
    }
    for entry in fs::read_dir(&snapshots).expect("snapshot directory") {
        let path = entry.expect("directory entry").path();
        if path.extension().is_some_and(|e| e == "snap") && !seen.contains(&name_of(&path)) {
            failures.push(format!("{}: a snapshot without a fixture", path.display()));
        }
    }
    assert!(failures.is_empty(), "{} snapshot failures:\n{}", failures.len(), failures.join("\n"));
}
