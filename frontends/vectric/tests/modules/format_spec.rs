use postc_front_vectric::format_spec::*;
use postc_ir::{Justify, Padding, PointStyle, SignStyle, WidthOf};

fn spec(text: &str) -> FormatSpec {
    parse_format(text).unwrap_or_else(|e| panic!("{text}: {}", e.message))
}

#[test]
fn plain_width_and_decimals() {
    let s = spec("1.3");
    assert_eq!((s.width, s.decimals, s.separator, s.has_separator), (1, 3, '.', true));
    assert!(!s.left && !s.plus && !s.zero && !s.point);
    assert_eq!(spec("1.0").decimals, 0);
}

#[test]
fn flags() {
    let s = spec("-#5.0");
    assert!(s.left && s.point && !s.plus && !s.zero);
    assert_eq!((s.width, s.decimals), (5, 0));
    let s = spec("+0#-8.2");
    assert!(s.left && s.point && s.plus && s.zero);
    assert_eq!((s.width, s.decimals), (8, 2));
}

#[test]
fn comma_separator() {
    let s = spec("+1,3");
    assert!(s.plus);
    assert_eq!((s.width, s.separator, s.decimals), (1, ',', 3));
}

#[test]
fn leading_zero_width_pads_with_zeros() {
    let s = spec("02.0");
    assert!(s.zero);
    assert_eq!((s.width, s.decimals), (2, 0));
    let s = spec("0.3");
    assert!(!s.zero);
    assert_eq!((s.width, s.decimals), (0, 3));
    let s = spec("00.3");
    assert!(s.zero);
    assert_eq!(s.width, 0);
}

#[test]
fn blanks_around_are_allowed() {
    assert_eq!(spec(" 1.4 "), spec("1.4"));
}

#[test]
fn missing_separator_reads_whole_numbers() {
    let s = spec("3");
    assert!(!s.has_separator);
    assert_eq!((s.width, s.decimals), (3, 0));
}

#[test]
fn lowering_to_number_format() {
    let f = spec("-+0#6,2").to_number_format(0.5);
    assert_eq!(f.justify, Justify::Left);
    assert_eq!(f.sign, SignStyle::Always);
    assert_eq!(f.padding, Padding::Zero);
    assert_eq!(f.point, PointStyle::Always);
    assert_eq!((f.width, f.decimals, f.decimal_mark, f.multiplier), (6, 2, ',', 0.5));
    assert_eq!(f.width_of, WidthOf::Whole);
    assert!(!f.trim_zeros && f.leading_zero);
}

#[test]
fn bad_formats_are_errors() {
    for bad in ["", "X", "1.3.4", "1.a", "1.99", "300.1", "F1.0", "1.3 2"] {
        assert!(parse_format(bad).is_err(), "{bad:?} should be rejected");
    }
    let e = parse_format("1.99").unwrap_err();
    assert!(e.message.contains("at most 15"), "{}", e.message);
    assert_eq!(e.range, 2..4);
}
