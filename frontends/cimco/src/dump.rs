//! A compact, line-per-statement dump of a syntax tree, for snapshot
//! tests and debugging.
//!
//! Each statement is one line, prefixed with its `line:column`, nested
//! statements are indented, and expressions are S-expressions that show
//! the tree's structure (`(+ a (* b c))`, `(call (. xOutput format) vx)`).
//! The bodies of function expressions follow the statement they appear in,
//! under a `fn` line.

use crate::ast::*;
use crate::print::js_number;
use crate::strings::quote;

/// Dumps `program`; `text` is the source it was parsed from (for line and
/// column numbers).
pub fn dump(program: &Program, text: &str) -> String {
    let line_starts: Vec<usize> = std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect();
    let mut d = Dumper { text, line_starts, out: String::new(), depth: 0 };
    for s in &program.body {
        d.stmt(s);
    }
    d.out
}

struct Dumper<'a> {
    text: &'a str,
    line_starts: Vec<usize>,
    out: String,
    depth: usize,
}

impl Dumper<'_> {
    fn position(&self, offset: usize) -> String {
        let offset = offset.min(self.text.len());
        let line = self.line_starts.partition_point(|&s| s <= offset).saturating_sub(1);
        let start = self.line_starts.get(line).copied().unwrap_or(0);
        let column = self.text.get(start..offset).map_or(offset - start, |s| s.chars().count());
        format!("{}:{}", line + 1, column + 1)
    }

    /// Writes one line for a node at `offset`, then the bodies of the
    /// function expressions it contains.
    fn line(&mut self, offset: usize, text: &str, functions: Vec<&Function>) {
        let position = self.position(offset);
        self.out.push_str(&"  ".repeat(self.depth));
        self.out.push_str(&position);
        self.out.push(' ');
        self.out.push_str(text);
        self.out.push('\n');
        for f in functions {
            self.depth += 1;
            let name = f.name.as_ref().map_or("", |n| n.name.as_str());
            let head = format!("fn {name}({})", params(f));
            self.line(f.span.start, head.trim_end(), Vec::new());
            self.block(&f.body);
            self.depth -= 1;
        }
    }

    fn block(&mut self, body: &[Stmt]) {
        self.depth += 1;
        for s in body {
            self.stmt(s);
        }
        self.depth -= 1;
    }

    fn stmt(&mut self, s: &Stmt) {
        let at = s.span.start;
        let mut fns = Vec::new();
        match &s.kind {
            StmtKind::Var(decls) => {
                let text = format!("var {}", declarators(decls, &mut fns));
                self.line(at, &text, fns);
            }
            StmtKind::Function(f) => {
                let name = f.name.as_ref().map_or("", |n| n.name.as_str());
                self.line(at, &format!("function {name}({})", params(f)), fns);
                self.block(&f.body);
            }
            StmtKind::Expr(e) => {
                let text = expr(e, &mut fns);
                self.line(at, &text, fns);
            }
            StmtKind::Block(body) => {
                self.line(at, "block", fns);
                self.block(body);
            }
            StmtKind::Empty => self.line(at, "empty", fns),
            StmtKind::If { branches, otherwise } => {
                for (i, b) in branches.iter().enumerate() {
                    let mut fns = Vec::new();
                    let text = format!("{} {}", if i == 0 { "if" } else { "else if" }, expr(&b.cond, &mut fns));
                    self.line(if i == 0 { at } else { b.cond.span.start }, &text, fns);
                    self.block(std::slice::from_ref(&b.body));
                }
                if let Some(o) = otherwise {
                    self.line(o.span.start, "else", Vec::new());
                    self.block(std::slice::from_ref(o));
                }
            }
            StmtKind::Switch { discriminant, cases } => {
                let text = format!("switch {}", expr(discriminant, &mut fns));
                self.line(at, &text, fns);
                self.depth += 1;
                for c in cases {
                    let mut fns = Vec::new();
                    let text = match &c.test {
                        Some(t) => format!("case {}", expr(t, &mut fns)),
                        None => "default".to_string(),
                    };
                    self.line(c.span.start, &text, fns);
                    self.block(&c.body);
                }
                self.depth -= 1;
            }
            StmtKind::For { init, test, update, body } => {
                let init = match init {
                    Some(ForInit::Var(d)) => format!("var {}", declarators(d, &mut fns)),
                    Some(ForInit::Expr(e)) => expr(e, &mut fns),
                    None => String::new(),
                };
                let test = test.as_ref().map(|t| expr(t, &mut fns)).unwrap_or_default();
                let update = update.as_ref().map(|u| expr(u, &mut fns)).unwrap_or_default();
                self.line(at, &format!("for {init}; {test}; {update}"), fns);
                self.block(std::slice::from_ref(body));
            }
            StmtKind::ForIn { declared, name, object, body } => {
                let var = if *declared { "var " } else { "" };
                let text = format!("for {var}{} in {}", name.name, expr(object, &mut fns));
                self.line(at, &text, fns);
                self.block(std::slice::from_ref(body));
            }
            StmtKind::While { cond, body } => {
                let text = format!("while {}", expr(cond, &mut fns));
                self.line(at, &text, fns);
                self.block(std::slice::from_ref(body));
            }
            StmtKind::DoWhile { body, cond } => {
                let text = format!("do-while {}", expr(cond, &mut fns));
                self.line(at, &text, fns);
                self.block(std::slice::from_ref(body));
            }
            StmtKind::Break => self.line(at, "break", fns),
            StmtKind::Continue => self.line(at, "continue", fns),
            StmtKind::Return(value) => {
                let text = match value {
                    Some(v) => format!("return {}", expr(v, &mut fns)),
                    None => "return".to_string(),
                };
                self.line(at, &text, fns);
            }
            StmtKind::Throw(v) => {
                let text = format!("throw {}", expr(v, &mut fns));
                self.line(at, &text, fns);
            }
            StmtKind::Try { block, handler, finalizer } => {
                self.line(at, "try", fns);
                self.block(block);
                if let Some(h) = handler {
                    self.line(h.span.start, &format!("catch {}", h.param.name), Vec::new());
                    self.block(&h.body);
                }
                if let Some(f) = finalizer {
                    self.line(f.first().map_or(at, |s| s.span.start), "finally", Vec::new());
                    self.block(f);
                }
            }
            StmtKind::Error => self.line(at, "<error>", fns),
        }
    }
}

fn params(f: &Function) -> String {
    f.params.iter().map(|p| p.name.as_str()).collect::<Vec<_>>().join(" ")
}

fn declarators<'a>(decls: &'a [VarDeclarator], fns: &mut Vec<&'a Function>) -> String {
    decls
        .iter()
        .map(|d| match &d.init {
            Some(init) => format!("{} = {}", d.name.name, expr(init, fns)),
            None => d.name.name.clone(),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn list<'a>(items: &'a [Expr], fns: &mut Vec<&'a Function>) -> String {
    items.iter().map(|e| format!(" {}", expr(e, fns))).collect()
}

/// An expression as an S-expression; function expressions are collected
/// into `fns` so their bodies can follow the line.
fn expr<'a>(e: &'a Expr, fns: &mut Vec<&'a Function>) -> String {
    match &e.kind {
        ExprKind::Number(n) => js_number(*n),
        ExprKind::String(s) => quote(s),
        ExprKind::Bool(b) => b.to_string(),
        ExprKind::Null => "null".to_string(),
        ExprKind::Undefined => "undefined".to_string(),
        ExprKind::This => "this".to_string(),
        ExprKind::Regex { pattern, flags } => format!("/{pattern}/{flags}"),
        ExprKind::Ident(n) => n.clone(),
        ExprKind::Array(items) => format!("[{}]", list(items, fns).trim_start()),
        ExprKind::Template { quasis, exprs } => {
            let texts: Vec<String> = quasis.iter().map(|q| quote(q)).collect();
            format!("(template [{}]{})", texts.join(" "), list(exprs, fns))
        }
        ExprKind::Object(props) => {
            let parts: Vec<String> = props
                .iter()
                .map(|p| {
                    let key = match p.key.written {
                        KeyForm::String => quote(&p.key.name),
                        KeyForm::Ident | KeyForm::Number => p.key.name.clone(),
                    };
                    format!("{key}: {}", expr(&p.value, fns))
                })
                .collect();
            format!("{{{}}}", parts.join(", "))
        }
        ExprKind::Function(f) => {
            fns.push(f);
            let name = f.name.as_ref().map_or(String::new(), |n| format!(" {}", n.name));
            let kind = if f.arrow { "arrow" } else { "function" };
            format!("({kind}{name} ({}))", params(f))
        }
        ExprKind::Member { object, property } => format!("(. {} {})", expr(object, fns), property.name),
        ExprKind::Index { object, index } => format!("([] {} {})", expr(object, fns), expr(index, fns)),
        ExprKind::Call { callee, args } => format!("(call {}{})", expr(callee, fns), list(args, fns)),
        ExprKind::New { callee, args } => format!("(new {}{})", expr(callee, fns), list(args, fns)),
        ExprKind::Unary { op, operand } => format!("({} {})", op.as_str(), expr(operand, fns)),
        ExprKind::Update { op, prefix, target } => {
            let side = if *prefix { "pre" } else { "post" };
            format!("({side}{} {})", op.as_str(), expr(target, fns))
        }
        ExprKind::Binary { op, left, right } => format!("({} {} {})", op.as_str(), expr(left, fns), expr(right, fns)),
        ExprKind::Logical { op, left, right } => format!("({} {} {})", op.as_str(), expr(left, fns), expr(right, fns)),
        ExprKind::Assign { op, target, value } => {
            format!("({} {} {})", op.as_str(), expr(target, fns), expr(value, fns))
        }
        ExprKind::Conditional { test, consequent, alternate } => {
            format!("(? {} {} {})", expr(test, fns), expr(consequent, fns), expr(alternate, fns))
        }
        ExprKind::Sequence(items) => format!("(,{})", list(items, fns)),
        ExprKind::Error => "<error>".to_string(),
    }
}
