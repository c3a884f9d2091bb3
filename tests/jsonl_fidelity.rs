//! JSON Lines toolpaths post exactly as RON ones.
//!
//! Every corpus toolpath (`corpus/toolpaths/**/*.ron`) is read, written as
//! JSON Lines, read back and posted through every corpus post; the program
//! (or the diagnostics' codes) must be byte-identical to posting the RON.
//! Each toolpath is posted twice: as it is, and "nudged", every double moved
//! one step down (36.2075 becomes 36.207499999999996), which puts every
//! coordinate next to a rounding tie of the posts' formats: a reader that
//! is not correctly rounded reads the next double up and prints a different
//! last digit.

use std::path::{Path, PathBuf};

use postc_ir::{Event, Post};
use postc_reader_native::{Syntax, write_event};

use crate::support;

use crate::support::{compile, corpus, files, post_parts, stem};

fn corpus_toolpaths() -> Vec<PathBuf> {
    let root = corpus().join("toolpaths");
    let mut out = files(&root, "ron");
    for sub in ["cimco", "vcpost", "turning"] {
        out.extend(files(&root.join(sub), "ron"));
    }
    out
}

fn corpus_posts() -> Vec<(PathBuf, Post)> {
    let root = corpus().join("posts");
    let mut paths = files(&root.join("vectric"), "pp");
    paths.extend(files(&root.join("cimco"), "js"));
    paths.extend(files(&root.join("vcpost"), "VcPost"));
    paths.extend(files(&root.join("postp"), "VcPost"));
    paths
        .into_iter()
        .map(|p| {
            let post = compile(&p).unwrap_or_else(|e| panic!("{e}"));
            (p, post)
        })
        .collect()
}

fn read_events(path: &Path) -> Vec<Event> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(path, &mut sources).expect("a corpus toolpath opens");
    let mut diagnostics = Vec::new();
    let mut events = Vec::new();
    while let Some((event, _)) = source.next_event(&mut diagnostics) {
        events.push(event);
    }
    assert!(diagnostics.is_empty(), "{}: {diagnostics:?}", path.display());
    events
}

/// Every double of an event one step towards minus infinity (zero stays).
fn nudged(event: &Event) -> Event {
    fn walk(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Number(n) if n.is_f64() => {
                let x = n.as_f64().expect("a double");
                if x != 0.0 && x.is_finite() {
                    *v = serde_json::json!(f64::from_bits(if x > 0.0 { x.to_bits() - 1 } else { x.to_bits() + 1 }));
                }
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(walk),
            serde_json::Value::Object(map) => map.values_mut().for_each(walk),
            _ => {}
        }
    }
    let mut value = serde_json::to_value(event).expect("an event serializes");
    walk(&mut value);
    serde_json::from_value(value).expect("a nudged event deserializes")
}

fn write(path: &Path, events: &[Event], syntax: Syntax) {
    let mut text = String::new();
    for e in events {
        write_event(e, syntax, &mut text);
    }
    std::fs::write(path, text).expect("the toolpath is written");
}

fn post(post: &Post, toolpath: &Path) -> Result<Vec<Vec<u8>>, String> {
    post_parts(post, toolpath)
        .map_err(|e| e.lines().skip(1).map(|l| l.split_whitespace().next().unwrap_or("")).collect::<Vec<_>>().join(" "))
}

#[test]
fn json_lines_toolpaths_post_byte_identically_to_ron() {
    let posts = corpus_posts();
    let toolpaths = corpus_toolpaths();
    assert!(posts.len() >= 30 && toolpaths.len() >= 9, "{} posts, {} toolpaths", posts.len(), toolpaths.len());
    let dir = tempfile::tempdir().expect("a temporary directory");
    let mut failures = Vec::new();
    let mut compared = 0;
    for toolpath in &toolpaths {
        let events = read_events(toolpath);
        for (variant, events) in [("as is", events.clone()), ("nudged", events.iter().map(nudged).collect())] {
            let sub = dir.path().join(format!("{}-{}", stem(toolpath), variant.replace(' ', "_")));
            std::fs::create_dir_all(&sub).expect("a folder");
            let ron = sub.join(format!("{}.ron", stem(toolpath)));
            let jsonl = sub.join(format!("{}.jsonl", stem(toolpath)));
            write(&ron, &events, Syntax::Ron);
            write(&jsonl, &events, Syntax::JsonLines);
            let from_json = read_events(&jsonl);
            let same_bits = read_events(&ron)
                .iter()
                .zip(&from_json)
                .all(|(a, b)| serde_json::to_value(a).ok() == serde_json::to_value(b).ok() && a == b);
            if !same_bits || from_json.len() != events.len() {
                failures.push(format!("{} ({variant}): JSON Lines read back different events", stem(toolpath)));
            }
            for (post_path, post_ir) in &posts {
                let a = post(post_ir, &ron);
                let b = post(post_ir, &jsonl);
                compared += 1;
                if a != b {
                    let first = match (&a, &b) {
                        (Ok(a), Ok(b)) => {
                            let (a, b) = (a.concat(), b.concat());
                            let (la, lb) = (support::lines(&a), support::lines(&b));
                            let i = la.iter().zip(&lb).position(|(x, y)| x != y).unwrap_or(la.len().min(lb.len()));
                            format!(
                                "line {}: RON `{}`, JSON Lines `{}`",
                                i + 1,
                                la.get(i).map_or(String::new(), |l| support::show(l)),
                                lb.get(i).map_or(String::new(), |l| support::show(l))
                            )
                        }
                        _ => format!("RON {a:?}, JSON Lines {b:?}"),
                    };
                    failures.push(format!("{} over {} ({variant}): {first}", stem(post_path), stem(toolpath)));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} of {compared} posts differ:\n{}", failures.len(), failures.join("\n"));
}
