//! A native CIMCO function's IR printed back as the JavaScript function
//! the CIMCO frontend lowers to that same IR: the inverse of its lowering
//! (`postc_front_cimco`'s `lower::native`), built as the frontend's syntax
//! tree and printed by its printer (`postc_front_cimco::print`).
//!
//! - Locals keep their source names (`Function::locals`); a slot the
//!   frontend made (a `switch`'s value, an array's count) is `t` and its
//!   slot. Each is declared with `var` at its first assignment when the
//!   first assignments come in slot order, as the frontend numbers `var`s
//!   in the order they are written; the others are declared first.
//! - Operators are JavaScript's: the IR's `Js*` comparisons are `==`,
//!   `<`, ..., `StrictEq` is `===`; the `UnaryOp::Plus` the lowering puts
//!   around an operand of `-`, `*`, `/`, `%`, of `format()` and of `Math.*`
//!   is not printed, since the lowering puts it back.
//! - `Expr::FormatVar` is `xOutput.format(v)`, `Expr::Format`
//!   `xyzFormat.format(v)`, `0 + Var(v)` `xOutput.getLast()`,
//!   `Stmt::Forget` `xOutput.reset()`, `Expr::Output` the format or
//!   variable's name; built-ins are the CNC-Calc and
//!   JavaScript calls they came from (`Math.abs`, `parseFloat`,
//!   `text.substring(a, b)`, `x.toFixed(n)`, ...); a call of a form for N
//!   arguments (`writeBlock/5`) calls the function by its name.
//! - A loop whose last statement leaves when a condition fails is
//!   `do { ... } while (c);`; `if` chains keep their shape (`else if`, or
//!   an `else` block holding an `if`).
//!
//! What no CNC-Calc function says (output lines and buffer statements,
//! runtime quantities, BASIC's operators and built-ins, variables assigned
//! as values) is refused: [`function`] returns what it is.

use std::collections::HashSet;

use postc_front_cimco::ast::{
    AssignOp, BinaryOp as JsBin, CatchClause, Expr as Js, ExprKind, Function as JsFunction, Ident, IfBranch, KeyForm,
    LogicalOp, Property, PropertyKey, Stmt as JsStmt, StmtKind, UnaryOp as JsUn, UpdateOp, VarDeclarator,
};
use postc_front_cimco::{builtins, made};
use postc_ir::{BinaryOp, Body, Builtin, Expr, FileId, Function, LocalId, OutputRef, Place, Post, Span, Stmt, UnaryOp};

/// A construct a function body has that no CNC-Calc function says.
pub(super) type Unsayable = String;

type R<T> = Result<T, Unsayable>;

/// The names of a function's slots: parameters, the source's locals, then
/// `t` and the slot for the frontend's own (renamed when a name of the
/// post or the host has it), up to the last slot the body uses: a slot
/// nothing uses or names is no local of any JavaScript.
pub(super) fn local_names(post: &Post, f: &Function) -> Vec<String> {
    let mut names: Vec<String> = f.params.iter().chain(&f.locals).cloned().collect();
    let used = match &f.body {
        Body::Native(body) => slots_used(body),
        Body::Script(_) => 0,
    };
    let taken: HashSet<&str> = names
        .iter()
        .map(String::as_str)
        .chain(post.globals.iter().map(|g| g.name.as_str()))
        .chain(post.functions.iter().map(|f| f.name.as_str()))
        .collect();
    let mut made_up = Vec::new();
    for slot in names.len()..used.min(usize::from(f.slots)) {
        let mut name = format!("t{slot}");
        while taken.contains(name.as_str()) || builtins::knows(&name) || builtins::is_object(&name) {
            name.insert(0, '_');
        }
        made_up.push(name);
    }
    names.extend(made_up);
    names
}

/// One past the highest slot a body reads or assigns.
fn slots_used(body: &[Stmt]) -> usize {
    use postc_ir::visit::{Visit, walk_expr, walk_stmt};
    struct Highest(usize);
    impl Visit for Highest {
        fn visit_stmt(&mut self, s: &Stmt) {
            if let Stmt::Assign(Place::Local(k), _) = s {
                self.0 = self.0.max(k.index() + 1);
            }
            walk_stmt(self, s);
        }
        fn visit_expr(&mut self, e: &Expr) {
            if let Expr::Local(k) = e {
                self.0 = self.0.max(k.index() + 1);
            }
            walk_expr(self, e);
        }
    }
    let mut h = Highest(0);
    body.iter().for_each(|s| h.visit_stmt(s));
    h.0
}

/// The JavaScript declaration of a native function.
#[doc(hidden)]
pub fn function(post: &Post, f: &Function) -> R<JsStmt> {
    let Body::Native(body) = &f.body else { return Err("a body that runs as a script".into()) };
    let names = local_names(post, f);
    let params = f.params.len().min(names.len());
    // Slots from `inline` on are declared where they are first assigned.
    let firsts = first_assignments(body, names.len());
    let mut inline = names.len();
    while inline > params {
        let k = inline - 1;
        let ordered = firsts[k].is_some_and(|p| inline == names.len() || firsts[inline].is_some_and(|q| p < q));
        if !ordered {
            break;
        }
        inline = k;
    }
    let declared = (0..names.len()).map(|k| k < inline).collect();
    let mut b = Printer { post, names, declared, inline };
    let mut stmts = Vec::new();
    if inline > params {
        let ds = (params..inline).map(|k| VarDeclarator { name: ident(&b.names[k]), init: None, span: at() }).collect();
        stmts.push(stmt(StmtKind::Var(ds)));
    }
    stmts.extend(b.stmts(body)?);
    Ok(stmt(StmtKind::Function(JsFunction {
        name: Some(ident(&f.name)),
        params: b.names[..params].iter().map(|p| ident(p)).collect(),
        body: stmts,
        body_span: at(),
        span: at(),
        arrow: false,
    })))
}

/// Where each slot is first assigned, in the order the statements print.
fn first_assignments(body: &[Stmt], slots: usize) -> Vec<Option<usize>> {
    fn walk(body: &[Stmt], n: &mut usize, firsts: &mut [Option<usize>]) {
        for s in body {
            *n += 1;
            match s {
                Stmt::Assign(Place::Local(k), _) => {
                    if let Some(first @ None) = firsts.get_mut(k.index()) {
                        *first = Some(*n);
                    }
                }
                Stmt::If { branches, otherwise } => {
                    branches.iter().for_each(|(_, b)| walk(b, n, firsts));
                    walk(otherwise, n, firsts);
                }
                Stmt::While { body, .. } => walk(body, n, firsts),
                _ => {}
            }
        }
    }
    let mut firsts = vec![None; slots];
    walk(body, &mut 0, &mut firsts);
    firsts
}

struct Printer<'p> {
    post: &'p Post,
    names: Vec<String>,
    /// Slots declared already (or at the top).
    declared: Vec<bool>,
    /// Slots from here on are declared at their first assignment.
    inline: usize,
}

/// Nodes the printer builds carry no place in a file.
#[doc(hidden)]
pub fn at() -> Span {
    Span::new(FileId(0), 0, 0)
}

pub(super) fn ident(name: &str) -> Ident {
    Ident { name: name.to_string(), span: at() }
}

pub(super) fn js(kind: ExprKind) -> Js {
    Js::new(kind, at())
}

fn stmt(kind: StmtKind) -> JsStmt {
    JsStmt::new(kind, at())
}

fn block(stmts: Vec<JsStmt>) -> JsStmt {
    stmt(StmtKind::Block(stmts))
}

pub(super) fn name(n: &str) -> Js {
    js(ExprKind::Ident(n.to_string()))
}

fn member(object: Js, property: &str) -> Js {
    js(ExprKind::Member { object: Box::new(object), property: ident(property) })
}

pub(super) fn call(callee: Js, args: Vec<Js>) -> Js {
    js(ExprKind::Call { callee: Box::new(callee), args })
}

/// `object.method(args)`.
fn method(object: Js, m: &str, args: Vec<Js>) -> Js {
    call(member(object, m), args)
}

fn binary(op: JsBin, a: Js, b: Js) -> Js {
    js(ExprKind::Binary { op, left: Box::new(a), right: Box::new(b) })
}

/// A value the IR holds as a constant, as a JavaScript literal.
pub(super) fn literal(e: &Expr) -> Option<Js> {
    Some(js(match e {
        Expr::Number(n) => ExprKind::Number(*n),
        Expr::Text(t) => ExprKind::String(t.clone()),
        Expr::Bool(b) => ExprKind::Bool(*b),
        Expr::Null => ExprKind::Null,
        Expr::Undefined => ExprKind::Undefined,
        _ => return None,
    }))
}

/// Whether a text is a JavaScript name (`a.b` may be written for `a["b"]`).
fn is_name(t: &str) -> bool {
    let mut chars = t.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_' || c == '$')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$')
}

/// `object.key` for a name, `object[key]` otherwise.
fn member_or_index(object: Js, key: Js) -> Js {
    match &key.kind {
        ExprKind::String(k) if is_name(k) => member(object, &k.clone()),
        _ => js(ExprKind::Index { object: Box::new(object), index: Box::new(key) }),
    }
}

impl Printer<'_> {
    fn stmts(&mut self, body: &[Stmt]) -> R<Vec<JsStmt>> {
        let mut out = Vec::with_capacity(body.len());
        for s in body {
            if let Some(s) = self.stmt(s)? {
                out.push(s);
            }
        }
        Ok(out)
    }

    fn stmt(&mut self, s: &Stmt) -> R<Option<JsStmt>> {
        Ok(Some(match s {
            Stmt::Assign(place, e) => return self.assign(*place, e).map(Some),
            Stmt::Eval(e) => stmt(StmtKind::Expr(self.expr(e)?)),
            Stmt::If { branches, otherwise } => {
                if branches.is_empty() {
                    return Err("an `if` without a condition".into());
                }
                let mut bs = Vec::new();
                for (c, b) in branches {
                    bs.push(IfBranch { cond: self.expr(c)?, body: block(self.stmts(b)?) });
                }
                let otherwise = if otherwise.is_empty() { None } else { Some(Box::new(block(self.stmts(otherwise)?))) };
                stmt(StmtKind::If { branches: bs, otherwise })
            }
            Stmt::While { cond, body, step, .. } if !step.is_empty() => {
                let mut updates = Vec::new();
                for s in step {
                    match self.stmt(s)? {
                        Some(JsStmt { kind: StmtKind::Expr(e), .. }) => updates.push(e),
                        Some(_) => return Err("a loop update that is not an expression".into()),
                        None => {}
                    }
                }
                let update = match updates.len() {
                    0 => None,
                    1 => updates.pop(),
                    _ => Some(js(ExprKind::Sequence(updates))),
                };
                let test = Some(self.expr(cond)?);
                stmt(StmtKind::For { init: None, test, update, body: Box::new(block(self.stmts(body)?)) })
            }
            Stmt::SetMember { object, key, value, .. } => {
                let target = member_or_index(self.expr(object)?, self.expr(key)?);
                let assign = ExprKind::Assign {
                    op: AssignOp::Assign,
                    target: Box::new(target),
                    value: Box::new(self.expr(value)?),
                };
                stmt(StmtKind::Expr(js(assign)))
            }
            Stmt::Throw { value, .. } => stmt(StmtKind::Throw(self.expr(value)?)),
            Stmt::Try { body, catch, finally } => {
                let handler = match catch {
                    Some((k, b)) => {
                        Some(CatchClause { param: ident(&self.local(*k)?), body: self.stmts(b)?, span: at() })
                    }
                    None => None,
                };
                let finalizer = if finally.is_empty() { None } else { Some(self.stmts(finally)?) };
                stmt(StmtKind::Try { block: self.stmts(body)?, handler, finalizer })
            }
            Stmt::While { cond, body, .. } => match do_while(cond, body) {
                Some((body, cond)) => {
                    let body = block(self.stmts(body)?);
                    stmt(StmtKind::DoWhile { body: Box::new(body), cond: self.expr(cond)? })
                }
                None => {
                    let cond = self.expr(cond)?;
                    stmt(StmtKind::While { cond, body: Box::new(block(self.stmts(body)?)) })
                }
            },
            Stmt::Break => stmt(StmtKind::Break),
            Stmt::Continue => stmt(StmtKind::Continue),
            Stmt::Return(e) => stmt(StmtKind::Return(e.as_ref().map(|e| self.expr(e)).transpose()?)),
            Stmt::Forget(v) => stmt(StmtKind::Expr(method(name(&self.var(v.index())?), "reset", vec![]))),
            // Where `--trace` says a line came from: the lowering puts it back.
            Stmt::Origin(_) => return Ok(None),
            Stmt::Line { .. } => return Err("an output line (a section's statement)".into()),
            Stmt::Write(_) => return Err("a statement that writes a value as output (a handler's)".into()),
            Stmt::Script(_) => return Err("a script call".into()),
        }))
    }

    /// `x = e`, `var x = e` where `x` is first assigned, `x += e`, `x++`.
    fn assign(&mut self, place: Place, e: &Expr) -> R<JsStmt> {
        let target = match place {
            Place::Local(k) => {
                let n = self.local(k)?;
                if k.index() >= self.inline && !self.declared[k.index()] {
                    self.declared[k.index()] = true;
                    let d = VarDeclarator { name: ident(&n), init: Some(self.expr(e)?), span: at() };
                    return Ok(stmt(StmtKind::Var(vec![d])));
                }
                name(&n)
            }
            Place::Global(g) => self.global(g.index())?,
            Place::Var(_) => return Err("an assignment to an output variable".into()),
        };
        let read = match place {
            Place::Local(k) => Expr::Local(k),
            Place::Global(g) => Expr::Global(g),
            Place::Var(v) => Expr::Var(v),
        };
        let (op, value) = match e {
            Expr::Binary(op @ (BinaryOp::Add | BinaryOp::Sub), a, b)
                if **b == Expr::Number(1.0) && **a == Expr::Unary(UnaryOp::Plus, Box::new(read.clone())) =>
            {
                let op = if *op == BinaryOp::Add { UpdateOp::Increment } else { UpdateOp::Decrement };
                let update = ExprKind::Update { op, prefix: false, target: Box::new(target) };
                return Ok(stmt(StmtKind::Expr(js(update))));
            }
            Expr::Binary(BinaryOp::Add, a, b) if **a == read => (AssignOp::Add, self.expr(b)?),
            Expr::Binary(op @ (BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::Rem), a, b)
                if **a == postc_front_cimco::to_number(read.clone()) =>
            {
                let op = match op {
                    BinaryOp::Sub => AssignOp::Sub,
                    BinaryOp::Mul => AssignOp::Mul,
                    BinaryOp::Div => AssignOp::Div,
                    _ => AssignOp::Rem,
                };
                (op, self.number(b)?)
            }
            e => (AssignOp::Assign, self.expr(e)?),
        };
        let assign = ExprKind::Assign { op, target: Box::new(target), value: Box::new(value) };
        Ok(stmt(StmtKind::Expr(js(assign))))
    }

    fn local(&self, k: LocalId) -> R<String> {
        self.names.get(k.index()).cloned().ok_or_else(|| format!("local slot {} past the function's slots", k.index()))
    }

    /// A global as JavaScript reads it: its name (`globals.x` for a
    /// property of `globals`).
    fn global(&self, g: usize) -> R<Js> {
        let global = self.post.globals.get(g).ok_or_else(|| format!("global {g}, which the post does not have"))?;
        Ok(match global.name.split_once('.') {
            Some((object, property)) => member(name(object), property),
            None => name(&global.name),
        })
    }

    fn var(&self, v: usize) -> R<String> {
        let var =
            self.post.variables.get(v).ok_or_else(|| format!("output variable {v}, which the post does not have"))?;
        if var.name == made::FEED_VAR || var.name == made::FEED_REV_VAR {
            return Err(format!("postc's own output variable `{}`", var.name));
        }
        Ok(var.name.clone())
    }

    /// An operand the lowering reads as a number: the `+` it puts around
    /// it is left out, since it puts it back.
    fn number(&mut self, e: &Expr) -> R<Js> {
        if let Expr::Unary(UnaryOp::Plus, x) = e
            && postc_front_cimco::to_number((**x).clone()) == *e
        {
            return self.expr(x);
        }
        self.expr(e)
    }

    fn numbers(&mut self, args: &[Expr]) -> R<Vec<Js>> {
        args.iter().map(|a| self.number(a)).collect()
    }

    fn exprs(&mut self, args: &[Expr]) -> R<Vec<Js>> {
        args.iter().map(|a| self.expr(a)).collect()
    }

    /// The name the post gives a format.
    fn format_name(&self, format: postc_ir::FormatId) -> R<String> {
        self.post
            .formats
            .get(format.index())
            .and_then(|f| f.name.clone())
            .ok_or_else(|| "a format without a name".to_string())
    }

    fn expr(&mut self, e: &Expr) -> R<Js> {
        Ok(match e {
            Expr::Number(_) | Expr::Text(_) | Expr::Bool(_) | Expr::Null | Expr::Undefined => {
                literal(e).ok_or_else(|| "a constant".to_string())?
            }
            Expr::This => js(ExprKind::This),
            Expr::Arguments => name("arguments"),
            Expr::Host { name: host, args } => {
                let args = self.exprs(args)?;
                call(name(host), args)
            }
            Expr::Array(items) => js(ExprKind::Array(self.exprs(items)?)),
            Expr::Regex { pattern, flags, .. } => {
                js(ExprKind::Regex { pattern: pattern.clone(), flags: flags.clone() })
            }
            // A name the post never defines: the name, which JavaScript
            // reads as the runtime does (a ReferenceError when it runs).
            Expr::Undeclared { name, .. } => js(ExprKind::Ident(name.clone())),
            Expr::Object(props) => {
                let mut out = Vec::with_capacity(props.len());
                for (k, v) in props {
                    let written = if is_name(k) { KeyForm::Ident } else { KeyForm::String };
                    out.push(Property {
                        key: PropertyKey { name: k.clone(), written, span: at() },
                        value: self.expr(v)?,
                        span: at(),
                    });
                }
                js(ExprKind::Object(out))
            }
            Expr::Member { object: o, key: k, .. } => member_or_index(self.expr(o)?, self.expr(k)?),
            Expr::Invoke { object, method: m, args, .. } => {
                let args = self.exprs(args)?;
                method(self.expr(object)?, m, args)
            }
            Expr::CallValue(f, args) => {
                let args = self.exprs(args)?;
                call(self.expr(f)?, args)
            }
            Expr::Closure { function, captures } => {
                if !captures.is_empty() {
                    return Err("a function that closes over values of the function that makes it".into());
                }
                let f = self
                    .post
                    .functions
                    .get(function.index())
                    .ok_or_else(|| format!("function {}, which the post does not have", function.index()))?;
                name(&f.name)
            }
            Expr::Local(k) => name(&self.local(*k)?),
            Expr::Global(g) => self.global(g.index())?,
            Expr::FormatVar { var, value, .. } => {
                let v = self.number(value)?;
                method(name(&self.var(var.index())?), "format", vec![v])
            }
            Expr::Output(OutputRef::Variable(var)) => name(&self.var(var.index())?),
            Expr::Output(OutputRef::Format(format)) => name(&self.format_name(*format)?),
            Expr::Format { format, value, .. } => {
                let f = self.format_name(*format)?;
                let v = self.number(value)?;
                method(name(&f), "format", vec![v])
            }
            Expr::Binary(BinaryOp::Add, a, b) if **a == Expr::Number(0.0) && matches!(**b, Expr::Var(_)) => {
                let Expr::Var(v) = **b else { return Err("`getLast()`".into()) };
                method(name(&self.var(v.index())?), "getLast", vec![])
            }
            Expr::Unary(op, a) => {
                let (op, a) = match op {
                    UnaryOp::Neg => (JsUn::Neg, self.number(a)?),
                    UnaryOp::Not => (JsUn::Not, self.expr(a)?),
                    UnaryOp::Plus => (JsUn::Plus, self.expr(a)?),
                    UnaryOp::BitNot => (JsUn::BitNot, self.expr(a)?),
                    UnaryOp::Typeof => (JsUn::Typeof, self.expr(a)?),
                };
                js(ExprKind::Unary { op, operand: Box::new(a) })
            }
            Expr::Binary(op, a, b) => self.binary(*op, a, b)?,
            Expr::Choose(c, a, b) => js(ExprKind::Conditional {
                test: Box::new(self.expr(c)?),
                consequent: Box::new(self.expr(a)?),
                alternate: Box::new(self.expr(b)?),
            }),
            Expr::Call(f, args) => {
                let function = self
                    .post
                    .functions
                    .get(f.index())
                    .ok_or_else(|| format!("a call of function {}, which the post does not have", f.index()))?;
                if [made::INIT, made::COMPENSATION, made::DRILL_HEADER, made::TURN_DRILL]
                    .contains(&function.name.as_str())
                {
                    return Err(format!("a call of postc's own `{}`", function.name));
                }
                let callee = made::specialized(&function.name).unwrap_or(&function.name);
                let args = self.exprs(args)?;
                call(name(callee), args)
            }
            Expr::Builtin(b, args) => self.builtin(*b, args)?,
            Expr::Var(_) | Expr::Previous(_) => return Err("an output variable read as a value".into()),
            Expr::Quantity(q) => {
                return Err(format!(
                    "the runtime value `{}`, which a function receives only as an argument",
                    q.label()
                ));
            }
        })
    }

    fn binary(&mut self, op: BinaryOp, a: &Expr, b: &Expr) -> R<Js> {
        let logical = |op, a, b| js(ExprKind::Logical { op, left: Box::new(a), right: Box::new(b) });
        let js_op = match op {
            BinaryOp::Add => JsBin::Add,
            BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::Rem => {
                let (a, b) = (self.number(a)?, self.number(b)?);
                let op = match op {
                    BinaryOp::Sub => JsBin::Sub,
                    BinaryOp::Mul => JsBin::Mul,
                    BinaryOp::Div => JsBin::Div,
                    _ => JsBin::Rem,
                };
                return Ok(binary(op, a, b));
            }
            BinaryOp::Pow => {
                let args = vec![self.number(a)?, self.number(b)?];
                return Ok(method(name("Math"), "pow", args));
            }
            BinaryOp::And => return Ok(logical(LogicalOp::And, self.expr(a)?, self.expr(b)?)),
            BinaryOp::Or => return Ok(logical(LogicalOp::Or, self.expr(a)?, self.expr(b)?)),
            BinaryOp::StrictEq => JsBin::StrictEq,
            BinaryOp::StrictNe => JsBin::StrictNe,
            BinaryOp::BitAnd => JsBin::BitAnd,
            BinaryOp::BitOr => JsBin::BitOr,
            BinaryOp::BitXor => JsBin::BitXor,
            BinaryOp::Shl => JsBin::Shl,
            BinaryOp::Shr => JsBin::Shr,
            BinaryOp::UShr => JsBin::UShr,
            BinaryOp::JsEq => JsBin::Eq,
            BinaryOp::JsNe => JsBin::Ne,
            BinaryOp::JsLt => JsBin::Lt,
            BinaryOp::JsLe => JsBin::Le,
            BinaryOp::JsGt => JsBin::Gt,
            BinaryOp::JsGe => JsBin::Ge,
            BinaryOp::IntDiv | BinaryOp::Concat => {
                return Err(format!("BASIC's `{}` operator", if op == BinaryOp::IntDiv { "\\" } else { "&" }));
            }
            BinaryOp::Eq | BinaryOp::Ne | BinaryOp::Lt | BinaryOp::Le | BinaryOp::Gt | BinaryOp::Ge => {
                return Err(format!(
                    "a comparison with BASIC's meaning (`{op:?}`: text that is not a number reads as 0)"
                ));
            }
        };
        Ok(binary(js_op, self.expr(a)?, self.expr(b)?))
    }

    fn builtin(&mut self, b: Builtin, args: &[Expr]) -> R<Js> {
        let math = |s: &mut Self, f: &str| -> R<Js> { Ok(method(name("Math"), f, s.numbers(args)?)) };
        let host = |s: &mut Self, f: &str| -> R<Js> { Ok(call(name(f), s.exprs(args)?)) };
        Ok(match (b, args) {
            (Builtin::Abs, _) => math(self, "abs")?,
            (Builtin::Sqrt, _) => math(self, "sqrt")?,
            (Builtin::Sin, _) => math(self, "sin")?,
            (Builtin::Cos, _) => math(self, "cos")?,
            (Builtin::Tan, _) => math(self, "tan")?,
            (Builtin::Atan, _) => math(self, "atan")?,
            (Builtin::Atan2, _) => math(self, "atan2")?,
            (Builtin::Asin, _) => math(self, "asin")?,
            (Builtin::Acos, _) => math(self, "acos")?,
            (Builtin::Exp, _) => math(self, "exp")?,
            (Builtin::Log, _) => math(self, "log")?,
            (Builtin::Floor, _) => math(self, "floor")?,
            (Builtin::Ceil, _) => math(self, "ceil")?,
            (Builtin::JsRound, _) => math(self, "round")?,
            (Builtin::Min, _) => math(self, "min")?,
            (Builtin::Max, _) => math(self, "max")?,
            (Builtin::ParseInt, _) => host(self, "parseInt")?,
            (Builtin::ParseFloat, _) => host(self, "parseFloat")?,
            (Builtin::IsNaN, _) => host(self, "isNaN")?,
            (Builtin::ToNumber, _) => host(self, "Number")?,
            (Builtin::Str | Builtin::JsString, [_]) => host(self, "String")?,
            (Builtin::Upper | Builtin::Lower, [Expr::Builtin(Builtin::Str, inner)]) if inner.len() == 1 => {
                let m = if b == Builtin::Upper { "toUpperCase" } else { "toLowerCase" };
                method(self.expr(&inner[0])?, m, vec![])
            }
            (Builtin::Len, [x]) => member(self.expr(x)?, "length"),
            (Builtin::Keys | Builtin::OwnKeys, [x]) => {
                method(js(ExprKind::Ident("Object".into())), "keys", vec![self.expr(x)?])
            }
            (Builtin::HasProperty, [k, o]) => binary(JsBin::In, self.expr(k)?, self.expr(o)?),
            (Builtin::ToFixed, [x, d]) => {
                let (x, d) = (self.expr(x)?, self.expr(d)?);
                method(x, "toFixed", vec![d])
            }
            (Builtin::Substring, [x, rest @ ..]) if (1..=2).contains(&rest.len()) => {
                let x = self.expr(x)?;
                method(x, "substring", self.exprs(rest)?)
            }
            (b, _) => return Err(format!("the built-in `{b:?}` with {} argument(s)", args.len())),
        })
    }
}

/// `while (true) { body; if (!(c)) break; }` as `do { body } while (c)`,
/// when nothing in the body goes on to the next pass (a `continue` there
/// would skip the test in the IR and run it in JavaScript).
fn do_while<'e>(cond: &Expr, body: &'e [Stmt]) -> Option<(&'e [Stmt], &'e Expr)> {
    let (Expr::Bool(true), Some((Stmt::If { branches, otherwise }, rest))) = (cond, body.split_last()) else {
        return None;
    };
    let [(Expr::Unary(UnaryOp::Not, c), leave)] = branches.as_slice() else { return None };
    (otherwise.is_empty() && leave.as_slice() == [Stmt::Break] && !continues(rest)).then_some((rest, &**c))
}

/// Whether statements have a `continue` of the loop around them.
fn continues(body: &[Stmt]) -> bool {
    body.iter().any(|s| match s {
        Stmt::Continue => true,
        Stmt::If { branches, otherwise } => branches.iter().any(|(_, b)| continues(b)) || continues(otherwise),
        _ => false,
    })
}
