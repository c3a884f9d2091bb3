//! What the values of each global statement mean: `POST_NAME = "..."`,
//! `UNITS = "MM"`, `LINE_ENDING = "[13][10]"`, `SUBSTITUTE = "({)}"`,
//! `TAPE_SPLITTING = 1000 100 "%s_%d.tap" 1 "YES"`,
//! `SPINDLE_SPEED_RANGE = 1 15 4500 15000`, `ROTARY_WRAP_Y = "-A"`, ...

use postc_ir::post::{RotaryWrap, SpindleSpeedRange, Substitution, TapeSplitting, WrappedAxis};
use postc_ir::{Diagnostic, Span, Units};

use crate::ast::{QuotedText, Spanned, TextPiece, Value};
use crate::decode::Encoding;
use crate::diagnostics::Code;
use crate::lower::model::GlobalValue;
use crate::names::GlobalName;

/// Reads the values of one global statement; `None` after reporting a
/// problem.
pub fn interpret(
    name: GlobalName,
    line: Span,
    values: &[Spanned<Value>],
    encoding: Encoding,
    diags: &mut Vec<Diagnostic>,
) -> Option<GlobalValue> {
    let mut bad = |at: Span, message: String| {
        diags.push(
            Code::BadGlobalValue
                .diag(message)
                .at(at, "bad value")
                .help(format!("write it like this: {}", name.example())),
        );
        None
    };
    let whole = values.first().map_or(line, |first| values.iter().fold(first.span, |s, v| s.to(v.span)));
    let one = |bad: &mut dyn FnMut(Span, String) -> Option<GlobalValue>| -> Option<&Spanned<Value>> {
        match values {
            [v] => Some(v),
            [] => bad(line, format!("{} needs a value", name.name())).and(None),
            _ => bad(whole, format!("{} takes one value, this line has {}", name.name(), values.len())).and(None),
        }
    };
    use GlobalName as G;
    match name {
        G::PostName | G::FileExtension | G::DirectOutput | G::PostBase => {
            let v = one(&mut bad)?;
            Some(GlobalValue::Text(text_of(&v.value)))
        }
        G::Units => {
            let v = one(&mut bad)?;
            match text_of(&v.value).trim().to_ascii_uppercase().as_str() {
                "MM" => Some(GlobalValue::Units(Units::Mm)),
                "INCH" | "INCHES" => Some(GlobalValue::Units(Units::Inch)),
                other => bad(v.span, format!("UNITS must be \"MM\" or \"INCHES\", not \"{other}\"")),
            }
        }
        G::PrintDirect | G::RapidPlungeToStartZ | G::LaserSupport | G::InverseTimeMode => {
            let v = one(&mut bad)?;
            match flag(&v.value) {
                Some(f) => Some(GlobalValue::Flag(f)),
                None => bad(v.span, format!("{} is \"YES\" or \"NO\"", name.name())),
            }
        }
        G::LineNumberStart | G::LineNumberIncrement | G::LineNumberMaximum | G::MinArcRadius | G::MaxArcRadius => {
            let v = one(&mut bad)?;
            match number(&v.value) {
                Some(n) if n >= 0.0 => Some(GlobalValue::Number(n)),
                _ => bad(v.span, format!("{} is a number, 0 or more", name.name())),
            }
        }
        G::LineEnding => {
            let v = one(&mut bad)?;
            match &v.value {
                Value::Text(q) if q.pieces.iter().all(|p| !matches!(p.value, TextPiece::Label(_))) => {
                    Some(GlobalValue::Bytes(characters(q, encoding).concat()))
                }
                _ => {
                    bad(v.span, "LINE_ENDING holds characters and [nn] codes between quotes, like \"[13][10]\"".into())
                }
            }
        }
        G::Substitute => {
            let v = one(&mut bad)?;
            let Value::Text(q) = &v.value else {
                return bad(v.span, "SUBSTITUTE holds pairs of characters between quotes, like \"({)}\"".into());
            };
            let chars: Vec<Vec<u8>> =
                characters(q, encoding).into_iter().filter(|c| c.as_slice() != b" " && c.as_slice() != b"\t").collect();
            if chars.len() % 2 == 1 {
                diags.push(
                    Code::OddSubstitute
                        .diag("SUBSTITUTE has an odd number of characters; the last one has no replacement and is ignored")
                        .at(v.span, "pairs of original and replacement characters")
                        .help("write each character followed by its replacement; write [32] for a blank"),
                );
            }
            let pairs = chars.chunks_exact(2).map(|p| Substitution { from: p[0].clone(), to: p[1].clone() }).collect();
            Some(GlobalValue::Substitutions(pairs))
        }
        G::TapeSplitting => tape_splitting(values, whole, line, &mut bad),
        G::SpindleSpeedRange => {
            let numbers: Vec<f64> = values.iter().filter_map(|v| number(&v.value)).collect();
            match numbers.as_slice() {
                &[out_min, out_max, rpm_min, rpm_max] if values.len() == 4 => {
                    Some(GlobalValue::SpindleRange(SpindleSpeedRange { out_min, out_max, rpm_min, rpm_max }))
                }
                _ => bad(
                    whole,
                    "SPINDLE_SPEED_RANGE takes four numbers: lowest and highest output, lowest and highest rpm".into(),
                ),
            }
        }
        G::RotaryWrapX | G::RotaryWrapY => {
            let v = one(&mut bad)?;
            let axis = if name == G::RotaryWrapX { WrappedAxis::X } else { WrappedAxis::Y };
            match rotary_wrap(&text_of(&v.value), axis) {
                Some(wrap) => Some(GlobalValue::Wrap(wrap)),
                None => bad(v.span, format!("{} is an axis letter (A, \"-A\") or \"YES\" / \"NO\"", name.name())),
            }
        }
    }
}

/// `TAPE_SPLITTING = MAX TOL "FORMAT" START "YES"` (a blank string turns it
/// off; the last value may be left out and means "NO").
fn tape_splitting(
    values: &[Spanned<Value>],
    whole: Span,
    line: Span,
    bad: &mut dyn FnMut(Span, String) -> Option<GlobalValue>,
) -> Option<GlobalValue> {
    if let [Spanned { value: Value::Text(q), .. }] = values
        && q.plain().trim().is_empty()
    {
        return Some(GlobalValue::Tape(None));
    }
    let count = |v: &Spanned<Value>| number(&v.value).filter(|n| *n >= 0.0 && n.fract() == 0.0).map(|n| n as u64);
    let parsed = match values {
        [max, tol, Spanned { value: Value::Text(fmt), .. }, start, rest @ ..] if rest.len() <= 1 => {
            let index_on_first = match rest.first() {
                Some(v) => flag(&v.value),
                None => Some(false),
            };
            match (count(max), count(tol), count(start), index_on_first) {
                (Some(max_lines), Some(tolerance), Some(start_index), Some(index_on_first_file)) => {
                    Some(TapeSplitting {
                        max_lines,
                        tolerance,
                        name_format: fmt.plain(),
                        start_index,
                        index_on_first_file,
                    })
                }
                _ => None,
            }
        }
        _ => None,
    };
    match parsed {
        Some(t) => Some(GlobalValue::Tape(Some(t))),
        None => bad(
            if values.is_empty() { line } else { whole },
            "TAPE_SPLITTING takes: most lines per file, tolerance, \"file name format\", first index, \"YES\" or \"NO\"".into(),
        ),
    }
}

/// `A`, `"-A"`, `"YES"`, `"NO"`: `Some(None)` is "no wrapping".
fn rotary_wrap(text: &str, axis: WrappedAxis) -> Option<Option<RotaryWrap>> {
    let t = text.trim().to_ascii_uppercase();
    match t.as_str() {
        "YES" | "TRUE" | "ON" | "1" => {
            return Some(Some(RotaryWrap { axis, letter: None, reversed: false }));
        }
        "NO" | "FALSE" | "OFF" | "0" | "" => return Some(None),
        _ => {}
    }
    let (reversed, letter) = match t.strip_prefix('-') {
        Some(l) => (true, l),
        None => (false, t.as_str()),
    };
    let mut chars = letter.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) if c.is_ascii_alphabetic() => Some(Some(RotaryWrap { axis, letter: Some(c), reversed })),
        _ => None,
    }
}

/// The text of a value (`"mm"`, `mm`, `3`).
fn text_of(value: &Value) -> String {
    match value {
        Value::Text(q) => q.plain(),
        Value::Word(w) => w.clone(),
        Value::Number(n) => n.to_string(),
    }
}

/// `YES`/`NO` (also `TRUE`/`FALSE`, `ON`/`OFF`, `1`/`0`), any case.
fn flag(value: &Value) -> Option<bool> {
    match text_of(value).trim().to_ascii_uppercase().as_str() {
        "YES" | "TRUE" | "ON" | "1" => Some(true),
        "NO" | "FALSE" | "OFF" | "0" => Some(false),
        _ => None,
    }
}

/// A number, bare or quoted.
fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Number(n) => Some(*n),
        Value::Text(q) => q.plain().trim().parse::<f64>().ok().filter(|n| n.is_finite()),
        Value::Word(_) => None,
    }
}

/// The characters of a string as bytes: each literal character in the
/// file's encoding, each `[nn]` code as its byte, each label as written.
pub fn characters(text: &QuotedText, encoding: Encoding) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for piece in &text.pieces {
        match &piece.value {
            TextPiece::Text(t) => {
                for c in t.chars() {
                    let mut buf = [0u8; 4];
                    out.push(encoding.encode(c.encode_utf8(&mut buf)).into_owned());
                }
            }
            TextPiece::Code(b) => out.push(vec![*b]),
            TextPiece::Label(l) => out.push(encoding.encode(&format!("[{l}]")).into_owned()),
        }
    }
    out
}
