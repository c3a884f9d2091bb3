//! Corpus goldens: posts every Vectric post of `corpus/posts/vectric/` over
//! every toolpath of `corpus/toolpaths/` and compares the program, byte for
//! byte, with the committed file in `corpus/expected/`.
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
//! `POSTC_BLESS=1 cargo test --test corpus_goldens` rewrites the expected
//! files from the current output and deletes expected files no pair makes
//! any more. Read every blessed file before committing it.

use std::collections::BTreeSet;
use std::path::PathBuf;

use postc_runtime::output::part_names;

mod golden_common;

use golden_common::{compile, corpus, diff, files, post_parts as post_toolpath, stem};

#[test]
fn corpus_posts_match_their_goldens() {
    let bless = std::env::var("POSTC_BLESS").is_ok_and(|v| !v.is_empty() && v != "0");
    let root = corpus();
    let expected_dir = root.join("expected");
    let posts = files(&root.join("posts/vectric"), "pp");
    let toolpaths = files(&root.join("toolpaths"), "ron");
    assert!(posts.len() >= 10, "the corpus has {} posts", posts.len());
    assert!(toolpaths.len() >= 8, "the corpus has {} toolpaths", toolpaths.len());
    if bless {
        std::fs::create_dir_all(&expected_dir).expect("create corpus/expected");
    }

    let mut failures = Vec::new();
    let mut made = BTreeSet::new();
    let mut written = 0;
    for post_path in &posts {
        let post = match compile(post_path) {
            Ok(p) => p,
            Err(e) => {
                failures.push(e);
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
                    failures.push(format!("{pair}: {e}"));
                    continue;
                }
            };
            let target = expected_dir.join(format!("{pair}.{ext}"));
            let names = part_names(&target, parts.len(), post.options.tape_splitting.as_ref());
            assert_eq!(names.len(), parts.len(), "{pair}: one name per part");
            for (name, part) in names.iter().zip(&parts) {
                let file = name.file_name().expect("a part name").to_string_lossy().into_owned();
                made.insert(file.clone());
                let old = std::fs::read(name).ok();
                if bless {
                    if old.as_deref() != Some(part.as_slice()) {
                        std::fs::write(name, part).unwrap_or_else(|e| panic!("cannot write {}: {e}", name.display()));
                        written += 1;
                    }
                    continue;
                }
                match old {
                    None => failures.push(format!(
                        "{file}: no expected file (posting {pair} gave {} bytes); bless with POSTC_BLESS=1",
                        part.len()
                    )),
                    Some(old) if old != *part => failures.push(format!("{file}: output differs\n{}", diff(&old, part))),
                    Some(_) => {}
                }
            }
        }
    }

    // Expected files no pair makes any more (a post or toolpath renamed, or
    // a program that no longer splits).
    if let Ok(entries) = std::fs::read_dir(&expected_dir) {
        let mut stale: Vec<PathBuf> = entries
            .map(|e| e.expect("directory entry").path())
            .filter(|p| {
                let name = p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
                p.is_file() && !name.starts_with('.') && !made.contains(&name)
            })
            .collect();
        stale.sort();
        for path in stale {
            if bless {
                std::fs::remove_file(&path).unwrap_or_else(|e| panic!("cannot remove {}: {e}", path.display()));
                eprintln!("removed stale {}", path.display());
            } else {
                failures.push(format!("{}: no post and toolpath make this file any more", path.display()));
            }
        }
    }

    if bless {
        eprintln!("blessed {written} changed files of {} in {}", made.len(), expected_dir.display());
    }
    assert!(
        failures.is_empty(),
        "{} of {} expected files fail:\n\n{}\n\nIf the new output is right, read it and bless it: POSTC_BLESS=1 cargo test --test corpus_goldens",
        failures.len(),
        made.len(),
        failures.join("\n\n")
    );
}

#[test]
fn diff_shows_line_endings() {
    let d = diff(b"G0X1\r\nG1X2\r\n", b"G0X1\r\nG1X2\n");
    assert!(d.contains("line 2"), "{d}");
    assert!(d.contains("- G1X2\\r\\n") && d.contains("+ G1X2\\n"), "{d}");
}
