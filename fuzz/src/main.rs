//! `postc-fuzz`: the mutation fuzzer's command line. Runs N mutants over the
//! corpus with a fixed seed and prints a summary; findings are saved with a
//! `replay.sh` each. Exit status 1 when anything was found.
//!
//! ```sh
//! cargo build --release -p postc -p postc-fuzz
//! target/release/postc-fuzz --postc target/release/postc --mutants 100000 --seed 1 --save /tmp/findings
//! ```

use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::Parser;

#[derive(Parser, Debug)]
#[command(
    about = "Mutates postc's inputs and runs its commands on them; reports panics, hangs, memory over the limit, files left behind and diagnostics without a code or position"
)]
struct Args {
    /// The postc binary to run.
    #[arg(long, default_value = "target/release/postc")]
    postc: PathBuf,
    /// The repository root (its corpus/ is read, and ../shared/corpus beside it).
    #[arg(long, default_value = ".")]
    root: PathBuf,
    /// How many mutants.
    #[arg(long, default_value_t = 1000)]
    mutants: u64,
    /// The random seed: the same seed makes the same mutants.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Seconds of processor time one command may use before it counts as
    /// a hang (or six times as many on the clock, busy or not).
    #[arg(long, default_value_t = 10)]
    timeout: u64,
    /// Peak resident memory one command may use, in MiB.
    #[arg(long, default_value_t = 1024)]
    memory: u64,
    /// Save each finding's inputs and a replay.sh here.
    #[arg(long)]
    save: Option<PathBuf>,
    /// Parallel workers (each runs its own mutants, seeded from --seed).
    #[arg(long, default_value_t = 2)]
    jobs: u64,
    /// Mutate only inputs of these kinds (`vectric`, `cimco`, `fusion`,
    /// `vcpost`, `ron`, `jsonl`, `apt`, `probe-table`, `composites`,
    /// `postp`, `lsp`); every kind when not given.
    #[arg(long = "kind")]
    kinds: Vec<String>,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let mut seeds = postc_fuzz::seeds(&args.root);
    seeds.extend(postc_fuzz::jsonl_seed(&args.postc));
    if let Some(unknown) = args.kinds.iter().find(|k| !postc_fuzz::Kind::ALL.iter().any(|kind| kind.name() == *k)) {
        eprintln!("postc-fuzz: no input kind is called `{unknown}`");
        return std::process::ExitCode::from(2);
    }
    seeds.retain(|s| args.kinds.is_empty() || args.kinds.iter().any(|k| k == s.kind.name()));
    if seeds.is_empty() {
        eprintln!("postc-fuzz: no corpus under {}", args.root.display());
        return std::process::ExitCode::from(2);
    }
    let settings = postc_fuzz::Settings {
        postc: std::path::absolute(&args.postc).unwrap_or(args.postc.clone()),
        timeout: Duration::from_secs(args.timeout),
        memory: args.memory << 20,
        save: args.save.clone(),
    };
    let started = Instant::now();
    let jobs = args.jobs.max(1);
    let per_job = args.mutants.div_ceil(jobs);
    let tallies: Vec<postc_fuzz::Tally> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..jobs)
            .map(|j| {
                let (settings, seeds) = (&settings, &seeds);
                let count = per_job.min(args.mutants.saturating_sub(j * per_job));
                let mut settings = settings.clone();
                settings.save = settings.save.map(|p| p.join(format!("worker-{j}")));
                s.spawn(move || {
                    postc_fuzz::fuzz(&settings, seeds, count, args.seed.wrapping_mul(1000).wrapping_add(j), |t| {
                        if j == 0 && t.mutants.is_multiple_of(500) {
                            eprintln!(
                                "postc-fuzz: {} mutants, {} runs, {} findings, {:.0} s",
                                t.mutants * jobs,
                                t.runs * jobs,
                                t.findings.len(),
                                started.elapsed().as_secs_f64()
                            );
                        }
                    })
                })
            })
            .collect();
        handles.into_iter().filter_map(|h| h.join().ok()).collect()
    });
    let mutants: u64 = tallies.iter().map(|t| t.mutants).sum();
    let runs: u64 = tallies.iter().map(|t| t.runs).sum();
    let slowest = tallies.iter().map(|t| t.slowest).max().unwrap_or_default();
    let peak = tallies.iter().map(|t| t.peak_memory).max().unwrap_or_default();
    let mut per_kind = std::collections::BTreeMap::new();
    for t in &tallies {
        for (k, n) in &t.per_kind {
            *per_kind.entry(k.name()).or_insert(0u64) += n;
        }
    }
    let findings: Vec<&postc_fuzz::Finding> = tallies.iter().flat_map(|t| &t.findings).collect();
    let mut by_problem = std::collections::BTreeMap::new();
    for f in &findings {
        *by_problem.entry(f.problem.label()).or_insert(0u64) += 1;
    }
    println!("seed {}: {mutants} mutants, {runs} runs in {:.0} s", args.seed, started.elapsed().as_secs_f64());
    println!("per kind: {per_kind:?}");
    println!("slowest run {:.2} s, peak memory {} MiB", slowest.as_secs_f64(), peak >> 20);
    println!("findings: {} {by_problem:?}", findings.len());
    for f in findings.iter().take(50) {
        println!(
            "  {} ({}, from {}): {}{}",
            f.problem.label(),
            f.kind.name(),
            f.origin.display(),
            f.command,
            f.saved.as_ref().map(|p| format!("  [{}]", p.display())).unwrap_or_default()
        );
        if let postc_fuzz::Problem::NoCode(l) | postc_fuzz::Problem::NoPosition(l) | postc_fuzz::Problem::Crash(l) =
            &f.problem
        {
            println!("      {}", l.chars().take(200).collect::<String>());
        }
    }
    if findings.is_empty() { std::process::ExitCode::SUCCESS } else { std::process::ExitCode::from(1) }
}
