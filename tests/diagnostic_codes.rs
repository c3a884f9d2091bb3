//! Every diagnostic code the source reports is listed in
//! docs/diagnostics.md, and no code means two things (each appears in one
//! row there).

use std::collections::BTreeSet;
use std::path::Path;

/// Codes written as string literals (`"PP012"`) in the Rust sources under `dir`.
fn codes_in(dir: &Path, found: &mut BTreeSet<String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            if !path.ends_with("target") && !path.ends_with("tests") {
                codes_in(&path, found);
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).unwrap();
            let bytes = text.as_bytes();
            for i in 0..bytes.len().saturating_sub(6) {
                let w = &bytes[i..i + 7];
                if w[0] == b'"'
                    && w[6] == b'"'
                    && w[1].is_ascii_uppercase()
                    && w[2].is_ascii_uppercase()
                    && w[3..6].iter().all(u8::is_ascii_digit)
                {
                    found.insert(String::from_utf8(w[1..6].to_vec()).unwrap());
                }
            }
        }
    }
}

#[test]
fn every_code_is_documented_once() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = BTreeSet::new();
    for dir in ["ir", "runtime", "frontends", "backends", "postp", "verify", "lint", "src"] {
        codes_in(&root.join(dir), &mut found);
    }
    let doc = std::fs::read_to_string(root.join("docs/diagnostics.md")).unwrap();
    let rows: Vec<&str> = doc
        .lines()
        .filter(|l| l.starts_with("| ") && l.as_bytes().get(2).is_some_and(u8::is_ascii_uppercase))
        .collect();
    let missing: Vec<_> = found.iter().filter(|c| !rows.iter().any(|r| r.starts_with(&format!("| {c} |")))).collect();
    assert!(missing.is_empty(), "codes reported in the source but not in docs/diagnostics.md: {missing:?}");
    for code in &found {
        let n = rows.iter().filter(|r| r.starts_with(&format!("| {code} |"))).count();
        assert_eq!(n, 1, "{code} has {n} rows in docs/diagnostics.md");
    }
    assert!(found.len() > 150, "only {} codes found", found.len());
}
