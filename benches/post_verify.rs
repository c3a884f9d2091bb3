//! Whole-job wall time of `postc post` with its default verification
//! against `--no-verify`: the command a user runs, as a process, over a
//! 1,000,000-move JSON Lines toolpath (`postc toolpath gen --pattern mixed`),
//! writing the program to a file.
//!
//! The two are run in turn, pair after pair, so that whatever else the
//! machine is doing weighs on both alike; the medians and their ratio are
//! printed (docs/performance.md, "Verifying while posting"). The bar: the
//! ratio at most 1.15.
//!
//! `cargo bench --bench post_verify`; `POSTC_BENCH_MOVES` and
//! `POSTC_BENCH_PAIRS` change the toolpath's length (1000000) and the pairs
//! run per post (7).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const POSTS: &[&str] = &["corpus/posts/vectric/gcode_mm.pp", "corpus/posts/cimco/fanuc_mill.js"];

fn postc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_postc"))
}

/// Seconds one `postc post` takes; panics when it fails.
fn time(post: &Path, toolpath: &Path, out: &Path, extra: &[&str]) -> f64 {
    let start = Instant::now();
    let o = postc().arg("post").arg(post).arg(toolpath).arg("-o").arg(out).args(extra).output().unwrap();
    let seconds = start.elapsed().as_secs_f64();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    seconds
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

fn main() {
    // `cargo test --benches` runs bench targets with `--bench` absent: stay quick then.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let moves = env("POSTC_BENCH_MOVES", 1_000_000);
    let pairs = env("POSTC_BENCH_PAIRS", 7).max(1);
    let dir = tempfile::tempdir().unwrap();
    let toolpath = dir.path().join("m.jsonl");
    let o = postc()
        .args(["toolpath", "gen", "--pattern", "mixed", "--moves", &moves.to_string(), "-o"])
        .arg(&toolpath)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = dir.path().join("out.nc");
    println!("postc post over {moves} moves (mixed), {pairs} pairs each, medians:");
    for post in POSTS {
        let post = root.join(post);
        // Once each, untimed: the files in the page cache, the output checked.
        time(&post, &toolpath, &out, &["--no-verify"]);
        time(&post, &toolpath, &out, &[]);
        let (mut plain, mut verified) = (Vec::new(), Vec::new());
        for _ in 0..pairs {
            plain.push(time(&post, &toolpath, &out, &["--no-verify"]));
            verified.push(time(&post, &toolpath, &out, &[]));
        }
        let (p, v) = (median(plain), median(verified));
        let name = post.file_name().unwrap().to_string_lossy();
        println!("{name:>16}: --no-verify {p:.3} s, verified {v:.3} s, ratio {:.3}", v / p);
    }
}
