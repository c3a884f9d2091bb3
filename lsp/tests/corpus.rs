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
