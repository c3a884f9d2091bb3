//! The VcPost applications end to end: a post is untrusted code (no file
//! or process access; a runaway loop stops at its line), the runtime-provided
//! composites functions, and the `postc post` / `postc probe-table` command
//! lines for probe tables and composites event files.

use postc_report::Render as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use postc_ir::{CallValue, MissingSub, Post, SourceMap, Span, SubCall};
use postc_runtime::{Finished, Output, RunOptions};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn compile(text: &str, sources: &mut SourceMap) -> (Post, Vec<postc_ir::Diagnostic>) {
    let compiled = postc_driver::compile_post_bytes(Path::new("t.VcPost"), text.as_bytes(), None, sources);
    (compiled.post.unwrap(), compiled.diagnostics)
}

fn toolpath() -> PathBuf {
    root().join("corpus/toolpaths/standard.ron")
}

/// Posts the standard toolpath; the error's code and the 1-based line of
/// its primary label in the post.
fn runaway(body: &str, budget: Option<u64>) -> (String, usize) {
    let text = format!("Sub GOTO\n  Dim I\n{body}\nEnd Sub\n");
    let mut sources = postc_report::source_map();
    let (mut post, diagnostics) = compile(&text, &mut sources);
    assert!(!postc_ir::diagnostic::has_errors(&diagnostics), "{}", sources.render(&diagnostics, false));
    if let Some(b) = budget {
        post.options.step_budget = b;
    }
    let mut source = postc_driver::open_toolpath(&toolpath(), &mut sources).unwrap();
    let errors = match postc_runtime::run(&post, &mut source, Output::memory(), postc_driver::run_options(&post)) {
        Ok(_) => panic!("{body}: the runaway loop was not stopped"),
        Err(d) => d,
    };
    let error = errors.iter().find(|d| d.is_error()).unwrap();
    let span = error.primary_span().expect("the error points at the post");
    (error.code.to_string(), sources.line_column(span.file, span.start).unwrap().0)
}

#[test]
fn a_runaway_loop_stops_at_its_line() {
    assert_eq!(runaway("  While True\n    I = I + 1\n  Wend", Some(100_000)), ("RT002".into(), 3));
    assert_eq!(runaway("  Do\n    I = I + 1\n  Loop Until I < 0", Some(100_000)), ("RT002".into(), 3));
    assert_eq!(runaway("  For I = 1 To 1E300\n  Next I", Some(100_000)), ("RT002".into(), 3));
    // The default budget (ten million steps per call) stops it too.
    assert_eq!(runaway("  While 1 = 1\n  Wend", None), ("RT002".into(), 3));
}

/// A register or `Format$` given a value that is not a finite number
/// stops the run at the `Out` that would print it: no `X0` in its place.
#[test]
fn a_number_that_is_not_finite_stops_at_its_out() {
    let at = |body: &str| runaway(body, None);
    assert_eq!(at("  X = X / 0\n  Out \"G1<X>\""), ("RT032".into(), 4));
    assert_eq!(at("  X = Sqr(-1)\n  Out \"G1<X>\""), ("RT032".into(), 4));
    assert_eq!(at("  Out \"G1X\" & Format$(Sqr(-1), \"0.000\")"), ("RT032".into(), 3));
}

#[test]
fn endless_recursion_stops() {
    let mut sources = postc_report::source_map();
    let (post, _) = compile("Sub Again\n  Again\nEnd Sub\nSub GOTO\n  Again\nEnd Sub\n", &mut sources);
    let mut source = postc_driver::open_toolpath(&toolpath(), &mut sources).unwrap();
    let errors =
        postc_runtime::run(&post, &mut source, Output::memory(), postc_driver::run_options(&post)).err().unwrap();
    assert!(errors.iter().any(|d| d.code == "RT004"), "{errors:?}");
}

#[test]
fn a_post_has_no_file_or_process_access() {
    for (line, code) in [
        ("  X = Shell(\"rm -rf /\")", "VC032"),
        ("  Open \"/etc/passwd\" For Input As #1", "VC003"),
        ("  Set F = CreateObject(\"Scripting.FileSystemObject\")", "VC025"),
        ("  X = CreateObject(\"WScript.Shell\")", "VC023"),
        ("  Kill \"/tmp/x\"", "VC025"),
    ] {
        let mut sources = postc_report::source_map();
        let (_, diagnostics) = compile(&format!("Sub GOTO\n{line}\nEnd Sub\n"), &mut sources);
        assert!(diagnostics.iter().any(|d| d.code == code && d.is_error()), "{line}: {diagnostics:?}");
    }
}

#[test]
fn composites_functions_read_the_calls_lists() {
    let text = "Sub GoTo\n  Out \"L\" & getNthLength1(0) & \",\" & getNthLength1(2) & \",\" & getNthLength3(1) & \",\" & getNthLength1(99)\nEnd Sub\n";
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(text, &mut sources);
    assert!(diagnostics.is_empty(), "{diagnostics:?}");
    let call = |vars: Vec<(String, CallValue)>| SubCall {
        sub: "goto".into(),
        vars,
        span: Span::default(),
        missing: MissingSub::Warn,
    };
    let calls = vec![
        call(vec![
            ("getNthLength1".into(), CallValue::List(vec![5.0, 6.0, 7.5])),
            ("GETNTHLENGTH3".into(), CallValue::List(vec![1.0, 2.0])),
        ]),
        call(Vec::new()),
        call(vec![("Unknown".into(), CallValue::Number(1.0)), ("Missing".into(), CallValue::List(vec![1.0]))]),
        SubCall { sub: "NoSuchSub".into(), vars: Vec::new(), span: Span::default(), missing: MissingSub::Warn },
        SubCall { sub: "Optional".into(), vars: Vec::new(), span: Span::default(), missing: MissingSub::Skip },
    ];
    let report = postc_runtime::calls::run_calls(
        &postc_driver::for_calls(&post),
        &mut calls.into_iter(),
        Output::memory(),
        RunOptions::default(),
    )
    .unwrap();
    let Finished::Memory(parts) = report.output else { panic!() };
    assert_eq!(String::from_utf8_lossy(&parts[0]), "L5,7.5,2,0\nL0,0,0,0\nL0,0,0,0\n");
    assert_eq!(report.warnings.iter().map(|d| d.code).collect::<Vec<_>>(), ["RT030"]);
}

fn postc(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_postc")).args(args).current_dir(root()).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn probe_table_command() {
    let (code, stdout, _) = postc(&["probe-table", "corpus/posts/vcpost/siemens_probe.VcPost"]);
    assert_eq!(code, 0);
    assert!(stdout.contains("\nWallThick,!X,!Y,!Width,!Depth,!Angle,!Correction,Offset,MaxSafe\n"), "{stdout}");
    let (code, _, stderr) = postc(&["probe-table", "corpus/posts/vcpost/fanuc_mill.VcPost"]);
    assert_eq!((code, stderr.contains("PT016")), (1, true), "{stderr}");
}

#[test]
fn post_runs_tables_and_event_files_and_refuses_bad_ones() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "Initialize\nRapid,1,2\nTerminate\n").unwrap();
    let out = dir.path().join("out.mpf");
    let (code, _, stderr) = postc(&[
        "post",
        "corpus/posts/vcpost/siemens_probe.VcPost",
        bad.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("PT008") && stderr.contains("bad.csv:2:10"), "{stderr}");
    assert!(!out.exists(), "no output is written for a bad table");

    let (code, stdout, stderr) =
        postc(&["post", "corpus/posts/vcpost/siemens_probe.VcPost", "corpus/probe/siemens_probe__housing.csv"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("CYCLE979"));

    let events = "corpus/composites/afp_roller__spar_ply90.vcp.jsonl";
    let (code, stdout, stderr) =
        postc(&["post", "corpus/posts/vcpost/afp_roller.VcPost", events, "--primer", "S5_Horizontal"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("M38 S5"), "the primer ran first: {stdout}");
    let (code, _, stderr) = postc(&["post", "corpus/posts/vcpost/afp_roller.VcPost", events, "--primer", "Nope"]);
    assert_eq!((code, stderr.contains("CP005")), (1, true), "{stderr}");

    let broken = dir.path().join("broken.vcp.ron");
    std::fs::write(&broken, "VcpFile(kind: Probing)\nProgramHeader\n").unwrap();
    let (code, _, stderr) = postc(&["post", "corpus/posts/vcpost/afp_probe.VcPost", broken.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(stderr.contains("CP003") && stderr.contains("broken.vcp.ron:2:1"), "{stderr}");
}

#[test]
fn the_docs_record_table_is_the_runtimes() {
    let module = std::fs::read_to_string(root().join("runtime/src/apt_words.rs")).unwrap();
    let doc = std::fs::read_to_string(root().join("docs/vcpost.md")).unwrap();
    let table = |lines: Vec<&str>| -> Vec<String> {
        let start = lines.iter().position(|l| l.starts_with("| record | from | sets |")).expect("the record table");
        lines[start..].iter().take_while(|l| l.starts_with('|')).map(|l| l.to_string()).collect()
    };
    let from_module = table(module.lines().filter_map(|l| l.strip_prefix("//! ")).collect());
    let from_doc = table(doc.lines().collect());
    assert!(from_module.len() > 10);
    assert_eq!(from_doc, from_module, "docs/vcpost.md and runtime/src/apt_words.rs disagree");
}
