//! # postc-fuzz
//!
//! A mutation fuzzer of the postc command line. It takes every input kind a
//! user hands postc from the corpus (Vectric, CIMCO and VcPost posts; RON,
//! JSON Lines and APT CL toolpaths; probe tables; composites files; `postp`
//! folders; language-server frames), mutates it, runs the commands a user
//! runs on it (`check`, `post -o`, `convert -o`, `postp`, `lsp`) in a folder
//! of its own, and reports what a professional tool must never do:
//!
//! - a panic, or a crash by a signal;
//! - a hang: a run longer than the time limit;
//! - a run whose memory (peak resident set) goes over the limit;
//! - a file left behind: anything in the run's folder but its inputs, and,
//!   when the command succeeded, the outputs it was asked for;
//! - a diagnostic without a code (`error[XX000]`), or, in `check --format
//!   json`, without a line and column.
//!
//! Each finding is saved with its inputs and a `replay.sh` that runs the
//! same command. Mutants are made from a seed, so a run is reproducible.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What an input is, which decides the commands run on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    Vectric,
    Cimco,
    /// An Autodesk Fusion `.cps` post (the shared corpus's real posts).
    Fusion,
    VcPost,
    Ron,
    Jsonl,
    Apt,
    ProbeTable,
    Composites,
    Postp,
    Lsp,
}

impl Kind {
    pub const ALL: [Kind; 11] = [
        Kind::Vectric,
        Kind::Cimco,
        Kind::Fusion,
        Kind::VcPost,
        Kind::Ron,
        Kind::Jsonl,
        Kind::Apt,
        Kind::ProbeTable,
        Kind::Composites,
        Kind::Postp,
        Kind::Lsp,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Vectric => "vectric",
            Kind::Cimco => "cimco",
            Kind::Fusion => "fusion",
            Kind::VcPost => "vcpost",
            Kind::Ron => "ron",
            Kind::Jsonl => "jsonl",
            Kind::Apt => "apt",
            Kind::ProbeTable => "probe-table",
            Kind::Composites => "composites",
            Kind::Postp => "postp",
            Kind::Lsp => "lsp",
        }
    }
}

/// One corpus file to mutate, with the file it runs beside (the post of a
/// probe table or composites file, the toolpath a post is run over).
#[derive(Clone, Debug)]
pub struct Seed {
    pub kind: Kind,
    /// The name the mutant is written under (its extension matters).
    pub file_name: String,
    /// Where the seed comes from, for reports.
    pub origin: PathBuf,
    pub bytes: Vec<u8>,
    /// A companion input, written unmutated: (file name, bytes).
    pub companion: Option<(String, Vec<u8>)>,
}

/// Seeds larger than this are left out: a mutant is run several times.
const MAX_SEED_BYTES: u64 = 256 * 1024;

fn read_small(path: &Path) -> Option<Vec<u8>> {
    let meta = std::fs::metadata(path).ok()?;
    (meta.is_file() && meta.len() <= MAX_SEED_BYTES).then(|| std::fs::read(path).ok()).flatten()
}

/// Files under `dir` (recursively) whose name ends with one of `exts`
/// (case-insensitive), sorted.
#[doc(hidden)]
pub fn files(dir: &Path, exts: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let name = p.file_name().map(|n| n.to_string_lossy().to_lowercase()).unwrap_or_default();
                if exts.iter().any(|x| name.ends_with(x)) {
                    out.push(p);
                }
            }
        }
    }
    out.sort();
    out
}

fn name_of(path: &Path) -> String {
    path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
}

/// The seeds of every kind: the repository's corpus at `root`, and the
/// shared corpus of real files beside it (`root/../shared/corpus`) when it
/// is there. `standard` is the toolpath posts run over.
pub fn seeds(root: &Path) -> Vec<Seed> {
    let corpus = root.join("corpus");
    let shared = root.join("../shared/corpus");
    let toolpath = read_small(&corpus.join("toolpaths/standard.ron")).unwrap_or_default();
    let beside = || Some(("standard.ron".to_string(), toolpath.clone()));
    let mut out = Vec::new();
    let mut add = |kind: Kind, path: &Path, file_name: String, companion: Option<(String, Vec<u8>)>| {
        if let Some(bytes) = read_small(path) {
            out.push(Seed { kind, file_name, origin: path.to_path_buf(), bytes, companion });
        }
    };
    for p in files(&corpus.join("posts/vectric"), &[".pp"]).iter().chain(&files(&shared.join("vectric"), &[".pp"])) {
        add(Kind::Vectric, p, "post.pp".into(), beside());
    }
    for p in files(&corpus.join("posts/cimco"), &[".js"]) {
        add(Kind::Cimco, &p, "post.js".into(), beside());
    }
    for p in files(&shared.join("fusion"), &[".cps"]) {
        add(Kind::Fusion, &p, "post.cps".into(), beside());
    }
    for p in files(&corpus.join("posts/vcpost"), &[".vcpost"])
        .iter()
        .chain(&files(&corpus.join("posts/postp"), &[".vcpost"]))
    {
        add(Kind::VcPost, p, "post.VcPost".into(), beside());
    }
    for p in files(&corpus.join("toolpaths"), &[".ron"]) {
        add(Kind::Ron, &p, "toolpath.ron".into(), None);
    }
    for p in files(&corpus.join("toolpaths"), &[".jsonl"]) {
        add(Kind::Jsonl, &p, "toolpath.jsonl".into(), None);
    }
    for p in files(&corpus.join("toolpaths/apt"), &[".apt"])
        .iter()
        .chain(&files(&shared.join("apt"), &[".apt", ".cl", ".cls", ".clsf", ".ncl", ".clt", ".aptsource", ".tap"]))
    {
        let ext = p.extension().map(|e| e.to_string_lossy().to_lowercase()).unwrap_or_else(|| "apt".into());
        let ext = if ["apt", "cl", "cls", "ncl", "clt"].contains(&ext.as_str()) { ext } else { "apt".into() };
        add(Kind::Apt, p, format!("toolpath.{ext}"), None);
        add(Kind::Postp, p, "cl.tap".into(), None);
    }
    for p in files(&corpus.join("probe"), &[".csv"]) {
        let post = name_of(&p).split("__").next().unwrap_or_default().to_string();
        let post_bytes = read_small(&corpus.join("posts/vcpost").join(format!("{post}.VcPost")));
        add(Kind::ProbeTable, &p, "table.csv".into(), post_bytes.map(|b| ("post.VcPost".to_string(), b)));
    }
    for p in files(&corpus.join("composites"), &[".vcp.ron", ".vcp.jsonl"]) {
        let name = name_of(&p);
        let post = name.split("__").next().unwrap_or_default().to_string();
        let post_bytes = read_small(&corpus.join("posts/vcpost").join(format!("{post}.VcPost")));
        let ext = if name.ends_with(".jsonl") { "vcp.jsonl" } else { "vcp.ron" };
        add(Kind::Composites, &p, format!("events.{ext}"), post_bytes.map(|b| ("post.VcPost".to_string(), b)));
    }
    // Language-server frames open a post: one of each dialect.
    for (dir, ext) in [("posts/vectric", ".pp"), ("posts/cimco", ".js"), ("posts/vcpost", ".vcpost")] {
        if let Some(p) = files(&corpus.join(dir), &[ext]).first() {
            add(Kind::Lsp, p, format!("post{}", if ext == ".vcpost" { ".VcPost" } else { ext }), None);
        }
    }
    out
}

/// A JSON Lines toolpath seed, made by `postc toolpath gen` (the corpus
/// keeps its toolpaths as RON).
pub fn jsonl_seed(postc: &Path) -> Option<Seed> {
    let dir = tempfile::tempdir().ok()?;
    let path = dir.path().join("mixed.jsonl");
    let status = Command::new(postc)
        .args(["toolpath", "gen", "--pattern", "mixed", "--moves", "300", "-o"])
        .arg(&path)
        .stderr(Stdio::null())
        .status()
        .ok()?;
    let bytes = std::fs::read(&path).ok().filter(|_| status.success())?;
    Some(Seed {
        kind: Kind::Jsonl,
        file_name: "toolpath.jsonl".into(),
        origin: PathBuf::from("postc toolpath gen --pattern mixed --moves 300"),
        bytes,
        companion: None,
    })
}

/// Numbers that have broken parsers and formatters.
const NUMBERS: &[&str] = &[
    "0",
    "-0",
    "1e308",
    "-1e308",
    "1e-320",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "Infinity",
    "99999999999999999999999",
    "4294967296",
    "-2147483649",
    "0x10",
    "1.",
    ".5",
    "-",
    "1e",
    "1..2",
    "18446744073709551615",
];

/// Bytes that mean something to one of the grammars.
const BYTES: &[u8] = b"\0\xff\n\r\t \"'[]{}()<>,;:/\\|+-.=0123456789eE%$#!&\x1b\x07";

/// Makes a mutant of `seed`: one to four edits, each picked at random:
/// bit flips, a meaningful byte, a range deleted, duplicated or filled
/// with random bytes, a number replaced by an extreme one, a line spliced
/// in from another seed of the kind (`donors`), two lines swapped, a line
/// repeated many times (a flood), or the end cut off.
pub fn mutate(rng: &mut fastrand::Rng, seed: &[u8], donors: &[&[u8]]) -> Vec<u8> {
    let mut data = seed.to_vec();
    for _ in 0..rng.usize(1..=4) {
        edit(rng, &mut data, donors);
        data.truncate(4 << 20);
    }
    data
}

fn line_bounds(data: &[u8], at: usize) -> (usize, usize) {
    let start = data[..at].iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let end = data[at..].iter().position(|&b| b == b'\n').map_or(data.len(), |i| at + i + 1);
    (start, end)
}

fn edit(rng: &mut fastrand::Rng, data: &mut Vec<u8>, donors: &[&[u8]]) {
    if data.is_empty() {
        data.extend_from_slice(&BYTES[rng.usize(..BYTES.len())..]);
        return;
    }
    let at = rng.usize(..data.len());
    match rng.u8(..10) {
        0 => {
            for _ in 0..rng.usize(1..=8) {
                let i = rng.usize(..data.len());
                data[i] ^= 1 << rng.u8(..8);
            }
        }
        1 => data[at] = BYTES[rng.usize(..BYTES.len())],
        2 => {
            let end = (at + rng.usize(1..=64)).min(data.len());
            data.drain(at..end);
        }
        3 => {
            let end = (at + rng.usize(1..=256)).min(data.len());
            let piece = data[at..end].to_vec();
            let to = rng.usize(..=data.len());
            data.splice(to..to, piece);
        }
        4 => {
            let junk: Vec<u8> = (0..rng.usize(1..=32)).map(|_| rng.u8(..)).collect();
            data.splice(at..at, junk);
        }
        5 => {
            // A number replaced by an extreme one.
            let digits: Vec<usize> =
                data.iter().enumerate().filter(|(_, b)| b.is_ascii_digit()).map(|(i, _)| i).collect();
            if let Some(&i) = digits.get(rng.usize(..digits.len().max(1))) {
                let start = data[..i].iter().rposition(|b| !(b.is_ascii_digit() || *b == b'.')).map_or(0, |k| k + 1);
                let end =
                    data[i..].iter().position(|b| !(b.is_ascii_digit() || *b == b'.')).map_or(data.len(), |k| i + k);
                data.splice(start..end, NUMBERS[rng.usize(..NUMBERS.len())].bytes());
            }
        }
        6 => {
            if let Some(donor) = donors.get(rng.usize(..donors.len().max(1))).filter(|d| !d.is_empty()) {
                let (s, e) = line_bounds(donor, rng.usize(..donor.len()));
                let (ds, de) = line_bounds(data, at);
                data.splice(ds..de, donor[s..e].iter().copied());
            }
        }
        7 => {
            let (s1, e1) = line_bounds(data, at);
            let other = rng.usize(..data.len());
            let (s2, e2) = line_bounds(data, other);
            if e1 <= s2 {
                let second = data[s2..e2].to_vec();
                let first = data[s1..e1].to_vec();
                data.splice(s2..e2, first);
                data.splice(s1..e1, second);
            }
        }
        8 => {
            // A flood: one line many times.
            let (s, e) = line_bounds(data, at);
            let line = data[s..e].to_vec();
            let times = if line.len() < 200 { rng.usize(2..=2_000) } else { rng.usize(2..=20) };
            let piece: Vec<u8> = line.iter().copied().cycle().take(line.len() * times).collect();
            data.splice(e..e, piece);
        }
        _ => data.truncate(at),
    }
}

/// What went wrong in one run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Problem {
    Panic,
    Crash(String),
    Hang,
    Memory(u64),
    LeftBehind(Vec<String>),
    NoCode(String),
    NoPosition(String),
    LspStopped,
}

impl Problem {
    pub fn label(&self) -> &'static str {
        match self {
            Problem::Panic => "panic",
            Problem::Crash(_) => "crash",
            Problem::Hang => "hang",
            Problem::Memory(_) => "memory",
            Problem::LeftBehind(_) => "left-behind",
            Problem::NoCode(_) => "no-code",
            Problem::NoPosition(_) => "no-position",
            Problem::LspStopped => "lsp-stopped",
        }
    }
}

/// A finding: the problem, the command, and where its inputs were saved.
#[derive(Clone, Debug)]
pub struct Finding {
    pub problem: Problem,
    pub kind: Kind,
    pub origin: PathBuf,
    pub command: String,
    pub saved: Option<PathBuf>,
}

/// Limits and where things go.
#[derive(Clone, Debug)]
pub struct Settings {
    pub postc: PathBuf,
    /// Processor time a run may use before it is a hang (and
    /// [`WALL_FACTOR`] times it on the clock).
    pub timeout: Duration,
    /// Peak resident memory allowed, in bytes.
    pub memory: u64,
    /// Where findings are saved (`None`: not saved).
    pub save: Option<PathBuf>,
}

/// Counts of a run.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub mutants: u64,
    pub runs: u64,
    pub findings: Vec<Finding>,
    pub per_kind: std::collections::BTreeMap<Kind, u64>,
    pub slowest: Duration,
    pub peak_memory: u64,
}

/// One command of a mutant: its arguments (relative to the run folder),
/// and the files it may leave when it succeeds.
struct Run {
    args: Vec<String>,
    outputs: Vec<String>,
    json: bool,
}

fn runs_for(seed: &Seed) -> Vec<Run> {
    let f = seed.file_name.clone();
    let run = |args: &[&str], outputs: &[&str], json: bool| Run {
        args: args.iter().map(|s| s.to_string()).collect(),
        outputs: outputs.iter().map(|s| s.to_string()).collect(),
        json,
    };
    match seed.kind {
        Kind::Vectric | Kind::Cimco | Kind::VcPost => vec![
            run(&["check", "--format", "json", &f], &[], true),
            run(&["post", &f, "standard.ron", "-o", "out.nc"], &["out"], false),
            run(&["convert", &f, "--to", "ron", "-o", "out.ron"], &["out.ron"], false),
        ],
        // A Fusion post converts to its own dialect only (docs/convert.md).
        Kind::Fusion => vec![
            run(&["check", "--format", "json", &f], &[], true),
            run(&["post", &f, "standard.ron", "-o", "out.nc"], &["out"], false),
            run(&["convert", &f, "--to", "fusion", "-o", "out.cps"], &["out.cps"], false),
        ],
        Kind::Ron | Kind::Jsonl | Kind::Apt => vec![
            run(&["check", "--format", "json", &f], &[], true),
            run(&["post", &f, "-o", "out.nc"], &["out.nc"], false),
        ],
        Kind::ProbeTable | Kind::Composites => vec![run(&["post", "post.VcPost", &f, "-o", "out.nc"], &["out"], false)],
        Kind::Postp => vec![run(&["postp", "."], &[], false)],
        Kind::Lsp => vec![run(&["lsp"], &[], false)],
    }
}

/// Peak resident memory of a running process, in bytes (Linux).
fn peak_rss(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Processor time (user and system) a running process has used (Linux:
/// `/proc/PID/stat`, whose times are in the kernel's fixed user tick of
/// 1/100 s).
fn processor_time(pid: u32) -> Option<Duration> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    processor_time_of(&stat)
}

/// [`processor_time`] from the text of a `/proc/PID/stat`: fields 14 and
/// 15 (utime, stime), counted after the command name, which is in
/// parentheses and may hold blanks.
#[doc(hidden)]
pub fn processor_time_of(stat: &str) -> Option<Duration> {
    let after = &stat[stat.rfind(')')? + 1..];
    let mut fields = after.split_whitespace().skip(11);
    let (user, system): (u64, u64) = (fields.next()?.parse().ok()?, fields.next()?.parse().ok()?);
    Some(Duration::from_millis((user + system) * 10))
}

/// How many times the time limit a run may take on the clock while it has
/// not used the limit's processor time (a machine whose cores are busy
/// with other work runs it slowly): past that it is a hang too, blocked
/// rather than busy.
const WALL_FACTOR: u32 = 6;

/// What a finished process left.
struct Ended {
    code: Option<i32>,
    signalled: bool,
    hung: bool,
    peak: u64,
    stdout: Vec<u8>,
    /// Standard output was longer than [`READ_LIMIT`]: `stdout` is its start.
    stdout_cut: bool,
    stderr: Vec<u8>,
    took: Duration,
}

/// The most of a run's standard output and error read back. `check
/// --format json` keeps every diagnostic: a mutant with 50,000 bad
/// characters prints 11 MB of valid JSON.
const READ_LIMIT: u64 = 64 << 20;

/// Runs `postc args` in `dir`, stdin from `input`, under the limits.
fn execute(settings: &Settings, dir: &Path, args: &[String], input: &[u8]) -> std::io::Result<Ended> {
    let logs = tempfile::tempdir()?;
    let (out_path, err_path) = (logs.path().join("stdout"), logs.path().join("stderr"));
    // The address space is capped at four times the memory limit so that a
    // runaway cannot take the machine; the limit itself is judged on the
    // peak resident set.
    let cap_kb = settings.memory / 1024 * 4;
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {cap_kb}; exec \"$0\" \"$@\""))
        .arg(&settings.postc)
        .args(args)
        .current_dir(dir)
        .env("SOURCE_DATE_EPOCH", "0")
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::piped())
        .stdout(std::fs::File::create(&out_path)?)
        .stderr(std::fs::File::create(&err_path)?)
        .spawn()?;
    let pid = child.id();
    let started = Instant::now();
    if let Some(mut stdin) = child.stdin.take() {
        let input = input.to_vec();
        std::thread::spawn(move || {
            let _ = stdin.write_all(&input);
        });
    }
    let mut peak = 0;
    let mut hung = false;
    let status = loop {
        if let Some(s) = child.try_wait()? {
            break s;
        }
        if let Some(p) = peak_rss(pid) {
            peak = peak.max(p);
        }
        // A hang is a run that has used the limit's processor time, or
        // stays past several times the limit on the clock: a run a busy
        // machine slows is not one.
        let elapsed = started.elapsed();
        if elapsed > settings.timeout
            && (processor_time(pid).is_none_or(|t| t > settings.timeout) || elapsed > settings.timeout * WALL_FACTOR)
        {
            hung = true;
            let _ = child.kill();
            break child.wait()?;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let took = started.elapsed();
    let read = |p: &Path| {
        let mut b = Vec::new();
        if let Ok(mut f) = std::fs::File::open(p) {
            let _ = Read::by_ref(&mut f).take(READ_LIMIT + 1).read_to_end(&mut b);
        }
        let cut = b.len() as u64 > READ_LIMIT;
        b.truncate(READ_LIMIT as usize);
        (b, cut)
    };
    #[cfg(unix)]
    let signalled = std::os::unix::process::ExitStatusExt::signal(&status).is_some();
    #[cfg(not(unix))]
    let signalled = false;
    let (stdout, stdout_cut) = read(&out_path);
    Ok(Ended { code: status.code(), signalled, hung, peak, stdout, stdout_cut, stderr: read(&err_path).0, took })
}

/// Every `error`/`warning` header of human output has a code.
#[doc(hidden)]
pub fn uncoded(stderr: &[u8]) -> Option<String> {
    let text = String::from_utf8_lossy(stderr);
    text.lines()
        .find(|l| {
            (l.starts_with("error") || l.starts_with("warning"))
                && !l.starts_with("error[")
                && !l.starts_with("warning[")
        })
        .map(str::to_string)
}

/// Every item of `check --format json` has a code, and a line and column
/// when it names a file.
#[doc(hidden)]
pub fn json_problem(stdout: &[u8]) -> Option<Problem> {
    let Ok(serde_json::Value::Array(items)) = serde_json::from_slice::<serde_json::Value>(stdout) else {
        return (!stdout.is_empty()).then(|| Problem::NoCode("check --format json printed no JSON array".into()));
    };
    for item in items {
        let code = item.get("code").and_then(|c| c.as_str()).unwrap_or("");
        if code.is_empty() {
            return Some(Problem::NoCode(item.to_string()));
        }
        let has_file = item.get("file").is_some_and(|f| !f.is_null());
        let line = item.get("line").and_then(|l| l.as_u64()).unwrap_or(0);
        let column = item.get("column").and_then(|c| c.as_u64()).unwrap_or(0);
        if has_file && (line == 0 || column == 0) {
            return Some(Problem::NoPosition(item.to_string()));
        }
    }
    None
}

/// The LSP frames of a session: initialize, open the (mutated) post,
/// then some mutated frames, then shutdown (id 99) and exit.
fn lsp_session(rng: &mut fastrand::Rng, file_name: &str, text: &[u8]) -> Vec<u8> {
    let frame = |body: &[u8]| {
        let mut f = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
        f.extend_from_slice(body);
        f
    };
    let open = serde_json::json!({
        "jsonrpc": "2.0", "method": "textDocument/didOpen",
        "params": {"textDocument": {"uri": format!("file:///fuzz/{file_name}"), "languageId": "post", "version": 1,
                   "text": String::from_utf8_lossy(text)}}
    });
    let mut frames = vec![
        frame(br#"{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}}"#),
        frame(br#"{"jsonrpc":"2.0","method":"initialized","params":{}}"#),
        frame(open.to_string().as_bytes()),
    ];
    for i in 0..rng.usize(1..=4) {
        let hover = serde_json::json!({
            "jsonrpc": "2.0", "id": 10 + i, "method": "textDocument/hover",
            "params": {"textDocument": {"uri": format!("file:///fuzz/{file_name}")},
                       "position": {"line": rng.u32(..200), "character": rng.u32(..80)}}
        })
        .to_string()
        .into_bytes();
        let body = if rng.bool() { mutate(rng, &hover, &[]) } else { hover };
        frames.push(match rng.u8(..4) {
            // A frame whose length lies.
            0 => {
                let mut f =
                    format!("Content-Length: {}\r\n\r\n", body.len().saturating_sub(rng.usize(..5))).into_bytes();
                f.extend_from_slice(&body);
                f
            }
            1 => mutate(rng, &frame(&body), &[]),
            _ => frame(&body),
        });
    }
    frames.push(frame(br#"{"jsonrpc":"2.0","id":99,"method":"shutdown"}"#));
    frames.push(frame(br#"{"jsonrpc":"2.0","method":"exit"}"#));
    frames.concat()
}

/// Runs one mutant of `seed` through its commands; the problems found.
pub fn run_mutant(settings: &Settings, tally: &mut Tally, seed: &Seed, mutant: &[u8], rng: &mut fastrand::Rng) {
    tally.mutants += 1;
    *tally.per_kind.entry(seed.kind).or_default() += 1;
    for run in runs_for(seed) {
        let Ok(dir) = tempfile::tempdir() else { continue };
        let mut inputs = Vec::new();
        let input_name = if seed.kind == Kind::Lsp { "session.lsp".to_string() } else { seed.file_name.clone() };
        let stdin = if seed.kind == Kind::Lsp { lsp_session(rng, &seed.file_name, mutant) } else { Vec::new() };
        let written = if seed.kind == Kind::Lsp { &stdin[..] } else { mutant };
        if std::fs::write(dir.path().join(&input_name), written).is_err() {
            continue;
        }
        inputs.push(input_name.clone());
        if let Some((name, bytes)) = &seed.companion {
            let _ = std::fs::write(dir.path().join(name), bytes);
            inputs.push(name.clone());
        }
        let Ok(ended) = execute(settings, dir.path(), &run.args, &stdin) else { continue };
        tally.runs += 1;
        tally.slowest = tally.slowest.max(ended.took);
        tally.peak_memory = tally.peak_memory.max(ended.peak);
        let mut problems = Vec::new();
        let stderr = String::from_utf8_lossy(&ended.stderr);
        if ended.hung {
            problems.push(Problem::Hang);
        } else if stderr.contains("panicked at") || ended.code == Some(101) {
            problems.push(Problem::Panic);
        } else if ended.signalled {
            problems.push(Problem::Crash(stderr.lines().last().unwrap_or("killed by a signal").to_string()));
        }
        if ended.peak > settings.memory {
            problems.push(Problem::Memory(ended.peak));
        }
        // What is in the folder now, beside the inputs.
        let left: Vec<String> = std::fs::read_dir(dir.path())
            .map(|entries| {
                entries
                    .flatten()
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .filter(|n| !inputs.contains(n))
                    .filter(|n| !(ended.code == Some(0) && run.outputs.iter().any(|o| n.starts_with(o.as_str()))))
                    .collect()
            })
            .unwrap_or_default();
        if !left.is_empty() && !ended.hung {
            problems.push(Problem::LeftBehind(left));
        }
        if let Some(line) = uncoded(&ended.stderr) {
            problems.push(Problem::NoCode(line));
        }
        // (JSON cut short by the read limit is not judged.)
        if run.json
            && !ended.stdout_cut
            && let Some(p) = json_problem(&ended.stdout)
        {
            problems.push(p);
        }
        if seed.kind == Kind::Lsp && !ended.hung && !String::from_utf8_lossy(&ended.stdout).contains("\"id\":99") {
            problems.push(Problem::LspStopped);
        }
        for problem in problems {
            let command = format!(
                "postc {}{}",
                run.args.join(" "),
                if seed.kind == Kind::Lsp { format!(" < {input_name}") } else { String::new() }
            );
            let what = format!("{problem:?}, a {} mutant of {}", seed.kind.name(), seed.origin.display());
            let saved = settings
                .save
                .as_ref()
                .and_then(|root| save(root, tally.findings.len(), dir.path(), &inputs, &command, &what));
            tally.findings.push(Finding { problem, kind: seed.kind, origin: seed.origin.clone(), command, saved });
        }
    }
}

/// Copies a finding's inputs and a `replay.sh` into `root/finding-N`;
/// `what` (the problem, the kind and the corpus file mutated) is its
/// first comment.
fn save(root: &Path, n: usize, dir: &Path, inputs: &[String], command: &str, what: &str) -> Option<PathBuf> {
    let to = root.join(format!("finding-{n:04}"));
    std::fs::create_dir_all(&to).ok()?;
    for i in inputs {
        std::fs::copy(dir.join(i), to.join(i)).ok()?;
    }
    std::fs::write(
        to.join("replay.sh"),
        format!(
            "#!/bin/sh\n# found: {}\n# run in this folder\ncd \"$(dirname \"$0\")\" && {command}\n",
            what.replace('\n', " ")
        ),
    )
    .ok()?;
    Some(to)
}

/// Runs `count` mutants made from `seed` over the seeds, round robin by
/// kind so that every kind is fuzzed whatever the count.
pub fn fuzz(settings: &Settings, seeds: &[Seed], count: u64, rng_seed: u64, mut progress: impl FnMut(&Tally)) -> Tally {
    let mut rng = fastrand::Rng::with_seed(rng_seed);
    let mut tally = Tally::default();
    let kinds: Vec<Kind> = Kind::ALL.iter().copied().filter(|k| seeds.iter().any(|s| s.kind == *k)).collect();
    if kinds.is_empty() {
        return tally;
    }
    for i in 0..count {
        let kind = kinds[(i as usize) % kinds.len()];
        let of_kind: Vec<&Seed> = seeds.iter().filter(|s| s.kind == kind).collect();
        let seed = of_kind[rng.usize(..of_kind.len())];
        let donors: Vec<&[u8]> = of_kind.iter().map(|s| s.bytes.as_slice()).collect();
        let mutant = mutate(&mut rng, &seed.bytes, &donors);
        run_mutant(settings, &mut tally, seed, &mutant, &mut rng);
        progress(&tally);
    }
    tally
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/fuzz/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod root {
        pub use crate::{json_problem, uncoded};
    }
}
