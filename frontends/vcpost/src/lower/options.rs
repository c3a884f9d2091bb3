//! postc's extension of VcPost for posts driven by the kind of each move:
//! `Postc.Property = value` statements (outside the Subs) that set what a
//! Vectric post sets with its global statements, so that a Vectric post
//! converts to VcPost (docs/vcpost.md, "Section posts").
//!
//! | property | value | Vectric statement |
//! |---|---|---|
//! | `Name` | text | `POST_NAME` |
//! | `FileExtension` | text | `FILE_EXTENSION` |
//! | `Units` | `"MM"` or `"INCH"` | `UNITS` |
//! | `LineEnding` | `"CRLF"`, `"LF"` or `"CR"` | `LINE_ENDING` |
//! | `Substitute` | two characters: the one replaced, its replacement (one statement per pair) | `SUBSTITUTE` |
//! | `SpindleSpeedRange` | `"OUTMIN OUTMAX RPMMIN RPMMAX"` | `SPINDLE_SPEED_RANGE` |
//! | `RotaryWrap` | `"X"`/`"Y"`, then the letter that replaces it, `-` first when reversed (`"X -A"`) | `ROTARY_WRAP_X`/`_Y` |
//! | `MinArcRadius`, `MaxArcRadius` | number | `MIN_ARC_RADIUS`, `MAX_ARC_RADIUS` |
//! | `InverseTimeFeed`, `LaserSupport`, `PrintDirect`, `RapidPlungeToStartZ` | `True`/`False` | `INVERSE_TIME_MODE`, `LASER_SUPPORT`, `PRINT_DIRECT`, `RAPID_PLUNGE_TO_STARTZ` |
//! | `DirectOutput` | text | `DIRECT_OUTPUT` |
//! | `TapeSplitLines`, `TapeSplitTolerance`, `TapeSplitName`, `TapeSplitStart`, `TapeSplitIndexFirst` | number, number, text, number, `True`/`False` | `TAPE_SPLITTING = MAX TOL "FORMAT" START "INDEX_ON_FIRST"` (splitting is on once `TapeSplitLines` is set) |
//! | `Revision` | text | none: what `[REVISION]` prints, the hash of the Vectric post it was converted from (docs/vectric.md) |
//! | `OnChangeByValue`, `RapidForgetsFeed` | `True`/`False` | none: what VCarve's engine does (docs/vectric.md): a `Modal` register prints when its value changes, not its text; the feed prints again on the first feed move after a rapid |
//! | `ModalMemory` | `"Toolpath"` or `"Program"` | none: how long a `Modal` register remembers what it printed, until each toolpath starts (Vectric's rule, the default) or for the whole program (CNC-Calc's) |

use postc_ir::post::{RotaryWrap, SpindleSpeedRange, Substitution, TapeSplitting, WrappedAxis};
use postc_ir::{Diagnostic, OutputOptions, PostInfo, Units};

use super::Lowerer;
use crate::ast::{Expr, ExprKind, Name, UnaryOp};
use crate::diagnostics as codes;

/// The pseudo-register whose properties are the post's options.
pub const OPTIONS: &str = "Postc";

/// Every property, as documented.
pub const PROPERTIES: &[&str] = &[
    "Name",
    "FileExtension",
    "Units",
    "LineEnding",
    "Substitute",
    "SpindleSpeedRange",
    "RotaryWrap",
    "MinArcRadius",
    "MaxArcRadius",
    "InverseTimeFeed",
    "LaserSupport",
    "PrintDirect",
    "RapidPlungeToStartZ",
    "DirectOutput",
    "TapeSplitLines",
    "TapeSplitTolerance",
    "TapeSplitName",
    "TapeSplitStart",
    "TapeSplitIndexFirst",
    "OnChangeByValue",
    "RapidForgetsFeed",
    "ModalMemory",
    "Revision",
];

enum Value {
    Number(f64),
    Text(String),
    Bool(bool),
}

fn value(e: &Expr) -> Option<Value> {
    match &e.kind {
        ExprKind::Number(n) => Some(Value::Number(*n)),
        ExprKind::Text(t) => Some(Value::Text(t.clone())),
        ExprKind::Bool(b) => Some(Value::Bool(*b)),
        ExprKind::Paren(inner) => value(inner),
        ExprKind::Unary(UnaryOp::Neg, inner) => match value(inner)? {
            Value::Number(n) => Some(Value::Number(-n)),
            _ => None,
        },
        _ => None,
    }
}

impl Lowerer<'_> {
    /// `Postc.Property = value`.
    pub(super) fn postc_option(&mut self, property: &Name, e: &Expr) {
        let Some(canonical) = PROPERTIES.iter().copied().find(|p| property.is(p)) else {
            self.diagnostics.push(
                Diagnostic::error(codes::UNKNOWN_PROPERTY, format!("`{OPTIONS}` has no property `{}`", property.text))
                    .at(property.span, "unknown option")
                    .help(format!("postc's options are {}", PROPERTIES.join(", "))),
            );
            return;
        };
        let bad = |expected: &str| {
            Diagnostic::error(codes::BAD_PROPERTY_VALUE, format!("`{OPTIONS}.{canonical}` cannot be set to this value"))
                .at(e.span, format!("expected {expected}"))
        };
        let info = &mut self.post.info;
        let options = &mut self.post.options;
        let count = |n: f64| (n.fract() == 0.0 && (0.0..1e15).contains(&n)).then_some(n as u64);
        let value = value(e);
        if let (Some(flag), Some(Value::Bool(b))) = (flag_of(canonical, info, options), &value) {
            *flag = *b;
            return;
        }
        let result = match (canonical, value) {
            ("Name", Some(Value::Text(t))) => {
                info.name = t;
                Ok(())
            }
            ("FileExtension", Some(Value::Text(t))) => {
                info.file_extension = t;
                Ok(())
            }
            ("Units", Some(Value::Text(t))) if t.eq_ignore_ascii_case("mm") => {
                info.units = Some(Units::Mm);
                Ok(())
            }
            ("Units", Some(Value::Text(t))) if t.eq_ignore_ascii_case("inch") => {
                info.units = Some(Units::Inch);
                Ok(())
            }
            ("Units", _) => Err(bad("\"MM\" or \"INCH\"")),
            ("LineEnding", Some(Value::Text(t))) => match t.to_ascii_uppercase().as_str() {
                "CRLF" => {
                    options.line_ending = b"\r\n".to_vec();
                    Ok(())
                }
                "LF" => {
                    options.line_ending = b"\n".to_vec();
                    Ok(())
                }
                "CR" => {
                    options.line_ending = b"\r".to_vec();
                    Ok(())
                }
                _ => Err(bad("\"CRLF\", \"LF\" or \"CR\"")),
            },
            ("Substitute", Some(Value::Text(t))) => {
                let chars: Vec<char> = t.chars().collect();
                match chars.as_slice() {
                    [from, to] => {
                        options.substitutions.push(Substitution {
                            from: from.to_string().into_bytes(),
                            to: to.to_string().into_bytes(),
                        });
                        Ok(())
                    }
                    _ => Err(bad("two characters: the one replaced, then its replacement")),
                }
            }
            ("SpindleSpeedRange", Some(Value::Text(t))) => {
                let n: Vec<f64> = t.split_whitespace().filter_map(|w| w.parse().ok()).collect();
                match n.as_slice() {
                    [out_min, out_max, rpm_min, rpm_max] if t.split_whitespace().count() == 4 => {
                        options.spindle_speed_range = Some(SpindleSpeedRange {
                            out_min: *out_min,
                            out_max: *out_max,
                            rpm_min: *rpm_min,
                            rpm_max: *rpm_max,
                        });
                        Ok(())
                    }
                    _ => Err(bad("four numbers: \"OUTMIN OUTMAX RPMMIN RPMMAX\"")),
                }
            }
            ("RotaryWrap", Some(Value::Text(t))) => {
                let words: Vec<&str> = t.split_whitespace().collect();
                let axis = match words.first().map(|w| w.to_ascii_uppercase()) {
                    Some(a) if a == "X" => Some(WrappedAxis::X),
                    Some(a) if a == "Y" => Some(WrappedAxis::Y),
                    _ => None,
                };
                let letter = words.get(1).map(|w| (w.starts_with('-'), w.trim_start_matches('-')));
                match (axis, letter, words.len()) {
                    (Some(axis), None, 1) => {
                        options.rotary_wrap = Some(RotaryWrap { axis, letter: None, reversed: false });
                        Ok(())
                    }
                    (Some(axis), Some((reversed, l)), 2) if l.chars().count() == 1 => {
                        options.rotary_wrap = Some(RotaryWrap { axis, letter: l.chars().next(), reversed });
                        Ok(())
                    }
                    _ => Err(bad("\"X\" or \"Y\", then the letter that replaces it (\"X A\", \"Y -B\")")),
                }
            }
            ("MinArcRadius", Some(Value::Number(n))) if n.is_finite() => {
                options.min_arc_radius = Some(n);
                Ok(())
            }
            ("MaxArcRadius", Some(Value::Number(n))) if n.is_finite() => {
                options.max_arc_radius = Some(n);
                Ok(())
            }
            ("DirectOutput", Some(Value::Text(t))) => {
                info.direct_output = Some(t);
                Ok(())
            }
            ("ModalMemory", Some(Value::Text(t))) if t.eq_ignore_ascii_case("toolpath") => {
                options.forget_modal_at_toolpath_start = true;
                Ok(())
            }
            ("ModalMemory", Some(Value::Text(t))) if t.eq_ignore_ascii_case("program") => {
                options.forget_modal_at_toolpath_start = false;
                Ok(())
            }
            ("ModalMemory", _) => Err(bad("\"Toolpath\" or \"Program\"")),
            ("Revision", Some(Value::Text(t))) => {
                info.revision = t;
                Ok(())
            }
            ("TapeSplitLines", Some(Value::Number(n))) if count(n).is_some_and(|c| c > 0) => {
                split(options).max_lines = n as u64;
                Ok(())
            }
            ("TapeSplitTolerance", Some(Value::Number(n))) if count(n).is_some() => {
                split(options).tolerance = n as u64;
                Ok(())
            }
            ("TapeSplitStart", Some(Value::Number(n))) if count(n).is_some() => {
                split(options).start_index = n as u64;
                Ok(())
            }
            ("TapeSplitName", Some(Value::Text(t))) => {
                split(options).name_format = t;
                Ok(())
            }
            ("TapeSplitIndexFirst", Some(Value::Bool(b))) => {
                split(options).index_on_first_file = b;
                Ok(())
            }
            ("TapeSplitLines" | "TapeSplitTolerance" | "TapeSplitStart", _) => Err(bad("a whole number")),
            ("MinArcRadius" | "MaxArcRadius", _) => Err(bad("a number")),
            (
                "InverseTimeFeed"
                | "LaserSupport"
                | "PrintDirect"
                | "RapidPlungeToStartZ"
                | "TapeSplitIndexFirst"
                | "OnChangeByValue"
                | "RapidForgetsFeed",
                _,
            ) => Err(bad("True or False")),
            _ => Err(bad("text in quotes")),
        };
        if let Err(d) = result {
            self.diagnostics.push(d);
        }
    }
}

/// The yes/no setting a `True`/`False` option names (but for
/// `TapeSplitIndexFirst`, which makes tape splitting).
fn flag_of<'a>(name: &str, info: &'a mut PostInfo, options: &'a mut OutputOptions) -> Option<&'a mut bool> {
    Some(match name {
        "InverseTimeFeed" => &mut options.inverse_time_feed,
        "LaserSupport" => &mut info.laser_support,
        "PrintDirect" => &mut info.print_direct,
        "RapidPlungeToStartZ" => &mut info.rapid_plunge_to_start_z,
        "OnChangeByValue" => &mut options.on_change_by_value,
        "RapidForgetsFeed" => &mut options.rapid_forgets_feed,
        _ => return None,
    })
}

/// The tape splitting a `TapeSplit...` option sets, made on the first.
fn split(o: &mut postc_ir::OutputOptions) -> &mut TapeSplitting {
    o.tape_splitting.get_or_insert_with(|| TapeSplitting {
        max_lines: 0,
        tolerance: 0,
        name_format: String::new(),
        start_index: 1,
        index_on_first_file: false,
    })
}
