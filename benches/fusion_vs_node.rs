//! Fusion `.cps` posting against Node.js: the real posts of
//! `../shared/corpus/fusion/`, each run as a user runs it, as a process,
//! over the same milling toolpath written as JSON Lines, measured in one
//! run: `postc post POST job.jsonl -o out.nc --no-verify` against
//! `node tests/node_host/fusion.js POST job.jsonl` (the Node.js Fusion
//! host of the tests, which drives the same host API from the events).
//!
//! The toolpath is `postc toolpath gen --pattern mixed` (1,000,000 moves,
//! or `POSTC_BENCH_MOVES`: feeds, rapids and XY arcs). A post is measured
//! when both engines post a 1,000-move job of the same pattern with the
//! same bytes (the others are counted, not timed: a post that refuses the
//! job, or that postc does not run); then each engine posts the long job,
//! best of `POSTC_BENCH_RUNS` (1), the two back to back within a run so
//! that a busy spell weighs on both. `POSTC_BENCH_POSTS=haas,linuxcnc`
//! measures only the posts whose file stem is named. The table gives both
//! times, the ratio (Node.js time / postc time) and postc's moves per
//! second, and flags programs of different sizes; it asserts nothing
//! about time.
//!
//! `cargo bench --bench fusion_vs_node` (says so and stops when `node` or
//! the shared corpus is missing). docs/performance.md has the numbers.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

fn postc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_postc"))
}

fn generate(moves: u64, target: &Path) {
    let o = postc()
        .args(["toolpath", "gen", "--pattern", "mixed", "--moves", &moves.to_string(), "-o"])
        .arg(target)
        .output()
        .expect("postc runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// postc's program and wall time, or `None` when it refuses.
fn run_postc(post: &Path, job: &Path, out: &Path) -> Option<(Vec<u8>, f64)> {
    let start = Instant::now();
    let o = postc()
        .arg("post")
        .arg(post)
        .arg(job)
        .arg("-o")
        .arg(out)
        .args(["--no-verify", "-q"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .ok()?;
    let took = start.elapsed().as_secs_f64();
    o.success().then(|| (std::fs::read(out).unwrap_or_default(), took))
}

/// Node.js's program and wall time, or `None` when it stops. Node.js
/// starts without the extra CA certificates a machine may name in
/// `NODE_EXTRA_CA_CERTS`: reading them is no part of running a post, and
/// would count against Node.js.
fn run_node(script: &Path, post: &Path, job: &Path) -> Option<(Vec<u8>, f64)> {
    let start = Instant::now();
    let o = Command::new("node")
        .env_remove("NODE_EXTRA_CA_CERTS")
        .arg(script)
        .arg(post)
        .arg(job)
        .stderr(Stdio::null())
        .output()
        .ok()?;
    let took = start.elapsed().as_secs_f64();
    o.status.success().then_some((o.stdout, took))
}

fn main() {
    // `cargo bench` passes --bench; `cargo test --benches` runs this too: measure only for cargo bench.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let corpus = root.join("../shared/corpus/fusion");
    let version = Command::new("node").arg("--version").output().ok().filter(|o| o.status.success());
    let Some(version) = version.map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string()) else {
        println!("fusion_vs_node: `node` is not installed; nothing measured");
        return;
    };
    if !corpus.is_dir() {
        println!("fusion_vs_node: {} is missing; nothing measured", corpus.display());
        return;
    }
    let moves: u64 = std::env::var("POSTC_BENCH_MOVES").ok().and_then(|m| m.parse().ok()).unwrap_or(1_000_000);
    let runs: usize = std::env::var("POSTC_BENCH_RUNS").ok().and_then(|m| m.parse().ok()).unwrap_or(1).max(1);
    let only: Option<Vec<String>> =
        std::env::var("POSTC_BENCH_POSTS").ok().map(|s| s.split(',').map(|p| p.trim().to_string()).collect());
    let script = root.join("tests/node_host/fusion.js");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let (short, long) = (dir.path().join("short.jsonl"), dir.path().join("long.jsonl"));
    generate(1_000, &short);
    generate(moves, &long);
    let out = dir.path().join("out.nc");

    println!("Fusion posts, postc against Node.js {version}: {moves}-move mixed milling job, best of {runs}");
    let (mut refused, mut differ) = (0, Vec::new());
    let mut rows = Vec::new();
    for post in postc_fuzz::files(&corpus, &[".cps"]) {
        let name = post.strip_prefix(&corpus).unwrap_or(&post).display().to_string();
        let stem = post.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        if only.as_ref().is_some_and(|o| !o.contains(&stem)) {
            continue;
        }
        let (Some((ours, _)), Some((theirs, _))) = (run_postc(&post, &short, &out), run_node(&script, &post, &short))
        else {
            refused += 1;
            continue;
        };
        if ours != theirs {
            differ.push(name);
            continue;
        }
        let (mut postc_s, mut node_s, mut same_size) = (f64::INFINITY, f64::INFINITY, true);
        for _ in 0..runs {
            let (Some((ours, a)), Some((theirs, b))) = (run_postc(&post, &long, &out), run_node(&script, &post, &long))
            else {
                break;
            };
            same_size &= ours.len() == theirs.len();
            postc_s = postc_s.min(a);
            node_s = node_s.min(b);
        }
        eprintln!("{name}: postc {postc_s:.3} s, Node.js {node_s:.3} s");
        rows.push((name, postc_s, node_s, same_size));
    }

    println!();
    println!("| post | postc | Node.js | ratio | postc moves/s |");
    println!("|---|---|---|---|---|");
    for (name, ours, theirs, same_size) in &rows {
        let flag = if *same_size { "" } else { " (program sizes differ!)" };
        println!("| {name}{flag} | {ours:.3} s | {theirs:.3} s | {:.2} | {:.0} |", theirs / ours, moves as f64 / ours);
    }
    let mut ratios: Vec<f64> = rows.iter().map(|(_, a, b, _)| b / a).collect();
    ratios.sort_by(f64::total_cmp);
    if !ratios.is_empty() {
        let at_3 = ratios.iter().filter(|r| **r >= 3.0).count();
        let fast = rows.iter().filter(|(_, a, ..)| moves as f64 / a >= 1e6).count();
        println!(
            "\n{} posts measured: ratio min {:.2}, median {:.2}, max {:.2}; {at_3} at 3x Node.js or more; {fast} at 1 M moves/s or more",
            ratios.len(),
            ratios[0],
            ratios[ratios.len() / 2],
            ratios[ratios.len() - 1]
        );
    }
    println!(
        "{refused} posts not measured (refused by either engine over the short job); {} whose short programs differ: {}",
        differ.len(),
        differ.join(", ")
    );
}
