//! CIMCO host semantics, end to end: formats and output variables, modal
//! memory shared by native code and scripts, errors and runaway loops
//! reported at the JavaScript line, and posts that must not panic.

use std::path::Path;

use postc_ir::event::{Event, FeedMove, Move, Tool, ToolpathStart, VecSource};
use postc_ir::{Body, FileId, Post, SourceMap};
use postc_runtime::{Finished, Output};

fn compile(js: &str) -> (Post, Vec<postc_ir::Diagnostic>, SourceMap) {
    let mut sources = postc_report::source_map();
    let (post, diags) = cimco(Path::new("test.js"), js.as_bytes(), &mut sources);
    (post, diags, sources)
}

fn cimco(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<postc_ir::Diagnostic>) {
    let c = postc_driver::compile_post_bytes(path, bytes, Some(postc_ir::Dialect::Cimco), sources);
    (c.post.unwrap_or_default(), c.diagnostics)
}

fn events() -> Vec<Event> {
    vec![
        Event::Job(Box::default()),
        Event::Tool(Tool { number: 1, cut_feed: 1000.0, plunge_feed: 300.0, spindle_speed: 8000.0, ..Tool::default() }),
        Event::ToolpathStart(ToolpathStart::default()),
        Event::Rapid(Move { x: 1.0, y: 2.0, z: 5.0, ..Move::default() }),
        Event::Feed(FeedMove { x: 3.0, y: 2.0, z: 5.0, ..FeedMove::default() }),
        Event::Feed(FeedMove { x: 3.0, y: 2.5, z: 5.0, ..FeedMove::default() }),
        Event::End,
    ]
}

fn run(post: &Post) -> Result<String, Vec<postc_ir::Diagnostic>> {
    let mut source = VecSource::new(events(), FileId(0));
    let report = postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post))?;
    match report.output {
        Finished::Memory(parts) => Ok(String::from_utf8_lossy(&parts.concat()).into_owned()),
        _ => unreachable!("memory output"),
    }
}

fn post_output(js: &str) -> String {
    let (post, diags, _) = compile(js);
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
    run(&post).unwrap_or_else(|d| panic!("{d:?}"))
}

/// A function calling `isFinite`: the general lowering has no form
/// for it, so the post keeps the shaped lowering and its Rhai scripts.
const KEEPS_SCRIPTS: &str = "function keepsScripts(t) { return isFinite(t); }\n";

#[test]
fn formats_trim_pad_sign_and_scale() {
    let out = post_output(
        r#"
        var linebreak = "\n";
        var a = createFormat({decimals: 3});
        var b = createFormat({decimals: 3, forceDecimal: true});
        var c = createFormat({width: 4, zeropad: true, decimals: 0});
        var d = createFormat({decimals: 2, forceSign: true});
        var e = createFormat({decimals: 1, scale: 2});
        var f = createFormat({decimals: 0, forceDecimal: true});
        function onOpen() {
            return [a.format(3), a.format(2.5), a.format(2.0005), a.format(-0.0001), b.format(3), c.format(1),
                    d.format(4.25), d.format(-1), e.format(1.26), f.format(80)].join(" ") + "\n";
        }
        function onLinear(x, y, z, m) { return ""; }
        "#,
    );
    assert_eq!(out, "3 2.5 2.001 0 3.000 0001 +4.25 -1 2.5 80.\n");
}

#[test]
fn modal_memory_is_shared_by_native_code_and_scripts() {
    let js = r#"
        var linebreak = "\n";
        var xOutput = createVariable({prefix: "X"}, createFormat({decimals: 1}));
        var seen = [];
        function onLinear(x, y, z, m) { return "L" + xOutput.format(x) + "\n"; }
        // Objects make this one a script, with the `isFinite` call below.
        function onClose() { seen.push(1); return "C" + xOutput.format(3) + "|" + xOutput.getLast() + "\n"; }
    "#;
    let js = format!("{js}{KEEPS_SCRIPTS}");
    let (post, diags, _) = compile(&js);
    assert!(diags.is_empty(), "{diags:?}");
    let kind = |name: &str| post.functions.iter().find(|f| f.name == name).map(|f| matches!(f.body, Body::Native(_)));
    assert_eq!(kind("onLinear"), Some(true));
    assert_eq!(kind("onClose"), Some(false));
    // X3 was printed natively last; the script's X3 is modal and prints nothing.
    assert_eq!(run(&post).unwrap(), "LX1\nLX3\nL\nC|3\n");
}

#[test]
fn script_errors_point_at_the_javascript() {
    let js = "var linebreak = \"\\n\";\nvar o = null;\nfunction onOpen() {\n    return \"O\" + o.name;\n}\nfunction onLinear(x, y, z, m) { return \"\"; }\n";
    let js = format!("{js}{KEEPS_SCRIPTS}");
    let (post, _, sources) = compile(&js);
    let d = run(&post).expect_err("the post fails");
    let d = d.iter().find(|d| d.code == "RT023").expect("an RT023 error");
    let span = d.primary_span().expect("a span");
    assert_eq!(sources.line_column(span.file, span.start), Some((4, 18)), "{d:?}");
}

#[test]
fn runaway_loops_stop_at_their_line() {
    for (body, line) in [("while (true) { n++; }", 4), ("for (;;) { list.push(n); if (list.length < 0) break; }", 4)] {
        let js = format!(
            "var linebreak = \"\\n\";\nvar n = 0, list = [];\nfunction onOpen() {{\n    {body}\n    return \"\";\n}}\nfunction onLinear(x, y, z, m) {{ return \"\"; }}\n"
        );
        let (mut post, diags, sources) = compile(&js);
        assert!(diags.is_empty(), "{diags:?}");
        post.options.step_budget = 100_000;
        let d = run(&post).expect_err("the post is stopped");
        let d = d.iter().find(|d| d.code == "RT002").unwrap_or_else(|| panic!("no RT002: {d:?}"));
        let span = d.primary_span().expect("a span");
        assert_eq!(sources.line_column(span.file, span.start).map(|(l, _)| l), Some(line), "{body}: {d:?}");
    }
}

#[test]
fn posts_have_no_file_network_or_process_access() {
    let js = r#"
        var linebreak = "\n";
        function onOpen() { var fs = require("fs"); return fs.readFileSync("/etc/passwd"); }
        function onLinear(x, y, z, m) { return ""; }
    "#;
    let (post, diags, _) = compile(js);
    assert!(diags.iter().any(|d| d.code == "JS102"), "{diags:?}");
    let d = run(&post).expect_err("require is not there");
    assert!(d.iter().any(|d| d.message.contains("require is not defined")), "{d:?}");
}

/// In Rhai scripts (the post keeps them) and in the general form (which
/// runs `prototype` as JavaScript does), the same text.
#[test]
fn javascript_semantics_in_scripts() {
    let js = r#"
        var linebreak = "\n";
        function Point(x) { this.x = x; }
        Point.prototype.twice = function () { return this.x * 2; };
        function counter(start) { var n = start; return function () { return n++; }; }
        function onOpen() {
            var c = counter(5);
            c();
            var p = new Point(4);
            var parts = [];
            switch (p.twice()) {
                case 8: parts.push("eight");
                case 9: parts.push("nine"); break;
                default: parts.push("other");
            }
            for (var k in {a: 1, b: 2}) { parts.push(k); }
            var s = "a(b)c".replace(/[()]/g, "-");
            try { throw "boom"; } catch (e) { parts.push(e); }
            return [c(), p.twice(), parts.join("+"), s, typeof p, 1 + "2", "3" * 2, 7 / 2, (1 / 3).toFixed(3), parseInt("12px"), 0.1 + 0.2].join(" ") + "\n";
        }
        function onLinear(x, y, z, m) { return ""; }
        "#;
    for (js, scripts) in [(js.to_string(), false), (format!("{js}{KEEPS_SCRIPTS}"), true)] {
        let (post, diags, _) = compile(&js);
        assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
        assert_eq!(!post.scripts.is_empty(), scripts);
        let out = run(&post).unwrap_or_else(|d| panic!("{d:?}"));
        assert_eq!(out, "6 8 eight+nine+a+b+boom a-b-c object 12 6 3.5 0.333 12 0.30000000000000004\n");
    }
}

#[test]
fn regular_expressions_as_javascript_runs_them() {
    // A text longer than 4,096 characters, an empty-match replace, split
    // with a group and search: what Node.js prints for the same code.
    let out = post_output(
        r#"
        var linebreak = "\n";
        function onOpen() {
            var long = "";
            for (var i = 0; i < 5000; i++) { long += "y"; }
            long += "(x)";
            var stripped = long.replace(/[()]/g, "");
            return [stripped.length, "baaac".replace(/a*/g, "-"), "a-b".split(/(-)/).join("|"), long.search(/\(/), /^\d+$/.test("12")].join(" ") + "\n";
        }
        function onLinear(x, y, z, m) { return ""; }
        "#,
    );
    assert_eq!(out, "5001 -b--c- a|-|b 5000 true\n");
}

#[test]
fn regular_expressions_without_a_linear_form_are_errors_at_their_line() {
    let js = "var linebreak = \"\\n\";\nfunction onOpen() {\n    return \"aa\".replace(/(a)\\1/, \"b\");\n}\nfunction onLinear(x, y, z, m) { return \"\"; }\n";
    // Lowered to native IR: refused when the post is compiled.
    let (_, diags, sources) = compile(js);
    let d = diags.iter().find(|d| d.code == "JS108").unwrap_or_else(|| panic!("a JS108 error: {diags:?}"));
    assert!(d.message.contains("backreference"), "{d:?}");
    let span = d.primary_span().expect("a span");
    assert_eq!(sources.line_column(span.file, span.start), Some((3, 25)), "{d:?}");
    // Kept in a script: an error when the script reaches it.
    let (post, diags, sources) = compile(&format!("{js}{KEEPS_SCRIPTS}"));
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
    let d = run(&post).expect_err("the post fails");
    let d = d.iter().find(|d| d.code == "RT023").unwrap_or_else(|| panic!("an RT023 error: {d:?}"));
    assert!(d.message.contains("backreference"), "{d:?}");
    let span = d.primary_span().expect("a span");
    assert_eq!(sources.line_column(span.file, span.start).map(|(l, _)| l), Some(3), "{d:?}");
}

/// What depends on a `lastIndex` postc does not keep, a function as a
/// replacement, and `^` under `m` over a `\r` stop the post with RT038 at
/// its function, natively and in a script alike, and a `try` does not
/// catch it.
#[test]
fn what_needs_last_index_is_refused_in_both_tiers() {
    for (body, what) in [
        ("var re = /a/g; re.test(\"a\"); return re.test(\"a\") + \"\\n\";", "`test`"),
        ("try { return /a/.exec(\"a\") + \"\\n\"; } catch (e) { return \"caught\\n\"; }", "`exec`"),
        ("var re = /a/; return re.lastIndex + \"\\n\";", "`lastIndex`"),
        ("return \"a\".replace(/a/, function (m) { return m; }) + \"\\n\";", "a function as the replacement"),
        ("return \"a\\r\\nb\".replace(/^/gm, \"> \") + \"\\n\";", "line end"),
    ] {
        let js = format!(
            "var linebreak = \"\\n\";\nfunction onOpen() {{\n    {body}\n}}\nfunction onLinear(x, y, z, m) {{ return \"\"; }}\n"
        );
        for js in [js.clone(), format!("{js}{KEEPS_SCRIPTS}")] {
            let (post, diags, sources) = compile(&js);
            assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
            let d = run(&post).expect_err("the post fails");
            let d = d.iter().find(|d| d.code == "RT038").unwrap_or_else(|| panic!("an RT038 error for {body}: {d:?}"));
            assert!(d.message.contains(what), "{d:?}");
            let span = d.primary_span().unwrap_or_else(|| panic!("a span: {d:?}"));
            assert!(matches!(sources.line_column(span.file, span.start), Some((2 | 3, _))), "{d:?}");
        }
    }
}

/// Posts cut short or with bytes changed still compile and run or fail
/// cleanly: no panic.
#[test]
fn mutated_posts_never_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut posts: Vec<String> = Vec::new();
    for d in ["corpus/posts/cimco", "frontends/cimco/tests/fixtures/valid"] {
        for e in std::fs::read_dir(dir.join(d)).expect("a folder").flatten() {
            posts.push(std::fs::read_to_string(e.path()).expect("a post"));
        }
    }
    let mut seed = 12345u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for text in &posts {
        for _ in 0..12 {
            let mut bytes = text.as_bytes().to_vec();
            match next() % 3 {
                0 => bytes.truncate((next() as usize) % bytes.len().max(1)),
                1 => {
                    let i = (next() as usize) % bytes.len().max(1);
                    bytes[i] = b"{}();+-.\"x0 "[(next() % 12) as usize];
                }
                _ => {
                    let i = (next() as usize) % bytes.len().max(1);
                    bytes.insert(i, b'(');
                }
            }
            let mut sources = postc_report::source_map();
            let (post, diags) = cimco(Path::new("m.js"), &bytes, &mut sources);
            if !postc_ir::diagnostic::has_errors(&diags) {
                let mut p = post;
                p.options.step_budget = 200_000;
                let _ = run(&p);
            }
        }
    }
}

/// A value that is not a finite number never becomes a word: formatting it
/// stops the run at the JavaScript line that formats it, in native code and
/// in scripts alike, and nothing is written.
#[test]
fn formatting_a_value_that_is_not_a_number_stops_at_its_line() {
    let cases = [
        // Native: NaN, a division by zero, an undefined global.
        ("function onOpen() {\n    return \"A\" + f.format(NaN) + \"\\n\";\n}", 5, true),
        (
            "function onOpen() {\n    return \"\";\n}\nfunction onLinear(x, y, z, m) {\n    return \"G1\" + g.format(x / 0) + \"\\n\";\n}",
            8,
            true,
        ),
        ("var u;\nfunction onOpen() {\n    return g.format(u) + \"\\n\";\n}", 6, true),
        ("function onOpen() {\n    return \"C\" + f.format(parseFloat(\"abc\")) + \"\\n\";\n}", 5, true),
        // A table lookup of a missing key (native), and in a script.
        ("var codes = {drill: 81};\nfunction onOpen() {\n    return g.format(codes[\"tap\"]) + \"\\n\";\n}", 6, true),
        (
            "var codes = {drill: 81};\nfunction onOpen() {\n    var state = {n: 0};\n    state.n = 1;\n    return g.format(codes[\"tap\"]) + \"\\n\";\n}",
            8,
            false,
        ),
        (
            "function onOpen() {\n    var state = {n: 0};\n    state.n = 1;\n    return f.format(1 / 0) + \"\\n\";\n}",
            7,
            false,
        ), // A format and an output variable handed to a helper as values.
        (
            "function word(w, v) {\n    return w.format(v);\n}\nfunction onOpen() {\n    return word(f, 0 / 0) + \"\\n\";\n}",
            5,
            true,
        ),
        (
            "function word(w, v) {\n    return w.format(v);\n}\nfunction onOpen() {\n    return word(g, 1 / 0) + \"\\n\";\n}",
            5,
            true,
        ),
    ];
    // The cases that use objects run three ways: natively as the general
    // lowering makes them, and as scripts when an `isFinite` call keeps the
    // post on Rhai.
    let cases = cases.into_iter().flat_map(|(body, line, native)| {
        let general = (!native).then(|| (body.to_string(), line, true));
        let script = (!native).then(|| (format!("{body}\n{KEEPS_SCRIPTS}"), line, false));
        std::iter::once((body.to_string(), line, native)).filter(move |_| native).chain(general).chain(script)
    });
    for (body, line, native) in cases {
        let js = format!(
            "var linebreak = \"\\n\";\nvar f = createFormat({{decimals: 3}});\nvar g = createVariable({{prefix: \"G\"}}, f);\n{body}\n"
        );
        let js =
            if js.contains("function onLinear") { js } else { js + "function onLinear(x, y, z, m) { return \"\"; }\n" };
        let (post, diags, sources) = compile(&js);
        assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
        let open = post.functions.iter().find(|f| f.name == "onOpen").expect("onOpen");
        let runs = if native { "native" } else { "script" };
        assert_eq!(matches!(open.body, Body::Native(_)), native, "onOpen should run as {runs}:\n{js}");
        let d = run(&post).expect_err(&format!("the post must stop:\n{js}"));
        let d = d.iter().find(|d| d.code == "RT032").unwrap_or_else(|| panic!("no RT032: {d:?}\n{js}"));
        let span = d.primary_span().expect("a span");
        let at = sources.line_column(span.file, span.start).map(|(l, _)| l);
        assert_eq!(at, Some(line), "{d:?}\n{js}");
    }
}

/// One site reading, storing and calling a property by name over objects
/// whose keys are in different orders, or missing it: each gets its own
/// property, as Node.js prints (the site's inline cache is only a hint).
#[test]
fn a_property_site_reads_objects_of_any_key_order() {
    let out = post_output(
        r#"
        function nameOf(o) { return o.name; }
        function setName(o, v) { o.name = v; return o; }
        function callIt(o) { return o.say(); }
        function onOpen() {
            var a = {name: "a", x: 1};
            var b = {x: 2, y: 3, name: "b"};
            var c = {y: 4};
            var d = {z: 0, name: "d0"};
            var out = [];
            var list = [a, b, c, b, a, d, c];
            for (var i = 0; i < list.length; i++) { out.push(String(nameOf(list[i]))); }
            setName(c, "c");
            setName(a, "a2");
            setName(b, "b2");
            setName({w: 1}, "w");
            for (var j = 0; j < list.length; j++) { out.push(nameOf(list[j])); }
            var p = {say: function () { return "p"; }, k: 1};
            var q = {k: 2, j: 3, say: function () { return "q" + this.k; }};
            var r = {k: 5};
            r.say = function () { return "r" + this.k; };
            var calls = [p, q, r, q, p];
            for (var m = 0; m < calls.length; m++) { out.push(callIt(calls[m])); }
            return out.join(" ") + "\n";
        }
        function onLinear(x, y, z, m) { return ""; }
        "#,
    );
    assert_eq!(out, "a b undefined b a d0 undefined a2 b2 c b2 a2 d0 c p q2 r5 q2 p\n");
}
