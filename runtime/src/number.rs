//! The number formatter: exact, fixed-point and allocation-free.
//!
//! [`NumberWriter`] is a [`NumberFormat`] compiled for printing. Rounding is
//! half away from zero on the *decimal* value of the double, the value its
//! shortest round-trip representation names: 2.675 is stored as
//! 2.67499999999999982236431605997495353221893310546875, yet prints 2.68 at
//! two decimals, as a machinist reading "2.675" expects.
//!
//! The fast path scales by a power of ten and rounds in floating point; it is
//! exact whenever the scaled value is not within a few ulps of a rounding
//! tie. Near a tie it compares the value with the double nearest to the
//! decimal tie point, which decides exactly on the decimal value. Past 1e14 scaled
//! the slow path takes the shortest decimal digits of the double and rounds
//! them as decimal text. A value that is not a finite number prints nothing
//! and is reported ([`take_non_finite`]).
//! Either way the digits land in a stack buffer and are appended to the
//! caller's output; nothing is allocated once the output has capacity.
//!
//! Under [`Rounding::Binary`] (CIMCO) the rounding is on the exact binary
//! value instead, as JavaScript's `toFixed` does: 2.675 prints 2.67. The
//! fast path is the same; near a tie it compares the double with the tie
//! point exactly in integers, and the slow path rounds the exact decimal
//! expansion of the double.

use std::cell::Cell;
use std::io::Write as _;

use postc_ir::{Justify, NumberFormat, Padding, PointStyle, Rounding, SignStyle, WidthOf};

use crate::value::{INLINE_TEXT, Text};

thread_local! {
    /// The last value that is not a finite number a writer was asked to
    /// print, since [`take_non_finite`] last looked.
    static NON_FINITE: Cell<Option<f64>> = const { Cell::new(None) };
}

/// The value that is not a finite number (NaN or an infinity) a writer of
/// this thread was asked to print since the last call, if any; forgets it.
///
/// A writer prints nothing for such a value: no controller reads "NaN",
/// and printing 0 in its place moves the machine somewhere the post never
/// meant. The engine asks after every block and every format it runs and
/// stops the run with an error at the post's line.
#[inline]
pub fn take_non_finite() -> Option<f64> {
    NON_FINITE.with(|c| if c.get().is_some() { c.replace(None) } else { None })
}

/// Records a value that is not a finite number that a format was asked to
/// print (a picture format of its own, VcPost's `Format$`), for
/// [`take_non_finite`].
#[cold]
pub fn report_non_finite(value: f64) {
    NON_FINITE.with(|c| c.set(Some(value)));
}

/// Powers of ten that are exact doubles.
pub(crate) use postc_ir::js::POW10;

/// Scaled magnitudes below this round on the fast path.
const FAST_LIMIT: f64 = 1e14;

/// Decimals are capped here; no controller reads more.
pub const MAX_DECIMALS: u8 = 15;

/// Room for every digit of a finite double printed without exponent.
const DIGITS: usize = 400;

/// Room for the fraction digits of an exact binary expansion (half of it
/// is asked for, past the format's decimals).
const EXACT_FRACTION: usize = 160;

/// A [`NumberFormat`] ready to print.
#[derive(Clone, Debug)]
pub struct NumberWriter {
    decimals: usize,
    scale: f64,
    width: usize,
    integer_width: bool,
    zero_pad: bool,
    left: bool,
    sign_always: bool,
    point_always: bool,
    trim_zeros: bool,
    leading_zero: bool,
    mark: [u8; 4],
    mark_len: usize,
    multiplier: f64,
    prefix: Vec<u8>,
    /// Nothing to pad: the fast right-to-left writer applies.
    #[doc(hidden)]
    pub plain: bool,
    /// Round the binary double, not its shortest decimal form.
    binary: bool,
    /// A negative value that rounds to zero keeps its minus sign.
    negative_zero: bool,
}

impl NumberWriter {
    pub fn new(format: &NumberFormat) -> NumberWriter {
        let decimals = format.decimals.min(MAX_DECIMALS) as usize;
        let mut mark = [0u8; 4];
        let mark_len = format.decimal_mark.encode_utf8(&mut mark).len();
        NumberWriter {
            decimals,
            scale: POW10[decimals],
            width: format.width as usize,
            integer_width: format.width_of == WidthOf::IntegerDigits,
            zero_pad: format.padding == Padding::Zero,
            left: format.justify == Justify::Left,
            sign_always: format.sign == SignStyle::Always,
            point_always: format.point == PointStyle::Always,
            trim_zeros: format.trim_zeros,
            leading_zero: format.leading_zero,
            mark,
            mark_len,
            multiplier: if format.multiplier.is_finite() { format.multiplier } else { 1.0 },
            prefix: format.prefix.as_bytes().to_vec(),
            plain: format.width <= 1,
            binary: format.rounding == Rounding::Binary,
            negative_zero: format.negative_zero,
        }
    }

    pub fn decimals(&self) -> usize {
        self.decimals
    }

    pub fn multiplier(&self) -> f64 {
        self.multiplier
    }

    /// The value as the controller will read it back: multiplied, rounded
    /// to the printed decimals, and divided back.
    pub fn printed_value(&self, value: f64) -> f64 {
        let mut digits = Digits::new();
        let negative = match self.round(value) {
            Some(r) => {
                digits.fill_scaled_integer(r.m, self.decimals);
                r.negative
            }
            None => digits.round(value * self.multiplier, self.decimals, self.binary),
        };
        let mut v = 0.0;
        for &d in digits.integer() {
            v = v * 10.0 + f64::from(d - b'0');
        }
        let mut f = 0.0;
        for &d in digits.fraction().iter().rev() {
            f = (f + f64::from(d - b'0')) / 10.0;
        }
        let v = v + f;
        let v = if negative { -v } else { v };
        if self.multiplier != 0.0 { v / self.multiplier } else { v }
    }

    /// Rounds a value on the fast path: its sign and its magnitude in units
    /// of the last printed decimal. `None` past 1e14 scaled or for non-finite
    /// values, which take the slow path. Two values with the same key print
    /// the same text, so modal memory can compare keys instead of text.
    #[inline]
    pub fn round(&self, value: f64) -> Option<Rounded> {
        let value = value * self.multiplier;
        let magnitude = value.abs();
        let scaled = magnitude * self.scale;
        // Below 1e14 the scaled double is within 1/64 of the exact product,
        // so its floor is right and a tie is recognisable. NaN and
        // infinities take the slow path too.
        if scaled.is_nan() || scaled >= FAST_LIMIT {
            return None;
        }
        // Truncation is the floor of a non-negative value, without a libm
        // call; signed conversions are single instructions on x86-64.
        let floor = scaled as i64;
        let frac = scaled - floor as f64;
        let margin = 8.0 * f64::EPSILON * scaled.max(1.0);
        let up = if (frac - 0.5).abs() > margin {
            frac > 0.5
        } else if self.binary {
            at_or_above_binary_tie(magnitude, floor as u64, self.scale as u64)
        } else {
            // Near a tie. The tie point t = (2k+1) / (2·10^d) is a decimal
            // with d+1 digits; dividing two exact integers gives the double
            // nearest to it. If that double is the value, the value's
            // shortest decimal form is t itself (a tie: round away from
            // zero); otherwise its shortest form lies on the value's side
            // of t.
            let tie = (2 * floor + 1) as f64 / (2.0 * self.scale);
            magnitude >= tie
        };
        let m = (floor + i64::from(up)) as u64;
        Some(Rounded { negative: value < 0.0 && (m != 0 || self.negative_zero), m })
    }

    /// Appends the formatted value (prefix included) to `out`.
    #[inline]
    pub fn write(&self, value: f64, out: &mut Vec<u8>) {
        match self.round(value) {
            Some(r) => self.write_rounded(r, out),
            None => self.write_slow(value, out),
        }
    }

    /// Appends a value rounded by [`NumberWriter::round`].
    #[inline]
    pub fn write_rounded(&self, r: Rounded, out: &mut Vec<u8>) {
        self.write_rounded_after(&[], r, out);
    }

    /// Appends `prefix` and then a value rounded by [`NumberWriter::round`].
    #[inline(always)]
    pub fn write_rounded_after(&self, prefix: &[u8], r: Rounded, out: &mut Vec<u8>) {
        if self.plain && prefix.len() + self.prefix.len() <= 16 {
            self.write_plain(prefix, r, out);
            return;
        }
        let mut tmp = [b'0'; 24];
        let n = write_digits(r.m, &mut tmp);
        // At least one integer digit before the fraction.
        let start = n.min(24 - self.decimals - 1);
        let digits = &tmp[start..];
        let int_len = digits.len() - self.decimals;
        self.emit(prefix, r.negative, &digits[..int_len], &digits[int_len..], out);
    }

    /// The common case: no width to fill (zeros may be trimmed). The word is
    /// written right to left, two digits at a time, into one stack buffer
    /// and appended at once.
    #[inline(always)]
    fn write_plain(&self, prefix: &[u8], r: Rounded, out: &mut Vec<u8>) {
        // The word ends at WORD_END; the slack after it lets the append
        // below copy a fixed-size window.
        let mut buf = [0u8; WORD_END + WINDOW];
        let i = self.plain_word(prefix, r, &mut buf);
        append_word(out, &buf, i);
    }

    /// The word of a value rounded by [`NumberWriter::round`], `prefix`
    /// first, as a text value: `None` when the format pads (the caller
    /// then writes it with [`NumberWriter::write_rounded_after`]). A word
    /// of a field post's handler made straight into its value.
    #[inline(always)]
    pub fn word_text(&self, prefix: &[u8], r: Rounded) -> Option<Text> {
        if !self.plain || prefix.len() + self.prefix.len() > 16 {
            return None;
        }
        let mut buf = [0u8; WORD_END + WINDOW];
        let i = self.plain_word(prefix, r, &mut buf);
        let len = WORD_END - i;
        // Zeros follow the word: a short one is taken as a whole array.
        Some(match buf[i..].first_chunk::<INLINE_TEXT>() {
            Some(padded) if len <= INLINE_TEXT => Text::from_padded(padded, len),
            _ => Text::from_bytes(&buf[i..WORD_END]),
        })
    }

    /// Writes the word of [`NumberWriter::write_plain`] right to left so
    /// that it ends at `WORD_END` of `buf`, zeros after it; returns where
    /// it starts.
    #[inline(always)]
    fn plain_word(&self, prefix: &[u8], r: Rounded, buf: &mut [u8; WORD_END + WINDOW]) -> usize {
        let mut i = WORD_END;
        let mut m = r.m;
        let mut d = self.decimals;
        // Trailing zeros of the fraction are dropped before any is written.
        if self.trim_zeros {
            while d > 0 && m.is_multiple_of(10) {
                m /= 10;
                d -= 1;
            }
        }
        let fraction_digits = d;
        while d >= 2 {
            let pair = (m % 100) as usize * 2;
            m /= 100;
            i -= 2;
            buf[i] = PAIRS[pair];
            buf[i + 1] = PAIRS[pair + 1];
            d -= 2;
        }
        if d == 1 {
            i -= 1;
            buf[i] = b'0' + (m % 10) as u8;
            m /= 10;
        }
        if fraction_digits > 0 || self.point_always {
            for &b in self.mark[..self.mark_len].iter().rev() {
                i -= 1;
                buf[i] = b;
            }
        }
        if m > 0 || self.leading_zero || fraction_digits == 0 {
            i = digits_before(m, buf, i);
        }
        if r.negative {
            i -= 1;
            buf[i] = b'-';
        } else if self.sign_always {
            i -= 1;
            buf[i] = b'+';
        }
        for &b in self.prefix.iter().rev().chain(prefix.iter().rev()) {
            i -= 1;
            buf[i] = b;
        }
        i
    }

    #[doc(hidden)]
    pub fn write_slow(&self, value: f64, out: &mut Vec<u8>) {
        if !(value * self.multiplier).is_finite() {
            report_non_finite(value);
            return;
        }
        let mut digits = Digits::new();
        let negative = digits.round(value * self.multiplier, self.decimals, self.binary);
        self.emit(&[], negative, digits.integer(), digits.fraction(), out);
    }

    /// Writes `extra` (a variable's prefix), the format's prefix, sign,
    /// digits, mark and padding: assembled on the stack and appended at once.
    #[inline]
    fn emit(&self, extra: &[u8], negative: bool, integer: &[u8], fraction: &[u8], out: &mut Vec<u8>) {
        let mut fraction = fraction;
        if self.trim_zeros {
            while let [rest @ .., b'0'] = fraction {
                fraction = rest;
            }
        }
        let is_zero = integer.iter().chain(fraction).all(|&d| d == b'0');
        let sign: &[u8] = match (negative && (!is_zero || self.negative_zero), self.sign_always) {
            (true, _) => b"-",
            (false, true) => b"+",
            (false, false) => b"",
        };
        let integer: &[u8] = if !self.leading_zero && integer == b"0" && !fraction.is_empty() { b"" } else { integer };
        let point = !fraction.is_empty() || self.point_always;
        let mark = &self.mark[..if point { self.mark_len } else { 0 }];
        let core_len = sign.len() + integer.len() + mark.len() + fraction.len();
        let (int_pad, outer_pad) = if self.integer_width {
            (self.width.saturating_sub(integer.len()), 0)
        } else {
            (0, self.width.saturating_sub(core_len))
        };
        let total = extra.len() + self.prefix.len() + core_len + int_pad + outer_pad;
        let mut buf = StackBuf::new();
        if total > buf.room() {
            // Huge widths or prefixes: assemble on the heap.
            let mut v = Vec::with_capacity(total);
            self.assemble(extra, sign, integer, mark, fraction, int_pad, outer_pad, &mut |b: &[u8]| {
                v.extend_from_slice(b)
            });
            out.extend_from_slice(&v);
            return;
        }
        self.assemble(extra, sign, integer, mark, fraction, int_pad, outer_pad, &mut |b: &[u8]| buf.push(b));
        out.extend_from_slice(buf.as_slice());
    }

    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn assemble(
        &self,
        extra: &[u8],
        sign: &[u8],
        integer: &[u8],
        mark: &[u8],
        fraction: &[u8],
        int_pad: usize,
        outer_pad: usize,
        put: &mut impl FnMut(&[u8]),
    ) {
        const SPACES: [u8; 255] = [b' '; 255];
        const ZEROS: [u8; 255] = [b'0'; 255];
        put(extra);
        put(&self.prefix);
        let pad_zeros = self.zero_pad && !self.left;
        if !self.left && !pad_zeros {
            put(&SPACES[..outer_pad.min(255)]);
        }
        put(sign);
        if pad_zeros {
            put(&ZEROS[..outer_pad.min(255)]);
        }
        if self.zero_pad {
            put(&ZEROS[..int_pad.min(255)]);
        } else {
            put(&SPACES[..int_pad.min(255)]);
        }
        put(integer);
        put(mark);
        put(fraction);
        if self.left {
            put(&SPACES[..outer_pad.min(255)]);
        }
    }
}

/// A small stack buffer for one formatted word.
struct StackBuf {
    buf: [u8; 96],
    len: usize,
}

impl StackBuf {
    #[inline]
    fn new() -> StackBuf {
        StackBuf { buf: [0; 96], len: 0 }
    }

    #[inline]
    fn room(&self) -> usize {
        self.buf.len()
    }

    #[inline]
    fn push(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.buf[self.len] = b;
            self.len += 1;
        }
    }

    #[inline]
    fn as_slice(&self) -> &[u8] {
        &self.buf[..self.len]
    }
}

/// A value rounded to a format's decimals: sign and magnitude in units of
/// the last decimal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rounded {
    pub negative: bool,
    pub m: u64,
}

/// Where a word built right to left ends in its buffer.
const WORD_END: usize = 64;
/// Words up to this long are appended as one fixed-size copy.
pub(crate) const WINDOW: usize = 32;

/// Appends `buf[start..WORD_END]`. Short words copy a fixed window and
/// truncate the slack, which compiles to a few vector moves instead of a
/// `memcpy` call.
#[inline]
fn append_word(out: &mut Vec<u8>, buf: &[u8; WORD_END + WINDOW], start: usize) {
    let len = WORD_END - start;
    if len <= WINDOW {
        let window: &[u8; WINDOW] = buf[start..start + WINDOW].try_into().expect("the window is in the buffer");
        out.extend_from_slice(window);
        out.truncate(out.len() - (WINDOW - len));
    } else {
        out.extend_from_slice(&buf[start..WORD_END]);
    }
}

/// Appends an integer's decimal digits (a block number, `N1234`), written
/// two at a time and appended as one fixed-size copy.
#[inline]
#[doc(hidden)]
pub fn push_integer(out: &mut Vec<u8>, n: i64) {
    let mut buf = [0u8; WORD_END + WINDOW];
    let mut i = digits_before(n.unsigned_abs(), &mut buf, WORD_END);
    if n < 0 {
        i -= 1;
        buf[i] = b'-';
    }
    append_word(out, &buf, i);
}

/// Writes the decimal digits of `m` at the end of `tmp`; returns where they start.
#[inline]
fn write_digits(m: u64, tmp: &mut [u8; 24]) -> usize {
    digits_before(m, tmp, 24)
}

/// Writes the decimal digits of `m` (at least one) right to left so that
/// they end at `end`, two at a time; returns where they start.
#[inline]
fn digits_before<const N: usize>(mut m: u64, buf: &mut [u8; N], end: usize) -> usize {
    let mut i = end;
    while m >= 100 {
        let pair = (m % 100) as usize * 2;
        m /= 100;
        i -= 2;
        buf[i] = PAIRS[pair];
        buf[i + 1] = PAIRS[pair + 1];
    }
    if m >= 10 {
        let pair = m as usize * 2;
        i -= 2;
        buf[i] = PAIRS[pair];
        buf[i + 1] = PAIRS[pair + 1];
    } else {
        i -= 1;
        buf[i] = b'0' + m as u8;
    }
    i
}

/// Two-digit pairs "00" to "99".
static PAIRS: [u8; 200] = {
    let mut t = [0u8; 200];
    let mut i = 0;
    while i < 100 {
        t[2 * i] = b'0' + (i / 10) as u8;
        t[2 * i + 1] = b'0' + (i % 10) as u8;
        i += 1;
    }
    t
};

/// The rounded digits of one number: integer digits then exactly
/// `decimals` fraction digits, as ASCII.
struct Digits {
    buf: [u8; DIGITS],
    len: usize,
    int_len: usize,
}

impl Digits {
    fn new() -> Digits {
        Digits { buf: [0; DIGITS], len: 0, int_len: 0 }
    }

    fn integer(&self) -> &[u8] {
        &self.buf[..self.int_len]
    }

    fn fraction(&self) -> &[u8] {
        &self.buf[self.int_len..self.len]
    }

    /// Rounds `value` half away from zero to `decimals` places on its
    /// shortest decimal digits, or on its exact binary value when `binary`;
    /// returns whether it is negative. Values that are not finite (never
    /// printed: [`take_non_finite`]) read as zero.
    fn round(&mut self, value: f64, decimals: usize, binary: bool) -> bool {
        let value = if value.is_finite() { value } else { 0.0 };
        let negative = value.is_sign_negative() && value != 0.0;
        self.fill_decimal(value.abs(), decimals, binary);
        negative
    }

    /// Digits of `m / 10^decimals`.
    fn fill_scaled_integer(&mut self, mut m: u64, decimals: usize) {
        let mut tmp = [b'0'; 24];
        let mut n = 0;
        while m > 0 {
            tmp[n] = b'0' + (m % 10) as u8;
            m /= 10;
            n += 1;
        }
        // At least one integer digit.
        let total = n.max(decimals + 1);
        for i in 0..total {
            self.buf[i] = tmp[total - 1 - i];
        }
        self.len = total;
        self.int_len = total - decimals;
    }

    /// Digits from the shortest round-trip decimal form of `magnitude`
    /// (or, when `binary`, its exact decimal expansion), rounded as decimal
    /// text.
    fn fill_decimal(&mut self, magnitude: f64, decimals: usize, binary: bool) {
        let mut text = [0u8; DIGITS + EXACT_FRACTION];
        let len = {
            let mut cursor = std::io::Cursor::new(&mut text[..]);
            if binary {
                // The slow path has magnitude · 10^decimals >= 1e14 (or a
                // zero), so the magnitude is at least 0.1 and its ulp at
                // least 2^-57: the exact expansion ends within 57 fraction
                // digits, and this prints it whole, unrounded.
                let _ = write!(cursor, "{magnitude:.prec$}", prec = decimals + EXACT_FRACTION / 2);
            } else {
                // `{}` on f64 writes the shortest digits that round-trip, with no exponent.
                let _ = write!(cursor, "{magnitude}");
            }
            cursor.position() as usize
        };
        let text = &text[..len];
        let (int_part, frac_part) = match text.iter().position(|&c| c == b'.') {
            Some(p) => (&text[..p], &text[p + 1..]),
            None => (text, &text[len..]),
        };
        let int_len = int_part.len().min(DIGITS - decimals - 2);
        self.buf[0] = b'0';
        // One leading slot for a carry out of the integer part.
        self.buf[1..1 + int_len].copy_from_slice(&int_part[..int_len]);
        for i in 0..decimals {
            self.buf[1 + int_len + i] = frac_part.get(i).copied().unwrap_or(b'0');
        }
        let end = 1 + int_len + decimals;
        let round_up = frac_part.get(decimals).is_some_and(|&d| d >= b'5');
        if round_up {
            let mut i = end;
            while i > 0 {
                i -= 1;
                if self.buf[i] == b'9' {
                    self.buf[i] = b'0';
                } else {
                    self.buf[i] += 1;
                    break;
                }
            }
        }
        // Drop the carry slot (and other leading zeros) but keep one integer digit.
        let mut start = 0;
        while start < end - decimals - 1 && self.buf[start] == b'0' {
            start += 1;
        }
        self.buf.copy_within(start..end, 0);
        self.len = end - start;
        self.int_len = self.len - decimals;
    }
}

/// Whether `magnitude` (finite, not negative) is at or above the tie point
/// (2k+1) / (2·10^d) of rounding to d decimals, compared exactly on the
/// binary value (`pow10` is 10^d, at most 10^15).
// Out of line and cold: near-ties are rare, and inlined into the hot
// rounding path this integer arithmetic slowed every move (criterion `posting`).
#[cold]
#[inline(never)]
fn at_or_above_binary_tie(magnitude: f64, k: u64, pow10: u64) -> bool {
    let bits = magnitude.to_bits();
    let exp_bits = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, exp) = if exp_bits == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp_bits - 1075) };
    // magnitude = mant · 2^exp: compare 2 · mant · 10^d · 2^exp with 2k+1.
    let lhs = u128::from(mant) * u128::from(pow10) * 2;
    let odd = u128::from(2 * k + 1);
    if exp >= 0 {
        // The scaled value is below 1e14 here, so this does not overflow.
        (lhs << exp as u32) >= odd
    } else {
        let s = exp.unsigned_abs();
        s < 128 && odd.leading_zeros() > s && lhs >= odd << s
    }
}
