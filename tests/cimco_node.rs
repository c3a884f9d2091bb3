//! The second engine as referee: every corpus CIMCO post runs under
//! Node.js with the host in `tests/node_host/` (written from docs/cimco.md,
//! sharing no code with postc) over the same toolpaths, exported as JSON
//! Lines, and must print byte for byte what postc prints. Skipped, with a
//! message, when `node` is not installed.
//!
//! `cargo test --release --test cimco_node -- --ignored --nocapture` also
//! measures both engines over a million-move toolpath (see
//! docs/performance.md); it asserts nothing about time.

mod cimco_common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use cimco_common::*;

fn node() -> Option<String> {
    let out = Command::new("node").arg("--version").output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn host_script() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/run.js")
}

fn run_node(post: &Path, jsonl: &Path, extra: &[&str]) -> Result<Vec<u8>, String> {
    let out = Command::new("node")
        .arg(host_script())
        .arg(post)
        .arg(jsonl)
        .args(extra)
        .output()
        .map_err(|e| format!("cannot run node: {e}"))?;
    if !out.status.success() {
        return Err(format!("node failed:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    Ok(out.stdout)
}

#[test]
fn node_prints_what_postc_prints() {
    let Some(version) = node() else {
        eprintln!("cimco_node: `node` is not installed; the Node.js referee is skipped");
        return;
    };
    eprintln!("cimco_node: referee is Node.js {version}");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut compared = 0;
    for post_path in posts() {
        let post = match compile(&post_path) {
            Ok(p) => p,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        for toolpath in toolpaths(&post) {
            let pair = format!("{}__{}", stem(&post_path), stem(&toolpath));
            let jsonl = dir.path().join(format!("{}.jsonl", stem(&toolpath)));
            if let Err(e) = export_jsonl(&toolpath, &jsonl) {
                failures.push(format!("{pair}: cannot export the toolpath: {e}"));
                continue;
            }
            let ours = match post_toolpath(&post, &toolpath) {
                Ok(o) => o,
                Err(e) => {
                    failures.push(format!("{pair}: {e}"));
                    continue;
                }
            };
            match run_node(&post_path, &jsonl, &[]) {
                Ok(theirs) if theirs == ours => compared += 1,
                Ok(theirs) => failures.push(format!("{pair}: Node.js (-) and postc (+) differ\n{}", diff(&theirs, &ours))),
                Err(e) => failures.push(format!("{pair}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{} pairs differ:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(compared >= 10, "only {compared} pairs were compared");
}

/// Throughput of both engines over the same million-move toolpath.
#[test]
#[ignore = "a measurement, not a test: run with --release -- --ignored --nocapture"]
fn node_vs_postc_speed() {
    let Some(version) = node() else {
        eprintln!("cimco_node: `node` is not installed");
        return;
    };
    let moves: u64 = std::env::var("POSTC_BENCH_MOVES").ok().and_then(|m| m.parse().ok()).unwrap_or(1_000_000);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let jsonl = dir.path().join("zigzag.jsonl");
    let made = Command::new(env!("CARGO_BIN_EXE_postc"))
        .args(["toolpath", "gen", "--pattern", "zigzag", "--moves", &moves.to_string(), "-o"])
        .arg(&jsonl)
        .status()
        .expect("postc toolpath gen");
    assert!(made.success());
    let post_path = corpus().join("posts/cimco/fanuc_mill.js");
    let post = compile(&post_path).expect("fanuc_mill.js compiles");

    // postc: reading the same JSON Lines file, output counted and dropped.
    let mut best_postc = f64::INFINITY;
    let mut events = 0;
    for _ in 0..3 {
        let mut sources = postc_ir::SourceMap::new();
        let mut source = postc_frontends::open_toolpath(&jsonl, &mut sources).expect("the toolpath opens");
        let start = Instant::now();
        let report = postc_runtime::run(&post, &mut source, postc_runtime::Output::discard(), postc_runtime::RunOptions::default())
            .expect("postc posts");
        best_postc = best_postc.min(start.elapsed().as_secs_f64());
        events = report.events;
    }
    // postc over events already read (what Node.js's `post_s` measures).
    let mut sources = postc_ir::SourceMap::new();
    let mut reader = postc_frontends::open_toolpath(&jsonl, &mut sources).expect("the toolpath opens");
    let mut all = Vec::new();
    let mut diags = Vec::new();
    while let Some((e, _)) = postc_ir::EventSource::next_event(&mut reader, &mut diags) {
        all.push(e);
    }
    let mut best_postc_run = f64::INFINITY;
    for _ in 0..3 {
        let mut source = postc_ir::event::VecSource::new(all.clone(), postc_ir::FileId(0));
        let start = Instant::now();
        postc_runtime::run(&post, &mut source, postc_runtime::Output::discard(), postc_runtime::RunOptions::default()).expect("postc posts");
        best_postc_run = best_postc_run.min(start.elapsed().as_secs_f64());
    }
    // Node.js: the referee host over the same file.
    let mut best_total = f64::INFINITY;
    let mut best_post = f64::INFINITY;
    for _ in 0..3 {
        let out = run_node(&post_path, &jsonl, &["--bench"]).expect("node runs");
        let text = String::from_utf8_lossy(&out);
        let field = |name: &str| -> f64 {
            let key = format!("\"{name}\":");
            let at = text.find(&key).map(|i| i + key.len()).unwrap_or(0);
            text[at..].split([',', '}']).next().and_then(|v| v.trim().parse().ok()).unwrap_or(f64::NAN)
        };
        let (parse, post) = (field("parse_s"), field("post_s"));
        best_total = best_total.min(parse + post);
        best_post = best_post.min(post);
    }
    let rate = |s: f64| events as f64 / s;
    println!("CIMCO fanuc_mill.js over a {moves}-move zigzag ({events} events), best of 3, Node.js {version}");
    println!("postc (read JSON Lines + post):   {:>10.0} events/s  ({best_postc:.3} s)", rate(best_postc));
    println!("Node.js (parse JSON Lines + post):{:>10.0} events/s  ({best_total:.3} s)", rate(best_total));
    println!("postc (post only, events read):   {:>10.0} events/s  ({best_postc_run:.3} s)", rate(best_postc_run));
    println!("Node.js (post only, pre-parsed):  {:>10.0} events/s  ({best_post:.3} s)", rate(best_post));
    println!("ratio postc / Node.js (read + post): {:.2}", best_total / best_postc);
    println!("ratio postc / Node.js (post only):   {:.2}", best_post / best_postc_run);
}
