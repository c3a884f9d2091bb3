//! Lowering expressions, calls and `Out` lines.
//!
//! BASIC operators map onto the IR's: `Mod` is `Rem`, `\` is `IntDiv`, `&`
//! is `Concat`; `Xor` (absent from the IR) is `(Not a) <> (Not b)`, a
//! logical exclusive or. `X.Previous` is `Previous(X)`. Built-ins map as
//! [`crate::builtins`] says. The composites functions whose values come
//! from the calls (`getNthLength1` ...) become stub functions returning 0,
//! which [`crate::call_tables::lower`] makes read the calls' lists.

use postc_ir::{
    BinaryOp as IrOp, Body, Builtin, Diagnostic, Expr as IrExpr, Function, Piece, Span, Stmt as IrStmt,
    UnaryOp as IrUnary,
};

use postc_ir::post::FunctionId;

use super::Lowerer;
use super::template::{TemplatePart, out_parts, split, unclosed};
use crate::ast::{BinaryOp, Expr, ExprKind, Name, ProcKind, UnaryOp};
use crate::builtins::{self, Lowering};
use crate::diagnostics as codes;
use crate::token::Kw;

/// The IR operator of a BASIC operator (`Xor` has none).
pub(super) fn binary_op(op: BinaryOp) -> Option<IrOp> {
    Some(match op {
        BinaryOp::Add => IrOp::Add,
        BinaryOp::Sub => IrOp::Sub,
        BinaryOp::Mul => IrOp::Mul,
        BinaryOp::Div => IrOp::Div,
        BinaryOp::IntDiv => IrOp::IntDiv,
        BinaryOp::Mod => IrOp::Rem,
        BinaryOp::Pow => IrOp::Pow,
        BinaryOp::Concat => IrOp::Concat,
        BinaryOp::Eq => IrOp::Eq,
        BinaryOp::Ne => IrOp::Ne,
        BinaryOp::Lt => IrOp::Lt,
        BinaryOp::Le => IrOp::Le,
        BinaryOp::Gt => IrOp::Gt,
        BinaryOp::Ge => IrOp::Ge,
        BinaryOp::And => IrOp::And,
        BinaryOp::Or => IrOp::Or,
        BinaryOp::Xor => return None,
    })
}

impl Lowerer<'_> {
    /// Lowers an expression (depth already checked).
    pub(super) fn expr(&mut self, e: &Expr) -> IrExpr {
        match &e.kind {
            ExprKind::Number(n) => IrExpr::Number(*n),
            ExprKind::Text(t) => IrExpr::Text(t.clone()),
            ExprKind::Bool(b) => IrExpr::Bool(*b),
            ExprKind::Name(name) => self.value(name),
            ExprKind::Previous(name) => self.previous(name),
            ExprKind::Property { target, property } => {
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::BAD_PROPERTY_READ,
                        format!("`{}.{}` cannot be read", target.text, property.text),
                    )
                    .at(property.span, "only `.Previous` can be read in an expression")
                    .help("register properties are settings for printing; they are set outside the Subs, not read"),
                );
                IrExpr::Number(0.0)
            }
            ExprKind::Call { name, args } => self.call_expr(name, args, e),
            ExprKind::Unary(op, inner) => {
                let inner = self.expr(inner);
                match op {
                    UnaryOp::Neg => IrExpr::Unary(IrUnary::Neg, Box::new(inner)),
                    UnaryOp::Not => IrExpr::Unary(IrUnary::Not, Box::new(inner)),
                    UnaryOp::Plus => inner,
                }
            }
            ExprKind::Binary(op, a, b) => {
                let (a, b) = (self.expr(a), self.expr(b));
                match binary_op(*op) {
                    Some(op) => IrExpr::Binary(op, Box::new(a), Box::new(b)),
                    None => IrExpr::Binary(
                        IrOp::Ne,
                        Box::new(IrExpr::Unary(IrUnary::Not, Box::new(a))),
                        Box::new(IrExpr::Unary(IrUnary::Not, Box::new(b))),
                    ),
                }
            }
            ExprKind::Paren(inner) => self.expr(inner),
            ExprKind::Error => IrExpr::Number(0.0),
        }
    }

    fn previous(&mut self, name: &Name) -> IrExpr {
        let local = self.scope.as_ref().is_some_and(|s| s.locals.contains_key(&name.key()));
        match (local, self.register_var(&name.text)) {
            (false, Some(var)) => IrExpr::Previous(var),
            _ => {
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::BAD_PROPERTY_READ,
                        format!("`{}` is a local variable and has no `.Previous`", name.text),
                    )
                    .at(name.span, "`.Previous` belongs to registers")
                    .help("only registers remember the value they had before their last assignment"),
                );
                IrExpr::Number(0.0)
            }
        }
    }

    /// `Name(args)` in an expression.
    fn call_expr(&mut self, name: &Name, args: &[Expr], e: &Expr) -> IrExpr {
        let key = name.key();
        let shadowed =
            self.scope.as_ref().is_some_and(|s| s.locals.contains_key(&key)) || self.registers.contains_key(&key);
        if !shadowed && let Some(b) = builtins::lookup(&key) {
            if !(b.min_args..=b.max_args).contains(&args.len()) {
                self.arity_error(name, b.min_args, b.max_args, args.len(), e, Some(b.summary));
                return IrExpr::Number(0.0);
            }
            let mut lowered: Vec<IrExpr> = args.iter().map(|a| self.expr(a)).collect();
            return match b.lowering {
                Lowering::Ir(builtin) => IrExpr::Builtin(builtin, lowered),
                Lowering::Format if lowered.len() == 1 => IrExpr::Builtin(Builtin::Str, lowered),
                Lowering::Format => IrExpr::Builtin(Builtin::FormatPicture, lowered),
                Lowering::IIf => {
                    let (c, a, b) = (lowered.remove(0), lowered.remove(0), lowered.remove(0));
                    IrExpr::Choose(Box::new(c), Box::new(a), Box::new(b))
                }
                Lowering::Sgn => {
                    let x = lowered.remove(0);
                    let cmp = |op, x: IrExpr| IrExpr::Binary(op, Box::new(x), Box::new(IrExpr::Number(0.0)));
                    let negative = IrExpr::Choose(
                        Box::new(cmp(IrOp::Lt, x.clone())),
                        Box::new(IrExpr::Number(-1.0)),
                        Box::new(IrExpr::Number(0.0)),
                    );
                    IrExpr::Choose(Box::new(cmp(IrOp::Gt, x)), Box::new(IrExpr::Number(1.0)), Box::new(negative))
                }
            };
        }
        if let Some(p) = self.procs.get(&key).cloned() {
            if p.kind == ProcKind::Sub {
                self.diagnostics.push(
                    Diagnostic::error(codes::NOT_A_VALUE, format!("Sub `{}` gives no value", name.text))
                        .at(name.span, "a Sub cannot be used in an expression")
                        .help("call it on a line of its own, or make it a Function"),
                );
                return IrExpr::Number(0.0);
            }
            if p.params != args.len() {
                self.arity_error(name, p.params, p.params, args.len(), e, None);
                return IrExpr::Number(0.0);
            }
            let lowered = args.iter().map(|a| self.expr(a)).collect();
            return IrExpr::Call(p.id, lowered);
        }
        if let Some(id) = self.host_call(name, args.len(), e) {
            let lowered = args.iter().map(|a| self.expr(a)).collect();
            return IrExpr::Call(id, lowered);
        }
        let d = if shadowed || self.globals.contains_key(&key) {
            Diagnostic::error(codes::NOT_A_VALUE, format!("`{}` is a variable, not a function", name.text))
                .at(e.span, "called like a function")
                .help("VcPost in postc has no arrays; use separate variables")
        } else if builtins::is_unsupported(&key) {
            Diagnostic::error(
                codes::UNSUPPORTED,
                format!("the BASIC function `{}` is not supported by postc", name.text),
            )
            .at(name.span, "not available")
            .help(format!("available functions: {}", builtin_names()))
        } else {
            let functions: Vec<String> = self.function_names();
            let candidates = builtins::BUILTINS.iter().map(|b| b.name).chain(functions.iter().map(String::as_str));
            let d = Diagnostic::error(codes::UNKNOWN_FUNCTION, format!("there is no function `{}`", name.text))
                .at(name.span, "unknown function");
            match codes::suggest(&name.text, candidates) {
                Some(s) => d.help(format!("did you mean `{s}`?")),
                None => d.help(format!(
                    "built-in functions are {}; a post's own are declared with `Function`",
                    builtin_names()
                )),
            }
        };
        self.diagnostics.push(d);
        IrExpr::Number(0.0)
    }

    /// A call on a line of its own: `Name`, `Name a, b`, `Call Name(a, b)`.
    pub(super) fn call_stmt(&mut self, name: &Name, args: &[Expr], span: postc_ir::Span) -> Option<IrStmt> {
        let key = name.key();
        let whole = Expr { kind: ExprKind::Error, span };
        if let Some(p) = self.procs.get(&key).cloned() {
            if p.params != args.len() {
                self.arity_error(name, p.params, p.params, args.len(), &whole, None);
                return None;
            }
            let lowered = args.iter().map(|a| self.expr_checked(a)).collect();
            return Some(IrStmt::Eval(IrExpr::Call(p.id, lowered)));
        }
        let d = if key == "option" {
            Diagnostic::warning(codes::OPTION_IGNORED, "`Option` lines are ignored")
                .at(span, "VcPost has no options")
                .help("every name is declared by its first use; postc warns (VC030) about names that are read but never set")
        } else if builtins::lookup(&key).is_some() {
            Diagnostic::error(codes::NOT_A_VALUE, format!("`{}` gives a value and cannot stand alone", name.text))
                .at(span, "its result would be lost")
                .help(format!("use it in an assignment, for example `Result = {}(...)`", name.text))
        } else if self.registers.contains_key(&key)
            || self.globals.contains_key(&key)
            || self.scope.as_ref().is_some_and(|s| s.locals.contains_key(&key))
        {
            Diagnostic::error(codes::NOT_A_VALUE, format!("`{}` is a variable, not a Sub", name.text))
                .at(span, "a variable cannot be called")
                .help(format!("to set it, write `{} = value`", name.text))
        } else {
            let subs = self.function_names();
            let d = Diagnostic::error(codes::UNKNOWN_SUB, format!("there is no Sub `{}`", name.text))
                .at(name.span, "called here");
            match codes::suggest(&name.text, subs.iter().map(String::as_str)) {
                Some(s) => d.help(format!("did you mean `{s}`?")),
                None => d.help(format!("define it with `Sub {}` ... `End Sub`", name.text)),
            }
        };
        self.diagnostics.push(d);
        None
    }

    /// The stub function of a runtime-provided function, if `name` is one.
    fn host_call(&mut self, name: &Name, args: usize, e: &Expr) -> Option<FunctionId> {
        let (canonical, params) = crate::routines::host_function(&name.text)?;
        if args != params.len() {
            self.arity_error(name, params.len(), params.len(), args, e, None);
            return None;
        }
        if let Some(id) = self.host_functions.get(canonical) {
            return Some(*id);
        }
        let id = FunctionId::from_usize(self.post.functions.len())?;
        self.post.functions.push(Function {
            name: canonical.to_string(),
            params: params.iter().map(|p| p.to_string()).collect(),
            slots: u16::try_from(params.len()).unwrap_or(0),
            locals: Vec::new(),
            body: Body::Native(vec![IrStmt::Return(Some(IrExpr::Number(0.0)))]),
            span: None,
            why_script: None,
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: false,
        });
        self.host_functions.insert(canonical.to_string(), id);
        Some(id)
    }

    fn function_names(&self) -> Vec<String> {
        self.post.functions.iter().map(|f| f.name.clone()).collect()
    }

    fn arity_error(&mut self, name: &Name, min: usize, max: usize, given: usize, e: &Expr, summary: Option<&str>) {
        let wanted = match (min, max) {
            (a, b) if a == b => format!("{a}"),
            (a, b) => format!("{a} to {b}"),
        };
        let plural = if max == 1 { "argument" } else { "arguments" };
        let mut d =
            Diagnostic::error(codes::ARGUMENT_COUNT, format!("`{}` takes {wanted} {plural}, not {given}", name.text))
                .at(e.span, format!("{given} given"));
        if let Some(s) = summary {
            d = d.help(s.to_string());
        }
        self.diagnostics.push(d);
    }

    /// `Out` and what follows it; `span` is the whole statement's.
    pub(super) fn out_line(&mut self, e: Option<&Expr>, span: Span) -> IrStmt {
        let span = Some(span);
        let mut pieces: Vec<Piece> = Vec::new();
        let Some(e) = e else { return IrStmt::Line { pieces, span } };
        if e.depth() > super::MAX_EXPR_DEPTH {
            return IrStmt::Line { pieces: vec![Piece::Expr(self.expr_checked(e))], span };
        }
        for part in out_parts(e) {
            let ExprKind::Text(text) = &part.kind else {
                let value = self.expr(part);
                pieces.push(Piece::Expr(value));
                continue;
            };
            for range in unclosed(text) {
                // Source offsets: after the opening quote, each `"` of the
                // text was written `""`.
                let at = |i: usize| part.span.start + 1 + i + text[..i].matches('"').count();
                let name = &text[range.start + 1..range.end];
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::UNCLOSED_REGISTER,
                        format!("`<{name}` is never closed: `>` is missing, so it would print as text"),
                    )
                    .at(Span::new(part.span.file, at(range.start), at(range.end)), "this register has no `>`")
                    .help(format!("write `<{name}>` to print the register, or move the `<` out of the template")),
                );
            }
            for piece in split(text) {
                match piece {
                    TemplatePart::Text(t) => self.push_text(&mut pieces, t),
                    TemplatePart::Register(name) if Kw::from_word(name).is_some() => {
                        self.diagnostics.push(
                            Diagnostic::warning(
                                codes::KEYWORD_IN_TEMPLATE,
                                format!("`<{name}>` names a keyword; it prints as text"),
                            )
                            .at(part.span, "in this string")
                            .help("registers cannot be named like keywords"),
                        );
                        self.push_text(&mut pieces, &format!("<{name}>"));
                    }
                    TemplatePart::Register(name) => {
                        if self.register_var(name).is_none() {
                            self.add_register(name, part.span);
                        }
                        match self.register_var(name) {
                            Some(var) => pieces.push(Piece::Var(var)),
                            None => self.push_text(&mut pieces, &format!("<{name}>")),
                        }
                    }
                }
            }
        }
        IrStmt::Line { pieces, span }
    }

    fn push_text(&self, pieces: &mut Vec<Piece>, text: &str) {
        let bytes = if self.legacy_encoding {
            encoding_rs::WINDOWS_1252.encode(text).0.into_owned()
        } else {
            text.as_bytes().to_vec()
        };
        if let Some(Piece::Text(last)) = pieces.last_mut() {
            last.extend_from_slice(&bytes);
        } else if !bytes.is_empty() {
            pieces.push(Piece::Text(bytes));
        }
    }
}

fn builtin_names() -> String {
    builtins::BUILTINS.iter().map(|b| b.name).collect::<Vec<_>>().join(", ")
}
