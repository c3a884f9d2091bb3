//! Fusion posts under two JavaScript engines: every corpus `.cps` post
//! that postc runs over a job of the bar (the standard milling job, the
//! arcs job, the drilling job, a real APT CL file), the jet job or the
//! turning job prints the same bytes when Node.js runs it with the same
//! host API (`tests/node_host/fusion.js`, which drives
//! `frontends/cimco/src/fusion/host.js` from the toolpath's events as
//! docs/fusion.md describes). A difference is postc's JavaScript
//! engine disagreeing with V8, or the event order disagreeing with a second
//! reading of the documentation.

use std::path::{Path, PathBuf};

use crate::fusion_corpus::{posts, shared};
use crate::support;

/// A temporary folder with the standard milling job as RON (for postc)
/// and JSON Lines (for the Node.js referee), and the referee's script.
fn milling_job_for_node() -> (tempfile::TempDir, PathBuf, PathBuf, PathBuf) {
    let folder = tempfile::tempdir().expect("a temporary folder");
    let job = crate::fusion_corpus::milling_job(folder.path());
    let jsonl = folder.path().join("standard_milling.jsonl");
    support::cimco::export_jsonl(&job, &jsonl).expect("export the job");
    // fusion.js with the job's product (Fusion's `generated-by`).
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/fusion.js");
    (folder, job, jsonl, script)
}

/// [`milling_job_for_node`], or `None` (the referee said missing) when
/// `node` is not installed.
fn node_and_milling_job() -> Option<(tempfile::TempDir, PathBuf, PathBuf, PathBuf)> {
    if support::cimco::node().is_none() {
        support::referee_missing("fusion_node", "node");
        return None;
    }
    Some(milling_job_for_node())
}

#[test]
fn node_and_postc_print_the_same_program_for_every_corpus_fusion_post_that_runs() {
    let dir = shared();
    if !dir.is_dir() {
        support::referee_missing("fusion_node", "../shared/corpus/fusion");
        return;
    }
    if support::cimco::node().is_none() {
        support::referee_missing("fusion_node", "node");
        return;
    }
    let (folder, job, jsonl, script) = milling_job_for_node();
    let toolpaths = support::corpus().join("toolpaths");
    let apt = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/apt");
    let mut jobs = vec![("milling", job, jsonl)];
    for (what, toolpath) in [
        ("arcs", toolpaths.join("arcs_mm.ron")),
        ("drilling", toolpaths.join("drill_mm.ron")),
        ("APT CL file", apt.join("MichaHofft__CreoPost/profilfraesen_2.ncl.2")),
        ("jet", toolpaths.join("jet_mm.ron")),
        ("turning", toolpaths.join("turning/turning_mm.ron")),
    ] {
        let exported = folder.path().join(format!("{what}.jsonl"));
        support::cimco::export_jsonl(&toolpath, &exported).expect("export the job");
        jobs.push((what, toolpath, exported));
    }
    let posts = posts(&dir);
    let results: Vec<(&str, Result<(), String>)> = support::in_workers(&posts, |post| {
        let name = post.strip_prefix(&dir).unwrap_or(post).display().to_string();
        // JS110 warns of host API the job may never reach.
        let Ok(compiled) = support::compile_warned(post) else { return Vec::new() };
        let mut done = Vec::new();
        for (what, job, jsonl) in &jobs {
            let Ok(ours) = support::cimco::post_toolpath(&compiled, job) else { continue };
            let node = support::cimco::node_command().arg(&script).arg(post).arg(jsonl).output().expect("run node");
            done.push((
                *what,
                if !node.status.success() {
                    Err(format!("{name} ({what}): Node.js stops: {}", String::from_utf8_lossy(&node.stderr)))
                } else if node.stdout != ours {
                    Err(format!("{name} ({what}):\n{}", support::diff(&node.stdout, &ours)))
                } else {
                    Ok(())
                },
            ));
        }
        done
    });
    let same = results.iter().filter(|(_, r)| r.is_ok()).count();
    let per_job: Vec<String> = jobs
        .iter()
        .map(|(what, ..)| format!("{what} {}", results.iter().filter(|(w, r)| w == what && r.is_ok()).count()))
        .collect();
    let differ: Vec<String> = results.into_iter().filter_map(|(_, r)| r.err()).collect();
    println!("{same} programs of corpus Fusion posts are the same under Node.js and postc ({})", per_job.join(", "));
    assert!(differ.is_empty(), "{} posts differ (Node.js first, postc second):\n{}", differ.len(), differ.join("\n"));
    assert!(same >= SAME_AT_LEAST, "{same} programs compared, fewer than {SAME_AT_LEAST}: posts no longer run");
}

/// Programs (a post over a job) that postc writes and Node.js prints the
/// same today: fewer means posts stopped running, and the comparison
/// would shrink without failing.
const SAME_AT_LEAST: usize = 651;

/// The JavaScript newer than ES5 that Fusion's engine runs and real posts
/// use (docs/fusion.md, "Language"), each in a small post whose `onOpen`
/// prints what it computes: postc prints what Node.js prints.
const MODERN: &[(&str, &str)] = &[
    (
        "template literals",
        r#"var o = {toString: function () { return "T"; }, valueOf: function () { return 5; }};
  var n = null, u;
  writeln(`plain ${1 + 1} ${"s"}${n}${u} ${o} ${[1, [2, 3]]} ${{}} ${1e21} ${0.1 + 0.2} ${-0} ${true}`);
  writeln(`multi
line \`tick\` \${not} \x41\u0042 ${`nested ${`deep ${3}`}`} ${ {a: 1}.a } ${"}"}`);
  writeln(`(WCS# ${o.valueOf()})` + `#1000=${2.5}`);
  var calls = [];
  function f(x) { calls.push(x); return x; }
  writeln(`${f(1)}-${f(2)}-${f(3)}` + calls.join(""));"#,
    ),
    (
        "arrow functions",
        r#"var sq = x => x * x;
  var add = (a, b) => { return a + b; };
  var none = () => "none";
  var obj = () => ({k: 7});
  writeln([sq(4), add(2, 3), none(), obj().k, [1, 2, 3].map(v => v + 1).join(",")].join(" "));
  var total = 0;
  [4, 5, 6].forEach(i => { total += i; });
  writeln("total " + total);
  function Thing(n) {
    this.n = n;
    this.twice = function () { var inner = () => () => this.n * 2; return inner()(); };
  }
  writeln("this " + new Thing(21).twice());
  var counter = (start => () => start++)(10);
  writeln("closure " + counter() + counter() + counter());"#,
    ),
    (
        "legacy octal numbers",
        r#"writeln([010, 08, 09.5, 019, 0777, 00, 007 + 1, 0x1F, 0b101, 0o17, 08e1].join(" "));
  writeln(gFormat.format(010) + " " + gFormat.format(09));"#,
    ),
    (
        "destructuring",
        r#"var state = {x: 1, y: 2, z: 3};
  var saved = [10, 20, 30];
  [state.x, state.y, state.z] = saved;
  writeln("assign " + state.x + " " + state.y + " " + state.z);
  var a = 1, b = 2;
  [a, b] = [b, a];
  writeln("swap " + a + " " + b);
  var list = [0, 0];
  var i = 0;
  [list[i++], list[i++]] = [7, 8];
  writeln("elements " + list.join(",") + " " + i);
  var r = ([a, b] = [5, 6]);
  writeln("value " + r.join(",") + " " + a + b);
  var [p, , q = 9, [s], t = "d"] = [1, 2, undefined, [4]];
  var {x, y: why, w = "dw", nested: {deep} = {deep: "dd"}} = state;
  writeln("var " + p + q + s + t + x + why + w + deep);
  var {length} = "four";
  writeln("length " + length);
  ({x: state.z, y: state.x} = {x: "zz", y: "xx"});
  writeln("object " + state.x + state.z);
  var shorthand = {x, why};
  writeln("shorthand " + shorthand.x + shorthand.why);"#,
    ),
    (
        "default parameters",
        r#"function pick({ a = false, b = 7 } = {}, c = 3) { return `${a}/${b}/${c}`; }
  writeln(pick() + " " + pick({a: true}) + " " + pick({b: undefined}, 0) + " " + pick({b: null}, null));
  var count = 0;
  var f = function (k = count++, m = k + 1) { return k + ":" + m; };
  writeln(f() + " " + f(5) + " " + f() + " " + f(undefined, 0) + " " + count);
  function pair([first, second] = [1, 2]) { return first + second; }
  writeln("pair " + pair() + " " + pair([3, 4]));
  var g = ({ afterToolChange = false } = {}) => afterToolChange ? "after" : "before";
  writeln(g() + " " + g({ afterToolChange: true }));"#,
    ),
];

/// JavaScript's prototypes (docs/fusion.md, "Language"), each case a post
/// whose top level defines constructors and adds to prototypes, and whose
/// `onOpen` prints what they give: constructors and their `prototype`,
/// inheritance through `Object.create`, `constructor`, super calls with
/// `call` and `apply`, `instanceof`, `in` and `hasOwnProperty`, `for ...
/// in` over inherited properties, `toString` and `valueOf` from a
/// prototype, and methods added to the prototypes of texts, numbers,
/// arrays, booleans and functions; built-in methods read as values
/// (`Object.prototype.toString.call`, `Array.prototype.slice.call`), and
/// the TypeErrors of methods on no chain.
const PROTOTYPES: &[(&str, &str, &str)] = &[
    (
        "one var statement of a global assigned later and one never assigned",
        "var seen = NaN, never = NaN, label = \"T\";",
        r#"seen = 1; writeln(label + seen + never + (never == never));"#,
    ),
    (
        "constructors and inheritance",
        r#"function Shape(name) { this.name = name; this.sides = 0; }
Shape.prototype.describe = function () { return this.name + " with " + this.sides + " sides"; };
Shape.prototype.area = function () { return 0; };
Shape.count = 0;
function Square(side) {
  Shape.call(this, "square");
  this.sides = 4;
  this.side = side;
  Shape.count++;
}
Square.prototype = Object.create(Shape.prototype);
Square.prototype.constructor = Square;
Square.prototype.area = function () { return this.side * this.side; };
Square.prototype.describe = function () {
  return "[" + Shape.prototype.describe.call(this) + ", area " + this.area() + "]";
};
function Cube(side) {
  Square.apply(this, arguments);
  this.name = "cube";
}
Cube.prototype = Object.create(Square.prototype);
Cube.prototype.constructor = Cube;
Cube.prototype.area = function () { return 6 * Square.prototype.area.call(this); };
function Point(x, y) { this.x = x; this.y = y; }
Point.prototype.toString = function () { return "(" + this.x + "," + this.y + ")"; };
Point.prototype.valueOf = function () { return this.x * 10 + this.y; };
function Made() { return {made: true}; }
function Plain() {}
Plain.prototype = 5;"#,
        r#"var s = new Shape("blob"), q = new Square(3), c = new Cube(2);
  writeln(s.describe() + " | " + q.describe() + " | " + c.describe());
  writeln([q instanceof Square, q instanceof Shape, q instanceof Cube, c instanceof Shape, s instanceof Square,
    [] instanceof Array, [] instanceof Object, {} instanceof Object, "t" instanceof String, q instanceof Object,
    Square instanceof Function, Object.create(null) instanceof Object].join(" "));
  writeln([q.constructor === Square, s.constructor === Shape, c.constructor === Cube, Square.prototype.constructor === Square,
    Shape.count, typeof Shape.prototype, typeof q.area, typeof q.nothing, Shape === Shape].join(" "));
  writeln([q.hasOwnProperty("side"), q.hasOwnProperty("area"), "area" in q, "describe" in c, "nothing" in q,
    "constructor" in s, "toString" in q, Shape.prototype.hasOwnProperty("describe")].join(" "));
  var keys = [];
  for (var k in c) { keys.push(k); }
  writeln("keys " + keys.join(","));
  var pk = [];
  for (var k2 in Shape.prototype) { pk.push(k2); }
  writeln("proto keys " + pk.join(",") + " / " + Object.keys(c).join(","));
  var p = new Point(1, 2);
  writeln("point " + p + " " + (p + 1) + " " + String(p) + ` ${p}` + " " + [p, p].join(";"));
  writeln("made " + new Made().made + " " + (new Plain() instanceof Object) + " " + typeof new Plain().toString);
  var m = q.describe;
  var other = new Square(5);
  writeln("borrowed " + m.call(other) + " " + m.apply(other, []));
  q.area = function () { return -1; };
  writeln("own " + q.area() + " " + new Square(2).area());
  Shape.prototype.extra = function () { return "late " + this.name; };
  writeln(q.extra() + " " + c.extra());"#,
    ),
    (
        "built-in prototypes and Object.create",
        r#"var initialState = {feed: 100, units: "mm", nested: {a: 1}};
String.prototype.capitalizeFirstLetter = function () {
  return this.charAt(0).toUpperCase() + this.slice(1);
};
Number.prototype.round = function (places) {
  return +(Math.round(this + "e+" + places) + "e-" + places);
};
Array.prototype.last = function () { return this[this.length - 1]; };
Boolean.prototype.yes = function () { return this == true ? "yes" : "no"; };
Function.prototype.twice = function (x) { return this(this(x)); };
function inc(x) { return x + 1; }
function isType(obj, s) { return Object.prototype.toString.call(obj) === "[object " + s + "]"; }
function rest() { return Array.prototype.slice.call(arguments, 1); }"#,
        r#"writeln("abc".capitalizeFirstLetter() + " " + "x".capitalizeFirstLetter() + " " + "".capitalizeFirstLetter());
  writeln((1.005).round(2) + " " + (1.5).round(0) + " " + (2.345).round(1) + " " + Math.PI.round(3));
  writeln([1, 2, 3].last() + " " + [].last() + " " + true.yes() + " " + false.yes() + " " + inc.twice(5));
  writeln(["a".toUpperCase(), "trim" in String.prototype, typeof "".capitalizeFirstLetter, typeof "".trim,
    typeof [].push, typeof (5).toFixed, typeof "".nothing].join(" "));
  writeln([isType([], "Array"), isType({}, "Object"), isType("s", "String"), isType(1, "Number"), isType(true, "Boolean"),
    isType(inc, "Function"), isType(null, "Null"), isType(undefined, "Undefined"), isType(/x/, "RegExp")].join(" "));
  writeln(Object.prototype.toString.call([1]) + " " + Object.prototype.toString.call(null) + " " + {}.toString());
  writeln(rest(1, 2, 3).join("+") + " " + Array.prototype.join.call([1, 2], "-") + " " + String.prototype.trim.call("  t  ") + "|");
  var a = [1];
  Array.prototype.push.apply(a, [2, 3]);
  writeln("pushed " + a.join(","));
  var state = Object.create(initialState);
  state.feed = 200;
  writeln([state.feed, initialState.feed, state.units, state.hasOwnProperty("units"), "units" in state].join(" "));
  initialState.units = "in";
  state.nested.a = 2;
  writeln([state.units, initialState.nested.a].join(" "));
  var ks = [];
  for (var k in state) { ks.push(k); }
  writeln("state keys " + ks.join(","));
  var bare = Object.create(null);
  bare.x = 1;
  writeln(["toString" in bare, "x" in bare, typeof bare.toString, bare.x].join(" "));
  var caught = [];
  try { state.nothing(); } catch (e) { caught.push(e.name); }
  try { "x".nothing(); } catch (e) { caught.push(e.name); }
  try { new Object.prototype.toString(); } catch (e) { caught.push(e.name); }
  try { Object.create(5); } catch (e) { caught.push(e.name); }
  try { ({}) instanceof inc.nothing; } catch (e) { caught.push(e.name); }
  writeln("caught " + caught.join(","));"#,
    ),
    (
        "the global object",
        r#"var gMotionModal = createModal({prefix: "G"}, gFormat);
var feedOutput = createVariable({prefix: "F"}, gFormat);
var counter = 1;
function forceModals() {
  var modals = ["gMotionModal", "feedOutput", "noSuchModal"];
  var found = [];
  for (var i = 0; i < modals.length; ++i) {
    if (typeof this[modals[i]] != "undefined") {
      this[modals[i]].reset();
      found.push(modals[i]);
    }
  }
  return found.join(",");
}
function bump() { this.added = "new"; return this.counter + 1; }
function self() { return this; }
var holder = {m: function () { return this === holder; }, n: self, plain: function () { return self() === this; }};"#,
        r#"writeln(gMotionModal.format(1) + "|" + gMotionModal.format(1) + "|" + feedOutput.format(5));
  writeln("reset " + forceModals());
  writeln(gMotionModal.format(1) + "|" + feedOutput.format(5));
  writeln("bump " + bump() + " " + counter + " " + typeof this.bump + " " + this.bump() + " " + self().added);
  var f = self;
  writeln([f() === this, self() === this, typeof this.nothing, this["counter"]].join(" "));
  writeln([holder.m(), holder.n() === holder, holder.plain(), self() === this].join(" "));"#,
    ),
    (
        "Array.from",
        r#"function words() { return Array.from(arguments).join(" "); }"#,
        r#"writeln(words("G1", "X1", 2) + "|" + Array.from("abc", function (c, i) { return c + i; }).join(",") + "|" +
    Array.from([1, 2, 3], function (v) { return v * 2; }).join(",") + "|" + Array.from([]).length);"#,
    ),
    (
        "output variables that print every value not zero",
        r#"var iOutput = createOutputVariable({prefix: "I", control: CONTROL_NONZERO}, gFormat);
var xOutput = createOutputVariable({prefix: "X"}, gFormat);
var fOutput = createOutputVariable({prefix: "F", control: CONTROL_FORCE}, gFormat);"#,
        r#"var words = [];
  [1, 1, 0, 0, 2, 2, -1, 0.1].forEach(function (v) {
    words.push(iOutput.format(v) + "/" + xOutput.format(v) + "/" + fOutput.format(v));
  });
  writeln(words.join(" "));"#,
    ),
];

/// What newer engines than Autodesk's declarations give and JavaScript
/// that real posts use beyond the constructs above (docs/fusion.md,
/// "Names the post never defines", "Language", choices 26-30): a small
/// post each, its top-level code and `onOpen`'s body. `included.js`
/// beside the posts holds `included()`.
const NEWER: &[(&str, &str, &str)] = &[
    (
        "regular expressions made when the post runs, match, replace by a function",
        "",
        r#"var sentinel = "@@";
  var re = new RegExp(sentinel + "(\\d+)" + sentinel, "g");
  var text = "a@@12@@b@@345@@c";
  writeln(text.replace(re, function (m, n, i, t) { return "<" + n + ":" + i + ":" + t.length + ">"; }));
  writeln(text.match(re).join(",") + "|" + text.match(/@@(\d+)@@/).join(",") + "|" + "abc".match(/(x)?b/).length +
    "|" + ("x".match(/y/) === null) + "|" + "a.b".match(".").join(""));
  writeln(new RegExp(/a+/g).flags + new RegExp(/a+/g, "i").flags + "|" + "AAA".replace(new RegExp("a", "gi"), "b") +
    "|" + "one two".replace(/\w+/g, function (w) { return w.charAt(0).toUpperCase() + w.substr(1); }) +
    "|" + "x-y".replace("-", function (m, i) { return "[" + m + i + "]"; }));"#,
    ),
    (
        "host API of newer engines",
        r#"var isArray = Array.isArray || function () { return false; };
var props = {first: {value: 3}};
properties = props;
setWriteInvocations = true;
var isMilling = "mine";
(function (global) { global._underscore = {v: 7}; })(this);
function writeComment(text) { writeln("(" + text + ")"); }"#,
        r#"writeln([Math.random(), Math.random(), Math.random()].join(" "));
  writeln(isArray([1]) + " " + isArray("a") + " " + FileSystem.getFilename(getConfigurationPath()) + " " +
    (getConfigurationFolder() != "") + " " + isDrillingCycle() + isMillingCycle() + isTappingCycle() + " " +
    (createToolRenderer() === null) + " " + getProperty(properties.first) + " " + setWriteInvocations + " " + isMilling + " " +
    _underscore.v);
  writeSetupNotes();
  writeSectionNotes();"#,
    ),
    (
        "Number.toPrecision",
        "",
        r#"var xs = [200, 0, -0, 2.5, 0.5, 9.99, 123.456, 0.000001234, 0.0000001234, 1e21, 99.95, -1.005, 1 / 3, 15, 1234567];
  var out = [];
  for (var i = 0; i < xs.length; ++i) {
    out.push(xs[i].toPrecision(1) + "/" + xs[i].toPrecision(2) + "/" + xs[i].toPrecision(4) + "/" + xs[i].toPrecision());
  }
  writeln(out.join(" "));"#,
    ),
    ("include", r#"include("included.js");"#, r#"writeln(included() + " " + includedValue);"#),
    // The host's formats, outputs and words, which postc runs natively
    // (runtime interp/host_text.rs), against the referee's JavaScript.
    (
        "formats",
        r#"var specs = [{decimals: 3}, {decimals: 3, forceDecimal: true}, {decimals: 0}, {decimals: 0, forceDecimal: true},
  {decimals: 4, trim: false}, {decimals: 3, zeropad: true, width: 8}, {decimals: 2, width: 8},
  {decimals: 3, forceSign: true}, {decimals: 3, trimLeadZero: true}, {decimals: 3, trimLeadZero: true, trim: false},
  {decimals: 3, separator: ","}, {decimals: 3, decimalSymbol: "\u00b7"}, {decimals: 3, prefix: "X", suffix: "!"},
  {decimals: 3, scale: 25.4}, {decimals: 3, offset: -10}, {decimals: 2, cyclicLimit: 360, cyclicSign: 1},
  {decimals: 2, cyclicLimit: 360, cyclicSign: -1}, {decimals: 2, cyclicLimit: 360, cyclicSign: 0},
  {decimals: 0, zeropad: true, width: 4}, {decimals: 3, zeropad: true, width: 8, forceSign: true},
  {decimals: 3, zeropad: true, width: 8, forceDecimal: true}, {decimals: 3, zeropad: true, width: 8, trim: false},
  {decimals: 20}, {decimals: 17}, {decimals: 15}, {decimals: -1}, {decimals: 3, width: 3.5},
  {decimals: 3, zeropad: true, width: 6.5}, {decimals: 2, width: 12, forceSign: true}, {decimals: 1, scale: -1},
  {decimals: 3, zeropad: true, width: 2}, {decimals: 4, trimLeadZero: true, forceSign: true, zeropad: true, width: 7},
  {decimals: 1, cyclicLimit: 0}, {decimals: 6, scale: 1000}, {decimals: 3, separator: "", forceDecimal: true}];
var values = [0, 0.5, -0.5, 1.5, 2.5, -0.0004, 0.0005, -0.0005, 0.00049999, 1e21, -1e21, 1e22,
  123456789012345678901234, 1.23456789e-7, -0, 9007199254740993, 1e300, 0.1 + 0.2, 1.005, 2.675,
  359.999, -359.999, 720, -720.5, 360, -360, "12.5", " 7 ", true, false, null, 99999.9999, 0.125, -0.125,
  1234567.891, 4.35, 1e-7, 5e-324, 1.7976931348623157e308, 4503599627370495.5];"#,
        r#"for (var i = 0; i < specs.length; ++i) {
    var f = createFormat(specs[i]);
    var line = i + ":";
    for (var j = 0; j < values.length; ++j) {
      try { line += " [" + f.format(values[j]) + "]"; } catch (e) { line += " <" + e.message + ">"; }
    }
    writeln(line);
  }
  var bad = [NaN, Infinity, -Infinity, undefined, "abc", {}];
  for (var k = 0; k < bad.length; ++k) {
    try { writeln("ok " + createFormat({decimals: 3}).format(bad[k])); } catch (e) { writeln("caught " + e.message); }
  }"#,
    ),
    (
        "outputs",
        r#"var f = createFormat({decimals: 3, forceDecimal: true});
var xOut = createVariable({prefix: "X"}, f);
var yOut = createOutputVariable({prefix: "Y", control: CONTROL_FORCE}, f);
var zOut = createOutputVariable({prefix: "Z", control: CONTROL_NONZERO}, f);
var changes = 0;
var aOut = createVariable({prefix: "A", onchange: function () { ++changes; }}, f);
var gModal = createModal({prefix: "G", suffix: ";"}, createFormat({decimals: 0, width: 2, zeropad: true}));
var mModal = createModal({}, f);
var own = createVariable({prefix: "O"}, {format: function (v) { return "<" + v + ">"; }, areDifferent: function () { return true; }});"#,
        r#"var seq = [1, 1, 1.0004, 2, -0, 0, 0.0001, 2, "3", NaN];
  for (var i = 0; i < seq.length; ++i) {
    var texts = [];
    var outs = [xOut, yOut, zOut, aOut, gModal, mModal, own];
    for (var o = 0; o < outs.length; ++o) {
      try { texts.push(outs[o].format(seq[i])); } catch (e) { texts.push("!" + e.message); }
    }
    writeln(i + ": " + texts.join("|") + " changes " + changes);
  }
  xOut.disable(); writeln("[" + xOut.format(5) + "]"); xOut.enable(); xOut.reset(); writeln("[" + xOut.format(2) + "]");
  gModal.reset(); writeln(gModal.format("G17") + gModal.format("G17") + gModal.format(0));
  xOut.setFormat(createFormat({decimals: 1})); writeln(xOut.format(2.25) + " " + xOut.getCurrent());"#,
    ),
    (
        "words",
        "",
        r#"var v = createVariable({prefix: "X"}, createFormat({decimals: 3, forceDecimal: true}));
  writeWords("G1", "", undefined, null, ["X1", ["Y2", ""], []], 5, 0, true, false, v.format(1), v.format(1));
  writeWords();
  writeWords("", [""], [[]]);
  writeln("[" + formatWords("A", ["B", "C"], "", 3.25) + "]");
  writeln("[" + formatWords() + "]");
  writeWords2("N10", "", "");
  writeWords2("N10", "G0");
  writeWords2(["A", "B"], "C");
  writeWords2("", "C", ["D"]);
  writeWords2(undefined, "E");
  setWordSeparator("");
  writeWords("A", "B", ["C"]);
  setWordSeparator(", ");
  writeWords("A", "B", ["C"]);
  writeWords2("N1", "B");
  setWordSeparator(" ");
  writeWords("end");"#,
    ),
];

#[test]
fn modern_javascript_in_fusion_posts_prints_what_node_prints() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let tmp = folder.path();
    let mut differ = Vec::new();
    std::fs::write(
        tmp.join("included.js"),
        "var includedValue = 6 * 7;\nfunction included() { return \"inc\" + includedValue; }\n",
    )
    .expect("write the included file");
    let cases = MODERN
        .iter()
        .map(|(what, body)| (what, "", body))
        .chain(PROTOTYPES.iter().map(|(w, t, b)| (w, *t, b)))
        .chain(NEWER.iter().map(|(w, t, b)| (w, *t, b)));
    for (k, (what, top, body)) in cases.enumerate() {
        let text = format!(
            "description = \"{what}\";\ncapabilities = CAPABILITY_MILLING;\n\
             var gFormat = createFormat({{prefix: \"G\", decimals: 0, width: 2, zeropad: true}});\n{top}\n\
             function onOpen() {{\n  {body}\n}}\n\
             function onSection() {{}}\nfunction onRapid(x, y, z) {{}}\nfunction onLinear(x, y, z, feed) {{}}\n\
             function onClose() {{ writeln(\"M30\"); }}\n"
        );
        let post = tmp.join(format!("modern_{k}.cps"));
        std::fs::write(&post, &text).expect("write the post");
        let compiled = support::compile_file(&post);
        let ours = support::cimco::post_toolpath(&compiled, &job).unwrap_or_else(|e| panic!("{what}: {e}"));
        let node = node_prints(&script, &post, &jsonl, what);
        if node != ours {
            differ.push(format!("{what}:\n{}", support::diff(&node, &ours)));
        }
    }
    assert!(differ.is_empty(), "Node.js first, postc second:\n{}", differ.join("\n"));
}

/// A method that is on no prototype chain: Node.js throws a TypeError, and
/// postc stops with RT037 at the line of the call, writing nothing.
#[test]
fn a_method_on_no_prototype_chain_stops_the_post_at_its_call() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let said = both_stop(
        folder.path(),
        "missing.cps",
        "description = \"missing\";\ncapabilities = CAPABILITY_MILLING;\n\
         function Tool(n) { this.n = n; }\nTool.prototype.get = function () { return this.n; };\n\
         function onOpen() {\n  var t = new Tool(1);\n  writeln(\"T\" + t.get());\n  writeln(t.put(2));\n}\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "t.put is not a function",
    );
    assert!(said.contains("error[RT037]: TypeError: the object has no method 'put'"), "{said}");
    assert!(said.contains("missing.cps:8:"), "not at the call's line:\n{said}");
}

/// JavaScript's errors in a post's own code: Node.js throws each, and
/// postc stops at the expression that raised it (at the statement, for a
/// call of a value that is no function), line and column, with the
/// function it is in, writing nothing.
#[test]
fn a_javascript_error_stops_the_post_at_the_expression_that_raised_it() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let cases = [
        (
            "a.y",
            "writeln(a.y);",
            "Cannot read properties of undefined",
            "cannot read property 'y' of undefined",
            "6:11",
        ),
        ("a.y = 3", "a.y = 3;", "Cannot set properties of undefined", "cannot set property 'y' of undefined", "6:3"),
        (
            "a[k]",
            "writeln(a[\"k\"]);",
            "Cannot read properties of undefined",
            "cannot read property 'k' of undefined",
            "6:11",
        ),
        ("a local that holds no function", "a(3);", "a is not a function", "undefined is not a function", "6:3"),
        (
            "an undeclared name",
            "writeln(nothingHere + 1);",
            "nothingHere is not defined",
            "nothingHere is not defined",
            "6:11",
        ),
    ];
    for (i, (what, line, node_says, postc_says, at)) in cases.into_iter().enumerate() {
        let text = format!(
            "description = \"raises\";\ncapabilities = CAPABILITY_MILLING;\n\
             function helper() {{\n  var a;\n  writeln(\"x\");\n  {line}\n}}\n\
             function onOpen() {{\n  helper();\n}}\nfunction onClose() {{}}\n"
        );
        let said = both_stop(folder.path(), &format!("raises{i}.cps"), &text, &job, &jsonl, &script, node_says);
        assert!(said.contains("error[RT037]") && said.contains(postc_says), "{what}: {said}");
        assert!(said.contains(&format!("raises{i}.cps:{at}")), "{what}: not at {at}:\n{said}");
        assert!(said.contains("in function `helper`"), "{what}: the function it is in:\n{said}");
    }
}

/// An error the host raises for the post (`error(message)`, a host method
/// given what it cannot take) points at the post's statement that led
/// there, line and column, as well as at the host's line.
#[test]
fn an_error_raised_in_the_host_points_at_the_posts_statement() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let said = both_stop(
        folder.path(),
        "stops.cps",
        "description = \"stops\";\ncapabilities = CAPABILITY_MILLING;\n\
         function check(n) {\n  if (n > 2) {\n    error(\"too many: \" + n);\n  }\n}\n\
         function onOpen() {\n  check(1);\n  check(3);\n}\nfunction onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "too many: 3",
    );
    assert!(said.contains("error[RT036]") && said.contains("too many: 3"), "{said}");
    assert!(said.contains("stops.cps:5:5"), "not at the post's `error(...)`:\n{said}");
    assert!(said.contains("the post's statement that led there"), "{said}");
}

/// The machine angles of the top are 0 on any machine; asked for those of
/// another direction on a machine with rotary axes, which postc's host
/// does not model (docs/fusion.md, choice 39), the post stops with the
/// function named at its call, under Node.js's host as under postc.
#[test]
fn machine_angles_of_a_tilted_direction_stop_the_post_with_the_function_named() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let said = both_stop(
        folder.path(),
        "tilted.cps",
        "description = \"tilted\";\ncapabilities = CAPABILITY_MILLING;\n\
         function onOpen() {\n  var c = createAxis({coordinate: 2, table: true, axis: [0, 0, 1], cyclic: true});\n\
         machineConfiguration = new MachineConfiguration(c);\n\
         var top = machineConfiguration.getABC(new Matrix());\n  writeln(\"C\" + top.z);\n\
         var tilted = machineConfiguration.getABC(new Matrix(new Vector(0, 1, 0), 0.5));\n}\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "MachineConfiguration.getABC",
    );
    assert!(said.contains("error[RT036]") && said.contains("`MachineConfiguration.getABC`"), "{said}");
    assert!(said.contains("tilted.cps:8:1"), "not at the post's statement:\n{said}");
}

/// A machine a post makes with rotary axes is a multi-axis machine whose
/// axes are what the post specified (docs/fusion.md, choice 39): the
/// post reads back each property, the range in radians; the top's angles
/// are 0 and `Matrix.getXYZRotation` turns about X, then Y, then Z. The
/// values are the declarations' meaning, written out here; Node.js with
/// the same host prints the same bytes.
#[test]
fn a_machine_made_with_rotary_axes_is_a_multi_axis_machine() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    // Rz(90°)·Ry(0)·Rx(90°): X to Y, Y to Z, Z to X.
    both_print(
        folder.path(),
        "axes.cps",
        "description = \"axes\";\ncapabilities = CAPABILITY_MILLING;\n\
         var f = createFormat({decimals: 3});\n\
         function onOpen() {\n\
           writeln(\"plain \" + machineConfiguration.isMultiAxisConfiguration() + \" \" + machineConfiguration.isMachineCoordinate(2));\n\
           var b = createAxis({coordinate: 1, table: false, axis: [0, -1, 0], range: [-90, 45], preference: 1});\n\
           var c = createAxis({coordinate: 2, table: true, axis: [0, 0, 1], cyclic: true});\n\
           machineConfiguration = new MachineConfiguration(b, c);\n\
           var m = machineConfiguration;\n\
           writeln(\"multi \" + m.isMultiAxisConfiguration() + \" \" + m.getNumberOfAxes() + \" \" + m.isMachineCoordinate(0) + m.isMachineCoordinate(1) + m.isMachineCoordinate(2));\n\
           writeln(\"kind \" + m.isHeadConfiguration() + \" \" + m.isTableConfiguration());\n\
           var u = m.getAxisU();\n\
           writeln(\"B \" + u.getCoordinate() + \" \" + u.isHead() + \" \" + u.getAxis().y + \" \" + f.format(u.getRange().getMinimum()) + \" \" + f.format(u.getRange().getMaximum()) + \" \" + u.getPreference());\n\
           var w = m.getAxisByCoordinate(2);\n\
           writeln(\"C \" + w.isTable() + \" \" + w.isCyclic() + \" \" + m.getAxisW().isEnabled());\n\
           var top = m.remapABC(m.getABC(new Matrix()));\n\
           writeln(\"top \" + top.x + \" \" + top.y + \" \" + top.z);\n\
           var r = Matrix.getXYZRotation(new Vector(Math.PI / 2, 0, Math.PI / 2));\n\
           var e = r.eulerZYX_R;\n\
           writeln(\"R \" + f.format(r.getElement(0, 2)) + \" \" + f.format(r.getElement(1, 0)) + \" \" + f.format(r.getElement(2, 1)) + \" \" + f.format(e.x) + \" \" + f.format(e.y) + \" \" + f.format(e.z));\n\
         }\n\
         function onSection() {}\nfunction onRapid(x, y, z) {}\nfunction onLinear(x, y, z, feed) {}\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "plain false false\nmulti true 5 falsetruetrue\nkind false false\nB 1 true -1 -1.571 0.785 1\n\
         C true true false\ntop 0 0 0\nR 1 1 1 1.571 0 1.571\n",
    );
}

/// A matrix changed in place reads as the matrix it now is: `forward`,
/// `right`, `up` and `eulerZYX_R` after `setElement`, `setColumn`,
/// `setForward`, `transpose`, `negate`, `add` and `subtract`; `multiply`
/// by a number scales it; `isZero` of the zero matrix is true. The values
/// are the declarations' meaning, written out here; Node.js with the same
/// host prints the same bytes.
#[test]
fn a_matrix_changed_in_place_reads_as_the_matrix_it_is() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    both_print(
        folder.path(),
        "matrix.cps",
        "description = \"matrix\";\ncapabilities = CAPABILITY_MILLING;\n\
         var f = createFormat({decimals: 3});\n\
         function v(a) { return f.format(a.x) + \",\" + f.format(a.y) + \",\" + f.format(a.z); }\n\
         function onOpen() {\n\
           var m = new Matrix();\n\
           m.setElement(0, 2, 1);\n\
           writeln(\"forward \" + v(m.forward) + \" \" + v(m.getForward()));\n\
           var r = Matrix.getZRotation(Math.PI / 2);\n\
           writeln(\"euler \" + v(r.eulerZYX_R));\n\
           r.setElement(0, 0, 1); r.setElement(0, 1, 0); r.setElement(1, 0, 0); r.setElement(1, 1, 1);\n\
           writeln(\"euler \" + v(r.eulerZYX_R) + \" \" + r.isIdentity());\n\
           var c = new Matrix();\n\
           c.setForward(new Vector(0, 1, 0));\n\
           writeln(\"column \" + v(c.forward) + \" \" + v(c.up) + \" \" + v(c.getRow(1)));\n\
           c.transpose();\n\
           writeln(\"transposed \" + v(c.getRow(2)) + \" \" + v(c.forward));\n\
           var n = new Matrix();\n\
           n.negate();\n\
           writeln(\"negated \" + v(n.right) + \" \" + v(new Matrix().getNegated().up));\n\
           n.add(new Matrix(3));\n\
           writeln(\"sum \" + v(n.right));\n\
           n.subtract(new Matrix(2));\n\
           writeln(\"difference \" + v(n.right) + \" \" + n.isZero() + \" \" + new Matrix(0).isZero());\n\
           writeln(\"scaled \" + v(new Matrix().multiply(2).forward));\n\
           writeln(\"angles \" + v(new Matrix().getEuler2(EULER_ZXZ_R)) + \" \" + v(new Matrix().getTurnAndTilt(0, 1)));\n\
         }\n\
         function onSection() {}\nfunction onRapid(x, y, z) {}\nfunction onLinear(x, y, z, feed) {}\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "forward 1,0,1 1,0,1\neuler 0,0,1.571\neuler 0,0,0 true\ncolumn 0,1,0 0,1,0 0,1,1\n\
         transposed 0,1,0 0,0,0\nnegated -1,0,0 0,-1,0\nsum 2,0,0\ndifference 0,0,0 true true\n\
         scaled 0,0,2\nangles 0,0,0 0,0,0\n",
    );
}

/// A rotation's angles in one of Fusion's conventions are known to postc
/// for the identity only (docs/fusion.md, choice 39): of another matrix,
/// the post stops with the function named at its call, under Node.js's
/// host as under postc, and writes nothing.
#[test]
fn euler_angles_of_a_rotation_stop_the_post_with_the_function_named() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let said = both_stop(
        folder.path(),
        "euler.cps",
        "description = \"euler\";\ncapabilities = CAPABILITY_MILLING;\n\
         function onOpen() {\n  var top = new Matrix().getEuler2(EULER_XYZ_S);\n  writeln(\"A\" + top.x);\n\
         var tilted = Matrix.getXRotation(0.5).getEuler2(EULER_XYZ_S);\n}\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "Matrix.getEuler2",
    );
    assert!(said.contains("error[RT036]") && said.contains("`Matrix.getEuler2`"), "{said}");
    assert!(said.contains("euler.cps:6:1"), "not at the post's statement:\n{said}");
}

/// Writes `text` as the post `name` in `folder` and runs it with postc
/// over `job` and with Node.js's host `script` over `jsonl`: both must
/// print `expected` (line ends read as `\n`).
fn both_print(folder: &Path, name: &str, text: &str, job: &Path, jsonl: &Path, script: &Path, expected: &str) {
    let post = folder.join(name);
    std::fs::write(&post, text).expect("write the post");
    let ours = support::cimco::post_toolpath(&support::compile_file(&post), job).expect("posts");
    let ours = String::from_utf8(ours).expect("text");
    assert_eq!(ours.replace("\r\n", "\n"), expected, "postc");
    let node = node_prints(script, &post, jsonl, name);
    assert_eq!(String::from_utf8_lossy(&node), ours, "Node.js first");
}

/// The job's unit is known before a post's top level runs, as Fusion's
/// engine knows the document's: 183 corpus posts make their formats there
/// from `unit` (`decimals: (unit == MM ? 3 : 4)`) and many give settings
/// with `spatial(..., MM)`. An inch job printed three decimals and took
/// `spatial(0.25, MM)` for 0.25 inch before.
#[test]
fn a_post_top_level_reads_the_unit_of_the_job() {
    let Some((folder, _, _, script)) = node_and_milling_job() else { return };
    let job = support::corpus().join("toolpaths/native/one_toolpath_inch.ron");
    let jsonl = folder.path().join("inch.jsonl");
    support::cimco::export_jsonl(&job, &jsonl).expect("export the job");
    both_print(
        folder.path(),
        "units.cps",
        "description = \"units\";\ncapabilities = CAPABILITY_MILLING;\n\
         var xyzFormat = createFormat({decimals: (unit == MM ? 3 : 4), forceDecimal: true});\n\
         var chord = spatial(0.25, MM);\n\
         var opened = false;\n\
         function onOpen() { writeln((unit == IN ? \"inch \" : \"mm \") + xyzFormat.format(chord) + \" \" + xyzFormat.format(spatial(1, IN))); }\n\
         function onLinear(x, y, z, feed) { if (!opened) { opened = true; writeln(\"X\" + xyzFormat.format(x)); } }\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "inch 0.0098 1.\nX1.\n",
    );
}

/// The spindle's direction is the tool's `clockwise` (docs/fusion.md,
/// choice 41): a tool loaded clockwise, a `SpindleOn` with `ccw` (here one
/// that changes nothing but the direction) turning the next section's
/// spindle the other way; postc prints what Node.js prints.
#[test]
fn a_counter_clockwise_spindle_is_the_tools_direction() {
    let Some((folder, _, _, script)) = node_and_milling_job() else { return };
    let job = folder.path().join("ccw.ron");
    std::fs::write(
        &job,
        "Job(units: Mm, file: (name: \"ccw\", dir: \"/jobs\", extension: \"nc\"))\n\
         Tool(number: 1, name: \"Mill\", diameter: 6, spindle_speed: 9000, cut_feed: 600, plunge_feed: 200)\n\
         ToolpathStart(name: \"One\")\n\
         Rapid(x: 0, y: 0, z: 5)\n\
         Feed(x: 10, y: 0, z: 5)\n\
         ToolpathEnd\n\
         Tool(number: 2, name: \"Left hand\", diameter: 3, spindle_speed: 4000, cut_feed: 300, plunge_feed: 100)\n\
         ToolpathStart(name: \"Two\")\n\
         SpindleOn(speed: 4000, ccw: true)\n\
         Rapid(x: 20, y: 0, z: 5)\n\
         Feed(x: 30, y: 0, z: 5)\n\
         ToolpathEnd\n\
         End\n",
    )
    .expect("write the job");
    let jsonl = folder.path().join("ccw.jsonl");
    support::cimco::export_jsonl(&job, &jsonl).expect("export the job");
    both_print(
        folder.path(),
        "direction.cps",
        "description = \"direction\";\ncapabilities = CAPABILITY_MILLING;\n\
         function onSection() { writeln(\"T\" + tool.number + \" S\" + tool.spindleRPM + (tool.clockwise ? \" M3\" : \" M4\")); }\n\
         function onClose() {}\n",
        &job,
        &jsonl,
        &script,
        "T1 S9000 M3\nT2 S4000 M4\n",
    );
}

/// Functions declared in a function (a post's module, as a CIMCO post
/// converted to Fusion is): each names its siblings, one sets a `var` of
/// the function around it that has no value, one reads `arguments`; postc
/// prints what Node.js prints.
#[test]
fn functions_declared_in_a_function_call_each_other_as_node_runs_them() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    both_print(
        folder.path(),
        "module.cps",
        "description = \"module\";\ncapabilities = CAPABILITY_MILLING;\n\
         var api = (function () {\n\
           var count;\n\
           var prefix = \"N\";\n\
           function next() { count = (count || 0) + 1; return prefix + count; }\n\
           function line() { var words = []; for (var i = 0; i < arguments.length; i++) { words.push(arguments[i]); } return next() + \" \" + words.join(\" \"); }\n\
           function both(a, b) { return line(a, b); }\n\
           return {both: both, line: line};\n\
         })();\n\
         function onOpen() { writeln(api.both(\"G90\", \"G21\")); writeln(api.line(\"G0\", \"X1\", \"Y2\")); }\n\
         function onLinear(x, y, z, feed) {}\n\
         function onClose() { writeln(api.line(\"M30\")); }\n",
        &job,
        &jsonl,
        &script,
        "N1 G90 G21\nN2 G0 X1 Y2\nN3 M30\n",
    );
}

/// A post property is set only to a value its type takes: an `enum` to
/// one of its `values`, a boolean to true or false; anything else stops the
/// post naming what it takes, in postc and under Node.js alike (Kinetic-NC's
/// `useRadius`, an enum, set to `true` printed arcs with no centre).
#[test]
fn a_property_is_set_only_to_a_value_its_type_takes() {
    let Some((folder, job, jsonl, script)) = node_and_milling_job() else { return };
    let post = folder.path().join("props.cps");
    std::fs::write(
        &post,
        "description = \"props\";\ncapabilities = CAPABILITY_MILLING;\n\
         properties = {\n\
           arcs: {title: \"Arcs\", type: \"enum\", values: [{title: \"Radius\", id: \"radius\"}, {title: \"Centre\", id: \"centre\"}], value: \"centre\"},\n\
           flag: {title: \"Flag\", type: \"boolean\", value: false}\n\
         };\n\
         function onOpen() { writeln(getProperty(\"arcs\") + \" \" + getProperty(\"flag\")); }\n\
         function onClose() {}\n",
    )
    .expect("write the post");
    let out = folder.path().join("props.nc");
    let post_with = |set: &str| {
        support::postc(&[
            "post",
            &post.display().to_string(),
            &job.display().to_string(),
            "-o",
            &out.display().to_string(),
            "--set",
            &format!("property.{set}"),
            // The program is the property's value, no G-code.
            "--no-verify",
        ])
    };
    let node_with = |set: &str| {
        support::cimco::node_command().arg(&script).arg(&post).arg(&jsonl).arg("--property").arg(set).output()
    };
    for (set, says) in
        [("arcs=true", "is one of radius, centre, not \"true\""), ("flag=maybe", "is true or false, not \"maybe\"")]
    {
        let node = node_with(set).expect("run node");
        let node_err = String::from_utf8_lossy(&node.stderr);
        assert!(!node.status.success() && node_err.contains(says), "{set}: Node.js: {node_err}");
        let ours = post_with(set);
        let err = String::from_utf8_lossy(&ours.stderr);
        assert_eq!(ours.status.code(), Some(1), "{set}: {err}");
        assert!(err.contains(says), "{set}: {err}");
        assert!(!out.exists(), "{set}: no program is written");
    }
    for (set, prints) in [("arcs=radius", "radius false"), ("flag=True", "centre true")] {
        let ours = post_with(set);
        assert!(ours.status.success(), "{}", String::from_utf8_lossy(&ours.stderr));
        let node = node_with(set).expect("run node");
        let printed = std::fs::read(&out).expect("the program");
        assert_eq!(String::from_utf8_lossy(&printed).lines().next(), Some(prints), "{set}");
        assert_eq!(node.stdout, printed, "{set}: Node.js and postc");
    }
}

/// What Node.js prints running `post` over `jsonl` with the host
/// `script`; Node.js stopping fails the test, naming `what`.
fn node_prints(script: &Path, post: &Path, jsonl: &Path, what: &str) -> Vec<u8> {
    let node = support::cimco::node_command().arg(script).arg(post).arg(jsonl).output().expect("run node");
    assert!(node.status.success(), "{what}: Node.js stops: {}", String::from_utf8_lossy(&node.stderr));
    node.stdout
}

/// Writes `text` as the post `name` in `folder` and runs it under Node.js,
/// which must stop saying `node_says`, and under postc, which must stop
/// too ([`postc_stops`]): what postc said.
fn both_stop(
    folder: &Path,
    name: &str,
    text: &str,
    job: &Path,
    jsonl: &Path,
    script: &Path,
    node_says: &str,
) -> String {
    let post = folder.join(name);
    std::fs::write(&post, text).expect("write the post");
    let node = support::cimco::node_command().arg(script).arg(&post).arg(jsonl).output().expect("run node");
    let stderr = String::from_utf8_lossy(&node.stderr);
    assert!(!node.status.success() && stderr.contains(node_says), "{name}: Node.js: {stderr}");
    postc_stops(&post, job)
}

/// Posts `post` over `job` with `postc post -o`: the run must fail with
/// exit 1 and write no program. What postc said.
fn postc_stops(post: &Path, job: &Path) -> String {
    let out = post.with_extension("nc");
    let s = |p: &Path| p.to_str().expect("a UTF-8 path").to_string();
    let run = support::postc(&["post", "-q", &s(post), &s(job), "-o", &s(&out)]);
    let said = support::said(&run);
    assert_eq!(run.status.code(), Some(1), "{said}");
    assert!(!out.exists(), "no program is written:\n{said}");
    said
}

/// `getCurrentRecordId()` and `getNextRecord().isMotion()` (docs/fusion.md,
/// choice 22) over a toolpath whose feed changes with no motion (a Feed to
/// where the tool is, a FeedRate record, a dwell): postc's runtime, which
/// holds one event in hand, prints what the Node.js referee computes from
/// the whole file.
#[test]
fn records_number_the_events_and_say_whether_a_move_follows() {
    if support::cimco::node().is_none() {
        support::referee_missing("fusion_node", "node");
        return;
    }
    let folder = tempfile::tempdir().expect("a temporary folder");
    let tmp = folder.path();
    let job = tmp.join("records.ron");
    std::fs::write(
        &job,
        "Job(units: Mm, home: (x: 0, y: 0, z: 25), safe_z: 5)\n\
         Tool(number: 1, name: \"T1\", diameter: 6, spindle_speed: 10000, cut_feed: 1000, plunge_feed: 300)\n\
         ToolpathStart(name: \"P\")\n\
         Rapid(x: 1, y: 2, z: 5)\n\
         Feed(x: 1, y: 2, z: -1, intent: Plunge)\n\
         Feed(x: 1, y: 2, z: -1, feed: 500)\n\
         FeedRate(value: 700)\n\
         Feed(x: 9, y: 2, z: -1, feed: 700)\n\
         Dwell(seconds: 1)\n\
         Feed(x: 9, y: 2, z: -1, feed: 200)\n\
         ToolpathEnd\n\
         End\n",
    )
    .expect("write the job");
    let jsonl = tmp.join("records.jsonl");
    support::cimco::export_jsonl(&job, &jsonl).expect("export the job");
    let post = tmp.join("records.cps");
    std::fs::write(
        &post,
        "description = \"records\";\ncapabilities = CAPABILITY_MILLING;\n\
         function at(what) { writeln(what + \" \" + getCurrentRecordId() + \" \" + getNextRecord().isMotion()); }\n\
         function onOpen() { at(\"open\"); }\n\
         function onSection() { at(\"section\"); }\n\
         function onRapid(x, y, z) { at(\"rapid\"); }\n\
         function onLinear(x, y, z, feed) { at(\"linear \" + feed); }\n\
         function onDwell(seconds) { at(\"dwell\"); }\n\
         function onSectionEnd() { at(\"section end\"); }\n\
         function onClose() { at(\"close\"); }\n",
    )
    .expect("write the post");
    let compiled = support::compile_file(&post);
    let ours = support::cimco::post_toolpath(&compiled, &job).expect("postc posts the job");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/fusion.js");
    let node = node_prints(&script, &post, &jsonl, "records.cps");
    assert_eq!(String::from_utf8_lossy(&node), String::from_utf8_lossy(&ours));
    // The zero-length feed that only changes the feed is followed by a move.
    assert!(String::from_utf8_lossy(&ours).contains("linear 500 5 true"), "{}", String::from_utf8_lossy(&ours));
}

/// Setting one of the post's own globals through the global object
/// (`this.counter = ...` in a plain function) is refused with RT039 at the
/// assignment's function and writes nothing. (Reading them through `this`,
/// and setting a property the post does not declare, print what Node.js
/// prints: "the global object" in [`PROTOTYPES`].)
#[test]
fn a_global_set_through_this_is_refused() {
    let Some((folder, job, _jsonl, _script)) = node_and_milling_job() else { return };
    let post = folder.path().join("global.cps");
    std::fs::write(
        &post,
        "description = \"global\";\ncapabilities = CAPABILITY_MILLING;\nvar counter = 1;\n\
         function bump() { this.counter = 2; }\n\
         function onOpen() {\n  writeln(\"C\" + counter);\n  bump();\n}\n\
         function onClose() {}\n",
    )
    .expect("write the post");
    let said = postc_stops(&post, &job);
    assert!(said.contains("error[RT039]") && said.contains("`counter`"), "{said}");
    assert!(said.contains("global.cps:4:"), "not at the function that sets it:\n{said}");
}
