//! CIMCO fidelity: modal memory for the whole program and
//! `reset()`, feeds per revolution, the drill header's reference plane,
//! `finally`, NaN in native code, and number-to-text as a JavaScript
//! engine does it. Each case runs under postc and, when `node` is
//! installed, under the Node.js referee host (`tests/node_host/`), and both
//! must print the expected program.

use crate::support::cimco::*;

/// Posts `js` over the native toolpath `ron` with postc and (when it is
/// installed) Node.js; both must print `expected`.
fn check(js: &str, ron: &str, expected: &str) {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("post.js");
    let toolpath = dir.path().join("job.ron");
    std::fs::write(&post_path, js).expect("write the post");
    std::fs::write(&toolpath, ron).expect("write the toolpath");
    let post = compile(&post_path).unwrap_or_else(|e| panic!("{e}"));
    let ours = post_toolpath(&post, &toolpath).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(String::from_utf8_lossy(&ours), expected, "postc");
    if node_or_skip("cimco_fidelity").is_none() {
        return;
    }
    let jsonl = dir.path().join("job.jsonl");
    export_jsonl(&toolpath, &jsonl).unwrap_or_else(|e| panic!("{e}"));
    let theirs = run_node(&post_path, &jsonl, &[]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(String::from_utf8_lossy(&theirs), expected, "Node.js");
}

const TWO_TOOLPATHS: &str = "Job(units: Mm)
Tool(number: 1, cut_feed: 1000, plunge_feed: 300, spindle_speed: 8000)
ToolpathStart(name: \"one\")
Rapid(x: 10, y: 20, z: 5)
Feed(x: 30, y: 20, z: 5)
ToolpathStart(name: \"two\")
Rapid(x: 30, y: 20, z: 5)
Feed(x: 30, y: 40, z: 5)
Tool(number: 2, cut_feed: 1000, plunge_feed: 300, spindle_speed: 8000)
ToolpathStart(name: \"three\")
Rapid(x: 30, y: 40, z: 5)
Feed(x: 50, y: 40, z: 5)
End
";

/// The CNC-Calc Post Processor Manual: a variable without force "will only be written if it has
/// changed since the last time it was used" -- a toolpath start does not
/// make it forget; `reset()` (here in `onToolChange`) does.
#[test]
fn output_variables_remember_across_toolpaths_until_reset() {
    let js = r#"
var linebreak = "\n";
var f = createFormat({decimals: 1});
var gOut = createVariable({prefix: "G"}, createFormat({decimals: 0}));
var xOut = createVariable({prefix: "X"}, f);
var yOut = createVariable({prefix: "Y"}, f);
var zOut = createVariable({prefix: "Z"}, f);
var tools = 0;
function onToolChange(tool) {
    tools++;
    if (tools > 1) {
        gOut.reset(); xOut.reset(); yOut.reset(); zOut.reset();
    }
    return "T" + tool + "\n";
}
function onLinear(x, y, z, m) {
    var xyz = xOut.format(x) + yOut.format(y) + zOut.format(z);
    return xyz == "" ? "" : gOut.format(m == MOVEMENT_RAPID ? 0 : 1) + xyz + "\n";
}
"#;
    let expected = "T1\nG0X10Y20Z5\nG1X30\nY40\nT2\nG0X30Y40Z5\nG1X50\n";
    check(js, TWO_TOOLPATHS, expected);
    // The same from a script (objects make onToolChange a Rhai script).
    let script = js.replace("function onToolChange(tool) {", "function onToolChange(tool) {\n    var o = {};");
    check(&script, TWO_TOOLPATHS, expected);
    // And through variables made while the post runs.
    let dynamic = js.replace("var gOut", "var gOut;\nfunction onInit() { gOut = createVariable({prefix: \"G\"}, createFormat({decimals: Number(\"0\")})); }\nvar unused");
    check(&dynamic, TWO_TOOLPATHS, expected);
}

const LATHE_PER_REV: &str = "Job(units: Mm)
Tool(number: 1, cut_feed: 0.15, plunge_feed: 0.08, spindle_speed: 1500)
ToolpathStart(name: \"rough\", feed_per_rev: true)
Rapid(x: 20, y: 0, z: 2)
Feed(x: 20, y: 0, z: -30)
Feed(x: 22, y: 0, z: -30, feed: 0.0025)
ToolpathStart(name: \"per minute\")
Feed(x: 24, y: 0, z: -30, feed: 47.25)
End
";

/// A lathe post in G95/G99 prints 0.15 mm/rev as F0.15, not F0.2.
#[test]
fn feeds_per_revolution_keep_their_decimals() {
    let js = r#"
var linebreak = "\n";
var f = createFormat({decimals: 3, forceDecimal: true});
var xOut = createVariable({prefix: " X"}, f);
var zOut = createVariable({prefix: " Z"}, f);
function onLinear(x, z, m) {
    return "G" + (m == MOVEMENT_RAPID ? 0 : 1) + xOut.format(x) + zOut.format(z) + (m == MOVEMENT_RAPID ? "" : " " + getFeedrate(m)) + "\n";
}
"#;
    let expected = "G0 X20.000 Z2.000\nG1 Z-30.000 F0.15\nG1 X22.000 F0.0025\nG1 X24.000 F47.3\n";
    check(js, LATHE_PER_REV, expected);
    // The host's getFeedrate from a script.
    let script = js.replace("function onLinear(x, z, m) {", "function onLinear(x, z, m) {\n    var o = {};");
    check(&script, LATHE_PER_REV, expected);
}

const DRILL: &str = "Job(units: Mm)
Tool(number: 3, cut_feed: 200, plunge_feed: 100, spindle_speed: 3000)
ToolpathStart(name: \"holes\")
DrillCycle(kind: Drill, retract_plane: 15, reference_plane: 2, surface: -1, depth: -11, feed: 80)
DrillPoint(x: 5, y: 5, z: -1)
DrillEnd
ToolpathStart(name: \"no surface given\")
DrillCycle(kind: Drill, retract_plane: 15, reference_plane: 2, depth: -11, feed: 80)
DrillPoint(x: 9, y: 5, z: -1)
DrillEnd
End
";

/// The drill header's referencePlane is the top of the hole (the CNC-Calc Post Processor Manual:
/// safe distance and end depth "are relative to this plane"), so a
/// set-up clearance (Heidenhain Q200 = safe distance - reference plane)
/// is the real one, not 0.
#[test]
fn drill_header_reference_plane_is_the_hole_top() {
    let js = r#"
var linebreak = "\n";
var f = createFormat({decimals: 3});
var drill;
function onLinear(x, y, z, m) { return ""; }
function onDrillingHeader(h) { drill = h; return ""; }
function onDrillingPoint(x, y) {
    return "RET " + f.format(drill.retractPlane) + " REF " + f.format(drill.referencePlane)
        + " SAFE " + f.format(drill.safeDistance) + " Q200 " + f.format(drill.safeDistance - drill.referencePlane)
        + " END " + f.format(drill.endDepth) + "\n";
}
"#;
    let expected = "RET 15 REF -1 SAFE 2 Q200 3 END -11\nRET 15 REF 2 SAFE 2 Q200 0 END -11\n";
    check(js, DRILL, expected);
}

/// APT CYCLE measures its clearance from the hole's top: the reader
/// gives the cycle that surface.
#[test]
fn apt_cycles_carry_the_hole_top() {
    let cl = "PARTNO/T\nLOADTL/1\nGOTO/0,0,50\nCYCLE/DRILL,10,MMPM,100,3\nGOTO/5,5,-1\nCYCLE/OFF\nFINI\n";
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("job.cl");
    std::fs::write(&path, cl).expect("write the CL file");
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(&path, &mut sources).unwrap_or_else(|d| panic!("{}", d.message));
    let mut diags = Vec::new();
    let mut cycle = None;
    while let Some((e, _)) = postc_ir::EventSource::next_event(&mut source, &mut diags) {
        if let postc_ir::event::Event::DrillCycle(c) = e {
            cycle = Some(c);
        }
    }
    let c = cycle.expect("a drill cycle");
    assert_eq!((c.surface, c.reference_plane, c.depth), (Some(-1.0), 2.0, -11.0));
}

const ONE_MOVE: &str = "Job(units: Mm)
Tool(number: 1, cut_feed: 1000, plunge_feed: 300, spindle_speed: 8000)
ToolpathStart(name: \"one\")
Rapid(x: 1, y: 2, z: 3)
End
";

/// `finally` runs however its `try` is left: by a `return`, `break` or
/// `continue` (also through a `switch`), by a `throw` from the `catch`,
/// and through nested `try`s.
#[test]
fn finally_runs_after_return_break_continue_and_throw() {
    let js = r#"
var linebreak = "\n";
var log = "";
function f(n) {
    try { if (n > 0) return "r" + n; log += "t"; } finally { log += "F"; }
    return "end";
}
function g() {
    var s = "";
    for (var i = 0; i < 4; i++) {
        try { if (i == 1) continue; if (i == 3) break; s += i; } finally { s += "f"; }
    }
    return s;
}
function h() { try { try { return 1; } finally { log += "a"; } } finally { log += "b"; } }
function k() { try { throw "x"; } catch (e) { throw "y" + e; } finally { log += "c"; } }
function sw() {
    var s = "";
    for (var i = 0; i < 3; i++) {
        try { switch (i) { case 1: continue; default: s += i; } } finally { s += "."; }
    }
    return s;
}
function over() { try { return "try"; } finally { return "finally"; } }
function onOpen() {
    var r = f(1) + f(0) + g() + h() + sw() + over();
    try { k(); } catch (e) { r += e; }
    return r + "|" + log + "\n";
}
function onLinear(x, y, z, m) { return ""; }
"#;
    check(js, ONE_MOVE, "r1end0ff2ff10..2.finallyyx|FtFabc\n");
}

/// In native code, text that is not a number reads as NaN in arithmetic
/// and comparisons, as in JavaScript (BASIC's `Val` reads it as 0, which
/// VcPost keeps), and NaN joins to text as "NaN".
#[test]
fn text_that_is_not_a_number_is_nan_in_native_code() {
    let js = r#"
var linebreak = "\n";
var nothing = null;
function nan(s, n) {
    var a = s * 1;
    var b = n;
    b -= s;
    return "" + a + " " + (-s) + " " + b + " " + (s == 0) + " " + (s < 1) + " " + (s >= 1) + " " + (s != 0)
        + " " + (nothing == 0) + " " + (n == "5") + " " + ("10" < "9") + " " + (n < "10") + " " + ("" == 0) + " " + (" 12 " * 2);
}
function onOpen() { return nan("abc", 5) + "\n"; }
function onLinear(x, y, z, m) { return ""; }
"#;
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("nan.js");
    std::fs::write(&path, js).expect("write the post");
    let post = compile(&path).unwrap_or_else(|e| panic!("{e}"));
    let f = post.functions.iter().find(|f| f.name == "nan").expect("nan()");
    assert!(matches!(f.body, postc_ir::Body::Native(_)), "nan() must run natively");
    check(js, ONE_MOVE, "NaN NaN NaN false false false true false true true true true 24\n");
}

/// Number-to-text in CIMCO formats is the JavaScript engine's: the binary
/// double is rounded (as `toFixed` does), so 1.005 at two decimals prints
/// 1.00 (the double is 1.00499999999999989...), where rounding the decimal
/// value half away from zero would print 1.01. Exact ties (0.125) round
/// away from zero.
#[test]
fn formats_round_the_binary_double_as_javascript_does() {
    let js = r#"
var linebreak = "\n";
var f = createFormat({decimals: 2, forceDecimal: true});
var xOut = createVariable({prefix: "X", force: true}, f);
function line() { return f.format(1.005) + " " + f.format(2.675) + " " + f.format(0.125) + " " + xOut.format(-1.005) + " " + (1.005).toFixed(2); }
function dynamic() {
    var o = {};
    var g = createFormat({decimals: Number("2"), forceDecimal: true});
    return g.format(1.005) + " " + g.format(2.675) + " " + g.format(0.125);
}
function onOpen() { return line() + "|" + dynamic() + "\n"; }
function onLinear(x, y, z, m) { return ""; }
"#;
    check(js, ONE_MOVE, "1.00 2.67 0.13 X-1.00 1.00|1.00 2.67 0.13\n");
}

/// Closures share the locals they capture with the function that made
/// them and with each other, however often either changes them (the
/// locals live in cells), and formats and output variables are values a
/// post hands to helpers: every function runs natively, and the program is
/// the one Node.js prints.
#[test]
fn closures_share_changing_captures_and_formats_are_values() {
    let js = r#"
var linebreak = "\n";
var xyzFormat = createFormat({decimals: 3});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
function counter(start) {
    var n = start;
    function bump(by) { n += by; return n; }
    var api = { bump: bump, peek: function () { return n; }, set: function (v) { n = v; } };
    n = n * 2;
    return api;
}
function words(list, f) {
    var out = [];
    for (var i = 0; i < list.length; i++) {
        out.push(f.format(list[i]));
    }
    return out.join(" ");
}
function later(w) {
    var said = [];
    return function (v) { said.push(w.format(v)); return said.join("|"); };
}
function onOpen() {
    var c = counter(10);
    var d = counter(1);
    c.bump(5);
    d.set(7);
    var r = c.peek() + " " + c.bump(1) + " " + d.peek() + " " + d.bump(3);
    var say = later(xOutput);
    say(1.5);
    say(1.5);
    xOutput.reset();
    return r + "; " + words([1, 2.25, -0.5], xyzFormat) + "; " + say(1.5) + "; " + words([3, 3], xOutput) + "\n";
}
function onLinear(x, y, z, m) { return ""; }
"#;
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("closures.js");
    std::fs::write(&path, js).expect("write the post");
    let post = compile(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(script_functions(&post), (vec![], false), "scripts");
    check(js, ONE_MOVE, "25 26 7 10; 1 2.25 -0.5; X1.5||X1.5; X3 \n");
}

/// `key in value` finds own properties and those of the value's prototype
/// (`"toString" in {}`, `"push" in []`, `"call" in f`), array indices
/// below the length and nothing else, natively as Node.js does.
#[test]
fn the_in_operator_finds_what_javascript_finds() {
    let js = r#"
var linebreak = "\n";
var table = {a: 1, "(": "[", 2: "x"};
var list = [10, 20];
function f() {}
function onOpen() {
    var r = [];
    r.push("a" in table, "b" in table, "(" in table, 2 in table, "2" in table, "toString" in table, "hasOwnProperty" in table);
    r.push(0 in list, 1 in list, 2 in list, "length" in list, "push" in list, "1" in list, "01" in list);
    r.push("call" in f, "name" in f, "x" in f);
    var k = "a";
    r.push(k in table ? table[k] : "none", !("z" in table), "source" in /x/g, "y" in /x/g);
    return r.join(",") + "\n";
}
function onLinear(x, y, z, m) { return ""; }
"#;
    let expected =
        "true,false,true,true,true,true,true,true,true,false,true,true,true,false,true,true,false,1,true,true,false\n";
    check(js, ONE_MOVE, expected);
    // The same in the Rhai tier: an `isFinite` call keeps the post there.
    let scripted = format!("{js}function keepsScripts(t) {{ return isFinite(t); }}\n");
    check(&scripted, ONE_MOVE, expected);
}

/// JavaScript's value semantics are one definition (`postc_ir::js`) for
/// the values known when the post is compiled and those it computes when
/// it runs: texts order by their UTF-16 units (U+E000 sorts after 😀,
/// whose first unit is a surrogate, U+D83D, though its UTF-8 bytes sort
/// before), text reads as a number as `Number()` reads it (`"0x10"`,
/// `"Infinity"`) and a number prints as `String()` prints it (`1e+21`,
/// `1e-7`), whether the globals are constants the compiler folds or
/// values `onOpen` makes.
#[test]
fn values_known_when_compiling_are_the_values_javascript_computes() {
    let js = "var linebreak = \"\\n\";\n\
var privateUse = \"\u{E000}\";\n\
var emoji = \"\u{1F600}\";\n\
var hex = \"0x10\" * 1;\n\
var inf = \"Infinity\" * 1;\n\
var big = \"\" + 1e21;\n\
var small = \"\" + 1e-7;\n\
var known = (privateUse < emoji) + \" \" + hex + \" \" + inf + \" \" + big + \" \" + small;\n\
function made(a, b) {\n\
    return (a < b) + \" \" + [b, a, \"z\"].sort().join(\",\") + \" \" + (\"0x10\" * a.length) + \" \" + (\"\" + 1e21 * a.length);\n\
}\n\
function onOpen() { return known + linebreak + made(privateUse, emoji) + linebreak; }\n\
function onLinear(x, y, z, m) { return \"\"; }\n";
    check(js, ONE_MOVE, "false 16 Infinity 1e+21 1e-7\nfalse z,\u{1F600},\u{E000} 16 1e+21\n");
}

/// `null` is 0 to arithmetic and comparisons and equals only `null` and
/// `undefined`, as JavaScript's `Number(null)` and `==` read it, in a
/// function that runs natively.
#[test]
fn null_reads_as_zero_in_arithmetic_and_comparisons() {
    let js = r#"
var linebreak = "\n";
var nothing = null;
function f(n) {
    return (n + 1) + " " + (n * 2) + " " + (n < 1) + " " + (n >= 0) + " " + (n == 0) + " " + Math.max(n, -1)
        + " " + (-n) + " " + (n - 1) + " " + (n == undefined);
}
function onOpen() { return f(nothing) + linebreak; }
function onLinear(x, y, z, m) { return ""; }
"#;
    check(js, ONE_MOVE, "1 0 true true false 0 0 -1 true\n");
}
