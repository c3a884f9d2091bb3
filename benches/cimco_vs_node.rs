//! CIMCO posting against Node.js: `corpus/posts/cimco/fanuc_mill.js` over
//! the same synthetic zigzag (1,000,000 moves, or `POSTC_BENCH_MOVES`),
//! written as JSON Lines, in postc and in the Node.js referee host of
//! `tests/node_host/`. Best of three runs of each, measured in one run;
//! the target is a ratio of at least 2 (docs/performance.md).
//!
//! `cargo bench --bench cimco_vs_node` (says so and stops when `node` is
//! not installed).

#[path = "../tests/support/mod.rs"]
mod support;

use std::io::Write;
use std::time::Instant;

use postc_frontends::native::{Syntax, write_event};
use postc_ir::EventSource;
use postc_runtime::Output;
use support::cimco::{compile, corpus, node, run_node};

fn best_of_three(mut f: impl FnMut() -> f64) -> f64 {
    (0..3).map(|_| f()).fold(f64::INFINITY, f64::min)
}

fn main() {
    // `cargo bench` passes --bench; `cargo test --benches` runs this too: measure only for cargo bench.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let Some(version) = node() else {
        println!("cimco_vs_node: `node` is not installed; nothing measured");
        return;
    };
    let moves: u64 = std::env::var("POSTC_BENCH_MOVES").ok().and_then(|m| m.parse().ok()).unwrap_or(1_000_000);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let jsonl = dir.path().join("zigzag.jsonl");
    {
        let mut file = std::io::BufWriter::new(std::fs::File::create(&jsonl).expect("the toolpath file"));
        let mut generator = postc_frontends::synthetic::Synthetic::new("zigzag", moves).expect("the zigzag pattern");
        let (mut line, mut diags) = (String::new(), Vec::new());
        while let Some((event, _)) = generator.next_event(&mut diags) {
            line.clear();
            write_event(&event, Syntax::JsonLines, &mut line);
            file.write_all(line.as_bytes()).expect("the toolpath is written");
        }
    }
    let post_path = corpus().join("posts/cimco/fanuc_mill.js");
    let post = compile(&post_path).expect("fanuc_mill.js compiles");

    let mut events = 0;
    let postc_total = best_of_three(|| {
        let mut sources = postc_report::source_map();
        let mut source = postc_frontends::open_toolpath(&jsonl, &mut sources).expect("the toolpath opens");
        let start = Instant::now();
        let report = postc_runtime::run(&post, &mut source, Output::discard(), postc_frontends::run_options(&post))
            .expect("postc posts");
        events = report.events;
        start.elapsed().as_secs_f64()
    });
    let mut sources = postc_report::source_map();
    let mut reader = postc_frontends::open_toolpath(&jsonl, &mut sources).expect("the toolpath opens");
    let (mut all, mut diags) = (Vec::new(), Vec::new());
    while let Some((e, _)) = reader.next_event(&mut diags) {
        all.push(e);
    }
    let postc_post = best_of_three(|| {
        let mut source = postc_ir::event::VecSource::new(all.clone(), postc_ir::FileId(0));
        let start = Instant::now();
        postc_runtime::run(&post, &mut source, Output::discard(), postc_frontends::run_options(&post))
            .expect("postc posts");
        start.elapsed().as_secs_f64()
    });
    let (mut node_total, mut node_post) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..3 {
        let out = run_node(&post_path, &jsonl, &["--bench"]).expect("node runs");
        let text = String::from_utf8_lossy(&out);
        let field = |name: &str| -> f64 {
            let key = format!("\"{name}\":");
            let at = text.find(&key).map(|i| i + key.len()).unwrap_or(0);
            text[at..].split([',', '}']).next().and_then(|v| v.trim().parse().ok()).unwrap_or(f64::NAN)
        };
        let (parse, post) = (field("parse_s"), field("post_s"));
        node_total = node_total.min(parse + post);
        node_post = node_post.min(post);
    }
    let rate = |s: f64| events as f64 / s;
    println!("CIMCO fanuc_mill.js over a {moves}-move zigzag ({events} events), best of 3, Node.js {version}");
    println!("postc (read JSON Lines + post):   {:>10.0} events/s  ({postc_total:.3} s)", rate(postc_total));
    println!("Node.js (parse JSON Lines + post):{:>10.0} events/s  ({node_total:.3} s)", rate(node_total));
    println!("postc (post only, events read):   {:>10.0} events/s  ({postc_post:.3} s)", rate(postc_post));
    println!("Node.js (post only, pre-parsed):  {:>10.0} events/s  ({node_post:.3} s)", rate(node_post));
    println!("ratio postc / Node.js (read + post): {:.2}", node_total / postc_total);
    println!("ratio postc / Node.js (post only):   {:.2}", node_post / postc_post);
}
