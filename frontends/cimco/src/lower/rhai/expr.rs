//! Expressions in Rhai.

use crate::ast::*;

use super::super::host;
use super::super::scope::Symbol;
use super::super::setup::Binding;
use super::{Gen, arguments_name, fn_name, local_name, number, quote};

/// Where a name stores.
pub(super) enum Target {
    Local(String),
    Global(postc_ir::GlobalId),
    None,
}

impl Gen<'_, '_> {
    /// A condition: JavaScript truthiness as a Rhai boolean.
    pub(super) fn cond(&mut self, e: &Expr) {
        self.w("__t(");
        self.expr(e);
        self.w(")");
    }

    pub(super) fn target_of(&self, name: &str) -> Target {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Local { func, slot } if slot == usize::MAX => Target::Local(arguments_name(func)),
            Symbol::Local { .. } => Target::Local(local_name(name)),
            Symbol::Global(g) => match self.layout.global_index.get(&g) {
                Some(&i) if !self.setup.bindings.contains_key(&g) => Target::Global(i),
                _ => Target::None,
            },
            Symbol::TopFn(_) => Target::None,
        }
    }

    fn list(&mut self, items: &[Expr]) {
        self.w("[");
        for (i, a) in items.iter().enumerate() {
            if i > 0 {
                self.w(", ");
            }
            self.expr(a);
        }
        self.w("]");
    }

    /// The value of a global by name.
    fn global(&mut self, name: &str) {
        if let Some(b) = self.setup.bindings.get(name) {
            let text = match b {
                Binding::Var(id) => format!("__vref({id})"),
                Binding::Format(id) => format!("__fref({id})"),
            };
            return self.w(&text);
        }
        if let Some(g) = self.model.global(name) {
            if let Some(c) = &g.constant {
                let text = constant(c);
                return self.w(&text);
            }
            if let Some(&i) = self.layout.global_index.get(name) {
                return self.w(&format!("__gg({i})"));
            }
        }
        if let Some(c) = host::constant(name) {
            return self.w(&constant(&c));
        }
        if name == "Math" {
            return self.w("__math_obj()");
        }
        if host::knows(name) {
            return self.w(&format!("__hostfn({})", quote(name)));
        }
        self.w(&format!("__undef({})", quote(name)))
    }

    pub(super) fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Number(n) => self.w(&number(*n)),
            ExprKind::String(s) => self.w(&quote(s)),
            ExprKind::Bool(b) => self.w(if *b { "true" } else { "false" }),
            ExprKind::Null => self.w("__null()"),
            ExprKind::Undefined | ExprKind::Error => self.w("()"),
            ExprKind::This => self.w(if self.at == 0 { "()" } else { "this" }),
            ExprKind::Regex { pattern, flags } => {
                self.mark(e.span);
                self.w(&format!("__regex({}, {})", quote(pattern), quote(flags)));
            }
            ExprKind::Ident(name) => match self.model.scopes.resolve(name, self.at) {
                Symbol::Local { func, slot } if slot == usize::MAX => self.w(&arguments_name(func)),
                Symbol::Local { .. } => self.w(&local_name(name)),
                Symbol::TopFn(_) => self.w(&format!("__fnobj({})", quote(&fn_name(name)))),
                Symbol::Global(g) => {
                    self.mark(e.span);
                    self.global(&g)
                }
            },
            ExprKind::Array(items) => {
                self.w("__arr(");
                self.list(items);
                self.w(")");
            }
            ExprKind::Object(props) => {
                self.w("__obj([");
                for (i, p) in props.iter().enumerate() {
                    if i > 0 {
                        self.w(", ");
                    }
                    self.w(&quote(&p.key.name));
                    self.w(", ");
                    self.expr(&p.value);
                }
                self.w("])");
            }
            ExprKind::Function(f) => self.closure(f),
            ExprKind::Member { object, property } => {
                self.mark(e.span);
                if let Some(flat) = self.model.flattened_name(e) {
                    return self.global(&flat);
                }
                if let ExprKind::Ident(o) = &object.kind
                    && o == "Math"
                    && self.is_host("Math")
                    && let Some(c) = host::math_constant(&property.name)
                {
                    return self.w(&number(c));
                }
                self.w("__get(");
                self.expr(object);
                self.w(&format!(", {})", quote(&property.name)));
            }
            ExprKind::Index { object, index } => {
                self.mark(e.span);
                self.w("__get(");
                self.expr(object);
                self.w(", ");
                self.expr(index);
                self.w(")");
            }
            ExprKind::Call { callee, args } => {
                self.mark(e.span);
                self.call(callee, args);
            }
            ExprKind::New { callee, args } => {
                self.mark(e.span);
                self.w("__new(");
                self.expr(callee);
                self.w(", ");
                self.list(args);
                self.w(")");
            }
            ExprKind::Unary { op, operand } => {
                if *op == UnaryOp::Typeof
                    && let ExprKind::Ident(n) = &operand.kind
                    && matches!(self.model.scopes.resolve(n, self.at), Symbol::Global(_))
                    && self.model.global(n).is_none()
                    && host::constant(n).is_none()
                {
                    let t = if n == "Math" {
                        "object"
                    } else if host::knows(n) {
                        "function"
                    } else {
                        "undefined"
                    };
                    return self.w(&quote(t));
                }
                self.mark(e.span);
                let f = match op {
                    UnaryOp::Neg => "__neg(",
                    UnaryOp::Plus => "__pos(",
                    UnaryOp::Not => "!__t(",
                    UnaryOp::BitNot => "__bnot(",
                    UnaryOp::Typeof => "__typeof(",
                };
                self.w(f);
                self.expr(operand);
                self.w(")");
            }
            ExprKind::Update { op, prefix, target } => self.update(*op, *prefix, target),
            ExprKind::Binary { op: BinaryOp::Add, .. } => {
                let mut terms = Vec::new();
                flatten_add(e, &mut terms);
                self.mark(e.span);
                if terms.len() == 2 {
                    self.w("__add(");
                    self.expr(terms[0]);
                    self.w(", ");
                    self.expr(terms[1]);
                    self.w(")");
                } else {
                    self.w("__adds([");
                    for (i, t) in terms.iter().enumerate() {
                        if i > 0 {
                            self.w(", ");
                        }
                        self.expr(t);
                    }
                    self.w("])");
                }
            }
            ExprKind::Binary { op, left, right } => {
                self.mark(e.span);
                self.w(binary_fn(*op));
                self.w("(");
                self.expr(left);
                self.w(", ");
                self.expr(right);
                self.w(")");
            }
            ExprKind::Logical { op, left, right } => {
                let t = self.temp("l");
                self.w(&format!("{{ let {t} = "));
                self.expr(left);
                self.w(&format!("; if __t({t}) {{ "));
                match op {
                    LogicalOp::And => {
                        self.expr(right);
                        self.w(&format!(" }} else {{ {t} }} }}"));
                    }
                    LogicalOp::Or => {
                        self.w(&format!("{t} }} else {{ "));
                        self.expr(right);
                        self.w(" } }");
                    }
                }
            }
            ExprKind::Conditional { test, consequent, alternate } => {
                self.w("(if ");
                self.cond(test);
                self.w(" { ");
                self.expr(consequent);
                self.w(" } else { ");
                self.expr(alternate);
                self.w(" })");
            }
            ExprKind::Assign { op, target, value } => self.assign_expr(target, *op, value),
            ExprKind::Sequence(items) => {
                self.w("{ ");
                for (i, it) in items.iter().enumerate() {
                    if i > 0 {
                        self.w("; ");
                    }
                    self.expr(it);
                }
                self.w(" }");
            }
        }
    }

    fn is_host(&self, name: &str) -> bool {
        matches!(self.model.scopes.resolve(name, self.at), Symbol::Global(_)) && self.model.global(name).is_none()
    }

    fn call(&mut self, callee: &Expr, args: &[Expr]) {
        match &callee.kind {
            ExprKind::Member { object, property } if self.model.flattened_name(callee).is_none() => {
                let name = &property.name;
                if let ExprKind::Ident(o) = &object.kind {
                    if o == "Math" && self.is_host("Math") {
                        self.w(&format!("__math({}, ", quote(name)));
                        self.list(args);
                        return self.w(")");
                    }
                    let bound = match self.model.scopes.resolve(o, self.at) {
                        Symbol::Global(g) => self.setup.bindings.get(&g).copied(),
                        _ => None,
                    };
                    match (bound, name.as_str()) {
                        (Some(Binding::Var(id)), "format") => {
                            self.w(&format!("__vfmt({id}, "));
                            self.first_arg(args);
                            return self.w(")");
                        }
                        (Some(Binding::Var(id)), "getLast") => return self.w(&format!("__vlast({id})")),
                        (Some(Binding::Format(id)), "format") => {
                            self.w(&format!("__ffmt({id}, "));
                            self.first_arg(args);
                            return self.w(")");
                        }
                        _ => {}
                    }
                }
                self.w("__callm(");
                self.expr(object);
                self.w(&format!(", {}, ", quote(name)));
                self.list(args);
                self.w(")");
            }
            ExprKind::Ident(name) => match self.model.scopes.resolve(name, self.at) {
                Symbol::TopFn(i) => {
                    let id = self.model.scopes.top_fns[i];
                    let rhai = fn_name(name);
                    if self.model.scopes.funcs[id].uses_this {
                        self.w(&format!("__call(__fnobj({}), ", quote(&rhai)));
                        self.list(args);
                        self.w(")");
                    } else {
                        self.w(&format!("{rhai}("));
                        self.list(args);
                        self.w(")");
                    }
                }
                Symbol::Global(g) if self.model.global(&g).is_none() && !self.setup.bindings.contains_key(&g) => {
                    if g == "getFeedrate" {
                        self.w(&format!("{}(", fn_name("getFeedrate")));
                    } else if host::FUNCTIONS.contains(&g.as_str()) {
                        self.w(&format!("__host({}, ", quote(&g)));
                    } else {
                        self.w(&format!("__call(__undef({}), ", quote(&g)));
                    }
                    self.list(args);
                    self.w(")");
                }
                _ => {
                    self.w("__call(");
                    self.expr(callee);
                    self.w(", ");
                    self.list(args);
                    self.w(")");
                }
            },
            _ => {
                self.w("__call(");
                self.expr(callee);
                self.w(", ");
                self.list(args);
                self.w(")");
            }
        }
    }

    fn first_arg(&mut self, args: &[Expr]) {
        match args.first() {
            Some(a) => self.expr(a),
            None => self.w("()"),
        }
    }
}

/// The terms of a left-associated chain of `+`.
fn flatten_add<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    match &e.kind {
        ExprKind::Binary { op: BinaryOp::Add, left, right } => {
            flatten_add(left, out);
            out.push(right);
        }
        _ => out.push(e),
    }
}

pub(super) fn binary_fn(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Add => "__add",
        BinaryOp::Sub => "__sub",
        BinaryOp::Mul => "__mul",
        BinaryOp::Div => "__div",
        BinaryOp::Rem => "__rem",
        BinaryOp::Shl => "__shl",
        BinaryOp::Shr => "__shr",
        BinaryOp::UShr => "__ushr",
        BinaryOp::BitAnd => "__band",
        BinaryOp::BitOr => "__bor",
        BinaryOp::BitXor => "__bxor",
        BinaryOp::Eq => "__eq",
        BinaryOp::Ne => "__ne",
        BinaryOp::StrictEq => "__seq",
        BinaryOp::StrictNe => "__sne",
        BinaryOp::Lt => "__lt",
        BinaryOp::Le => "__le",
        BinaryOp::Gt => "__gt",
        BinaryOp::Ge => "__ge",
    }
}

/// A constant as Rhai text.
fn constant(c: &super::super::consts::Const) -> String {
    use super::super::consts::Const;
    match c {
        Const::Num(n) => number(*n),
        Const::Str(s) => quote(s),
        Const::Bool(b) => b.to_string(),
        Const::Null => "__null()".into(),
        Const::Undefined => "()".into(),
    }
}
