//! Differential testing of postc's JavaScript engine against Node.js: a
//! proptest strategy writes small CIMCO posts of the constructs real posts
//! use (docs/cimco.md, *Differential testing against Node.js*), and each
//! runs three ways over one tiny toolpath: prepared (as `postc post`
//! runs it), unprepared (`RunOptions::unprepared`, the IR as it is), and
//! under Node.js with the referee host of `tests/node_host/`. The three
//! programs must be byte for byte the same, or all three runs must fail
//! (a JavaScript error: postc stops with a diagnostic, Node.js throws). A
//! post postc refuses when it compiles is counted by its code.
//!
//! The programs come from a fixed list of seeds, so a run is repeatable:
//! `POSTC_DIFF_PROGRAMS` sets how many (2,000 by default),
//! `POSTC_DIFF_SEED` the base seed, and `POSTC_DIFF_CASE=K` runs only
//! program K. Node.js runs them all in one process (`batch.js`). A
//! program that differs is shrunk (proptest's simplification, each
//! candidate checked again three ways) and reported with its three
//! outputs; both forms are kept in `CARGO_TARGET_TMPDIR` to replay (the
//! program as made for every one that differs).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::strategy::{Union, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::support::cimco::*;
use crate::support::{lines, show};

/// Constructs the generator leaves out because postc and Node.js
/// disagree on them and the fix is not local; each says what diverges
/// and where. The generator consults [`excluded`].
pub const EXCLUSIONS: &[(&str, &str)] = &[(
    "Math.pow",
    "V8 computes `Math.pow` with its own port of fdlibm, which differs from Rust's `powf` (the C library's `pow`) \
         in the last digit for some operands: `Math.pow(1000, -7) * 0.1` is 1.0000000000000002e-22 in Node.js and \
         9.999999999999999e-23 in postc (ir/src/js.rs, `math_pow`)",
)];

fn excluded(name: &str) -> bool {
    EXCLUSIONS.iter().any(|(n, _)| *n == name)
}

/// The toolpath every program posts: one tool, a rapid, a plunge and
/// three feeds (one with its own feed rate).
const TOOLPATH: &str = r#"Job(units: Mm, home: (x: 0, y: 0, z: 25), safe_z: 5)
Tool(number: 1, name: "T1 6mm", diameter: 6, spindle_speed: 10000, cut_feed: 1000, plunge_feed: 300)
ToolpathStart(name: "P")
Rapid(x: 1.5, y: 2, z: 5)
Feed(x: 1.5, y: 2, z: -1, intent: Plunge)
Feed(x: 10.25, y: -3.125, z: -1)
Feed(x: 0.1, y: 0.2, z: -1, feed: 250.5)
Feed(x: -7, y: 1e-7, z: 0.30000000000000004)
ToolpathEnd
End
"#;

// ---------------------------------------------------------------------
// The generator

const NUMBERS: &[&str] = &[
    "0", "1", "2", "3", "-1", "7", "10", "0.5", "1.5", "-2.5", "0.1", "0.2", "1e21", "1e-7", "123.456", "-0", "255",
    "2.675", "1.005", "100000", "0.000001", "12", "-3",
];
const TEXTS: &[&str] = &[
    r#""""#,
    r#""0x10""#,
    r#"" 12 ""#,
    r#""1e3""#,
    r#""inf""#,
    r#""-0""#,
    r#""abc""#,
    r#""G1""#,
    r#""3.5""#,
    r#""Infinity""#,
    r#""10""#,
    r#""a,b""#,
    r#""1""#,
];
const OTHERS: &[&str] = &["true", "false", "null", "undefined", "NaN", "Infinity", "-Infinity"];

const BINARY: &[&str] =
    &["+", "+", "+", "-", "*", "/", "%", "<", ">", "<=", ">=", "==", "===", "!=", "!==", "&&", "||"];
const UNARY: &[&str] = &["-", "!", "typeof", "+"];
const MATH1: &[&str] = &["floor", "ceil", "round", "abs", "sqrt"];
const MATH2: &[&str] = &["max", "min", "pow"];
const CONVERSIONS: &[&str] = &["parseFloat", "parseInt", "Number", "String", "isNaN", "Number", "String"];
const TEXT_METHODS: &[&str] = &[
    ".substring(1, 3)",
    ".substring(2)",
    ".substring(3, 1)",
    r#".indexOf("1")"#,
    r#".indexOf("")"#,
    ".charAt(0)",
    ".charAt(2)",
    ".toUpperCase()",
    r#".replace("1", "x")"#,
    r#".replace("n", "N")"#,
    ".length",
];
const READS: &[&str] = &["state.p", "state.q", r#"state["2"]"#, "table[1]", "table[5]", "table.length"];

/// What a function's code may name.
#[derive(Clone, Copy)]
struct Scope {
    /// Parameters, locals and globals holding plain values.
    names: &'static [&'static str],
    /// The post's functions it may call.
    calls: &'static [&'static str],
    /// Whether it may read `arguments`.
    arguments: bool,
}

fn pick(list: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::sample::select(list).prop_map(String::from).boxed()
}

fn literal() -> BoxedStrategy<String> {
    let others: Vec<&'static str> = OTHERS.iter().copied().filter(|o| !excluded(o)).collect();
    prop_oneof![3 => pick(NUMBERS), 2 => pick(TEXTS), 2 => prop::sample::select(others).prop_map(String::from)].boxed()
}

/// A two-argument `Math` function.
fn math2() -> BoxedStrategy<String> {
    let names: Vec<&'static str> = MATH2.iter().copied().filter(|f| !excluded(&format!("Math.{f}"))).collect();
    prop::sample::select(names).prop_map(String::from).boxed()
}

/// An expression of any type.
fn expr(scope: Scope) -> BoxedStrategy<String> {
    let mut leaves = vec![(3, literal()), (3, pick(scope.names)), (1, pick(READS))];
    if scope.arguments {
        leaves.push((1, pick(&["arguments.length", "arguments[0]", "arguments[1]", "arguments[2]"])));
    }
    let leaf = Union::new_weighted(leaves).boxed();
    leaf.prop_recursive(3, 16, 3, move |inner| {
        let e = || inner.clone();
        let mut arms: Vec<(u32, BoxedStrategy<String>)> = vec![
            (6, (e(), pick(BINARY), e()).prop_map(|(a, op, b)| format!("({a} {op} {b})")).boxed()),
            (2, (pick(UNARY), e()).prop_map(|(op, a)| format!("({op} {a})")).boxed()),
            (2, (e(), e(), e()).prop_map(|(c, a, b)| format!("({c} ? {a} : {b})")).boxed()),
            (1, (pick(MATH1), e()).prop_map(|(f, a)| format!("Math.{f}({a})")).boxed()),
            (1, (math2(), e(), e()).prop_map(|(f, a, b)| format!("Math.{f}({a}, {b})")).boxed()),
            (2, (pick(CONVERSIONS), e()).prop_map(|(f, a)| format!("{f}({a})")).boxed()),
            (1, e().prop_map(|a| format!("parseInt({a}, 16)")).boxed()),
            (1, (e(), 0..4u8).prop_map(|(a, d)| format!("Number({a}).toFixed({d})")).boxed()),
            (2, (e(), pick(TEXT_METHODS)).prop_map(|(a, m)| format!("String({a}){m}")).boxed()),
            (1, (e(), e()).prop_map(|(a, b)| format!(r#"[{a}, {b}].join("/")"#)).boxed()),
            (1, e().prop_map(|a| format!("table[{a}]")).boxed()),
        ];
        if !scope.calls.is_empty() {
            let call = (pick(scope.calls), prop::collection::vec(e(), 0..=3))
                .prop_map(|(f, args)| format!("{f}({})", args.join(", ")));
            arms.push((2, call.boxed()));
        }
        Union::new_weighted(arms)
    })
    .boxed()
}

/// A number, mostly: what a post gives a format.
fn number(scope: Scope) -> BoxedStrategy<String> {
    let names: Vec<&'static str> = scope.names.iter().copied().filter(|n| ["x", "y", "z", "p"].contains(n)).collect();
    let leaf = if names.is_empty() {
        pick(NUMBERS)
    } else {
        prop_oneof![pick(NUMBERS), prop::sample::select(names).prop_map(String::from)].boxed()
    };
    let num = leaf.prop_recursive(2, 6, 2, |inner| {
        prop_oneof![
            (inner.clone(), pick(&["+", "-", "*", "/"]), inner.clone())
                .prop_map(|(a, op, b)| format!("({a} {op} {b})")),
            (pick(MATH1), inner.clone()).prop_map(|(f, a)| format!("Math.{f}({a})")),
        ]
    });
    prop_oneof![8 => num, 1 => expr(scope)].boxed()
}

fn indent(body: &str) -> String {
    body.lines().map(|l| format!("    {l}\n")).collect()
}

fn print(e: String) -> String {
    format!("out += writeln(\"= \" + {e});\n")
}

/// A statement without nested statements.
fn simple(scope: Scope) -> BoxedStrategy<String> {
    let e = || expr(scope);
    let targets = pick(&["a", "b", "g0", "g1", "state.p", "state.q", "state.r", "table[0]", r#"state["2"]"#]);
    let closure_scope = Scope { names: &["v", "v", "g0"], calls: &[], arguments: false };
    let arms: Vec<(u32, BoxedStrategy<String>)> = vec![
        (6, e().prop_map(print).boxed()),
        (
            2,
            (pick(&["xOut", "yOut"]), number(scope), pick(&["fmtA", "fmtB"]), number(scope))
                .prop_map(|(v, a, f, b)| format!("out += writeBlock(\"G1\", {v}.format({a}), {f}.format({b}));\n"))
                .boxed(),
        ),
        (4, (targets, pick(&["=", "=", "+="]), e()).prop_map(|(t, op, v)| format!("{t} {op} {v};\n")).boxed()),
        (1, pick(&["a++;\n", "b--;\n", "g1++;\n"])),
        (1, e().prop_map(|v| format!("table.push({v});\n")).boxed()),
        (
            1,
            (expr(closure_scope), e())
                .prop_map(|(body, arg)| {
                    format!("var h = function (v) {{\n    return {body};\n}};\n{}", print(format!("h({arg})")))
                })
                .boxed(),
        ),
        (
            1,
            (e(), e(), e())
                .prop_map(|(p, q, r)| {
                    format!(
                        "var o = {{p: {p}, \"1\": {q}}};\no.p = {r};\nfor (var k in o) {{\n    out += writeln(k + \"=\" + o[k]);\n}}\n"
                    )
                })
                .boxed(),
        ),
        (
            1,
            (e(), e(), e())
                .prop_map(|(p, q, r)| {
                    format!(
                        "var arr = [{p}, {q}];\narr.push({r});\n{}",
                        print("arr.join(\",\") + \" \" + arr.length + \" \" + arr[0]".into())
                    )
                })
                .boxed(),
        ),
        (1, Just("for (var k in state) {\n    out += writeln(k + \":\" + state[k]);\n}\n".to_string()).boxed()),
    ];
    Union::new_weighted(arms).boxed()
}

/// One to `most` statements at nesting `level` (0: no nested statements).
fn block(scope: Scope, level: u8, most: usize) -> BoxedStrategy<String> {
    prop::collection::vec(statement(scope, level), 1..=most).prop_map(|s| s.concat()).boxed()
}

fn statement(scope: Scope, level: u8) -> BoxedStrategy<String> {
    if level == 0 {
        return simple(scope);
    }
    let i = if level >= 2 { "i" } else { "j" };
    let body = || block(scope, level - 1, 2);
    let e = || expr(scope);
    let leave = prop::option::of((e(), pick(&["break", "continue"])));
    let for_loop = (0..4u8, body(), leave.clone()).prop_map(move |(n, b, leave)| {
        let exit = leave.map(|(c, w)| format!("if ({c}) {{\n    {w};\n}}\n")).unwrap_or_default();
        format!("for (var {i} = 0; {i} < {n}; {i}++) {{\n{}}}\n", indent(&format!("{b}{exit}")))
    });
    let breaks = prop::option::of(e());
    let while_loop = (0..4u8, body(), breaks.clone()).prop_map(move |(n, b, leave)| {
        let exit = leave.map(|c| format!("if ({c}) {{\n    break;\n}}\n")).unwrap_or_default();
        format!("{i} = 0;\nwhile ({i} < {n}) {{\n{}}}\n", indent(&format!("{b}{exit}{i}++;\n")))
    });
    let do_loop = (1..4u8, body(), breaks).prop_map(move |(n, b, leave)| {
        let exit = leave.map(|c| format!("if ({c}) {{\n    break;\n}}\n")).unwrap_or_default();
        format!("{i} = 0;\ndo {{\n{}}} while ({i} < {n});\n", indent(&format!("{b}{exit}{i}++;\n")))
    });
    let if_else = (e(), body(), prop::option::of(body())).prop_map(|(c, a, b)| match b {
        Some(b) => format!("if ({c}) {{\n{}}} else {{\n{}}}\n", indent(&a), indent(&b)),
        None => format!("if ({c}) {{\n{}}}\n", indent(&a)),
    });
    let case = (literal(), body(), any::<bool>());
    let switch = (e(), prop::collection::vec(case, 1..=3), prop::option::of((0..3usize, body()))).prop_map(
        |(d, cases, default)| {
            let mut arms: Vec<String> = cases
                .into_iter()
                .map(|(l, b, brk)| format!("case {l}:\n{}", indent(&(b + if brk { "break;\n" } else { "" }))))
                .collect();
            if let Some((at, b)) = default {
                arms.insert(at.min(arms.len()), format!("default:\n{}", indent(&b)));
            }
            format!("switch ({d}) {{\n{}}}\n", indent(&arms.concat()))
        },
    );
    let try_catch = (body(), prop::option::of(e()), prop::option::of(body())).prop_map(|(b, throw, fin)| {
        let throw = throw.map(|t| format!("throw {t};\n")).unwrap_or_default();
        let caught = "out += writeln(\"caught \" + (typeof err === \"object\" ? \"an error\" : err));\n";
        let fin = fin.map(|f| format!(" finally {{\n{}}}", indent(&f))).unwrap_or_default();
        format!("try {{\n{}}} catch (err) {{\n{}}}{fin}\n", indent(&format!("{b}{throw}")), indent(caught))
    });
    prop_oneof![
        8 => simple(scope),
        2 => if_else,
        1 => for_loop,
        1 => while_loop,
        1 => do_loop,
        1 => switch,
        1 => try_catch,
    ]
    .boxed()
}

const LOCALS: &str = "a = {}, b = {}, i = 0, j = 0";

fn locals(a: &str, b: &str) -> String {
    LOCALS.replacen("{}", a, 1).replacen("{}", b, 1)
}

const HELPER: Scope = Scope { names: &["p", "q", "a", "b", "g0", "g1", "i", "j"], calls: &[], arguments: true };
const HELPER2: Scope = Scope { names: &["p", "q", "a", "b", "g0", "g1", "i", "j"], calls: &["f1"], arguments: true };
const OPEN: Scope = Scope { names: &["a", "b", "g0", "g1", "i", "j"], calls: &["f1", "f2"], arguments: false };
const LINEAR: Scope = Scope {
    names: &["x", "y", "z", "movement", "a", "b", "g0", "g1", "i", "j"],
    calls: &["f1", "f2"],
    arguments: false,
};

fn helper(name: &'static str, scope: Scope) -> BoxedStrategy<String> {
    (literal(), literal(), block(scope, 1, 3), expr(scope), any::<bool>())
        .prop_map(move |(a, b, body, ret, text)| {
            let ret = if text { format!("out + {ret}") } else { ret };
            format!(
                "function {name}(p, q) {{\n    var out = \"\", {};\n{}    return {ret};\n}}\n",
                locals(&a, &b),
                indent(&body)
            )
        })
        .boxed()
}

fn handler(head: &'static str, scope: Scope, tail: &'static str) -> BoxedStrategy<String> {
    (literal(), literal(), block(scope, 2, 4))
        .prop_map(move |(a, b, body)| {
            format!(
                "function {head} {{\n    var out = \"\", {};\n{}{tail}    return out;\n}}\n",
                locals(&a, &b),
                indent(&body)
            )
        })
        .boxed()
}

fn format_props() -> BoxedStrategy<String> {
    (0..5u8, any::<bool>(), any::<bool>(), 0..4u8, any::<bool>(), pick(&["1", "1", "2", "0.5"]))
        .prop_map(|(decimals, force_decimal, force_sign, width, zeropad, scale)| {
            format!(
                "{{decimals: {decimals}, forceDecimal: {force_decimal}, forceSign: {force_sign}, width: {width}, zeropad: {zeropad}, scale: {scale}}}"
            )
        })
        .boxed()
}

const SCRIPT_TIER: &str = "\nfunction scriptTier(t) {\n    return isFinite(t);\n}\n";

/// A whole post.
fn post() -> BoxedStrategy<String> {
    let head = (
        literal(),
        literal(),
        (literal(), literal(), literal()),
        (literal(), literal(), literal()),
        pick(&[".", ".", ","]),
        format_props(),
        format_props(),
        any::<bool>(),
    )
        .prop_map(|(g0, g1, (p, q, two), (t0, t1, t2), mark, fa, fb, force)| {
            format!(
                r#"var decimalMark = "{mark}";
var g0 = {g0};
var g1 = {g1};
var state = {{p: {p}, q: {q}, "2": {two}}};
var table = [{t0}, {t1}, {t2}];
var fmtA = createFormat({fa});
var fmtB = createFormat({fb});
var xOut = createVariable({{prefix: "X", force: {force}}}, fmtA);
var yOut = createVariable({{prefix: "Y"}}, fmtB);
var zFormat = createFormat({{decimals: 3, forceDecimal: true}});

function writeln(text) {{
    return text + "\n";
}}

function writeBlock() {{
    var words = [];
    for (var i = 0; i < arguments.length; i++) {{
        if (arguments[i] !== "") {{
            words.push(arguments[i]);
        }}
    }}
    return words.join(" ") + "\n";
}}

"#
            )
        });
    let last = "    out += writeBlock(\"G1\", xOut.format(x), yOut.format(y), \"Z\" + zFormat.format(z), getFeedrate(movement));\n";
    // One post in five has a function that calls `isFinite`, which has no
    // native form: the post keeps the shaped lowering, and what that
    // cannot hold runs in the Rhai script tier.
    let tier = prop_oneof![4 => Just(String::new()), 1 => Just(SCRIPT_TIER.to_string())];
    (
        (head, tier),
        helper("f1", HELPER),
        helper("f2", HELPER2),
        handler("onOpen(isClipboard)", OPEN, ""),
        handler("onLinear(x, y, z, movement)", LINEAR, last),
        handler("onClose()", OPEN, ""),
    )
        .prop_map(|((h, tier), f1, f2, open, linear, close)| format!("{h}{f1}\n{f2}\n{open}\n{linear}\n{close}{tier}"))
        .boxed()
}

// ---------------------------------------------------------------------
// Running a program three ways

/// What one engine did with a program.
#[derive(Clone, Debug, PartialEq)]
enum Run {
    Printed(Vec<u8>),
    /// A runtime error: the diagnostic's code and message, or Node's error.
    Failed(String),
}

fn short(run: &Run) -> String {
    match run {
        Run::Printed(p) => format!("printed {} bytes", p.len()),
        Run::Failed(e) => e.lines().next().unwrap_or("").chars().take(160).collect(),
    }
}

impl Run {
    fn show(&self) -> String {
        match self {
            Run::Printed(p) => format!("printed {} bytes:\n{}", p.len(), String::from_utf8_lossy(p)),
            Run::Failed(e) => format!("failed: {e}"),
        }
    }
}

/// What postc did with a program.
enum Postc {
    /// Refused when compiled: the error codes.
    Refused(Vec<&'static str>),
    Ran {
        prepared: Run,
        unprepared: Run,
        scripts: bool,
    },
}

fn postc_runs(path: &Path, toolpath: &Path) -> Postc {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    let errors: Vec<&'static str> =
        compiled.diagnostics.iter().filter(|d| d.severity == postc_ir::Severity::Error).map(|d| d.code).collect();
    let Some(post) = compiled.post.filter(|_| errors.is_empty()) else { return Postc::Refused(errors) };
    let run = |unprepared: bool| {
        let mut sources = postc_report::source_map();
        let mut source = postc_driver::open_toolpath(toolpath, &mut sources).expect("the toolpath opens");
        let mut options = postc_driver::run_options(&post);
        options.unprepared = unprepared;
        match postc_runtime::run(&post, &mut source, postc_runtime::output::Output::memory(), options) {
            Ok(report) => match report.output {
                postc_runtime::output::Finished::Memory(parts) => Run::Printed(parts.concat()),
                _ => Run::Failed("not in memory".into()),
            },
            Err(d) => Run::Failed(d.iter().map(|d| format!("{} {}", d.code, d.message)).collect::<Vec<_>>().join("; ")),
        }
    };
    let (prepared, unprepared) = (run(false), run(true));
    Postc::Ran { prepared, unprepared, scripts: !script_functions(&post).0.is_empty() }
}

/// A runtime error of postc that is a JavaScript error (what Node.js
/// throws for), not a postc bug or limit.
fn javascript_error(run: &Run) -> bool {
    match run {
        Run::Failed(e) => !e.starts_with("RT022"),
        Run::Printed(_) => false,
    }
}

/// How the three runs disagree, if they do: a short name of the kind.
fn disagreement(prepared: &Run, unprepared: &Run, node: &Run) -> Option<&'static str> {
    let same = |a: &Run, b: &Run| match (a, b) {
        (Run::Printed(x), Run::Printed(y)) => x == y,
        (Run::Failed(x), Run::Failed(y)) => x.get(..5) == y.get(..5),
        _ => false,
    };
    if !same(prepared, unprepared) {
        return Some("prepared and unprepared differ");
    }
    match (prepared, node) {
        (Run::Printed(x), Run::Printed(y)) if x == y => None,
        (Run::Printed(_), Run::Printed(_)) => Some("postc and Node.js print differently"),
        (Run::Failed(_), Run::Failed(_)) if javascript_error(prepared) => None,
        // postc's documented budget (docs/cimco.md, "Size budgets"): a text
        // past 16 MiB stops the post, where Node.js has no such limit.
        (Run::Failed(e), Run::Printed(y)) if e.starts_with("RT031") && y.len() > 16 << 20 => None,
        (Run::Failed(_), _) => Some("postc fails where Node.js does not"),
        (_, Run::Failed(_)) => Some("Node.js fails where postc does not"),
    }
}

fn node_run(js: &Path, jsonl: &Path) -> Run {
    match run_node(js, jsonl, &[]) {
        Ok(out) => Run::Printed(out),
        Err(e) => Run::Failed(e),
    }
}

/// The batch's answer for one post.
fn node_batch_result(js: &Path) -> Run {
    let with = |ext: &str| PathBuf::from(format!("{}.{ext}", js.display()));
    match std::fs::read(with("out")) {
        Ok(out) => Run::Printed(out),
        Err(_) => Run::Failed(std::fs::read_to_string(with("err")).unwrap_or_else(|_| "no answer".into())),
    }
}

/// The three runs of one program: its kind of disagreement, or None.
fn check_one(js: &Path, ron: &Path, jsonl: &Path) -> Option<(&'static str, String)> {
    let Postc::Ran { prepared, unprepared, .. } = postc_runs(js, ron) else { return None };
    let node = node_run(js, jsonl);
    disagreement(&prepared, &unprepared, &node).map(|kind| {
        (kind, format!("prepared {}\n\nunprepared {}\n\nNode.js {}", prepared.show(), unprepared.show(), node.show()))
    })
}

fn env_number(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// The runner whose random numbers make program `k` of base seed `seed`.
fn runner(seed: u64, k: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&k.to_le_bytes());
    TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes))
}

/// Shrinks a program that disagrees to a smaller one that disagrees the
/// same way (proptest's simplification, each candidate run three ways).
fn shrink(
    tree: &mut impl ValueTree<Value = String>,
    kind: &str,
    dir: &Path,
    ron: &Path,
    jsonl: &Path,
) -> (String, String) {
    let js = dir.join("shrinking.js");
    let mut best = (tree.current(), String::new());
    let started = Instant::now();
    let mut steps = 0;
    let check = |text: &str| {
        std::fs::write(&js, text).expect("write the candidate");
        check_one(&js, ron, jsonl)
    };
    if let Some((_, outputs)) = check(&best.0) {
        best.1 = outputs;
    }
    let mut more = tree.simplify();
    while more && steps < 150 && started.elapsed() < Duration::from_secs(40) {
        steps += 1;
        let candidate = tree.current();
        match check(&candidate) {
            Some((k, outputs)) if k == kind => {
                best = (candidate, outputs);
                more = tree.simplify();
            }
            _ => more = tree.complicate(),
        }
    }
    best
}

#[test]
fn generated_posts_print_as_node_prints() {
    let Some(version) = node_or_skip("cimco_differential") else { return };
    let seed = env_number("POSTC_DIFF_SEED", 2026);
    let only = std::env::var("POSTC_DIFF_CASE").ok().and_then(|v| v.parse::<u64>().ok());
    let count = env_number("POSTC_DIFF_PROGRAMS", 2000);
    let cases: Vec<u64> = match only {
        Some(k) => vec![k],
        None => (0..count).collect(),
    };
    let started = Instant::now();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let ron = dir.path().join("toolpath.ron");
    std::fs::write(&ron, TOOLPATH).expect("write the toolpath");
    let jsonl = dir.path().join("toolpath.jsonl");
    export_jsonl(&ron, &jsonl).expect("export the toolpath");

    let strategy = post();
    let mut paths = Vec::new();
    for &k in &cases {
        let text = strategy.new_tree(&mut runner(seed, k)).expect("a program").current();
        let path = dir.path().join(format!("p{k}.js"));
        std::fs::write(&path, text).expect("write the program");
        paths.push(path);
    }
    let list = dir.path().join("posts.txt");
    std::fs::write(&list, paths.iter().map(|p| format!("{}\n", p.display())).collect::<String>()).expect("list");
    let batch = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/batch.js");
    let node = node_command().arg(&batch).arg(&list).arg(&jsonl).spawn().expect("start node");

    // postc's runs, on as many threads as there are cores, while Node.js
    // runs the batch.
    let workers = std::thread::available_parallelism().map_or(1, |n| n.get()).min(8);
    let chunk = paths.len().div_ceil(workers).max(1);
    let results: Vec<Postc> = std::thread::scope(|s| {
        let handles: Vec<_> = paths
            .chunks(chunk)
            .map(|part| s.spawn(|| part.iter().map(|p| postc_runs(p, &ron)).collect::<Vec<_>>()))
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("a postc worker")).collect()
    });
    let mut ran = Vec::new();
    let mut refused: BTreeMap<&'static str, usize> = BTreeMap::new();
    for ((&k, path), result) in cases.iter().zip(&paths).zip(results) {
        match result {
            Postc::Refused(codes) => *refused.entry(codes.first().copied().unwrap_or("no post")).or_default() += 1,
            Postc::Ran { prepared, unprepared, scripts } => ran.push((k, path, prepared, unprepared, scripts)),
        }
    }
    let out = node.wait_with_output().expect("node ran");
    assert!(out.status.success(), "node batch.js failed: {}", String::from_utf8_lossy(&out.stderr));

    let (mut printed, mut scripts) = (0, 0);
    let mut failed: BTreeMap<String, usize> = BTreeMap::new();
    let mut differ = Vec::new();
    let mut first_lines = String::new();
    for (k, path, prepared, unprepared, script) in ran {
        let node = node_batch_result(path);
        scripts += usize::from(script);
        match disagreement(&prepared, &unprepared, &node) {
            None => match &prepared {
                Run::Printed(_) => printed += 1,
                Run::Failed(e) => *failed.entry(e.chars().take(5).collect()).or_default() += 1,
            },
            Some(kind) => {
                if let (Run::Printed(x), Run::Printed(y)) = (&prepared, &node) {
                    let at = lines(x).iter().zip(lines(y)).find(|(a, b)| **a != *b).map(|(a, b)| (show(a), show(b)));
                    let _ = writeln!(first_lines, "  {k}: postc {:?}", at);
                } else {
                    let _ = writeln!(first_lines, "  {k}: postc {} / Node.js {}", short(&prepared), short(&node));
                }
                differ.push((k, kind))
            }
        }
    }
    let failed_count: usize = failed.values().sum();
    eprintln!(
        "cimco_differential: Node.js {version}, seed {seed}: {} programs in {:.1} s: {printed} print the same, {failed_count} fail in all three runs ({failed:?}), {} differ, refused when compiled: {refused:?}; {scripts} keep script functions\n{first_lines}",
        cases.len(),
        started.elapsed().as_secs_f64(),
        differ.len()
    );
    if differ.is_empty() {
        // A run where every program fails compares nothing.
        assert!(printed * 2 >= cases.len() || only.is_some(), "only {printed} of {} programs printed", cases.len());
        return;
    }
    let keep = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cimco_differential");
    std::fs::create_dir_all(&keep).expect("a folder for the failing programs");
    std::fs::copy(&ron, keep.join("toolpath.ron")).expect("keep the toolpath");
    std::fs::copy(&jsonl, keep.join("toolpath.jsonl")).expect("keep the toolpath");
    // Every program that differs is kept as it was made; the first two
    // also shrunk.
    for (k, _) in &differ {
        let text = strategy.new_tree(&mut runner(seed, *k)).expect("a program").current();
        std::fs::write(keep.join(format!("case-{seed}-{k}.js")), text).expect("keep the program");
    }
    let mut report = String::new();
    for &(k, kind) in differ.iter().take(2) {
        let mut tree = strategy.new_tree(&mut runner(seed, k)).expect("a program");
        let original = tree.current();
        let (small, outputs) = shrink(&mut tree, kind, dir.path(), &ron, &jsonl);
        let case = keep.join(format!("case-{seed}-{k}.js"));
        let shrunk = keep.join(format!("case-{seed}-{k}-shrunk.js"));
        std::fs::write(&case, &original).expect("keep the program");
        std::fs::write(&shrunk, &small).expect("keep the program");
        let _ = write!(
            report,
            "\n=== program {k}: {kind}\n--- shrunk ({}):\n{small}\n--- its three runs:\n{outputs}\n--- replay: POSTC_DIFF_SEED={seed} POSTC_DIFF_CASE={k} cargo test --test suite cimco_differential\n    or: postc post {} {} ; node tests/node_host/run.js {} {}\n",
            shrunk.display(),
            shrunk.display(),
            keep.join("toolpath.ron").display(),
            shrunk.display(),
            keep.join("toolpath.jsonl").display(),
        );
    }
    let all: Vec<String> = differ.iter().map(|(k, kind)| format!("{k} ({kind})")).collect();
    panic!("{} of {} generated programs differ: {}\n{report}", differ.len(), cases.len(), all.join(", "));
}
