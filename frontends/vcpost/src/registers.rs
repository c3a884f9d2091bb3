//! Registers and their properties: how a register prints.
//!
//! A register is a name that appears as `<NAME>` in an `Out` string, has a
//! property set, is read with `.Previous`, or is a keyword-comment
//! parameter. Each becomes an IR [`postc_ir::Variable`] with its own
//! [`NumberFormat`]. Properties are set by statements outside any Sub,
//! applied when the post is compiled (the IR's formats are fixed):
//!
//! | property | value | meaning | default |
//! |---|---|---|---|
//! | `Prefix` | text | written before the number | the register's name as first written (`N` for `N`) |
//! | `Format` | text `"[+]I.D"` | up to `I` integer digits, `D` decimals; `+` forces the sign | `"4.4"` (`N`: `"6.0"`) |
//! | `Decimals` | 0-9 | decimals alone | 4 (`N`: 0) |
//! | `TrailingZeros` | `True`/`False` | keep trailing zeros of the fraction | `False` (trimmed: `X10`, `X10.5`) |
//! | `LeadingZeros` | `True`/`False` or a number | pad the integer part with zeros to the `Format`'s integer digits (or to that many) | `False` |
//! | `DecimalPoint` | `True`/`False` or `"Always"`/`"Auto"` | write the point even with no decimals after it (`X10.`) | `False` (`"Auto"`) |
//! | `ZeroBeforePoint` | `True`/`False` | `0.5` rather than `.5` | `True` |
//! | `Sign` | `"+"`/`"Always"`/`True`, `"-"`/`"Negative"`/`False` | when a sign is written | negative only |
//! | `Width` | 0-40 | minimum width of the whole number, blank padded | 0 |
//! | `Padding` | `"Blank"`/`"Zero"` | what fills `Width` (zeros go after the sign: `-0012`) | `"Blank"` |
//! | `Justify` | `"Left"`/`"Right"` | side of the value inside `Width` | `"Right"` |
//! | `DecimalMark` | `"."` or `","` | the decimal mark | `"."` |
//! | `Multiplier` (or `Scale`) | number | the value is multiplied by this before rounding | 1 |
//! | `NegativeZero` | `True`/`False` | a negative value that rounds to zero keeps its minus (`-0.000`), as Vectric prints it | `False` |
//! | `Modal` | `True`/`False` | print only when the printed text changes (memory cleared at each toolpath start) | `False` (always printed) |
//! | `Start`, `Increment`, `Maximum` | number | `N` only: block numbering | 1, 1, 999999 |

use postc_ir::post::BlockNumbers;
use postc_ir::{Diagnostic, Justify, Modality, NumberFormat, Padding, PointStyle, SignStyle, Span, WidthOf};

use crate::ast::{Expr, ExprKind, Name, UnaryOp};
use crate::diagnostics as codes;

/// Every property name, as documented.
pub const PROPERTIES: &[&str] = &[
    "Prefix",
    "Format",
    "Decimals",
    "TrailingZeros",
    "LeadingZeros",
    "DecimalPoint",
    "ZeroBeforePoint",
    "Sign",
    "Width",
    "Padding",
    "Justify",
    "DecimalMark",
    "Multiplier",
    "Scale",
    "NegativeZero",
    "Modal",
    "Start",
    "Increment",
    "Maximum",
];

/// How one register prints, as the properties have set it so far.
#[derive(Clone, Debug)]
pub struct RegisterSpec {
    /// The name as first written.
    pub name: String,
    pub prefix: Option<String>,
    pub format: NumberFormat,
    /// Integer digits from `Format` (used by `LeadingZeros = True`).
    pub integer_digits: u8,
    /// `LeadingZeros`: pad to this many integer digits, and where it was set.
    pub leading_zeros: Option<(u8, Span)>,
    /// `Width`, and where it was set.
    pub width: Option<(u8, Span)>,
    /// `Padding = "Zero"`: `Width` is filled with zeros.
    pub zero_fill: bool,
    pub modality: Modality,
    /// The register's first mention in the post.
    pub span: Option<Span>,
}

impl RegisterSpec {
    /// A register with the defaults.
    pub fn new(name: &str) -> RegisterSpec {
        let sequence = name.eq_ignore_ascii_case("N");
        RegisterSpec {
            name: if sequence { "N".to_string() } else { name.to_string() },
            prefix: None,
            format: NumberFormat {
                decimals: if sequence { 0 } else { 4 },
                trim_zeros: true,
                width: 0,
                ..NumberFormat::default()
            },
            integer_digits: if sequence { 6 } else { 4 },
            span: None,
            leading_zeros: None,
            width: None,
            zero_fill: false,
            modality: Modality::Always,
        }
    }

    /// The prefix, format and modality the register ends up with.
    pub fn finish(&self, diagnostics: &mut Vec<Diagnostic>) -> (Vec<u8>, NumberFormat, Modality) {
        let mut format = self.format.clone();
        match (self.leading_zeros, self.width) {
            (Some((digits, _)), None) if digits > 0 => {
                format.width = digits;
                format.width_of = WidthOf::IntegerDigits;
                format.padding = Padding::Zero;
            }
            (None | Some(_), Some((width, _))) => {
                format.width = width;
                format.width_of = WidthOf::Whole;
                format.padding = if self.zero_fill { Padding::Zero } else { Padding::Space };
                if let Some((_, at)) = self.leading_zeros.filter(|(d, _)| *d > 0) {
                    diagnostics.push(
                        Diagnostic::error(
                            codes::BAD_PROPERTY_VALUE,
                            format!("`{}` sets both `Width` and `LeadingZeros`", self.name),
                        )
                        .at(at, "a register pads with zeros or with blanks, not both")
                        .help("keep `LeadingZeros` for zero padding (`N0010`) or `Width` for blank padding"),
                    );
                }
            }
            _ => {}
        }
        let prefix = self.prefix.clone().unwrap_or_else(|| self.name.clone());
        (prefix.into_bytes(), format, self.modality)
    }
}

/// A property value known when the post is compiled.
#[derive(Clone, Debug, PartialEq)]
enum Constant {
    Number(f64),
    Text(String),
    Bool(bool),
}

fn constant(e: &Expr) -> Option<Constant> {
    match &e.kind {
        ExprKind::Number(n) => Some(Constant::Number(*n)),
        ExprKind::Text(t) => Some(Constant::Text(t.clone())),
        ExprKind::Bool(b) => Some(Constant::Bool(*b)),
        ExprKind::Paren(inner) => constant(inner),
        ExprKind::Unary(UnaryOp::Neg, inner) => match constant(inner)? {
            Constant::Number(n) => Some(Constant::Number(-n)),
            _ => None,
        },
        ExprKind::Unary(UnaryOp::Plus, inner) => constant(inner),
        _ => None,
    }
}

/// Sets one property. `numbering` receives `N.Start` and friends.
pub fn apply(
    spec: &mut RegisterSpec,
    property: &Name,
    value: &Expr,
    numbering: &mut BlockNumbers,
) -> Result<(), Diagnostic> {
    let Some(canonical) = PROPERTIES.iter().find(|p| property.is(p)) else {
        let mut d =
            Diagnostic::error(codes::UNKNOWN_PROPERTY, format!("registers have no property `{}`", property.text))
                .at(property.span, "unknown property");
        d = if property.is("Previous") {
            d.help("`.Previous` is read-only: it is the value the register had before its last assignment")
        } else if let Some(s) = codes::suggest(&property.text, PROPERTIES.iter().copied()) {
            d.help(format!("did you mean `{}.{s}`?", spec.name))
        } else {
            d.help(format!("register properties are {}", PROPERTIES.join(", ")))
        };
        return Err(d);
    };
    let Some(v) = constant(value) else {
        return Err(Diagnostic::error(
            codes::BAD_PROPERTY_VALUE,
            format!("`{}.{canonical}` must be set to a plain value", spec.name),
        )
        .at(value.span, "not a number, text, True or False")
        .help("register properties are fixed when the post is compiled; write the value itself"));
    };
    let bad = |expected: &str| {
        Diagnostic::error(codes::BAD_PROPERTY_VALUE, format!("`{}.{canonical}` cannot be set to this value", spec.name))
            .at(value.span, format!("expected {expected}"))
    };
    let sequence = spec.name == "N";
    match (*canonical, &v) {
        ("Prefix", Constant::Text(t)) => spec.prefix = Some(t.clone()),
        ("Format", Constant::Text(t)) => {
            let (sign, int_digits, decimals) = parse_format(t).ok_or_else(|| {
                bad("a format such as \"4.3\" (integer digits, then decimals), \"+4.3\" to force the sign")
            })?;
            spec.integer_digits = int_digits;
            spec.format.decimals = decimals;
            if sign {
                spec.format.sign = SignStyle::Always;
            }
        }
        ("Decimals", Constant::Number(n)) => {
            spec.format.decimals = small(*n, 9).ok_or_else(|| bad("a whole number from 0 to 9"))?
        }
        ("TrailingZeros", Constant::Bool(b)) => spec.format.trim_zeros = !b,
        ("LeadingZeros", Constant::Bool(b)) => {
            spec.leading_zeros = Some((if *b { spec.integer_digits } else { 0 }, value.span))
        }
        ("LeadingZeros", Constant::Number(n)) => {
            spec.leading_zeros =
                Some((small(*n, 20).ok_or_else(|| bad("True, False or a digit count from 0 to 20"))?, value.span))
        }
        ("DecimalPoint", Constant::Bool(b)) => {
            spec.format.point = if *b { PointStyle::Always } else { PointStyle::WithDecimals }
        }
        ("DecimalPoint", Constant::Text(t)) if t.eq_ignore_ascii_case("always") => {
            spec.format.point = PointStyle::Always
        }
        ("DecimalPoint", Constant::Text(t)) if t.eq_ignore_ascii_case("auto") => {
            spec.format.point = PointStyle::WithDecimals
        }
        ("ZeroBeforePoint", Constant::Bool(b)) => spec.format.leading_zero = *b,
        ("Sign", Constant::Bool(b)) => spec.format.sign = if *b { SignStyle::Always } else { SignStyle::Negative },
        ("Sign", Constant::Text(t)) if t == "+" || t.eq_ignore_ascii_case("always") => {
            spec.format.sign = SignStyle::Always
        }
        ("Sign", Constant::Text(t)) if t == "-" || t.eq_ignore_ascii_case("negative") => {
            spec.format.sign = SignStyle::Negative
        }
        ("Width", Constant::Number(n)) => {
            spec.width = Some((small(*n, 40).ok_or_else(|| bad("a whole number from 0 to 40"))?, value.span))
        }
        ("Padding", Constant::Text(t)) if t.eq_ignore_ascii_case("zero") => spec.zero_fill = true,
        ("Padding", Constant::Text(t)) if t.eq_ignore_ascii_case("blank") => spec.zero_fill = false,
        ("Justify", Constant::Text(t)) if t.eq_ignore_ascii_case("left") => spec.format.justify = Justify::Left,
        ("Justify", Constant::Text(t)) if t.eq_ignore_ascii_case("right") => spec.format.justify = Justify::Right,
        ("DecimalMark", Constant::Text(t)) if t == "." || t == "," => {
            spec.format.decimal_mark = t.chars().next().unwrap_or('.')
        }
        ("Multiplier" | "Scale", Constant::Number(n)) if n.is_finite() && *n != 0.0 => spec.format.multiplier = *n,
        ("NegativeZero", Constant::Bool(b)) => spec.format.negative_zero = *b,
        ("Modal", Constant::Bool(b)) => spec.modality = if *b { Modality::OnChange } else { Modality::Always },
        ("Start" | "Increment" | "Maximum", _) if !sequence => {
            return Err(Diagnostic::error(
                codes::UNKNOWN_PROPERTY,
                format!("only the sequence number `N` has `{canonical}`"),
            )
            .at(property.span, format!("`{}` is not the sequence number", spec.name))
            .help(format!("block numbering is set with `N.{canonical} = ...`")));
        }
        ("Start", Constant::Number(n)) if n.is_finite() && *n >= 0.0 => numbering.start = *n,
        ("Increment", Constant::Number(n)) if n.is_finite() && *n > 0.0 => numbering.increment = *n,
        ("Maximum", Constant::Number(n)) if n.is_finite() && *n > 0.0 => numbering.maximum = *n,
        (p, _) => return Err(bad(expected_for(p))),
    }
    Ok(())
}

fn expected_for(property: &str) -> &'static str {
    match property {
        "Prefix" => "text in quotes",
        "Format" => "a format in quotes, such as \"4.3\"",
        "Decimals" => "a whole number from 0 to 9",
        "TrailingZeros" | "ZeroBeforePoint" | "NegativeZero" | "Modal" => "True or False",
        "LeadingZeros" => "True, False or a digit count",
        "DecimalPoint" => "True, False, \"Always\" or \"Auto\"",
        "Sign" => "\"+\" (always) or \"-\" (negative only)",
        "Width" => "a whole number from 0 to 40",
        "Justify" => "\"Left\" or \"Right\"",
        "Padding" => "\"Blank\" or \"Zero\"",
        "DecimalMark" => "\".\" or \",\"",
        "Multiplier" | "Scale" => "a number other than 0",
        "Start" => "a number, 0 or more",
        _ => "a number above 0",
    }
}

fn small(n: f64, max: u8) -> Option<u8> {
    (n.fract() == 0.0 && (0.0..=f64::from(max)).contains(&n)).then_some(n as u8)
}

/// `"[+]I.D"`, `"[+]I"` or `"[+].D"`: forced sign, integer digits, decimals.
pub fn parse_format(text: &str) -> Option<(bool, u8, u8)> {
    let t = text.trim();
    let (sign, t) = match t.strip_prefix('+') {
        Some(rest) => (true, rest),
        None => (false, t),
    };
    let (int, dec) = match t.split_once('.') {
        Some((i, d)) => (i, d),
        None => (t, ""),
    };
    if int.is_empty() && dec.is_empty() {
        return None;
    }
    let digits = |s: &str, max: u8| -> Option<u8> {
        if s.is_empty() {
            return Some(0);
        }
        if !s.bytes().all(|b| b.is_ascii_digit()) || s.len() > 2 {
            return None;
        }
        s.parse::<u8>().ok().filter(|v| *v <= max)
    };
    Some((sign, digits(int, 20)?, digits(dec, 9)?))
}
