use crate::modules::prepare::testing::{local, set};
use postc_ir::{BinaryOp, LocalId, Place};
use postc_runtime::exec::{Expr, Piece, Stmt, WordsBefore};
use postc_runtime::testing::prepare_unshift::*;

fn k(i: u16) -> LocalId {
    LocalId::new(i)
}

fn word(w: u16, before: WordsBefore) -> Stmt {
    Stmt::Word {
        cond: Expr::LocalEmpty { local: k(w), op: BinaryOp::JsNe },
        word: vec![Piece::Expr(local(w))],
        sep: vec![b' '],
        before,
    }
}

fn leave(cond: Expr, m: u16) -> Stmt {
    Stmt::If { branches: vec![(cond, vec![Stmt::Truncate(k(m)), Stmt::Break])], otherwise: vec![] }
}

fn number() -> Stmt {
    Stmt::Emit(vec![Piece::Text(b"N".to_vec()), Piece::Expr(Expr::Global(postc_ir::GlobalId::new(0)))])
}

/// `writeBlock` counting its words, in a loop run once, after mark 9.
fn counted(leaving_mark: u16) -> Vec<Stmt> {
    let count = WordsBefore::Count(k(4));
    vec![
        Stmt::Mark(k(9)),
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![
                Stmt::Mark(k(5)),
                set(4, Expr::Number(0.0)),
                word(1, count),
                word(2, count),
                leave(count_is_zero(k(4)), leaving_mark),
                Stmt::Mark(k(6)),
                number(),
                Stmt::If {
                    branches: vec![(count_is_positive(k(4)), vec![Stmt::Emit(vec![Piece::Text(b" ".to_vec())])])],
                    otherwise: vec![],
                },
                Stmt::MoveBack { to: k(5), from: k(6) },
                set(4, Expr::Binary(BinaryOp::Add, Box::new(local(4)), Box::new(Expr::Number(1.0)))),
                Stmt::Emit(vec![Piece::Text(b"\n".to_vec())]),
                Stmt::Break,
            ],
            span: None,
            step: vec![],
        },
    ]
}

fn inner(body: &[Stmt]) -> &[Stmt] {
    match &body[1] {
        Stmt::While { body, .. } => body,
        other => panic!("a loop: {other:?}"),
    }
}

#[test]
fn a_counted_block_writes_its_number_first() {
    let mut body = counted(9);
    block_numbers(&mut body);
    let body = inner(&body);
    assert_eq!(
        body[0],
        Stmt::Emit(vec![
            Piece::Text(b"N".to_vec()),
            Piece::Expr(Expr::Global(postc_ir::GlobalId::new(0))),
            Piece::Text(b" ".to_vec())
        ])
    );
    // Mark 5 is read by nobody any more; the words follow.
    assert_eq!(body[1], set(4, Expr::Number(0.0)));
    assert!(!body.iter().any(|s| matches!(s, Stmt::MoveBack { .. } | Stmt::Mark(_))), "{body:?}");
    // The count is no longer counted up after the words.
    let stores = body.iter().filter(|s| matches!(s, Stmt::Assign(Place::Local(c), _) if *c == k(4))).count();
    assert_eq!(stores, 1, "{body:?}");
}

#[test]
fn a_block_asking_the_output_keeps_its_mark_after_the_number() {
    let asked = WordsBefore::Written(k(5));
    let mut body = vec![
        Stmt::Mark(k(9)),
        Stmt::While {
            cond: Expr::Bool(true),
            body: vec![
                Stmt::Mark(k(5)),
                word(1, asked),
                word(2, asked),
                leave(Expr::Unary(postc_ir::UnaryOp::Not, Box::new(Expr::Written(k(5)))), 9),
                Stmt::Mark(k(6)),
                number(),
                Stmt::MoveBack { to: k(5), from: k(6) },
                Stmt::Break,
            ],
            span: None,
            step: vec![],
        },
    ];
    block_numbers(&mut body);
    let body = inner(&body);
    assert_eq!(body[0], number());
    assert_eq!(body[1], Stmt::Mark(k(5)));
    assert!(!body.iter().any(|s| matches!(s, Stmt::MoveBack { .. })), "{body:?}");
}

#[test]
fn a_leaving_mark_not_set_before_keeps_the_move() {
    // Mark 7 is never set on the way: dropping to it might keep the number.
    let mut body = counted(7);
    block_numbers(&mut body);
    assert_eq!(body, counted(7));
    // Text dropped between the mark and the block: the same.
    let mut body = counted(9);
    body.insert(1, Stmt::Truncate(k(3)));
    let before = body.clone();
    block_numbers(&mut body);
    assert_eq!(body, before);
}

#[test]
fn a_word_that_calls_or_a_mark_read_later_keeps_the_move() {
    let mut body = counted(9);
    if let Stmt::While { body, .. } = &mut body[1] {
        body[2] = Stmt::Word {
            cond: Expr::Bool(true),
            word: vec![Piece::Expr(Expr::Call(postc_ir::FunctionId::new(0), vec![]))],
            sep: vec![b' '],
            before: WordsBefore::Count(k(4)),
        };
    }
    let before = body.clone();
    block_numbers(&mut body);
    assert_eq!(body, before);
    let mut body = counted(9);
    body.push(Stmt::Truncate(k(5)));
    let before = body.clone();
    block_numbers(&mut body);
    assert_eq!(body, before);
}
