//! Formatter tests: every flag, rounding on the decimal value, and a
//! property test against an exact decimal reference.

use postc_ir::{Justify, NumberFormat, Padding, PointStyle, Rounding, SignStyle, WidthOf};
use postc_runtime::number::*;
use proptest::prelude::*;

fn vectric(spec: &str) -> NumberFormat {
    // A tiny reader of Vectric format specs for tests: flags, width, separator, decimals.
    let mut f = NumberFormat::default();
    let mut chars = spec.chars().peekable();
    while let Some(&c) = chars.peek() {
        match c {
            '-' => f.justify = Justify::Left,
            '+' => f.sign = SignStyle::Always,
            '0' => f.padding = Padding::Zero,
            '#' => f.point = PointStyle::Always,
            _ => break,
        }
        chars.next();
    }
    let rest: String = chars.collect();
    let sep = rest.find(['.', ',']).unwrap();
    f.width = rest[..sep].parse().unwrap_or(1);
    f.decimal_mark = rest.as_bytes()[sep] as char;
    f.decimals = rest[sep + 1..].parse().unwrap();
    f
}

fn fmt(spec: &str, v: f64) -> String {
    let mut out = Vec::new();
    NumberWriter::new(&vectric(spec)).write(v, &mut out);
    String::from_utf8(out).unwrap()
}

#[test]
fn rounds_on_the_decimal_value() {
    assert_eq!(fmt("1.2", 2.675), "2.68");
    assert_eq!(fmt("1.2", 1.005), "1.01");
    assert_eq!(fmt("1.4", 8.49655), "8.4966");
    assert_eq!(fmt("1.4", 1.04675), "1.0468");
    assert_eq!(fmt("1.1", 0.25), "0.3");
    assert_eq!(fmt("1.0", 2.5), "3");
    assert_eq!(fmt("1.0", -2.5), "-3");
    assert_eq!(fmt("1.3", 1e-4), "0.000");
    assert_eq!(fmt("1.2", 0.125), "0.13");
    assert_eq!(fmt("1.4", 0.92178), "0.9218");
}

fn binary(decimals: u8, v: f64) -> String {
    let f = NumberFormat { decimals, rounding: Rounding::Binary, ..NumberFormat::default() };
    let mut out = Vec::new();
    NumberWriter::new(&f).write(v, &mut out);
    String::from_utf8(out).unwrap()
}

/// CIMCO formats round the binary double as JavaScript's `toFixed` does.
#[test]
fn binary_rounding_is_javascripts_to_fixed() {
    assert_eq!(binary(2, 1.005), "1.00");
    assert_eq!(binary(2, 2.675), "2.67");
    assert_eq!(binary(2, -2.675), "-2.67");
    assert_eq!(binary(3, 1.0005), "1.000");
    assert_eq!(binary(4, 8.49655), "8.4965");
    // Exact binary ties round away from zero (toFixed picks the larger n).
    assert_eq!(binary(2, 0.125), "0.13");
    assert_eq!(binary(1, 0.25), "0.3");
    assert_eq!(binary(0, 2.5), "3");
    assert_eq!(binary(0, -2.5), "-3");
    assert_eq!(binary(1, 0.35), "0.3");
    // The slow path (past 1e14 scaled): exact too.
    assert_eq!(binary(2, 1e13 + 0.125), "10000000000000.13");
    assert_eq!(binary(3, 123456789012.0005), "123456789012.001");
    assert_eq!(binary(3, 123456789012.0004), "123456789012.000");
}

/// A value that is not a finite number prints nothing and is reported.
#[test]
fn values_that_are_not_finite_print_nothing_and_are_reported() {
    assert_eq!(postc_runtime::number::take_non_finite(), None);
    for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(binary(1, v), "");
        assert_eq!(postc_runtime::number::take_non_finite().map(f64::to_bits), Some(v.to_bits()));
        assert_eq!(fmt("1.3", v), "");
        assert!(postc_runtime::number::take_non_finite().is_some());
    }
    // A finite value that the multiplier makes infinite too.
    let f = NumberFormat { decimals: 1, multiplier: 1e308, ..NumberFormat::default() };
    let mut out = Vec::new();
    NumberWriter::new(&f).write(10.0, &mut out);
    assert!(out.is_empty() && postc_runtime::number::take_non_finite() == Some(10.0));
    assert_eq!(fmt("1.3", 1.0), "1.000");
    assert_eq!(postc_runtime::number::take_non_finite(), None);
}

#[test]
fn negative_zero_has_no_sign() {
    assert_eq!(fmt("1.3", -0.0), "0.000");
    assert_eq!(fmt("1.3", -0.0004), "0.000");
    assert_eq!(fmt("1.3", -0.0005), "-0.001");
    assert_eq!(fmt("+1.3", -0.0004), "+0.000");
}

/// Vectric's engine keeps the minus of a negative value that rounds to
/// zero (`Z-0.000`, docs/vectric.md); zero itself has no sign, -0.0 (a
/// zero times a multiplier of -1) included.
#[test]
fn negative_zero_keeps_its_sign_when_asked() {
    let f = |spec: &str, v: f64| {
        let mut out = Vec::new();
        NumberWriter::new(&NumberFormat { negative_zero: true, ..vectric(spec) }).write(v, &mut out);
        String::from_utf8(out).unwrap()
    };
    assert_eq!(f("1.3", -0.0004), "-0.000");
    assert_eq!(f("1.3", -1e-9), "-0.000");
    assert_eq!(f("1.3", -0.0), "0.000");
    assert_eq!(f("1.3", 0.0004), "0.000");
    assert_eq!(f("+1.3", -0.0004), "-0.000");
    assert_eq!(f("07.3", -0.0004), "-00.000");
    assert_eq!(f("1.0", -0.4), "-0");
    let w = NumberWriter::new(&NumberFormat { negative_zero: true, ..vectric("1.3") });
    assert_ne!(w.round(-0.0004), w.round(0.0004), "modal memory tells -0.000 from 0.000");
}

#[test]
fn flags_and_widths() {
    assert_eq!(fmt("1.3", 12.5), "12.500");
    assert_eq!(fmt("8.3", 12.5), "  12.500");
    assert_eq!(fmt("08.3", -12.5), "-012.500");
    assert_eq!(fmt("-8.3", 12.5), "12.500  ");
    assert_eq!(fmt("+1.3", 12.5), "+12.500");
    assert_eq!(fmt("+1.3", -12.5), "-12.500");
    assert_eq!(fmt("1.0", 12.0), "12");
    assert_eq!(fmt("#1.0", 12.0), "12.");
    assert_eq!(fmt("1,3", -1.25), "-1,250");
    assert_eq!(fmt("+09,3", 1.25), "+0001,250");
    assert_eq!(fmt("02.0", 7.0), "07");
    assert_eq!(fmt("1.0", 0.0), "0");
}

#[test]
fn multiplier_applies_before_rounding() {
    let mut f = vectric("1.0");
    f.multiplier = 40.0;
    let mut out = Vec::new();
    NumberWriter::new(&f).write(2.45666 * 25.4, &mut out);
    assert_eq!(out, b"2496");
    let mut f = vectric("1.3");
    f.multiplier = 57.2957795;
    out.clear();
    NumberWriter::new(&f).write(std::f64::consts::FRAC_PI_2, &mut out);
    assert_eq!(out, b"90.000");
}

#[test]
fn trimmed_zeros_and_integer_digit_width() {
    let f = NumberFormat { decimals: 3, trim_zeros: true, ..NumberFormat::default() };
    let w = NumberWriter::new(&f);
    let mut out = Vec::new();
    for (v, want) in [(80.0, "80"), (80.5, "80.5"), (-0.25, "-0.25"), (1.0004, "1")] {
        out.clear();
        w.write(v, &mut out);
        assert_eq!(out, want.as_bytes());
    }
    let f = NumberFormat {
        decimals: 0,
        width: 4,
        width_of: WidthOf::IntegerDigits,
        padding: Padding::Zero,
        prefix: "N".into(),
        ..NumberFormat::default()
    };
    out.clear();
    NumberWriter::new(&f).write(1.0, &mut out);
    assert_eq!(out, b"N0001");
    let f = NumberFormat { decimals: 3, trim_zeros: true, point: PointStyle::Always, ..NumberFormat::default() };
    out.clear();
    NumberWriter::new(&f).write(80.0, &mut out);
    assert_eq!(out, b"80.");
    let f = NumberFormat { decimals: 3, trim_zeros: true, leading_zero: false, ..NumberFormat::default() };
    out.clear();
    NumberWriter::new(&f).write(-0.5, &mut out);
    assert_eq!(out, b"-.5");
}

#[test]
fn huge_and_odd_values_do_not_panic() {
    for v in [f64::MAX, -f64::MAX, f64::MIN_POSITIVE, f64::NAN, f64::INFINITY, 1e300, 123456789012345678.0] {
        for spec in ["1.0", "1.3", "+020.6", "-#1.15"] {
            let _ = fmt(spec, v);
        }
    }
    assert_eq!(fmt("1.0", 1e20), "100000000000000000000");
    assert_eq!(fmt("1.2", 99.995), "100.00");
    assert_eq!(fmt("1.2", 9.995), "10.00");
}

#[test]
fn printed_value_reads_back() {
    let w = NumberWriter::new(&vectric("1.4"));
    assert_eq!(w.printed_value(8.49655), 8.4966);
    assert_eq!(w.printed_value(-1.04675), -1.0468);
}

/// Reference: round the shortest decimal text of `v` half away from zero.
fn reference(v: f64, decimals: usize) -> String {
    reference_of(v, decimals, format!("{}", v.abs()))
}

/// Reference for `Rounding::Binary`: round the exact decimal expansion of
/// the double half away from zero (JavaScript's `toFixed`).
fn reference_binary(v: f64, decimals: usize) -> String {
    reference_of(v, decimals, format!("{:.1100}", v.abs()))
}

fn reference_of(v: f64, decimals: usize, text: String) -> String {
    let (int, frac) = text.split_once('.').unwrap_or((&text, ""));
    let mut digits: Vec<u8> = int.bytes().chain(frac.bytes().chain(std::iter::repeat(b'0')).take(decimals)).collect();
    if frac.as_bytes().get(decimals).is_some_and(|&d| d >= b'5') {
        let mut i = digits.len();
        loop {
            if i == 0 {
                digits.insert(0, b'1');
                break;
            }
            i -= 1;
            if digits[i] == b'9' {
                digits[i] = b'0';
            } else {
                digits[i] += 1;
                break;
            }
        }
    }
    let split = digits.len() - decimals;
    let mut s = String::from_utf8(digits[..split].to_vec()).unwrap();
    let s_trim = s.trim_start_matches('0');
    s = if s_trim.is_empty() { "0".into() } else { s_trim.into() };
    let f = String::from_utf8(digits[split..].to_vec()).unwrap();
    let zero = s == "0" && f.bytes().all(|b| b == b'0');
    let sign = if v < 0.0 && !zero { "-" } else { "" };
    if decimals == 0 { format!("{sign}{s}") } else { format!("{sign}{s}.{f}") }
}

proptest! {
    #[test]
    fn matches_exact_decimal_rounding(v in -1e9f64..1e9, decimals in 0usize..8) {
        let f = NumberFormat { decimals: decimals as u8, ..NumberFormat::default() };
        let mut out = Vec::new();
        NumberWriter::new(&f).write(v, &mut out);
        prop_assert_eq!(String::from_utf8(out).unwrap(), reference(v, decimals));
    }

    #[test]
    fn binary_matches_exact_binary_rounding(v in -1e12f64..1e12, decimals in 0usize..10) {
        prop_assert_eq!(binary(decimals as u8, v), reference_binary(v, decimals));
    }

    #[test]
    fn binary_matches_on_short_decimals(n in -10_000_000i64..10_000_000, scale in 1u32..7, decimals in 0usize..6) {
        let v = n as f64 / 10f64.powi(scale as i32);
        prop_assert_eq!(binary(decimals as u8, v), reference_binary(v, decimals));
    }

    #[test]
    fn matches_on_short_decimals(n in -10_000_000i64..10_000_000, scale in 1u32..7, decimals in 0usize..6) {
        // Values written with few decimals: ties like 2.675 are common here.
        let v = n as f64 / 10f64.powi(scale as i32);
        let f = NumberFormat { decimals: decimals as u8, ..NumberFormat::default() };
        let mut out = Vec::new();
        NumberWriter::new(&f).write(v, &mut out);
        prop_assert_eq!(String::from_utf8(out).unwrap(), reference(v, decimals));
    }

    #[test]
    fn fast_path_writes_what_the_general_path_writes(
        n in -10_000_000i64..10_000_000,
        scale in 0u32..7,
        decimals in 0u8..7,
        trim in any::<bool>(),
        leading_zero in any::<bool>(),
        point_always in any::<bool>(),
        sign_always in any::<bool>(),
        comma in any::<bool>(),
        negative_zero in any::<bool>(),
    ) {
        // Trimmed formats (CIMCO's default) take the right-to-left writer
        // too: every flag it reads against the assembling writer.
        let v = n as f64 / 10f64.powi(scale as i32);
        let f = NumberFormat {
            decimals,
            trim_zeros: trim,
            leading_zero,
            point: if point_always { PointStyle::Always } else { PointStyle::default() },
            sign: if sign_always { SignStyle::Always } else { SignStyle::default() },
            decimal_mark: if comma { ',' } else { '.' },
            negative_zero,
            ..NumberFormat::default()
        };
        let w = NumberWriter::new(&f);
        prop_assert!(w.plain);
        let (mut fast, mut general) = (Vec::new(), Vec::new());
        w.write(v, &mut fast);
        w.write_slow(v, &mut general);
        prop_assert_eq!(String::from_utf8(fast).unwrap(), String::from_utf8(general).unwrap());
    }
}

proptest! {
    #[test]
    fn a_word_made_into_text_is_the_word_written(
        n in -1_000_000_000_000i64..1_000_000_000_000,
        scale in 0u32..9,
        decimals in 0u8..7,
        trim in any::<bool>(),
        prefix in "[A-Z]{0,3}|é|[A-Z]{12,16}",
        format_prefix in "[A-Z]{0,2}",
        width in 0u8..4,
    ) {
        // What a handler's `xOutput.format(x)` keeps as a value is what the
        // fast path writes into a block, short or long, ASCII or not; a
        // padded format has no word (the caller writes it).
        let v = n as f64 / 10f64.powi(scale as i32);
        let f = NumberFormat { decimals, trim_zeros: trim, prefix: format_prefix, width, ..NumberFormat::default() };
        let w = NumberWriter::new(&f);
        let Some(r) = w.round(v) else { return Ok(()) };
        let mut written = Vec::new();
        w.write_rounded_after(prefix.as_bytes(), r, &mut written);
        match w.word_text(prefix.as_bytes(), r) {
            Some(text) => prop_assert_eq!(text.as_bytes(), &written[..]),
            None => prop_assert!(!w.plain || prefix.len() + f.prefix.len() > 16),
        }
    }
}

proptest! {
    #[test]
    fn an_integer_is_appended_as_display_writes_it(n in any::<i64>(), before in "[A-Z]{0,3}") {
        let mut out = before.as_bytes().to_vec();
        push_integer(&mut out, n);
        prop_assert_eq!(String::from_utf8(out).unwrap(), format!("{before}{n}"));
    }
}
