use crate::modules::prepare::testing::{local, set};
use postc_ir::{LocalId, Place};
use postc_runtime::exec::{Expr, Stmt};
use postc_runtime::testing::prepare_fresh::*;

fn nulls(body: Vec<Stmt>) -> Vec<u16> {
    start_nulls(body)
        .iter()
        .map_while(|s| match s {
            Stmt::Assign(Place::Local(k), Expr::Null) => Some(k.index() as u16),
            _ => None,
        })
        .collect()
}

fn when(c: Expr, then: Vec<Stmt>, otherwise: Vec<Stmt>) -> Stmt {
    Stmt::If { branches: vec![(c, then)], otherwise }
}

fn once(body: Vec<Stmt>) -> Stmt {
    Stmt::While { cond: Expr::Bool(true), body, span: None, step: vec![] }
}

#[test]
fn a_local_written_before_it_is_read_needs_no_null() {
    let body = vec![set(0, Expr::Number(1.0)), Stmt::Eval(local(0))];
    assert_eq!(nulls(body), Vec::<u16>::new());
}

#[test]
fn a_local_read_first_on_some_path_starts_null() {
    // var s; if (a) s = "M8"; return s;
    let body =
        vec![set(1, Expr::Bool(true)), when(local(1), vec![set(0, Expr::text("M8"))], vec![]), Stmt::Eval(local(0))];
    assert_eq!(nulls(body), vec![0]);
}

#[test]
fn both_arms_assigning_or_an_arm_leaving_count_as_assigned() {
    let both = vec![
        when(Expr::Bool(false), vec![set(0, Expr::Number(1.0))], vec![set(0, Expr::Number(2.0))]),
        Stmt::Eval(local(0)),
    ];
    assert_eq!(nulls(both), Vec::<u16>::new());
    // while (true) { if (c) { s = ""; break } s = "G1"; break } read s
    let spliced = vec![
        once(vec![
            when(Expr::Bool(false), vec![set(0, Expr::text("")), Stmt::Break], vec![]),
            set(0, Expr::text("G1")),
            Stmt::Break,
        ]),
        Stmt::Eval(local(0)),
    ];
    assert_eq!(nulls(spliced), Vec::<u16>::new());
}

#[test]
fn a_loop_that_may_not_run_assigns_nothing_after_it() {
    let body = vec![
        Stmt::While { cond: Expr::Bool(false), body: vec![set(0, Expr::Number(1.0))], span: None, step: vec![] },
        Stmt::Eval(local(0)),
    ];
    assert_eq!(nulls(body), vec![0]);
}

#[test]
fn leading_nulls_are_replaced_by_the_needed_ones() {
    let body =
        vec![set(3, Expr::Null), set(0, Expr::Number(1.0)), Stmt::Eval(local(0)), Stmt::Truncate(LocalId::new(2))];
    let out = start_nulls(body);
    assert_eq!(out[0], set(2, Expr::Null));
    assert_eq!(out[1], set(0, Expr::Number(1.0)));
    assert_eq!(out.len(), 4);
}
