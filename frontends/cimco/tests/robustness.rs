//! Bad input never panics or hangs: deeply nested and very long inputs
//! report one "nested too deeply" diagnostic, and random mutations of the
//! valid fixtures (proptest) parse to some tree with diagnostics whose
//! spans lie inside the text and render.

use postc_report::Render as _;
use std::time::{Duration, Instant};

use postc_front_cimco::{Syntax, dump::dump, parse, parse_as, print::to_js};
use postc_ir::FileId;
use proptest::prelude::*;

/// Parses on a thread with half the default stack of a Rust thread, so
/// that unbounded recursion would show as a crash here rather than pass on
/// a big main stack.
fn parse_small_stack(text: String) -> Vec<&'static str> {
    parse_small_stack_as(text, Syntax::Cimco)
}

fn parse_small_stack_as(text: String, syntax: Syntax) -> Vec<&'static str> {
    std::thread::Builder::new()
        .stack_size(1024 * 1024)
        .spawn(move || {
            let (program, diagnostics) = parse_as(&text, FileId(0), syntax);
            // Walking the tree must be safe too.
            let _ = dump(&program, &text);
            let _ = to_js(&program);
            diagnostics.iter().map(|d| d.code).collect()
        })
        .expect("spawn")
        .join()
        .expect("the parser panicked or overflowed")
}

#[test]
fn deep_and_long_inputs_are_refused_once() {
    let n = 20_000;
    let cases = [
        ("parentheses", format!("x = {}1{};", "(".repeat(n), ")".repeat(n))),
        ("unclosed parentheses", format!("x = {}1\n", "(".repeat(n))),
        ("blocks", format!("{}{}", "{".repeat(n), "}".repeat(n))),
        ("arrays", format!("x = {}{};", "[".repeat(n), "]".repeat(n))),
        ("objects", format!("x = {}1{};", "{a:".repeat(n), "}".repeat(n))),
        ("prefix operators", format!("x = {}y;", "!".repeat(n))),
        ("sums", format!("x = {};", vec!["1"; n].join("+"))),
        ("member chain", format!("x{};", ".y".repeat(n))),
        ("call chain", format!("f{};", "()".repeat(n))),
        ("if chain", format!("{}x();", "if (a) ".repeat(n))),
        ("conditionals", format!("x = {}c;", "a ? b : ".repeat(n))),
        ("assignments", format!("x{};", " = x".repeat(n))),
        ("functions", format!("x = {}1{};", "function(){ return ".repeat(n / 10), "}".repeat(n / 10))),
    ];
    for (name, text) in cases {
        let start = Instant::now();
        let codes = parse_small_stack(text);
        let took = start.elapsed();
        assert!(took < Duration::from_secs(30), "{name}: took {took:?}");
        assert_eq!(codes.iter().filter(|c| **c == "JS013").count(), 1, "{name}: {codes:?}");
    }
}

/// The same, for the forms only Fusion's JavaScript reads: nested
/// template substitutions, arrow functions and patterns, and parentheses
/// (each of which may open an arrow function's parameters).
#[test]
fn deep_fusion_inputs_are_refused_once() {
    let n = 20_000;
    let cases = [
        ("parentheses", format!("x = {}1{};", "(".repeat(n), ")".repeat(n))),
        ("parenthesised names", format!("x = {}a{};", "(".repeat(n), ")".repeat(n))),
        ("templates", format!("x = {}1{};", "`${".repeat(n), "}`".repeat(n))),
        ("arrow functions", format!("f = {}1;", "x => ".repeat(n))),
        ("array patterns", format!("var {}a{} = b;", "[".repeat(n), "]".repeat(n))),
        ("assignment patterns", format!("{}a{} = b;", "[".repeat(n), "]".repeat(n))),
        ("parameter patterns", format!("function f({}a{}) {{}}", "{k:".repeat(n), "}".repeat(n))),
    ];
    for (name, text) in cases {
        let start = Instant::now();
        let codes = parse_small_stack_as(text, Syntax::Fusion);
        let took = start.elapsed();
        assert!(took < Duration::from_secs(30), "{name}: took {took:?}");
        assert_eq!(codes.iter().filter(|c| **c == "JS013").count(), 1, "{name}: {codes:?}");
    }
}

#[test]
fn long_flat_else_if_chains_are_fine() {
    let text = format!("if (a) x();{}", " else if (a) x();".repeat(20_000));
    assert_eq!(parse_small_stack(text), Vec::<&str>::new());
}

#[test]
fn many_independent_errors_are_all_reported() {
    let text = "var a = ;\n".repeat(500);
    let codes = parse_small_stack(text);
    assert_eq!(codes.len(), 500);
}

/// The valid fixtures, as mutation seeds.
const SEEDS: &[&str] = &[
    include_str!("fixtures/valid/iso_mill.js"),
    include_str!("fixtures/valid/iso_lathe.js"),
    include_str!("fixtures/valid/es5_subset.js"),
];

/// Fragments that stress the lexer and the recovery.
const FRAGMENTS: &[&str] = &[
    "{", "}", "(", ")", "[", "]", ";", ",", "\"", "'", "`", "/", "/*", "*/", "//", "\n", "\\", "=>", "...", "function",
    "if", "else", "var", "return", "new", "switch", "case", "default:", "for (", "in", "?", ":", "0x", "1e", ".", "++",
    "--", "=", "+", "/g", "\u{0}", "\u{b0}", "\r", "let", "class", "${", "#",
];

#[derive(Clone, Debug)]
enum Mutation {
    Delete { at: usize, len: usize },
    Insert { at: usize, fragment: usize },
    Duplicate { at: usize, len: usize },
    Truncate { at: usize },
    Byte { at: usize, byte: u8 },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), 1usize..40).prop_map(|(at, len)| Mutation::Delete { at, len }),
        (any::<usize>(), 0..FRAGMENTS.len()).prop_map(|(at, fragment)| Mutation::Insert { at, fragment }),
        (any::<usize>(), 1usize..200).prop_map(|(at, len)| Mutation::Duplicate { at, len }),
        any::<usize>().prop_map(|at| Mutation::Truncate { at }),
        (any::<usize>(), any::<u8>()).prop_map(|(at, byte)| Mutation::Byte { at, byte }),
    ]
}

/// Applies mutations to bytes; the result is read as lossy UTF-8, as the
/// command line reads a post.
fn mutate(seed: &str, mutations: &[Mutation]) -> String {
    let mut bytes = seed.as_bytes().to_vec();
    for m in mutations {
        let len = bytes.len().max(1);
        match *m {
            Mutation::Delete { at, len: n } => {
                let at = at % len;
                let end = (at + n).min(bytes.len());
                bytes.drain(at.min(end)..end);
            }
            Mutation::Insert { at, fragment } => {
                let at = (at % len).min(bytes.len());
                bytes.splice(at..at, FRAGMENTS[fragment].bytes());
            }
            Mutation::Duplicate { at, len: n } => {
                let at = (at % len).min(bytes.len());
                let end = (at + n).min(bytes.len());
                let copy = bytes[at..end].to_vec();
                bytes.splice(at..at, copy);
            }
            Mutation::Truncate { at } => bytes.truncate(at % len),
            Mutation::Byte { at, byte } => {
                if !bytes.is_empty() {
                    let at = at % bytes.len();
                    bytes[at] = byte;
                }
            }
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

proptest! {
    // PROPTEST_CASES=5000 runs a longer search.
    #![proptest_config(ProptestConfig {
        cases: std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(96),
        ..ProptestConfig::default()
    })]

    #[test]
    fn mutated_posts_never_panic_or_hang(seed in 0..SEEDS.len(), mutations in prop::collection::vec(mutation(), 1..6)) {
        let text = mutate(SEEDS[seed], &mutations);
        let start = Instant::now();
        let (program, diagnostics) = parse(&text, FileId(0));
        prop_assert!(start.elapsed() < Duration::from_secs(20), "parse took {:?}", start.elapsed());
        for d in &diagnostics {
            let span = d.primary_span().expect("every diagnostic has a primary label");
            prop_assert!(span.start <= span.end && span.end <= text.len(), "{} out of range: {:?}", d.code, span);
            prop_assert!(text.is_char_boundary(span.start) && text.is_char_boundary(span.end));
        }
        let mut sources = postc_report::source_map();
        sources.add("mutated.js", text.clone());
        let _ = sources.render(&diagnostics, false);
        let _ = dump(&program, &text);
        let _ = to_js(&program);
    }
}

/// A long expression over many lines with one error in it: the parser's
/// work (token reads, re-reads included) per token stays the same when the
/// expression grows, wherever the error is. Statement recovery once
/// stopped at every line break, so each following `+` line started a new
/// statement that re-read the rest of the chain: quadratic work, and a
/// mutant of a corpus post took minutes to check.
#[test]
fn broken_long_expressions_parse_in_linear_work() {
    let line = "        + \"Q202=\" + qFormat.format(peck) + \" ;DEPTH ~\" + linebreak";
    let tail = "        \"Q202=\" + qFormat.format(peck) + \" ;DEPTH ~\" + linebreak +";
    type Shape = fn(usize, &str, &str) -> String;
    let shapes: [(&str, Shape); 4] = [
        ("an unclosed call in the middle", |n, line, _| {
            let half = vec![line; n / 2].join("\n");
            format!("function f() {{\n    return w(\"x\")\n{half}\n{}\n{half};\n}}\n", line.replace("peck)", "peck("))
        }),
        ("an operator with nothing after it at the end", |n, line, _| {
            format!("function f() {{\n    return w(\"x\")\n{}\n        + ;\n}}\n", vec![line; n].join("\n"))
        }),
        ("a trailing comma in a call at the end", |n, line, _| {
            format!(
                "function f() {{\n    return w(\"x\")\n{}\n        + q.format(p, ) +\n;\n}}\n",
                vec![line; n].join("\n")
            )
        }),
        ("operators at the line ends", |n, _, tail| {
            format!("function f() {{\n    return w(\"x\") +\n{}\n        ;\n}}\n", vec![tail; n].join("\n"))
        }),
    ];
    for (name, shape) in shapes {
        let per_token = |n: usize| {
            let (tokens, reads) = postc_front_cimco::parse_work(&shape(n, line, tail));
            reads as f64 / tokens as f64
        };
        let (small, large) = (per_token(100), per_token(800));
        assert!(
            large < 1.5 * small && large < 64.0,
            "{name}: {small:.1} reads per token at 100 lines, {large:.1} at 800"
        );
    }
}
