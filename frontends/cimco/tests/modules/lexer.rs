use postc_front_cimco::lexer::*;
use postc_front_cimco::token::{Punct, TokenKind};
use postc_ir::FileId;

fn kinds(text: &str) -> Vec<TokenKind<'_>> {
    let (tokens, diags) = lex(text, FileId(0));
    assert!(diags.is_empty(), "{diags:?}");
    tokens.into_iter().map(|(t, _)| t.kind).collect()
}

#[test]
fn regex_or_division() {
    assert!(matches!(kinds("s.replace(/a\\/b[/]/g, \"\")")[4], TokenKind::Regex { pattern: "a\\/b[/]", flags: "g" }));
    assert_eq!(kinds("a / b / c")[1], TokenKind::Punct(Punct::Slash));
    assert_eq!(kinds("(a) / 2")[3], TokenKind::Punct(Punct::Slash));
    assert!(matches!(kinds("return /x/")[1], TokenKind::Regex { .. }));
    assert_eq!(kinds("x /= 2")[1], TokenKind::Punct(Punct::SlashAssign));
}

#[test]
fn numbers() {
    assert_eq!(kinds("0x1F 1.5e3 .25 7.")[..4], [31.0, 1500.0, 0.25, 7.0].map(TokenKind::Number));
}

#[test]
fn newline_flags() {
    let (tokens, _) = lex("a /* \n */ b // c\n c d", FileId(0));
    let flags: Vec<bool> = tokens.iter().map(|(t, _)| t.newline_before).collect();
    assert_eq!(flags, [false, true, true, false]);
}

#[test]
fn longest_punctuator() {
    assert_eq!(
        kinds("a >>>= b === c ?.5 : d"),
        [
            TokenKind::Ident("a"),
            TokenKind::Punct(Punct::UShrAssign),
            TokenKind::Ident("b"),
            TokenKind::Punct(Punct::StrictEq),
            TokenKind::Ident("c"),
            TokenKind::Punct(Punct::Question),
            TokenKind::Number(0.5),
            TokenKind::Punct(Punct::Colon),
            TokenKind::Ident("d"),
        ]
    );
}

#[test]
fn problems_are_reported_and_skipped() {
    let (tokens, diags) = lex("a # \"open\n 0x 1e 3mm `t` /* x", FileId(0));
    let codes: Vec<&str> = diags.iter().map(|d| d.code).collect();
    assert_eq!(codes, ["JS001", "JS002", "JS005", "JS005", "JS005", "JS004"]);
    assert_eq!(tokens.len(), 6);
}
