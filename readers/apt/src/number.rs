//! APT numbers: `5.`, `.5`, `-1.5E-3`, Fortran's `1.5D3`. The usual CL
//! number is read on a fast path in the same pass that finds its end; the
//! rest goes through the standard library. `INF` and `NAN` are words.

use crate::grammar::VALUE_BYTE;

/// Exact powers of ten representable as `f64`.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
    1e21, 1e22,
];

/// Reads an APT number: digits with an optional point, sign and exponent
/// (`E` or Fortran's `D`). `None` for anything else (`INF` and `NAN` are words).
///
/// The usual CL number (at most 15 significant digits, no exponent) is read
/// on a fast path that divides two exact values, which rounds correctly;
/// anything else goes through the standard library.
#[doc(hidden)]
pub fn parse_number(s: &[u8]) -> Option<f64> {
    let (negative, body) = match *s.first()? {
        b'-' => (true, &s[1..]),
        b'+' => (false, &s[1..]),
        _ => (false, s),
    };
    // Digits, an optional point, digits: 18 digits never overflow a u64.
    let mut mantissa: u64 = 0;
    let mut i = 0;
    while let Some(d) = body.get(i).map(|b| b.wrapping_sub(b'0')).filter(|d| *d < 10) {
        mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    let mut digits = i;
    let mut decimals = 0;
    if body.get(i) == Some(&b'.') {
        i += 1;
        while let Some(d) = body.get(i).map(|b| b.wrapping_sub(b'0')).filter(|d| *d < 10) {
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
            i += 1;
            decimals += 1;
        }
        digits += decimals;
    }
    if i != body.len() {
        return parse_number_slow(s);
    }
    if digits == 0 {
        return None;
    }
    if digits <= 18 && mantissa < (1u64 << 53) && decimals < POW10.len() {
        let value = mantissa as f64 / POW10[decimals];
        return Some(if negative { -value } else { value });
    }
    parse_number_slow(s)
}

/// Scans a value at the start of `tail`: its length, and its value when it
/// is a number. The common case (a plain decimal number) is read in the
/// same pass that finds its end.
pub(crate) fn scan_value(tail: &[u8]) -> (usize, Option<f64>) {
    let (negative, start) = match tail.first() {
        Some(b'-') => (true, 1),
        Some(b'+') => (false, 1),
        _ => (false, 0),
    };
    let mut mantissa: u64 = 0;
    let mut i = start;
    while let Some(d) = tail.get(i).map(|b| b.wrapping_sub(b'0')).filter(|d| *d < 10) {
        mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    let mut digits = i - start;
    let mut decimals = 0;
    if tail.get(i) == Some(&b'.') {
        i += 1;
        while let Some(d) = tail.get(i).map(|b| b.wrapping_sub(b'0')).filter(|d| *d < 10) {
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
            i += 1;
            decimals += 1;
        }
        digits += decimals;
    }
    let ends = tail.get(i).is_none_or(|&b| !VALUE_BYTE[b as usize]);
    if ends && digits > 0 && digits <= 18 && mantissa < (1u64 << 53) && decimals < POW10.len() {
        let value = mantissa as f64 / POW10[decimals];
        return (i, Some(if negative { -value } else { value }));
    }
    let n = i + tail[i.min(tail.len())..]
        .iter()
        .position(|&b| !VALUE_BYTE[b as usize])
        .unwrap_or(tail.len() - i.min(tail.len()));
    (n, parse_number(&tail[..n]))
}

fn parse_number_slow(s: &[u8]) -> Option<f64> {
    let mut digits = false;
    for &b in s {
        match b {
            b'0'..=b'9' => digits = true,
            b'+' | b'-' | b'.' | b'e' | b'E' | b'd' | b'D' => {}
            _ => return None,
        }
    }
    // A sign only at the start or after the exponent letter.
    let signs_ok = s
        .iter()
        .enumerate()
        .all(|(i, &b)| !matches!(b, b'+' | b'-') || i == 0 || matches!(s[i - 1], b'e' | b'E' | b'd' | b'D'));
    if !digits || !signs_ok {
        return None;
    }
    let text: String = s.iter().map(|&b| if b == b'd' || b == b'D' { 'E' } else { b as char }).collect();
    text.parse::<f64>().ok().filter(|v| v.is_finite())
}
