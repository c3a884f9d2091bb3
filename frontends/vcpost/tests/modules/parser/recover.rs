use postc_front_vcpost::parser::LineItem;
use postc_front_vcpost::testing::parser_recover::*;
use postc_front_vcpost::token::Op;
use postc_front_vcpost::token::{Kw, Token};
use postc_ir::FileId;
use postc_ir::Span;

#[test]
fn block_lines_keep_their_shape() {
    let span = Span::new(FileId(0), 0, 1);
    let kinds = |tokens: &[Token]| line(tokens, span);
    assert!(matches!(kinds(&[Token::Kw(Kw::If), Token::Error, Token::Kw(Kw::Then)])[0], LineItem::IfStart { .. }));
    assert!(matches!(kinds(&[Token::Kw(Kw::If), Token::Error])[0], LineItem::Stmt(_)));
    assert!(matches!(
        &kinds(&[Token::Kw(Kw::Sub), Token::Ident("A".into()), Token::Error])[0],
        LineItem::ProcStart { name, .. } if name.text == "A"
    ));
    assert!(matches!(kinds(&[Token::Kw(Kw::Next), Token::Number(1.0)])[0], LineItem::Next { .. }));
    assert!(matches!(kinds(&[Token::Op(Op::Eq)])[0], LineItem::Stmt(_)));
}
