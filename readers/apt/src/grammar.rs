//! The record grammar (chumsky): one assembled statement record in, a flat
//! list of [`Item`]s out.
//!
//! ```text
//! record   = heads blank ( "/" blank args | "=" anything | ε ) blank END
//! heads    = word ( ("," | blank+) word )*          GOTO, TOOL PATH, TLON,GOFWD
//! args     = item ( sep item )* ","?                 may be empty: RAPID/
//! sep      = blank "," blank | blank+                blank+ alone: a missing comma
//! item     = "(" blank word blank "/" blank value ( sep value )* ","? blank ")"
//!          | "(" expr ")"                            (.5-2*.05*.6)
//!          | value                                   number or word
//! expr     = term ( ("+" | "-") term )*
//! term     = factor ( ("*" | "/") factor )*
//! factor   = blank sign? unsigned blank
//! ```
//!
//! A value is a run of bytes other than blanks and `, / ( ) = $`; it is a
//! number when it reads as one (`5.`, `.5`, `-1.5E-3`, Fortran `1.5D3`),
//! else a word (`CLW`, `1STPECK`, `8_KONTUR_NAR_40_N2`). A word that starts
//! a record or a nested record cannot start with a digit, a sign or a point.
//!
//! The record structure (heads, `/` or `=`, nested records, expressions)
//! is chumsky combinators; the lexemes (blanks, values, separators, and the
//! scan of the argument list from value to value) are hand-written
//! `custom` parsers, because they run for every byte of a 1 GB file. The
//! parser writes items into a state vector the reader reuses for every
//! record, so a record is parsed without allocating; backtracking truncates
//! the vector. Errors are [`Cheap`] (a span only): the reader words the
//! message itself.

use chumsky::error::Cheap;
use chumsky::extra::Full;
use chumsky::input::{InputRef, MapExtra};
use chumsky::inspector::TruncateState;
use chumsky::prelude::*;
use chumsky::primitive::custom;

use crate::number::{parse_number, scan_value};

/// What an item is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum ItemKind {
    /// A major word (several for `TOOL PATH` or `TLON,GOFWD`).
    Head,
    /// A number, or the value of a parenthesised expression.
    Number,
    /// A word argument.
    Word,
    /// `(WORD/` opens a nested record; the item is its word.
    Open,
    /// `)` closes a nested record.
    Close,
    /// Two values stood side by side without a comma.
    MissingComma,
}

/// One piece of a parsed record: its kind, its bytes in the record and, for
/// numbers, its value.
#[derive(Clone, Copy, Debug, PartialEq)]
#[doc(hidden)]
pub struct Item {
    pub kind: ItemKind,
    pub start: u32,
    pub end: u32,
    pub value: f64,
}

/// The shape of a record after its heads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum Shape {
    /// No `/`: `RAPID`, `FINI`.
    Bare,
    /// `WORD/args`.
    Slash,
    /// `NAME = ...`: a part-program assignment.
    Assignment,
}

pub(crate) type Items = TruncateState<Item>;
type Extra = Full<Cheap, Items, ()>;

const fn byte_table(excluded: &[u8], also_excluded: &[u8]) -> [bool; 256] {
    let mut table = [true; 256];
    let mut i = 0;
    while i < 32 {
        table[i] = false;
        i += 1;
    }
    table[127] = false;
    let mut i = 0;
    while i < excluded.len() {
        table[excluded[i] as usize] = false;
        i += 1;
    }
    let mut i = 0;
    while i < also_excluded.len() {
        table[also_excluded[i] as usize] = false;
        i += 1;
    }
    table
}

/// Bytes a value may contain.
pub(crate) static VALUE_BYTE: [bool; 256] = byte_table(b" \t,/()=$", b"");
/// Bytes a word that starts a record may start with.
static WORD_START: [bool; 256] = byte_table(b" \t,/()=$", b"0123456789+-.");

fn push<'s, 'b>(e: &mut MapExtra<'s, 'b, &'s [u8], Extra>, kind: ItemKind, value: f64) {
    let span: SimpleSpan = e.span();
    let item = Item { kind, start: span.start as u32, end: span.end as u32, value };
    e.state().push(item);
}

/// Side effects run only where chumsky computes outputs; `try_map_with`
/// always does, even inside `ignored()` parsers.
fn push_ok<'s, 'b>(e: &mut MapExtra<'s, 'b, &'s [u8], Extra>, kind: ItemKind, value: f64) -> Result<(), Cheap> {
    push(e, kind, value);
    Ok(())
}

/// The input from the cursor on, and the cursor's offset.
fn rest<'s>(inp: &mut InputRef<'s, '_, &'s [u8], Extra>) -> (usize, &'s [u8]) {
    let at = *inp.cursor().inner();
    let all: &'s [u8] = inp.full_slice();
    (at, all.get(at..).unwrap_or_default())
}

/// Moves the cursor `n` bytes on.
fn advance<'s>(inp: &mut InputRef<'s, '_, &'s [u8], Extra>, n: usize) {
    for _ in 0..n {
        inp.skip();
    }
}

fn error_at(at: usize) -> Cheap {
    Cheap::new(SimpleSpan::new((), at..at + 1))
}

/// Skips blanks and tabs.
fn blanks<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let (_, rest) = rest(inp);
        let n = rest.iter().position(|&b| b != b' ' && b != b'\t').unwrap_or(rest.len());
        advance(inp, n);
        Ok(())
    })
}

/// A run of value bytes that starts with a byte of `first`; pushes an
/// item of `kind`, or for values a number or a word.
fn lexeme<'s>(first: &'static [bool; 256], kind: Option<ItemKind>) -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(move |inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let (at, rest) = rest(inp);
        match rest.first() {
            Some(&b) if first[b as usize] => {}
            _ => return Err(error_at(at)),
        }
        let n = rest.iter().position(|&b| !VALUE_BYTE[b as usize]).unwrap_or(rest.len());
        advance(inp, n);
        let (kind, value) = match kind {
            Some(kind) => (kind, 0.0),
            None => match parse_number(&rest[..n]) {
                Some(v) => (ItemKind::Number, v),
                None => (ItemKind::Word, 0.0),
            },
        };
        inp.state().push(Item { kind, start: at as u32, end: (at + n) as u32, value });
        Ok(())
    })
}

/// A separator between values: a comma with blanks around it, or blanks
/// alone (a missing comma, recorded as an item).
fn separator<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        let (at, rest) = rest(inp);
        let blank = |r: &[u8]| r.iter().position(|&b| b != b' ' && b != b'\t').unwrap_or(r.len());
        let n = blank(rest);
        if rest.get(n) == Some(&b',') {
            let m = blank(&rest[n + 1..]);
            advance(inp, n + 1 + m);
            return Ok(());
        }
        if n == 0 {
            return Err(error_at(at));
        }
        advance(inp, n);
        inp.state().push(Item { kind: ItemKind::MissingComma, start: at as u32, end: (at + n) as u32, value: 0.0 });
        Ok(())
    })
}

/// `( expr )`: arithmetic inside parentheses, as APT source writes
/// `THREAD/.05,(.5-2*.05*.6)`.
fn paren_expr<'s>() -> impl Parser<'s, &'s [u8], (), Extra> {
    let blank = blanks();
    let digits = any().filter(u8::is_ascii_digit).repeated();
    let mantissa = digits
        .at_least(1)
        .then(just(b'.').then(digits).or_not())
        .ignored()
        .or(just(b'.').then(digits.at_least(1)).ignored());
    let exponent = one_of(b"eEdD").then(one_of(b"+-").or_not()).then(digits.at_least(1));
    let unsigned =
        mantissa.then(exponent.or_not()).to_slice().try_map(|s: &[u8], span| parse_number(s).ok_or(Cheap::new(span)));
    let factor = one_of(b"+-")
        .or_not()
        .then_ignore(blank)
        .then(unsigned)
        .map(|(sign, v)| if sign == Some(b'-') { -v } else { v })
        .padded_by(blank);
    let term = factor.foldl(one_of(b"*/").then(factor).repeated(), |a, (op, b)| if op == b'*' { a * b } else { a / b });
    let expr = term
        .foldl(one_of(b"+-").then(term).repeated(), |a, (op, b)| if op == b'+' { a + b } else { a - b })
        .try_map(|v: f64, span| if v.is_finite() { Ok(v) } else { Err(Cheap::new(span)) });
    just(b'(').ignore_then(expr).then_ignore(just(b')')).try_map_with(|v, e| push_ok(e, ItemKind::Number, v))
}

/// `(WORD/value,...)`: a nested record, as in `CLEARP/(PLANE/0,0,1,3.5)`
/// or CATIA's `TLON,GOFWD/(CIRCLE/...),ON,(LINE/...)`.
fn nested<'s>() -> impl Parser<'s, &'s [u8], (), Extra> {
    let blank = blanks();
    just(b'(')
        .then(blank)
        .ignore_then(lexeme(&WORD_START, Some(ItemKind::Open)))
        .then(blank)
        .then(just(b'/'))
        .then(blank)
        .then(lexeme(&VALUE_BYTE, None).separated_by(separator()).allow_trailing())
        .then(blank)
        .then(just(b')').try_map_with(|_, e| push_ok(e, ItemKind::Close, 0.0)))
        .ignored()
}

/// The arguments after the `/`: values separated by commas (or by blanks,
/// a missing comma), with parenthesised items parsed by [`nested`] and
/// [`paren_expr`]. Values and separators are lexical, so the list is
/// scanned by hand for speed; a trailing comma is allowed.
fn arguments<'s>() -> impl Parser<'s, &'s [u8], (), Extra> + Copy {
    custom(|inp: &mut InputRef<'s, '_, &'s [u8], Extra>| {
        loop {
            let (at, tail) = rest(inp);
            match tail.first() {
                None => return Ok(()),
                Some(b'(') => inp.parse(nested().or(paren_expr()))?,
                Some(&b) if VALUE_BYTE[b as usize] => {
                    let (n, number) = scan_value(tail);
                    advance(inp, n);
                    let (kind, value) = match number {
                        Some(v) => (ItemKind::Number, v),
                        None => (ItemKind::Word, 0.0),
                    };
                    inp.state().push(Item { kind, start: at as u32, end: (at + n) as u32, value });
                }
                Some(_) => return Err(error_at(at)),
            }
            let (at, tail) = rest(inp);
            let n = tail.iter().position(|&b| b != b' ' && b != b'\t').unwrap_or(tail.len());
            match tail.get(n) {
                Some(b',') => {
                    let m = tail[n + 1..].iter().position(|&b| b != b' ' && b != b'\t').unwrap_or(tail.len() - n - 1);
                    advance(inp, n + 1 + m);
                }
                Some(&b) if n > 0 && (VALUE_BYTE[b as usize] || b == b'(') => {
                    advance(inp, n);
                    inp.state().push(Item {
                        kind: ItemKind::MissingComma,
                        start: at as u32,
                        end: (at + n) as u32,
                        value: 0.0,
                    });
                }
                _ => return Ok(()),
            }
        }
    })
}

/// The parser of one statement record. The lexemes (blanks, values,
/// separators) are hand-written `custom` parsers for speed; the structure
/// is combinators.
#[doc(hidden)]
pub fn record<'s>() -> impl Parser<'s, &'s [u8], Shape, Extra> + Clone {
    let blank = blanks();
    let blank1 = any().filter(|b: &u8| *b == b' ' || *b == b'\t').then(blank);
    let comma = blank.then(just(b',')).then(blank).ignored();
    let args = arguments();
    let heads = lexeme(&WORD_START, Some(ItemKind::Head)).separated_by(comma.or(blank1.ignored())).at_least(1);
    let tail = choice((
        just(b'/').then(blank).then(args).to(Shape::Slash),
        just(b'=').then(any().repeated()).to(Shape::Assignment),
        empty().to(Shape::Bare),
    ));
    heads.then(blank).ignore_then(tail).then_ignore(blank).then_ignore(end())
}
