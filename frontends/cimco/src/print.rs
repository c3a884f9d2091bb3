//! Prints a syntax tree back as JavaScript.
//!
//! The output is normalised (four-space indentation, a block's `{` on the
//! line of its statement and `} else {` on one line, double-quoted
//! strings, one statement per line, parentheses only where precedence
//! needs them) and parses back to the same tree. The later lowering uses
//! the same rules when it writes Rhai.

use std::fmt::Write;

use crate::ast::*;
use crate::strings::quote;

/// The program as JavaScript text.
pub fn to_js(program: &Program) -> String {
    let mut p = Printer { out: String::new(), indent: 0 };
    for s in &program.body {
        p.stmt(s);
    }
    p.out
}

/// One expression as JavaScript text.
pub fn expr_to_js(e: &Expr) -> String {
    let mut p = Printer { out: String::new(), indent: 0 };
    p.expr(e, 0);
    p.out
}

/// A number as JavaScript writes it.
pub fn js_number(n: f64) -> String {
    if n.is_nan() {
        "NaN".to_string()
    } else if n.is_infinite() {
        if n > 0.0 { "Infinity" } else { "-Infinity" }.to_string()
    } else {
        format!("{n}")
    }
}

/// A piece of a template literal's text as written between backquotes.
fn template_text(text: &str) -> String {
    let quoted = quote(text);
    let inner = &quoted[1..quoted.len() - 1];
    inner.replace("\\\"", "\"").replace('`', "\\`").replace("${", "\\${")
}

/// Whether a name can be written without quotes as a property key.
fn is_plain_name(name: &str) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_alphabetic() || c == '_' || c == '$')
        && chars.all(|c| c.is_alphanumeric() || c == '_' || c == '$')
}

/// An object literal longer than this prints one property a line.
const LONG_OBJECT: usize = 100;

/// Binding strength of each expression form; higher binds tighter.
fn precedence(e: &Expr) -> u8 {
    match &e.kind {
        ExprKind::Sequence(_) => 0,
        ExprKind::Assign { .. } => 1,
        ExprKind::Function(f) if f.arrow => 1,
        ExprKind::Conditional { .. } => 2,
        ExprKind::Logical { op: LogicalOp::Or, .. } => 3,
        ExprKind::Logical { op: LogicalOp::And, .. } => 4,
        ExprKind::Binary { op, .. } => binary_precedence(*op),
        ExprKind::Unary { .. } | ExprKind::Update { prefix: true, .. } => 14,
        ExprKind::Update { prefix: false, .. } => 15,
        ExprKind::Call { .. } | ExprKind::New { .. } => 16,
        ExprKind::Member { .. } | ExprKind::Index { .. } => 17,
        _ => 18,
    }
}

fn binary_precedence(op: BinaryOp) -> u8 {
    use BinaryOp::*;
    match op {
        BitOr => 5,
        BitXor => 6,
        BitAnd => 7,
        Eq | Ne | StrictEq | StrictNe => 8,
        Lt | Le | Gt | Ge | In | Instanceof => 9,
        Shl | Shr | UShr => 10,
        Add | Sub => 11,
        Mul | Div | Rem => 12,
    }
}

struct Printer {
    out: String,
    indent: usize,
}

impl Printer {
    fn line(&mut self, text: &str) {
        for _ in 0..self.indent {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    fn text(&mut self, e: &Expr, min: u8) -> String {
        let mut p = Printer { out: String::new(), indent: self.indent };
        p.expr(e, min);
        p.out
    }

    fn stmt(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Var(decls) => {
                let d = self.declarators(decls);
                self.line(&format!("var {d};"));
            }
            StmtKind::Function(f) => {
                let head = self.function_head(f);
                self.line(&format!("{head} {{"));
                self.body(&f.body);
                self.line("}");
            }
            StmtKind::Expr(e) => {
                let text = self.text(e, 0);
                if text.starts_with("function") || text.starts_with('{') {
                    self.line(&format!("({text});"));
                } else {
                    self.line(&format!("{text};"));
                }
            }
            StmtKind::Block(body) => {
                self.line("{");
                self.body(body);
                self.line("}");
            }
            StmtKind::Empty => self.line(";"),
            StmtKind::If { branches, otherwise } => {
                let mut open = false;
                for (i, b) in branches.iter().enumerate() {
                    let cond = self.text(&b.cond, 0);
                    let keyword = if i == 0 { "if" } else { "else if" };
                    open = self.clause(open, &format!("{keyword} ({cond})"), &b.body);
                }
                if let Some(o) = otherwise {
                    open = self.clause(open, "else", o);
                }
                if open {
                    self.line("}");
                }
            }
            StmtKind::Switch { discriminant, cases } => {
                let d = self.text(discriminant, 0);
                self.line(&format!("switch ({d}) {{"));
                for c in cases {
                    match &c.test {
                        Some(t) => {
                            let t = self.text(t, 0);
                            self.line(&format!("case {t}:"));
                        }
                        None => self.line("default:"),
                    }
                    self.body(&c.body);
                }
                self.line("}");
            }
            StmtKind::For { init, test, update, body } => {
                let init = match init {
                    Some(ForInit::Var(d)) => format!("var {}", self.declarators(d)),
                    Some(ForInit::Expr(e)) => self.text(e, 0),
                    None => String::new(),
                };
                let test = test.as_ref().map(|t| format!(" {}", self.text(t, 0))).unwrap_or_default();
                let update = update.as_ref().map(|u| format!(" {}", self.text(u, 0))).unwrap_or_default();
                self.block(&format!("for ({init};{test};{update})"), body);
            }
            StmtKind::ForIn { declared, name, object, body } => {
                let var = if *declared { "var " } else { "" };
                let object = self.text(object, 0);
                self.block(&format!("for ({var}{} in {object})", name.name), body);
            }
            StmtKind::While { cond, body } => {
                let cond = self.text(cond, 0);
                self.block(&format!("while ({cond})"), body);
            }
            StmtKind::DoWhile { body, cond } => {
                let open = self.clause(false, "do", body);
                let cond = self.text(cond, 0);
                self.line(&format!("{}while ({cond});", if open { "} " } else { "" }));
            }
            StmtKind::Break => self.line("break;"),
            StmtKind::Continue => self.line("continue;"),
            StmtKind::Return(None) => self.line("return;"),
            StmtKind::Return(Some(e)) => {
                let e = self.text(e, 0);
                self.line(&format!("return {e};"));
            }
            StmtKind::Throw(e) => {
                let e = self.text(e, 0);
                self.line(&format!("throw {e};"));
            }
            StmtKind::Try { block, handler, finalizer } => {
                self.line("try {");
                self.body(block);
                if let Some(h) = handler {
                    self.line(&format!("}} catch ({}) {{", h.param.name));
                    self.body(&h.body);
                }
                if let Some(f) = finalizer {
                    self.line("} finally {");
                    self.body(f);
                }
                self.line("}");
            }
            StmtKind::Error => self.line("/* error */;"),
        }
    }

    /// A loop's head and body: a block opens on the head's line and
    /// closes on a line of its own; another statement is indented below.
    fn block(&mut self, head: &str, body: &Stmt) {
        if self.clause(false, head, body) {
            self.line("}");
        }
    }

    /// One clause of a compound statement (`if (c)`, `else`, `do`): a
    /// block opens on the clause's line, after the `}` of the clause
    /// before when that one is still `open`, and is left open (the result
    /// says so); another statement is indented below.
    fn clause(&mut self, open: bool, head: &str, body: &Stmt) -> bool {
        let head = if open { format!("}} {head}") } else { head.to_string() };
        if let StmtKind::Block(stmts) = &body.kind {
            self.line(&format!("{head} {{"));
            self.body(stmts);
            true
        } else {
            self.line(&head);
            self.indent += 1;
            self.stmt(body);
            self.indent -= 1;
            false
        }
    }

    fn body(&mut self, body: &[Stmt]) {
        self.indent += 1;
        for s in body {
            self.stmt(s);
        }
        self.indent -= 1;
    }

    fn declarators(&mut self, decls: &[VarDeclarator]) -> String {
        let parts: Vec<String> = decls
            .iter()
            .map(|d| match &d.init {
                Some(init) => format!("{} = {}", d.name.name, self.text(init, 1)),
                None => d.name.name.clone(),
            })
            .collect();
        parts.join(", ")
    }

    fn function_head(&self, f: &Function) -> String {
        let name = f.name.as_ref().map(|n| format!(" {}", n.name)).unwrap_or_default();
        let params: Vec<&str> = f.params.iter().map(|p| p.name.as_str()).collect();
        if f.arrow {
            return format!("({}) =>", params.join(", "));
        }
        format!("function{name}({})", params.join(", "))
    }

    fn list(&mut self, items: &[Expr]) -> String {
        let parts: Vec<String> = items.iter().map(|e| self.text(e, 1)).collect();
        parts.join(", ")
    }

    fn expr(&mut self, e: &Expr, min: u8) {
        let own = precedence(e);
        let wrap = own < min;
        if wrap {
            self.out.push('(');
        }
        self.expr_bare(e, own);
        if wrap {
            self.out.push(')');
        }
    }

    fn expr_bare(&mut self, e: &Expr, own: u8) {
        match &e.kind {
            ExprKind::Number(n) => self.out.push_str(&js_number(*n)),
            ExprKind::String(s) => self.out.push_str(&quote(s)),
            ExprKind::Bool(b) => self.out.push_str(if *b { "true" } else { "false" }),
            ExprKind::Null => self.out.push_str("null"),
            ExprKind::Undefined => self.out.push_str("undefined"),
            ExprKind::This => self.out.push_str("this"),
            ExprKind::Regex { pattern, flags } => {
                let _ = write!(self.out, "/{pattern}/{flags}");
            }
            ExprKind::Ident(n) => self.out.push_str(n),
            ExprKind::Template { quasis, exprs } => {
                self.out.push('`');
                for (k, text) in quasis.iter().enumerate() {
                    self.out.push_str(&template_text(text));
                    if let Some(e) = exprs.get(k) {
                        let e = self.text(e, 0);
                        let _ = write!(self.out, "${{{e}}}");
                    }
                }
                self.out.push('`');
            }
            ExprKind::Array(items) => {
                let items = self.list(items);
                let _ = write!(self.out, "[{items}]");
            }
            ExprKind::Object(props) => {
                let parts: Vec<String> = props
                    .iter()
                    .map(|p| {
                        let key = match p.key.written {
                            KeyForm::Ident if is_plain_name(&p.key.name) => p.key.name.clone(),
                            KeyForm::Number => p.key.name.clone(),
                            _ => quote(&p.key.name),
                        };
                        format!("{key}: {}", self.text(&p.value, 1))
                    })
                    .collect();
                let one_line = format!("{{{}}}", parts.join(", "));
                if one_line.len() <= LONG_OBJECT {
                    self.out.push_str(&one_line);
                } else {
                    // A long object (a post's `globals`) has one property a line.
                    let pad = "    ".repeat(self.indent + 1);
                    let _ = write!(
                        self.out,
                        "{{\n{pad}{}\n{}}}",
                        parts.join(&format!(",\n{pad}")),
                        "    ".repeat(self.indent)
                    );
                }
            }
            ExprKind::Function(f) => {
                let head = self.function_head(f);
                let _ = writeln!(self.out, "{head} {{");
                let mut inner = Printer { out: String::new(), indent: self.indent + 1 };
                for s in &f.body {
                    inner.stmt(s);
                }
                self.out.push_str(&inner.out);
                for _ in 0..self.indent {
                    self.out.push_str("    ");
                }
                self.out.push('}');
            }
            ExprKind::Member { object, property } => {
                self.object(object);
                let _ = write!(self.out, ".{}", property.name);
            }
            ExprKind::Index { object, index } => {
                self.object(object);
                let index = self.text(index, 0);
                let _ = write!(self.out, "[{index}]");
            }
            ExprKind::Call { callee, args } => {
                self.expr(callee, 16);
                let args = self.list(args);
                let _ = write!(self.out, "({args})");
            }
            ExprKind::New { callee, args } => {
                self.out.push_str("new ");
                self.expr(callee, 17);
                let args = self.list(args);
                let _ = write!(self.out, "({args})");
            }
            ExprKind::Unary { op, operand } => {
                let text = self.text(operand, own);
                self.out.push_str(op.as_str());
                let clash = match op {
                    UnaryOp::Typeof => true,
                    UnaryOp::Neg => text.starts_with('-'),
                    UnaryOp::Plus => text.starts_with('+'),
                    _ => false,
                };
                if clash {
                    self.out.push(' ');
                }
                self.out.push_str(&text);
            }
            ExprKind::Update { op, prefix: true, target } => {
                let text = self.text(target, own);
                self.out.push_str(op.as_str());
                if text.starts_with(['+', '-']) {
                    self.out.push(' ');
                }
                self.out.push_str(&text);
            }
            ExprKind::Update { op, prefix: false, target } => {
                self.expr(target, 16);
                self.out.push_str(op.as_str());
            }
            ExprKind::Binary { op, left, right } => self.infix(left, op.as_str(), right, own),
            ExprKind::Logical { op, left, right } => self.infix(left, op.as_str(), right, own),
            ExprKind::Assign { op, target, value } => {
                self.expr(target, 16);
                let _ = write!(self.out, " {} ", op.as_str());
                self.expr(value, 1);
            }
            ExprKind::Conditional { test, consequent, alternate } => {
                self.expr(test, 3);
                self.out.push_str(" ? ");
                self.expr(consequent, 1);
                self.out.push_str(" : ");
                self.expr(alternate, 1);
            }
            ExprKind::Sequence(items) => {
                let parts: Vec<String> = items.iter().map(|e| self.text(e, 1)).collect();
                self.out.push_str(&parts.join(", "));
            }
            ExprKind::Error => self.out.push_str("/* error */ undefined"),
        }
    }

    /// The object of a member or index access (`1.5.toFixed` needs brackets).
    fn object(&mut self, object: &Expr) {
        if matches!(object.kind, ExprKind::Number(_)) {
            self.out.push('(');
            self.expr(object, 0);
            self.out.push(')');
        } else {
            self.expr(object, 16);
        }
    }

    fn infix(&mut self, left: &Expr, op: &str, right: &Expr, own: u8) {
        self.expr(left, own);
        let _ = write!(self.out, " {op} ");
        self.expr(right, own + 1);
    }
}
