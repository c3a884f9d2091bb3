//! Fixture snapshots: every post in `tests/fixtures/valid` and
//! `tests/fixtures/invalid` is compiled and compared with
//! `tests/snapshots/<name>.snap`: the lowered IR as RON, then every
//! diagnostic rendered for people and as JSON. These are `insta`
//! snapshots: any difference fails, and `cargo insta review` (or
//! `INSTA_UPDATE=always cargo test -p postc-front-vectric`) accepts new
//! output.
//! Valid fixtures must compile without errors, invalid ones with at least
//! one.

use postc_report::Render as _;
use std::fmt::Write as _;
use std::path::Path;

use postc_ir::{HandlerKey, Piece, Post, Stmt};

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

/// The snapshot text of one fixture, and whether it had errors.
fn snapshot(path: &Path) -> (String, bool) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut sources = postc_report::source_map();
    let (mut post, diagnostics) = postc_front_vectric::compile(path, &bytes, &mut sources);
    // The file as written (`PostInfo::written`) is the fixture itself.
    post.drop_written();
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
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut failures = Vec::new();
    let mut names = std::collections::BTreeSet::new();
    insta::glob!("fixtures/{valid,invalid}/*.pp", |absolute| {
        let path = absolute.strip_prefix(root).unwrap_or(absolute);
        let kind = path.parent().and_then(Path::file_name).and_then(|k| k.to_str()).unwrap_or_default();
        let expect_errors = kind == "invalid";
        let name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        assert!(names.insert(name.clone()), "two fixtures are named {name}");
        let (text, has_errors) = snapshot(path);
        if has_errors != expect_errors {
            failures.push(format!("{}: expected {}errors", path.display(), if expect_errors { "" } else { "no " }));
        }
        // `tests/snapshots/<name>.snap`, whatever folder the fixture is in.
        let mut settings = insta::Settings::clone_current();
        settings.remove_snapshot_suffix();
        settings.set_prepend_module_to_snapshot(false);
        settings.set_omit_expression(true);
        settings.bind(|| insta::assert_snapshot!(name, text));
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
