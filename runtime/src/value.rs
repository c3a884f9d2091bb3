//! Values of the IR's statement language: numbers, text, booleans, null.

use std::fmt::Write as _;
use std::rc::Rc;

/// A value computed by a post's code.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Value {
    #[default]
    Null,
    Num(f64),
    Bool(bool),
    Text(Rc<str>),
}

impl Value {
    pub fn text(s: &str) -> Value {
        Value::Text(Rc::from(s))
    }

    /// The value as a number: text that reads as a number gives it, other
    /// text and null give 0, true gives 1.
    pub fn num(&self) -> f64 {
        match self {
            Value::Num(n) => *n,
            Value::Bool(b) => f64::from(u8::from(*b)),
            Value::Text(s) => s.trim().parse().unwrap_or(0.0),
            Value::Null => 0.0,
        }
    }

    /// Truthiness: non-zero numbers, non-empty text, true.
    pub fn truthy(&self) -> bool {
        match self {
            Value::Num(n) => *n != 0.0 && !n.is_nan(),
            Value::Bool(b) => *b,
            Value::Text(s) => !s.is_empty(),
            Value::Null => false,
        }
    }

    /// Appends the value as text: numbers in their shortest form without a
    /// trailing `.0`.
    pub fn append_to(&self, out: &mut String) {
        match self {
            Value::Num(n) => push_number(out, *n),
            Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
            Value::Text(s) => out.push_str(s),
            Value::Null => {}
        }
    }

    pub fn to_text(&self) -> Rc<str> {
        match self {
            Value::Text(s) => s.clone(),
            other => {
                let mut s = String::new();
                other.append_to(&mut s);
                Rc::from(s)
            }
        }
    }
}

/// Shortest text of a number: `3`, `2.5`, `-0.125`.
pub fn push_number(out: &mut String, n: f64) {
    if n.is_finite() && n == n.trunc() && n.abs() < 1e21 {
        let _ = write!(out, "{}", n as i128);
    } else if n.is_nan() {
        out.push_str("NaN");
    } else {
        let _ = write!(out, "{n}");
    }
}
