//! JavaScript's values in the IR, run by the runtime: arrays, objects,
//! properties, methods, function values, `this`, `for (k in o)`, `for`
//! loops with `continue`, `throw` and `try`. Each post is built by hand in
//! IR; what it writes is what Node.js prints for the same JavaScript
//! (written beside each case).

use postc_ir::event::{Event, VecSource};
use postc_ir::*;
use postc_runtime::{Finished, Output, RunOptions, run};

fn text(s: &str) -> Expr {
    Expr::Text(s.into())
}
fn num(n: f64) -> Expr {
    Expr::Number(n)
}
fn local(i: u16) -> Expr {
    Expr::Local(LocalId::new(i))
}
fn set(i: u16, e: Expr) -> Stmt {
    Stmt::Assign(Place::Local(LocalId::new(i)), e)
}
fn add(a: Expr, b: Expr) -> Expr {
    Expr::Binary(BinaryOp::Add, Box::new(a), Box::new(b))
}
fn member(o: Expr, k: Expr) -> Expr {
    Expr::Member { object: Box::new(o), key: Box::new(k), span: postc_ir::Site(None) }
}
fn invoke(o: Expr, m: &str, args: Vec<Expr>) -> Expr {
    Expr::Invoke { object: Box::new(o), method: m.into(), args, span: None }
}

/// A post whose header writes what function 0 returns; `functions` are
/// its functions (function 0 takes no arguments).
fn post(functions: Vec<Function>) -> Post {
    let mut post = Post::default();
    post.options.line_ending = b"\n".to_vec();
    post.functions = functions;
    post.handlers.push(Handler {
        key: HandlerKey::Section(Section::Header),
        body: vec![Stmt::Write(Expr::Call(FunctionId::new(0), vec![]))],
        span: None,
    });
    post
}

fn function(name: &str, params: usize, slots: u16, body: Vec<Stmt>) -> Function {
    Function {
        name: name.into(),
        params: (0..params).map(|i| format!("p{i}")).collect(),
        slots,
        locals: vec![],
        body: Body::Native(body),
        span: None,
        why_script: None,
        source: vec![],
        uses_arguments: false,
        starts_undefined: true,
    }
}

fn output(post: &Post) -> Result<String, Vec<Diagnostic>> {
    assert!(postc_ir::validate::validate(post).is_empty(), "{:?}", postc_ir::validate::validate(post));
    let mut source = VecSource::new(vec![Event::End], FileId(0));
    let report = run(post, &mut source, Output::memory(), RunOptions::default())?;
    match report.output {
        Finished::Memory(parts) => Ok(String::from_utf8_lossy(&parts.concat()).into_owned()),
        _ => unreachable!("memory output"),
    }
}

#[test]
fn arrays_join_push_index_and_length() {
    // var a = ["G1", 2]; a.push("X" + 3); a[4] = "F"; return a.join(" ") + "|" + a.length + "|" + a[1];
    // Node.js: "G1 2 X3  F|5|2"
    let body = vec![
        set(0, Expr::Array(vec![text("G1"), num(2.0)])),
        Stmt::Eval(invoke(local(0), "push", vec![add(text("X"), num(3.0))])),
        Stmt::SetMember { object: local(0), key: num(4.0), value: text("F"), span: postc_ir::Site(None) },
        Stmt::Return(Some(add(
            add(
                add(add(invoke(local(0), "join", vec![text(" ")]), text("|")), member(local(0), text("length"))),
                text("|"),
            ),
            member(local(0), num(1.0)),
        ))),
    ];
    assert_eq!(output(&post(vec![function("f", 0, 1, body)])).unwrap(), "G1 2 X3  F|5|2\n");
}

#[test]
fn objects_keep_their_order_and_walk_with_for_in() {
    // var o = {x: 1, y: 2}; o.z = 3; o.x = 9; var s = "";
    // for (var k in o) { s = s + k + "=" + o[k] + ";"; } return s + o.missing;
    // Node.js: "x=9;y=2;z=3;undefined"
    let keys = 2;
    let i = 3;
    let k = 4;
    let body = vec![
        set(0, Expr::Object(vec![("x".into(), num(1.0)), ("y".into(), num(2.0))])),
        Stmt::SetMember { object: local(0), key: text("z"), value: num(3.0), span: postc_ir::Site(None) },
        Stmt::SetMember { object: local(0), key: text("x"), value: num(9.0), span: postc_ir::Site(None) },
        set(1, text("")),
        set(keys, Expr::Builtin(Builtin::Keys, vec![local(0)])),
        set(i, num(0.0)),
        Stmt::While {
            cond: Expr::Binary(BinaryOp::JsLt, Box::new(local(i)), Box::new(member(local(keys), text("length")))),
            body: vec![
                set(k, member(local(keys), local(i))),
                set(1, add(add(add(add(local(1), local(k)), text("=")), member(local(0), local(k))), text(";"))),
            ],
            span: None,
            step: vec![set(i, add(local(i), num(1.0)))],
        },
        Stmt::Return(Some(add(local(1), member(local(0), text("missing"))))),
    ];
    assert_eq!(output(&post(vec![function("f", 0, 5, body)])).unwrap(), "x=9;y=2;z=3;undefined\n");
}

#[test]
fn continue_runs_the_loop_step() {
    // var s = ""; for (var i = 0; i < 5; i++) { if (i == 2) continue; s = s + i; } return s;
    // Node.js: "0134"
    let body = vec![
        set(0, text("")),
        set(1, num(0.0)),
        Stmt::While {
            cond: Expr::Binary(BinaryOp::JsLt, Box::new(local(1)), Box::new(num(5.0))),
            body: vec![
                Stmt::If {
                    branches: vec![(
                        Expr::Binary(BinaryOp::JsEq, Box::new(local(1)), Box::new(num(2.0))),
                        vec![Stmt::Continue],
                    )],
                    otherwise: vec![],
                },
                set(0, add(local(0), local(1))),
            ],
            span: None,
            step: vec![set(1, add(local(1), num(1.0)))],
        },
        Stmt::Return(Some(local(0))),
    ];
    assert_eq!(output(&post(vec![function("f", 0, 2, body)])).unwrap(), "0134\n");
}

#[test]
fn methods_see_this_and_closures_their_captures() {
    // function block() { this.n = this.n + 10; return "N" + this.n; }
    // function scale(k, x) { return k * x; }   (k captured)
    // var out = {n: 0, block: block}; var twice = scale.bind(null, 2);
    // return out.block() + " " + out.block() + " " + twice(21) + " " + typeof twice;
    // Node.js: "N10 N20 42 function"
    let block = function(
        "block",
        0,
        0,
        vec![
            Stmt::SetMember {
                object: Expr::This,
                key: text("n"),
                value: add(member(Expr::This, text("n")), num(10.0)),
                span: postc_ir::Site(None),
            },
            Stmt::Return(Some(add(text("N"), member(Expr::This, text("n"))))),
        ],
    );
    let scale = function(
        "scale",
        2,
        2,
        vec![Stmt::Return(Some(Expr::Binary(BinaryOp::Mul, Box::new(local(0)), Box::new(local(1)))))],
    );
    let main = vec![
        set(
            0,
            Expr::Object(vec![
                ("n".into(), num(0.0)),
                ("block".into(), Expr::Closure { function: FunctionId::new(1), captures: vec![] }),
            ]),
        ),
        set(1, Expr::Closure { function: FunctionId::new(2), captures: vec![num(2.0)] }),
        Stmt::Return(Some(add(
            add(
                add(
                    add(add(invoke(local(0), "block", vec![]), text(" ")), invoke(local(0), "block", vec![])),
                    text(" "),
                ),
                add(Expr::CallValue(Box::new(local(1)), vec![num(21.0)]), text(" ")),
            ),
            Expr::Unary(UnaryOp::Typeof, Box::new(local(1))),
        ))),
    ];
    let post = post(vec![function("f", 0, 2, main), block, scale]);
    assert_eq!(output(&post).unwrap(), "N10 N20 42 function\n");
}

#[test]
fn try_catches_throws_and_type_errors_and_finally_runs() {
    // var s = "";
    // try { throw "bad cycle"; } catch (e) { s = s + "caught " + e; } finally { s = s + "; done"; }
    // try { var u; u.x; } catch (e) { s = s + "; " + e.name; }
    // return s;
    // Node.js: "caught bad cycle; done; TypeError"
    let body = vec![
        set(0, text("")),
        Stmt::Try {
            body: vec![Stmt::Throw { value: text("bad cycle"), span: None }],
            catch: Some((LocalId::new(1), vec![set(0, add(add(local(0), text("caught ")), local(1)))])),
            finally: vec![set(0, add(local(0), text("; done")))],
        },
        Stmt::Try {
            body: vec![set(2, Expr::Undefined), Stmt::Eval(member(local(2), text("x")))],
            catch: Some((
                LocalId::new(1),
                vec![set(0, add(add(local(0), text("; ")), member(local(1), text("name"))))],
            )),
            finally: vec![],
        },
        Stmt::Return(Some(local(0))),
    ];
    assert_eq!(output(&post(vec![function("f", 0, 3, body)])).unwrap(), "caught bad cycle; done; TypeError\n");
}

#[test]
fn an_uncaught_throw_stops_the_run_with_its_message() {
    let span = Span::new(FileId(0), 10, 20);
    let body = vec![Stmt::Throw {
        value: Expr::Object(vec![("name".into(), text("Error")), ("message".into(), text("unknown cycle"))]),
        span: Some(span),
    }];
    let errors = output(&post(vec![function("f", 0, 0, body)])).unwrap_err();
    let e = errors.iter().find(|d| d.code == "RT036").expect("RT036");
    assert!(e.message.contains("Error: unknown cycle"), "{}", e.message);
    assert_eq!(e.primary_span(), Some(span));
}

#[test]
fn array_methods_and_callbacks() {
    // function cmp(a, b) { return a - b; } function big(x) { return x > 2; }
    // var a = [3, 1, 2, 5]; a.sort(cmp);
    // return a.join(",") + " " + a.filter(big).join(",") + " " + a.indexOf(5) + " " + a.slice(-2).join("");
    // Node.js: "1,2,3,5 3,5 3 35"
    let cmp = function(
        "cmp",
        2,
        2,
        vec![Stmt::Return(Some(Expr::Binary(BinaryOp::Sub, Box::new(local(0)), Box::new(local(1)))))],
    );
    let big = function(
        "big",
        1,
        1,
        vec![Stmt::Return(Some(Expr::Binary(BinaryOp::JsGt, Box::new(local(0)), Box::new(num(2.0)))))],
    );
    let f = |i: u32| Expr::Closure { function: FunctionId::new(i as u16), captures: vec![] };
    let body = vec![
        set(0, Expr::Array(vec![num(3.0), num(1.0), num(2.0), num(5.0)])),
        Stmt::Eval(invoke(local(0), "sort", vec![f(1)])),
        Stmt::Return(Some(add(
            add(
                add(
                    add(
                        add(invoke(local(0), "join", vec![text(",")]), text(" ")),
                        invoke(invoke(local(0), "filter", vec![f(2)]), "join", vec![text(",")]),
                    ),
                    add(text(" "), invoke(local(0), "indexOf", vec![num(5.0)])),
                ),
                text(" "),
            ),
            invoke(invoke(local(0), "slice", vec![num(-2.0)]), "join", vec![text("")]),
        ))),
    ];
    assert_eq!(output(&post(vec![function("f", 0, 1, body), cmp, big])).unwrap(), "1,2,3,5 3,5 3 35\n");
}

fn closure(f: u16) -> Expr {
    Expr::Closure { function: FunctionId::new(f), captures: vec![] }
}

/// `function F(n) { this.n = n; } F.prototype.get = function () { return
/// this.n; }` as functions 1 and 2 of a post whose function 0 runs `body`
/// (local 0 is `F`, local 1 `new F(5)`).
fn with_constructor(body: Vec<Stmt>) -> Post {
    let mut main = vec![
        set(0, closure(1)),
        Stmt::SetMember {
            object: member(local(0), text("prototype")),
            key: text("get"),
            value: closure(2),
            span: postc_ir::Site(None),
        },
        set(1, Expr::Builtin(Builtin::Construct, vec![local(0), num(5.0)])),
    ];
    main.extend(body);
    let ctor = function(
        "F",
        1,
        1,
        vec![Stmt::SetMember { object: Expr::This, key: text("n"), value: local(0), span: postc_ir::Site(None) }],
    );
    let get = function("get", 0, 0, vec![Stmt::Return(Some(member(Expr::This, text("n"))))]);
    post(vec![function("f", 0, 3, main), ctor, get])
}

#[test]
fn new_objects_read_the_methods_of_their_constructors_prototype() {
    // var o = new F(5); return o.get() + "|" + (o.constructor === F) + "|" + o.hasOwnProperty("get") + "|" + ("get" in o);
    // Node.js: "5|true|false|true"
    let sep = |e: Expr, next: Expr| add(add(e, text("|")), next);
    let body = vec![Stmt::Return(Some(sep(
        sep(
            sep(
                invoke(local(1), "get", vec![]),
                Expr::Binary(BinaryOp::StrictEq, Box::new(member(local(1), text("constructor"))), Box::new(closure(1))),
            ),
            invoke(local(1), "hasOwnProperty", vec![text("get")]),
        ),
        Expr::Builtin(Builtin::HasProperty, vec![text("get"), local(1)]),
    )))];
    assert_eq!(output(&with_constructor(body)).unwrap(), "5|true|false|true\n");
}

#[test]
fn a_method_on_no_chain_is_a_type_error_at_its_call() {
    // var o = new F(5); o.put(1);  Node.js: TypeError: o.put is not a function
    let span = Span::new(FileId(0), 30, 38);
    let call =
        Expr::Invoke { object: Box::new(local(1)), method: "put".into(), args: vec![num(1.0)], span: Some(span) };
    let errors = output(&with_constructor(vec![Stmt::Eval(call)])).unwrap_err();
    let e = errors.iter().find(|d| d.code == "RT037").expect("RT037");
    assert_eq!(e.message, "TypeError: the object has no method 'put'");
    assert_eq!(e.primary_span(), Some(span));
}

#[test]
fn a_chain_of_prototypes_is_walked_and_bounded() {
    // var o = {x: 7}; for (var i = 0; i < n; i++) o = Object.create(o); return o.x;
    let chain = |n: f64| {
        let body = vec![
            set(0, Expr::Object(vec![("x".into(), num(7.0))])),
            set(1, num(0.0)),
            Stmt::While {
                cond: Expr::Binary(BinaryOp::JsLt, Box::new(local(1)), Box::new(num(n))),
                body: vec![set(0, Expr::Builtin(Builtin::CreateObject, vec![local(0)]))],
                span: None,
                step: vec![set(1, add(local(1), num(1.0)))],
            },
            Stmt::Return(Some(member(local(0), text("x")))),
        ];
        output(&post(vec![function("f", 0, 2, body)]))
    };
    assert_eq!(chain(1000.0).unwrap(), "7\n");
    let errors = chain(5000.0).unwrap_err();
    let e = errors.iter().find(|d| d.code == "RT031").expect("RT031");
    assert!(e.message.contains("chain of more than 1024 prototypes"), "{}", e.message);
}
