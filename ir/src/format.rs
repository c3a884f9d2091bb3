//! Number-format descriptors: one type that says how every dialect prints a
//! number.
//!
//! A Vectric `1.3` with flags, a CIMCO `createFormat({...})` and a VcPost
//! register format all become a [`NumberFormat`]. The runtime's formatter
//! reads only this type. Printing a value goes:
//!
//! 1. multiply by `multiplier` (unit conversion has happened before);
//! 2. round half away from zero to `decimals` places, on the decimal value
//!    of the number (2.675 rounds to 2.68 even though the binary double is a
//!    hair below), or on the binary double itself under
//!    [`Rounding::Binary`] (2.675 rounds to 2.67, as JavaScript's
//!    `toFixed` does: CIMCO formats);
//! 3. drop trailing fraction zeros when `trim_zeros`; write the decimal mark
//!    as `point` says;
//! 4. write the sign (`-` for negatives, `+` too under `SignStyle::Always`;
//!    a value that rounds to zero has no sign, unless `negative_zero` keeps
//!    the minus of a negative value: `-0.000`);
//! 5. pad to `width` (counted as `WidthOf` says) with blanks or zeros, on the
//!    left unless `justify` is `Left`;
//! 6. put `prefix` in front.

use serde::{Deserialize, Serialize};

use crate::Span;

/// How one number prints.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct NumberFormat {
    /// Digits after the decimal mark.
    pub decimals: u8,
    /// Minimum width; what it counts is `width_of`.
    pub width: u8,
    /// What `width` counts.
    pub width_of: WidthOf,
    /// What fills the width.
    pub padding: Padding,
    /// Which side the value sits on inside the width.
    pub justify: Justify,
    /// When a sign is written.
    pub sign: SignStyle,
    /// When the decimal mark is written.
    pub point: PointStyle,
    /// Drop trailing zeros of the fraction.
    pub trim_zeros: bool,
    /// Write `0.5` rather than `.5`.
    pub leading_zero: bool,
    /// The decimal mark, `.` or `,`.
    pub decimal_mark: char,
    /// The value is multiplied by this before rounding.
    pub multiplier: f64,
    /// Text written before the number (after the variable's own prefix).
    pub prefix: String,
    /// Which value is rounded: the decimal the double's shortest form names
    /// (Vectric, VcPost) or the binary double (CIMCO, as a JavaScript
    /// engine rounds). Written out (RON) only when it is `Binary`.
    #[serde(skip_serializing_if = "Rounding::is_decimal")]
    pub rounding: Rounding,
    /// A negative value that rounds to zero keeps its minus sign (`-0.000`
    /// for -0.0001), as Vectric's engine prints it; zero itself, -0.0
    /// included, has no sign either way. Written out (RON) only when set.
    #[serde(skip_serializing_if = "is_false")]
    pub negative_zero: bool,
    /// Where the post defines the format (a Vectric `VAR` line, a CIMCO
    /// `createFormat` call); `None` for formats a frontend made up.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub span: Option<Span>,
    /// The name the post gave the format (CIMCO `var xyzFormat =
    /// createFormat(...)`), which a backend prints; `None` for a format
    /// made without one (inside a `createVariable` call, a Vectric `VAR`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// Which value a format rounds to its decimals, half away from zero.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Rounding {
    /// The decimal value the double's shortest round-trip form names:
    /// 1.005 (stored as 1.00499999999999989...) prints 1.01 at two decimals.
    #[default]
    Decimal,
    /// The exact binary value of the double, as JavaScript's
    /// `Number.prototype.toFixed` rounds: 1.005 prints 1.00; an exact tie
    /// (0.125 at two decimals) rounds away from zero (0.13).
    Binary,
}

impl Rounding {
    fn is_decimal(&self) -> bool {
        *self == Rounding::Decimal
    }
}

impl Default for NumberFormat {
    fn default() -> Self {
        NumberFormat {
            decimals: 3,
            width: 1,
            width_of: WidthOf::Whole,
            padding: Padding::Space,
            justify: Justify::Right,
            sign: SignStyle::Negative,
            point: PointStyle::WithDecimals,
            trim_zeros: false,
            leading_zero: true,
            decimal_mark: '.',
            multiplier: 1.0,
            prefix: String::new(),
            rounding: Rounding::Decimal,
            negative_zero: false,
            span: None,
            name: None,
        }
    }
}

/// What a format's `width` counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum WidthOf {
    /// The whole number, sign and decimal mark included (Vectric).
    #[default]
    Whole,
    /// The integer digits only (CIMCO `width` with `zeropad`).
    IntegerDigits,
}

/// What fills a format's width.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Padding {
    #[default]
    Space,
    /// Zeros, after the sign (`-0012.5`).
    Zero,
}

/// Where the value sits in its width.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Justify {
    #[default]
    Right,
    /// Blanks go after the value (zeros never do).
    Left,
}

/// When a sign is written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum SignStyle {
    /// Only negative values carry a sign.
    #[default]
    Negative,
    /// Every non-zero value carries `+` or `-`; zero carries `+`.
    Always,
}

/// When the decimal mark is written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum PointStyle {
    /// When digits follow it (Vectric without `#`).
    #[default]
    WithDecimals,
    /// Always, even with no digits after it (`#` flag: `12.`).
    Always,
}
