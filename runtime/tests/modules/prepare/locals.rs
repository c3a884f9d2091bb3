use crate::modules::prepare::testing::{local, set};
use postc_ir::BinaryOp;
use postc_runtime::exec::Piece;
use postc_runtime::exec::{Expr, Stmt};
use postc_runtime::testing::prepare_locals::*;

fn emit(e: Expr) -> Stmt {
    Stmt::Emit(vec![Piece::Expr(e)])
}

fn call() -> Expr {
    Expr::Call(postc_ir::FunctionId::new(0), vec![])
}

#[test]
fn a_copy_is_read_through_and_dropped() {
    let body = vec![set(0, call()), set(1, local(0)), emit(local(1))];
    assert_eq!(tidy(body), vec![set(0, call()), emit(local(0))]);
}

#[test]
fn a_copy_stops_at_a_write_of_its_source() {
    // `b = a; a = f(); emit b` must print the old `a`.
    let body = vec![set(0, call()), set(1, local(0)), set(0, call()), emit(local(1)), emit(local(0))];
    assert_eq!(tidy(body.clone()), body);
}

#[test]
fn a_constant_folds_a_switch() {
    let is = |k: f64| Expr::Binary(BinaryOp::StrictEq, Box::new(local(0)), Box::new(Expr::Number(k)));
    let body = vec![
        set(0, Expr::Number(1.0)),
        Stmt::If {
            branches: vec![(is(0.0), vec![emit(Expr::text("G0"))]), (is(1.0), vec![emit(Expr::text("G1"))])],
            otherwise: vec![],
        },
    ];
    assert_eq!(tidy(body), vec![Stmt::Emit(vec![Piece::Text(b"G1".to_vec())])]);
}

#[test]
fn defaults_assigned_on_every_path_are_dropped() {
    let cond = Expr::Binary(BinaryOp::JsNe, Box::new(local(0)), Box::new(Expr::text("")));
    let body = vec![
        set(0, call()),
        set(1, Expr::Null),
        Stmt::If { branches: vec![(cond.clone(), vec![set(1, call())])], otherwise: vec![set(1, call())] },
        emit(local(1)),
    ];
    let want = vec![
        set(0, call()),
        Stmt::If { branches: vec![(cond, vec![set(1, call())])], otherwise: vec![set(1, call())] },
        emit(local(1)),
    ];
    assert_eq!(tidy(body), want);
}

#[test]
fn a_default_set_again_in_a_loop_that_runs_once_is_dropped() {
    // `x = null; while (true) { if (f()) { x = ""; break } x = g(); break } emit x`
    let once = Stmt::While {
        cond: Expr::Bool(true),
        body: vec![
            Stmt::If { branches: vec![(call(), vec![set(1, Expr::text("")), Stmt::Break])], otherwise: vec![] },
            set(1, call()),
            Stmt::Break,
        ],
        span: None,
        step: vec![],
    };
    let body = vec![set(1, Expr::Null), once.clone(), emit(local(1))];
    assert_eq!(tidy(body), vec![once, emit(local(1))]);
}

#[test]
fn a_store_read_after_a_loop_or_at_its_head_stays() {
    // `n = 0; while (n < 3) { n = n + 1 }; emit n`: every store is read.
    let less = Expr::Binary(BinaryOp::JsLt, Box::new(local(0)), Box::new(Expr::Number(3.0)));
    let step = Expr::Binary(BinaryOp::Sub, Box::new(local(0)), Box::new(Expr::Number(-1.0)));
    let body = vec![
        set(0, call()),
        Stmt::While { cond: less, body: vec![set(0, step)], span: None, step: vec![] },
        emit(local(0)),
    ];
    assert_eq!(tidy(body.clone()), body);
}

#[test]
fn a_store_read_after_break_stays() {
    let body = vec![
        set(0, call()),
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![
                set(1, local(0)),
                Stmt::If { branches: vec![(call(), vec![Stmt::Break])], otherwise: vec![] },
                set(1, Expr::Number(2.0)),
                Stmt::Break,
            ],
            span: None,
            step: vec![],
        },
        emit(local(1)),
    ];
    assert_eq!(tidy(body.clone()), body);
}
