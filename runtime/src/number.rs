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
//! tie. Near a tie (and for magnitudes past 2^52) the slow path takes the
//! shortest decimal digits of the double and rounds them as decimal text.
//! Either way the digits land in a stack buffer and are appended to the
//! caller's output; nothing is allocated once the output has capacity.

use std::io::Write as _;

use postc_ir::{Justify, NumberFormat, Padding, PointStyle, SignStyle, WidthOf};

/// Powers of ten that are exact doubles.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19,
    1e20, 1e21, 1e22,
];

/// Decimals are capped here; no controller reads more.
pub const MAX_DECIMALS: u8 = 15;

/// Room for every digit of a finite double printed without exponent.
const DIGITS: usize = 400;

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
        let negative = digits.round(value * self.multiplier, self.decimals, self.scale);
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

    /// Appends the formatted value (prefix included) to `out`.
    pub fn write(&self, value: f64, out: &mut Vec<u8>) {
        let mut digits = Digits::new();
        let negative = digits.round(value * self.multiplier, self.decimals, self.scale);
        let integer = digits.integer();
        let mut fraction = digits.fraction();
        if self.trim_zeros {
            while let [rest @ .., b'0'] = fraction {
                fraction = rest;
            }
        }
        let is_zero = integer.iter().chain(fraction).all(|&d| d == b'0');
        let sign: &[u8] = match (negative && !is_zero, self.sign_always) {
            (true, _) => b"-",
            (false, true) => b"+",
            (false, false) => b"",
        };
        let integer: &[u8] = if !self.leading_zero && integer == b"0" && !fraction.is_empty() { b"" } else { integer };
        let point = !fraction.is_empty() || self.point_always;
        let mark = &self.mark[..self.mark_len];

        out.extend_from_slice(&self.prefix);
        let core_len = sign.len() + integer.len() + if point { mark.len() } else { 0 } + fraction.len();
        let (int_pad, outer_pad) = if self.integer_width {
            (self.width.saturating_sub(integer.len()), 0)
        } else {
            (0, self.width.saturating_sub(core_len))
        };
        let pad_zeros = self.zero_pad && !self.left;
        if !self.left && !pad_zeros {
            out.extend(std::iter::repeat_n(b' ', outer_pad));
        }
        out.extend_from_slice(sign);
        if pad_zeros {
            out.extend(std::iter::repeat_n(b'0', outer_pad));
        }
        let int_fill = if self.zero_pad { b'0' } else { b' ' };
        out.extend(std::iter::repeat_n(int_fill, int_pad));
        out.extend_from_slice(integer);
        if point {
            out.extend_from_slice(mark);
        }
        out.extend_from_slice(fraction);
        if self.left {
            out.extend(std::iter::repeat_n(b' ', outer_pad));
        }
    }
}

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

    /// Rounds `value` half away from zero to `decimals` places; returns
    /// whether it is negative. Non-finite values print as zero.
    fn round(&mut self, value: f64, decimals: usize, scale: f64) -> bool {
        let value = if value.is_finite() { value } else { 0.0 };
        let negative = value.is_sign_negative() && value != 0.0;
        let magnitude = value.abs();
        let scaled = magnitude * scale;
        // Fast path: far from a tie, the double's rounding decides nothing.
        if scaled < 4.5e15 {
            let floor = scaled.floor();
            let frac = scaled - floor;
            let margin = 8.0 * f64::EPSILON * scaled.max(1.0);
            if (frac - 0.5).abs() > margin {
                let m = floor as u64 + u64::from(frac > 0.5);
                self.fill_scaled_integer(m, decimals);
                return negative;
            }
        }
        self.fill_shortest_decimal(magnitude, decimals);
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

    /// Digits from the shortest round-trip decimal form of `magnitude`,
    /// rounded as decimal text.
    fn fill_shortest_decimal(&mut self, magnitude: f64, decimals: usize) {
        let mut text = [0u8; DIGITS];
        let len = {
            let mut cursor = std::io::Cursor::new(&mut text[..]);
            // `{}` on f64 writes the shortest digits that round-trip, with no exponent.
            let _ = write!(cursor, "{magnitude}");
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

#[cfg(test)]
mod tests;
