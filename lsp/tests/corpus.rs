//! Every corpus post, probed at many offsets: hover, definition,
//! completion and fixes never panic and stay on character boundaries, and
//! positions convert back to the same offsets.

use std::path::Path;

use postc_ir::Dialect;
use postc_lsp::{analysis, text};

fn posts() -> Vec<(std::path::PathBuf, Dialect)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus/posts");
    let mut out = Vec::new();
    for dir in std::fs::read_dir(&root).unwrap() {
        for f in std::fs::read_dir(dir.unwrap().path()).unwrap() {
            let path = f.unwrap().path();
            let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
            let dialect = match ext.as_str() {
                "pp" => Dialect::Vectric,
                "js" => Dialect::Cimco,
                "vcpost" => Dialect::VcPost,
                _ => continue,
            };
            out.push((path, dialect));
        }
    }
    out
}

#[test]
fn corpus_posts_answer_everywhere() {
    let posts = posts();
    assert!(posts.len() >= 20, "{posts:?}");
    let mut hovers = 0;
    for (path, dialect) in posts {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        for at in (0..=text.len()).step_by(13).filter(|&i| text.is_char_boundary(i)) {
            let pos = text::position(&text, at);
            assert_eq!(text::offset(&text, pos), at, "{} at {at}", path.display());
            if let Some(h) = analysis::hover(dialect, &text, at) {
                assert!(text.is_char_boundary(h.start) && text.is_char_boundary(h.end));
                hovers += 1;
            }
            if let Some((s, e)) = analysis::definition(dialect, &text, at) {
                assert!(s <= e && e <= text.len());
            }
            let _ = analysis::completion(dialect, &text, at, false);
        }
        if let Some(f) = analysis::fixes(dialect, &text, 0, text.len()).first() {
            panic!("{}: a fix in a corpus post: {}", path.display(), f.title);
        }
    }
    assert!(hovers > 500, "only {hovers} hovers");
}

/// The real Fusion posts of `../shared/corpus/fusion/` (beside the
/// checkout; under `CI=true` their absence fails): every name of Fusion's
/// host API a post uses answers a hover with its declaration.
#[test]
fn fusion_corpus_posts_answer_on_host_names() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus/fusion");
    if !root.is_dir() {
        assert!(std::env::var("CI").is_err(), "the Fusion corpus is missing: {}", root.display());
        return;
    }
    let mut stack = vec![root];
    let (mut posts, mut answered) = (0, 0);
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if !path.extension().is_some_and(|e| e.eq_ignore_ascii_case("cps")) {
                continue;
            }
            posts += 1;
            let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
            let mut seen = std::collections::HashSet::new();
            let bytes = text.as_bytes();
            let mut i = 0;
            while i < bytes.len() {
                if !(bytes[i].is_ascii_alphabetic() || bytes[i] == b'_')
                    || (i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_' || bytes[i - 1] == b'.'))
                {
                    i += 1;
                    continue;
                }
                let end = i + bytes[i..].iter().take_while(|b| b.is_ascii_alphanumeric() || **b == b'_').count();
                let word = &text[i..end];
                if postc_front_cimco::fusion::api::is_declared(word) && seen.insert(word.to_string()) {
                    let h = analysis::hover(Dialect::Fusion, &text, i)
                        .unwrap_or_else(|| panic!("{}: no hover on `{word}`", path.display()));
                    assert!(h.markdown.contains(&format!("**{word}** — Fusion")), "{}: {}", path.display(), h.markdown);
                    answered += 1;
                }
                i = end;
            }
        }
    }
    println!("{posts} Fusion posts, {answered} hovers on host names");
    assert!(posts >= 200 && answered > 10_000, "{posts} posts, {answered} hovers on host names");
}
