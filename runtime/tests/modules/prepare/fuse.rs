use crate::modules::prepare::testing::local;
use postc_ir::{BinaryOp, Builtin, LocalId, Place, UnaryOp};
use postc_runtime::exec::{Expr, Piece, Stmt, WordRun, WordsBefore};
use postc_runtime::testing::prepare_fuse::*;

fn not_empty(e: Expr) -> Expr {
    Expr::Binary(BinaryOp::JsNe, Box::new(e), Box::new(Expr::text("")))
}

fn counted(word: u16, n: u16, zero: f64) -> Stmt {
    Stmt::If {
        branches: vec![(
            not_empty(local(word)),
            vec![
                Stmt::If {
                    branches: vec![(
                        Expr::Binary(BinaryOp::JsGt, Box::new(local(n)), Box::new(Expr::Number(zero))),
                        vec![Stmt::Emit(vec![Piece::Text(b" ".to_vec())])],
                    )],
                    otherwise: vec![],
                },
                Stmt::Emit(vec![Piece::Expr(local(word))]),
                Stmt::Assign(
                    Place::Local(LocalId::new(n)),
                    Expr::Binary(BinaryOp::Add, Box::new(local(n)), Box::new(Expr::Number(1.0))),
                ),
            ],
        )],
        otherwise: vec![],
    }
}

#[test]
fn a_counted_word_is_fused_and_a_near_miss_is_not() {
    let mut body = vec![Stmt::While {
        cond: Expr::Bool(true),
        body: vec![counted(2, 9, 0.0), counted(3, 9, 1.0)],
        span: None,
        step: vec![],
    }];
    stmts(&mut body);
    let Stmt::While { body, .. } = &body[0] else { panic!() };
    assert!(
        matches!(&body[0], Stmt::Word { before: WordsBefore::Count(k), sep, .. } if sep == b" " && k.index() == 9),
        "{:?}",
        body[0]
    );
    // `n > 1` is not the shape: left as it is.
    assert_eq!(body[1], counted(3, 9, 1.0));
}

#[test]
fn a_word_after_written_text_is_fused() {
    let m = LocalId::new(4);
    let w = vec![Piece::Expr(local(1))];
    let stmt = Stmt::If {
        branches: vec![(
            not_empty(local(1)),
            vec![Stmt::If {
                branches: vec![(
                    Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(m))),
                    vec![Stmt::Truncate(m), Stmt::Emit(w.clone())],
                )],
                otherwise: vec![Stmt::Emit(vec![Piece::Text(b" ".to_vec()), Piece::Expr(local(1))])],
            }],
        )],
        otherwise: vec![],
    };
    let mut body = vec![stmt];
    stmts(&mut body);
    assert_eq!(
        body[0],
        Stmt::Word { cond: not_empty(local(1)), word: w, sep: b" ".to_vec(), before: WordsBefore::Written(m) }
    );
}

#[test]
fn chains_of_and_and_or_become_lists() {
    let (a, b, c) = (local(0), local(1), local(2));
    let and = |x: Expr, y: Expr| Expr::Binary(BinaryOp::And, Box::new(x), Box::new(y));
    let or = |x: Expr, y: Expr| Expr::Binary(BinaryOp::Or, Box::new(x), Box::new(y));
    let mut body = vec![Stmt::Eval(or(and(and(a.clone(), b.clone()), c.clone()), a.clone()))];
    expressions(&mut body);
    let all = Expr::Chain { all: true, operands: vec![a.clone(), b, c] };
    assert_eq!(body, vec![Stmt::Eval(Expr::Chain { all: false, operands: vec![all, a] })]);
}

#[test]
fn parse_float_of_a_cut_text_becomes_one_expression() {
    let cut = |k: f64| {
        Expr::Builtin(Builtin::ParseFloat, vec![Expr::Builtin(Builtin::Substring, vec![local(0), Expr::Number(k)])])
    };
    let mut body = vec![Stmt::Eval(cut(1.0)), Stmt::Eval(cut(1.5)), Stmt::Eval(cut(-1.0))];
    expressions(&mut body);
    assert_eq!(body[0], Stmt::Eval(Expr::ParseFloatFrom { value: Box::new(local(0)), from: 1 }));
    assert_eq!(body[1..], [Stmt::Eval(cut(1.5)), Stmt::Eval(cut(-1.0))]);
    // `+parseFloat(...)`: parseFloat gives a number, the `+` goes.
    let mut body = vec![Stmt::Eval(Expr::Unary(UnaryOp::Plus, Box::new(cut(1.0))))];
    expressions(&mut body);
    assert_eq!(body[0], Stmt::Eval(Expr::ParseFloatFrom { value: Box::new(local(0)), from: 1 }));
}

#[test]
fn empty_and_typeof_tests_of_a_local_become_one_expression() {
    let typeof_is = |op, name: &str| {
        Expr::Binary(op, Box::new(Expr::Unary(UnaryOp::Typeof, Box::new(local(2)))), Box::new(Expr::text(name)))
    };
    let mut body = vec![Stmt::If {
        branches: vec![(
            Expr::Binary(
                BinaryOp::And,
                Box::new(typeof_is(BinaryOp::StrictEq, "string")),
                Box::new(not_empty(local(1))),
            ),
            vec![Stmt::Eval(typeof_is(BinaryOp::JsEq, "string")), Stmt::Eval(typeof_is(BinaryOp::StrictNe, "number"))],
        )],
        otherwise: vec![],
    }];
    expressions(&mut body);
    let want = vec![Stmt::If {
        branches: vec![(
            Expr::Chain {
                all: true,
                operands: vec![
                    Expr::LocalIsText { local: LocalId::new(2), is: true },
                    Expr::LocalEmpty { local: LocalId::new(1), op: BinaryOp::JsNe },
                ],
            },
            // Near misses stay as they are.
            vec![Stmt::Eval(typeof_is(BinaryOp::JsEq, "string")), Stmt::Eval(typeof_is(BinaryOp::StrictNe, "number"))],
        )],
        otherwise: vec![],
    }];
    assert_eq!(body, want);
}

fn word_of(w: u16, before: WordsBefore, sep: &[u8]) -> Stmt {
    Stmt::Word {
        cond: Expr::LocalEmpty { local: LocalId::new(w), op: BinaryOp::JsNe },
        word: vec![Piece::Expr(local(w))],
        sep: sep.to_vec(),
        before,
    }
}

#[test]
fn a_run_of_words_becomes_one_statement_with_the_if_of_an_empty_block() {
    let (n, m) = (LocalId::new(9), LocalId::new(8));
    // Counted (`n = 0 ... if (n == 0)`) and asked of the output
    // (`mark n ... if (!written(n))`).
    let forms = [
        (
            WordsBefore::Count(n),
            Stmt::Assign(Place::Local(n), Expr::Number(0.0)),
            Expr::Binary(BinaryOp::JsEq, Box::new(Expr::Local(n)), Box::new(Expr::Number(0.0))),
        ),
        (WordsBefore::Written(n), Stmt::Mark(n), Expr::Unary(UnaryOp::Not, Box::new(Expr::Written(n)))),
    ];
    for (before, start, none_printed) in forms {
        let empty =
            Stmt::If { branches: vec![(none_printed, vec![Stmt::Truncate(m), Stmt::Break])], otherwise: vec![] };
        let general = vec![start, word_of(1, before, b" "), word_of(2, before, b" "), empty];
        let mut body = vec![Stmt::While {
            cond: Expr::Bool(true),
            body: [general.clone(), vec![Stmt::Break]].concat(),
            span: None,
            step: vec![],
        }];
        runs(&mut body);
        let want = WordRun {
            general,
            locals: vec![LocalId::new(1), LocalId::new(2)],
            sep: b" ".to_vec(),
            before,
            empty: Some(m),
        };
        let Stmt::While { body, .. } = &body[0] else { panic!() };
        assert_eq!(body.as_slice(), [Stmt::Words(Box::new(want)), Stmt::Break]);
    }
}

#[test]
fn near_misses_of_a_run_stay_as_they_are() {
    let n = LocalId::new(9);
    let count = WordsBefore::Count(n);
    let start = Stmt::Assign(Place::Local(n), Expr::Number(0.0));
    let cases = [
        // One word: nothing to gain.
        vec![start.clone(), word_of(1, count, b" ")],
        // Two separators.
        vec![start.clone(), word_of(1, count, b" "), word_of(2, count, b",")],
        // Another count.
        vec![start.clone(), word_of(1, WordsBefore::Count(LocalId::new(7)), b" "), word_of(2, count, b" ")],
        // The count started at 1.
        vec![Stmt::Assign(Place::Local(n), Expr::Number(1.0)), word_of(1, count, b" "), word_of(2, count, b" ")],
    ];
    for case in cases {
        let mut body = case.clone();
        runs(&mut body);
        assert_eq!(body, case);
    }
    // A word of a test on another local ends the run.
    let mut other = word_of(3, count, b" ");
    if let Stmt::Word { cond, .. } = &mut other {
        *cond = Expr::Local(LocalId::new(4));
    }
    let mut body = vec![start, word_of(1, count, b" "), word_of(2, count, b" "), other.clone()];
    runs(&mut body);
    assert!(matches!(&body[0], Stmt::Words(run) if run.locals.len() == 2 && run.empty.is_none()));
    assert_eq!(body[1], other);
}
