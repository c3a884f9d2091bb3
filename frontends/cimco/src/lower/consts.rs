//! Values known when the post is compiled: the globals that are never
//! assigned after their first value (`useRadius`, `linebreak`, the
//! properties of `globals`), and the arguments of `createFormat` and
//! `createVariable` calls. JavaScript's rules for the operators apply.

use crate::ast::*;

use super::builtins;

/// A value known at compile time.
#[derive(Clone, Debug, PartialEq)]
pub enum Const {
    Num(f64),
    Str(String),
    Bool(bool),
    Null,
    Undefined,
}

impl Const {
    pub fn truthy(&self) -> bool {
        match self {
            Const::Num(n) => *n != 0.0 && !n.is_nan(),
            Const::Str(s) => !s.is_empty(),
            Const::Bool(b) => *b,
            Const::Null | Const::Undefined => false,
        }
    }

    /// ToNumber, when it is certain here: text is read only when it is
    /// blank or a plain decimal number (`" 12 "`, `"-1.5e3"`), where
    /// Rust's parse and JavaScript's `Number()` agree. Other text
    /// (`"0x10"`, `"Infinity"`, `"inf"`, which Rust reads as infinity) is
    /// `None`: the runtime reads it, as JavaScript does.
    pub fn num(&self) -> Option<f64> {
        Some(match self {
            Const::Num(n) => *n,
            Const::Bool(b) => f64::from(u8::from(*b)),
            Const::Str(s) => {
                let t = s.trim();
                if t.is_empty() {
                    0.0
                } else if plain_decimal(t) {
                    t.parse().ok()?
                } else {
                    return None;
                }
            }
            Const::Null => 0.0,
            Const::Undefined => f64::NAN,
        })
    }

    /// ToString, when JavaScript's text of the value is certain.
    pub fn text(&self) -> Option<String> {
        Some(match self {
            Const::Str(s) => s.clone(),
            Const::Num(n) => number_text(*n)?,
            Const::Bool(b) => b.to_string(),
            Const::Null => "null".into(),
            Const::Undefined => "undefined".into(),
        })
    }
}

/// Text that is a decimal number and nothing else: a sign, digits with
/// at most one point (a digit on one side), an exponent.
fn plain_decimal(t: &str) -> bool {
    let b = t.strip_prefix(['+', '-']).unwrap_or(t).as_bytes();
    let mantissa = b.iter().position(|c| *c == b'e' || *c == b'E').unwrap_or(b.len());
    let (m, e) = b.split_at(mantissa);
    let digits = m.iter().filter(|c| c.is_ascii_digit()).count();
    let points = m.iter().filter(|c| **c == b'.').count();
    let exponent_ok = match e {
        [] => true,
        [_, rest @ ..] => {
            let rest = rest.strip_prefix(b"+").or_else(|| rest.strip_prefix(b"-")).unwrap_or(rest);
            !rest.is_empty() && rest.iter().all(u8::is_ascii_digit)
        }
    };
    digits > 0 && points <= 1 && digits + points == m.len() && exponent_ok
}

/// A number as JavaScript prints it (Number::toString), for the range
/// where it has no exponent form: the shortest digits that read back as
/// the same double (Rust finds the same digits), and a whole number past
/// 2^53 as those digits padded with zeros (`2 ** 60` is
/// `1152921504606847000`, not its exact value).
pub fn number_text(n: f64) -> Option<String> {
    if n == 0.0 {
        return Some("0".into());
    }
    if !n.is_finite() || n.abs() >= 1e21 || n.abs() < 1e-6 {
        return None;
    }
    if n == n.trunc() {
        if n.abs() < 9_007_199_254_740_992.0 {
            return Some(format!("{}", n as i64));
        }
        // Shortest digits and exponent: `1.152921504606847e18`.
        let e = format!("{:e}", n.abs());
        let (mantissa, exp) = e.split_once('e')?;
        let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
        let exp: usize = exp.parse().ok()?;
        let sign = if n < 0.0 { "-" } else { "" };
        return Some(format!("{sign}{digits:0<width$}", width = exp + 1));
    }
    Some(format!("{n}"))
}

/// Evaluates an expression made of literals, known names and operators.
pub fn const_eval(
    e: &Expr,
    ident: &dyn Fn(&str) -> Option<Const>,
    flattened: &dyn Fn(&Expr) -> Option<String>,
) -> Option<Const> {
    let ev = |x: &Expr| const_eval(x, ident, flattened);
    Some(match &e.kind {
        ExprKind::Number(n) => Const::Num(*n),
        ExprKind::String(s) => Const::Str(s.clone()),
        ExprKind::Bool(b) => Const::Bool(*b),
        ExprKind::Null => Const::Null,
        ExprKind::Undefined => Const::Undefined,
        ExprKind::Ident(name) => ident(name)?,
        ExprKind::Member { object, property } => {
            if let ExprKind::Ident(o) = &object.kind
                && o == "Math"
            {
                return builtins::math_constant(&property.name).map(Const::Num);
            }
            let name = flattened(e)?;
            ident(&name)?
        }
        ExprKind::Unary { op, operand } => {
            let v = ev(operand)?;
            match op {
                UnaryOp::Neg => Const::Num(-v.num()?),
                UnaryOp::Plus => Const::Num(v.num()?),
                UnaryOp::Not => Const::Bool(!v.truthy()),
                UnaryOp::BitNot => Const::Num(f64::from(!to_int32(v.num()?))),
                UnaryOp::Typeof => Const::Str(
                    match v {
                        Const::Num(_) => "number",
                        Const::Str(_) => "string",
                        Const::Bool(_) => "boolean",
                        Const::Null => "object",
                        Const::Undefined => "undefined",
                    }
                    .into(),
                ),
            }
        }
        ExprKind::Binary { op, left, right } => binary(*op, &ev(left)?, &ev(right)?)?,
        ExprKind::Logical { op, left, right } => {
            let l = ev(left)?;
            match (op, l.truthy()) {
                (LogicalOp::And, true) | (LogicalOp::Or, false) => ev(right)?,
                _ => l,
            }
        }
        ExprKind::Conditional { test, consequent, alternate } => {
            if ev(test)?.truthy() {
                ev(consequent)?
            } else {
                ev(alternate)?
            }
        }
        _ => return None,
    })
}

fn to_int32(x: f64) -> i32 {
    if !x.is_finite() {
        return 0;
    }
    x.trunc().rem_euclid(4_294_967_296.0) as u32 as i32
}

/// A binary operator over known values.
pub fn binary(op: BinaryOp, a: &Const, b: &Const) -> Option<Const> {
    use BinaryOp::*;
    let num = |f: fn(f64, f64) -> f64| Some(Const::Num(f(a.num()?, b.num()?)));
    match op {
        Add => match (a, b) {
            (Const::Str(_), _) | (_, Const::Str(_)) => Some(Const::Str(format!("{}{}", a.text()?, b.text()?))),
            _ => num(|x, y| x + y),
        },
        In | Instanceof => None,
        Sub => num(|x, y| x - y),
        Mul => num(|x, y| x * y),
        Div => num(|x, y| x / y),
        Rem => num(|x, y| x % y),
        Lt | Le | Gt | Ge => {
            let ord = match (a, b) {
                (Const::Str(x), Const::Str(y)) => x.partial_cmp(y),
                _ => a.num()?.partial_cmp(&b.num()?),
            };
            let r = match op {
                Lt => ord == Some(std::cmp::Ordering::Less),
                Le => matches!(ord, Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)),
                Gt => ord == Some(std::cmp::Ordering::Greater),
                _ => matches!(ord, Some(std::cmp::Ordering::Greater | std::cmp::Ordering::Equal)),
            };
            Some(Const::Bool(r))
        }
        StrictEq => Some(Const::Bool(strict_eq(a, b))),
        StrictNe => Some(Const::Bool(!strict_eq(a, b))),
        Eq => Some(Const::Bool(loose_eq(a, b)?)),
        Ne => Some(Const::Bool(!loose_eq(a, b)?)),
        BitAnd | BitOr | BitXor | Shl | Shr | UShr => {
            let (x, y) = (to_int32(a.num()?), to_int32(b.num()?));
            let s = (y as u32) & 31;
            Some(Const::Num(match op {
                BitAnd => f64::from(x & y),
                BitOr => f64::from(x | y),
                BitXor => f64::from(x ^ y),
                Shl => f64::from(x.wrapping_shl(s)),
                Shr => f64::from(x >> s),
                _ => f64::from((x as u32) >> s),
            }))
        }
    }
}

fn strict_eq(a: &Const, b: &Const) -> bool {
    match (a, b) {
        (Const::Num(x), Const::Num(y)) => x == y,
        (Const::Str(x), Const::Str(y)) => x == y,
        (Const::Bool(x), Const::Bool(y)) => x == y,
        (Const::Null, Const::Null) | (Const::Undefined, Const::Undefined) => true,
        _ => false,
    }
}

fn loose_eq(a: &Const, b: &Const) -> Option<bool> {
    Some(match (a, b) {
        (Const::Null | Const::Undefined, Const::Null | Const::Undefined) => true,
        (Const::Null | Const::Undefined, _) | (_, Const::Null | Const::Undefined) => false,
        (Const::Str(x), Const::Str(y)) => x == y,
        _ => a.num()? == b.num()?,
    })
}
