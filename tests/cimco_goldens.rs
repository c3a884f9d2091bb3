//! CIMCO corpus goldens: posts every CIMCO post of `corpus/posts/cimco/`
//! over its toolpaths (milling posts: `corpus/toolpaths/cimco/mill.ron`,
//! `drill.ron` and `standard.ron`; lathe posts: `cimco/lathe.ron`) and
//! compares the program, byte for byte, with the committed file
//! `corpus/expected/cimco/POST__TOOLPATH.nc`.
//!
//! Every post must compile with no diagnostic at all (the corpus must
//! `postc check` clean), and the acceptance post `fanuc_mill.js` must run
//! `onLinear` and `onCircular` natively.
//!
//! `POSTC_BLESS=1 cargo test --test cimco_goldens` rewrites the expected
//! files from the current output and deletes the ones no pair makes.

mod cimco_common;

use std::collections::BTreeSet;

use cimco_common::*;
use postc_ir::Body;

#[test]
fn cimco_posts_match_their_goldens() {
    let bless = std::env::var("POSTC_BLESS").is_ok_and(|v| !v.is_empty() && v != "0");
    let expected_dir = corpus().join("expected/cimco");
    let posts = posts();
    assert!(posts.len() >= 7, "the corpus has {} CIMCO posts", posts.len());
    if bless {
        std::fs::create_dir_all(&expected_dir).expect("create corpus/expected/cimco");
    }
    let mut failures = Vec::new();
    let mut made = BTreeSet::new();
    for post_path in &posts {
        let post = match compile(post_path) {
            Ok(p) => p,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        for toolpath in toolpaths(&post) {
            let pair = format!("{}__{}", stem(post_path), stem(&toolpath));
            let program = match post_toolpath(&post, &toolpath) {
                Ok(p) => p,
                Err(e) => {
                    failures.push(format!("{pair}: {e}"));
                    continue;
                }
            };
            let name = format!("{pair}.{}", post.info.file_extension);
            let target = expected_dir.join(&name);
            made.insert(name.clone());
            let old = std::fs::read(&target).ok();
            if bless {
                if old.as_deref() != Some(program.as_slice()) {
                    std::fs::write(&target, &program)
                        .unwrap_or_else(|e| panic!("cannot write {}: {e}", target.display()));
                }
                continue;
            }
            match old {
                None => failures.push(format!("{name}: no expected file; bless with POSTC_BLESS=1")),
                Some(old) if old != program => {
                    failures.push(format!("{name}: output differs\n{}", diff(&old, &program)))
                }
                Some(_) => {}
            }
        }
    }
    if let Ok(entries) = std::fs::read_dir(&expected_dir) {
        for e in entries.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if e.path().is_file() && !made.contains(&name) {
                if bless {
                    let _ = std::fs::remove_file(e.path());
                } else {
                    failures.push(format!("{name}: no post and toolpath make this file any more"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} CIMCO goldens fail:\n\n{}\n\nIf the new output is right, read it and bless it: POSTC_BLESS=1 cargo test --test cimco_goldens",
        failures.len(),
        failures.join("\n\n")
    );
}

#[test]
fn fanuc_moves_are_native() {
    let post = compile(&corpus().join("posts/cimco/fanuc_mill.js")).expect("fanuc_mill.js compiles");
    for name in ["onLinear", "onCircular", "writeBlock", "getCompensation", "feedWord"] {
        let f = post.functions.iter().find(|f| f.name == name).unwrap_or_else(|| panic!("no {name}"));
        assert!(matches!(f.body, Body::Native(_)), "{name} is not native");
    }
    // The move handlers build their text in the output: no `Write` left.
    for h in &post.handlers {
        if let postc_ir::HandlerKey::Section(
            s @ (postc_ir::Section::FeedMove | postc_ir::Section::RapidMove | postc_ir::Section::CwArcMove),
        ) = h.key
        {
            let text = format!("{:?}", h.body);
            assert!(!text.contains("Write("), "{s:?} still writes a returned string: {text}");
            assert!(text.contains("Emit("), "{s:?} does not emit");
        }
    }
}
