//! What the CIMCO corpus tests share: the corpus posts, the toolpaths each
//! posts (milling posts the milling, drilling and standard jobs; lathe
//! posts the lathe job), posting into memory, JSON Lines export of a
//! toolpath for the Node.js referee, running that referee, and a readable
//! diff. Also used by `benches/cimco_vs_node.rs`.

use std::path::{Path, PathBuf};
use std::process::Command;

#[allow(unused_imports)]
pub use super::{compile, corpus, diff, post_parts, stem};
use postc_ir::{EventSource, Post};
use postc_reader_native::{Syntax, write_event};

/// The corpus CIMCO posts, sorted.
pub fn posts() -> Vec<PathBuf> {
    super::files(&corpus().join("posts/cimco"), "js")
}

/// The field-style CIMCO posts (`corpus/posts/cimco-styles/`), sorted.
pub fn style_posts() -> Vec<PathBuf> {
    super::files(&corpus().join("posts/cimco-styles"), "js")
}

/// The toolpaths a post is posted over.
pub fn toolpaths(post: &Post) -> Vec<PathBuf> {
    if post.options.lathe { vec![corpus().join("toolpaths/cimco/lathe.ron")] } else { mill_toolpaths() }
}

/// The toolpaths a milling post is posted over.
pub fn mill_toolpaths() -> Vec<PathBuf> {
    let t = corpus().join("toolpaths");
    vec![t.join("cimco/mill.ron"), t.join("cimco/drill.ron"), t.join("standard.ron")]
}

/// The golden of a field-style post over a toolpath: the program Node.js
/// prints (`tests/cimco_styles.rs`).
pub fn style_golden(post: &Path, toolpath: &Path) -> PathBuf {
    corpus().join("expected/cimco-styles").join(format!("{}__{}.nc", stem(post), stem(toolpath)))
}

/// Every field-style golden with the toolpath it was posted from.
pub fn style_goldens() -> Vec<(PathBuf, PathBuf)> {
    let mut out = Vec::new();
    for post in style_posts() {
        out.extend(mill_toolpaths().into_iter().map(|t| (style_golden(&post, &t), t)));
    }
    out
}

/// Posts a toolpath into memory: the whole program.
pub fn post_toolpath(post: &Post, toolpath: &Path) -> Result<Vec<u8>, String> {
    post_parts(post, toolpath).map(|parts| parts.concat())
}

/// Writes a toolpath as JSON Lines (the referee host's input).
pub fn export_jsonl(toolpath: &Path, target: &Path) -> Result<(), String> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).map_err(|d| d.message)?;
    let mut text = String::new();
    let mut diags = Vec::new();
    while let Some((event, _)) = source.next_event(&mut diags) {
        write_event(&event, Syntax::JsonLines, &mut text);
    }
    std::fs::write(target, text).map_err(|e| e.to_string())
}

/// A `node` command for the referee: Node.js without the extra CA
/// certificates a machine may name in `NODE_EXTRA_CA_CERTS`. The referee
/// opens no connection, and reading a certificate bundle at every start
/// took a third of each run's time.
pub fn node_command() -> Command {
    let mut command = Command::new("node");
    command.env_remove("NODE_EXTRA_CA_CERTS");
    command
}

/// The installed Node.js version, if `node` is on PATH.
pub fn node() -> Option<String> {
    let out = node_command().arg("--version").output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Node.js's version, or None when the Node.js checks are to be skipped;
/// under `CI=true` a missing `node` fails.
pub fn node_or_skip(test: &str) -> Option<String> {
    let version = node();
    if version.is_none() {
        super::referee_missing(test, "node");
    }
    version
}

/// The referee host that runs a CIMCO post under Node.js.
pub fn host_script() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/run.js")
}

/// Runs a post under Node.js over a JSON Lines toolpath; its output.
pub fn run_node(post: &Path, jsonl: &Path, extra: &[&str]) -> Result<Vec<u8>, String> {
    let out = node_command()
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

/// The names of a post's functions that run as Rhai scripts, and whether
/// it keeps any script at all: empty and false when it runs natively whole.
pub fn script_functions(post: &Post) -> (Vec<&str>, bool) {
    let names = post
        .functions
        .iter()
        .filter(|f| !matches!(f.body, postc_ir::Body::Native(_)))
        .map(|f| f.name.as_str())
        .collect();
    (names, !post.scripts.is_empty())
}
