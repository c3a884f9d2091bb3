//! `postc inspect` says, for every CIMCO function that runs as a script,
//! why: the construct with no native form and where it is.
//! The functions every move goes through (`onLinear`, `onCircular`,
//! `onRapid` and everything they call) are native in every corpus post.

use postc_ir::visit::{Visit, walk_expr};
use postc_ir::{Body, Expr, Function, Post};

use crate::support::{corpus, files};

/// Move handlers (and functions they call) of corpus posts that still run
/// as scripts. The field-style posts' variadic
/// `writeBlock(a, b, c)` is native, one form per number of arguments, and
/// so are arrays kept in slots (indexed, handed to `writeBlock.apply` with
/// a length the lowering follows, arrays of objects returned in an
/// object) and tables that are arrays: the list is empty, and only
/// shrinks.
const KNOWN_SCRIPTS: &[(&str, &str)] = &[];

/// The entry points every move goes through.
const MOVE_HANDLERS: &[&str] = &["onLinear", "onCircular", "onRapid"];

/// The functions a function calls, as native IR says (a script's calls are
/// not known here; a script on the way is reported as one).
fn callees(post: &Post, f: &Function) -> Vec<usize> {
    struct Calls(Vec<usize>);
    impl Visit for Calls {
        fn visit_expr(&mut self, e: &Expr) {
            if let Expr::Call(f, _) = e {
                self.0.push(f.index());
            }
            walk_expr(self, e);
        }
    }
    let mut c = Calls(Vec::new());
    if let Body::Native(body) = &f.body {
        body.iter().for_each(|s| c.visit_stmt(s));
    }
    c.0.retain(|&i| i < post.functions.len());
    c.0
}

#[test]
fn every_script_function_says_why_and_the_move_handlers_are_native() {
    let mut problems = Vec::new();
    for path in files(&corpus().join("posts/cimco"), "js") {
        let mut sources = postc_report::source_map();
        let post = postc_driver::compile_post(&path, None, &mut sources).post.expect("compiles");
        for f in &post.functions {
            match (&f.body, &f.why_script) {
                (Body::Script(_), None) => {
                    problems.push(format!("{}: `{}` is a script and says not why", path.display(), f.name))
                }
                (Body::Native(_), Some(w)) => {
                    problems.push(format!("{}: `{}` is native but says {}", path.display(), f.name, w.what))
                }
                _ => {}
            }
        }
        // The move handlers and every function they call, transitively.
        let stem = path.file_stem().unwrap_or_default().to_string_lossy().into_owned();
        let mut seen = vec![false; post.functions.len()];
        let mut todo: Vec<(usize, String)> = post
            .functions
            .iter()
            .enumerate()
            .filter(|(_, f)| MOVE_HANDLERS.contains(&f.name.as_str()))
            .map(|(i, f)| (i, f.name.clone()))
            .collect();
        while let Some((i, via)) = todo.pop() {
            if std::mem::replace(&mut seen[i], true) {
                continue;
            }
            let f = &post.functions[i];
            let known = KNOWN_SCRIPTS.iter().any(|(p, func)| *p == stem && *func == f.name);
            let script = matches!(f.body, Body::Script(_));
            if script != known {
                problems.push(if script {
                    let why = f.why_script.as_ref().map_or("", |w| w.what.as_str());
                    format!("{}: `{}` (reached from `{via}`) runs as a script: {why}", path.display(), f.name)
                } else {
                    format!("{}: `{}` is native now: take it off KNOWN_SCRIPTS", path.display(), f.name)
                });
            }
            todo.extend(callees(&post, f).into_iter().map(|c| (c, format!("{via} > {}", f.name))));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn inspect_names_the_construct_and_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("args.js");
    std::fs::write(
        &post,
        "function writeBlock() {\n  var words = arguments;\n  return words.length;\n}\nfunction onLinear(x, y, z, movement) { return writeBlock(\"G1\", \"X\" + x); }\nfunction keepsScripts(t) { return isFinite(t); }\n",
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_postc")).arg("inspect").arg(&post).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().find(|l| l.starts_with("// function writeBlock")).unwrap_or_default();
    assert!(line.contains("script: uses `arguments` other than as `arguments.length`"), "{text}");
    assert!(line.contains("args.js:2:15"), "{line}");
    // The form for two arguments says so; onLinear calls it through the host.
    assert!(text.contains("(its form for 2 arguments);") && text.contains("args.js:2:15"), "{text}");
    let line = text.lines().find(|l| l.starts_with("// function onLinear")).unwrap_or_default();
    assert!(line.contains("native"), "{line}");
}

#[test]
fn bench_profile_shows_where_the_time_goes() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("args.js");
    std::fs::write(
        &post,
        "var xyzFormat = createFormat({decimals: 3});\nfunction writeBlock(a, b) {\n  return a + b;\n}\nfunction onLinear(x, y, z, movement) {\n  var words = {g: \"G1\"};\n  words.g = \"G01\";\n  return writeBlock(words.g, xyzFormat.format(x));\n}\nfunction keepsScripts(t) { return isFinite(t); }\n",
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_postc"))
        .args(["bench".as_ref(), post.as_os_str(), "--moves".as_ref(), "2000".as_ref(), "--profile".as_ref()])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("where the time goes"), "{text}");
    // onLinear changes an object: it is a script, and the calls inside
    // Rhai are its time.
    let row = text.lines().find(|l| l.starts_with("onLinear")).unwrap_or_default();
    assert!(row.contains("script"), "{text}");
    let row = text.lines().find(|l| l.starts_with("FEED_MOVE")).unwrap_or_default();
    assert!(row.contains("handler"), "{text}");
    assert!(text.contains("`onLinear` runs as a script: assigns a property of an object"), "{text}");
}

/// Every function of every corpus CIMCO post and field-style post runs as
/// native IR: a change that sends one back to the Rhai tier fails here,
/// naming the function and the reason `postc inspect` gives.
#[test]
fn no_corpus_cimco_function_is_a_script() {
    let mut problems = Vec::new();
    let posts = files(&corpus().join("posts/cimco"), "js").into_iter().chain(crate::support::cimco::style_posts());
    for path in posts {
        let mut sources = postc_report::source_map();
        let post = postc_driver::compile_post(&path, None, &mut sources).post.expect("compiles");
        for f in post.functions.iter().filter(|f| matches!(f.body, Body::Script(_))) {
            let why = f.why_script.as_ref().map_or("", |w| w.what.as_str());
            problems.push(format!("{}: `{}` is a script: {why}", path.display(), f.name));
        }
        if !post.scripts.is_empty() {
            problems.push(format!("{}: {} script(s) left", path.display(), post.scripts.len()));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The runtime's passes keep what the code means: every corpus CIMCO post
/// and field-style post, run as its IR says (no `prepare`) and prepared,
/// prints the same bytes over the mill, drill and standard toolpaths.
#[test]
fn prepared_and_unprepared_runs_print_the_same() {
    let mut problems = Vec::new();
    let mut ran_short = Vec::new();
    let posts = files(&corpus().join("posts/cimco"), "js").into_iter().chain(crate::support::cimco::style_posts());
    let toolpaths = ["toolpaths/cimco/mill.ron", "toolpaths/cimco/drill.ron", "toolpaths/standard.ron"];
    for path in posts {
        let mut sources = postc_report::source_map();
        let post = postc_driver::compile_post(&path, None, &mut sources).post.expect("compiles");
        for toolpath in toolpaths.map(|t| corpus().join(t)) {
            let run = |unprepared: bool| {
                let mut sources = postc_report::source_map();
                let mut source = postc_driver::open_toolpath(&toolpath, &mut sources).expect("opens");
                let mut options = postc_driver::run_options(&post);
                options.unprepared = unprepared;
                match postc_runtime::run(&post, &mut source, postc_runtime::output::Output::memory(), options) {
                    Ok(report) => match report.output {
                        postc_runtime::output::Finished::Memory(parts) => Ok(parts.concat()),
                        _ => Err("not in memory".to_string()),
                    },
                    Err(d) => Err(d.iter().map(|d| format!("{} {}", d.code, d.message)).collect::<Vec<_>>().join("; ")),
                }
            };
            let (prepared, raw) = (run(false), run(true));
            if let Err(e) = &prepared {
                ran_short.push(format!("{} over {}: {e}", path.display(), toolpath.display()));
            }
            if prepared != raw {
                problems.push(format!(
                    "{} over {}: prepared {:?} bytes, unprepared {:?} bytes",
                    path.display(),
                    toolpath.display(),
                    prepared.as_ref().map(Vec::len),
                    raw.as_ref().map(Vec::len)
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // Every run posts a whole program (two runs that fail alike would
    // compare equal and prove nothing).
    assert!(ran_short.is_empty(), "{}", ran_short.join("\n"));
}
