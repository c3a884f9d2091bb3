//! The lints (`postc-lint`) over the corpus: the project's own posts lint
//! clean (they are meant to `postc check` clean), and over the 112 real
//! Vectric posts each rule's count is printed for docs/diagnostics.md — a
//! rule that fires on nearly every real post without a real fault is
//! wrong, not the posts.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::support::{corpus, files};

fn lint(path: &Path) -> Option<Vec<postc_ir::Diagnostic>> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    let post = compiled.post?;
    Some(postc_lint::lint(&post, &postc_lint::Options::default()))
}

/// Findings on the project's posts that are deliberate properties of them.
const DELIBERATE: &[(&str, &str, &str)] = &[
    ("gcode_noarcs_mm.pp", "LN012", "numbering wraps at 990 so that the goldens pin the wrap"),
    ("noarcs_wrap_x_mm.pp", "LN012", "numbering wraps at 990 so that the goldens pin the wrap"),
    ("text_output_mm.pp", "LN012", "a text listing numbers its lines to 9999"),
];

#[test]
fn the_projects_posts_lint_clean() {
    let root = corpus();
    let mut posts: Vec<PathBuf> = files(&root.join("posts/vectric"), "pp");
    posts.extend(files(&root.join("posts/cimco"), "js"));
    posts.extend(files(&root.join("posts/vcpost"), "VcPost"));
    posts.extend(files(&root.join("posts/postp"), "VcPost"));
    let mut found = Vec::new();
    for p in &posts {
        let file = p.file_name().unwrap_or_default().to_string_lossy().into_owned();
        for d in lint(p).unwrap_or_else(|| panic!("{} does not compile", p.display())) {
            if !DELIBERATE.iter().any(|(f, code, _)| *f == file && *code == d.code) {
                found.push(format!("{}: {} {}", p.display(), d.code, d.message));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn real_vectric_posts_per_rule() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/vectric");
    if !dir.is_dir() {
        crate::support::referee_missing("lint_corpus", "../shared/corpus/vectric");
        eprintln!("skipped: {} is absent (the real-world corpus sits beside the checkout in CI)", dir.display());
        return;
    }
    let mut real = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("list ../shared/corpus/vectric").flatten() {
        if entry.path().is_dir() {
            real.extend(files(&entry.path(), "pp"));
        }
    }
    let mut per_rule: BTreeMap<&str, (usize, Vec<String>)> = BTreeMap::new();
    let mut linted = 0;
    for p in &real {
        let Some(found) = lint(p) else { continue };
        linted += 1;
        let mut codes: Vec<&str> = found.iter().map(|d| d.code).collect();
        codes.dedup();
        for c in codes {
            let e = per_rule.entry(c).or_default();
            e.0 += 1;
            if e.1.len() < 3 {
                e.1.push(p.file_name().unwrap().to_string_lossy().into_owned());
            }
        }
    }
    eprintln!("lints over {linted} real Vectric posts (posts each rule fires on):");
    for rule in postc_lint::rules::ALL {
        let (n, examples) = per_rule.get(rule.code).cloned().unwrap_or_default();
        eprintln!("  {} {:<28} {n:>3}  {}", rule.code, rule.name, examples.join(", "));
    }
    assert!(linted >= 100, "only {linted} real posts compiled");
    for rule in postc_lint::rules::ALL {
        let n = per_rule.get(rule.code).map_or(0, |e| e.0);
        assert!(
            n * 10 < linted * 9,
            "{} fires on {n} of {linted} real posts: the rule is wrong, not the posts",
            rule.code
        );
    }
}

#[test]
fn check_runs_the_lints_and_the_product_table() {
    let post = corpus().join("posts/vectric/tape_split_mm.pp");
    let run = |extra: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_postc"))
            .arg("check")
            .arg(&post)
            .args(extra)
            .output()
            .unwrap();
        (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
    };
    let (code, stderr) = run(&[]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("LN006"), "{stderr}");
    let (code, stderr) = run(&["--product", "photovcarve"]);
    assert_eq!(code, Some(0), "warnings only: {stderr}");
    assert!(stderr.contains("warning[LN006]: PhotoVCarve does not support TAPE_SPLITTING"), "{stderr}");
    assert!(stderr.contains("the section CW_ARC_MOVE"), "{stderr}");
}

#[test]
fn check_fix_applies_the_certain_fixes() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("typo.pp");
    // Windows-1252 bytes (0xB0, a degree sign) must come back unchanged.
    let text: &[u8] = b"UNITS = \"MM\"\r\nbegin HEADR\r\n\"(90\xB0) G0 [X\"\r\nbegin FEED_MOVE\r\n\"G1 [X] [F]\"\r\n";
    std::fs::write(&post, text).unwrap();
    let out =
        std::process::Command::new(env!("CARGO_BIN_EXE_postc")).arg("check").arg("--fix").arg(&post).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("fixed 2 problem(s)"), "{stderr}");
    let fixed = std::fs::read(&post).unwrap();
    assert_eq!(
        fixed,
        b"UNITS = \"MM\"\r\nbegin HEADER\r\n\"(90\xB0) G0 [X]\"\r\nbegin FEED_MOVE\r\n\"G1 [X] [F]\"\r\n"
    );
    // Nothing left to fix: the file is not rewritten.
    let out =
        std::process::Command::new(env!("CARGO_BIN_EXE_postc")).arg("check").arg("--fix").arg(&post).output().unwrap();
    assert!(!String::from_utf8_lossy(&out.stderr).contains("fixed"));
}
