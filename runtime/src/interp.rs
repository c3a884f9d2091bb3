//! The interpreter of the IR's statement language: assignments,
//! conditionals, loops, calls and expressions over [`Value`]s.
//!
//! Every statement costs one step; a handler call that runs past the post's
//! step budget stops with a diagnostic at the innermost loop, so a runaway
//! post never hangs.

use std::rc::Rc;

use postc_ir::{BinaryOp, Body, Builtin, Diagnostic, Expr, Place, Quantity, Stmt, UnaryOp, ValueSource};

use crate::engine::{Engine, is_modal, put_number, put_text};
use crate::script::js;
use crate::value::Value;

/// How a block of statements ended.
pub(crate) enum Flow {
    Normal,
    Break,
    Continue,
    Return(Value),
}

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// Calls nest at most this deep.
const MAX_DEPTH: usize = 200;

impl Engine<'_> {
    /// Runs statements with a frame of locals.
    pub(crate) fn exec(&mut self, stmts: &[Stmt], frame: &mut Vec<Value>) -> Result<Flow> {
        for stmt in stmts {
            self.steps += 1;
            if self.steps > self.post.options.step_budget {
                return Err(Box::new(self.budget_error(None)));
            }
            match stmt {
                Stmt::Line(pieces) => self.write_line_in(pieces, frame)?,
                Stmt::Write(e) => {
                    let v = self.eval(e, frame)?;
                    self.write_blocks(&v.to_text());
                }
                Stmt::Assign(place, e) => {
                    let v = self.eval(e, frame)?;
                    self.assign(*place, v, frame);
                }
                Stmt::Eval(e) => {
                    self.eval(e, frame)?;
                }
                Stmt::If { branches, otherwise } => {
                    let mut taken = None;
                    for (cond, body) in branches {
                        if self.eval(cond, frame)?.truthy() {
                            taken = Some(body);
                            break;
                        }
                    }
                    let body = taken.unwrap_or(otherwise);
                    match self.exec(body, frame)? {
                        Flow::Normal => {}
                        flow => return Ok(flow),
                    }
                }
                Stmt::While { cond, body, span } => loop {
                    self.steps += 1;
                    if self.steps > self.post.options.step_budget {
                        return Err(Box::new(self.budget_error(*span)));
                    }
                    if !self.eval(cond, frame)?.truthy() {
                        break;
                    }
                    match self.exec(body, frame).map_err(|e| Self::in_loop(e, *span))? {
                        Flow::Break => break,
                        Flow::Return(v) => return Ok(Flow::Return(v)),
                        Flow::Normal | Flow::Continue => {}
                    }
                },
                Stmt::Break => return Ok(Flow::Break),
                Stmt::Continue => return Ok(Flow::Continue),
                Stmt::Return(e) => {
                    let v = match e {
                        Some(e) => self.eval(e, frame)?,
                        None => Value::Null,
                    };
                    return Ok(Flow::Return(v));
                }
                Stmt::Emit(pieces) => self.emit_pieces(pieces, frame)?,
                Stmt::Mark(k) => {
                    let at = Value::Num(self.out.buf.len() as f64);
                    self.assign(Place::Local(*k), at, frame);
                }
                Stmt::MoveBack { to, from } => {
                    let (to, from) = (self.mark(*to, frame), self.mark(*from, frame));
                    if to < from {
                        let moved = self.out.buf.len() - from;
                        self.out.buf[to..].rotate_right(moved);
                    }
                }
                Stmt::Truncate(k) => {
                    let at = self.mark(*k, frame);
                    self.out.buf.truncate(at);
                }
                Stmt::Blocks(k) => {
                    let at = self.mark(*k, frame);
                    self.blocks_since(at);
                }
                Stmt::Script(_) => self.warn_once(
                    Diagnostic::warning("RT003", "this post calls Lua scripts, which postc does not run; those lines are skipped")
                        .note("the rest of the post runs as written"),
                ),
            }
        }
        Ok(Flow::Normal)
    }

    /// Writes one block inside a function: its expression pieces read the
    /// function's locals (VcPost `Out "<N>" & Code`, with `Code` a `Dim`).
    fn write_line_in(&mut self, pieces: &[postc_ir::Piece], frame: &mut Vec<Value>) -> Result<()> {
        for piece in pieces {
            match piece {
                postc_ir::Piece::Text(bytes) => self.out.buf.extend_from_slice(bytes),
                postc_ir::Piece::Var(id) => self.write_var(*id),
                postc_ir::Piece::Expr(Expr::FormatVar { var, value }) => {
                    let v = self.eval(value, frame)?;
                    self.write_assigned(*var, v);
                }
                postc_ir::Piece::Expr(e) => {
                    let v = self.eval(e, frame)?;
                    self.write_value_text(&v);
                }
            }
        }
        self.end_block();
        Ok(())
    }

    /// A budget error from a loop's body points at the innermost loop.
    fn in_loop(e: Box<Diagnostic>, span: Option<postc_ir::Span>) -> Box<Diagnostic> {
        match span {
            Some(s) if e.code == "RT002" && e.labels.is_empty() => Box::new(e.at(s, "this loop did not finish")),
            _ => e,
        }
    }

    fn budget_error(&self, span: Option<postc_ir::Span>) -> Diagnostic {
        let d = Diagnostic::error(
            "RT002",
            format!(
                "the post ran more than {} steps for one event and was stopped (a loop that never ends?)",
                self.post.options.step_budget
            ),
        );
        match span {
            Some(s) => d.at(s, "this loop did not finish"),
            None => d,
        }
    }

    /// Writes text as blocks: each line of it (`\n` separated) that is not
    /// empty becomes a block with the post's line ending.
    pub(crate) fn write_blocks(&mut self, text: &str) {
        for line in text.split('\n') {
            let line = line.strip_suffix('\r').unwrap_or(line);
            if line.is_empty() {
                continue;
            }
            self.out.buf.extend_from_slice(line.as_bytes());
            self.end_block();
        }
    }

    fn assign(&mut self, place: Place, v: Value, frame: &mut Vec<Value>) {
        match place {
            Place::Local(i) => {
                let i = i as usize;
                if frame.len() <= i {
                    frame.resize(i + 1, Value::Null);
                }
                frame[i] = v;
            }
            Place::Global(i) => self.set_global(i, v),
            Place::Var(id) => self.set_var(id, v),
        }
    }

    /// Sets a global's value.
    pub fn set_global(&mut self, i: u16, v: Value) {
        let i = i as usize;
        if self.globals.len() <= i {
            self.globals.resize(i + 1, Value::Null);
        }
        self.globals[i] = v;
    }

    /// Sets a variable's value, keeping the old one as its previous value.
    pub fn set_var(&mut self, id: u16, v: Value) {
        let state = &mut self.vars[id as usize];
        state.previous = std::mem::replace(&mut state.value, v);
    }

    /// A variable's current value.
    pub fn var_value(&self, id: u16) -> Value {
        match self.post.variables[id as usize].source {
            ValueSource::Quantity(q) => self.quantity(q),
            ValueSource::Assigned => self.vars[id as usize].value.clone(),
        }
    }

    fn quantity(&self, q: Quantity) -> Value {
        if q.is_text() {
            Value::text(self.machine.text(q))
        } else if q == Quantity::BlockNumber {
            Value::Num(self.block.next)
        } else {
            Value::Num(self.machine.number(q))
        }
    }

    /// Evaluates an expression.
    pub(crate) fn eval(&mut self, e: &Expr, frame: &mut Vec<Value>) -> Result<Value> {
        Ok(match e {
            Expr::Number(n) => Value::Num(*n),
            Expr::Text(s) => Value::text(s),
            Expr::Bool(b) => Value::Bool(*b),
            Expr::Null => Value::Null,
            Expr::Written(k) => Value::Bool(self.out.buf.len() > self.mark(*k, frame)),
            Expr::Quantity(q) => self.quantity(*q),
            Expr::Local(i) => frame.get(*i as usize).cloned().unwrap_or_default(),
            Expr::Global(i) => self.globals.get(*i as usize).cloned().unwrap_or_default(),
            Expr::Var(id) => self.var_value(*id),
            Expr::Previous(id) => self.vars[*id as usize].previous.clone(),
            Expr::FormatVar { var, value } => {
                let v = self.eval(value, frame)?;
                self.format_through_var(*var, v)
            }
            Expr::Format { format, value } => {
                let n = self.eval(value, frame)?.num();
                let mut buf = Vec::new();
                self.writers[*format as usize].write(n, &mut buf);
                Value::text(&String::from_utf8_lossy(&buf))
            }
            Expr::Unary(op, a) => {
                let a = self.eval(a, frame)?;
                match op {
                    UnaryOp::Neg => Value::Num(-a.num()),
                    UnaryOp::Not => Value::Bool(!a.truthy()),
                    UnaryOp::Plus => Value::Num(js_number(&a)),
                    UnaryOp::BitNot => Value::Num(f64::from(!js::to_int32(js_number(&a)))),
                    UnaryOp::Typeof => Value::text(match a {
                        Value::Num(_) => "number",
                        Value::Text(_) => "string",
                        Value::Bool(_) => "boolean",
                        Value::Null => "undefined",
                    }),
                }
            }
            Expr::Binary(BinaryOp::And, a, b) => {
                let a = self.eval(a, frame)?;
                if a.truthy() { self.eval(b, frame)? } else { a }
            }
            Expr::Binary(BinaryOp::Or, a, b) => {
                let a = self.eval(a, frame)?;
                if a.truthy() { a } else { self.eval(b, frame)? }
            }
            Expr::Binary(op, a, b) => {
                let a = self.eval(a, frame)?;
                let b = self.eval(b, frame)?;
                binary(*op, &a, &b)
            }
            Expr::Choose(c, a, b) => {
                if self.eval(c, frame)?.truthy() {
                    self.eval(a, frame)?
                } else {
                    self.eval(b, frame)?
                }
            }
            Expr::Call(f, args) => {
                let mut values = Vec::with_capacity(args.len());
                for a in args {
                    values.push(self.eval(a, frame)?);
                }
                self.call(*f, values)?
            }
            Expr::Builtin(b, args) => {
                let mut values = Vec::with_capacity(args.len());
                for a in args {
                    values.push(self.eval(a, frame)?);
                }
                builtin(*b, &values)
            }
        })
    }

    /// Formats a value through a variable (prefix, format, modality) and
    /// returns the text; an on-change variable returns "" when the text is
    /// the one it returned last.
    pub fn format_through_var(&mut self, id: u16, v: Value) -> Value {
        let post = self.post;
        let var = &post.variables[id as usize];
        let mut buf = Vec::with_capacity(16);
        let (state, prefix) = (&mut self.vars[id as usize], &self.prefixes[id as usize]);
        match &v {
            Value::Text(s) => put_text(is_modal(var), state, prefix, s.as_bytes(), &post.options.substitutions, &mut buf),
            other => put_number(is_modal(var), &self.writers[var.format as usize], state, prefix, other.num(), &mut buf),
        }
        self.set_var(id, v);
        Value::Text(Rc::from(String::from_utf8_lossy(&buf).as_ref()))
    }

    /// Calls a post function with arguments.
    pub fn call(&mut self, f: u16, args: Vec<Value>) -> Result<Value> {
        let post = self.post;
        let Some(function) = post.functions.get(f as usize) else {
            return Ok(Value::Null);
        };
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            self.depth -= 1;
            let d = Diagnostic::error("RT004", format!("calls nest deeper than {MAX_DEPTH} levels (endless recursion?)"));
            return Err(Box::new(match function.span {
                Some(s) => d.at(s, "in this function"),
                None => d,
            }));
        }
        let result = match &function.body {
            Body::Native(body) => {
                let mut frame = args;
                frame.resize((function.slots as usize).max(frame.len()), Value::Null);
                match self.exec(body, &mut frame) {
                    Ok(Flow::Return(v)) => Ok(v),
                    Ok(_) => Ok(Value::Null),
                    Err(e) => Err(e),
                }
            }
            Body::Script(id) => self.call_script(*id, &function.name, args),
        };
        self.depth -= 1;
        result
    }

    fn call_script(&mut self, id: u16, name: &str, args: Vec<Value>) -> Result<Value> {
        crate::script::call(self, id, name, args)
    }

    /// A mark stored by [`Stmt::Mark`], within the output buffer.
    fn mark(&self, k: u16, frame: &[Value]) -> usize {
        let at = frame.get(k as usize).map_or(0.0, Value::num);
        (at.max(0.0) as usize).min(self.out.buf.len())
    }

    /// Writes pieces into the output with the frame's locals in reach.
    fn emit_pieces(&mut self, pieces: &[postc_ir::Piece], frame: &mut Vec<Value>) -> Result<()> {
        for piece in pieces {
            match piece {
                postc_ir::Piece::Text(bytes) => self.out.buf.extend_from_slice(bytes),
                postc_ir::Piece::Var(id) => self.write_var(*id),
                postc_ir::Piece::Expr(Expr::FormatVar { var, value }) => {
                    let n = match &**value {
                        Expr::Quantity(q) if !q.is_text() && *q != Quantity::BlockNumber => self.machine.number(*q),
                        Expr::Number(n) => *n,
                        other => match self.eval(other, frame)? {
                            Value::Num(n) => n,
                            v => {
                                self.write_assigned(*var, v);
                                continue;
                            }
                        },
                    };
                    self.write_number_var(*var, n);
                }
                postc_ir::Piece::Expr(e) => match self.eval(e, frame)? {
                    Value::Num(n) if n == n.trunc() && n.abs() < 1e15 => push_integer(&mut self.out.buf, n as i64),
                    v => self.write_value_text(&v),
                },
            }
        }
        Ok(())
    }

    /// Prints a number through an assigned variable and keeps it as its value.
    fn write_number_var(&mut self, id: u16, n: f64) {
        let post = self.post;
        let var = &post.variables[id as usize];
        let (state, prefix) = (&mut self.vars[id as usize], &self.prefixes[id as usize]);
        put_number(is_modal(var), &self.writers[var.format as usize], state, prefix, n, &mut self.out.buf);
        state.previous = std::mem::replace(&mut state.value, Value::Num(n));
    }
}

fn binary(op: BinaryOp, a: &Value, b: &Value) -> Value {
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
        Pow => Value::Num(a.num().powf(b.num())),
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
    }
}

/// JavaScript `===` over the interpreter's values.
fn strict_eq(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Num(x), Value::Num(y)) => x == y,
        (Value::Text(x), Value::Text(y)) => x == y,
        (Value::Bool(x), Value::Bool(y)) => x == y,
        (Value::Null, Value::Null) => true,
        _ => false,
    }
}

/// A value as JavaScript's `Number()` reads it.
fn js_number(v: &Value) -> f64 {
    match v {
        Value::Text(s) => js::text_to_number(s),
        Value::Null => f64::NAN,
        other => other.num(),
    }
}

fn concat(a: &Value, b: &Value) -> Value {
    let mut s = String::new();
    a.append_to(&mut s);
    b.append_to(&mut s);
    Value::Text(Rc::from(s))
}

/// Appends an integer's decimal digits without allocating.
fn push_integer(out: &mut Vec<u8>, n: i64) {
    let mut buf = [0u8; 20];
    let mut i = buf.len();
    let mut m = n.unsigned_abs();
    loop {
        i -= 1;
        buf[i] = b'0' + (m % 10) as u8;
        m /= 10;
        if m == 0 {
            break;
        }
    }
    if n < 0 {
        out.push(b'-');
    }
    out.extend_from_slice(&buf[i..]);
}

/// Rounds half away from zero to `decimals` places.
fn round_to(v: f64, decimals: f64) -> f64 {
    let p = 10f64.powi(decimals.clamp(0.0, 15.0) as i32);
    (v * p).round() / p
}

fn builtin(b: Builtin, args: &[Value]) -> Value {
    let n = |i: usize| args.get(i).map_or(0.0, Value::num);
    let s = |i: usize| args.get(i).map(Value::to_text).unwrap_or_else(|| Rc::from(""));
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
        Builtin::Min => Value::Num(args.iter().map(Value::num).fold(f64::INFINITY, f64::min)),
        Builtin::Max => Value::Num(args.iter().map(Value::num).fold(f64::NEG_INFINITY, f64::max)),
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
        Builtin::Str => Value::Text(args.first().map(Value::to_text).unwrap_or_else(|| Rc::from(""))),
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
    }
}

/// VB-style picture formats: `0.000` (fixed decimals), `#.###` (trimmed),
/// `0000` (zero-padded integer).
fn format_picture(v: f64, picture: &str) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pictures() {
        assert_eq!(format_picture(12.34567, "0.000"), "12.346");
        assert_eq!(format_picture(2.5, "#.###"), "2.5");
        assert_eq!(format_picture(7.0, "0000"), "0007");
        assert_eq!(format_picture(-0.25, "0.00"), "-0.25");
    }

    #[test]
    fn text_builtins() {
        let t = |s: &str| Value::text(s);
        assert_eq!(builtin(Builtin::Mid, &[t("ABCDEF"), Value::Num(2.0), Value::Num(3.0)]), t("BCD"));
        assert_eq!(builtin(Builtin::Right, &[t("ABC"), Value::Num(5.0)]), t("ABC"));
        assert_eq!(builtin(Builtin::Val, &[t(" 12.5mm")]), Value::Num(12.5));
        assert_eq!(binary(BinaryOp::Concat, &Value::Num(3.0), &t("x")), t("3x"));
        assert_eq!(binary(BinaryOp::Add, &Value::Num(3.0), &Value::Num(0.5)), Value::Num(3.5));
    }
}
