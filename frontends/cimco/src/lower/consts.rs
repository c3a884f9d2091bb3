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
    /// The primitive this value is, for `postc_ir::js`'s operators.
    pub fn primitive(&self) -> js::Primitive<'_> {
        match self {
            Const::Num(n) => js::Primitive::Number(*n),
            Const::Str(s) => js::Primitive::Text(s),
            Const::Bool(b) => js::Primitive::Bool(*b),
            Const::Null => js::Primitive::Null,
            Const::Undefined => js::Primitive::Undefined,
        }
    }

    /// ToBoolean.
    pub fn truthy(&self) -> bool {
        self.primitive().truthy()
    }

    /// ToNumber (`Number(v)`).
    pub fn num(&self) -> f64 {
        self.primitive().to_number()
    }

    /// ToString (`String(v)`).
    pub fn text(&self) -> String {
        let mut out = String::new();
        self.primitive().push_text(&mut out);
        out
    }
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
                UnaryOp::Neg => Const::Num(-v.num()),
                UnaryOp::Plus => Const::Num(v.num()),
                UnaryOp::Not => Const::Bool(!v.truthy()),
                UnaryOp::BitNot => Const::Num(f64::from(!js::to_int32(v.num()))),
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
    let (x, y) = (a.primitive(), b.primitive());
    let num = |f: fn(f64, f64) -> f64| Some(Const::Num(f(x.to_number(), y.to_number())));
    match op {
        Add => match (a, b) {
            (Const::Str(_), _) | (_, Const::Str(_)) => {
                let mut text = String::new();
                x.push_text(&mut text);
                y.push_text(&mut text);
                Some(Const::Str(text))
            }
            _ => num(|x, y| x + y),
        },
        In | Instanceof => None,
        Sub => num(|x, y| x - y),
        Mul => num(|x, y| x * y),
        Div => num(|x, y| x / y),
        Rem => num(|x, y| x % y),
        Lt | Le | Gt | Ge => {
            use std::cmp::Ordering::{Equal, Greater, Less};
            let ord = js::order(x, y);
            Some(Const::Bool(match op {
                Lt => ord == Some(Less),
                Le => matches!(ord, Some(Less | Equal)),
                Gt => ord == Some(Greater),
                _ => matches!(ord, Some(Greater | Equal)),
            }))
        }
        StrictEq => Some(Const::Bool(js::strict_equals(x, y))),
        StrictNe => Some(Const::Bool(!js::strict_equals(x, y))),
        Eq => Some(Const::Bool(js::loose_equals(x, y))),
        Ne => Some(Const::Bool(!js::loose_equals(x, y))),
        BitAnd | BitOr | BitXor | Shl | Shr | UShr => {
            let (i, j) = (js::to_int32(x.to_number()), js::to_int32(y.to_number()));
            let s = (j as u32) & 31;
            Some(Const::Num(match op {
                BitAnd => f64::from(i & j),
                BitOr => f64::from(i | j),
                BitXor => f64::from(i ^ j),
                Shl => f64::from(i.wrapping_shl(s)),
                Shr => f64::from(i >> s),
                _ => f64::from(js::to_uint32(x.to_number()) >> s),
            }))
        }
    }
}
