//! The one test harness of the byte-exact goldens (NC programs, converted
//! posts, `postp` programs, the backplot image): every test that compares
//! output with a committed file goes through here, with `mod support;`.
//!
//! - listing fixtures: [`files`] (by extension) and [`all_files`];
//! - comparing and blessing: [`check_golden`] compares bytes and, when
//!   [`blessing`] (`POSTC_BLESS=1`, and only that), rewrites the file;
//!   [`Goldens`] does it for a folder of goldens and removes (or reports)
//!   the files nothing makes any more;
//! - the readable [`diff`] that spells out line endings (`\r\n`);
//! - compiling a corpus post (any diagnostic is a failure) and posting a
//!   toolpath into memory.
//!
//! Text snapshots (IR listings, diagnostics, reader events) are not here:
//! they are `insta` snapshots in the frontends' tests.
//!
//! Beside it: [`cimco`] (the CIMCO corpus and its Node.js referee),
//! [`postp`] (the `postp` controllers' runs) and [`rs274`] (LinuxCNC's
//! interpreter as a referee).

#![allow(dead_code)]

pub mod cimco;
pub mod converting;
pub mod postp;
pub mod prepared;
pub mod rs274;
pub mod verifying;

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use postc_ir::Post;
use postc_runtime::{Finished, Output};

pub fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus")
}

/// The files of `dir` whose extension is `ext`, sorted by name.
pub fn files(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext)))
        .collect();
    out.sort();
    out
}

/// Every file of `dir` (no folders), sorted; none when `dir` is missing.
pub fn all_files(dir: &Path) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_file()).collect())
        .unwrap_or_default();
    out.sort();
    out
}

/// Whether this run rewrites the goldens: `POSTC_BLESS=1`.
pub fn blessing() -> bool {
    std::env::var_os("POSTC_BLESS").is_some_and(|v| v == "1")
}

/// How a failure message tells to bless.
pub fn bless_hint(test: &str) -> String {
    format!("If the new output is right, read it and bless it: POSTC_BLESS=1 cargo test --test suite {test}")
}

/// Compares `actual`, byte for byte, with the golden at `path`. When
/// [`blessing`], a missing or different golden is written instead (its
/// folder created): `Ok(true)`. `Ok(false)` when it already matched; an
/// error naming the file, with the [`diff`], when it does not.
pub fn check_golden(path: &Path, actual: &[u8]) -> Result<bool, String> {
    let old = std::fs::read(path).ok();
    if old.as_deref() == Some(actual) {
        return Ok(false);
    }
    if blessing() {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
        }
        std::fs::write(path, actual).unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
        return Ok(true);
    }
    Err(match old {
        None => {
            format!("{}: no golden (the output has {} bytes); bless with POSTC_BLESS=1", path.display(), actual.len())
        }
        Some(old) => format!("{}: output differs\n{}", path.display(), diff(&old, actual)),
    })
}

/// The goldens of one test: each file checked with [`check_golden`], the
/// files made remembered, failures gathered.
#[derive(Default)]
pub struct Goldens {
    /// The golden files this run made (compared or wrote).
    pub made: BTreeSet<PathBuf>,
    /// How many goldens a blessing run wrote.
    pub written: usize,
    pub failures: Vec<String>,
}

impl Goldens {
    pub fn new() -> Self {
        Self::default()
    }

    /// Checks (or blesses) one golden.
    pub fn check(&mut self, path: &Path, actual: &[u8]) {
        self.made.insert(path.to_path_buf());
        match check_golden(path, actual) {
            Ok(written) => self.written += usize::from(written),
            Err(e) => self.failures.push(e),
        }
    }

    pub fn fail(&mut self, failure: impl Into<String>) {
        self.failures.push(failure.into());
    }

    /// The `candidates` this run did not make: removed when [`blessing`],
    /// failures (`<path>: <why>`) otherwise.
    pub fn sweep(&mut self, candidates: impl IntoIterator<Item = PathBuf>, why: &str) {
        for path in candidates {
            if self.made.contains(&path) {
                continue;
            }
            if blessing() {
                std::fs::remove_file(&path).unwrap_or_else(|e| panic!("cannot remove {}: {e}", path.display()));
                eprintln!("removed stale {}", path.display());
            } else {
                self.failures.push(format!("{}: {why}", path.display()));
            }
        }
    }

    /// Fails with every failure gathered, and how to bless (`test` is the
    /// test target's name); when blessing, says how many files it wrote.
    #[track_caller]
    pub fn finish(self, what: &str, test: &str) {
        if blessing() {
            eprintln!("blessed {} changed files of {} {what}", self.written, self.made.len());
        }
        assert!(
            self.failures.is_empty(),
            "{} of {} {what} fail:\n\n{}\n\n{}",
            self.failures.len(),
            self.made.len(),
            self.failures.join("\n\n"),
            bless_hint(test)
        );
    }
}

pub fn stem(path: &Path) -> String {
    path.file_stem().expect("a file name").to_string_lossy().into_owned()
}

/// Compiles a post given as text (named `name`, which tells its dialect);
/// panics when it has errors.
pub fn compile_text(name: &str, text: &str) -> Post {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(Path::new(name), text.as_bytes(), None, &mut sources);
    assert!(!compiled.has_errors(), "{name}: {:?}", compiled.diagnostics);
    compiled.post.expect("a compiled post")
}

/// Compiles a post file; panics when it has errors (warnings pass).
pub fn compile_file(path: &Path) -> Post {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    assert!(!compiled.has_errors(), "{}: {:?}", path.display(), compiled.diagnostics);
    compiled.post.expect("a compiled post")
}

/// Compiles a corpus post; any diagnostic (error or warning) is a failure.
pub fn compile(path: &Path) -> Result<Post, String> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    if !compiled.diagnostics.is_empty() {
        let list: Vec<String> = compiled.diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
        return Err(format!("{} does not compile cleanly:\n{}", path.display(), list.join("\n")));
    }
    compiled.post.ok_or_else(|| format!("{} gave no post", path.display()))
}

/// Compiles a corpus post that may have warnings; its errors are a failure.
pub fn compile_warned(path: &Path) -> Result<Post, String> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    if compiled.has_errors() {
        let list: Vec<String> = compiled.diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
        return Err(format!("{} does not compile:\n{}", path.display(), list.join("\n")));
    }
    compiled.post.ok_or_else(|| format!("{} gave no post", path.display()))
}

/// A referee of a test (an outside program postc is checked against:
/// Node.js, rs274, bash, man) is not installed: under `CI=true` that fails
/// the test, since CI never skips a referee (`bash .ci/run` installs them);
/// elsewhere the check is skipped with a message.
pub fn referee_missing(test: &str, tool: &str) {
    assert!(
        std::env::var_os("CI").is_none_or(|v| v != "true"),
        "{test}: `{tool}` is not installed, and CI=true requires it (bash .ci/run installs it)"
    );
    eprintln!("{test}: `{tool}` is not installed; that check is skipped");
}

/// Runs the `postc` binary in the repository's folder.
pub fn postc(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_postc")).current_dir(root()).args(args).output().unwrap()
}

/// What a run of `postc` printed: standard output, then standard error.
pub fn said(o: &std::process::Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Posts a toolpath into memory: the parts of the program.
pub fn post_parts(post: &Post, toolpath: &Path) -> Result<Vec<Vec<u8>>, String> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources)
        .map_err(|d| format!("cannot open {}: {} {}", toolpath.display(), d.code, d.message))?;
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => Ok(parts),
            _ => Err("a memory run did not finish in memory".into()),
        },
        Err(diagnostics) => {
            let list: Vec<String> = diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
            Err(format!("posting failed:\n{}", list.join("\n")))
        }
    }
}

/// Lines with their endings, so that a CR/LF difference is a difference.
pub fn lines(bytes: &[u8]) -> Vec<&[u8]> {
    bytes.split_inclusive(|&b| b == b'\n').collect()
}

/// A line as text with its line ending spelled out.
pub fn show(line: &[u8]) -> String {
    let mut s = String::new();
    for c in String::from_utf8_lossy(line).chars() {
        match c {
            '\r' => s.push_str("\\r"),
            '\n' => s.push_str("\\n"),
            '\t' => s.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(s, "\\x{:02x}", c as u32);
            }
            c => s.push(c),
        }
    }
    s
}

/// A readable account of how `actual` differs from `expected`: the first
/// differing lines with a little context.
pub fn diff(expected: &[u8], actual: &[u8]) -> String {
    let (e, a) = (lines(expected), lines(actual));
    let first = e.iter().zip(&a).position(|(x, y)| x != y).unwrap_or(e.len().min(a.len()));
    let mut out = format!(
        "  first difference at line {} (expected {} lines, {} bytes; got {} lines, {} bytes)\n",
        first + 1,
        e.len(),
        expected.len(),
        a.len(),
        actual.len()
    );
    let context = first.saturating_sub(2);
    for (i, line) in e.iter().enumerate().take(first).skip(context) {
        let _ = writeln!(out, "    {:>5}   {}", i + 1, show(line));
    }
    // The first run of differing lines (at most six), two lines of
    // context after it, and how many other lines differ.
    let total = e.len().max(a.len());
    let differs = |i: usize| e.get(i) != a.get(i);
    let mut i = first;
    while i < total && differs(i) && i < first + 6 {
        if let Some(x) = e.get(i) {
            let _ = writeln!(out, "    {:>5} - {}", i + 1, show(x));
        }
        if let Some(y) = a.get(i) {
            let _ = writeln!(out, "    {:>5} + {}", i + 1, show(y));
        }
        i += 1;
    }
    for (j, line) in e.iter().enumerate().take(i + 2).skip(i) {
        if !differs(j) {
            let _ = writeln!(out, "    {:>5}   {}", j + 1, show(line));
        }
    }
    let more = (i..total).filter(|&j| differs(j)).count();
    if more > 0 {
        let _ = writeln!(out, "    ... and {more} more differing lines");
    }
    out
}

/// `each` over every item, on a few worker threads with big stacks
/// (compiling a large post recurses deeply in a debug build): what each
/// item gives, in no particular order.
pub fn in_workers<T: Sync, R: Send>(items: &[T], each: impl Fn(&T) -> Vec<R> + Sync) -> Vec<R> {
    let next = std::sync::atomic::AtomicUsize::new(0);
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).min(8);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|_| {
                let (next, each) = (&next, &each);
                std::thread::Builder::new()
                    .stack_size(256 << 20)
                    .spawn_scoped(scope, move || {
                        let mut done = Vec::new();
                        while let Some(item) = items.get(next.fetch_add(1, std::sync::atomic::Ordering::Relaxed)) {
                            done.extend(each(item));
                        }
                        done
                    })
                    .expect("a worker thread")
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("a worker")).collect()
    })
}
