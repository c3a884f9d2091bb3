//! Small grammar cases: automatic semicolon insertion, regular
//! expressions, precedence, and what each unsupported construct reports.

use postc_front_cimco::{dump::dump, parse};
use postc_ir::FileId;

/// The dump of a snippet without positions, one statement per line; the
/// snippet must parse without diagnostics.
fn tree(text: &str) -> String {
    let (program, diagnostics) = parse(text, FileId(0));
    assert!(diagnostics.is_empty(), "{text:?} reported {diagnostics:#?}");
    dump(&program, text)
        .lines()
        .map(|l| {
            let indent = l.len() - l.trim_start().len();
            let rest = l.trim_start().split_once(' ').map_or("", |(_, r)| r);
            format!("{}{rest}", " ".repeat(indent))
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The codes a snippet reports.
fn codes(text: &str) -> Vec<&'static str> {
    parse(text, FileId(0)).1.iter().map(|d| d.code).collect()
}

#[test]
fn line_breaks_end_statements() {
    assert_eq!(tree("a = 1\nb = 2"), "(= a 1)\n(= b 2)");
    assert_eq!(tree("var a = 1\nvar b"), "var a = 1\nvar b");
    assert_eq!(tree("f()\n{ g() }"), "(call f)\nblock\n  (call g)");
    assert_eq!(tree("if (a) { b() } c()"), "if a\n  block\n    (call b)\n(call c)");
}

#[test]
fn line_breaks_do_not_end_unfinished_expressions() {
    assert_eq!(tree("a = b\n  + c"), "(= a (+ b c))");
    assert_eq!(tree("a = b +\n  c"), "(= a (+ b c))");
    assert_eq!(tree("x = f\n(1)"), "(= x (call f 1))");
    assert_eq!(tree("x = o\n.p"), "(= x (. o p))");
    assert_eq!(tree("foo(1,\n 2)"), "(call foo 1 2)");
}

#[test]
fn restricted_productions() {
    assert_eq!(tree("function f() { return\n1 }"), "function f()\n  return\n  1");
    assert_eq!(tree("a\n++b"), "a\n(pre++ b)");
    assert_eq!(tree("a++\nb"), "(post++ a)\nb");
    assert_eq!(tree("for (;;) { break\n}"), "for ; ; \n  block\n    break");
}

#[test]
fn statement_before_closing_brace_and_end() {
    assert_eq!(tree("function f() { return 1 }"), "function f()\n  return 1");
    assert_eq!(tree("x = 1"), "(= x 1)");
    assert_eq!(tree("do x++\nwhile (x < 3) y()"), "do-while (< x 3)\n  (post++ x)\n(call y)");
}

#[test]
fn missing_semicolon_on_one_line() {
    assert_eq!(codes("a = 1 b = 2"), ["JS008"]);
    assert_eq!(codes("var a = 1 var b"), ["JS008"]);
}

#[test]
fn regex_and_division() {
    assert_eq!(tree("x = a / b / c"), "(= x (/ (/ a b) c))");
    assert_eq!(tree("x = s.replace(/ab+/g, \"\")"), "(= x (call (. s replace) /ab+/g \"\"))");
    assert_eq!(tree("x = (a) / 2"), "(= x (/ a 2))");
    assert_eq!(tree("x = [/a/, /b/i]"), "(= x [/a/ /b/i])");
    assert_eq!(tree("if (/x/.test(s)) y()"), "if (call (. /x/ test) s)\n  (call y)");
}

#[test]
fn precedence_and_associativity() {
    assert_eq!(
        tree("x = a || b && c | d ^ e & f == g < h << i + j * k"),
        "(= x (|| a (&& b (| c (^ d (& e (== f (< g (<< h (+ i (* j k)))))))))))"
    );
    assert_eq!(tree("x = y = z"), "(= x (= y z))");
    assert_eq!(tree("x = a ? b : c ? d : e"), "(= x (? a b (? c d e)))");
    assert_eq!(tree("x = -a.b[c](d)"), "(= x (- (call ([] (. a b) c) d)))");
    assert_eq!(tree("x = !typeof a"), "(= x (! (typeof a)))");
    assert_eq!(tree("x = a - b - c"), "(= x (- (- a b) c))");
}

#[test]
fn new_and_calls() {
    assert_eq!(tree("x = new Foo"), "(= x (new Foo))");
    assert_eq!(tree("x = new Foo(1).bar()"), "(= x (call (. (new Foo 1) bar)))");
    assert_eq!(tree("x = new a.B(1)"), "(= x (new (. a B) 1))");
    assert_eq!(tree("x = o.default + o.new"), "(= x (+ (. o default) (. o new)))");
}

#[test]
fn if_else_chains_are_flat() {
    assert_eq!(
        tree("if (a) x()\nelse if (b) y()\nelse z()"),
        "if a\n  (call x)\nelse if b\n  (call y)\nelse\n  (call z)"
    );
    // A dangling `else` belongs to the nearest `if`.
    assert_eq!(tree("if (a) if (b) x(); else y()"), "if a\n  if b\n    (call x)\n  else\n    (call y)");
}

#[test]
fn unsupported_constructs_are_named() {
    let cases: &[(&str, &str)] = &[
        ("let x = 1", "JS018"),
        ("const x = 1", "JS018"),
        ("f = (a) => a", "JS019"),
        ("class A {}", "JS020"),
        ("x = `t`", "JS021"),
        ("o = { get x() { return 1 } }", "JS022"),
        ("with (o) x = 1", "JS023"),
        ("a: for (;;) {}", "JS024"),
        ("for (;;) break a", "JS024"),
        ("delete o.x", "JS025"),
        ("x = o instanceof A", "JS027"),
        ("function* g() {}", "JS028"),
        ("async function g() {}", "JS029"),
        ("f(...a)", "JS030"),
        ("var [a, b] = c", "JS031"),
        ("function f(a = 1) {}", "JS032"),
        ("o = { a }", "JS033"),
        ("for (var a of b) {}", "JS034"),
        ("x = 2 ** 3", "JS035"),
        ("x = a?.b", "JS036"),
        ("import x from 'y'", "JS037"),
        ("x = void 0", "JS038"),
        ("debugger", "JS039"),
        ("x = /a/u", "JS040"),
        ("x = 0b1", "JS041"),
        ("f(a,)", "JS042"),
        ("x = [1,,2]", "JS043"),
    ];
    for (text, code) in cases {
        assert_eq!(codes(text), [*code], "{text}");
    }
}

#[test]
fn names_that_are_only_sometimes_keywords() {
    assert_eq!(
        tree("var let_ = 1, of = 2, get = 3, set = 4, async = 5, await = 6"),
        "var let_ = 1, of = 2, get = 3, set = 4, async = 5, await = 6"
    );
    assert_eq!(tree("x = { get: 1, set: 2 }"), "(= x {get: 1, set: 2})");
    assert_eq!(tree("x = await"), "(= x await)");
}

#[test]
fn empty_input_and_comments_only() {
    assert_eq!(tree(""), "");
    assert_eq!(tree("// nothing\n/* at all */"), "");
    assert_eq!(tree("\u{feff}var a"), "var a");
}

#[test]
fn sniffs_cimco_posts() {
    let mill = include_bytes!("fixtures/valid/iso_mill.js");
    let lathe = include_bytes!("fixtures/valid/iso_lathe.js");
    assert!(postc_front_cimco::looks_like_cimco(mill));
    assert!(postc_front_cimco::looks_like_cimco(lathe));
    assert!(!postc_front_cimco::looks_like_cimco(b"begin HEADER\n\"G21\"\n"));
}
