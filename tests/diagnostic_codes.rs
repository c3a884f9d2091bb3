//! The registry of diagnostic codes (`postc_ir::codes`): every code the
//! source reports is declared there, with the severity it is reported at,
//! and docs/diagnostics.md is the registry rendered.
//!
//! `POSTC_BLESS=1 cargo test --test suite diagnostic_codes` rewrites
//! docs/diagnostics.md from the registry.

use std::collections::BTreeSet;
use std::path::Path;

use postc_ir::Severity;
use postc_ir::codes::{self, ALL, PREFIXES, SECTIONS};

use crate::support;

/// The Rust sources under `dir`, without `tests` folders and the registry itself.
fn sources(dir: &Path, found: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            if !path.ends_with("target") && !path.ends_with("tests") {
                sources(&path, found);
            }
        } else if path.extension().is_some_and(|e| e == "rs") && !path.ends_with("ir/src/codes.rs") {
            found.push((path.display().to_string(), std::fs::read_to_string(&path).unwrap()));
        }
    }
}

fn all_sources() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = Vec::new();
    for dir in ["ir", "runtime", "frontends", "backends", "postp", "verify", "lint", "src", "lsp"] {
        sources(&root.join(dir), &mut found);
    }
    found
}

fn is_code(w: &[u8]) -> bool {
    w.len() == 5 && w[..2].iter().all(u8::is_ascii_uppercase) && w[2..].iter().all(u8::is_ascii_digit)
}

/// Codes written as string literals (`"RT012"`) or registry names
/// (`codes::PP012`), at their byte offsets.
fn codes_in(text: &str) -> Vec<(usize, String)> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    for i in 0..bytes.len().saturating_sub(6) {
        let w = &bytes[i..i + 7];
        if w[0] == b'"' && w[6] == b'"' && is_code(&w[1..6]) {
            found.push((i, String::from_utf8(w[1..6].to_vec()).unwrap()));
        }
        if bytes[i..].starts_with(b"codes::") && bytes.len() >= i + 12 && is_code(&bytes[i + 7..i + 12]) {
            found.push((i, String::from_utf8(bytes[i + 7..i + 12].to_vec()).unwrap()));
        }
    }
    found
}

#[test]
fn every_code_the_source_reports_is_in_the_registry() {
    let mut found = BTreeSet::new();
    for (_, text) in all_sources() {
        found.extend(codes_in(&text).into_iter().map(|(_, c)| c));
    }
    let missing: Vec<_> = found.iter().filter(|c| codes::lookup(c).is_none()).collect();
    assert!(missing.is_empty(), "codes in the source but not in the registry (ir/src/codes.rs): {missing:?}");
    assert!(found.len() > 150, "only {} codes found", found.len());
}

/// `Diagnostic::error(X, `, `Diagnostic::warning(X, ` and
/// `Severity::Error, X` with X a literal or a registry name: the severity
/// written at the call site matches the registry's. (Debug builds also
/// check this in the `Diagnostic` constructors, for every diagnostic made.)
#[test]
fn call_sites_report_the_registry_severity() {
    let mut wrong = Vec::new();
    let mut checked = 0;
    for (file, text) in all_sources() {
        for (at, code) in codes_in(&text) {
            let before = text[..at].trim_end();
            let severity = if before.ends_with("Diagnostic::error(") || before.ends_with("Severity::Error,") {
                Severity::Error
            } else if before.ends_with("Diagnostic::warning(") || before.ends_with("Severity::Warning,") {
                Severity::Warning
            } else {
                continue;
            };
            checked += 1;
            if !codes::severity_ok(&code, severity) {
                wrong.push(format!("{file}: {code} reported as {severity}"));
            }
        }
    }
    assert!(wrong.is_empty(), "severities that disagree with the registry: {wrong:#?}");
    assert!(checked > 100, "only {checked} call sites checked");
}

#[test]
fn the_registry_is_consistent() {
    let mut seen = BTreeSet::new();
    for c in ALL {
        assert!(codes::is_code_shaped(c.code), "{}", c.code);
        assert!(seen.insert(c.code), "{} is declared twice", c.code);
        assert!(PREFIXES.iter().any(|(p, _)| c.code.starts_with(p)), "{} has no prefix row", c.code);
        let sections = SECTIONS.iter().filter(|s| s.prefixes.iter().any(|p| c.code.starts_with(p))).count();
        assert_eq!(sections, 1, "{} is in {sections} sections", c.code);
        assert!(!c.summary.is_empty() && !c.summary.contains('\n'), "{}: the summary is one line", c.code);
    }
    // Within a prefix, codes are declared in number order.
    for pair in ALL.windows(2) {
        if pair[0].code[..2] == pair[1].code[..2] {
            assert!(pair[0].code < pair[1].code, "{} is declared before {}", pair[0].code, pair[1].code);
        }
    }
    assert!(ALL.len() >= 250, "only {} codes", ALL.len());
}

#[test]
fn docs_diagnostics_md_is_the_registry_rendered() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/diagnostics.md");
    let rendered = codes::markdown();
    // A byte-exact golden of `tests/support` (`POSTC_BLESS=1` rewrites it).
    if let Err(e) = support::check_golden(&path, rendered.as_bytes()) {
        panic!(
            "docs/diagnostics.md is not the registry rendered; edit ir/src/codes.rs, then run \
             `POSTC_BLESS=1 cargo test --test suite diagnostic_codes`\n{e}"
        );
    }
    let committed = std::fs::read_to_string(&path).unwrap();
    // Each code has one row.
    for c in ALL {
        let n = committed.lines().filter(|l| l.starts_with(&format!("| {} |", c.code))).count();
        assert_eq!(n, 1, "{} has {n} rows", c.code);
    }
}

#[test]
fn explain_prints_summary_severity_and_documentation() {
    let text = codes::lookup("PP021").unwrap().explain();
    assert!(text.starts_with("PP021: arc words print fewer decimals"), "{text}");
    assert!(text.contains("severity: warning"), "{text}");
    assert!(codes::similar("PQ021").contains(&"PP021"));
}
