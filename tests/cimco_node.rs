//! The second engine as referee: every corpus CIMCO post runs under
//! Node.js with the host in `tests/node_host/` (written from docs/cimco.md,
//! sharing no code with postc) over the same toolpaths, exported as JSON
//! Lines, and must print byte for byte what postc prints. Skipped, with a
//! message, when `node` is not installed.
//!
//! `cargo bench --bench cimco_vs_node` measures both engines over a
//! million-move toolpath (docs/performance.md).

use crate::support;

use std::path::{Path, PathBuf};

use crate::support::cimco::*;
use postc_ir::Post;

#[test]
fn node_prints_what_postc_prints() {
    let Some(version) = node() else {
        eprintln!("cimco_node: `node` is not installed; the Node.js referee is skipped");
        return;
    };
    eprintln!("cimco_node: referee is Node.js {version}");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut runs = Vec::new();
    for post_path in posts() {
        match compile(&post_path) {
            Ok(post) => runs.push((post_path, post)),
            Err(e) => failures.push(e),
        }
    }
    let compared = referee(&runs, dir.path(), &mut failures);
    assert!(failures.is_empty(), "{} pairs differ:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(compared >= 10, "only {compared} pairs were compared");
}

/// A corpus post converted to its own dialect (`postc convert --to
/// cimco`) is real JavaScript: Node.js runs it and prints, byte for byte,
/// what postc prints for the source post.
#[test]
fn node_runs_converted_posts_as_postc_posts_their_sources() {
    let Some(_) = node() else {
        eprintln!("cimco_node: `node` is not installed; the Node.js referee is skipped");
        return;
    };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut runs = Vec::new();
    for post_path in posts() {
        let post = match compile(&post_path) {
            Ok(p) => p,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        match postc_backends::convert(&post, postc_backends::Target::Cimco) {
            Ok(js) => {
                let converted = dir.path().join(format!("{}.js", stem(&post_path)));
                std::fs::write(&converted, js).expect("write the converted post");
                runs.push((converted, post));
            }
            Err(d) => failures.push(format!("{}: refused: {}", post_path.display(), d[0].message)),
        }
    }
    let compared = referee(&runs, dir.path(), &mut failures);
    assert!(failures.is_empty(), "{} pairs differ:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(compared >= 30, "only {compared} pairs were compared");
}

/// Runs each JavaScript post under Node.js over the toolpaths of its
/// post, which postc posts: the number of programs that agree; each
/// that does not is a failure.
fn referee(runs: &[(PathBuf, Post)], dir: &Path, failures: &mut Vec<String>) -> usize {
    let mut compared = 0;
    for (js, post) in runs {
        for toolpath in toolpaths(post) {
            let pair = format!("{}__{}", stem(js), stem(&toolpath));
            let jsonl = dir.join(format!("{}.jsonl", stem(&toolpath)));
            if let Err(e) = export_jsonl(&toolpath, &jsonl) {
                failures.push(format!("{pair}: cannot export the toolpath: {e}"));
                continue;
            }
            let ours = match post_toolpath(post, &toolpath) {
                Ok(o) => o,
                Err(e) => {
                    failures.push(format!("{pair}: {e}"));
                    continue;
                }
            };
            match run_node(js, &jsonl, &[]) {
                Ok(theirs) if theirs == ours => compared += 1,
                Ok(theirs) => {
                    failures.push(format!("{pair}: Node.js (-) and postc (+) differ\n{}", diff(&theirs, &ours)))
                }
                Err(e) => failures.push(format!("{pair}: {e}")),
            }
        }
    }
    compared
}

/// JavaScript corners Node.js and postc once disagreed on (found while
/// writing the field-style posts): `lastIndexOf` from an index, the
/// order of `for ... in` over keys that are array indices, whole
/// numbers in another radix, and chains of `+` that add numbers until a
/// text joins them (built in one buffer by the runtime).
#[test]
fn javascript_corners_print_as_node_prints() {
    let Some(_) = node() else {
        eprintln!("cimco_node: `node` is not installed; the Node.js referee is skipped");
        return;
    };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("corners.js");
    std::fs::write(
        &post_path,
        r#"var table = {b: 1, 10: "x", 2: "y", a: 2, "01": 3};
function keysOf(o) { var s = ""; for (var k in o) { s += k + ","; } return s; }
function onOpen(isClipboard) {
    var t = "ab ab ab";
    return "(" + t.lastIndexOf("ab", 4) + " " + t.lastIndexOf("ab") + " " + t.lastIndexOf("ab", -3) + " " +
        t.lastIndexOf("ab", 100) + " " + t.lastIndexOf("zz", 3) + ")\n(" + keysOf(table) + ")\n(" +
        (255).toString(16) + " " + (-10).toString(2) + " " + (35).toString(36) + " " + (12).toString(10) + ")\n";
}
function chain(p) { return p + 1 + "a" + p + 2 + "|" + (p + 1) + (p & 1) + "b"; }
function onLinear(x, y, z, movement) { return ""; }
function onClose() { return "(" + chain(2) + " " + chain(0.5) + ")\n"; }
"#,
    )
    .expect("write the post");
    let post = compile(&post_path).expect("compiles");
    let toolpath = support::corpus().join("toolpaths/cimco/mill.ron");
    let jsonl = dir.path().join("mill.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("export");
    let ours = post_toolpath(&post, &toolpath).expect("postc posts");
    let theirs = run_node(&post_path, &jsonl, &[]).expect("Node posts");
    assert_eq!(String::from_utf8_lossy(&theirs), String::from_utf8_lossy(&ours));
}
