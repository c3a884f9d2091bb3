//! CIMCO posting against Node.js: every post of `corpus/posts/cimco/`, in
//! postc and in the Node.js referee host of `tests/node_host/`, over the
//! same toolpath written as JSON Lines, measured in one run.
//!
//! Milling posts post the synthetic zigzag (1,000,000 moves, or
//! `POSTC_BENCH_MOVES`). Lathe posts post a turning toolpath of as many
//! moves: the finishing profile of `corpus/toolpaths/cimco/lathe.ron`
//! (rapids, feeds and ZX arcs) repeated; the zigzag is an XY job, and a
//! lathe post given it would turn every XY arc into chords and every Y
//! into nothing, which measures no lathe program.
//!
//! For each post: postc reading the JSON Lines (on a thread of its own,
//! as `open_toolpath` reads for `postc post`) and posting, postc posting
//! events already read, Node.js parsing and posting, Node.js posting events
//! already parsed; best of three runs each (`POSTC_BENCH_RUNS`), the two
//! engines measured back to back within each run;
//! `POSTC_BENCH_POSTS=mach3_field,okuma_field` measures only those posts. The table
//! gives both times, the ratio (Node.js time / postc time) and postc's
//! moves per second; it asserts nothing about time. The program sizes of
//! the two engines are compared and a difference is flagged.
//!
//! `cargo bench --bench cimco_vs_node` (says so and stops when `node` is
//! not installed). docs/performance.md has the numbers.

#[path = "../tests/support/mod.rs"]
mod support;

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use postc_ir::event::Event;
use postc_ir::{EventSource, Post};
use postc_reader_native::{Syntax, write_event};
use postc_runtime::Output;
use support::cimco::{compile, corpus, node, posts, run_node, stem};

/// Writes events as JSON Lines.
fn write_jsonl(target: &Path, events: impl Iterator<Item = Event>) {
    let mut file = std::io::BufWriter::new(std::fs::File::create(target).expect("the toolpath file"));
    let mut line = String::new();
    for event in events {
        line.clear();
        write_event(&event, Syntax::JsonLines, &mut line);
        file.write_all(line.as_bytes()).expect("the toolpath is written");
    }
}

fn read_events(path: &Path) -> Vec<Event> {
    let mut sources = postc_report::source_map();
    let mut reader = postc_driver::open_toolpath(path, &mut sources).expect("the toolpath opens");
    let (mut all, mut diags) = (Vec::new(), Vec::new());
    while let Some((e, _)) = reader.next_event(&mut diags) {
        all.push(e);
    }
    all
}

fn is_move(e: &Event) -> bool {
    matches!(e, Event::Rapid(_) | Event::Feed(_) | Event::Arc(_))
}

/// The turning job: the lathe corpus job's first toolpath, its moves
/// repeated until there are `moves` of them.
fn turning_events(moves: u64) -> Vec<Event> {
    let job = read_events(&corpus().join("toolpaths/cimco/lathe.ron"));
    let start = job.iter().position(|e| matches!(e, Event::ToolpathStart(_))).expect("a toolpath");
    let end = start + job[start..].iter().position(|e| matches!(e, Event::ToolpathEnd)).expect("its end");
    let body: Vec<&Event> = job[start + 1..end].iter().filter(|e| is_move(e)).collect();
    let mut out: Vec<Event> = job[..=start].to_vec();
    for i in 0..moves as usize {
        out.push(body[i % body.len()].clone());
    }
    out.push(Event::ToolpathEnd);
    out.push(Event::End);
    out
}

struct Row {
    post: String,
    toolpath: &'static str,
    moves: u64,
    postc_total: f64,
    postc_post: f64,
    node_total: f64,
    node_post: f64,
    same_size: bool,
}

fn measure(post_path: &Path, post: &Post, jsonl: &Path, events: &[Event], runs: usize) -> (f64, f64, f64, f64, bool) {
    let mut bytes = 0;
    let (mut postc_total, mut postc_post) = (f64::INFINITY, f64::INFINITY);
    let (mut node_total, mut node_post, mut node_bytes) = (f64::INFINITY, f64::INFINITY, f64::NAN);
    // Each run measures both engines back to back, so that a busy spell of
    // the machine falls on both rather than on one engine's runs.
    for _ in 0..runs {
        let mut sources = postc_report::source_map();
        let mut source = postc_driver::open_toolpath(jsonl, &mut sources).expect("the toolpath opens");
        let start = Instant::now();
        let report = postc_runtime::run(post, &mut source, Output::discard(), postc_driver::run_options(post))
            .expect("postc posts");
        postc_total = postc_total.min(start.elapsed().as_secs_f64());
        bytes = report.bytes;

        let mut source = postc_ir::event::VecSource::new(events.to_vec(), postc_ir::FileId(0));
        let start = Instant::now();
        postc_runtime::run(post, &mut source, Output::discard(), postc_driver::run_options(post)).expect("postc posts");
        postc_post = postc_post.min(start.elapsed().as_secs_f64());

        let out = run_node(post_path, jsonl, &["--bench"]).expect("node runs");
        let text = String::from_utf8_lossy(&out);
        let field = |name: &str| -> f64 {
            let key = format!("\"{name}\":");
            let at = text.find(&key).map(|i| i + key.len()).unwrap_or(0);
            text[at..].split([',', '}']).next().and_then(|v| v.trim().parse().ok()).unwrap_or(f64::NAN)
        };
        let (parse, post) = (field("parse_s"), field("post_s"));
        node_total = node_total.min(parse + post);
        node_post = node_post.min(post);
        node_bytes = field("bytes");
    }
    (postc_total, postc_post, node_total, node_post, node_bytes == bytes as f64)
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
    let runs: usize = std::env::var("POSTC_BENCH_RUNS").ok().and_then(|m| m.parse().ok()).unwrap_or(3).max(1);
    let dir = tempfile::tempdir().expect("a temporary folder");

    let zigzag = dir.path().join("zigzag.jsonl");
    let mut generator = postc_reader_synthetic::Synthetic::new("zigzag", moves).expect("the zigzag pattern");
    let mut diags = Vec::new();
    write_jsonl(&zigzag, std::iter::from_fn(|| generator.next_event(&mut diags).map(|(e, _)| e)));
    let zigzag_events = read_events(&zigzag);
    let zigzag_moves = zigzag_events.iter().filter(|e| is_move(e)).count() as u64;

    let turning = dir.path().join("turning.jsonl");
    let turning_events = turning_events(moves);
    write_jsonl(&turning, turning_events.iter().cloned());
    let turning_moves = turning_events.iter().filter(|e| is_move(e)).count() as u64;

    println!(
        "CIMCO posts, postc against Node.js {version}: {zigzag_moves}-move zigzag (milling), \
         {turning_moves}-move turning job (lathe), best of {runs}"
    );
    let mut rows = Vec::new();
    // `POSTC_BENCH_POSTS=mach3_field,okuma_field`: only those posts.
    let only: Option<Vec<String>> =
        std::env::var("POSTC_BENCH_POSTS").ok().map(|s| s.split(',').map(|p| p.trim().to_string()).collect());
    for post_path in posts() {
        if let Some(only) = &only
            && !only.iter().any(|p| stem(&post_path) == *p)
        {
            continue;
        }
        let post = compile(&post_path).expect("the corpus post compiles");
        let (jsonl, events, toolpath, moves) = if post.options.lathe {
            (&turning, &turning_events, "turning", turning_moves)
        } else {
            (&zigzag, &zigzag_events, "zigzag", zigzag_moves)
        };
        let (postc_total, postc_post, node_total, node_post, same_size) =
            measure(&post_path, &post, jsonl, events, runs);
        let row = Row {
            post: format!("{}.js", stem(&post_path)),
            toolpath,
            moves,
            postc_total,
            postc_post,
            node_total,
            node_post,
            same_size,
        };
        eprintln!(
            "{}: postc {:.3} s / {:.3} s, Node.js {:.3} s / {:.3} s",
            row.post, row.postc_total, row.postc_post, row.node_total, row.node_post
        );
        rows.push(row);
    }

    println!();
    println!("| post | toolpath | work | postc | Node.js | ratio | postc moves/s |");
    println!("|---|---|---|---|---|---|---|");
    for r in &rows {
        let flag = if r.same_size { "" } else { " (program sizes differ!)" };
        for (work, ours, theirs) in
            [("read + post", r.postc_total, r.node_total), ("post only", r.postc_post, r.node_post)]
        {
            println!(
                "| {}{flag} | {} | {work} | {ours:.3} s | {theirs:.3} s | {:.2} | {:.0} |",
                r.post,
                r.toolpath,
                theirs / ours,
                r.moves as f64 / ours
            );
        }
    }
}
