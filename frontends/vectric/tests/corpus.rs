//! The real posts of `../shared/corpus/vectric/*/*.pp` (read in place, never
//! copied here): every one compiles with zero errors. Skipped, with a
//! message, when the corpus is not there.

use postc_report::Render as _;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn corpus_posts(dir: &Path) -> Vec<PathBuf> {
    let mut posts = Vec::new();
    for folder in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        if !folder.path().is_dir() {
            continue;
        }
        for file in std::fs::read_dir(folder.path()).into_iter().flatten().flatten() {
            let path = file.path();
            if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("pp")) {
                posts.push(path);
            }
        }
    }
    posts.sort();
    posts
}

#[test]
fn every_corpus_post_compiles_without_errors() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/corpus/vectric");
    if !dir.is_dir() {
        println!("skipped: ../shared/corpus not found");
        return;
    }
    let posts = corpus_posts(&dir);
    assert!(!posts.is_empty(), "no .pp files under {}", dir.display());
    let mut failures = String::new();
    let mut warnings: BTreeMap<String, usize> = BTreeMap::new();
    for path in &posts {
        let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut sources = postc_report::source_map();
        let (post, diagnostics) = postc_front_vectric::compile(path, &bytes, &mut sources);
        let errors: Vec<_> = diagnostics.iter().filter(|d| d.is_error()).cloned().collect();
        if !errors.is_empty() {
            failures.push_str(&sources.render(&errors, false));
        }
        for d in diagnostics.iter().filter(|d| !d.is_error()) {
            *warnings.entry(format!("{} {}", d.code, d.message)).or_default() += 1;
        }
        assert!(!post.info.name.is_empty(), "{}: no POST_NAME", path.display());
        assert!(!post.handlers.is_empty(), "{}: no sections", path.display());
        assert!(postc_front_vectric::looks_like_vectric(&bytes), "{}: not recognised as Vectric", path.display());
    }
    println!("{} corpus posts compiled without errors; warnings:", posts.len());
    for (warning, count) in &warnings {
        println!("  {count:3} x {warning}");
    }
    assert!(failures.is_empty(), "corpus posts with errors:\n{failures}");
}

/// The project's own posts (`corpus/posts/vectric/*.pp` of this
/// repository) compile without errors too.
#[test]
fn project_posts_compile_without_errors() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../corpus/posts/vectric");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        println!("skipped: {} not found", dir.display());
        return;
    };
    let mut posts: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("pp")))
        .collect();
    posts.sort();
    for path in &posts {
        let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut sources = postc_report::source_map();
        let (_, diagnostics) = postc_front_vectric::compile(path, &bytes, &mut sources);
        let errors: Vec<_> = diagnostics.iter().filter(|d| d.is_error()).cloned().collect();
        assert!(errors.is_empty(), "{}", sources.render(&errors, false));
    }
}
