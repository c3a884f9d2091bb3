//! The field-style CIMCO posts of `corpus/posts/cimco-styles/`: six posts
//! for one Fanuc mill, each written in one way posts from the field are
//! written (docs/cimco.md, "Field-style posts"), which print the same
//! program for the same toolpath.
//!
//! Their goldens (`corpus/expected/cimco-styles/`) come from Node.js
//! running the posts with the referee host of `tests/node_host/`, not from
//! postc: Node.js must still print them (under `CI=true` a missing `node`
//! is a failure; elsewhere the check is skipped with a message), and the
//! six posts must print the same program. `POSTC_BLESS=1 cargo test --test
//! cimco_styles` rewrites the goldens from what Node.js prints.
//!
//! What postc prints for them is reported, not required: the count of
//! programs it prints byte for byte as Node.js does, and for each other
//! pair the first difference or the error. LinuxCNC's rs274 reads the
//! goldens in `tests/rs274.rs`, `postc verify` in `tests/verify_corpus.rs`.

use crate::support;

use std::path::{Path, PathBuf};

use crate::support::cimco::*;
use crate::support::{Goldens, all_files};

/// Every toolpath exported as JSON Lines into `dir`, in the order of
/// [`mill_toolpaths`].
fn exported(dir: &Path) -> Vec<(PathBuf, PathBuf)> {
    mill_toolpaths()
        .into_iter()
        .map(|toolpath| {
            let jsonl = dir.join(format!("{}.jsonl", stem(&toolpath)));
            export_jsonl(&toolpath, &jsonl).expect("the toolpath exports");
            (toolpath, jsonl)
        })
        .collect()
}

#[test]
fn node_prints_the_goldens() {
    let Some(version) = node_or_skip("cimco_styles") else { return };
    eprintln!("cimco_styles: referee is Node.js {version}");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let toolpaths = exported(dir.path());
    let posts = style_posts();
    assert!(posts.len() >= 6, "only {} field-style posts", posts.len());
    let mut goldens = Goldens::new();
    for post in &posts {
        for (toolpath, jsonl) in &toolpaths {
            match run_node(post, jsonl, &[]) {
                Ok(program) => goldens.check(&style_golden(post, toolpath), &program),
                Err(e) => goldens.fail(format!("{}__{}: {e}", stem(post), stem(toolpath))),
            }
        }
    }
    goldens.sweep(all_files(&corpus().join("expected/cimco-styles")), "no post and toolpath make this file any more");
    goldens.finish("field-style goldens", "cimco_styles");
}

/// The styles differ in how they are written, not in what they print:
/// every post's golden for a toolpath is the same program.
#[test]
fn every_style_prints_the_same_program() {
    let posts = style_posts();
    let mut differ = Vec::new();
    for toolpath in mill_toolpaths() {
        let first = std::fs::read(style_golden(&posts[0], &toolpath)).expect("the first post's golden");
        for post in &posts[1..] {
            let other = std::fs::read(style_golden(post, &toolpath)).expect("the golden");
            if other != first {
                differ.push(format!(
                    "{} and {} over {}:\n{}",
                    stem(&posts[0]),
                    stem(post),
                    stem(&toolpath),
                    support::diff(&first, &other)
                ));
            }
        }
    }
    assert!(differ.is_empty(), "{}", differ.join("\n"));
}

/// A drilling cycle the posts have no code for (a tapping cycle) stops
/// every post with an error naming it; none prints a default cycle.
#[test]
fn an_unknown_cycle_stops_every_post_under_node() {
    let Some(_) = node_or_skip("cimco_styles") else { return };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let (toolpath, jsonl) = tapping_job(dir.path());
    assert!(toolpath.is_file());
    for post in style_posts() {
        match run_node(&post, &jsonl, &[]) {
            Ok(program) => {
                panic!("{} printed a program for a tapping cycle:\n{}", stem(&post), String::from_utf8_lossy(&program))
            }
            Err(e) => assert!(e.contains("unsupported drilling cycle: Tapping"), "{}: {e}", stem(&post)),
        }
    }
}

/// A drilling job with a tapping cycle, as RON and as JSON Lines.
fn tapping_job(dir: &Path) -> (PathBuf, PathBuf) {
    let toolpath = dir.join("tapping.ron");
    std::fs::write(
        &toolpath,
        "Job(units: Mm)\n\
         Tool(number: 7, name: \"M8 tap\", diameter: 8, spindle_speed: 500, cut_feed: 625, plunge_feed: 625)\n\
         ToolpathStart(name: \"Tap\")\n\
         DrillCycle(kind: Tap, retract_plane: 10, reference_plane: 2, surface: 0, depth: -12, feed: 625, pitch: 1.25)\n\
         DrillPoint(x: 20, y: 15)\n\
         DrillEnd\n\
         ToolpathEnd\n\
         End\n",
    )
    .expect("write the toolpath");
    let jsonl = dir.join("tapping.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("the toolpath exports");
    (toolpath, jsonl)
}

/// What postc prints for the field-style posts today, against the
/// goldens: reported, never failed (the script tier these posts need is
/// being rebuilt). Each pair is a match, the first difference, or the
/// error postc stopped with; for each post that runs, what a tapping
/// cycle does.
#[test]
fn postc_against_the_goldens_is_reported() {
    let posts = style_posts();
    let (mut matched, mut total) = (0, 0);
    let mut report = Vec::new();
    for post_path in &posts {
        total += 3;
        let post = match compile(post_path) {
            Ok(p) => p,
            Err(e) => {
                report.push(format!("{}: refused\n{e}", stem(post_path)));
                continue;
            }
        };
        let mut ran = false;
        for toolpath in mill_toolpaths() {
            let pair = format!("{}__{}", stem(post_path), stem(&toolpath));
            let expected = std::fs::read(style_golden(post_path, &toolpath)).unwrap_or_default();
            match post_toolpath(&post, &toolpath) {
                Ok(ours) if ours == expected => {
                    matched += 1;
                    ran = true;
                }
                Ok(ours) => {
                    ran = true;
                    report.push(format!(
                        "{pair}: postc (+) differs from Node.js (-)\n{}",
                        support::diff(&expected, &ours)
                    ))
                }
                Err(e) => report.push(format!("{pair}: {e}")),
            }
        }
        if ran {
            let dir = tempfile::tempdir().expect("a temporary folder");
            let (tapping, _) = tapping_job(dir.path());
            let outcome = match post_toolpath(&post, &tapping) {
                Ok(_) => "prints a program".to_string(),
                Err(e) => e.replace("posting failed:\n ", "stops:"),
            };
            report.push(format!(
                "{}: a tapping cycle: {outcome} (Node.js: Error: unsupported drilling cycle: Tapping)",
                stem(post_path)
            ));
        }
    }
    println!("cimco_styles: postc prints {matched} of {total} field-style programs as Node.js does");
    for line in &report {
        println!("{line}");
    }
}

/// The styles the general lowering takes whole (docs/cimco.md, "The whole
/// post lowered generally"): no function is a script, and every program is
/// the one Node.js printed.
const LOWERED_WHOLE: [&str; 6] = [
    "style_state_object",
    "style_cycle_objects",
    "style_word_arrays",
    "style_writer_object",
    "style_closures",
    "style_tables",
];

#[test]
fn styles_lowered_whole_print_what_node_prints() {
    for post_path in style_posts().iter().filter(|p| LOWERED_WHOLE.contains(&stem(p).as_str())) {
        let post = compile(post_path).unwrap_or_else(|e| panic!("{}: {e}", post_path.display()));
        assert_eq!(script_functions(&post), (vec![], false), "{}: scripts", post_path.display());
        for toolpath in mill_toolpaths() {
            let expected = std::fs::read(style_golden(post_path, &toolpath)).expect("the golden");
            let ours = post_toolpath(&post, &toolpath).unwrap_or_else(|e| panic!("{}: {e}", post_path.display()));
            assert!(
                ours == expected,
                "{} over {}: postc (+) differs from Node.js (-)\n{}",
                post_path.display(),
                toolpath.display(),
                support::diff(&expected, &ours)
            );
        }
    }
}
