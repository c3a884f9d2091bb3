//! Issue 14, CIMCO fidelity: modal memory for the whole program and
//! `reset()`, feeds per revolution, the drill header's reference plane,
//! `finally`, NaN in native code, and number-to-text as a JavaScript
//! engine does it. Each case runs under postc and, when `node` is
//! installed, under the Node.js referee host (`tests/node_host/`), and both
//! must print the expected program.

mod cimco_common;

use std::path::Path;

use cimco_common::*;

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
    if node().is_none() {
        eprintln!("cimco_fidelity: `node` is not installed; the Node.js referee is skipped");
        return;
    }
    let jsonl = dir.path().join("job.jsonl");
    export_jsonl(&toolpath, &jsonl).unwrap_or_else(|e| panic!("{e}"));
    let theirs = run_node(&post_path, &jsonl, &[]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(String::from_utf8_lossy(&theirs), expected, "Node.js");
}

fn run_js(js: &str, ron: &str) -> String {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post_path = dir.path().join("post.js");
    let toolpath = dir.path().join("job.ron");
    std::fs::write(&post_path, js).expect("write the post");
    std::fs::write(&toolpath, ron).expect("write the toolpath");
    let post = compile(&post_path).unwrap_or_else(|e| panic!("{e}"));
    String::from_utf8_lossy(&post_toolpath(&post, &toolpath).unwrap_or_else(|e| panic!("{e}"))).into_owned()
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

/// Seed 002: a variable without force "will only be written if it has
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
