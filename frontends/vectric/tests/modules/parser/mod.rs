use postc_front_vectric::ast::{ItemKind, TextPiece, VarBody};
use postc_front_vectric::parse;
use postc_ir::{Diagnostic, FileId};

fn items(text: &str) -> (Vec<ItemKind>, Vec<Diagnostic>) {
    let (post, diags) = parse(text, FileId(0));
    (post.items.into_iter().map(|i| i.kind).collect(), diags)
}

#[test]
fn every_bad_line_is_reported_and_parsing_goes_on() {
    let text = "VAR X_POSITION [X|A|X|1.3]\n\"G0 [300]\"\nbegin\n\"G1[X]\"\nVAR Y_POSITION = [Y|Q|Y|1.3]\n";
    let (items, diags) = items(text);
    assert_eq!(items.len(), 5);
    let errors: Vec<(&str, usize)> =
        diags.iter().filter(|d| d.is_error()).map(|d| (d.code, d.labels[0].span.start)).collect();
    assert_eq!(errors, vec![("PP001", 0), ("PP008", 31), ("PP013", 38), ("PP004", 72)]);
    assert!(matches!(&items[3], ItemKind::Output(q) if q.closed && q.pieces.len() == 2));
}

#[test]
fn output_pieces() {
    let (items, diags) = items("  \"G0[X][13][10]x\"  + comment\r\n");
    assert!(diags.is_empty(), "{diags:?}");
    let ItemKind::Output(q) = &items[0] else { panic!("{items:?}") };
    let pieces: Vec<&TextPiece> = q.pieces.iter().map(|p| &p.value).collect();
    assert_eq!(
        pieces,
        [
            &TextPiece::Text("G0".into()),
            &TextPiece::Label("X".into()),
            &TextPiece::Code(13),
            &TextPiece::Code(10),
            &TextPiece::Text("x".into())
        ]
    );
}

#[test]
fn keywords_in_any_case_and_prefix_blanks_kept() {
    let (items, diags) = items("var X_POSITION = [X|c| X |1.3]\nBEGIN header\n");
    assert!(diags.is_empty(), "{diags:?}");
    let ItemKind::Var(v) = &items[0] else { panic!("{items:?}") };
    let VarBody::Fields(f) = &v.body else { panic!("{v:?}") };
    assert_eq!(f.prefix.value, " X ");
    assert!(matches!(&items[1], ItemKind::Begin(b) if b.words[0].value == "header"));
}

#[test]
fn script_block_runs_to_endscript() {
    let (items, diags) = items("SCRIPT\r\nlocal a = 1\r\nENDSCRIPT\r\n\"G0\"\r\n");
    assert!(diags.is_empty(), "{diags:?}");
    assert!(matches!(&items[0], ItemKind::ScriptBlock(code) if code.value == "local a = 1"));
    assert!(matches!(&items[1], ItemKind::Output(_)));
}
