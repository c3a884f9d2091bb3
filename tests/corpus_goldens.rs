//! Corpus goldens: posts every Vectric post of `corpus/posts/vectric/` over
//! every toolpath of `corpus/toolpaths/` and compares the program, byte for
//! byte, with the committed file in `corpus/expected/vectric/`.
//!
//! One expected file per pair, named `POST__TOOLPATH.EXT` after the two file
//! stems and the post's FILE_EXTENSION (`gcode_mm__standard.ngc`). A
//! tape-splitting post that splits a program writes one file per part, named
//! by its own TAPE_SPLITTING format from that stem
//! (`tape_split_mm__long_mm_1.nc`, `..._2.nc`).
//!
//! Every post must compile with no diagnostic at all (the corpus is meant to
//! `postc check` clean). No pair is skipped: a toolpath a post was not
//! written for (a jet toolpath through a post without jet sections, a rotary
//! job through a flat post) must still post, and its output is pinned too.
//!
//! `POSTC_BLESS=1 cargo test --test suite corpus_goldens` rewrites the expected
//! files from the current output and deletes expected files no pair makes
//! any more. Read every blessed file before committing it.

use postc_runtime::output::part_names;

use crate::support::{Goldens, all_files, compile, corpus, diff, files, post_parts as post_toolpath, stem};

#[test]
fn corpus_posts_match_their_goldens() {
    let root = corpus();
    let expected_dir = root.join("expected/vectric");
    let posts = files(&root.join("posts/vectric"), "pp");
    let toolpaths = files(&root.join("toolpaths"), "ron");
    assert!(posts.len() >= 10, "the corpus has {} posts", posts.len());
    assert!(toolpaths.len() >= 8, "the corpus has {} toolpaths", toolpaths.len());

    let mut goldens = Goldens::new();
    for post_path in &posts {
        let post = match compile(post_path) {
            Ok(p) => p,
            Err(e) => {
                goldens.fail(e);
                continue;
            }
        };
        let ext =
            if post.info.file_extension.is_empty() { "out" } else { post.info.file_extension.trim_start_matches('.') };
        for toolpath in &toolpaths {
            let pair = format!("{}__{}", stem(post_path), stem(toolpath));
            let parts = match post_toolpath(&post, toolpath) {
                Ok(parts) => parts,
                Err(e) => {
                    goldens.fail(format!("{pair}: {e}"));
                    continue;
                }
            };
            let target = expected_dir.join(format!("{pair}.{ext}"));
            let names = part_names(&target, parts.len(), post.options.tape_splitting.as_ref());
            assert_eq!(names.len(), parts.len(), "{pair}: one name per part");
            for (name, part) in names.iter().zip(&parts) {
                goldens.check(name, part);
            }
        }
    }

    // Expected files no pair makes any more (a post or toolpath renamed, or
    // a program that no longer splits). Dot files are not goldens.
    let stale = all_files(&expected_dir)
        .into_iter()
        .filter(|p| !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.')));
    goldens.sweep(stale, "no post and toolpath make this file any more");
    goldens.finish("expected files", "corpus_goldens");
}

#[test]
fn diff_shows_line_endings() {
    let d = diff(b"G0X1\r\nG1X2\r\n", b"G0X1\r\nG1X2\n");
    assert!(d.contains("line 2"), "{d}");
    assert!(d.contains("- G1X2\\r\\n") && d.contains("+ G1X2\\n"), "{d}");
}
