use postc_front_vcpost::ast::{CommentKind, SubKeyword, TipSlot};
use postc_front_vcpost::keywords::*;
use postc_front_vcpost::lexer::Comment;
use postc_ir::{FileId, Span};

fn comment(text: &str) -> Comment {
    Comment { text: text.to_string(), text_start: 1, span: Span::new(FileId(0), 0, text.len() + 1), whole_line: true }
}

#[test]
fn reads_keywords_params_and_tips() {
    let kc = read(&comment(" #Cycle !X !Y  Width"), FileId(0)).unwrap();
    assert_eq!(kc.kind, CommentKind::Keyword(SubKeyword::Cycle));
    let names: Vec<_> = kc.params.iter().map(|p| (p.name.as_str(), p.mandatory, p.span.start)).collect();
    assert_eq!(names, vec![("X", true, 9), ("Y", true, 12), ("Width", false, 16)]);
    let tip = read(&comment("  #c1 Operator message "), FileId(0)).unwrap();
    assert_eq!(tip.kind, CommentKind::Tip(TipSlot::C1, "Operator message".into()));
    assert!(read(&comment(" #1 roughing"), FileId(0)).is_none());
    assert!(read(&comment(" plain"), FileId(0)).is_none());
}
