use lsp_types::Position;
use postc_lsp::text::*;

#[test]
fn positions_count_utf16_units() {
    // 'ü' is 2 bytes and 1 UTF-16 unit, '𝄞' is 4 bytes and 2 units.
    let text = "ab\n\"Pièce 𝄞 [X]\"\r\nend";
    let x = text.find('X').unwrap();
    assert_eq!(position(text, x), Position::new(1, 11));
    assert_eq!(offset(text, Position::new(1, 11)), x);
    assert_eq!(position(text, text.len()), Position::new(2, 3));
    assert_eq!(offset(text, Position::new(9, 0)), text.len());
    assert_eq!(offset(text, Position::new(0, 99)), 2);
}

#[test]
fn edit_distances() {
    assert_eq!(edit_distance("FEED_MOVEE", "FEED_MOVE"), 1);
    assert_eq!(edit_distance("header", "HEADER"), 0);
    assert_eq!(edit_distance("", "ab"), 2);
}
