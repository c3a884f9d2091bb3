use postc_front_vcpost::lexer::*;
use postc_front_vcpost::token::{Kw, Op, Token};
use postc_ir::FileId;

fn kinds(text: &str) -> Vec<Token> {
    lex(text, FileId(0)).tokens.into_iter().map(|(t, _)| t).collect()
}

#[test]
fn words_numbers_strings() {
    let toks = kinds("If x$ >= .5E1 Then Out \"a\"\"b\"");
    assert_eq!(
        toks,
        vec![
            Token::Kw(Kw::If),
            Token::Ident("x".into()),
            Token::Op(Op::Ge),
            Token::Number(5.0),
            Token::Kw(Kw::Then),
            Token::Kw(Kw::Out),
            Token::Str("a\"b".into()),
        ]
    );
}

#[test]
fn comments_and_continuation() {
    let lexed = lex("X = 1 _\r\n  + 2 ' tail\n' #Init A\nREM whole\nRemark = 1", FileId(0));
    let toks: Vec<Token> = lexed.tokens.into_iter().map(|(t, _)| t).collect();
    assert_eq!(toks.iter().filter(|t| **t == Token::Newline).count(), 3);
    assert_eq!(lexed.comments.len(), 3);
    assert!(!lexed.comments[0].whole_line);
    assert!(lexed.comments[1].whole_line);
    assert_eq!(lexed.comments[1].text, " #Init A");
    assert_eq!(lexed.comments[2].text, " whole");
    assert!(toks.contains(&Token::Ident("Remark".into())));
}

#[test]
fn bad_characters_spoil_only_their_line() {
    let lexed = lex("X = 1 # 2\nY = \"open\nZ = [End]", FileId(0));
    assert_eq!(lexed.diagnostics.len(), 2);
    assert_eq!(lexed.spoiled.len(), 1);
    let toks: Vec<Token> = lexed.tokens.into_iter().map(|(t, _)| t).collect();
    assert_eq!(toks[3], Token::Error);
    assert_eq!(toks[8], Token::Str("open".into()));
    assert_eq!(toks[12], Token::Ident("End".into()));
}

#[test]
fn deep_parentheses_are_refused() {
    let text = format!("X = {}1{}", "(".repeat(40), ")".repeat(40));
    let lexed = lex(&text, FileId(0));
    assert_eq!(lexed.diagnostics.len(), 1);
    assert_eq!(lexed.tokens.len(), 3);
    assert_eq!(lexed.tokens[1].0, Token::Error);
}
