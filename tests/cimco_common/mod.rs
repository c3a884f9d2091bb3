//! What the CIMCO corpus tests share: the corpus posts, the toolpaths each
//! posts (milling posts the milling, drilling and standard jobs; lathe
//! posts the lathe job), posting into memory, JSON Lines export of a
//! toolpath for the Node.js referee, running that referee, and a readable
//! diff. Also used by `benches/cimco_vs_node.rs`.

#![allow(dead_code)]

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use postc_frontends::native::{Syntax, write_event};
use postc_ir::{EventSource, Post, SourceMap};
use postc_runtime::{Finished, Output, RunOptions};

pub fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus")
}

/// The corpus CIMCO posts, sorted.
pub fn posts() -> Vec<PathBuf> {
    let dir = corpus().join("posts/cimco");
    let mut out: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "js"))
        .collect();
    out.sort();
    out
}

/// The toolpaths a post is posted over.
pub fn toolpaths(post: &Post) -> Vec<PathBuf> {
    let t = corpus().join("toolpaths");
    if post.options.lathe {
        vec![t.join("cimco/lathe.ron")]
    } else {
        vec![t.join("cimco/mill.ron"), t.join("cimco/drill.ron"), t.join("standard.ron")]
    }
}

pub fn stem(path: &Path) -> String {
    path.file_stem().expect("a file name").to_string_lossy().into_owned()
}

/// Compiles a corpus post; any diagnostic is a failure.
pub fn compile(path: &Path) -> Result<Post, String> {
    let mut sources = SourceMap::new();
    let compiled = postc_frontends::compile_post(path, None, &mut sources);
    if !compiled.diagnostics.is_empty() {
        let list: Vec<String> = compiled.diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
        return Err(format!("{} does not compile cleanly:\n{}", path.display(), list.join("\n")));
    }
    compiled.post.ok_or_else(|| format!("{} gave no post", path.display()))
}

/// Posts a toolpath into memory (one part).
pub fn post_toolpath(post: &Post, toolpath: &Path) -> Result<Vec<u8>, String> {
    let mut sources = SourceMap::new();
    let mut source = postc_frontends::open_toolpath(toolpath, &mut sources)
        .map_err(|d| format!("cannot open {}: {} {}", toolpath.display(), d.code, d.message))?;
    match postc_runtime::run(post, &mut source, Output::memory(), RunOptions::default()) {
        Ok(report) => match report.output {
            Finished::Memory(mut parts) if parts.len() == 1 => Ok(parts.remove(0)),
            _ => Err("the run did not give one part in memory".into()),
        },
        Err(diagnostics) => {
            let list: Vec<String> = diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
            Err(format!("posting failed:\n{}", list.join("\n")))
        }
    }
}

/// Writes a toolpath as JSON Lines (the referee host's input).
pub fn export_jsonl(toolpath: &Path, target: &Path) -> Result<(), String> {
    let mut sources = SourceMap::new();
    let mut source = postc_frontends::open_toolpath(toolpath, &mut sources).map_err(|d| d.message)?;
    let mut text = String::new();
    let mut diags = Vec::new();
    while let Some((event, _)) = source.next_event(&mut diags) {
        write_event(&event, Syntax::JsonLines, &mut text);
    }
    std::fs::write(target, text).map_err(|e| e.to_string())
}

fn show(line: &[u8]) -> String {
    let mut s = String::new();
    for c in String::from_utf8_lossy(line).chars() {
        match c {
            '\r' => s.push_str("\\r"),
            '\n' => s.push_str("\\n"),
            c => s.push(c),
        }
    }
    s
}

/// The first differing lines of two programs, with context.
pub fn diff(expected: &[u8], actual: &[u8]) -> String {
    let e: Vec<&[u8]> = expected.split_inclusive(|&b| b == b'\n').collect();
    let a: Vec<&[u8]> = actual.split_inclusive(|&b| b == b'\n').collect();
    let first = e.iter().zip(&a).position(|(x, y)| x != y).unwrap_or(e.len().min(a.len()));
    let mut out = format!("  first difference at line {} ({} vs {} lines)\n", first + 1, e.len(), a.len());
    for i in first.saturating_sub(2)..(first + 4).min(e.len().max(a.len())) {
        match (e.get(i), a.get(i)) {
            (Some(x), Some(y)) if x == y => {
                let _ = writeln!(out, "    {:>5}   {}", i + 1, show(x));
            }
            (x, y) => {
                if let Some(x) = x {
                    let _ = writeln!(out, "    {:>5} - {}", i + 1, show(x));
                }
                if let Some(y) = y {
                    let _ = writeln!(out, "    {:>5} + {}", i + 1, show(y));
                }
            }
        }
    }
    out
}

/// The installed Node.js version, if `node` is on PATH.
pub fn node() -> Option<String> {
    let out = Command::new("node").arg("--version").output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The referee host that runs a CIMCO post under Node.js.
pub fn host_script() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/run.js")
}

/// Runs a post under Node.js over a JSON Lines toolpath; its output.
pub fn run_node(post: &Path, jsonl: &Path, extra: &[&str]) -> Result<Vec<u8>, String> {
    let out = Command::new("node")
        .arg(host_script())
        .arg(post)
        .arg(jsonl)
        .args(extra)
        .output()
        .map_err(|e| format!("cannot run node: {e}"))?;
    if !out.status.success() {
        return Err(format!("node failed:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    Ok(out.stdout)
}
