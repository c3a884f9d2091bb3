//! What the golden tests share (`corpus_goldens`, `cimco_goldens` and the
//! CIMCO referee): the corpus folder, compiling a corpus post (any
//! diagnostic is a failure), posting a toolpath into memory, and a readable
//! diff of two programs that spells out line endings.

#![allow(dead_code)]

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

pub fn stem(path: &Path) -> String {
    path.file_stem().expect("a file name").to_string_lossy().into_owned()
}

/// Compiles a corpus post; any diagnostic (error or warning) is a failure.
pub fn compile(path: &Path) -> Result<Post, String> {
    let mut sources = postc_report::source_map();
    let compiled = postc_frontends::compile_post(path, None, &mut sources);
    if !compiled.diagnostics.is_empty() {
        let list: Vec<String> = compiled.diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
        return Err(format!("{} does not compile cleanly:\n{}", path.display(), list.join("\n")));
    }
    compiled.post.ok_or_else(|| format!("{} gave no post", path.display()))
}

/// Posts a toolpath into memory: the parts of the program.
pub fn post_parts(post: &Post, toolpath: &Path) -> Result<Vec<Vec<u8>>, String> {
    let mut sources = postc_report::source_map();
    let mut source = postc_frontends::open_toolpath(toolpath, &mut sources)
        .map_err(|d| format!("cannot open {}: {} {}", toolpath.display(), d.code, d.message))?;
    match postc_runtime::run(post, &mut source, Output::memory(), postc_frontends::run_options(post)) {
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
