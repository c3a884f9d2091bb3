use crate::modules::prepare::testing::{local, set};
use postc_ir::Place;
use postc_ir::{BinaryOp, FunctionId, GlobalId};
use postc_runtime::exec::{Body, Expr, Function, Stmt};
use postc_runtime::testing::prepare_splice::*;

/// `function motion(code) { if (code == last) return ""; last = code; return code; }`
fn motion() -> Function {
    let last = Expr::Global(GlobalId::new(0));
    Function {
        params: 1,
        slots: 1,
        body: Body::Native(vec![
            Stmt::If {
                branches: vec![(
                    Expr::Binary(BinaryOp::JsEq, Box::new(local(0)), Box::new(last)),
                    vec![Stmt::Return(Some(Expr::text("")))],
                )],
                otherwise: vec![],
            },
            Stmt::Assign(Place::Global(GlobalId::new(0)), local(0)),
            Stmt::Return(Some(local(0))),
        ]),
        starts_undefined: false,
        returns: None,
        origin: FunctionId::new(0),
        uses_arguments: false,
        uses_this: false,
    }
}

#[test]
fn a_call_becomes_the_body_in_fresh_slots() {
    let mut body = vec![set(0, Expr::Call(FunctionId::new(0), vec![Expr::text("G1")]))];
    small_functions(&[motion()], &mut body);
    assert_eq!(body, motion_spliced(1, 0));
}

/// `motion("G1")` spliced: its argument in slot `arg`, its value to
/// local `dest`.
fn motion_spliced(arg: u16, dest: u16) -> Vec<Stmt> {
    let last = Expr::Global(GlobalId::new(0));
    vec![
        set(arg, Expr::text("G1")),
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![
                Stmt::If {
                    branches: vec![(
                        Expr::Binary(BinaryOp::JsEq, Box::new(local(arg)), Box::new(last)),
                        vec![set(dest, Expr::text("")), Stmt::Break],
                    )],
                    otherwise: vec![],
                },
                Stmt::Assign(Place::Global(GlobalId::new(0)), local(arg)),
                set(dest, local(arg)),
                Stmt::Break,
            ],
            span: None,
            step: vec![],
        },
    ]
}

#[test]
fn a_function_that_loops_is_called_and_a_recursive_one_spliced_once() {
    let recursive = Function {
        params: 0,
        slots: 0,
        body: Body::Native(vec![
            Stmt::Eval(Expr::Call(FunctionId::new(0), vec![])),
            Stmt::Return(Some(Expr::Number(1.0))),
        ]),
        starts_undefined: false,
        returns: None,
        origin: FunctionId::new(0),
        uses_arguments: false,
        uses_this: false,
    };
    let loops = Function {
        params: 0,
        slots: 0,
        body: Body::Native(vec![Stmt::While { cond: Expr::Bool(false), body: vec![], span: None, step: vec![] }]),
        starts_undefined: false,
        returns: None,
        origin: FunctionId::new(1),
        uses_arguments: false,
        uses_this: false,
    };
    let mut body = vec![set(0, Expr::Call(FunctionId::new(0), vec![])), set(1, Expr::Call(FunctionId::new(1), vec![]))];
    small_functions(&[recursive, loops], &mut body);
    let want = vec![
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![Stmt::Eval(Expr::Call(FunctionId::new(0), vec![])), set(0, Expr::Number(1.0)), Stmt::Break],
            span: None,
            step: vec![],
        },
        set(1, Expr::Call(FunctionId::new(1), vec![])),
    ];
    assert_eq!(body, want);
}

#[test]
fn falling_off_the_end_returns_null_and_locals_start_null() {
    let f = Function {
        params: 0,
        slots: 1,
        body: Body::Native(vec![Stmt::Eval(local(0))]),
        starts_undefined: false,
        returns: None,
        origin: FunctionId::new(0),
        uses_arguments: false,
        uses_this: false,
    };
    let mut body = vec![set(0, Expr::Call(FunctionId::new(0), vec![]))];
    small_functions(&[f], &mut body);
    let want = vec![
        set(1, Expr::Null),
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![Stmt::Eval(local(1)), set(0, Expr::Null), Stmt::Break],
            span: None,
            step: vec![],
        },
    ];
    assert_eq!(body, want);
}

#[test]
fn a_call_chosen_into_a_local_is_spliced_into_an_if() {
    let choose = |a: Expr, b: Expr| Expr::Choose(Box::new(local(5)), Box::new(a), Box::new(b));
    let call = Expr::Call(FunctionId::new(0), vec![Expr::text("G1")]);
    let mut body = vec![set(0, choose(call, Expr::text(""))), set(1, choose(local(2), local(3)))];
    small_functions(&[motion()], &mut body);
    let want = vec![
        Stmt::If { branches: vec![(local(5), motion_spliced(6, 0))], otherwise: vec![set(0, Expr::text(""))] },
        // No call in it: the choice stays.
        set(1, choose(local(2), local(3))),
    ];
    assert_eq!(body, want);
}
