//! Provenance (`postc post --trace`, docs/trace.md): every line a corpus
//! post writes is traced to the post statement that wrote it, and the text
//! at that span is that statement's — a Vectric output line (a quoted
//! string), a VcPost `Out`, a CIMCO `return` (or, for an entry point that
//! runs as a Rhai script, its function: the script's statements have no
//! spans).

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::rc::Rc;

use postc_ir::{Dialect, Span};
use postc_runtime::{Finished, Output, RunOptions};

use crate::support::{corpus, files, lines};

/// One traced line: part, line, the span's text (or why there is none),
/// and whether the span is a function that runs as a script.
type Traced = (usize, u64, Result<String, String>, bool);

/// What the sink keeps of each line while the run goes on.
type RawTrace = Rc<RefCell<Vec<(usize, u64, Option<Span>)>>>;

/// Posts `toolpath` through the post at `path` with a trace; the program's
/// parts and the trace, or `None` when the post does not post it.
fn traced(path: &Path, toolpath: &Path) -> Option<(Dialect, Vec<Vec<u8>>, Vec<Traced>)> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    let post = compiled.post?;
    let script_functions: Vec<Span> =
        post.functions.iter().filter(|f| matches!(f.body, postc_ir::Body::Script(_))).filter_map(|f| f.span).collect();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).ok()?;
    let raw: RawTrace = Rc::default();
    let sink = Rc::clone(&raw);
    let options = RunOptions {
        trace: Some(Box::new(move |t: &postc_runtime::trace::TraceLine<'_>| {
            sink.borrow_mut().push((t.part, t.line, t.span))
        })),
        ..postc_driver::run_options(&post)
    };
    let report = postc_runtime::run(&post, &mut source, Output::memory(), options).ok()?;
    let Finished::Memory(parts) = report.output else { panic!("a memory run did not finish in memory") };
    let records = raw
        .borrow()
        .iter()
        .map(|&(part, line, span)| {
            let text = match span {
                None => Err("no span".to_string()),
                Some(s) => sources
                    .text(s.file)
                    .and_then(|t| t.get(s.start..s.end))
                    .map(str::to_string)
                    .ok_or_else(|| format!("span {s:?} is not in a loaded file")),
            };
            (part, line, text, span.is_some_and(|s| script_functions.contains(&s)))
        })
        .collect();
    Some((post.info.dialect, parts, records))
}

/// What the text of a span must look like in each dialect.
fn statement_shape(dialect: Dialect, text: &str, script_function: bool) -> bool {
    match dialect {
        Dialect::Vectric => text.trim_start().starts_with('"'),
        Dialect::VcPost => text.trim_start().to_ascii_lowercase().starts_with("out"),
        Dialect::Cimco => text.starts_with("return") || script_function && text.starts_with("function"),
        Dialect::Fusion => text.starts_with("write"),
        Dialect::Ron => true,
    }
}

/// Checks one traced run; problems go to `failures`.
fn check(name: &str, dialect: Dialect, parts: &[Vec<u8>], records: &[Traced], failures: &mut Vec<String>) {
    let expected: usize = parts.iter().map(|p| lines(p).len()).sum();
    if records.len() != expected {
        failures.push(format!("{name}: {} trace records for {expected} lines", records.len()));
        return;
    }
    let mut at = (0usize, 0u64);
    for (part, line, text, script_function) in records {
        let next = if *part == at.0 { (at.0, at.1 + 1) } else { (at.0 + 1, 1) };
        if (*part, *line) != next {
            failures.push(format!("{name}: record for part {part} line {line} after part {} line {}", at.0, at.1));
            return;
        }
        at = next;
        match text {
            Ok(t) if statement_shape(dialect, t, *script_function) => {}
            Ok(t) => {
                failures.push(format!(
                    "{name}: line {line} traced to `{}`, not a statement",
                    t.lines().next().unwrap_or("")
                ));
                return;
            }
            Err(e) => {
                failures.push(format!("{name}: line {line}: {e}"));
                return;
            }
        }
    }
}

#[test]
fn every_corpus_line_is_traced_to_its_statement() {
    let root = corpus();
    let mut pairs: Vec<(PathBuf, PathBuf)> = Vec::new();
    for post in files(&root.join("posts/vectric"), "pp") {
        for toolpath in files(&root.join("toolpaths"), "ron") {
            pairs.push((post.clone(), toolpath));
        }
    }
    for post in files(&root.join("posts/cimco"), "js") {
        for toolpath in files(&root.join("toolpaths/cimco"), "ron") {
            pairs.push((post.clone(), toolpath));
        }
    }
    for post in files(&root.join("posts/vcpost"), "VcPost") {
        for toolpath in files(&root.join("toolpaths/vcpost"), "ron") {
            pairs.push((post.clone(), toolpath));
        }
    }
    let mut failures = Vec::new();
    let mut runs = 0;
    let mut traced_lines = 0;
    for (post, toolpath) in &pairs {
        let name = format!("{} over {}", post.display(), toolpath.display());
        let Some((dialect, parts, records)) = traced(post, toolpath) else { continue };
        runs += 1;
        traced_lines += records.len();
        check(&name, dialect, &parts, &records, &mut failures);
    }
    eprintln!("traced {runs} runs, {traced_lines} lines");
    assert!(runs >= 100, "only {runs} corpus runs posted");
    assert!(failures.is_empty(), "{} problems:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn real_vectric_posts_trace_every_line() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/vectric");
    if !dir.is_dir() {
        crate::support::referee_missing("trace", "../shared/corpus/vectric");
        eprintln!("skipped: {} is absent (the real-world corpus sits beside the checkout in CI)", dir.display());
        return;
    }
    let toolpath = corpus().join("toolpaths/arcs_mm.ron");
    let mut failures = Vec::new();
    let mut runs = 0;
    let mut real = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("list ../shared/corpus/vectric").flatten() {
        if entry.path().is_dir() {
            real.extend(files(&entry.path(), "pp"));
        }
    }
    real.sort();
    for post in real {
        let Some((dialect, parts, records)) = traced(&post, &toolpath) else { continue };
        runs += 1;
        check(&post.display().to_string(), dialect, &parts, &records, &mut failures);
    }
    assert!(runs >= 100, "only {runs} real posts posted");
    assert!(failures.is_empty(), "{} problems:\n{}", failures.len(), failures.join("\n"));
}

fn postc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_postc"))
}

#[test]
fn explain_names_the_post_line_and_the_toolpath_event() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.tap");
    let trace = dir.path().join("out.trace.jsonl");
    let root = corpus();
    let status = postc()
        .arg("post")
        .arg(root.join("posts/vectric/gcode_mm.pp"))
        .arg(root.join("toolpaths/arcs_mm.ron"))
        .arg("-o")
        .arg(&out)
        .arg("--trace")
        .arg(&trace)
        .status()
        .unwrap();
    assert!(status.success());
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(text.lines().count(), std::fs::read_to_string(&out).unwrap().lines().count());
    let line12 = text.lines().nth(11).unwrap();
    assert!(line12.contains("\"line\":12"), "{line12}");
    assert!(line12.contains("\"handler\":\"FIRST_FEED_MOVE\""), "{line12}");
    let explained = postc().arg("explain").arg(&trace).arg("12").output().unwrap();
    assert!(explained.status.success(), "{}", String::from_utf8_lossy(&explained.stderr));
    let shown = String::from_utf8_lossy(&explained.stdout);
    assert!(shown.contains("G1Z-1.000F250.0"), "{shown}");
    assert!(shown.contains("\"G1[X][Y][Z][F]\""), "{shown}");
    assert!(shown.contains("Feed(x: 10, y: 10, z: -1, intent: Plunge)"), "{shown}");
    assert!(shown.contains("FIRST_FEED_MOVE"), "{shown}");

    let missing = postc().arg("explain").arg(&trace).arg("9999").output().unwrap();
    assert_eq!(missing.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("IO011"));
}

#[test]
fn a_failed_run_writes_no_trace() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("bad.pp");
    std::fs::write(&post, "POST_NAME = \"x\"\nbegin HEADER\n\"G0 [X\"\n").unwrap();
    let trace = dir.path().join("t.jsonl");
    let status = postc()
        .arg("post")
        .arg(&post)
        .arg(corpus().join("toolpaths/arcs_mm.ron"))
        .arg("-o")
        .arg(dir.path().join("o.tap"))
        .arg("--trace")
        .arg(&trace)
        .status()
        .unwrap();
    assert!(!status.success());
    assert!(!trace.exists());
}

#[test]
fn verify_findings_name_the_post_line_from_the_trace() {
    let dir = tempfile::tempdir().unwrap();
    let root = corpus();
    // Arc directions swapped: every arc is a finding.
    let text = std::fs::read_to_string(root.join("posts/vectric/gcode_mm.pp")).unwrap();
    let swapped = text.replace("\"G2", "\"G#").replace("\"G3", "\"G2").replace("\"G#", "\"G3");
    assert_ne!(swapped, text);
    let post = dir.path().join("swapped.pp");
    std::fs::write(&post, swapped).unwrap();
    let out = dir.path().join("out.tap");
    let trace = dir.path().join("out.trace.jsonl");
    let run = postc()
        .arg("post")
        .arg(&post)
        .arg(root.join("toolpaths/arcs_mm.ron"))
        .args(["-o".as_ref(), out.as_os_str(), "--trace".as_ref(), trace.as_os_str(), "--verify".as_ref()])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("the post wrote this line here"), "{stderr}");
    assert!(stderr.contains("swapped.pp"), "{stderr}");
    assert!(stderr.contains("while the post handled CW_ARC_MOVE") || stderr.contains("ARC_MOVE"), "{stderr}");
    assert!(stderr.contains("toolpath event"), "{stderr}");
}

/// A CIMCO entry point with two `return`s: each line names the one that
/// returned it, though `onLinear` and `writeBlock` are inlined into the
/// handler and no call is left when the post runs.
#[test]
fn cimco_lines_name_the_return_that_wrote_them() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("two_returns.js");
    std::fs::write(
        &post,
        "var xyzFormat = createFormat({decimals: 3});\n\
         var xOutput = createVariable({prefix: \"X\"}, xyzFormat);\n\
         function writeBlock(text) { return text + \"\\n\"; }\n\
         function onLinear(x, y, z, movement) {\n\
         \x20 if (movement == MOVEMENT_RAPID) {\n\
         \x20   return writeBlock(\"G0\" + xOutput.format(x));\n\
         \x20 }\n\
         \x20 return writeBlock(\"G1\" + xOutput.format(x));\n\
         }\n",
    )
    .unwrap();
    let (dialect, parts, records) = traced(&post, &corpus().join("toolpaths/cimco/mill.ron")).expect("posts");
    assert_eq!(dialect, Dialect::Cimco);
    let program = String::from_utf8_lossy(&parts[0]).into_owned();
    let (mut rapid, mut feed) = (0, 0);
    for (line, (_, _, text, _)) in program.lines().zip(&records) {
        let text = text.as_deref().unwrap_or("");
        if line.starts_with("G0") {
            rapid += 1;
            assert!(text.starts_with("return writeBlock(\"G0\""), "{line} traced to {text}");
        } else if line.starts_with("G1") {
            feed += 1;
            assert!(text.starts_with("return writeBlock(\"G1\""), "{line} traced to {text}");
        }
    }
    assert!(rapid > 0 && feed > 0, "{program}");
}

/// A Fusion post's lines are written by the host's `writeln`: each is
/// traced to the post statement that called it, in the innermost post
/// function still running (`writeln(formatComment(text))` in the post's
/// `writeComment`, not the `return` of `formatComment` that ran last, nor
/// the host's own line).
#[test]
fn fusion_lines_name_the_post_statement_that_wrote_them() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("helpers.cps");
    std::fs::write(
        &post,
        "description = \"helpers\";\ncapabilities = CAPABILITY_MILLING;\n\
         var xOutput = createVariable({prefix: \"X\"}, createFormat({decimals: 3}));\n\
         function formatComment(text) {\n  return \"(\" + text + \")\";\n}\n\
         function writeComment(text) {\n  writeln(formatComment(text));\n}\n\
         function onOpen() {\n  writeComment(\"start\");\n}\n\
         function onLinear(x, y, z, feed) {\n  writeln(\"G1 \" + xOutput.format(x));\n}\n\
         function onRapid(x, y, z) {\n  writeln(\"G0 \" + xOutput.format(x));\n}\n\
         function onClose() {\n  writeComment(\"end\");\n}\n",
    )
    .unwrap();
    let (dialect, parts, records) =
        traced(&post, &corpus().join("toolpaths/native/one_toolpath_mm.ron")).expect("posts");
    assert_eq!(dialect, Dialect::Fusion);
    let program = String::from_utf8_lossy(&parts[0]).into_owned();
    let (mut comments, mut moves) = (0, 0);
    for (line, (_, _, text, _)) in program.lines().zip(&records) {
        let text = text.as_deref().unwrap_or("");
        if line.starts_with('(') {
            comments += 1;
            assert_eq!(text, "writeln(formatComment(text));", "{line}");
        } else if line.starts_with("G1") {
            moves += 1;
            assert_eq!(text, "writeln(\"G1 \" + xOutput.format(x));", "{line}");
        } else if line.starts_with("G0") {
            moves += 1;
            assert_eq!(text, "writeln(\"G0 \" + xOutput.format(x));", "{line}");
        }
    }
    assert!(comments == 2 && moves > 0, "{program}");
}
