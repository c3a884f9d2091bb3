//! Fixture snapshots: every post in `tests/fixtures/valid` and
//! `tests/fixtures/invalid` is compiled and compared with
//! `tests/snapshots/<name>.snap`: the lowered IR as RON, then every
//! diagnostic rendered for people and as JSON. Any difference fails;
//! `POSTC_BLESS=1 cargo test -p postc-front-vectric` rewrites the snapshots.
//! Valid fixtures must compile without errors, invalid ones with at least
//! one.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use postc_ir::{HandlerKey, Piece, Post, SourceMap, Stmt};

/// The handlers written back in Vectric's own notation, to read snapshots
/// by: literal bytes as text (`[nn]` for quotes, brackets and non-printable
/// bytes), variables as `[VARIABLE_NAME]`.
fn listing(post: &Post) -> String {
    let mut out = String::new();
    for handler in &post.handlers {
        let name = match &handler.key {
            HandlerKey::Section(s) => s.name().to_string(),
            HandlerKey::Word(w) => w.clone(),
        };
        let _ = writeln!(out, "begin {name}");
        for stmt in &handler.body {
            match stmt {
                Stmt::Line { pieces, .. } => {
                    out.push_str("  \"");
                    for piece in pieces {
                        match piece {
                            Piece::Text(bytes) => {
                                for &b in bytes {
                                    if (0x20..0x7f).contains(&b) && !b"[]\"".contains(&b) {
                                        out.push(char::from(b));
                                    } else {
                                        let _ = write!(out, "[{b}]");
                                    }
                                }
                            }
                            Piece::Var(id) => {
                                let name = post.variables.get(usize::from(*id)).map_or("?", |v| v.name.as_str());
                                let _ = write!(out, "[{name}]");
                            }
                            Piece::Expr(_) => out.push_str("[expr]"),
                        }
                    }
                    out.push_str("\"\n");
                }
                Stmt::Script(id) => {
                    let source = post.scripts.get(usize::from(*id)).map_or("?", |s| s.source.as_str());
                    let _ = writeln!(out, "  <!>{source}");
                }
                other => {
                    let _ = writeln!(out, "  {other:?}");
                }
            }
        }
    }
    out
}

fn fixtures(kind: &str) -> Vec<PathBuf> {
    let dir = Path::new("tests/fixtures").join(kind);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "pp"))
        .collect();
    files.sort();
    files
}

/// The snapshot text of one fixture, and whether it had errors.
fn snapshot(path: &Path) -> (String, bool) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut sources = SourceMap::new();
    let (post, diagnostics) = postc_front_vectric::compile(path, &bytes, &mut sources);
    let ron = ron::ser::to_string_pretty(&post, ron::ser::PrettyConfig::default()).expect("the IR serializes to RON");
    let mut out = format!(
        "# {}\n\n## handlers\n\n{}\n## post (RON)\n\n{ron}\n\n## diagnostics\n\n",
        path.display(),
        listing(&post)
    );
    if diagnostics.is_empty() {
        out.push_str("(none)\n");
    } else {
        out.push_str(&sources.render(&diagnostics, false));
        out.push_str("\n## diagnostics (JSON)\n\n");
        for d in &diagnostics {
            let json = serde_json::to_string(&sources.to_json(d, &path.display().to_string())).expect("JSON");
            let _ = writeln!(out, "{json}");
        }
    }
    (out, diagnostics.iter().any(|d| d.is_error()))
}

#[test]
fn fixtures_match_their_snapshots() {
    let bless = std::env::var_os("POSTC_BLESS").is_some_and(|v| v == "1");
    let snapshots = Path::new("tests/snapshots");
    let mut failures = Vec::new();
    let mut names = std::collections::BTreeSet::new();
    for (kind, expect_errors) in [("valid", false), ("invalid", true)] {
        for path in fixtures(kind) {
            let name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            assert!(names.insert(name.clone()), "two fixtures are named {name}");
            let (text, has_errors) = snapshot(&path);
            if has_errors != expect_errors {
                failures.push(format!("{}: expected {}errors", path.display(), if expect_errors { "" } else { "no " }));
            }
            let snap = snapshots.join(format!("{name}.snap"));
            if bless {
                std::fs::create_dir_all(snapshots).expect("snapshot folder");
                std::fs::write(&snap, &text).expect("write snapshot");
                continue;
            }
            match std::fs::read_to_string(&snap) {
                Ok(expected) if expected == text => {}
                Ok(expected) => {
                    let line = expected
                        .lines()
                        .zip(text.lines())
                        .position(|(a, b)| a != b)
                        .map_or_else(|| expected.lines().count().min(text.lines().count()) + 1, |i| i + 1);
                    failures.push(format!(
                        "{} differs from {} from line {line}:\n  expected: {:?}\n  actual:   {:?}",
                        path.display(),
                        snap.display(),
                        expected.lines().nth(line - 1).unwrap_or(""),
                        text.lines().nth(line - 1).unwrap_or("")
                    ));
                }
                Err(_) => failures.push(format!("{} has no snapshot {}", path.display(), snap.display())),
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{}\n\nrun `POSTC_BLESS=1 cargo test -p postc-front-vectric` to accept the new output",
        failures.join("\n")
    );
}
