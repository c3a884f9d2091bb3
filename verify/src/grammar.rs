//! The block grammar (chumsky): one program line in, a flat list of
//! [`Item`]s out.
//!
//! ```text
//! line    = blank ( "/" )? blank ( item blank )* END
//! item    = label | word | "(" [^)]* ")" | ";" anything | "%" anything
//! label   = "O" blank number ":"                 O1234: (a subprogram)
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

/// Reads a number at the start of `s`: bytes used, value, decimals
/// ([`scan_at`]).
#[inline(always)]
pub fn scan_number(s: &[u8]) -> Option<(usize, f64, u8)> {
    scan_at(s, 0)
}

/// [`scan_number`] for the number at `s[at..]`: where it ends in `s`,
/// value, decimals.
///
/// A number whose integer part and fraction have at most 7 digits each,
/// with 8 bytes of `s` from the first digit of each, is read 8 bytes at a
/// time ([`non_digits`], [`digits_value`]); the value is the same, from the
/// same integer of all its digits. Others are read a byte at a time
/// ([`scan_bytes`]).
#[inline(always)]
pub fn scan_at(s: &[u8], at: usize) -> Option<(usize, f64, u8)> {
    let negative = s.get(at) == Some(&b'-');
    match eights(s, at + usize::from(negative)) {
        Some((i, mantissa, written)) => {
            // At most 14 digits: under 2^63, where an i64 converts as a u64 does.
            let value = mantissa as i64 as f64 / pow10(written as u32);
            Some((i, if negative { -value } else { value }, written as u8))
        }
        None => scan_bytes(s, at),
    }
}

/// [`scan_at`] a byte at a time: numbers of at most 18 digits (all a post
/// prints) in two tight loops, integer part and fraction; longer ones by
/// [`scan_long`].
#[inline(never)]
#[doc(hidden)]
pub fn scan_bytes(s: &[u8], at: usize) -> Option<(usize, f64, u8)> {
    let (negative, start) = match s.get(at) {
        Some(b'-') => (true, at + 1),
        Some(b'+') => (false, at + 1),
        _ => (false, at),
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
        let (n, value, decimals) = scan_long(s.get(at..)?)?;
        return Some((at + n, value, decimals));
    }
    let value = mantissa as f64 / pow10(written as u32);
    Some((i, if negative { -value } else { value }, written as u8))
}

/// `b'0'` in each byte.
const ZEROS: u64 = 0x3030_3030_3030_3030;

/// The digits of the number at `s[start..]` (after its sign), 8 bytes at a
/// time: where it ends, the integer of all its digits and how many are
/// the fraction's. `None` when the loads do not settle it (fewer than 8
/// bytes left, 8 digits or more in a part, a decimal comma, no digit):
/// the digit-by-digit loops read those.
#[inline(always)]
fn eights(s: &[u8], start: usize) -> Option<(usize, u64, usize)> {
    let d = eight(s, start)? ^ ZEROS;
    let other = non_digits(d);
    let n = (other.trailing_zeros() / 8) as usize;
    if n == 8 {
        return None;
    }
    match (d >> (8 * n)) as u8 ^ b'0' {
        b'.' => {
            // The fraction ends at the next byte that is not a digit.
            let after = other & u64::MAX.checked_shl(8 * n as u32 + 8).unwrap_or(0);
            let end = (after.trailing_zeros() / 8) as usize;
            if end < 8 {
                // Within these 8 bytes: the integer part moved one byte up,
                // onto the point, makes the digits one run behind a zero.
                let below = (1u64 << (8 * n)) - 1;
                let joined = ((d & below) << 8) | (d & !(below << 8 | 0xFF));
                return (end > 1).then(|| (start + end, digits_value(joined, end), end - n - 1));
            }
            let f = eight(s, start + n + 1)? ^ ZEROS;
            let m = (non_digits(f).trailing_zeros() / 8) as usize;
            if m == 8 || n + m == 0 {
                return None;
            }
            Some((start + n + 1 + m, digits_value(d, n) * POW10[m] + digits_value(f, m), m))
        }
        b',' => None,
        _ if n == 0 => None,
        _ => Some((start + n, digits_value(d, n), 0)),
    }
}

/// The bytes of `d` (bytes minus `b'0'`) that are not digits: bits in
/// their high nibble, none in a digit's byte.
#[inline(always)]
fn non_digits(d: u64) -> u64 {
    const HIGH: u64 = 0xF0F0_F0F0_F0F0_F0F0;
    // A byte is a digit when its high nibble is 0 and its low one under 10.
    (d & HIGH) | ((d & !HIGH).wrapping_add(0x0606_0606_0606_0606) & HIGH)
}

/// The 8 bytes of `s` from `at`, the first the lowest, if `s` has them.
#[inline(always)]
fn eight(s: &[u8], at: usize) -> Option<u64> {
    let bytes: [u8; 8] = s.get(at..at.checked_add(8)?)?.try_into().ok()?;
    Some(u64::from_le_bytes(bytes))
}

/// The value of the first `n` (0 to 8) digits of `d` (bytes minus
/// `b'0'`, the first the lowest): the digits moved to the top as the last
/// of 8, behind zeros, and combined in pairs, fours and eights.
#[inline(always)]
fn digits_value(d: u64, n: usize) -> u64 {
    let Some(v) = d.checked_shl(8 * (8 - n as u32)) else { return 0 };
    let v = v.wrapping_mul(10).wrapping_add(v >> 8);
    let pairs = 0x0000_00FF_0000_00FF;
    ((v & pairs)
        .wrapping_mul(100 + (1_000_000 << 32))
        .wrapping_add(((v >> 16) & pairs).wrapping_mul(1 + (10_000 << 32))))
        >> 32
}

/// Powers of ten up to 10^7, as integers.
const POW10: [u64; 8] = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000];

/// [`scan_number`] for numbers of more than 18 digits: the first 18
/// significant digits make the value (the rest of a fraction is dropped),
/// and more than 18 integer digits go to the standard library.
#[doc(hidden)]
pub fn scan_long(s: &[u8]) -> Option<(usize, f64, u8)> {
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
    // `O1234:`: a subprogram's label (KinetiC-NC), the number of the
    // subprogram `M98 P1234` calls, read as its `O` word.
    let label = one_of(b"Oo")
        .ignore_then(blank)
        .ignore_then(number())
        .then_ignore(just(b':'))
        .try_map_with(|(value, decimals), e| push(e, ItemKind::Word(b'O'), value, decimals));
    let item = choice((label, word, paren, semicolon, percent, colon));
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
#[doc(hidden)]
pub fn plain(text: &[u8], items: &mut Vec<Item>) -> bool {
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
