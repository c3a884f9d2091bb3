//! The block grammar (chumsky): one program line in, a flat list of
//! [`Item`]s out.
//!
//! ```text
//! line    = blank ( "/" )? blank ( item blank )* END
//! item    = word | "(" [^)]* ")" | ";" anything | "%" anything
//! word    = letter blank number                 G1, x-1.5, F 1200., N0010
//! number  = sign? ( digits ( "." digits? )? | "." digits )
//! blank   = ( " " | "\t" | "\r" )*
//! ```
//!
//! Letters are case-insensitive, as RS274/NGC reads them. The structure is
//! chumsky combinators; the number lexeme is a hand-written `custom`
//! parser, because it runs for every word of a ten-million-line program.
//! The parser writes items into a state vector the reader reuses for every
//! line, so a block is parsed without allocating. Errors are [`Cheap`] (a
//! span only): the interpreter words the message itself.

use chumsky::error::Cheap;
use chumsky::extra::Full;
use chumsky::input::{InputRef, MapExtra};
use chumsky::inspector::TruncateState;
use chumsky::prelude::*;
use chumsky::primitive::custom;

/// What an item is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ItemKind {
    /// A word: its letter, upper case.
    Word(u8),
    /// `( ... )` or `; ...`: the item spans the whole comment.
    Comment,
    /// A `/` at the start of the block: block delete.
    Delete,
    /// `%`: the program start/end marker (and whatever follows it).
    Percent,
}

/// One piece of a block: its kind, its bytes in the line and, for words,
/// its value and how many decimals it was written with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Item {
    pub kind: ItemKind,
    pub start: u32,
    pub end: u32,
    pub value: f64,
    pub decimals: u8,
}

pub type Items = TruncateState<Item>;
type Extra = Full<Cheap, Items, ()>;

fn push<'s, 'b>(
    e: &mut MapExtra<'s, 'b, &'s [u8], Extra>,
    kind: ItemKind,
    value: f64,
    decimals: u8,
) -> Result<(), Cheap> {
    let span: SimpleSpan = e.span();
    e.state().push(Item { kind, start: span.start as u32, end: span.end as u32, value, decimals });
    Ok(())
}

/// Reads a number at the start of `s`: bytes used, value, decimals.
///
/// Numbers of at most 18 digits (all a post prints) are read in two tight
/// loops, integer part and fraction; longer ones by [`scan_long`].
#[inline(always)]
pub fn scan_number(s: &[u8]) -> Option<(usize, f64, u8)> {
    let (negative, start) = match s.first() {
        Some(b'-') => (true, 1),
        Some(b'+') => (false, 1),
        _ => (false, 0),
    };
    let digit = |i: usize| s.get(i).map(|b| b.wrapping_sub(b'0')).filter(|d| *d < 10);
    let (mut i, mut mantissa) = (start, 0u64);
    while let Some(d) = digit(i) {
        mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    let integer = i - start;
    let mut written = 0;
    // The decimal comma some European controls print (`X10,000`).
    if let Some(&b) = s.get(i)
        && (b == b'.' || (b == b',' && digit(i + 1).is_some()))
    {
        i += 1;
        let fraction = i;
        while let Some(d) = digit(i) {
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
            i += 1;
        }
        written = i - fraction;
    }
    if integer + written == 0 {
        return None;
    }
    if integer + written > 18 {
        return scan_long(s);
    }
    let value = mantissa as f64 / pow10(written as u32);
    Some((i, if negative { -value } else { value }, written as u8))
}

/// [`scan_number`] for numbers of more than 18 digits: the first 18
/// significant digits make the value (the rest of a fraction is dropped),
/// and more than 18 integer digits go to the standard library.
fn scan_long(s: &[u8]) -> Option<(usize, f64, u8)> {
    let mut i = 0;
    let negative = match s.first() {
        Some(b'-') => {
            i += 1;
            true
        }
        Some(b'+') => {
            i += 1;
            false
        }
        _ => false,
    };
    let (mut mantissa, mut digits, mut decimals, mut written) = (0u64, 0u32, 0u32, 0u32);
    let (mut point, mut any) = (false, false);
    while let Some(&b) = s.get(i) {
        let d = b.wrapping_sub(b'0');
        if d < 10 {
            any = true;
            written += u32::from(point);
            if digits < 18 {
                mantissa = mantissa * 10 + u64::from(d);
                digits += u32::from(mantissa > 0);
                decimals += u32::from(point);
            } else if !point {
                return slow(s);
            }
        } else if !point && (b == b'.' || (b == b',' && s.get(i + 1).is_some_and(u8::is_ascii_digit))) {
            point = true;
        } else {
            break;
        }
        i += 1;
    }
    if !any {
        return None;
    }
    let value = mantissa as f64 / pow10(decimals);
    Some((i, if negative { -value } else { value }, written.min(255) as u8))
}

/// 10 to the power `n`, as `10f64.powi(n)` gives it (exact up to 10^22).
pub(crate) fn pow10(n: u32) -> f64 {
    const TABLE: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19,
        1e20, 1e21, 1e22,
    ];
    TABLE.get(n as usize).copied().unwrap_or_else(|| 10f64.powi(n as i32))
}

/// Numbers with more than 18 integer digits: the standard library reads them.
fn slow(s: &[u8]) -> Option<(usize, f64, u8)> {
    let n = s
        .iter()
        .enumerate()
        .position(|(k, &b)| !(b.is_ascii_digit() || b == b'.' || (k == 0 && (b == b'-' || b == b'+'))))
        .unwrap_or(s.len());
    let text = std::str::from_utf8(&s[..n]).ok()?;
    let value: f64 = text.parse().ok()?;
    let decimals = text.find('.').map_or(0, |p| text.len() - p - 1);
    Some((n, value, decimals.min(255) as u8))
}

/// Skips blanks, tabs and carriage returns.
fn blanks<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let at = *inp.cursor().inner();
        let all: &'s [u8] = inp.full_slice();
        let rest = all.get(at..).unwrap_or_default();
        let n = rest.iter().position(|&b| !matches!(b, b' ' | b'\t' | b'\r')).unwrap_or(rest.len());
        for _ in 0..n {
            inp.skip();
        }
        Ok(())
    })
}

/// `( ... )`, nested parentheses included (the interpreter reports them for
/// the controllers that refuse them); the item spans the whole comment.
fn paren_comment<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let at = *inp.cursor().inner();
        let all: &'s [u8] = inp.full_slice();
        let rest = all.get(at..).unwrap_or_default();
        if rest.first() != Some(&b'(') {
            return Err(Cheap::new(SimpleSpan::new((), at..at + 1)));
        }
        let mut depth = 0u32;
        let mut close = None;
        for (i, &b) in rest.iter().enumerate() {
            match b {
                b'(' => depth += 1,
                b')' => {
                    depth -= 1;
                    if depth == 0 {
                        close = Some(i + 1);
                        break;
                    }
                }
                _ => {}
            }
        }
        let Some(n) = close else {
            return Err(Cheap::new(SimpleSpan::new((), all.len()..all.len())));
        };
        for _ in 0..n {
            inp.skip();
        }
        inp.state().push(Item {
            kind: ItemKind::Comment,
            start: at as u32,
            end: (at + n) as u32,
            value: 0.0,
            decimals: 0,
        });
        Ok(())
    })
}

/// A number lexeme: value and decimals.
fn number<'s>() -> impl Parser<'s, &'s [u8], (f64, u8), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let at = *inp.cursor().inner();
        let all: &'s [u8] = inp.full_slice();
        let rest = all.get(at..).unwrap_or_default();
        match scan_number(rest) {
            Some((n, value, decimals)) => {
                for _ in 0..n {
                    inp.skip();
                }
                Ok((value, decimals))
            }
            None => Err(Cheap::new(SimpleSpan::new((), at..at + 1))),
        }
    })
}

/// The parser of one line.
pub fn line<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Clone {
    let blank = blanks();
    let word = any().filter(u8::is_ascii_alphabetic).then_ignore(blank).then(number()).try_map_with(
        |(letter, (value, decimals)): (u8, (f64, u8)), e| {
            push(e, ItemKind::Word(letter.to_ascii_uppercase()), value, decimals)
        },
    );
    let paren = paren_comment();
    // ISO tape's `:` program number, as `O`.
    let colon = just(b':')
        .ignore_then(blank)
        .ignore_then(number())
        .try_map_with(|(value, decimals), e| push(e, ItemKind::Word(b'O'), value, decimals));
    let semicolon = just(b';').then(any().repeated()).try_map_with(|_, e| push(e, ItemKind::Comment, 0.0, 0));
    let percent = just(b'%').then(any().repeated()).try_map_with(|_, e| push(e, ItemKind::Percent, 0.0, 0));
    let item = choice((word, paren, semicolon, percent, colon));
    let delete = just(b'/').try_map_with(|_, e| push(e, ItemKind::Delete, 0.0, 0));
    blank.then(delete.or_not()).then(blank).then(item.then(blank).repeated()).then(end()).ignored()
}

/// Parses a line into `items`; on an error, the byte offset where reading stopped.
///
/// Lines of words, blanks and simple comments (what posts write on almost
/// every line) are read by [`plain`]; any other line, and every line that
/// does not read, goes through the chumsky grammar, which gives the same
/// items (a property test checks it) and says where reading stopped.
pub fn parse(text: &[u8], items: &mut Items) -> Result<(), usize> {
    items.0.clear();
    if plain(text, &mut items.0) {
        return Ok(());
    }
    items.0.clear();
    let result = line().parse_with_state(text, items);
    match result.into_result() {
        Ok(()) => Ok(()),
        Err(errors) => Err(errors.first().map_or(0, |e| e.span().start)),
    }
}

/// [`plain`] into `items`, cleared first: true when the line is plain.
pub fn parse_plain(text: &[u8], items: &mut Items) -> bool {
    items.0.clear();
    plain(text, &mut items.0)
}

/// The grammar's items for a line of words (`G1 X-1.5 y2.`), blanks, `( )`
/// comments without nested parentheses or NUL bytes and a closing `;`
/// comment without NUL bytes; false
/// for anything else (block delete, `%`, `:`, nested or open comments,
/// anything that does not read), which the chumsky grammar then reads.
fn plain(text: &[u8], items: &mut Vec<Item>) -> bool {
    let blank = |b: u8| matches!(b, b' ' | b'\t' | b'\r');
    let mut i = 0;
    while i < text.len() {
        let b = text[i];
        if blank(b) {
            i += 1;
        } else if b.is_ascii_alphabetic() {
            let start = i;
            i += 1;
            while i < text.len() && blank(text[i]) {
                i += 1;
            }
            let Some((n, value, decimals)) = scan_number(&text[i..]) else { return false };
            i += n;
            items.push(Item {
                kind: ItemKind::Word(b.to_ascii_uppercase()),
                start: start as u32,
                end: i as u32,
                value,
                decimals,
            });
        } else if b == b'(' {
            let Some(n) = text[i + 1..].iter().position(|&c| c == b'(' || c == b')') else { return false };
            if text[i + 1 + n] != b')' || text[i + 1..i + 1 + n].contains(&0) {
                return false;
            }
            let end = i + n + 2;
            items.push(Item { kind: ItemKind::Comment, start: i as u32, end: end as u32, value: 0.0, decimals: 0 });
            i = end;
        } else if b == b';' {
            if text[i..].contains(&0) {
                return false;
            }
            let end = text.len();
            items.push(Item { kind: ItemKind::Comment, start: i as u32, end: end as u32, value: 0.0, decimals: 0 });
            i = end;
        } else {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
