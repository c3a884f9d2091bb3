//! The second engine as referee: every corpus CIMCO post runs under
//! Node.js with the host in `tests/node_host/` (written from docs/cimco.md,
//! sharing no code with postc) over the same toolpaths, exported as JSON
//! Lines, and must print byte for byte what postc prints. Skipped, with a
//! message, when `node` is not installed; under `CI=true` that fails.
//!
//! `cargo bench --bench cimco_vs_node` measures both engines over a
//! million-move toolpath (docs/performance.md).

use crate::support;

use std::path::{Path, PathBuf};

use crate::support::cimco::*;
use postc_ir::Post;

#[test]
fn node_prints_what_postc_prints() {
    let Some(version) = node_or_skip("cimco_node") else { return };
    eprintln!("cimco_node: referee is Node.js {version}");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut runs = Vec::new();
    for post_path in posts() {
        match compile(&post_path) {
            Ok(post) => runs.push((post_path, post)),
            Err(e) => failures.push(e),
        }
    }
    let compared = referee(&runs, dir.path(), &mut failures);
    assert!(failures.is_empty(), "{} pairs differ:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(compared >= 10, "only {compared} pairs were compared");
}

/// A corpus post converted to its own dialect (`postc convert --to
/// cimco`) is real JavaScript: Node.js runs it and prints, byte for byte,
/// what postc prints for the source post.
#[test]
fn node_runs_converted_posts_as_postc_posts_their_sources() {
    if node_or_skip("cimco_node").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut runs = Vec::new();
    for post_path in posts() {
        let post = match compile(&post_path) {
            Ok(p) => p,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        match postc_backends::convert(&post, postc_backends::Target::Cimco) {
            Ok(js) => {
                let converted = dir.path().join(format!("{}.js", stem(&post_path)));
                std::fs::write(&converted, js).expect("write the converted post");
                runs.push((converted, post));
            }
            Err(d) => failures.push(format!("{}: refused: {}", post_path.display(), d[0].message)),
        }
    }
    let compared = referee(&runs, dir.path(), &mut failures);
    assert!(failures.is_empty(), "{} pairs differ:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(compared >= 30, "only {compared} pairs were compared");
}

/// Runs each JavaScript post under Node.js over the toolpaths of its
/// post, which postc posts: the number of programs that agree; each
/// that does not is a failure.
fn referee(runs: &[(PathBuf, Post)], dir: &Path, failures: &mut Vec<String>) -> usize {
    let mut compared = 0;
    for (js, post) in runs {
        for toolpath in toolpaths(post) {
            let pair = format!("{}__{}", stem(js), stem(&toolpath));
            let jsonl = dir.join(format!("{}.jsonl", stem(&toolpath)));
            if let Err(e) = export_jsonl(&toolpath, &jsonl) {
                failures.push(format!("{pair}: cannot export the toolpath: {e}"));
                continue;
            }
            let ours = match post_toolpath(post, &toolpath) {
                Ok(o) => o,
                Err(e) => {
                    failures.push(format!("{pair}: {e}"));
                    continue;
                }
            };
            match run_node(js, &jsonl, &[]) {
                Ok(theirs) if theirs == ours => compared += 1,
                Ok(theirs) => {
                    failures.push(format!("{pair}: Node.js (-) and postc (+) differ\n{}", diff(&theirs, &ours)))
                }
                Err(e) => failures.push(format!("{pair}: {e}")),
            }
        }
    }
    compared
}

/// JavaScript corners Node.js and postc once disagreed on (found while
/// writing the field-style posts): `lastIndexOf` from an index, the
/// order of `for ... in` over keys that are array indices, whole
/// numbers in another radix, chains of `+` that add numbers until a
/// text joins them (built in one buffer by the runtime), and the text
/// methods of ES2015 that real posts call (`startsWith`, `padStart` ...).
#[test]
fn javascript_corners_print_as_node_prints() {
    if node_or_skip("cimco_node").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("corners.js");
    std::fs::write(
        &post_path,
        r#"var table = {b: 1, 10: "x", 2: "y", a: 2, "01": 3};
function keysOf(o) { var s = ""; for (var k in o) { s += k + ","; } return s; }
function onOpen(isClipboard) {
    var t = "ab ab ab";
    return "(" + t.lastIndexOf("ab", 4) + " " + t.lastIndexOf("ab") + " " + t.lastIndexOf("ab", -3) + " " +
        t.lastIndexOf("ab", 100) + " " + t.lastIndexOf("zz", 3) + ")\n(" + keysOf(table) + ")\n(" +
        (255).toString(16) + " " + (-10).toString(2) + " " + (35).toString(36) + " " + (12).toString(10) + ")\n";
}
function chain(p) { return p + 1 + "a" + p + 2 + "|" + (p + 1) + (p & 1) + "b"; }
function onLinear(x, y, z, movement) { return ""; }
function es2015(t) {
    return [t.startsWith("ab"), t.startsWith("b", 1), t.startsWith("x"), t.endsWith("ab"), t.endsWith("a", 1),
        t.includes(" a"), t.includes("ab", 7), t.includes(""), "5".padStart(3, "0"), "5".padStart(4, "ab"),
        "5".padEnd(3), "abc".padStart(2, "x"), "ab".repeat(3), "[" + "  x ".trimStart() + "]",
        "[" + "  x ".trimEnd() + "]"].join(",");
}
function onClose() { return "(" + chain(2) + " " + chain(0.5) + ")\n(" + es2015("ab ab ab") + ")\n"; }
"#,
    )
    .expect("write the post");
    let post = compile(&post_path).expect("compiles");
    assert_posts_as_node(dir.path(), &post_path, &post);
}

/// JavaScript's `+` of every kind of value with every other (null,
/// `undefined`, booleans, text, numbers, arrays, objects): null joins text
/// as `null`, an array as its items joined, an object as `[object
/// Object]`, `[] + []` is "" and `1 + null` is 1; in a handler built in
/// the output (`"x" + p`), a chain of `+` and a function's value. The post
/// runs as postc's shaped lowering runs it and, with a constructor that
/// keeps it off that, as the general form does: both as Node.js prints.
#[test]
fn plus_of_every_kind_prints_as_node_prints() {
    if node_or_skip("cimco_node").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let shaped = r#"var vals = [null, undefined, true, false, "a", 1, [1, 2], {k: 1}, [], [null], 0];
var count = 0;
function show(a, b) { return a + b; }
function onOpen(isClipboard) { return "(" + ("a" + null) + "|" + (null + "a") + "|" + ([] + []) + "|" + (1 + null) + ")\n"; }
function onLinear(x, y, z, movement) {
    count++;
    if (count != 2) { return ""; }
    var out = [];
    for (var i = 0; i < vals.length; i++) {
        for (var j = 0; j < vals.length; j++) {
            out.push(show(vals[i], vals[j]));
        }
    }
    var p = null, q;
    var s = "x" + p + "|" + q + "|" + (p + "y") + "|" + (q + "y") + "|" + ("z" + (x > 1e9 ? 1 : null));
    return "(" + out.join(" ") + ")\n(" + s + ")\n";
}
function nothing() { return null; }
function onRapid(x, y, z) { return nothing(); }
function onClose() { var p = null; return "(" + p + ")\n"; }
"#;
    let general =
        shaped.replace("var count = 0;", "var count = 0;\nfunction Obj() { this.v = 1; }\nvar made = new Obj();");
    let toolpath = support::corpus().join("toolpaths/cimco/mill.ron");
    let jsonl = dir.path().join("mill.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("export");
    for (name, text) in [("plus.js", shaped.to_string()), ("plus_general.js", general)] {
        let post_path = dir.path().join(name);
        std::fs::write(&post_path, text).expect("write the post");
        let post = compile(&post_path).expect("compiles");
        let ours = post_toolpath(&post, &toolpath).expect("postc posts");
        let theirs = run_node(&post_path, &jsonl, &[]).expect("Node posts");
        assert_eq!(String::from_utf8_lossy(&theirs), String::from_utf8_lossy(&ours), "{name}");
    }
}

/// Arrays a call makes and drops are made again from the engine's spares
/// (`Engine::new_array`): an array something still holds (a global, an
/// array in an array, a closure's `arguments`, an object's property) keeps
/// its items and its identity, and a new array is never one of them.
#[test]
fn arrays_made_again_keep_what_is_still_held_as_node_does() {
    if node_or_skip("cimco_node").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("arrays.js");
    std::fs::write(
        &post_path,
        r#"var kept = [];
var held = {list: null};
var lastArgs = null;
function words(a, b) { var w = [a, b]; var inner = [w, [a]]; return inner; }
function note() { lastArgs = arguments; return arguments.length; }
function pick(list) { var f = list.filter(function (v) { return v !== ""; }); return f.concat([f.length]).slice(0); }
function onLinear(x, y, z, movement) {
    var made = words("X" + x, "Y" + y);
    var first = made[0];
    if (kept.length < 3) { kept.push(first); }
    held.list = pick(["A", "", "B" + z]);
    note(x, y, [z]);
    var fresh = [x];
    var again = [x];
    return "(" + first.join(" ") + "|" + made[1].join(",") + "|" + held.list.join(",") + "|" + lastArgs.length + "|" +
        lastArgs[2].join("") + "|" + (fresh === again) + "|" + (kept[0] === first) + "|" + kept.length + ")\n";
}
function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) { return ""; }
function onClose() {
    var out = [];
    for (var i = 0; i < kept.length; i++) { out.push(kept[i].join("/")); }
    return "(" + out.join(";") + "|" + held.list.join(",") + "|" + lastArgs[0] + ")\n";
}
"#,
    )
    .expect("write the post");
    let post = compile(&post_path).expect("compiles");
    assert_posts_as_node(dir.path(), &post_path, &post);
}

/// A CNC-Calc post with JavaScript's prototypes (a constructor, another
/// inheriting from it through `Object.create`, a super call, a method added
/// to `String.prototype`, `for ... in` over inherited methods): the shaped
/// lowering leaves it to the general form, which runs it as Node.js does.
#[test]
fn prototypes_print_as_node_prints() {
    let Some(_) = node_or_skip("cimco_node") else { return };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("prototypes.js");
    std::fs::write(
        &post_path,
        r#"function Counter(start) { this.n = start; }
Counter.prototype.next = function () { this.n += 1; return this.n; };
Counter.prototype.label = function (prefix) { return prefix + this.n; };
function Labeled(start, prefix) { Counter.call(this, start); this.prefix = prefix; }
Labeled.prototype = Object.create(Counter.prototype);
Labeled.prototype.constructor = Labeled;
Labeled.prototype.label = function () { return "[" + Counter.prototype.label.call(this, this.prefix) + "]"; };
String.prototype.shout = function () { return this.toUpperCase() + "!"; };
var counter = new Labeled(10, "N");
function onOpen(isClipboard) {
    var keys = [];
    for (var k in counter) { keys.push(k); }
    return "(" + counter.label() + " " + counter.next() + " " + counter.label() + " " + ("next" in counter) + " " +
        counter.hasOwnProperty("next") + " " + (counter.constructor === Labeled) + " " + keys.join(",") + " " +
        "open".shout() + " " + Object.prototype.toString.call([]) + ")\n";
}
function onLinear(x, y, z, movement) { return ""; }
function onClose() { counter.next(); return "(" + counter.label() + " " + Object.keys(counter).join(",") + ")\n"; }
"#,
    )
    .expect("write the post");
    let post = compile(&post_path).expect("compiles");
    assert!(post.scripts.is_empty(), "the general form runs the post, with no script");
    assert_posts_as_node(dir.path(), &post_path, &post);
}

/// A post that runs every text method with a regular expression, and
/// `test`, over texts with parentheses, digits, letters past ASCII, an
/// astral character and line breaks (`\n`, `\r\n`, U+2028): as postc
/// lowers it (native IR, no script), kept in Rhai scripts (an `isFinite`
/// keeps the post off the general lowering), and under Node.js, byte for
/// byte. What postc refuses (RT038: `^` and `$` under `m` over `\r` or
/// U+2028) the post steers around as a post would; where JavaScript steps
/// through UTF-16 units (an empty match, a class over a character past
/// U+FFFF) only the astral text's safe methods run (docs/cimco.md).
const REGEX_POST: &str = r#"var linebreak = "\n";
var samples = ["Tool (T1) D=6mm\nline 2 (\u00e9 \u00fc)", "G1 X10.5 Y-3 (cut)\r\nG0 Z25\u2028end", "\u00c4\u00d6\u00dc 123 abc_DEF (x(y)z)", "", "a\u00a0b\tc  d"];
var astral = "Tool (T2) \ud83d\ude00 6mm\nnext (\u00e9)";
function show(t) {
    return String(t).replace(/\r/g, "\\r").replace(/\n/g, "\\n").replace(/\u2028/g, "\\u2028");
}
function safe(t, out) {
    out.push(show(t.replace(/[()]/g, "")));
    out.push(show(t.replace(/\d+/g, "<$&>")));
    out.push(show(t.replace(/(\w)(\d)/g, "$2$1$$")));
    out.push(show(t.replace(/\s+/g, "_")));
    out.push(show(t.replace("(", "[").replace(")", "]")));
    out.push(show(t.replace("1", "[$&|$`|$'|$1]")));
    out.push(show(t.replace(/(\u00e9|\u00dc)/gi, "[$1|$`|$']")));
    out.push(show(t.replace(/\bT(\d)\b/, "tool $1")));
    out.push(show(t.split(/\s*[()]\s*/).join("|")));
    out.push(show(t.split(/(\d)/).join("|")));
    out.push(t.split(/\r?\n|\u2028/).length);
    out.push(t.search(/\d/));
    out.push(t.search(/\ud83d\ude00/));
    out.push(t.search(/\)/));
    out.push(t.search("Y"));
    out.push(/\(T\d\)/.test(t));
    out.push(/^line/.test(t));
    out.push(/\u00c9/i.test(t));
    out.push(/end$/.test(t));
}
function each(t) {
    var out = [];
    safe(t, out);
    out.push(show(t.replace(/.$/g, "!")));
    out.push(show(t.replace(/x*/g, "-")));
    out.push(show(t.replace(/[^\x20-\x7e]/g, "?")));
    out.push(t.split(/,?/).length);
    if (!/[\r\u2028\u2029]/.test(t)) {
        out.push(show(t.replace(/^/gm, "> ")));
        out.push(show(t.replace(/.$/gm, "!")));
        out.push(/^line/m.test(t));
    }
    return out.join(" ; ");
}
function onOpen() {
    var lines = [];
    for (var i = 0; i < samples.length; i++) {
        lines.push(each(samples[i]));
    }
    var out = [];
    safe(astral, out);
    lines.push(out.join(" ; "));
    var re = /a(b)c/g;
    lines.push([String(re), typeof re, re.source, re.global, re.ignoreCase, /x/im.multiline, re === re, /x/ === /x/, re == String(re), re ? "truthy" : "falsy"].join(" "));
    return lines.join("\n") + "\n";
}
function onLinear(x, y, z, m) { return ""; }
"#;

#[test]
fn node_runs_regular_expressions_as_postc_does() {
    let Some(_) = node_or_skip("cimco_node") else { return };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let toolpath = corpus().join("toolpaths/cimco/mill.ron");
    let jsonl = dir.path().join("mill.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("export the toolpath");
    let keeps_scripts = format!("{REGEX_POST}function keepsScripts(t) {{ return isFinite(t); }}\n");
    for (name, js, scripts) in [("regex.js", REGEX_POST.to_string(), false), ("regex_scripts.js", keeps_scripts, true)]
    {
        let path = dir.path().join(name);
        std::fs::write(&path, &js).expect("write the post");
        let post = compile(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(!post.scripts.is_empty(), scripts, "{name}: scripts {}", post.scripts.len());
        let postc = post_toolpath(&post, &toolpath).unwrap_or_else(|e| panic!("{name}: {e}"));
        let node = run_node(&path, &jsonl, &[]).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(String::from_utf8_lossy(&postc), String::from_utf8_lossy(&node), "{name}");
        assert_eq!(postc, node, "{name}");
    }
}

/// Posts `toolpaths/cimco/mill.ron` through `post` (compiled from
/// `post_path`) and through Node.js running `post_path`, and requires the
/// same text.
fn assert_posts_as_node(dir: &Path, post_path: &Path, post: &Post) {
    let toolpath = support::corpus().join("toolpaths/cimco/mill.ron");
    let jsonl = dir.join("mill.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("export");
    let ours = post_toolpath(post, &toolpath).expect("postc posts");
    let theirs = run_node(post_path, &jsonl, &[]).expect("Node posts");
    assert_eq!(String::from_utf8_lossy(&theirs), String::from_utf8_lossy(&ours));
}
