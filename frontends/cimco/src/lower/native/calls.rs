//! Calls in native IR: post functions, the host's functions (`getFeedrate`,
//! `parseFloat`, `Math.*`), and the `format` and `getLast` methods of the
//! output variables and formats bound at compile time.

use postc_ir::{BinaryOp as IrBin, Builtin, Expr as Ir};

use crate::ast::*;

use super::super::scope::Symbol;
use super::super::setup::Binding;
use super::super::{builtins, layout};
use super::{Native, R, to_number, why};

impl Native<'_, '_> {
    /// Whether a name is the host's (not shadowed by the post).
    pub(super) fn is_host(&self, name: &str) -> bool {
        matches!(self.model.scopes.resolve(name, self.at), Symbol::Global(_)) && self.model.global(name).is_none()
    }

    pub(super) fn args(&mut self, args: &[Expr]) -> R<Vec<Ir>> {
        args.iter().map(|a| self.expr(a)).collect()
    }

    pub(super) fn call(&mut self, callee: &Expr, args: &[Expr]) -> R<Ir> {
        let at = callee.span;
        match &callee.kind {
            ExprKind::Member { object, property } => self.method(object, &property.name, args, at),
            ExprKind::Ident(name) => match self.model.scopes.resolve(name, self.at) {
                Symbol::TopFn(i) => {
                    let f = self.call_target(i, name, args.len(), at)?;
                    Ok(Ir::Call(f, self.args(args)?))
                }
                Symbol::Global(g) if self.model.global(&g).is_none() => self.host_call(&g, args, at),
                _ => Err(why(at, format!("calls `{name}`, a function value held in a variable"))),
            },
            _ => Err(why(at, "calls a function value (not a function of the post by name)")),
        }
    }

    fn host_call(&mut self, name: &str, args: &[Expr], at: postc_ir::Span) -> R<Ir> {
        let one = |b: Builtin, s: &mut Self| -> R<Ir> { Ok(Ir::Builtin(b, s.args(args)?)) };
        match name {
            "getFeedrate" => {
                let f = self.layout.function(layout::FEEDRATE).ok_or_else(|| why(at, "calls `getFeedrate`"))?;
                Ok(Ir::Call(f, self.args(args)?))
            }
            "parseInt" => one(Builtin::ParseInt, self),
            "parseFloat" => one(Builtin::ParseFloat, self),
            "isNaN" => one(Builtin::IsNaN, self),
            "Number" if !args.is_empty() => one(Builtin::ToNumber, self),
            "String" if args.len() == 1 => Ok(Ir::Builtin(Builtin::Str, self.args(args)?)),
            _ => Err(why(at, format!("calls `{name}`, a host function with no native form"))),
        }
    }

    fn method(&mut self, object: &Expr, name: &str, args: &[Expr], at: postc_ir::Span) -> R<Ir> {
        if self.agg_root(object) {
            match self.agg_read(object)? {
                Some(super::aggregates::Agg::Array(id)) if name == "join" => return self.join_aggregate(id, args, at),
                Some(super::aggregates::Agg::Array(_)) => {
                    return Err(why(at, format!("calls array method `.{name}()` where a value is needed")));
                }
                Some(super::aggregates::Agg::Object(_)) => {
                    return Err(why(at, format!("calls method `.{name}()` of an object")));
                }
                _ => {}
            }
        }
        if let ExprKind::Ident(o) = &object.kind {
            if let Some(slot) = self.array_slot(o) {
                return self.array_method(slot, o, name, at);
            }
            if name == "apply"
                && args.len() == 2
                && let Symbol::TopFn(i) = self.model.scopes.resolve(o, self.at)
            {
                self.reshaped = true;
                return self.apply(i, o, args, at);
            }
            if o == "Math" && self.is_host("Math") {
                return self.math(name, args, at);
            }
            if let Some(b) = self.binding(o) {
                return match (b, name, args.len()) {
                    (Binding::Var(var), "format", 1) => {
                        let v = self.expr(&args[0])?;
                        Ok(Ir::FormatVar { var, value: Box::new(to_number(v)), span: Some(at) })
                    }
                    (Binding::Var(var), "getLast", _) if args.iter().all(is_pure) => {
                        Ok(Ir::Binary(IrBin::Add, Box::new(Ir::Number(0.0)), Box::new(Ir::Var(var))))
                    }
                    (Binding::Format(format), "format", 1) => {
                        let v = self.expr(&args[0])?;
                        Ok(Ir::Format { format, value: Box::new(to_number(v)), span: Some(at) })
                    }
                    _ => Err(why(at, format!("calls `{o}.{name}()` with {} argument(s)", args.len()))),
                };
            }
        }
        let recv = self.expr(object)?;
        match (name, args.len()) {
            ("toUpperCase", 0) => Ok(Ir::Builtin(Builtin::Upper, vec![Ir::Builtin(Builtin::Str, vec![recv])])),
            ("toLowerCase", 0) => Ok(Ir::Builtin(Builtin::Lower, vec![Ir::Builtin(Builtin::Str, vec![recv])])),
            ("toFixed", 0 | 1) => {
                let d = match args.first() {
                    Some(a) => self.expr(a)?,
                    None => Ir::Number(0.0),
                };
                Ok(Ir::Builtin(Builtin::ToFixed, vec![recv, d]))
            }
            ("substring", 1 | 2) => {
                let mut a = vec![recv];
                a.extend(self.args(args)?);
                Ok(Ir::Builtin(Builtin::Substring, a))
            }
            _ => Err(why(at, format!("calls method `.{name}()`, which has no native form"))),
        }
    }

    /// The variable or format a global is bound to, if the name is that global.
    /// The output variable of `xOutput.reset`, when it is one made at
    /// compile time.
    pub(super) fn reset_of(&self, callee: &Expr) -> Option<postc_ir::VarId> {
        let ExprKind::Member { object, property } = &callee.kind else { return None };
        let ExprKind::Ident(o) = &object.kind else { return None };
        match self.binding(o) {
            Some(Binding::Var(var)) if property.name == "reset" => Some(var),
            _ => None,
        }
    }

    fn binding(&self, name: &str) -> Option<Binding> {
        match self.model.scopes.resolve(name, self.at) {
            Symbol::Global(g) => self.setup.bindings.get(&g).copied(),
            _ => None,
        }
    }

    fn math(&mut self, name: &str, args: &[Expr], at: postc_ir::Span) -> R<Ir> {
        let a = self.args(args)?;
        if name == "pow" && a.len() == 2 {
            let mut it = a.into_iter();
            let (Some(x), Some(y)) = (it.next(), it.next()) else { return Err(why(at, "`Math.pow`")) };
            return Ok(Ir::Binary(IrBin::Pow, Box::new(to_number(x)), Box::new(to_number(y))));
        }
        let (b, arity) = builtins::math(name)
            .filter(|_| !(matches!(name, "min" | "max") && a.is_empty()))
            .ok_or_else(|| why(at, format!("`Math.{name}`")))?;
        if a.len() < arity.unwrap_or(0) {
            return Err(why(at, format!("`Math.{name}` with too few arguments")));
        }
        Ok(Ir::Builtin(b, a.into_iter().map(to_number).collect()))
    }
}

fn is_pure(e: &Expr) -> bool {
    matches!(e.kind, ExprKind::Number(_) | ExprKind::String(_) | ExprKind::Ident(_))
}
