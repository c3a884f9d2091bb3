//! The value format of a `VAR` (`1.3`, `02.0`, `+1,3`, `-#5.0`): its
//! parser and what it lowers to.
//!
//! A format is optional flags (`-` left justify, `+` always a sign, `0` zero
//! padding, `#` always the decimal separator), then the minimum width, then
//! the decimal separator (`.` or `,`), then the number of decimals. A width
//! written with a leading zero (`02.0`) pads with zeros like the `0` flag.

use chumsky::prelude::*;
use postc_ir::{Justify, NumberFormat, Padding, PointStyle, SignStyle, WidthOf};

/// The most decimals a format may ask for (an `f64` holds no more).
pub const MAX_DECIMALS: u32 = 15;

/// A parsed value format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FormatSpec {
    /// `-`: left justify.
    pub left: bool,
    /// `+`: positive values carry a `+`.
    pub plus: bool,
    /// `0` (or a width written `0n`): pad with zeros.
    pub zero: bool,
    /// `#`: always write the decimal separator.
    pub point: bool,
    /// Minimum number of characters.
    pub width: u8,
    /// `.` or `,`.
    pub separator: char,
    /// The separator was written (a format without one prints whole
    /// numbers).
    pub has_separator: bool,
    pub decimals: u8,
}

impl Default for FormatSpec {
    /// `1.0`: a whole number.
    fn default() -> Self {
        FormatSpec {
            left: false,
            plus: false,
            zero: false,
            point: false,
            width: 1,
            separator: '.',
            has_separator: true,
            decimals: 0,
        }
    }
}

impl FormatSpec {
    /// The IR number format, with `multiplier`.
    pub fn to_number_format(self, multiplier: f64) -> NumberFormat {
        NumberFormat {
            decimals: self.decimals,
            width: self.width,
            width_of: WidthOf::Whole,
            padding: if self.zero { Padding::Zero } else { Padding::Space },
            justify: if self.left { Justify::Left } else { Justify::Right },
            sign: if self.plus { SignStyle::Always } else { SignStyle::Negative },
            point: if self.point { PointStyle::Always } else { PointStyle::WithDecimals },
            trim_zeros: false,
            leading_zero: true,
            decimal_mark: self.separator,
            multiplier,
            prefix: String::new(),
            rounding: postc_ir::Rounding::Decimal,
            // VCarve writes `Z-0.000` for a small negative Z (docs/vectric.md).
            negative_zero: true,
            span: None,
            name: None,
        }
    }
}

/// Why a format could not be read: a message and the byte range of the
/// format text it is about.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormatError {
    pub message: String,
    pub range: std::ops::Range<usize>,
}

#[derive(Clone, Copy)]
enum Flag {
    Left,
    Plus,
    Zero,
    Point,
}

type Extra<'a> = extra::Err<Rich<'a, char>>;

fn number<'a>() -> impl Parser<'a, &'a str, (u32, SimpleSpan), Extra<'a>> + Clone {
    text::digits(10).to_slice().map_with(|s: &str, e| (s.parse::<u32>().unwrap_or(u32::MAX), e.span()))
}

fn spec_parser<'a>() -> impl Parser<'a, &'a str, FormatSpec, Extra<'a>> {
    let flag = choice((
        just('-').to(Flag::Left),
        just('+').to(Flag::Plus),
        just('#').to(Flag::Point),
        just('0').then(one_of("0123456789-+#").rewind()).to(Flag::Zero),
    ));
    let blanks = one_of(" \t").repeated();
    blanks
        .ignore_then(flag.repeated().collect::<Vec<_>>())
        .then(number().or_not())
        .then(one_of(".,").then(number().or_not()).or_not())
        .then_ignore(blanks)
        .then_ignore(end())
        .validate(|((flags, width), fraction), _, emitter| {
            let mut spec = FormatSpec::default();
            for flag in flags {
                match flag {
                    Flag::Left => spec.left = true,
                    Flag::Plus => spec.plus = true,
                    Flag::Zero => spec.zero = true,
                    Flag::Point => spec.point = true,
                }
            }
            if let Some((w, span)) = width {
                match u8::try_from(w) {
                    Ok(w) => spec.width = w,
                    Err(_) => emitter.emit(Rich::custom(span, "the width is at most 255 characters")),
                }
            }
            match fraction {
                Some((separator, decimals)) => {
                    spec.separator = separator;
                    if let Some((d, span)) = decimals {
                        match u8::try_from(d) {
                            Ok(d) if u32::from(d) <= MAX_DECIMALS => spec.decimals = d,
                            _ => emitter.emit(Rich::custom(span, format!("at most {MAX_DECIMALS} decimals"))),
                        }
                    }
                }
                None => spec.has_separator = false,
            }
            spec
        })
}

/// Reads a value format.
pub fn parse_format(text: &str) -> Result<FormatSpec, FormatError> {
    let (spec, errors) = spec_parser().parse(text).into_output_errors();
    if let Some(error) = errors.first() {
        let range = error.span().into_range();
        let message = match error.reason() {
            chumsky::error::RichReason::Custom(m) => m.clone(),
            _ => format!(
                "`{}` is not a value format: write optional flags (- + 0 #), a width, `.` or `,` and the decimals, like 1.3 or +1,3",
                text.trim()
            ),
        };
        return Err(FormatError { message, range });
    }
    if text.trim().is_empty() {
        return Err(FormatError {
            message: "the value format is empty: write a width, `.` or `,` and the decimals, like 1.3".to_string(),
            range: 0..text.len(),
        });
    }
    spec.ok_or_else(|| FormatError {
        message: format!("`{}` is not a value format", text.trim()),
        range: 0..text.len(),
    })
}
