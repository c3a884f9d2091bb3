//! The runtime prepares a post's fast form from what its IR means: a CIMCO
//! handler is `Write(onLinear(...))` in the IR, whoever reads it (the
//! backends, `postc inspect`, a RON post on disk); the runtime's
//! preparation (`postc_runtime::prepare`) inlines the entry point and
//! builds its text straight in the output, and turns calls of expression
//! functions into the expressions.

use crate::support;
use std::path::Path;

use crate::support::prepared::*;
use postc_ir::{HandlerKey, Post, Section};

fn feed_move(post: &Post) -> usize {
    post.handlers.iter().position(|h| h.key == HandlerKey::Section(Section::FeedMove)).expect("FEED_MOVE")
}

/// Expression functions (a chain of `if (c) return a;` and a last
/// `return`, after at most one local read once where evaluation always
/// reaches it) are inlined where a prepared handler calls them with cheap
/// arguments; others stay calls, and so do the calls in the functions and
/// in the IR.
#[test]
fn expression_functions_are_inlined_into_the_prepared_handlers() {
    let js = r#"
        function value() { var f = getFeedrate(1); return parseFloat(f.substring(1)); }
        function guarded(m) { var f = getFeedrate(m); return m == 0 ? "" : f; }
        function onLinear(x, y, z, m) { return (value() > 0 ? "p" : "n") + (guarded(m) == "" ? "r" : "f") + "\n"; }
    "#;
    let post = support::compile_text("t.js", js);
    let code = postc_runtime::prepare::prepare(&post);
    let handler = &code.handlers[feed_move(&post)];
    assert!(!calls(handler, function(&post, "value")), "value() is inlined: {handler:?}");
    assert!(
        calls(handler, function(&post, "guarded")),
        "guarded() reads its local under a choice: a call: {handler:?}"
    );
    let on_linear = &post.functions[function(&post, "onLinear").index()];
    let postc_ir::Body::Native(on_linear) = &on_linear.body else { panic!("onLinear is native") };
    assert!(ir_calls(on_linear, function(&post, "value")), "the function keeps its call: {on_linear:?}");
    let meaning = &post.handlers[feed_move(&post)].body;
    assert!(
        matches!(meaning.first(), Some(postc_ir::Stmt::Write(postc_ir::Expr::Call(..)))),
        "the IR's handler is the call of onLinear: {meaning:?}"
    );
}

/// A CIMCO post read back from RON gets the same fast form as the post
/// compiled from JavaScript: the fast path is the runtime's, not the
/// frontend's.
#[test]
fn a_ron_post_is_prepared_as_its_source() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/posts/cimco/fanuc_mill.js");
    let mut sources = postc_report::source_map();
    let post = postc_driver::compile_post(&path, None, &mut sources).post.expect("fanuc_mill.js compiles");
    let ron = postc_backends::ron::print(&post).expect("prints as RON");
    let mut sources = postc_report::source_map();
    let back = postc_driver::compile_post_bytes(Path::new("fanuc_mill.ron"), ron.as_bytes(), None, &mut sources)
        .post
        .expect("the RON post reads back");
    // RON keeps no spans (they point into the source), so neither do the
    // `Origin`s of `--trace`.
    let mut plain = post.clone();
    plain.drop_spans();
    let (a, b) = (postc_runtime::prepare::prepare(&plain), postc_runtime::prepare::prepare(&back));
    let i = feed_move(&post);
    let fast = &b.handlers[i];
    assert!(
        count_stmts(fast, &|s| matches!(s, XStmt::Emit(_))) > 0
            && count_stmts(fast, &|s| matches!(s, XStmt::Write(_))) == 0,
        "the RON post's FEED_MOVE is not on the fast path: {fast:?}"
    );
    assert_eq!(a.handlers.len(), b.handlers.len());
    assert_eq!(&a.handlers[i], fast, "both are prepared alike");
}

/// A field post's variadic `writeBlock()`: the words not empty, the block
/// number put in front, joined by blanks.
const WRITE_BLOCK: &str = r#"
    var linebreak = "\n";
    var sequenceNumber = 10;
    var xOutput = createVariable({prefix: "X"}, createFormat({decimals: 3}));
    var yOutput = createVariable({prefix: "Y"}, createFormat({decimals: 3}));
    function writeBlock() {
        var words = [];
        for (var i = 0; i < arguments.length; ++i) {
            if (arguments[i] != "") {
                words.push(arguments[i]);
            }
        }
        if (words.length == 0) {
            return "";
        }
        words.unshift("N" + sequenceNumber);
        sequenceNumber += 10;
        return words.join(" ") + linebreak;
    }
"#;

/// The post of [`WRITE_BLOCK`] and `on_linear`, its prepared `FEED_MOVE`
/// handler and the program it writes for feeds to the given (x, y).
fn write_block_post(on_linear: &str, feeds: &[(f64, f64)]) -> (Vec<XStmt>, String) {
    use postc_ir::event::{Event, FeedMove, VecSource};
    let post = support::compile_text("t.js", &format!("{WRITE_BLOCK}{on_linear}"));
    let code = postc_runtime::prepare::prepare(&post);
    let handler = code.handlers[feed_move(&post)].clone();
    let mut events = vec![Event::Job(Box::default())];
    events.extend(feeds.iter().map(|&(x, y)| Event::Feed(FeedMove { x, y, ..FeedMove::default() })));
    events.push(Event::End);
    let mut source = VecSource::new(events, postc_ir::FileId(0));
    let report =
        postc_runtime::run(&post, &mut source, postc_runtime::Output::memory(), postc_driver::run_options(&post))
            .expect("posts");
    let postc_runtime::Finished::Memory(parts) = report.output else { unreachable!("memory output") };
    (handler, String::from_utf8_lossy(&parts.concat()).into_owned())
}

/// `words.unshift("N" + n)` in a variadic `writeBlock()` writes the block
/// number first in the prepared handler (nothing moved back), and a block
/// of empty words still writes nothing, number included, and counts no
/// number.
#[test]
fn a_block_number_is_written_first_and_dropped_with_an_empty_block() {
    let on_linear = r#"
        function onLinear(x, y, z, movement) {
            return writeBlock(xOutput.format(x)) + writeBlock("G1", xOutput.format(x));
        }
    "#;
    let (handler, program) = write_block_post(on_linear, &[(1.0, 0.0), (1.0, 0.0), (2.0, 0.0)]);
    assert_eq!(
        count_stmts(&handler, &|s| matches!(s, XStmt::MoveBack { .. })),
        0,
        "the number is written first: {handler:?}"
    );
    assert_eq!(program, "N10 X1\nN20 G1\nN30 G1\nN40 X2\nN50 G1\n");
}

/// The words of a variadic `writeBlock()` are one statement in the
/// prepared handler; when each is a text it writes them at once, and a
/// word that is not a text (a number passed as it is) runs the words'
/// own statements: the same program either way, and an empty block still
/// writes and counts nothing.
#[test]
fn a_run_of_words_is_one_statement_and_a_word_not_text_runs_as_written() {
    let on_linear = r#"
        function onLinear(x, y, z, movement) {
            var t = x > 1.5 ? 7 : "";
            var u = x > 1.5 ? "U" : "";
            return writeBlock(xOutput.format(x), yOutput.format(y)) + writeBlock(t, u);
        }
    "#;
    let (handler, program) = write_block_post(on_linear, &[(1.0, 0.0), (1.0, 0.0), (2.0, 3.0)]);
    assert_eq!(
        count_stmts(&handler, &|s| matches!(s, XStmt::Words(_))),
        2,
        "each block's words are one statement: {handler:?}"
    );
    assert_eq!(program, "N10 X1 Y0\nN20 X2 Y3\nN30 7 U\n");
}

/// An object literal a global holds for the whole run, read only as
/// `g.k`, written as `g.k = v` (`+=` included) and called as `g.m()`,
/// keeps its properties in globals and its methods become functions
/// (`prepare/fields.rs`); an object that is passed as a value keeps its
/// properties.
#[test]
fn an_object_a_global_holds_becomes_globals_unless_it_is_seen_whole() {
    let js = |extra: &str| {
        format!(
            r#"
            var state = {{seq: 10, last: null, block: function (t) {{ this.seq += 10; return "N" + this.seq + " " + t + "\n"; }}}};
            function word(t) {{ if (t == state.last) {{ return ""; }} state.last = t; return t; }}
            function seq(o) {{ return o.seq; }}
            function onLinear(x, y, z, m) {{ {extra} return state.block(word("X" + x)); }}
            "#
        )
    };
    let post = support::compile_text("t.js", &js(""));
    let code = postc_runtime::prepare::prepare(&post);
    let onlinear = function(&post, "onLinear").index();
    let native = |code: &postc_runtime::exec::Code, i: usize| match &code.functions[i].body {
        postc_runtime::exec::Body::Native(b) => b.clone(),
        postc_runtime::exec::Body::Script(_) => panic!("native"),
    };
    let member = |e: &XExpr| matches!(e, XExpr::Member(..) | XExpr::Invoke { .. });
    assert!(!any_expr(&native(&code, onlinear), &member), "the object's uses are globals and calls");
    assert!(!any_expr(&native(&code, function(&post, "word").index()), &member), "state.last is a global");
    let post = support::compile_text("t.js", &js("var s = seq(state);"));
    let code = postc_runtime::prepare::prepare(&post);
    assert!(any_expr(&native(&code, onlinear), &member), "an object passed as a value stays one");
}

/// The program a JavaScript post writes for feeds to the given (x, y).
fn program_of(post: &Post, feeds: &[(f64, f64)]) -> String {
    use postc_ir::event::{Event, FeedMove, VecSource};
    let mut events = vec![Event::Job(Box::default())];
    events.extend(feeds.iter().map(|&(x, y)| Event::Feed(FeedMove { x, y, ..FeedMove::default() })));
    events.push(Event::End);
    let mut source = VecSource::new(events, postc_ir::FileId(0));
    let report =
        postc_runtime::run(post, &mut source, postc_runtime::Output::memory(), postc_driver::run_options(post))
            .expect("posts");
    let postc_runtime::Finished::Memory(parts) = report.output else { unreachable!("memory output") };
    String::from_utf8_lossy(&parts.concat()).into_owned()
}

/// A factory the one-time code calls with constants (`modal("X", f)`,
/// returning an object of closures over its state) has its closures made
/// into functions of their own, their state in globals, and the methods
/// of the object its global holds are called directly, even when the
/// object is also kept in an array and its method called from there
/// (`prepare/factories.rs`). A factory given a value known only when it
/// runs keeps its closures; a post that sets a property named as a method
/// keeps the method call. The program is the same in every case.
#[test]
fn a_factory_called_with_constants_is_specialised_unless_its_preconditions_fail() {
    let js = |arg: &str, extra: &str| {
        format!(
            r#"
            var f = createFormat({{decimals: 3}});
            function modal(prefix, format) {{
                var last = null;
                return {{
                    word: function (v) {{ var t = prefix + format.format(v); if (t == last) {{ return ""; }} last = t; return t; }},
                    reset: function () {{ last = null; }}
                }};
            }}
            function letter() {{ return "X"; }}
            var xWord = modal({arg}, f);
            var all = [xWord];
            function onLinear(x, y, z, m) {{ {extra} if (y > 2) {{ all[0].reset(); }} return xWord.word(x) + "\n"; }}
            "#
        )
    };
    let feeds = [(1.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 3.0)];
    let word_invoked = |post: &Post| {
        let code = postc_runtime::prepare::prepare(post);
        let postc_runtime::exec::Body::Native(body) = &code.functions[function(post, "onLinear").index()].body else {
            panic!("native")
        };
        any_expr(body, &|e| matches!(e, XExpr::Invoke { method, .. } if &**method == "word"))
    };
    let specialised = support::compile_text("t.js", &js("\"X\"", ""));
    assert!(!word_invoked(&specialised), "xWord.word(x) is a call of a function of its own");
    let program = program_of(&specialised, &feeds);
    let lines: Vec<&str> = program.lines().collect();
    assert_eq!(lines.len(), 3, "X1, nothing, X2, X2 again after reset: {program:?}");
    assert!(lines[0].starts_with('X') && lines[1] == lines[2], "{program:?}");
    let computed = support::compile_text("t.js", &js("letter()", ""));
    assert!(word_invoked(&computed), "an argument known only when it runs keeps the closures");
    assert_eq!(program_of(&computed, &feeds), program);
    let replaced = support::compile_text("t.js", &js("\"X\"", "if (y > 5) { xWord.word = null; }"));
    assert!(word_invoked(&replaced), "a property `word` set anywhere keeps the method call");
    assert_eq!(program_of(&replaced, &feeds), program);
}

/// A function that only returns an expression calling nothing is run as
/// that expression (`exec::Function::returns`); one that calls a
/// function, or reads `this`, runs its statements.
#[test]
fn a_function_that_only_returns_a_plain_expression_is_that_expression() {
    let js = r#"
        function isWord(w) { return w !== ""; }
        function calls(w) { return isWord(w); }
        function self() { return this; }
        function onLinear(x, y, z, m) { return [String(x), ""].filter(isWord).join(" ") + (calls("a") ? "\n" : ""); }
    "#;
    let post = support::compile_text("t.js", js);
    let code = postc_runtime::prepare::prepare(&post);
    let returns = |name: &str| code.functions[function(&post, name).index()].returns.is_some();
    assert!(returns("isWord"));
    assert!(!returns("calls"), "a call runs post code");
    assert!(!returns("self"), "`this` depends on the call");
    assert_eq!(program_of(&post, &[(1.0, 0.0), (2.0, 0.0)]), "1\n2\n");
}

/// A function given a function expression that it only calls and tests
/// (`motionBlock(code, words, function () {...}, null)`) runs as a copy
/// that calls the expression's function directly, with its captures as
/// arguments, and null as the constant it is (`prepare/callbacks.rs`). A
/// function that keeps the function it is given, or reads `arguments`,
/// is called as written, making the closure. The program is the same in
/// every case.
#[test]
fn a_function_expression_passed_to_a_function_that_calls_it_is_called_directly_unless_it_escapes() {
    let js = |extra: &str, args: &str| {
        format!(
            r#"
            var kept = null;
            function block(code, words, after) {{
                {extra}
                var all = [code].concat(words);
                return (after ? all.concat(after()) : all).join(" ") + "\n";
            }}
            function feed(m, then) {{ return then(m > 1 ? "F" + m : ""); }}
            function same(t) {{ return t; }}
            function onLinear(x, y, z, m) {{
                {args}
                return block("G1", ["X" + x], function () {{ return [feed(y, same)]; }}) + block("G0", ["Y" + y], null);
            }}
            "#
        )
    };
    let feeds = [(1.0, 0.0), (2.0, 3.0)];
    let closure_made = |post: &Post| {
        let code = postc_runtime::prepare::prepare(post);
        let postc_runtime::exec::Body::Native(body) = &code.functions[function(post, "onLinear").index()].body else {
            panic!("native")
        };
        any_expr(body, &|e| matches!(e, XExpr::Closure { .. }))
    };
    let direct = support::compile_text("t.js", &js("", ""));
    assert!(!closure_made(&direct), "the function expression is called directly");
    let program = program_of(&direct, &feeds);
    assert!(program.contains("G1 X2 F3") && program.contains("G0 Y3"), "{program:?}");
    let escapes = support::compile_text("t.js", &js("kept = after;", ""));
    assert!(closure_made(&escapes), "a function kept by the callee stays a closure");
    assert_eq!(program_of(&escapes, &feeds), program);
    let counted = support::compile_text("t.js", &js("var n = arguments.length;", ""));
    assert!(closure_made(&counted), "a callee reading `arguments` is called as written");
    assert_eq!(program_of(&counted, &feeds), program);
}
