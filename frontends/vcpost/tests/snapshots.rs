//! Snapshot tests: every fixture post under `tests/fixtures/valid` and
//! `tests/fixtures/invalid` is compiled, and its diagnostics (rendered as
//! people see them), Sub signatures and lowered IR (RON) are compared with
//! the `insta` snapshot `tests/snapshots/<name>.snap`. Any difference
//! fails; `cargo insta review` (or `INSTA_UPDATE=always cargo test -p
//! postc-front-vcpost --test snapshots`) accepts new output.
//!
//! Valid fixtures must compile without any diagnostic. Invalid fixtures are
//! named after the code they show (`vc006_missing_end_if.VcPost`) and must
//! give at least one diagnostic with that code.

use postc_report::Render as _;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use postc_front_vcpost::{compile, parse, signatures, signatures::from_post};
use postc_ir::Severity;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

struct Outcome {
    snapshot: String,
    codes: Vec<(String, Severity)>,
}

fn run(path: &Path) -> Outcome {
    let bytes = std::fs::read(path).unwrap();
    let relative = path.strip_prefix(crate_dir()).unwrap_or(path).to_path_buf();
    let mut sources = postc_report::source_map();
    let (mut post, diagnostics) = compile(&relative, &bytes, &mut sources);
    // The file as written (`PostInfo::written`) is the fixture itself.
    post.drop_written();

    let text = String::from_utf8_lossy(&bytes).into_owned();
    let (program, _) = parse(&text, postc_ir::FileId(0));
    let sigs = signatures(&program);
    let from_notes = from_post(&post);
    let plain = |s: &postc_front_vcpost::SubSignature| (s.name.clone(), s.keyword, s.params.clone(), s.tips.clone());
    assert_eq!(
        sigs.iter().map(plain).collect::<Vec<_>>(),
        from_notes.iter().map(plain).collect::<Vec<_>>(),
        "{}: signatures do not survive PostInfo::notes",
        path.display()
    );

    let mut out = String::new();
    out.push_str("== diagnostics ==\n");
    out.push_str(&sources.render(&diagnostics, false));
    out.push_str("== signatures ==\n");
    for s in &sigs {
        let line = sources.line_column(s.span.file, s.span.start).map_or(0, |p| p.0);
        let keyword = s.keyword.map_or("-".to_string(), |k| format!("#{}", k.as_str()));
        let params: Vec<String> = s.params.iter().map(|(n, m)| if *m { format!("!{n}") } else { n.clone() }).collect();
        let _ = writeln!(out, "{} {} [{}] (line {line})", s.name, keyword, params.join(" "));
        for (slot, tip) in &s.tips {
            let _ = writeln!(out, "    #{} {tip}", slot.as_str());
        }
    }
    out.push_str("== ir ==\n");
    let config = ron::ser::PrettyConfig::new().indentor("  ".to_string());
    out.push_str(&compact_byte_arrays(&ron::ser::to_string_pretty(&post, config).unwrap()));
    out.push('\n');
    Outcome { snapshot: out, codes: diagnostics.iter().map(|d| (d.code.to_string(), d.severity)).collect() }
}

/// Puts the byte arrays of RON (literal output text) on one line, with
/// the text they spell in a comment, so snapshots stay readable.
fn compact_byte_arrays(ron: &str) -> String {
    let lines: Vec<&str> = ron.lines().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.ends_with('[') {
            let mut bytes = Vec::new();
            let mut j = i + 1;
            while let Some(b) = lines.get(j).and_then(|l| l.trim().strip_suffix(',')).and_then(|t| t.parse::<u8>().ok())
            {
                bytes.push(b);
                j += 1;
            }
            if !bytes.is_empty() && lines.get(j).is_some_and(|l| l.trim_start().starts_with(']')) {
                let list: Vec<String> = bytes.iter().map(u8::to_string).collect();
                let close = lines[j].trim_start();
                let _ = writeln!(out, "{line}{}{close} // {:?}", list.join(", "), String::from_utf8_lossy(&bytes));
                i = j + 1;
                continue;
            }
        }
        out.push_str(line);
        out.push('\n');
        i += 1;
    }
    out
}

/// Compares `actual` with the snapshot `tests/snapshots/<stem>.snap`.
fn check_snapshot(path: &Path, actual: &str) {
    let name = path.file_stem().unwrap().to_string_lossy().into_owned();
    let mut settings = insta::Settings::clone_current();
    settings.remove_snapshot_suffix();
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.bind(|| insta::assert_snapshot!(name, actual));
}

#[test]
fn valid_fixtures_compile_cleanly_and_match_their_snapshots() {
    let mut failures = Vec::new();
    let mut count = 0;
    insta::glob!("fixtures/valid/*.vcpost", |path| {
        count += 1;
        let outcome = run(path);
        if !outcome.codes.is_empty() {
            failures.push(format!(
                "{}: unexpected diagnostics {:?}\n{}",
                path.display(),
                outcome.codes,
                outcome.snapshot
            ));
            return;
        }
        check_snapshot(path, &outcome.snapshot);
    });
    assert!(count >= 4, "expected the four application posts");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn invalid_fixtures_report_their_code_and_match_their_snapshots() {
    let mut failures = Vec::new();
    insta::glob!("fixtures/invalid/*.vcpost", |path| {
        let outcome = run(path);
        let stem = path.file_stem().unwrap().to_string_lossy().to_uppercase();
        let code = stem.split('_').next().unwrap_or_default().to_string();
        if !outcome.codes.iter().any(|(c, _)| *c == code) {
            failures.push(format!("{}: no {code} among {:?}\n{}", path.display(), outcome.codes, outcome.snapshot));
            return;
        }
        check_snapshot(path, &outcome.snapshot);
    });
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_code_has_an_invalid_fixture() {
    let mut have = Vec::new();
    insta::glob!("fixtures/invalid/*.vcpost", |p| {
        have.push(
            p.file_stem().unwrap().to_string_lossy().to_uppercase().split('_').next().unwrap_or_default().to_string(),
        );
    });
    let missing: Vec<&str> =
        postc_front_vcpost::diagnostics::ALL.iter().copied().filter(|c| !have.iter().any(|h| h == c)).collect();
    assert!(missing.is_empty(), "codes without an invalid fixture: {missing:?}");
}
