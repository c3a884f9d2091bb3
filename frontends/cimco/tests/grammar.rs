//! Small grammar cases: automatic semicolon insertion, regular
//! expressions, precedence, and what each unsupported construct reports.

use postc_front_cimco::{Syntax, dump::dump, parse, parse_as, print};
use postc_ir::FileId;

/// The dump of a snippet without positions, one statement per line; the
/// snippet must parse without diagnostics.
fn tree(text: &str) -> String {
    let (program, diagnostics) = parse(text, FileId(0));
    assert!(diagnostics.is_empty(), "{text:?} reported {diagnostics:#?}");
    shape(&dump(&program, text))
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
        ("var cells = xml..c", "JS044"),
        ("var data = xml..ss::Data", "JS044"),
        ("e.@ss::Type = \"Number\"", "JS044"),
        ("if (c.@t == \"s\") {}", "JS044"),
        ("default xml namespace = \"urn:schemas-microsoft-com:office:spreadsheet\"", "JS044"),
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

/// [`tree`] of a snippet read as Fusion's JavaScript.
fn fusion_tree(text: &str) -> String {
    let (program, diagnostics) = parse_as(text, FileId(0), Syntax::Fusion);
    assert!(diagnostics.is_empty(), "{text:?} reported {diagnostics:#?}");
    let printed = print::to_js(&program);
    let (again, _) = parse_as(&printed, FileId(0), Syntax::Fusion);
    assert_eq!(shape(&dump(&again, &printed)), shape(&dump(&program, text)), "{text:?} printed as {printed:?}");
    shape(&dump(&program, text))
}

/// A dump without positions.
fn shape(dump: &str) -> String {
    dump.lines()
        .map(|l| {
            let indent = l.len() - l.trim_start().len();
            let rest = l.trim_start().split_once(' ').map_or("", |(_, r)| r);
            format!("{}{rest}", " ".repeat(indent))
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The diagnostics of a snippet read as Fusion's JavaScript: code and message.
fn fusion_diagnostics(text: &str) -> Vec<(&'static str, String)> {
    parse_as(text, FileId(0), Syntax::Fusion).1.into_iter().map(|d| (d.code, d.message)).collect()
}

#[test]
fn fusion_reads_template_literals() {
    assert_eq!(fusion_tree("x = `a${b}c${d + 1}`"), "(= x (template [\"a\" \"c\" \"\"] b (+ d 1)))");
    assert_eq!(fusion_tree("x = `plain`"), "(= x (template [\"plain\"]))");
    // Escapes, line breaks (CR LF is LF), and a `}` inside a substitution.
    assert_eq!(
        fusion_tree("x = `\\`\\${a}\r\n${ {k: 1}.k }${`in${\"}\"}`}`"),
        "(= x (template [\"`${a}\\n\" \"\" \"\"] (. {k: 1} k) (template [\"in\" \"\"] \"}\")))"
    );
    // A `/` after a substitution divides; after `${` it starts a regular expression.
    assert_eq!(
        fusion_tree("x = `${a}` / 2 + `${/b/.source}`"),
        "(= x (+ (/ (template [\"\" \"\"] a) 2) (template [\"\" \"\"] (. /b/ source))))"
    );
}

#[test]
fn fusion_reads_arrow_functions() {
    assert_eq!(fusion_tree("f = x => x * 2"), "(= f (arrow (x)))\n  fn (x)\n    return (* x 2)");
    assert_eq!(fusion_tree("f = (a, b) => { return a + b; }"), "(= f (arrow (a b)))\n  fn (a b)\n    return (+ a b)");
    assert_eq!(fusion_tree("f = () => ({k: 1})"), "(= f (arrow ()))\n  fn ()\n    return {k: 1}");
    assert_eq!(
        fusion_tree("list.forEach(i => { n += i; })"),
        "(call (. list forEach) (arrow (i)))\n  fn (i)\n    (+= n i)"
    );
    // A parameter's default starts the body.
    assert_eq!(
        fusion_tree("f = (a = 1) => a"),
        "(= f (arrow (a)))\n  fn (a)\n    (= a (? (=== a undefined) 1 a))\n    return a"
    );
}

#[test]
fn fusion_reads_legacy_octal_and_newer_numbers() {
    assert_eq!(
        fusion_tree("x = [010, 08, 019, 09.5, 0777, 00, 0b101, 0o17, 0x1F]"),
        "(= x [8 8 19 9.5 511 0 5 15 31])"
    );
    // `07.5` is the octal 7 then a number: JavaScript refuses it too.
    assert!(!fusion_diagnostics("x = 07.5").is_empty());
    assert_eq!(fusion_diagnostics("x = 0b102")[0].0, "JS005");
}

#[test]
fn fusion_reads_destructuring_written_out() {
    assert_eq!(
        fusion_tree("[s.a, s.b] = list;"),
        "var __postc_d0\n(, (= __postc_d0 list) (= (. s a) ([] __postc_d0 0)) (= (. s b) ([] __postc_d0 1)) __postc_d0)"
    );
    assert_eq!(
        fusion_tree("var [a, , b = 2] = list, {c, d: e} = o"),
        "var __postc_d4 = list, a = ([] __postc_d4 0), b = (? (=== ([] __postc_d4 2) undefined) 2 ([] __postc_d4 2)), __postc_d25 = o, c = (. __postc_d25 c), e = (. __postc_d25 d)"
    );
    assert_eq!(
        fusion_tree("function f({ a = false } = {}) { return a; }"),
        "function f(__postc_p11)\n  var __postc_d11 = (? (=== __postc_p11 undefined) {} __postc_p11), a = (? (=== (. __postc_d11 a) undefined) false (. __postc_d11 a))\n  return a"
    );
    // The temporary of an assignment pattern is declared by the function around it.
    assert_eq!(
        fusion_tree("function g() { [a, b] = [b, a]; }"),
        "function g()\n  var __postc_d15\n  (, (= __postc_d15 [b a]) (= a ([] __postc_d15 0)) (= b ([] __postc_d15 1)) __postc_d15)"
    );
    assert_eq!(fusion_tree("o = {a, b: 2}"), "(= o {a: a, b: 2})");
    assert_eq!(fusion_tree("f(a, b,)"), "(call f a b)");
}

#[test]
fn fusion_reads_instanceof() {
    // With the precedence of `<` and `in`; CNC-Calc posts refuse it (JS027).
    assert_eq!(fusion_tree("x = this instanceof F == a < b"), "(= x (== (instanceof this F) (< a b)))");
}

#[test]
fn fusion_reports_what_it_still_does_not_read() {
    let first = |text: &str| fusion_diagnostics(text).into_iter().next().unwrap_or(("none", String::new()));
    assert_eq!(first("x = tag`a${b}`").0, "JS021");
    assert_eq!(first("x = (1) => 2").0, "JS007");
    assert_eq!(first("var [a, b];").0, "JS007");
    assert_eq!(first("[a + 1, b] = c").0, "JS012");
    let (code, message) = first("class A {}");
    assert_eq!(code, "JS020");
    assert!(message.contains("Fusion"), "{message}");
}

#[test]
fn cnc_calc_posts_still_refuse_the_newer_forms() {
    let cases: &[(&str, &[&str])] = &[
        ("x = `a${b}`", &["JS021"]),
        ("f = x => x", &["JS019"]),
        ("f = () => ({})", &["JS019"]),
        ("x = 010", &["JS041"]),
        ("x = 08", &["JS041"]),
        ("[a, b] = c", &["JS012"]),
        ("function f({ a = false } = {}) {}", &["JS031", "JS032"]),
        ("var {a} = o", &["JS031"]),
    ];
    for (text, expected) in cases {
        assert_eq!(codes(text), *expected, "{text}");
    }
}
