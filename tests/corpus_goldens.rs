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
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use postc_ir::{Post, SourceMap};
use postc_runtime::output::part_names;
use postc_runtime::{Finished, Output, RunOptions};

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus")
}

/// The files of `dir` whose extension is `ext`, sorted by name.
fn files(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext)))
        .collect();
    out.sort();
    out
}

fn stem(path: &Path) -> String {
    path.file_stem().expect("a file name").to_string_lossy().into_owned()
}

/// Compiles a corpus post; any diagnostic (error or warning) is a failure.
fn compile(path: &Path) -> Result<Post, String> {
    let mut sources = SourceMap::new();
    let compiled = postc_frontends::compile_post(path, None, &mut sources);
    if !compiled.diagnostics.is_empty() {
        let list: Vec<String> = compiled.diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
        return Err(format!("{} does not compile cleanly:\n{}", path.display(), list.join("\n")));
    }
    compiled.post.ok_or_else(|| format!("{} gave no post", path.display()))
}

/// Posts a toolpath into memory: the parts of the program.
fn post_toolpath(post: &Post, toolpath: &Path) -> Result<Vec<Vec<u8>>, String> {
    let mut sources = SourceMap::new();
    let mut source = postc_frontends::open_toolpath(toolpath, &mut sources)
        .map_err(|d| format!("cannot open {}: {} {}", toolpath.display(), d.code, d.message))?;
    match postc_runtime::run(post, &mut source, Output::memory(), RunOptions::default()) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => Ok(parts),
            _ => Err("a memory run did not finish in memory".into()),
        },
        Err(diagnostics) => {
            let list: Vec<String> = diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
            Err(format!("posting failed:\n{}", list.join("\n")))
        }
    }
}

/// Lines with their endings, so that a CR/LF difference is a difference.
fn lines(bytes: &[u8]) -> Vec<&[u8]> {
    bytes.split_inclusive(|&b| b == b'\n').collect()
}

/// A line as text with its line ending spelled out.
fn show(line: &[u8]) -> String {
    let mut s = String::new();
    for c in String::from_utf8_lossy(line).chars() {
        match c {
            '\r' => s.push_str("\\r"),
            '\n' => s.push_str("\\n"),
            '\t' => s.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(s, "\\x{:02x}", c as u32);
            }
            c => s.push(c),
        }
    }
    s
}

/// A readable account of how `actual` differs from `expected`: the first
/// differing lines with a little context.
fn diff(expected: &[u8], actual: &[u8]) -> String {
    let (e, a) = (lines(expected), lines(actual));
    let first = e.iter().zip(&a).position(|(x, y)| x != y).unwrap_or(e.len().min(a.len()));
    let mut out = format!(
        "  first difference at line {} (expected {} lines, {} bytes; got {} lines, {} bytes)\n",
        first + 1,
        e.len(),
        expected.len(),
        a.len(),
        actual.len()
    );
    let context = first.saturating_sub(2);
    for (i, line) in e.iter().enumerate().take(first).skip(context) {
        let _ = writeln!(out, "    {:>5}   {}", i + 1, show(line));
    }
    // The first run of differing lines (at most six), two lines of
    // context after it, and how many other lines differ.
    let total = e.len().max(a.len());
    let differs = |i: usize| e.get(i) != a.get(i);
    let mut i = first;
    while i < total && differs(i) && i < first + 6 {
        if let Some(x) = e.get(i) {
            let _ = writeln!(out, "    {:>5} - {}", i + 1, show(x));
        }
        if let Some(y) = a.get(i) {
            let _ = writeln!(out, "    {:>5} + {}", i + 1, show(y));
        }
        i += 1;
    }
    for (j, line) in e.iter().enumerate().take(i + 2).skip(i) {
        if !differs(j) {
            let _ = writeln!(out, "    {:>5}   {}", j + 1, show(line));
        }
    }
    let more = (i..total).filter(|&j| differs(j)).count();
    if more > 0 {
        let _ = writeln!(out, "    ... and {more} more differing lines");
    }
    out
}

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
        let ext = if post.info.file_extension.is_empty() { "out" } else { post.info.file_extension.trim_start_matches('.') };
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
