//! Operators and built-in functions of the IR's expression language:
//! arithmetic, comparison (loose and strict), bitwise and text operators
//! with JavaScript's number conversions where CIMCO needs them, the
//! built-ins VcPost and CIMCO lower to, and VB-style picture formats.

use postc_ir::{BinaryOp, Builtin, UnaryOp};

use crate::js;
use crate::value::{Text, Value};

/// A unary operator applied to a value.
#[inline]
pub(crate) fn unary(op: UnaryOp, a: &Value) -> Value {
    match op {
        UnaryOp::Neg => Value::Num(-a.num()),
        UnaryOp::Not => Value::Bool(!a.truthy()),
        UnaryOp::Plus => Value::Num(js_number(a)),
        UnaryOp::BitNot => Value::Num(f64::from(!js::to_int32(js_number(a)))),
        UnaryOp::Typeof => Value::text(type_name(a)),
    }
}

/// What JavaScript's `typeof` says of a value.
#[inline]
pub(crate) fn type_name(a: &Value) -> &'static str {
    match a {
        Value::Num(_) => "number",
        Value::Text(_) => "string",
        Value::Bool(_) => "boolean",
        Value::Undefined => "undefined",
        Value::Null | Value::Array(_) | Value::Object(_) | Value::Output(_) | Value::Regex(_) => "object",
        Value::Func(_) => "function",
    }
}

/// JavaScript's `+` of two values the interpreter has made primitive
/// (an object's `valueOf`/`toString` asked first): text when either is
/// text or would be (an array joins, a function and a regular expression
/// are their source), with null as `null`, `undefined` as `undefined` and
/// booleans as `true`/`false`; else the sum of their numbers (null 0,
/// `undefined` NaN, booleans 0 and 1). The other dialects' `+`
/// ([`binary`]) writes null as nothing.
#[doc(hidden)]
pub fn add_js(a: &Value, b: &Value) -> Value {
    if joins_as_text(a) || joins_as_text(b) {
        if let (Value::Text(_), Value::Text(_)) = (a, b) {
            return concat(a, b);
        }
        return joined(|s| {
            a.append_js(s);
            b.append_js(s);
        });
    }
    Value::Num(a.num() + b.num())
}

/// Whether `+` with this value makes text (JavaScript): text, and the
/// values whose primitive is text.
#[inline]
pub(crate) fn joins_as_text(v: &Value) -> bool {
    matches!(
        v,
        Value::Text(_) | Value::Array(_) | Value::Object(_) | Value::Func(_) | Value::Regex(_) | Value::Output(_)
    )
}

/// A binary operator applied to two values. (The interpreter evaluates
/// `And` and `Or` itself: they short-circuit and give an operand.)
#[doc(hidden)]
pub fn binary(op: BinaryOp, a: &Value, b: &Value) -> Value {
    use BinaryOp::*;
    match op {
        Add => match (a, b) {
            (Value::Text(_), _) | (_, Value::Text(_)) => concat(a, b),
            _ => Value::Num(a.num() + b.num()),
        },
        Concat => concat(a, b),
        Sub => Value::Num(a.num() - b.num()),
        Mul => Value::Num(a.num() * b.num()),
        Div => Value::Num(a.num() / b.num()),
        Rem => Value::Num(a.num() % b.num()),
        Pow => Value::Num(js::math_pow(a.num(), b.num())),
        IntDiv => {
            let d = b.num().round();
            Value::Num(if d == 0.0 { f64::NAN } else { (a.num().round() / d).trunc() })
        }
        Eq | Ne | Lt | Le | Gt | Ge => {
            let ord = match (a, b) {
                (Value::Text(x), Value::Text(y)) => x.partial_cmp(y),
                _ => a.num().partial_cmp(&b.num()),
            };
            let r = match op {
                Eq => ord == Some(std::cmp::Ordering::Equal),
                Ne => ord != Some(std::cmp::Ordering::Equal),
                Lt => ord == Some(std::cmp::Ordering::Less),
                Le => matches!(ord, Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)),
                Gt => ord == Some(std::cmp::Ordering::Greater),
                _ => matches!(ord, Some(std::cmp::Ordering::Greater | std::cmp::Ordering::Equal)),
            };
            Value::Bool(r)
        }
        And => Value::Bool(a.truthy() && b.truthy()),
        Or => Value::Bool(a.truthy() || b.truthy()),
        StrictEq => Value::Bool(strict_eq(a, b)),
        StrictNe => Value::Bool(!strict_eq(a, b)),
        BitAnd | BitOr | BitXor | Shl | Shr => {
            let (x, y) = (js::to_int32(js_number(a)), js::to_int32(js_number(b)));
            let shift = (y as u32) & 31;
            Value::Num(f64::from(match op {
                BitAnd => x & y,
                BitOr => x | y,
                BitXor => x ^ y,
                Shl => x.wrapping_shl(shift),
                _ => x >> shift,
            }))
        }
        UShr => Value::Num(f64::from(js::to_uint32(js_number(a)) >> (js::to_uint32(js_number(b)) & 31))),
        JsEq => Value::Bool(js_loose_eq(a, b)),
        JsNe => Value::Bool(!js_loose_eq(a, b)),
        JsLt | JsLe | JsGt | JsGe => {
            let ord = match (a, b) {
                (Value::Text(x), Value::Text(y)) => x.partial_cmp(y),
                _ => js_number(a).partial_cmp(&js_number(b)),
            };
            use std::cmp::Ordering::{Equal, Greater, Less};
            Value::Bool(match op {
                JsLt => ord == Some(Less),
                JsLe => matches!(ord, Some(Less | Equal)),
                JsGt => ord == Some(Greater),
                _ => matches!(ord, Some(Greater | Equal)),
            })
        }
    }
}

/// The comparison operators as a truth value, without making a value;
/// `None` for the other operators.
#[inline]
#[doc(hidden)]
pub fn compare(op: BinaryOp, a: &Value, b: &Value) -> Option<bool> {
    use BinaryOp::*;
    // Two numbers (a count against 0, a coordinate against a limit): every
    // dialect's comparison is the IEEE one, NaN unequal and unordered.
    if let (Value::Num(x), Value::Num(y)) = (a, b) {
        return match op {
            Eq | JsEq | StrictEq => Some(x == y),
            Ne | JsNe | StrictNe => Some(x != y),
            Lt | JsLt => Some(x < y),
            Le | JsLe => Some(x <= y),
            Gt | JsGt => Some(x > y),
            Ge | JsGe => Some(x >= y),
            _ => None,
        };
    }
    Some(match op {
        JsEq => js_loose_eq(a, b),
        JsNe => !js_loose_eq(a, b),
        StrictEq => strict_eq(a, b),
        StrictNe => !strict_eq(a, b),
        Eq | Ne | Lt | Le | Gt | Ge | JsLt | JsLe | JsGt | JsGe => match binary(op, a, b) {
            Value::Bool(r) => r,
            _ => return None,
        },
        _ => return None,
    })
}

/// JavaScript `==` over the interpreter's values: two texts or two
/// numbers at once, two objects by identity, an object against a
/// primitive by its text (ToPrimitive), two primitives as
/// [`js::loose_equals`] says.
#[inline]
fn js_loose_eq(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Text(x), Value::Text(y)) => x == y,
        (Value::Num(x), Value::Num(y)) => x == y,
        _ => match (a.primitive(), b.primitive()) {
            (Some(x), Some(y)) => js::loose_equals(x, y),
            (None, None) => a == b,
            (None, Some(_)) => js_loose_eq(&Value::Text(a.to_text()), b),
            (Some(_), None) => js_loose_eq(a, &Value::Text(b.to_text())),
        },
    }
}

/// JavaScript `===` over the interpreter's values.
#[inline]
pub(super) fn strict_eq(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Num(x), Value::Num(y)) => x == y,
        (Value::Text(x), Value::Text(y)) => x == y,
        (Value::Bool(x), Value::Bool(y)) => x == y,
        (Value::Null, Value::Null) | (Value::Undefined, Value::Undefined) => true,
        (Value::Array(_) | Value::Object(_) | Value::Func(_) | Value::Output(_) | Value::Regex(_), _) => a == b,
        _ => false,
    }
}

/// A value as JavaScript's `Number()` reads it: a primitive as
/// [`js::Primitive::to_number`] does (null 0, undefined NaN), an array as
/// its text.
pub(super) fn js_number(v: &Value) -> f64 {
    match v {
        Value::Num(n) => *n,
        Value::Array(_) => js::text_to_number(&v.to_text()),
        other => other.primitive().map_or(f64::NAN, js::Primitive::to_number),
    }
}

fn concat(a: &Value, b: &Value) -> Value {
    // Two texts whose sum is short: joined in place, no allocation.
    if let (Value::Text(x), Value::Text(y)) = (a, b) {
        if let Some(t) = Text::joined_inline(x, y) {
            return Value::Text(t);
        }
        let (x, y) = (x.as_bytes(), y.as_bytes());
        let n = x.len() + y.len();
        if n <= crate::value::INLINE_TEXT {
            let mut buf = [0u8; crate::value::INLINE_TEXT];
            buf[..x.len()].copy_from_slice(x);
            buf[x.len()..n].copy_from_slice(y);
            return Value::Text(Text::from_bytes(&buf[..n]));
        }
    }
    joined(|s| {
        a.append_to(s);
        b.append_to(s);
    })
}

/// The text `write` builds, in a buffer this thread reuses, so only the
/// result is allocated.
fn joined(write: impl FnOnce(&mut String)) -> Value {
    thread_local! {
        static JOINED: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
    }
    JOINED.with_borrow_mut(|s| {
        s.clear();
        write(s);
        let joined = Value::Text(Text::new(s));
        if s.capacity() > 1 << 16 {
            // A rare long text: its buffer is not kept.
            *s = String::new();
        }
        joined
    })
}

/// Rounds half away from zero to `decimals` places.
fn round_to(v: f64, decimals: f64) -> f64 {
    let p = 10f64.powi(decimals.clamp(0.0, 15.0) as i32);
    (v * p).round() / p
}

#[doc(hidden)]
pub fn builtin(b: Builtin, args: &[Value]) -> Value {
    let n = |i: usize| args.get(i).map_or(0.0, Value::num);
    let s = |i: usize| args.get(i).map(Value::to_text).unwrap_or_else(|| Text::new(""));
    let chars = |t: &str| t.chars().collect::<Vec<_>>();
    match b {
        Builtin::Abs => Value::Num(n(0).abs()),
        Builtin::Sqrt => Value::Num(n(0).sqrt()),
        Builtin::Sin => Value::Num(n(0).sin()),
        Builtin::Cos => Value::Num(n(0).cos()),
        Builtin::Tan => Value::Num(n(0).tan()),
        Builtin::Atan => Value::Num(n(0).atan()),
        Builtin::Atan2 => Value::Num(n(0).atan2(n(1))),
        Builtin::Floor => Value::Num(n(0).floor()),
        Builtin::Ceil => Value::Num(n(0).ceil()),
        Builtin::Round => Value::Num(round_to(n(0), n(1))),
        Builtin::Trunc => Value::Num(n(0).trunc()),
        Builtin::Min => Value::Num(js::math_min(args.iter().map(Value::num))),
        Builtin::Max => Value::Num(js::math_max(args.iter().map(Value::num))),
        Builtin::Len => Value::Num(s(0).chars().count() as f64),
        Builtin::Left => {
            let c = chars(&s(0));
            let k = (n(1).max(0.0) as usize).min(c.len());
            Value::text(&c[..k].iter().collect::<String>())
        }
        Builtin::Right => {
            let c = chars(&s(0));
            let k = (n(1).max(0.0) as usize).min(c.len());
            Value::text(&c[c.len() - k..].iter().collect::<String>())
        }
        Builtin::Mid => {
            let c = chars(&s(0));
            let start = ((n(1).max(1.0) as usize) - 1).min(c.len());
            let len = if args.len() > 2 { n(2).max(0.0) as usize } else { c.len() };
            let end = start.saturating_add(len).min(c.len());
            Value::text(&c[start..end].iter().collect::<String>())
        }
        Builtin::Upper => Value::text(&s(0).to_uppercase()),
        Builtin::Lower => Value::text(&s(0).to_lowercase()),
        Builtin::Str => Value::Text(args.first().map(Value::to_text).unwrap_or_else(|| Text::new(""))),
        // Objects ask their methods first (`Engine::text_of`).
        Builtin::JsString => match args.first() {
            Some(Value::Null) => Value::text("null"),
            Some(v) => Value::Text(v.to_text()),
            None => Value::text("undefined"),
        },
        Builtin::Val => {
            let t = s(0);
            let t = t.trim();
            let end = t
                .char_indices()
                .take_while(|(i, c)| c.is_ascii_digit() || *c == '.' || ((*c == '-' || *c == '+') && *i == 0))
                .map(|(i, c)| i + c.len_utf8())
                .last()
                .unwrap_or(0);
            Value::Num(t[..end].parse().unwrap_or(0.0))
        }
        Builtin::FormatPicture => Value::text(&format_picture(n(0), &s(1))),
        Builtin::Chr => Value::text(&char::from_u32(n(0) as u32).map(String::from).unwrap_or_default()),
        Builtin::Asin => Value::Num(n(0).asin()),
        Builtin::Acos => Value::Num(n(0).acos()),
        Builtin::Exp => Value::Num(n(0).exp()),
        Builtin::Log => Value::Num(n(0).ln()),
        Builtin::JsRound => Value::Num(js::math_round(n(0))),
        Builtin::ParseInt => Value::Num(js::parse_int(&s(0), n(1))),
        Builtin::ParseFloat => Value::Num(js::parse_float(&s(0))),
        Builtin::IsNaN => Value::Bool(args.first().map_or(f64::NAN, js_number).is_nan()),
        Builtin::ToNumber => Value::Num(args.first().map_or(0.0, js_number)),
        Builtin::ToFixed => Value::text(&js::to_fixed(args.first().map_or(f64::NAN, js_number), n(1))),
        Builtin::Substring => {
            let t = s(0);
            // ASCII text is cut by bytes, with no look at it as `str`.
            let ascii = t.ascii_bytes();
            let len = ascii.map_or_else(|| t.chars().count(), <[u8]>::len);
            let index = |v: Option<&Value>| match v {
                None | Some(Value::Null | Value::Undefined) => None,
                Some(v) => {
                    let x = js_number(v);
                    Some(if x.is_nan() { 0 } else { x.trunc().clamp(0.0, len as f64) as usize })
                }
            };
            let a = index(args.get(1)).unwrap_or(0);
            let b = index(args.get(2)).unwrap_or(len);
            let (a, b) = (a.min(b), a.max(b));
            if a == 0 && b == len {
                Value::Text(t.clone())
            } else if let Some(bytes) = ascii {
                Value::Text(Text::from_bytes(&bytes[a..b]))
            } else {
                Value::text(&t.chars().skip(a).take(b - a).collect::<String>())
            }
        }
        // The interpreter reads `in`, `for ... in`'s keys and the
        // built-ins below itself, with the run's prototypes; here (no run,
        // no error path) the built-in prototypes hold nothing the post
        // added, and a value that is not an object has no property.
        Builtin::Keys | Builtin::OwnKeys => super::objects::keys(args.first().unwrap_or(&Value::Undefined), None),
        Builtin::HasProperty => {
            let arg = |i: usize| args.get(i).unwrap_or(&Value::Undefined);
            super::objects::has_property(arg(0), arg(1), &super::protos::Protos::default())
                .unwrap_or(Value::Bool(false))
        }
        // Only the interpreter constructs (it calls the function) and makes
        // objects with prototypes; they are never constants.
        Builtin::Construct
        | Builtin::Prototype
        | Builtin::CreateObject
        | Builtin::InstanceOf
        | Builtin::NewRegExp
        | Builtin::FormatNumber
        | Builtin::Words
        | Builtin::FormatOutput
        | Builtin::Property
        | Builtin::SettingError => Value::Undefined,
        Builtin::IsArray => Value::Bool(matches!(args.first(), Some(Value::Array(_)))),
    }
}

/// VB-style picture formats: `0.000` (fixed decimals), `#.###` (trimmed),
/// `0000` (zero-padded integer).
#[doc(hidden)]
pub fn format_picture(v: f64, picture: &str) -> String {
    if !v.is_finite() {
        crate::number::report_non_finite(v);
        return String::new();
    }
    let (int_pic, frac_pic) = picture.split_once('.').unwrap_or((picture, ""));
    let fixed = frac_pic.chars().filter(|&c| c == '0').count();
    let optional = frac_pic.chars().filter(|&c| c == '#').count();
    let decimals = fixed + optional;
    let rounded = round_to(v, decimals as f64);
    let mut text = format!("{:.*}", decimals, rounded.abs());
    if optional > 0 {
        while text.ends_with('0') && text.len() - text.find('.').unwrap_or(text.len()) - 1 > fixed {
            text.pop();
        }
        if text.ends_with('.') {
            text.pop();
        }
    }
    let min_int = int_pic.chars().filter(|&c| c == '0').count();
    let int_len = text.find('.').unwrap_or(text.len());
    if int_len < min_int {
        text.insert_str(0, &"0".repeat(min_int - int_len));
    }
    if rounded < 0.0 && rounded != 0.0 {
        text.insert(0, '-');
    }
    text
}
