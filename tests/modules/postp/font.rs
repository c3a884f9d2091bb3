use postc_postp::font::*;

#[test]
fn every_glyph_is_on_the_grid() {
    for (i, glyph) in GLYPHS.iter().enumerate() {
        for stroke in glyph.split_ascii_whitespace() {
            assert!(stroke.len() % 2 == 0 && !stroke.is_empty(), "glyph {i}: {stroke}");
            for p in stroke.as_bytes().chunks_exact(2) {
                assert!((b'0'..=b'4').contains(&p[0]) && (b'0'..=b'8').contains(&p[1]), "glyph {i}: {stroke}");
            }
        }
        let c = char::from_u32(i as u32 + 32).unwrap();
        assert!(c == ' ' || !strokes(c).unwrap().is_empty(), "{c} has no strokes");
    }
    assert!(strokes('\u{e9}').is_none());
    assert_eq!(strokes('L').unwrap(), vec![vec![(0.0, 6.0), (0.0, 0.0), (4.0, 0.0)]]);
}
