//! Posts are code from strangers: text they build has a size budget.
//! A post that doubles a text in an endless loop
//! stops quickly with RT031 at its loop, in bounded memory, and writes no
//! output file: in native CIMCO code, in a CIMCO function that runs as a
//! script, and in VcPost.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

const NATIVE_JS: &str = "var linebreak = \"\\n\";\nfunction onOpen() { return \"%\\n\"; }\nfunction onLinear(x, y, z, feed) {\n  var s = \"x\";\n  while (true) { s = s + s; }\n  return \"G1\\n\";\n}\n";

/// An object table makes `onLinear` a script (run by Rhai): the
/// `isFinite` call keeps the post off the general lowering.
const SCRIPT_JS: &str = "var linebreak = \"\\n\";\nvar seen = {count: 0};\nfunction onOpen() { return \"%\\n\"; }\nfunction onLinear(x, y, z, feed) {\n  var s = \"x\";\n  while (true) { s = s + s; seen.count = s.length; }\n  return \"G1\\n\";\n}\nfunction keepsScripts(t) { return isFinite(t); }\n";

/// The same post lowered whole (no `isFinite` call): native objects.
const GENERAL_JS: &str = "var linebreak = \"\\n\";\nvar seen = {count: 0};\nfunction onOpen() { return \"%\\n\"; }\nfunction onLinear(x, y, z, feed) {\n  var s = \"x\";\n  while (true) { s = s + s; seen.count = s.length; }\n  return \"G1\\n\";\n}\n";

const GROW_VCPOST: &str =
    "Sub GOTO\n  Dim S\n  S = \"x\"\n  Do While True\n    S = S & S\n  Loop\n  Out \"<N> G1<X>\"\nEnd Sub\n";

/// Growing by a little each step: every step copies the whole text, so
/// long text costs steps by its length and the step budget stops it soon.
const SLOW_JS: &str = "var linebreak = \"\\n\";\nfunction onLinear(x, y, z, feed) {\n  var s = \"x\";\n  while (true) { s = s + \"xyz\"; }\n  return \"G1\\n\";\n}\n";

/// Posts `post` (written as `name`) over the standard corpus toolpath with
/// `-o` into a temporary folder, under a 4 GiB address-space limit.
/// Returns the standard error; asserts the run failed quickly and wrote
/// no file.
fn post_fails(name: &str, post: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let post_path = dir.path().join(name);
    std::fs::write(&post_path, post).unwrap();
    let toolpath = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/toolpaths/standard.ron");
    let out = dir.path().join("out.nc");
    let start = Instant::now();
    let run = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 4194304; exec \"$0\" post \"$1\" \"$2\" -o \"$3\"")
        .arg(env!("CARGO_BIN_EXE_postc"))
        .arg(&post_path)
        .arg(&toolpath)
        .arg(&out)
        .output()
        .unwrap();
    let elapsed = start.elapsed();
    let stderr = String::from_utf8_lossy(&run.stderr).into_owned();
    assert_eq!(run.status.code(), Some(1), "{name}: {stderr}");
    assert!(!out.exists(), "{name}: an output file was written");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers.len(), 1, "{name}: files left behind: {leftovers:?}");
    assert!(elapsed < Duration::from_secs(30), "{name}: took {elapsed:?}");
    stderr
}

#[test]
fn native_cimco_text_doubling_stops_at_its_loop() {
    let err = post_fails("double.js", NATIVE_JS);
    assert!(err.contains("error[RT031]") && err.contains("double.js:5:3"), "{err}");
}

#[test]
fn scripted_cimco_text_doubling_stops_at_its_loop() {
    let err = post_fails("double_script.js", SCRIPT_JS);
    assert!(err.contains("error[RT031]") && err.contains("double_script.js:6:3"), "{err}");
}

#[test]
fn cimco_text_doubling_with_objects_stops_at_its_loop() {
    let err = post_fails("double_general.js", GENERAL_JS);
    assert!(err.contains("error[RT031]") && err.contains("double_general.js:6:"), "{err}");
}

#[test]
fn vcpost_text_doubling_stops_at_its_loop() {
    let err = post_fails("double.VcPost", GROW_VCPOST);
    assert!(err.contains("error[RT031]") && err.contains("double.VcPost:4:3"), "{err}");
}

#[test]
fn slowly_growing_text_meets_the_step_budget_soon() {
    let err = post_fails("grow.js", SLOW_JS);
    assert!(err.contains("error[RT002]") && err.contains("grow.js:4:3"), "{err}");
}

#[test]
fn the_scripted_post_really_runs_as_a_script() {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(Path::new("s.js"), SCRIPT_JS.as_bytes(), None, &mut sources);
    let post = compiled.post.unwrap();
    let f = post.functions.iter().find(|f| f.name == "onLinear").unwrap();
    assert!(matches!(f.body, postc_ir::Body::Script(_)));
    let f = postc_driver::compile_post_bytes(Path::new("n.js"), NATIVE_JS.as_bytes(), None, &mut sources).post.unwrap();
    let f = f.functions.iter().find(|f| f.name == "onLinear").unwrap();
    assert!(matches!(f.body, postc_ir::Body::Native(_)));
}
