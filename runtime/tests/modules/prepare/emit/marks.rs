use crate::modules::prepare::testing::set;
use postc_ir::LocalId;
use postc_runtime::exec::{Expr, Piece, Stmt};
use postc_runtime::testing::prepare_emit_marks::*;

fn once(body: Vec<Stmt>) -> Stmt {
    Stmt::While { cond: Expr::Bool(true), body, span: None, step: vec![] }
}

fn m(i: u16) -> LocalId {
    LocalId::new(i)
}

#[test]
fn a_truncate_with_nothing_written_since_its_mark_goes_at_any_depth() {
    // mark 0; while (true) { x = 1; if (c) { truncate 0; break } truncate 0; emit; break }
    let leave =
        Stmt::If { branches: vec![(Expr::Bool(false), vec![Stmt::Truncate(m(0)), Stmt::Break])], otherwise: vec![] };
    let emit = Stmt::Emit(vec![Piece::Text(b"G1".to_vec())]);
    let body = vec![
        Stmt::Mark(m(0)),
        once(vec![
            set(1, Expr::Number(1.0)),
            leave,
            Stmt::Truncate(m(0)),
            emit.clone(),
            Stmt::Truncate(m(0)),
            Stmt::Break,
        ]),
    ];
    let quiet = Stmt::If { branches: vec![(Expr::Bool(false), vec![Stmt::Break])], otherwise: vec![] };
    assert_eq!(
        drop_truncates(body),
        vec![Stmt::Mark(m(0)), once(vec![set(1, Expr::Number(1.0)), quiet, emit, Stmt::Truncate(m(0)), Stmt::Break])]
    );
}

#[test]
fn a_loop_that_may_run_again_keeps_its_truncates() {
    let emit = Stmt::Emit(vec![Piece::Text(b"G1".to_vec())]);
    let body = vec![
        Stmt::Mark(m(0)),
        Stmt::While { cond: Expr::Bool(false), body: vec![Stmt::Truncate(m(0)), emit], span: None, step: vec![] },
    ];
    assert_eq!(drop_truncates(body.clone()), body);
}
