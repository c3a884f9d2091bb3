//! JavaScript to Rhai: every function of a post (native or not) also
//! becomes a Rhai function, so that a script can call any other function;
//! postc's own glue (`__postc_init`, the drilling and compensation calls)
//! is Rhai too. The whole post is one Rhai script, compiled once per run.
//!
//! The translation keeps JavaScript's meaning by calling host functions
//! (registered by the runtime's script host) for everything whose meaning
//! differs between the two languages:
//!
//! - values: numbers are always floats; `null` is a host value, `undefined`
//!   is Rhai's `()`; objects, arrays and functions are host values with
//!   reference semantics (`__obj`, `__arr`, `__fn`, `__fnobj`);
//! - operators: `__add` (and `__adds` for chains), `__sub`, `__eq`,
//!   `__seq` (`===`), `__lt`, ..., `__t` (truthiness);
//! - names: locals are Rhai variables `v_NAME`; globals are read and
//!   written through `__gg(i)` and `__gs(i, v)`, shared with native code;
//!   output variables and formats bound at compile time are `__vfmt(id, v)`,
//!   `__vlast(id)`, `__ffmt(id, v)`;
//! - calls: every JavaScript function takes one Rhai array of arguments
//!   (`fn js_NAME(a)`), so that calls with fewer or more arguments and
//!   `arguments` work; methods and function values go through `__callm`,
//!   `__call` and `__new`, which bind `this`;
//! - statements: `for` becomes `loop` with a first-pass flag (so that
//!   `continue` runs the update), `switch` a `loop` with a matched index
//!   (fallthrough and `break` as in JavaScript), `for-in` a loop over
//!   `__keys(o)`; `finally` runs however the `try` is left: normally, by
//!   a `throw` (also from the `catch`), or by a `return`, `break` or
//!   `continue`, which are thrown past it as a jump and carried on after
//!   the `finally` (see `Jump::Try`).
//!
//! Every statement and every call, member access and operator records in
//! the span map where it came from in the post, so that an error in the
//! script is reported at the JavaScript line and column.

mod assign;
mod expr;
mod stmt;

use crate::host_names as names;
use postc_ir::Span;

use crate::ast::*;

use super::layout::Layout;
use super::model::Model;
use super::scope::FnId;
use super::setup::Setup;

/// Writes the Rhai script of a post.
pub struct Gen<'c, 'a> {
    pub model: &'c Model<'a>,
    pub setup: &'c Setup,
    pub layout: &'c Layout,
    pub out: String,
    pub span_map: Vec<(u32, u32)>,
    temps: usize,
    /// The function being written.
    at: FnId,
    /// Enclosing loops and switches, innermost last.
    jumps: Vec<Jump>,
    /// Where the loop being written starts in the post.
    loop_at: usize,
}

/// What `break` and `continue` leave.
#[derive(Clone, Debug)]
enum Jump {
    Loop,
    /// A switch, with the flag that carries a `continue` out of it.
    Switch(String),
    /// The body or `catch` of a `try`: a `return`, `break` or `continue`
    /// that leaves it is thrown as a jump (`__jump(kind, value)`: 1 return,
    /// 2 break, 3 continue), which the `try`'s translation catches and
    /// records; the `finally` runs, then the jump goes on.
    Try,
}

impl<'c, 'a> Gen<'c, 'a> {
    pub fn new(model: &'c Model<'a>, setup: &'c Setup, layout: &'c Layout) -> Gen<'c, 'a> {
        Gen {
            model,
            setup,
            layout,
            out: String::new(),
            span_map: Vec::new(),
            temps: 0,
            at: 0,
            jumps: Vec::new(),
            loop_at: 0,
        }
    }

    /// Records that the text written next comes from `span`.
    fn mark(&mut self, span: Span) {
        let here = self.out.len() as u32;
        let from = span.start as u32;
        match self.span_map.last_mut() {
            Some(last) if last.0 == here => last.1 = from,
            _ => self.span_map.push((here, from)),
        }
    }

    fn temp(&mut self, prefix: &str) -> String {
        self.temps += 1;
        format!("{prefix}{}", self.temps)
    }

    fn w(&mut self, s: &str) {
        self.out.push_str(s);
    }

    /// Opens a call of a host function: its name and `(`.
    fn open(&mut self, function: &str) {
        self.out.push_str(function);
        self.out.push('(');
    }

    /// A top-level function (or postc glue) as `fn NAME(a) { ... }`.
    pub fn function(&mut self, rhai_name: &str, id: FnId) {
        let info = &self.model.scopes.funcs[id];
        let Some(func) = info.func else { return };
        self.mark(func.span);
        self.out.push_str(&format!("fn {rhai_name}({}) {{\n", args_var(id)));
        self.at = id;
        self.jumps.clear();
        self.prologue(id);
        for s in &func.body {
            self.stmt(s);
        }
        self.w("return ();\n}\n");
    }

    /// A Rhai function with a body written by `body`.
    pub fn glue(&mut self, rhai_name: &str, span: Span, body: &str) {
        self.mark(span);
        self.out.push_str(&format!("fn {rhai_name}(a) {{\n{body}}}\n"));
    }

    /// The top-level statements that run at start, as `fn NAME(a)`.
    pub fn init(&mut self, rhai_name: &str, stmts: &[Stmt], span: Span) {
        self.mark(span);
        self.out.push_str(&format!("fn {rhai_name}(a) {{\n"));
        self.at = 0;
        self.jumps.clear();
        for s in stmts {
            self.stmt(s);
        }
        self.w("return ();\n}\n");
    }

    /// Parameters, hoisted `var`s and nested function declarations.
    fn prologue(&mut self, id: FnId) {
        let info = &self.model.scopes.funcs[id];
        let args = args_var(id);
        let mut text = String::new();
        for (i, p) in info.params.iter().enumerate() {
            text.push_str(&format!("let {} = {ARG}({args}, {i});\n", local_name(p), ARG = names::ARG));
        }
        if info.uses_arguments {
            text.push_str(&format!("let {} = {ARRAY}({args});\n", arguments_name(id), ARRAY = names::ARRAY));
        }
        for l in &info.locals[info.params.len()..] {
            text.push_str(&format!("let {} = ();\n", local_name(l)));
        }
        self.w(&text);
        let nested = info.nested.clone();
        for f in nested {
            if let Some(name) = &f.name {
                self.mark(f.span);
                let target = local_name(&name.name);
                self.w(&format!("{target} = "));
                self.closure(f);
                self.w(";\n");
            }
        }
    }

    /// A function expression: a Rhai closure wrapped as a function object.
    fn closure(&mut self, f: &Function) {
        let Some(id) = self.model.scopes.id_of(f) else {
            self.w("()");
            return;
        };
        let (at, jumps) = (self.at, std::mem::take(&mut self.jumps));
        self.at = id;
        self.w(&format!("{FUNCTION}(|{}| {{\n", args_var(id), FUNCTION = names::FUNCTION));
        self.prologue(id);
        for s in &f.body {
            self.stmt(s);
        }
        self.w("return ();\n})");
        self.at = at;
        self.jumps = jumps;
    }
}

/// The Rhai variable of a JavaScript local.
pub fn local_name(name: &str) -> String {
    format!("v_{}", mangle(name))
}

/// The Rhai variable that holds a function's `arguments`.
fn arguments_name(id: FnId) -> String {
    format!("g{id}")
}

/// The Rhai parameter that holds a function's arguments array.
fn args_var(id: FnId) -> String {
    format!("a{id}")
}

/// A JavaScript name as a Rhai identifier: ASCII letters, digits and `_`
/// stay; anything else becomes `_uXXXX_`.
pub fn mangle(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            out.push(c);
        } else {
            out.push_str(&format!("_u{:x}_", c as u32));
        }
    }
    out
}

/// A Rhai string literal.
pub fn quote(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 || c == '\u{7f}' => out.push_str(&format!("\\x{:02x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A Rhai float literal (or a host call for NaN and infinities).
pub fn number(n: f64) -> String {
    if n.is_nan() {
        format!("{}()", names::NAN)
    } else if n.is_infinite() {
        if n > 0.0 { format!("{}()", names::INF) } else { format!("(-{}())", names::INF) }
    } else if n < 0.0 || (n == 0.0 && n.is_sign_negative()) {
        format!("(-{:?})", -n)
    } else {
        format!("{n:?}")
    }
}

/// The Rhai name of a post function.
pub fn fn_name(js: &str) -> String {
    postc_ir::Script::function_name(js)
}

impl Gen<'_, '_> {
    /// Whether a body statement was run at compile time.
    fn done(&self, s: &Stmt) -> bool {
        self.setup.done.contains(&s.span.start)
    }
}
