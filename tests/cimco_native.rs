//! The JavaScript that field posts are written in lowers to native IR,
//! and posts what Node.js posts: variadic functions and
//! `arguments`, `f.apply`, arrays gathered with `push` and joined,
//! object-literal tables, `switch` with fallthrough, `for ... in` over a
//! table, `do ... while`, `substring`. Each construct has a post where the
//! lowering fires (the function is native) and one where it must not (the
//! function stays a script and says why); both must print what Node.js
//! prints. Without Node.js the comparison is skipped, with a message, and fails under `CI=true`.

use crate::support::cimco::*;
use crate::support::prepared::*;
use postc_ir::{Body, Post};

/// The head every test post shares: formats, variables, and a variadic
/// `writeBlock` in the field style.
const HEAD: &str = r#"
var linebreak = "\n";
var seq = 10;
var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
function writeBlock() {
    var words = [];
    for (var i = 0; i < arguments.length; ++i) {
        if (arguments[i] != "") {
            words.push(arguments[i]);
        }
    }
    if (words.length == 0) {
        return "";
    }
    var text = words.join(" ");
    text = "N" + seq + " " + text;
    seq += 10;
    return text + linebreak;
}
function onCircular(cx, cy, cz, ex, ey, ez, isCW, m) {
    return writeBlock(isCW ? "G2" : "G3", xOutput.format(ex), yOutput.format(ey), zOutput.format(ez));
}
"#;

/// Compiles `HEAD` + `body`, checks which functions are native, and
/// compares postc's program over the milling job with Node's.
fn check(name: &str, body: &str, native: &[&str], script: &[&str]) {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join(format!("{name}.js"));
    std::fs::write(&path, format!("{HEAD}{body}")).expect("writes the post");
    let post = compile(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    for f in native {
        assert!(is(&post, f, true), "{name}: `{f}` should be native\n{}", how(&post));
    }
    // What the shaped lowering leaves to scripts makes the general
    // lowering take the whole post: every function native, no script.
    for f in script {
        assert!(is(&post, f, true) && post.scripts.is_empty(), "{name}: `{f}` should be lowered whole\n{}", how(&post));
    }
    let toolpath = corpus().join("toolpaths/cimco/mill.ron");
    let ours = post_toolpath(&post, &toolpath).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(!ours.is_empty(), "{name}: nothing posted");
    if node_or_skip("cimco_native").is_none() {
        return;
    }
    let jsonl = dir.path().join("mill.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("exports the toolpath");
    let theirs = run_node(&path, &jsonl, &[]).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(theirs == ours, "{name}: Node.js (-) and postc (+) differ\n{}", diff(&theirs, &ours));
}

fn is(post: &Post, name: &str, native: bool) -> bool {
    let mut found = post.functions.iter().filter(|f| f.name == name).peekable();
    found.peek().is_some() && found.all(|f| matches!(f.body, Body::Native(_)) == native)
}

fn how(post: &Post) -> String {
    post.functions
        .iter()
        .map(|f| format!("{}: {:?}\n", f.name, f.why_script.as_ref().map(|w| w.what.as_str())))
        .collect()
}

#[test]
fn variadic_functions_are_native_per_number_of_arguments() {
    check(
        "variadic",
        r#"
        function wordsOf() { return arguments.length + ":" + (arguments.length > 1 ? arguments[1] : "-"); }
        function line2() { return writeBlock.apply(null, arguments); }
        function onOpen(c) {
            return writeBlock("%") + writeBlock() + writeBlock("G90", "", "G17") + wordsOf("a") + wordsOf("a", 7)
                + linebreak + line2("G21", "G40") + writeBlock.apply(null, ["M6", "T1"]);
        }
        function onLinear(x, y, z, m) {
            return writeBlock(m == MOVEMENT_RAPID ? "G0" : "G1", xOutput.format(x), yOutput.format(y), zOutput.format(z));
        }
        "#,
        &["writeBlock", "writeBlock/1", "writeBlock/3", "writeBlock/4", "wordsOf/1", "line2", "onLinear", "onOpen"],
        &[],
    );
}

#[test]
fn arguments_used_as_a_value_lowers_the_post_whole() {
    check(
        "arguments_value",
        r#"
        function count() { var a = arguments; return a.length; }
        function onLinear(x, y, z, m) { return writeBlock("G1", xOutput.format(x), "C" + count(x, y)); }
        "#,
        &["onLinear", "writeBlock"],
        &["count"],
    );
}

#[test]
fn arrays_pushed_measured_and_joined_are_native() {
    check(
        "arrays",
        r#"
        function list(a, b) {
            var w = ["<", a];
            w.push(b, 3, null);
            w.push(undefined);
            w.unshift("N1", 7);
            return w.length + "=" + w.join("|");
        }
        function front(a) { var w = []; w.unshift(a); w.unshift("b"); w.push("c"); return w.join(" "); }
        function onOpen(c) { return list("x", 2.5) + front("a") + linebreak; }
        function onLinear(x, y, z, m) { return writeBlock(xOutput.format(x)); }
        "#,
        &["list", "front", "onOpen"],
        &[],
    );
}

#[test]
fn arrays_kept_in_slots_are_native() {
    check(
        "arrays_slots",
        r#"
        function pick(a, i) {
            var w = [a, "b", 3];
            return w[0] + w[i] + w.length + w.join("-") + w.join("+") + (w[7] === undefined) + "|" + w["1"]
                + w[i + 1];
        }
        function onOpen(c) { return pick("x", 1) + pick("y", 0) + pick("z", 2) + linebreak; }
        function onLinear(x, y, z, m) {
            var axes = [xOutput.format(x), yOutput.format(y), zOutput.format(z)];
            if (axes[0] == "" && axes[1] == "" && axes[2] == "") {
                return "";
            }
            var words = [];
            if (m == MOVEMENT_RAPID) {
                words.push("G0");
            }
            for (var i = 0; i < axes.length; i++) {
                words.push(axes[i]);
            }
            if (m != MOVEMENT_RAPID) {
                words.push("F" + m);
            }
            words[words.length] = ";";
            words[0] = words[0] + "";
            return writeBlock.apply(null, words);
        }
        "#,
        &["pick", "onOpen", "onLinear", "writeBlock/4", "writeBlock/5"],
        &[],
    );
}

#[test]
fn arrays_filled_in_bounded_loops_are_native() {
    check(
        "arrays_loops",
        r#"
        function pieces(n) {
            var list = [];
            for (var k = 0; k < 5; k++) {
                if (k >= n) {
                    break;
                }
                list.push("P" + k);
            }
            list.push("end");
            return list.length + ":" + list.join(",") + ":" + list[n] + ":" + list[0] + ":"
                + writeBlock.apply(null, list);
        }
        function running(n) {
            var seen = ["S"];
            var s = "";
            for (var k = 0; k < 4; k++) {
                if (k > 0) {
                    s += seen[k - 1] + seen.length + "|" + seen[k + 1] + ";";
                }
                if (k == n) {
                    break;
                }
                seen.push("S" + k);
            }
            return s + "/" + seen.join(".") + "/" + seen[seen.length - 1];
        }
        function onOpen(c) { return pieces(0) + pieces(2) + pieces(7) + running(1) + running(9) + linebreak; }
        function onLinear(x, y, z, m) {
            var words = [xOutput.format(x)];
            if (m == MOVEMENT_RAPID) {
                words.push("G0");
            }
            if (y > 1) {
                words.push(yOutput.format(y));
            }
            if (z < 0) {
                words.push(zOutput.format(z));
            }
            if (m == MOVEMENT_PLUNGE) {
                words.push("(plunge)");
            }
            return writeBlock.apply(null, words);
        }
        "#,
        &["pieces", "running", "onOpen", "onLinear"],
        &[],
    );
}

#[test]
fn objects_records_and_returned_objects_are_native() {
    check(
        "objects",
        r#"
        var quadrants = [{c: 1, s: 0}, {c: 0, s: 1}, {c: -1, s: 0}, {c: 0, s: -1}];
        var codes = ["G40", "G41", "G42"];
        var names = {first: {n: "one", v: 1}, second: {n: "two", v: 2}};
        function corner(k, r) {
            var q = quadrants[k % 4];
            k = k + 1;
            return {x: r * q.c, y: r * q.s, tag: codes[k % 3]};
        }
        function path(n) {
            var pts = [];
            for (var k = 0; k < 4; k++) {
                if (k == n) {
                    break;
                }
                pts.push(corner(k, 2));
            }
            return {count: pts.length, pts: pts, first: corner(1, 3)};
        }
        function onOpen(c) {
            var p = path(3);
            var none = path(0);
            var all = path(9);
            var s = "";
            for (var i = 0; i < p.pts.length; i++) {
                var e = p.pts[i];
                s += e.tag + "(" + e.x + "," + e.y + ")";
            }
            var o = {a: "A", list: [1, 2], inner: {b: "B"}};
            return s + p.count + p.first.x + p.first.tag + quadrants[2].c + quadrants.length + codes.length
                + names.second.n + names["first"].v + o.a + o.list[1] + o.list.length + o.inner.b + "|" + o.missing
                + writeBlock.apply(null, codes) + none.count + all.pts[3].tag + "|" + all.pts[4] + linebreak;
        }
        function onLinear(x, y, z, m) {
            return writeBlock(codes[m == MOVEMENT_RAPID ? 0 : 1], xOutput.format(x));
        }
        "#,
        &["corner", "path", "onOpen", "onLinear"],
        &[],
    );
}

#[test]
fn arrays_used_otherwise_lower_the_post_whole() {
    check(
        "arrays_other",
        r#"
        function grow(n) { var w = []; while (w.length < n) { w.push("x"); } return w[0]; }
        function count(list) { return list.length; }
        function pass(a) { var w = [a]; return count(w); }
        function change(a) { var o = {v: a}; o.v = 2; return o.v; }
        function reuse(a) { var w = [a]; w = [a, a]; return w[1]; }
        function early(n) {
            var w = [];
            var s = "";
            for (var k = 0; k < n && k < 3; k++) { s += w[0]; w.push(k); }
            return s;
        }
        function onOpen(c) { return grow(3) + pass("a") + change(1) + reuse(4) + early(2) + linebreak; }
        function onLinear(x, y, z, m) { return writeBlock(xOutput.format(x)); }
        "#,
        &["onLinear"],
        &["grow", "pass", "count", "change", "reuse", "early"],
    );
}

#[test]
fn object_tables_are_native_lookups() {
    check(
        "tables",
        r#"
        var codes = {1: "G02", 0: "G03", off: "M09", "2.5": "half"};
        var names = {a: "first", b: "second"};
        function code(k) { return codes[k]; }
        function onOpen(c) {
            var s = "";
            for (var k in codes) { s += k + "=" + codes[k] + ";"; }
            return s + code(1) + code("1") + code(0) + code("off") + code(2.5) + "|" + ("M" + codes[7]) + "|"
                + (codes.missing || "none") + "|" + names.a + "|" + (code(true ? 1 : 0) == "G02") + linebreak;
        }
        function onLinear(x, y, z, m) { return writeBlock(codes[m == MOVEMENT_RAPID ? 1 : 0], xOutput.format(x)); }
        "#,
        &["code", "onOpen", "onLinear"],
        &[],
    );
}

#[test]
fn tables_that_change_lower_the_post_whole() {
    check(
        "tables_changed",
        r#"
        var codes = {1: "G02", 0: "G03"};
        function code(k) { return codes[k]; }
        function onOpen(c) { codes[2] = "G04"; return code(2) + linebreak; }
        function onLinear(x, y, z, m) { return writeBlock(code(1), xOutput.format(x)); }
        "#,
        &[],
        &["code", "onOpen"],
    );
}

#[test]
fn switch_with_fallthrough_and_loops_are_native() {
    check(
        "switch",
        r#"
        function kind(n) {
            var s = "";
            switch (n) {
            case 1:
                s += "one ";
            case 2:
                s += "two ";
                break;
            default:
                s += "many ";
            case 0:
                s += "zero ";
            }
            return s;
        }
        function pad(n) {
            var s = "" + n;
            do {
                s = "0" + s;
            } while (s.length < 5);
            return "O" + s.substring(1) + s.substring(3, 1) + s.substring(9);
        }
        function onOpen(c) { return kind(1) + kind(2) + kind(5) + kind(0) + pad(42) + linebreak; }
        function onLinear(x, y, z, m) { return writeBlock(xOutput.format(x)); }
        "#,
        &["kind", "pad", "onOpen"],
        &[],
    );
}

/// A `writeBlock(text)` that drops the blank before its first word
/// (`text.substring(1)`, okuma_field.js) is built in the output and cut
/// there (the runtime's `Cut`); what it writes is what Node.js writes,
/// for accented words, numbers added before a text word, a cut past the
/// end and an empty block too.
#[test]
fn a_block_built_in_the_output_is_cut_as_substring_cuts() {
    check(
        "cut",
        r#"
        var comp = "";
        function block(text) {
            if (text == "") {
                return "";
            }
            return text.substring(1) + linebreak;
        }
        function tail(text) { return text.substring(9) + "|" + linebreak; }
        function word(m) { return m == 0 ? "" : " G" + m; }
        function onOpen(c) { return block(" é" + xOutput.format(1)) + tail(" ab") + block(1 + 2 + " N") + block(""); }
        function onLinear(x, y, z, m) {
            var c = comp;
            comp = " ";
            return block(c + word(m) + xOutput.format(x) + yOutput.format(y) + zOutput.format(z));
        }
        "#,
        &["block", "tail", "onOpen", "onLinear"],
        &[],
    );
    let post = {
        let dir = tempfile::tempdir().expect("a temporary folder");
        let path = dir.path().join("cut.js");
        std::fs::write(
            &path,
            format!(
                "{HEAD}{}",
                r#"function block(text) { if (text == "") { return ""; } return text.substring(1) + linebreak; }
                function onLinear(x, y, z, m) { return block(" G1" + xOutput.format(x)); }"#
            ),
        )
        .expect("writes the post");
        compile(&path).expect("compiles")
    };
    let code = postc_runtime::prepare::prepare(&post);
    let cuts: usize = code.handlers.iter().map(|h| count_stmts(h, &|s| matches!(s, XStmt::Cut { .. }))).sum();
    assert!(cuts > 0, "the handler cuts in the output: {:?}", code.handlers);
}

/// A `writeBlock` that joins its words with `text = text == "" ? word :
/// text + " " + word` (mach3_field.js) is built in the output when every
/// word is text, and runs as a call when one is not (a number is not
/// "nothing written" when it is 0 or when it prints); Node.js agrees either
/// way.
#[test]
fn words_joined_into_a_text_are_built_in_the_output_when_they_are_text() {
    let words = r#"
        function block() {
            var text = "";
            for (var i = 0; i < arguments.length; i++) {
                if (arguments[i] != "") {
                    text = text == "" ? arguments[i] : text + " " + arguments[i];
                }
            }
            if (text == "") {
                return "";
            }
            text = "N" + seq + " " + text;
            seq += 10;
            return text + linebreak;
        }
        var count = 0;
        function number() { count = count + 1; return count % 3 == 0 ? 0 : count; }
        function onOpen(c) { return block(number(), "G90", 0, "") + block("", "") + block(7) + block(1, 2); }
        function onLinear(x, y, z, m) {
            return block(m == 0 ? "G0" : "G1", xOutput.format(x), yOutput.format(y), zOutput.format(z)) + block(number(), "M1");
        }
    "#;
    check("join", words, &["onOpen", "onLinear"], &[]);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("join.js");
    std::fs::write(&path, format!("{HEAD}{words}")).expect("writes the post");
    let post = compile(&path).expect("compiles");
    let prepared = postc_runtime::prepare::prepare(&post).handlers;
    assert!(
        prepared.iter().any(|h| any_expr(h, &|e| matches!(e, XExpr::LocalIsText { .. }))),
        "the inlined join is guarded by the words being text: {prepared:?}"
    );
}

/// Small functions spliced into a handler, copies and constants read
/// through, and `w != ""` / `typeof w === "string"` asked of a local in one
/// step (`runtime/src/prepare/{splice,locals}.rs`, `fuse::expressions`): a
/// word that is sometimes the number 0 (`0 == ""` in JavaScript) and a
/// `switch` on a constant print what Node.js prints; so does
/// `parseFloat(v.format(x).substring(1))` read where it is formatted, with
/// a prefix that is not ASCII and a variable that prints nothing
/// (`NaN`).
#[test]
fn spliced_functions_and_local_tests_print_what_node_prints() {
    let body = r#"
        var last = "";
        var n = 0;
        var aOutput = createVariable({prefix: "éA"}, xyzFormat);
        function motion(code) { if (code == last) { return ""; } last = code; return code; }
        function kind(m) { switch (m) { case 0: return "G0"; case 1: return "G1"; } return "G1"; }
        function zero() { n = n + 1; return n % 3 == 0 ? 0 : (n % 3 == 1 ? "" : "M" + n); }
        function onLinear(x, y, z, m) {
            var w = zero();
            var c = w;
            var t = typeof c === "string" ? "T" : "N";
            var e = c != "" ? "X" : "E";
            var f = c === "" ? "S" : "D";
            var p = parseFloat(aOutput.format(z).substring(1));
            var q = parseFloat(yOutput.format(y).substring(1));
            return writeBlock(motion(kind(1)), t + e + f, xOutput.format(x), c, "P" + p, "Q" + q);
        }
        function onRapid(x, y, z) { return writeBlock(motion(kind(0)), xOutput.format(x)); }
    "#;
    check("splice", body, &["onLinear", "onRapid", "motion", "kind"], &[]);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("splice.js");
    std::fs::write(&path, format!("{HEAD}{body}")).expect("writes the post");
    let post = compile(&path).expect("compiles");
    let prepared = postc_runtime::prepare::prepare(&post).handlers;
    let any = |p: &dyn Fn(&XExpr) -> bool| prepared.iter().any(|h| any_expr(h, &|e| p(e)));
    assert!(any(&|e| matches!(e, XExpr::LocalEmpty { .. })), "`c != \"\"` is asked of the local: {prepared:?}");
    assert!(
        any(&|e| matches!(e, XExpr::ParseFloatFrom { .. })),
        "the number is read where it is formatted: {prepared:?}"
    );
    for name in ["motion", "kind"] {
        let f = function(&post, name);
        assert!(
            !prepared.iter().any(|h| calls(h, f)),
            "`{name}` is spliced into the handlers, not called: {prepared:?}"
        );
    }
}
