//! Expressions in Rhai.

use crate::ast::*;
use crate::host_names as names;

use super::super::builtins;
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
        self.open(names::TRUTHY);
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
                Binding::Var(id) => format!("{VAR_REF}({id})", VAR_REF = names::VAR_REF),
                Binding::Format(id) => format!("{FORMAT_REF}({id})", FORMAT_REF = names::FORMAT_REF),
            };
            return self.w(&text);
        }
        if let Some(g) = self.model.global(name) {
            if let Some(c) = &g.constant {
                let text = constant(c);
                return self.w(&text);
            }
            if let Some(&i) = self.layout.global_index.get(name) {
                return self.w(&format!("{GLOBAL_GET}({i})", GLOBAL_GET = names::GLOBAL_GET));
            }
        }
        if let Some(c) = builtins::constant(name) {
            return self.w(&constant(&c));
        }
        if name == "Math" {
            return self.w(&format!("{}()", names::MATH_OBJECT));
        }
        if builtins::knows(name) {
            return self.w(&format!("{HOST_FUNCTION}({})", quote(name), HOST_FUNCTION = names::HOST_FUNCTION));
        }
        self.w(&format!("{UNDEF}({})", quote(name), UNDEF = names::UNDEF))
    }

    pub(super) fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Number(n) => self.w(&number(*n)),
            ExprKind::String(s) => self.w(&quote(s)),
            ExprKind::Bool(b) => self.w(if *b { "true" } else { "false" }),
            ExprKind::Null => self.w(&format!("{}()", names::NULL)),
            // A template literal is Fusion's, and Fusion posts never become
            // Rhai: as an error node.
            ExprKind::Undefined | ExprKind::Error | ExprKind::Template { .. } => self.w("()"),
            ExprKind::This => self.w(if self.at == 0 { "()" } else { "this" }),
            ExprKind::Regex { pattern, flags } => {
                self.mark(e.span);
                self.w(&format!("{REGEX}({}, {})", quote(pattern), quote(flags), REGEX = names::REGEX));
            }
            ExprKind::Ident(name) => match self.model.scopes.resolve(name, self.at) {
                Symbol::Local { func, slot } if slot == usize::MAX => self.w(&arguments_name(func)),
                Symbol::Local { .. } => self.w(&local_name(name)),
                Symbol::TopFn(_) => self.w(&format!(
                    "{FUNCTION_OBJECT}({})",
                    quote(&fn_name(name)),
                    FUNCTION_OBJECT = names::FUNCTION_OBJECT
                )),
                Symbol::Global(g) => {
                    self.mark(e.span);
                    self.global(&g)
                }
            },
            ExprKind::Array(items) => {
                self.open(names::ARRAY);
                self.list(items);
                self.w(")");
            }
            ExprKind::Object(props) => {
                self.open(names::OBJECT);
                self.w("[");
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
                    && let Some(c) = builtins::math_constant(&property.name)
                {
                    return self.w(&number(c));
                }
                self.open(names::GET);
                self.expr(object);
                self.w(&format!(", {})", quote(&property.name)));
            }
            ExprKind::Index { object, index } => {
                self.mark(e.span);
                self.open(names::GET);
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
                self.open(names::NEW);
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
                    && builtins::constant(n).is_none()
                {
                    let t = if n == "Math" {
                        "object"
                    } else if builtins::knows(n) {
                        "function"
                    } else {
                        "undefined"
                    };
                    return self.w(&quote(t));
                }
                self.mark(e.span);
                let f = match op {
                    UnaryOp::Neg => names::NEG,
                    UnaryOp::Plus => names::POS,
                    UnaryOp::Not => {
                        self.w("!");
                        names::TRUTHY
                    }
                    UnaryOp::BitNot => names::BNOT,
                    UnaryOp::Typeof => names::TYPEOF,
                };
                self.open(f);
                self.expr(operand);
                self.w(")");
            }
            ExprKind::Update { op, prefix, target } => self.update(*op, *prefix, target),
            ExprKind::Binary { op: BinaryOp::Add, .. } => {
                let mut terms = Vec::new();
                flatten_add(e, &mut terms);
                self.mark(e.span);
                if terms.len() == 2 {
                    self.open(names::ADD);
                    self.expr(terms[0]);
                    self.w(", ");
                    self.expr(terms[1]);
                    self.w(")");
                } else {
                    self.open(names::ADDS);
                    self.w("[");
                    for (i, t) in terms.iter().enumerate() {
                        if i > 0 {
                            self.w(", ");
                        }
                        self.expr(t);
                    }
                    self.w("])");
                }
            }
            // Fusion's, as a template literal is.
            ExprKind::Binary { op: BinaryOp::Instanceof, .. } => self.w("()"),
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
                        self.w(&format!("{MATH}({}, ", quote(name), MATH = names::MATH));
                        self.list(args);
                        return self.w(")");
                    }
                    let bound = match self.model.scopes.resolve(o, self.at) {
                        Symbol::Global(g) => self.setup.bindings.get(&g).copied(),
                        _ => None,
                    };
                    match (bound, name.as_str()) {
                        (Some(Binding::Var(id)), "format") => {
                            self.w(&format!("{VAR_FORMAT}({id}, ", VAR_FORMAT = names::VAR_FORMAT));
                            self.first_arg(args);
                            return self.w(")");
                        }
                        (Some(Binding::Var(id)), "getLast") => {
                            return self.w(&format!("{VAR_LAST}({id})", VAR_LAST = names::VAR_LAST));
                        }
                        (Some(Binding::Format(id)), "format") => {
                            self.w(&format!("{FORMAT_FORMAT}({id}, ", FORMAT_FORMAT = names::FORMAT_FORMAT));
                            self.first_arg(args);
                            return self.w(")");
                        }
                        _ => {}
                    }
                }
                self.open(names::CALL_METHOD);
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
                        self.w(&format!(
                            "{CALL}({FUNCTION_OBJECT}({}), ",
                            quote(&rhai),
                            CALL = names::CALL,
                            FUNCTION_OBJECT = names::FUNCTION_OBJECT
                        ));
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
                    } else if builtins::FUNCTIONS.contains(&g.as_str()) {
                        self.w(&format!("{HOST}({}, ", quote(&g), HOST = names::HOST));
                    } else {
                        self.w(&format!("{CALL}({UNDEF}({}), ", quote(&g), CALL = names::CALL, UNDEF = names::UNDEF));
                    }
                    self.list(args);
                    self.w(")");
                }
                _ => {
                    self.open(names::CALL);
                    self.expr(callee);
                    self.w(", ");
                    self.list(args);
                    self.w(")");
                }
            },
            _ => {
                self.open(names::CALL);
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
        BinaryOp::Add => names::ADD,
        BinaryOp::Sub => names::SUB,
        BinaryOp::Mul => names::MUL,
        BinaryOp::Div => names::DIV,
        BinaryOp::Rem => names::REM,
        BinaryOp::Shl => names::SHL,
        BinaryOp::Shr => names::SHR,
        BinaryOp::UShr => names::USHR,
        BinaryOp::BitAnd => names::BAND,
        BinaryOp::BitOr => names::BOR,
        BinaryOp::BitXor => names::BXOR,
        BinaryOp::Eq => names::EQ,
        BinaryOp::Ne => names::NE,
        BinaryOp::StrictEq => names::SEQ,
        BinaryOp::StrictNe => names::SNE,
        BinaryOp::Lt => names::LT,
        BinaryOp::Le => names::LE,
        BinaryOp::Gt => names::GT,
        BinaryOp::Ge => names::GE,
        BinaryOp::In => names::IN,
        // Fusion's: Fusion posts never become scripts, and the `Binary`
        // arm writes `()` for it.
        BinaryOp::Instanceof => "",
    }
}

/// A constant as Rhai text.
fn constant(c: &super::super::consts::Const) -> String {
    use super::super::consts::Const;
    match c {
        Const::Num(n) => number(*n),
        Const::Str(s) => quote(s),
        Const::Bool(b) => b.to_string(),
        Const::Null => format!("{}()", names::NULL),
        Const::Undefined => "()".into(),
    }
}
