//! Values known when the post is compiled: the globals that are never
//! assigned after their first value (`useRadius`, `linebreak`, the
//! properties of `globals`), and the arguments of `createFormat` and
//! `createVariable` calls. JavaScript's rules for the operators apply,
//! with its conversions and order of texts from `postc_ir::js`, which the
//! runtime's interpreter uses too: a value known here is the value the
//! post computes when it runs.

use postc_ir::js;

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

    /// ToNumber (`Number(v)`).
    pub fn num(&self) -> Option<f64> {
        Some(match self {
            Const::Num(n) => *n,
            Const::Bool(b) => f64::from(u8::from(*b)),
            Const::Str(s) => js::text_to_number(s),
            Const::Null => 0.0,
            Const::Undefined => f64::NAN,
        })
    }

    /// ToString (`String(v)`).
    pub fn text(&self) -> Option<String> {
        Some(match self {
            Const::Str(s) => s.clone(),
            Const::Num(n) => js::number_to_string(*n),
            Const::Bool(b) => b.to_string(),
            Const::Null => "null".into(),
            Const::Undefined => "undefined".into(),
        })
    }
}

/// A number as JavaScript prints it (`String(n)`).
pub fn number_text(n: f64) -> String {
    js::number_to_string(n)
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
                UnaryOp::BitNot => Const::Num(f64::from(!js::to_int32(v.num()?))),
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
                (Const::Str(x), Const::Str(y)) => Some(js::compare_text(x, y)),
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
            let (x, y) = (js::to_int32(a.num()?), js::to_int32(b.num()?));
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
