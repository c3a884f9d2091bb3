//! The lowering: which functions run natively, the formats and variables
//! made at compile time, the settings read from the Globals (bare and the
//! `globals` object), the handlers' sections, and the lowering's lints.

use std::path::Path;

use postc_ir::{Body, HandlerKey, Modality, PointStyle, Post, Section, SignStyle};

fn compile(js: &str) -> (Post, Vec<postc_ir::Diagnostic>) {
    let mut sources = postc_report::source_map();
    postc_front_cimco::compile(Path::new("t.js"), js.as_bytes(), &mut sources)
}

fn native(post: &Post, name: &str) -> bool {
    post.functions.iter().any(|f| f.name == name && matches!(f.body, Body::Native(_)))
}

fn sections(post: &Post) -> Vec<Section> {
    post.handlers
        .iter()
        .filter_map(|h| match h.key {
            HandlerKey::Section(s) => Some(s),
            _ => None,
        })
        .collect()
}

const MILL: &str = r#"
var linebreak = "\r\n";
var tolerance = 0.05;
var useRadius = false;
var xyz = createFormat({decimals: 3, forceDecimal: true, forceSign: true, prefix: ""});
var xOut = createVariable({prefix: "X"}, xyz);
var fOut = createVariable({prefix: "F", force: true}, createFormat({decimals: 0}));
var words = [];
function writeBlock(t) { return t + linebreak; }
function onLinear(x, y, z, m) { return writeBlock("G1" + xOut.format(x) + getFeedrate(m)); }
function onCircular(cx, cy, cz, ex, ey, ez, cw, m) { return writeBlock((cw ? "G2" : "G3") + xOut.format(ex)); }
function onOpen(c) { words.push("%"); return words.join(""); }
function keepsScripts(t) { return isFinite(t); }
"#;

#[test]
fn formats_variables_and_settings() {
    let (post, diags) = compile(MILL);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(post.options.line_ending, b"\r\n");
    assert_eq!(post.options.arc_tolerance, 0.05);
    let x = post.variables.iter().find(|v| v.name == "xOut").expect("xOut");
    assert_eq!(x.prefix, b"X");
    assert_eq!(x.modality, Modality::OnChange);
    let f = &post.formats[x.format.index()];
    assert_eq!((f.decimals, f.point, f.trim_zeros, f.sign), (3, PointStyle::Always, false, SignStyle::Always));
    let fo = post.variables.iter().find(|v| v.name == "fOut").expect("fOut");
    assert_eq!(fo.modality, Modality::Always);
    assert!(post.formats[fo.format.index()].trim_zeros);
}

#[test]
fn plain_functions_are_native_and_object_users_are_scripts() {
    let (post, _) = compile(MILL);
    assert!(native(&post, "onLinear") && native(&post, "onCircular") && native(&post, "writeBlock"));
    assert!(!native(&post, "onOpen"), "onOpen uses an array");
    assert_eq!(post.scripts.len(), 1);
    assert!(post.scripts[0].source.contains("fn js_onOpen(") && post.scripts[0].source.contains("fn js_onLinear("));
    assert!(!post.scripts[0].span_map.is_empty());
}

#[test]
fn entry_points_occupy_their_sections() {
    let (post, _) = compile(MILL);
    let s = sections(&post);
    for want in [
        Section::Header,
        Section::RapidMove,
        Section::FeedMove,
        Section::PlungeMove,
        Section::CwArcMove,
        Section::CcwArcMove,
        Section::CwHelicalArcMove,
    ] {
        assert!(s.contains(&want), "{want:?} missing from {s:?}");
    }
    for absent in [
        Section::FirstFeedMove,
        Section::RetractMove,
        Section::InitialRapidMove,
        Section::DrillHeader,
        Section::CutterComp,
    ] {
        assert!(!s.contains(&absent), "{absent:?} should be left to the fallbacks");
    }
    assert!(!post.options.lathe);
}

#[test]
fn the_globals_object_and_a_lathe() {
    let (post, diags) = compile(
        r#"
        globals = { linebreak: "\n", decimalMark: ",", xDiameterProg: true };
        PostInfo = { title: "Lathe", author: "me", type: POST_TYPE_TURN };
        var x = createVariable({prefix: "X"}, createFormat({decimals: 3, scale: globals.xDiameterProg ? 2 : 1}));
        function onLinear(vx, vz, m) { return "G1" + x.format(vx) + globals.linebreak; }
        "#,
    );
    assert!(diags.is_empty(), "{diags:?}");
    assert!(post.options.lathe);
    assert_eq!(post.info.name, "Lathe");
    let f = &post.formats[post.variables[0].format.index()];
    assert_eq!((f.multiplier, f.decimal_mark), (2.0, ','));
    assert!(native(&post, "onLinear"));
}

#[test]
fn lints_name_what_is_wrong() {
    let (_, diags) = compile(
        r#"
        var f = createFormat({decimals: 2, roundTo: 5});
        function onLinear(x, y, z, m) { return undefinedThing(x); }
        function helper() {}
        function other() { helper = 1; }
        "#,
    );
    let codes: Vec<&str> = diags.iter().map(|d| d.code).collect();
    assert!(codes.contains(&"JS101"), "{codes:?}");
    assert!(codes.contains(&"JS102"), "{codes:?}");
    assert!(codes.contains(&"JS106"), "{codes:?}");
}

#[test]
fn every_fixture_lowers_to_a_script_that_compiles() {
    for dir in ["tests/fixtures/valid", "../../corpus/posts/cimco"] {
        for e in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(dir)).expect("fixtures").flatten() {
            let text = std::fs::read_to_string(e.path()).expect("a post");
            let (_, diags) = compile(&text);
            assert!(!diags.iter().any(|d| d.code == "JS100"), "{}: {diags:?}", e.path().display());
        }
    }
}

/// The JavaScript of field posts lowers to native IR. Each
/// lowering fires on the shape it handles and leaves anything else to the
/// script, which says why. (`tests/cimco_native.rs` posts both under
/// postc and Node.js.)
const FIELD: &str = r#"
var linebreak = "\n";
var codes = {1: "G02", 0: "G03"};
var changed = {a: "A"};
function writeBlock() {
    var words = [];
    for (var i = 0; i < arguments.length; ++i) {
        if (arguments[i] != "") { words.push(arguments[i]); }
    }
    return words.join(" ") + linebreak;
}
function forward() { return writeBlock.apply(null, arguments); }
function literal(a) { return writeBlock.apply(null, [a, "B"]); }
function dynamicApply(a) { var w = [a]; if (a) { w.push("C"); } return writeBlock.apply(null, w); }
function growApply(a) { var w = [a]; while (w.length < 3) { w.push("x"); } return writeBlock.apply(null, w); }
function argsValue() { var a = arguments; return a.length; }
function table(k) { return codes[k] + codes.x; }
function changes() { changed.a = "B"; return changed.a; }
function indexedArray() { var w = ["a"]; return w[0]; }
function fallthrough(n) { var s = ""; switch (n) { case 1: s += "1"; default: s += "d"; } return s; }
function forIn() { var s = ""; for (var k in codes) { s += k; } return s; }
function forInContinue() { var s = ""; for (var k in codes) { if (k == "1") continue; s += k; } return s; }
function onOpen(c) { return writeBlock("a", "b") + forward("x") + literal("y") + dynamicApply("z") + argsValue(1, 2); }
function onLinear(x, y, z, m) { return writeBlock("G1", "X" + x); }
function keepsScripts(t) { return isFinite(t); }
"#;

fn why(post: &Post, name: &str) -> String {
    post.functions
        .iter()
        .filter(|f| f.name == name)
        .filter_map(|f| f.why_script.as_ref().map(|w| w.what.clone()))
        .next()
        .unwrap_or_default()
}

#[test]
fn field_style_javascript_lowers_to_native_ir() {
    let (post, diags) = compile(FIELD);
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
    // Variadic functions: one form per number of arguments.
    for f in ["writeBlock", "writeBlock/1", "writeBlock/2", "forward", "forward/1", "literal", "onOpen", "onLinear"] {
        assert!(native(&post, f), "{f}: {}", why(&post, f));
    }
    // Tables, fallthrough, for-in, arrays kept in slots (read by index,
    // handed to `apply` with a length the lowering follows).
    for f in ["table", "fallthrough", "forIn", "dynamicApply", "indexedArray"] {
        assert!(native(&post, f), "{f}: {}", why(&post, f));
    }
    // Does not fire: an array filled in a loop the lowering cannot bound,
    // `arguments` as a value, a table that changes, `continue` in a for-in.
    assert!(!native(&post, "growApply"));
    assert!(
        why(&post, "growApply").contains("adds to array `w` in a loop whose passes postc cannot count"),
        "{}",
        why(&post, "growApply")
    );
    assert!(!native(&post, "argsValue"));
    assert!(why(&post, "argsValue").contains("uses `arguments` other than"), "{}", why(&post, "argsValue"));
    assert!(!native(&post, "changes"));
    assert!(!native(&post, "forInContinue"));
    assert!(
        why(&post, "forInContinue").contains("`continue` in a `for ... in` loop"),
        "{}",
        why(&post, "forInContinue")
    );
}

#[test]
fn entry_points_that_read_arguments_stay_scripts() {
    let (post, _) = compile(
        "function onLinear() { return arguments[0] + \"\\n\"; }\nfunction keepsScripts(t) { return isFinite(t); }\n",
    );
    assert!(!native(&post, "onLinear"));
    assert!(why(&post, "onLinear").contains("is an entry point postc calls"), "{}", why(&post, "onLinear"));
}

/// Without the `isFinite` call, the general lowering takes the field
/// post whole: every function native, no script.
#[test]
fn the_field_post_without_a_host_call_lowers_whole() {
    let text = FIELD.replace("function keepsScripts(t) { return isFinite(t); }\n", "");
    let (post, diags) = compile(&text);
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
    assert!(post.scripts.is_empty());
    for f in ["growApply", "argsValue", "changes", "forInContinue", "onOpen", "onLinear"] {
        assert!(native(&post, f), "{f}: {}", why(&post, f));
    }
}

/// A comment with a lone carriage return (which `str::lines` keeps) is two
/// comment lines: the IR is valid and the post compiles (the mutation
/// fuzzer's case, IR002 with no position).
#[test]
fn a_lone_carriage_return_in_a_comment_makes_two_lines() {
    let (post, diags) = compile("// first\rsecond\nfunction onLinear(x, y, z, m) { return \"\"; }\n");
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{diags:?}");
    assert!(post.comments.iter().all(|c| c.lines.iter().all(|l| !l.contains(['\n', '\r']))), "{:?}", post.comments);
}
