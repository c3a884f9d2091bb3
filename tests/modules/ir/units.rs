use postc_ir::units::*;

#[test]
fn units_words_are_g_words() {
    let scan = |text: &str| {
        let mut w = WrittenUnits::default();
        w.scan(text.as_bytes());
        w
    };
    assert_eq!(scan("G90 G17 G21 G40").only(), Some(Units::Mm));
    assert_eq!(scan("N10G20").only(), Some(Units::Inch));
    assert_eq!(scan("g21").only(), Some(Units::Mm));
    for text in ["G2 X1", "G210", "G21.1", "MSG21", "G1 X21", "G02"] {
        assert_eq!(scan(text), WrittenUnits::default(), "{text}");
    }
    assert_eq!(scan("G20 ... G21").only(), None);
}
