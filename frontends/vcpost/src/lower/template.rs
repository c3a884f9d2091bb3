//! `Out` strings: which parts of an `Out` expression are templates, and the
//! `<NAME>` register references inside them.
//!
//! The string literals joined by `&` at the top of an `Out` statement are
//! templates: each `<NAME>` in them (NAME a valid name) prints the register
//! NAME with its prefix and format, `<N>` the sequence number; everything
//! else is literal text. Strings anywhere else (assigned to a variable, passed
//! to a function) are plain text: `S = "<X>"` then `Out S` prints `<X>`.

use crate::ast::{BinaryOp, Expr, ExprKind};
use crate::token::is_valid_name;

/// A piece of a template.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TemplatePart<'a> {
    Text(&'a str),
    /// `<NAME>`: the name without brackets.
    Register(&'a str),
}

/// The parts of an `Out` expression: the operands of its top `&` chain
/// (through parentheses), in order.
pub fn out_parts(e: &Expr) -> Vec<&Expr> {
    let mut parts = Vec::new();
    flatten(e, &mut parts);
    parts
}

fn flatten<'a>(e: &'a Expr, parts: &mut Vec<&'a Expr>) {
    match &e.kind {
        ExprKind::Binary(BinaryOp::Concat, a, b) => {
            flatten(a, parts);
            flatten(b, parts);
        }
        ExprKind::Paren(inner) if matches!(inner.kind, ExprKind::Binary(BinaryOp::Concat, ..) | ExprKind::Text(_)) => {
            flatten(inner, parts)
        }
        _ => parts.push(e),
    }
}

/// Splits a template into text and register references.
pub fn split(text: &str) -> Vec<TemplatePart<'_>> {
    let mut parts = Vec::new();
    let mut literal_start = 0;
    let mut i = 0;
    while let Some(rel) = text[i..].find('<') {
        let open = i + rel;
        let Some(close_rel) = text[open + 1..].find('>') else { break };
        let close = open + 1 + close_rel;
        let name = &text[open + 1..close];
        if is_valid_name(name) {
            if literal_start < open {
                parts.push(TemplatePart::Text(&text[literal_start..open]));
            }
            parts.push(TemplatePart::Register(name));
            literal_start = close + 1;
            i = close + 1;
        } else {
            i = open + 1;
        }
    }
    if literal_start < text.len() {
        parts.push(TemplatePart::Text(&text[literal_start..]));
    }
    parts
}

/// The register references of a template that are never closed: each
/// `<NAME` (NAME a valid name, taken as long as it goes) followed by the
/// end of the string or by another `<` instead of `>`. Returns the byte
/// range of `<NAME` in `text`. Any other `<` is text (`(X<0)`, `a < b`,
/// `(DIST<MAX)`), as a less-than sign in a comment must stay.
pub fn unclosed(text: &str) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    for (open, _) in text.match_indices('<') {
        let rest = &text[open + 1..];
        if !rest.chars().next().is_some_and(char::is_alphabetic) {
            continue;
        }
        let len = rest.find(|c: char| !(c.is_alphanumeric() || c == '_')).unwrap_or(rest.len());
        if matches!(rest[len..].chars().next(), None | Some('<')) {
            out.push(open..open + 1 + len);
        }
    }
    out
}
