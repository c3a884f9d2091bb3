//! Tests of the line parser.

mod recover;

use postc_front_vcpost::ast::{BinaryOp, ExprKind, StmtKind, UnaryOp};
use postc_front_vcpost::lexer::lex;
use postc_front_vcpost::parser::{LineItem, parse_lines};
use postc_ir::FileId;

fn lines(text: &str) -> (Vec<Vec<LineItem>>, usize) {
    let lexed = lex(text, FileId(0));
    let (lines, diags) = parse_lines(&lexed.tokens, &lexed.spoiled, text.len(), FileId(0));
    (lines, diags.len() + lexed.diagnostics.len())
}

fn assigned_value(text: &str) -> postc_front_vcpost::ast::Expr {
    let (lines, errors) = lines(text);
    assert_eq!(errors, 0, "{text}");
    match &lines[0][0] {
        LineItem::Stmt(s) => match &s.kind {
            StmtKind::Assign { value, .. } => value.clone(),
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    }
}

#[test]
fn basic_precedence() {
    let e = assigned_value("X = -2 ^ 2");
    assert!(
        matches!(e.kind, ExprKind::Unary(UnaryOp::Neg, ref inner) if matches!(inner.kind, ExprKind::Binary(BinaryOp::Pow, ..)))
    );
    let e = assigned_value("X = Not A = B And C");
    let ExprKind::Binary(BinaryOp::And, l, _) = e.kind else { panic!() };
    assert!(
        matches!(l.kind, ExprKind::Unary(UnaryOp::Not, ref inner) if matches!(inner.kind, ExprKind::Binary(BinaryOp::Eq, ..)))
    );
    let e = assigned_value("X = \"a\" & 1 + 2");
    assert!(
        matches!(e.kind, ExprKind::Binary(BinaryOp::Concat, _, ref r) if matches!(r.kind, ExprKind::Binary(BinaryOp::Add, ..)))
    );
    let e = assigned_value("X = 7 Mod 4 \\ 2");
    assert!(
        matches!(e.kind, ExprKind::Binary(BinaryOp::Mod, _, ref r) if matches!(r.kind, ExprKind::Binary(BinaryOp::IntDiv, ..)))
    );
    let e = assigned_value("X = 2 ^ -1");
    assert!(
        matches!(e.kind, ExprKind::Binary(BinaryOp::Pow, _, ref r) if matches!(r.kind, ExprKind::Unary(UnaryOp::Neg, _)))
    );
}

#[test]
fn statements_and_headers() {
    let (lines, errors) = lines(
        "Sub GOTO\nIf (Z < Z.Previous) Then\nOut \"<N><X>\"\nElse If A Then B = 1 Else C\nEnd If\nEnd Sub\nX.Format = \"4.3\" : Call Foo(1, 2) : Foo 1, 2\nSelect Case T\nCase 1, 2 To 3, Is > 4\nCase Else\nEnd Select\nFor I = 1 To 10 Step 2\nNext I\nDo Until A\nLoop\nWhile A\nWend",
    );
    assert_eq!(errors, 0);
    assert!(matches!(lines[0][0], LineItem::ProcStart { .. }));
    assert!(matches!(lines[1][0], LineItem::IfStart { .. }));
    assert!(matches!(lines[3][0], LineItem::Else { .. }));
    assert!(matches!(lines[3][1], LineItem::Stmt(_)));
    assert_eq!(lines[6].len(), 3);
    assert!(matches!(lines[8][0], LineItem::Case { ref tests, .. } if tests.len() == 3));
}

#[test]
fn a_bad_line_does_not_stop_the_next() {
    let (lines, errors) = lines("X = 1 2\nIf X > Then\nY = 3\nEnd\n");
    assert_eq!(errors, 3);
    assert!(matches!(&lines[0][0], LineItem::Stmt(s) if s.kind == StmtKind::Error));
    assert!(matches!(lines[1][0], LineItem::IfStart { .. }), "the If line keeps its shape");
    assert!(matches!(&lines[2][0], LineItem::Stmt(s) if matches!(s.kind, StmtKind::Assign { .. })));
}
