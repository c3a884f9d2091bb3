use postc_reader_apt::testing::number::*;

#[test]
fn numbers_read_the_apt_way() {
    for (text, value) in [
        ("5.", 5.0),
        (".5", 0.5),
        ("-.5", -0.5),
        ("+1", 1.0),
        ("1.E-3", 0.001),
        ("1.5D2", 150.0),
        ("-16.1677728056", -16.1677728056),
        ("0.1000000191", 0.1000000191),
        ("12345678901234567890.5", 12345678901234567890.5),
        ("0.000000000000000000000000123", 1.23e-25),
    ] {
        assert_eq!(parse_number(text.as_bytes()), Some(value), "{text}");
    }
    for text in ["INF", "NAN", "1STPECK", "-", ".", "1.2.3x", "--1"] {
        assert_eq!(parse_number(text.as_bytes()), None, "{text}");
    }
}
