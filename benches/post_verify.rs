//! Whole-job wall time of `postc post` with its default verification
//! against `--no-verify`: the command a user runs, as a process, over a
//! 1,000,000-move JSON Lines toolpath (`postc toolpath gen --pattern mixed`),
//! writing the program to a file.
//!
//! Each criterion sample runs the pair in turn, `--no-verify` then the
//! default, so that whatever else the machine is doing weighs on both
//! alike; criterion times the verified run, and the bench prints, for each
//! post, the medians of both and their ratio (docs/performance.md,
//! "Verifying while posting"). The bar: the ratio at most 1.15 on two cores.
//!
//! `cargo bench --bench post_verify`; `POSTC_BENCH_MOVES` changes the
//! toolpath's length (1000000).

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};

const POSTS: &[&str] = &["corpus/posts/vectric/gcode_mm.pp", "corpus/posts/cimco/fanuc_mill.js"];

fn postc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_postc"))
}

/// How long one `postc post` takes; panics when it fails.
fn time(post: &Path, toolpath: &Path, out: &Path, extra: &[&str]) -> Duration {
    let start = Instant::now();
    let o = postc().arg("post").arg(post).arg(toolpath).arg("-o").arg(out).args(extra).output().unwrap();
    let took = start.elapsed();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    took
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn bench(c: &mut Criterion) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    // `cargo test --benches` runs each benchmark once, without `--bench`: a short toolpath then.
    let full = std::env::args().any(|a| a == "--bench");
    let moves: u64 = std::env::var("POSTC_BENCH_MOVES").ok().and_then(|v| v.parse().ok()).unwrap_or(if full {
        1_000_000
    } else {
        1_000
    });
    let dir = tempfile::tempdir().unwrap();
    let toolpath = dir.path().join("mixed.jsonl");
    let o = postc()
        .args(["toolpath", "gen", "--pattern", "mixed", "--moves", &moves.to_string(), "-o"])
        .arg(&toolpath)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = dir.path().join("out.nc");
    let mut group = c.benchmark_group(format!("post_verify_{moves}"));
    group.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(20));
    let mut ratios = Vec::new();
    for post in POSTS {
        let post = root.join(post);
        let name = post.file_name().unwrap().to_string_lossy().into_owned();
        let runs = RefCell::new((Vec::new(), Vec::new()));
        group.bench_function(&name, |b| {
            b.iter_custom(|iters| {
                let mut verified = Duration::ZERO;
                for _ in 0..iters {
                    let plain = time(&post, &toolpath, &out, &["--no-verify"]);
                    let with = time(&post, &toolpath, &out, &[]);
                    let mut runs = runs.borrow_mut();
                    runs.0.push(plain.as_secs_f64());
                    runs.1.push(with.as_secs_f64());
                    verified += with;
                }
                verified
            })
        });
        let (plain, with) = runs.into_inner();
        let pairs = plain.len();
        let (p, v) = (median(plain), median(with));
        ratios.push(format!(
            "{name}: {pairs} pairs over {moves} moves, medians --no-verify {p:.3} s, verified {v:.3} s, ratio {:.3}",
            v / p
        ));
    }
    group.finish();
    for line in ratios {
        println!("{line}");
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
