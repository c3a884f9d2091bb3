use postc_runtime::testing::value::*;
use postc_runtime::value::*;

#[test]
fn numbers_join_text_as_javascript_writes_them() {
    let text = |n: f64| Value::Num(n).to_text().as_str().to_string();
    assert_eq!(text(f64::INFINITY), "Infinity");
    assert_eq!(text(f64::NEG_INFINITY), "-Infinity");
    assert_eq!(text(f64::NAN), "NaN");
    assert_eq!(text(1e21), "1e+21");
    assert_eq!(text(1e-7), "1e-7");
    assert_eq!(text(0.000001), "0.000001");
    assert_eq!(text(-0.0), "0");
    assert_eq!(text(123.456), "123.456");
    assert_eq!(text(1e20), "100000000000000000000");
}

#[test]
fn a_value_is_three_words_and_short_text_is_in_place() {
    assert_eq!(std::mem::size_of::<Value>(), 24);
    let short = Text::new("X12.3456");
    assert!(matches!(short.repr(), Repr::Inline(8, _)));
    assert_eq!(short.as_str(), "X12.3456");
    let long = Text::new("a text longer than twenty-two bytes");
    assert!(matches!(long.repr(), Repr::Shared(_)));
    let mut out = b"N1 ".to_vec();
    short.append_to_bytes(&mut out);
    long.append_to_bytes(&mut out);
    Text::new("").append_to_bytes(&mut out);
    assert_eq!(out, b"N1 X12.3456a text longer than twenty-two bytes");
    let mut padded = [0; INLINE_TEXT];
    padded[..3].copy_from_slice(b"G01");
    assert_eq!(Text::from_padded(&padded, 2), Text::new("G0"));
    assert_eq!(Text::from_padded(&padded, 2).as_bytes(), b"G0");
    padded[..2].copy_from_slice("é".as_bytes());
    assert_eq!(Text::from_padded(&padded, 2).as_str(), "é");
    let accented = Text::new("été");
    assert!(matches!(accented.repr(), Repr::Shared(_)));
    assert_eq!(Text::new(""), Text::from(String::new()));
    assert!(Text::new("G0") < Text::new("G1"));
    assert_eq!(Text::from_bytes(b"\xffA").as_str(), "\u{fffd}A");
}
