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
    // Siemens, Heidenhain ISO: G71 millimetres, G70 inches, read when no
    // G20 or G21 is written (a Fanuc lathe's G71 is a turning cycle).
    assert_eq!(scan("G90G17G71G90.1").only(), Some(Units::Mm));
    assert_eq!(scan(" G17 G90 G94 G70 G40").only(), Some(Units::Inch));
    assert_eq!(scan("G20 ... G71 U1. R.5").only(), Some(Units::Inch));
    assert_eq!(scan("G70 P10 Q20 ... G71 U1.").only(), None);
    assert_eq!(scan("G710 G71.1").only(), None);
    assert_eq!(scan("G21").word(Units::Inch), "G20");
    assert_eq!(scan("G71").word(Units::Inch), "G70");
}
