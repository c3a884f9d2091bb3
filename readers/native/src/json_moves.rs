//! The JSON Lines fast path for the three move events, which are nearly
//! every line of a toolpath: `{"Rapid":{...}}`, `{"Feed":{...}}` and
//! `{"Arc":{...}}` written the way [`crate::write_event`] writes them (no
//! white space, keys without escapes, numbers, `null` and the enum names).
//!
//! [`read_move`] answers `Some(event)` only for a line it reads completely,
//! and then the event is exactly what serde_json gives for that line (the
//! tests check it over random lines): the same fields, the same defaults,
//! numbers as the double nearest to their decimal text (fast-float2's
//! correctly rounded parse, as serde_json's `float_roundtrip` reads them).
//! Anything else (another event, white space, an escape, an unknown or
//! repeated key, a missing field, a number out of range) answers `None` and
//! the line goes to serde_json, which reads it or says what is wrong. So the
//! fast path changes the speed of reading, never what is read.

use postc_ir::Event;
use postc_ir::event::{ArcDir, ArcMove, FeedMove, Intent, Move, Plane};

/// The move event of a JSON line, or `None` when the line is not a move
/// written in the plain form this reads.
pub fn read_move(line: &[u8]) -> Option<Event> {
    let mut c = Cursor { b: line, i: 0 };
    c.eat(b"{\"")?;
    let event = match c.word()? {
        b"Rapid" => {
            c.eat(b":{")?;
            Event::Rapid(c.rapid()?)
        }
        b"Feed" => {
            c.eat(b":{")?;
            Event::Feed(c.feed()?)
        }
        b"Arc" => {
            c.eat(b":{")?;
            Event::Arc(c.arc()?)
        }
        _ => return None,
    };
    c.eat(b"}")?;
    (c.i == c.b.len()).then_some(event)
}

struct Cursor<'a> {
    b: &'a [u8],
    i: usize,
}

/// Bits of the keys already read, so that a repeated key goes to serde_json.
struct Seen(u32);

impl Seen {
    /// Stores the value of key `bit`; `None` when the key came before or
    /// the value is not read.
    fn set<T>(&mut self, bit: u32, slot: &mut T, value: Option<T>) -> Option<()> {
        let mask = 1 << bit;
        if self.0 & mask != 0 {
            return None;
        }
        self.0 |= mask;
        *slot = value?;
        Some(())
    }
    fn has(&self, bit: u32) -> bool {
        self.0 & (1 << bit) != 0
    }
}

impl<'a> Cursor<'a> {
    fn eat(&mut self, text: &[u8]) -> Option<()> {
        if self.b[self.i..].starts_with(text) {
            self.i += text.len();
            Some(())
        } else {
            None
        }
    }

    /// The text up to the next `"`, which it consumes; `None` if it holds
    /// an escape or a control character (serde_json's business).
    fn word(&mut self) -> Option<&'a [u8]> {
        let start = self.i;
        while let Some(&b) = self.b.get(self.i) {
            self.i += 1;
            match b {
                b'"' => return Some(&self.b[start..self.i - 1]),
                b'\\' | 0..=0x1f => return None,
                _ => {}
            }
        }
        None
    }

    /// Reads `"key":` and hands the key to `field`, then `,` or the closing
    /// `}`, for every field of the object.
    fn fields(&mut self, mut field: impl FnMut(&mut Self, &[u8]) -> Option<()>) -> Option<()> {
        if self.eat(b"}").is_some() {
            return Some(());
        }
        loop {
            self.eat(b"\"")?;
            let key = self.word()?;
            self.eat(b":")?;
            field(self, key)?;
            match self.b.get(self.i)? {
                b',' => self.i += 1,
                b'}' => {
                    self.i += 1;
                    return Some(());
                }
                _ => return None,
            }
        }
    }

    /// A JSON number (`-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`),
    /// finite, as the double nearest to its text.
    ///
    /// A number of at most 19 digits, no exponent, whose digits read as a
    /// whole number up to 2^53 and with at most 22 decimals (every
    /// coordinate a CAM system writes) is that whole number divided by a
    /// power of ten: both are doubles exactly, and one IEEE division
    /// rounds correctly (Clinger's fast path). Any other goes to
    /// fast-float2, which rounds as `str::parse` does.
    fn number(&mut self) -> Option<f64> {
        /// Powers of ten that are doubles exactly.
        const EXACT: [f64; 23] = [
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18,
            1e19, 1e20, 1e21, 1e22,
        ];
        let start = self.i;
        // The digits from `i` on, added to `whole` (wrapping: the count
        // says when it may have).
        let digits = |c: &mut Self, whole: &mut u64| {
            let from = c.i;
            while let Some(&b) = c.b.get(c.i)
                && b.is_ascii_digit()
            {
                *whole = whole.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
                c.i += 1;
            }
            c.i - from
        };
        let negative = self.b.get(self.i) == Some(&b'-');
        if negative {
            self.i += 1;
        }
        let first = *self.b.get(self.i)?;
        let mut mantissa = 0u64;
        let whole = digits(self, &mut mantissa);
        if whole == 0 || (first == b'0' && whole > 1) {
            return None;
        }
        let mut decimals = 0;
        if self.b.get(self.i) == Some(&b'.') {
            self.i += 1;
            decimals = digits(self, &mut mantissa);
            if decimals == 0 {
                return None;
            }
        }
        if !matches!(self.b.get(self.i), Some(b'e' | b'E')) {
            if whole + decimals <= 19 && mantissa <= 1 << 53 && decimals < EXACT.len() {
                let x = mantissa as f64 / EXACT[decimals];
                return Some(if negative { -x } else { x });
            }
        } else {
            self.i += 1;
            if matches!(self.b.get(self.i), Some(b'+' | b'-')) {
                self.i += 1;
            }
            if digits(self, &mut 0) == 0 {
                return None;
            }
        }
        // The grammar is checked above; fast-float2 rounds as `str::parse` does.
        fast_float2::parse::<f64, _>(&self.b[start..self.i]).ok().filter(|x| x.is_finite())
    }

    fn optional_number(&mut self) -> Option<Option<f64>> {
        if self.eat(b"null").is_some() { Some(None) } else { self.number().map(Some) }
    }

    /// A quoted enum variant name.
    fn name(&mut self) -> Option<&'a [u8]> {
        self.eat(b"\"")?;
        self.word()
    }

    fn intent(&mut self) -> Option<Intent> {
        Some(match self.name()? {
            b"Cut" => Intent::Cut,
            b"Plunge" => Intent::Plunge,
            b"Retract" => Intent::Retract,
            b"LeadIn" => Intent::LeadIn,
            b"LeadOut" => Intent::LeadOut,
            _ => return None,
        })
    }

    fn rapid(&mut self) -> Option<Move> {
        let (mut m, mut seen) = (Move::default(), Seen(0));
        self.fields(|c, key| {
            match key {
                b"x" => seen.set(0, &mut m.x, c.number())?,
                b"y" => seen.set(1, &mut m.y, c.number())?,
                b"z" => seen.set(2, &mut m.z, c.number())?,
                b"a" => seen.set(3, &mut m.a, c.optional_number())?,
                b"b" => seen.set(4, &mut m.b, c.optional_number())?,
                b"c" => seen.set(5, &mut m.c, c.optional_number())?,
                _ => return None,
            }
            Some(())
        })?;
        (seen.has(0) && seen.has(1) && seen.has(2)).then_some(m)
    }

    fn feed(&mut self) -> Option<FeedMove> {
        let (mut m, mut seen) = (FeedMove::default(), Seen(0));
        self.fields(|c, key| {
            match key {
                b"x" => seen.set(0, &mut m.x, c.number())?,
                b"y" => seen.set(1, &mut m.y, c.number())?,
                b"z" => seen.set(2, &mut m.z, c.number())?,
                b"intent" => seen.set(3, &mut m.intent, c.intent())?,
                b"feed" => seen.set(4, &mut m.feed, c.optional_number())?,
                b"a" => seen.set(5, &mut m.a, c.optional_number())?,
                b"b" => seen.set(6, &mut m.b, c.optional_number())?,
                b"c" => seen.set(7, &mut m.c, c.optional_number())?,
                _ => return None,
            }
            Some(())
        })?;
        (seen.has(0) && seen.has(1) && seen.has(2)).then_some(m)
    }

    fn arc(&mut self) -> Option<ArcMove> {
        let (mut m, mut seen) = (ArcMove::default(), Seen(0));
        self.fields(|c, key| {
            match key {
                b"dir" => {
                    let dir = match c.name()? {
                        b"Cw" => ArcDir::Cw,
                        b"Ccw" => ArcDir::Ccw,
                        _ => return None,
                    };
                    seen.set(0, &mut m.dir, Some(dir))?
                }
                b"x" => seen.set(1, &mut m.x, c.number())?,
                b"y" => seen.set(2, &mut m.y, c.number())?,
                b"z" => seen.set(3, &mut m.z, c.number())?,
                b"cx" => seen.set(4, &mut m.cx, c.number())?,
                b"cy" => seen.set(5, &mut m.cy, c.number())?,
                b"cz" => seen.set(6, &mut m.cz, c.number())?,
                b"plane" => {
                    let plane = match c.name()? {
                        b"Xy" => Plane::Xy,
                        b"Zx" => Plane::Zx,
                        b"Yz" => Plane::Yz,
                        _ => return None,
                    };
                    seen.set(7, &mut m.plane, Some(plane))?
                }
                b"intent" => seen.set(8, &mut m.intent, c.intent())?,
                b"feed" => seen.set(9, &mut m.feed, c.optional_number())?,
                _ => return None,
            }
            Some(())
        })?;
        (0..6).all(|bit| seen.has(bit)).then_some(m)
    }
}
