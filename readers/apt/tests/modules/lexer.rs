use postc_reader_apt::testing::lexer::*;
use postc_reader_apt::testing::lines::Lines;

fn lex(text: &str) -> Vec<(RawKind, String, (usize, usize))> {
    let mut lexer = Lexer::new(Lines::new(text.as_bytes()));
    let mut out = Vec::new();
    while let Some(kind) = lexer.next().unwrap() {
        out.push((kind, String::from_utf8_lossy(lexer.record()).into_owned(), lexer.span()));
    }
    out
}

#[test]
fn continuation_and_comments() {
    let got = lex("CIRCLE / 1, 2, 3,  $\r\n0, 0, 1, 5\n$$-> CSYS / 1, 0,  $\n   0, 1\nRAPID \n");
    assert_eq!(got[0].0, RawKind::Statement);
    assert_eq!(got[0].1, "CIRCLE / 1, 2, 3,   0, 0, 1, 5");
    assert_eq!(got[1].0, RawKind::Comment);
    assert_eq!(got[1].1, "-> CSYS / 1, 0,   0, 1");
    assert_eq!(got[2].1, "RAPID");
}

#[test]
fn bare_numbers_join_the_record_before() {
    let got = lex("CUTTER/1,2,\n3\nGOTO/1,2\n3\n");
    assert_eq!(got[0].1, "CUTTER/1,2,3");
    assert_eq!(got[1].1, "GOTO/1,2,3");
    assert_eq!(got.len(), 2);
}
