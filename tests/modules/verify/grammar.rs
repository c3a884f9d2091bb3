use chumsky::inspector::TruncateState;
use chumsky::prelude::*;
use postc_verify::grammar::*;

fn words(text: &str) -> Result<Vec<(ItemKind, String, f64, u8)>, usize> {
    let mut items = TruncateState(Vec::new());
    parse(text.as_bytes(), &mut items)?;
    Ok(items
        .iter()
        .map(|i| (i.kind, text[i.start as usize..i.end as usize].to_string(), i.value, i.decimals))
        .collect())
}

#[test]
fn blocks_of_every_shape() {
    let w = words("N10 G1X-1.5 y2. Z.25 F1200 (cut) ; rest").unwrap();
    assert_eq!(w.len(), 8);
    assert_eq!(w[0].0, ItemKind::Word(b'N'));
    assert_eq!(w[2].2, -1.5);
    assert_eq!(w[2].3, 1);
    assert_eq!(w[3].0, ItemKind::Word(b'Y'));
    assert_eq!(w[3].2, 2.0);
    assert_eq!(w[4].2, 0.25);
    assert_eq!(w[5].3, 0);
    assert_eq!(w[6].0, ItemKind::Comment);
    assert_eq!(w[7].1, "; rest");
    assert_eq!(words("/G0 X1").unwrap()[0].0, ItemKind::Delete);
    assert_eq!(words("%").unwrap()[0].0, ItemKind::Percent);
    assert_eq!(words("").unwrap().len(), 0);
    assert_eq!(words("G90.1").unwrap()[0].2, 90.1);
    assert_eq!(words("X10,250Y-2,5").unwrap()[1].2, -2.5);
    assert_eq!(words("X10,250").unwrap()[0].3, 3);
    assert_eq!(words("X 1.0\r").unwrap()[0].2, 1.0);
}

/// The chumsky grammar alone: what [`parse`] gives for every line.
fn by_grammar(text: &[u8]) -> Result<Vec<Item>, usize> {
    let mut items = TruncateState(Vec::new());
    match line().parse_with_state(text, &mut items).into_result() {
        Ok(()) => Ok(items.0),
        Err(errors) => Err(errors.first().map_or(0, |e| e.span().start)),
    }
}

/// Pieces of program lines: words as posts print them, blanks,
/// comments, and the bytes only the grammar reads.
fn piece() -> impl proptest::strategy::Strategy<Value = String> {
    use proptest::prelude::*;
    let letter = proptest::char::ranges(vec!['A'..='Z', 'a'..='z'].into());
    let number = (any::<bool>(), 0u64..100_000, 0usize..5, any::<bool>()).prop_map(|(neg, m, d, comma)| {
        let digits = m.to_string();
        let sign = if neg { "-" } else { "" };
        match d {
            0 => format!("{sign}{digits}"),
            _ if d >= digits.len() => format!("{sign}.{digits}"),
            _ => {
                let (a, b) = digits.split_at(digits.len() - d);
                format!("{sign}{a}{}{b}", if comma { ',' } else { '.' })
            }
        }
    });
    prop_oneof![
        6 => (letter, " {0,2}", number).prop_map(|(l, b, n)| format!("{l}{b}{n}")),
        3 => " {1,3}|\\t|\\r".prop_map(String::from),
        1 => "\\([ -~]{0,12}\\)".prop_map(String::from),
        1 => ";[ -~]{0,12}".prop_map(String::from),
        1 => "[%/:#=\\[\\]().,+\\-0-9A-Z]".prop_map(String::from),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4000))]
    /// The fast path and the grammar give the same items, or the same error.
    #[test]
    fn the_fast_path_reads_as_the_grammar_does(pieces in proptest::collection::vec(piece(), 0..12)) {
        let text = pieces.concat();
        let mut items = TruncateState(Vec::new());
        let parsed = parse(text.as_bytes(), &mut items).map(|()| items.0.clone());
        proptest::prop_assert_eq!(parsed, by_grammar(text.as_bytes()), "{:?}", text);
        let mut plain_items = Vec::new();
        if plain(text.as_bytes(), &mut plain_items) {
            proptest::prop_assert_eq!(Ok(plain_items), by_grammar(text.as_bytes()), "{:?}", text);
        }
    }

    /// The two-loop number scan reads every number as the digit-by-digit one does.
    #[test]
    fn the_fast_number_scan_reads_as_the_long_one(text in "[-+]?[0-9]{0,22}([.,][0-9]{0,22})?[.,X0-9]?") {
        let fast = scan_number(text.as_bytes());
        let long = scan_long(text.as_bytes());
        proptest::prop_assert_eq!(fast.map(|(n, v, d)| (n, v.to_bits(), d)), long.map(|(n, v, d)| (n, v.to_bits(), d)), "{:?}", text);
    }

    /// Numbers followed by the rest of a program (what the 8-byte reads of
    /// `scan_at` see), anywhere in it: read as the byte-at-a-time scan and
    /// the digit-by-digit one read them.
    #[test]
    fn the_eight_byte_number_scan_reads_as_the_others(
        before in "[ -~]{0,3}",
        number in "[-+]?[0-9]{0,9}([.,][0-9]{0,9})?",
        after in "[-+.,:/ A-Z0-9\n\r\t\x00\x7f\u{e9}]{0,12}",
    ) {
        let text = format!("{before}{number}{after}");
        let (s, at) = (text.as_bytes(), before.len());
        let eight = scan_at(s, at).map(|(n, v, d)| (n, v.to_bits(), d));
        let bytes = scan_bytes(s, at).map(|(n, v, d)| (n, v.to_bits(), d));
        let long = scan_long(&s[at..]).map(|(n, v, d)| (at + n, v.to_bits(), d));
        proptest::prop_assert_eq!(eight, bytes, "{:?}", text);
        proptest::prop_assert_eq!(eight, long, "{:?}", text);
    }
}

#[test]
fn plain_lines_take_the_fast_path() {
    for line in ["N10 G1 X-1.5 Y2. Z.25 F1200", "G0X1Y2", "G1 X1 (cut) ; rest", "X10,250Y-2,5", "x 1.0\r", ""] {
        assert!(plain(line.as_bytes(), &mut Vec::new()), "{line}");
    }
    for line in ["/G0 X1", "%", ":1248", "(a (b) c)", "(open", "G1 X", "#1=2", "X1..2"] {
        assert!(!plain(line.as_bytes(), &mut Vec::new()), "{line}");
    }
}

#[test]
fn errors_say_where() {
    assert_eq!(words("G1 X"), Err(4));
    assert_eq!(words("G1 #1=2"), Err(3));
    assert!(words("(open comment").is_err());
    assert!(words("(a (b) c").is_err());
    let w = words("(Laser (5 W), End Mill (1/4\"))").unwrap();
    assert_eq!((w.len(), w[0].0), (1, ItemKind::Comment));
    assert_eq!(words(":1248").unwrap()[0].0, ItemKind::Word(b'O'));
    assert!(words("X1..2").is_err());
    assert_eq!(words("X123456789012345678901234.5").unwrap()[0].2, 123456789012345678901234.5);
}
