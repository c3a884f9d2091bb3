//! A short fixed-seed pass of the mutation fuzzer (`fuzz/`, `postc-fuzz`)
//! over every input kind: no panic, crash, hang, run over 1 GiB, file left
//! behind or diagnostic without a code or position. docs/reliability.md
//! records the long runs.

use std::path::PathBuf;
use std::time::Duration;

#[test]
fn a_short_fixed_seed_pass_finds_nothing() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let postc = PathBuf::from(env!("CARGO_BIN_EXE_postc"));
    let mut seeds = postc_fuzz::seeds(&root);
    seeds.extend(postc_fuzz::jsonl_seed(&postc));
    let kinds: std::collections::BTreeSet<_> = seeds.iter().map(|s| s.kind).collect();
    assert_eq!(kinds.len(), postc_fuzz::Kind::ALL.len(), "every input kind has seeds: {kinds:?}");
    // A debug build runs several times slower than the release build the
    // long runs use: the time limit is that much longer.
    let settings = postc_fuzz::Settings { postc, timeout: Duration::from_secs(30), memory: 1 << 30, save: None };
    let tally = postc_fuzz::fuzz(&settings, &seeds, 150, 20261129, |_| {});
    let found: Vec<String> = tally
        .findings
        .iter()
        .map(|f| format!("{:?} ({}, from {}): {}", f.problem, f.kind.name(), f.origin.display(), f.command))
        .collect();
    assert!(found.is_empty(), "{} findings:\n{}", found.len(), found.join("\n"));
    assert_eq!(tally.mutants, 150);
}

/// A saved finding says what was found, in its `replay.sh`: a run given
/// no time at all is a hang.
#[test]
fn a_saved_finding_says_what_was_found() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let postc = PathBuf::from(env!("CARGO_BIN_EXE_postc"));
    let seeds: Vec<_> =
        postc_fuzz::seeds(&root).into_iter().filter(|s| s.kind == postc_fuzz::Kind::Vectric).take(1).collect();
    let saved = tempfile::tempdir().expect("a temporary folder");
    let settings = postc_fuzz::Settings {
        postc,
        timeout: Duration::from_nanos(1),
        memory: 1 << 30,
        save: Some(saved.path().to_path_buf()),
    };
    let tally = postc_fuzz::fuzz(&settings, &seeds, 1, 7, |_| {});
    assert!(!tally.findings.is_empty(), "a run with no time is a hang");
    let replay = std::fs::read_to_string(saved.path().join("finding-0000/replay.sh")).expect("replay.sh is saved");
    assert!(replay.contains("# found: Hang, a vectric mutant of "), "{replay}");
    assert!(replay.contains("postc "), "{replay}");
}

/// A run's processor time is read from `/proc/PID/stat` after the command
/// name, which may hold blanks and parentheses: 1/100 s ticks of user and
/// system time.
#[test]
fn processor_time_is_read_after_the_command_name() {
    let stat = "4242 (postc (x) y) R 1 4242 4242 0 -1 4194304 120 0 0 0 731 69 0 0 20 0 1 0 100 1000 50";
    assert_eq!(postc_fuzz::processor_time_of(stat), Some(Duration::from_millis(8000)));
    assert_eq!(postc_fuzz::processor_time_of("4242 (postc) R 1"), None);
}

/// `check --format json` keeps every diagnostic (floods of diagnostics): a post
/// with 50,000 characters JavaScript does not allow prints one item for
/// each, over 8 MiB of valid JSON, which the fuzzer reads whole (it read
/// 8 MiB, and took a cut array for JSON that was not: seed 20261202).
#[test]
fn a_flood_of_json_diagnostics_is_valid_json_the_fuzzer_reads_whole() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post = dir.path().join("flood.js");
    std::fs::write(&post, format!("function onOpen() {{\n{}\n}}\n", "\u{a4} ".repeat(50_000))).expect("write");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_postc"))
        .args(["check", "--format", "json"])
        .arg(&post)
        .output()
        .expect("run postc");
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.len() > 8 << 20, "{} bytes", o.stdout.len());
    let items: Vec<serde_json::Value> = serde_json::from_slice(&o.stdout).expect("a JSON array");
    assert!(items.len() >= 50_000, "{} items", items.len());
    assert!(postc_fuzz::json_problem(&o.stdout).is_none());
}
