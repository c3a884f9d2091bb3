use postc_runtime::js::*;
use proptest::prelude::*;

proptest! {
    #[test]
    fn short_decimals_read_as_the_full_parse_reads_them(n in 0u64..1_000_000_000_000_000, point in 0usize..17) {
        let digits = n.to_string();
        let text = if point < digits.len() { format!("{}.{}", &digits[..point], &digits[point..]) } else { format!("{digits}.") };
        let full: f64 = text.parse().unwrap();
        prop_assert_eq!(parse_float(&text).to_bits(), full.to_bits(), "{}", text);
        prop_assert_eq!(parse_float(&format!("-{text}x")).to_bits(), (-full).to_bits());
        for signed in [text.clone(), format!("-{text}"), format!("+{text}")] {
            let short = parse_short_decimal(signed.as_bytes());
            prop_assert_eq!(short.map(f64::to_bits), Some(parse_float(&signed).to_bits()), "{}", signed);
        }
    }
}

#[test]
fn numbers_print_as_javascript_prints_them() {
    let cases = [
        (1.0, "1"),
        (-2.5, "-2.5"),
        (0.1 + 0.2, "0.30000000000000004"),
        (1e21, "1e+21"),
        (123456789012345680000.0, "123456789012345680000"),
        (1e-7, "1e-7"),
        (0.000001, "0.000001"),
        (1.5e-10, "1.5e-10"),
        (f64::NAN, "NaN"),
        (-0.0, "0"),
    ];
    for (n, text) in cases {
        assert_eq!(number_to_string(n), text, "{n}");
    }
}

#[test]
fn text_reads_as_javascript_reads_it() {
    assert_eq!(text_to_number(" 12.5 "), 12.5);
    assert_eq!(text_to_number(""), 0.0);
    assert!(text_to_number("12mm").is_nan());
    assert_eq!(text_to_number("0x1F"), 31.0);
    assert_eq!(parse_float("12.5mm"), 12.5);
    assert!(parse_float("mm").is_nan());
    assert_eq!(parse_int("  42px", 0.0), 42.0);
    assert_eq!(parse_int("0x10", 0.0), 16.0);
    assert_eq!(parse_int("-7.9", 10.0), -7.0);
}

#[test]
fn to_fixed_rounds_the_binary_value() {
    assert_eq!(to_fixed(2.675, 2.0), "2.67");
    assert_eq!(to_fixed(2.5, 0.0), "3");
    assert_eq!(to_fixed(-2.5, 0.0), "-3");
    assert_eq!(to_fixed(1.0, 3.0), "1.000");
    // Node.js: (-0.0001).toFixed(2) is "-0.00", (-0).toFixed(2) "0.00".
    assert_eq!(to_fixed(-0.0001, 2.0), "-0.00");
    assert_eq!(to_fixed(-0.0, 2.0), "0.00");
    assert_eq!(to_fixed(0.125, 2.0), "0.13");
    // A carry past the first digit, as Node.js prints it.
    assert_eq!(to_fixed(9.999, 2.0), "10.00");
    assert_eq!(to_fixed(999.96, 1.0), "1000.0");
    assert_eq!(to_precision(99.99, 2.0).as_deref(), Ok("1.0e+2"));
    assert_eq!(to_precision(0.0999, 2.0).as_deref(), Ok("0.10"));
}

#[test]
fn rounding_and_integers() {
    assert_eq!(math_round(2.5), 3.0);
    assert_eq!(math_round(-2.5), -2.0);
    assert_eq!(math_round(0.49999999999999994), 0.0);
    assert_eq!(to_int32(4294967297.0), 1);
    assert_eq!(to_int32(-1.0), -1);
    assert_eq!(to_uint32(-1.0), 4294967295);
}

#[test]
fn a_key_names_an_element_only_as_javascript_writes_the_index() {
    assert_eq!(array_index(Key::Number(1.0)), Some(1));
    assert_eq!(array_index(Key::Number(-0.0)), Some(0));
    assert_eq!(array_index(Key::Text("12")), Some(12));
    // Node.js: [5, 6][true], [5, 6]["01"], [5, 6][" 1"], [5, 6][1.5] are undefined.
    for key in [Key::Other, Key::Text("01"), Key::Text(" 1"), Key::Text("1.0"), Key::Text("+1"), Key::Text("")] {
        assert_eq!(array_index(key), None, "{key:?}");
    }
    assert_eq!(array_index(Key::Number(1.5)), None);
    assert_eq!(array_index(Key::Number(-1.0)), None);
    assert_eq!(array_index(Key::Number(4_294_967_295.0)), None);
}

#[test]
fn an_error_text_gives_the_name_and_message_of_its_object() {
    assert_eq!(error_parts("ReferenceError: out is not defined"), Some(("ReferenceError", "out is not defined")));
    assert_eq!(error_parts("TypeError: cannot read property 'x' of undefined").map(|p| p.0), Some("TypeError"));
    assert_eq!(error_parts("the post stopped"), None);
}

/// Texts order by their UTF-16 units, as JavaScript's `<` and `sort()`
/// order them: a character past U+FFFF (two surrogate units from U+D800)
/// comes before U+E000..U+FFFF, though its UTF-8 bytes come after.
#[test]
fn texts_order_by_utf16_units() {
    use std::cmp::Ordering::*;
    assert_eq!(compare_text("a", "b"), Less);
    assert_eq!(compare_text("ab", "a"), Greater);
    assert_eq!(compare_text("\u{E000}", "\u{1F600}"), Greater);
    assert_eq!(compare_text("\u{D7FF}", "\u{1F600}"), Less);
    assert_eq!(compare_text("é", "z"), Greater);
    assert_eq!(compare_text("\u{1F600}", "\u{1F600}"), Equal);
}

/// The primitive operators: `==` converts to numbers unless both are
/// texts, null and undefined equal each other only; `===` never
/// converts; `<` and friends compare texts as texts and NaN with nothing.
#[test]
fn primitive_operators_are_javascripts() {
    use Primitive::*;
    assert!(loose_equals(Text("0x10"), Number(16.0)));
    assert!(loose_equals(Bool(true), Text("1")));
    assert!(loose_equals(Null, Undefined));
    assert!(!loose_equals(Null, Number(0.0)));
    assert!(!loose_equals(Text("1.0"), Text("1")));
    assert!(!strict_equals(Text("1"), Number(1.0)));
    assert!(!strict_equals(Null, Undefined));
    assert!(!loose_equals(Number(f64::NAN), Number(f64::NAN)));
    assert_eq!(order(Text("10"), Text("9")), Some(std::cmp::Ordering::Less));
    assert_eq!(order(Text("10"), Number(9.0)), Some(std::cmp::Ordering::Greater));
    assert_eq!(order(Undefined, Number(0.0)), None);
    assert_eq!(order(Null, Number(0.0)), Some(std::cmp::Ordering::Equal));
    assert!(Text(" ").truthy() && !Text("").truthy() && !Number(f64::NAN).truthy());
    let mut out = String::new();
    for p in [Number(1e21), Bool(false), Null, Undefined, Text("x")] {
        p.push_text(&mut out);
    }
    assert_eq!(out, "1e+21falsenullundefinedx");
}
