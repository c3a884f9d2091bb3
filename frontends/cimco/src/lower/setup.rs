//! `createFormat` and `createVariable` calls that the compiler can run:
//! those that assign a global, at the top of the post or at the top of
//! `onInit`, from arguments known at compile time. Each becomes an IR
//! [`NumberFormat`] or [`Variable`], and the global is bound to it, so that
//! `xOutput.format(x)` lowers to one IR expression that formats straight
//! into the output. Other calls run when the post runs, in the script host.

use postc_ir::codes;
use std::collections::{HashMap, HashSet};

use postc_ir::{
    Diagnostic, FormatId, Modality, NumberFormat, Padding, PointStyle, SignStyle, ValueSource, VarId, Variable, WidthOf,
};

use crate::ast::*;

use super::consts::{Const, const_eval};
use super::model::Model;
use super::scope::{Symbol, Visit, walk_stmt};

/// What a global is bound to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binding {
    Format(FormatId),
    Var(VarId),
}

/// Formats, variables and the globals bound to them.
#[derive(Default)]
pub struct Setup {
    pub formats: Vec<NumberFormat>,
    pub variables: Vec<Variable>,
    pub bindings: HashMap<String, Binding>,
    /// Statements (by span start) the compiler ran; they are left out of
    /// the code that runs.
    pub done: HashSet<usize>,
}

/// The `createFormat` properties.
const FORMAT_KEYS: &[&str] = &["prefix", "width", "zeropad", "decimals", "scale", "forceDecimal", "forceSign"];
/// The `createVariable` properties.
const VARIABLE_KEYS: &[&str] = &["prefix", "force"];

impl Setup {
    pub fn build(program: &Program, model: &Model, diags: &mut Vec<Diagnostic>) -> Setup {
        let mut s = Setup::default();
        let mark = decimal_mark(model);
        let no_locals = HashMap::new();
        for stmt in &program.body {
            s.statement(stmt, model, &no_locals, mark, diags);
        }
        if let Some(&i) = model.scopes.top_fn_names.get("onInit")
            && let Some(f) = model.scopes.funcs[model.scopes.top_fns[i]].func
        {
            let id = model.scopes.top_fns[i];
            let mut env: HashMap<String, Const> = HashMap::new();
            for stmt in &f.body {
                match &stmt.kind {
                    StmtKind::Var(ds) => {
                        for d in ds {
                            let v = d.init.as_ref().and_then(|e| eval(e, model, &env, id));
                            match v {
                                Some(c) => env.insert(d.name.name.clone(), c),
                                None => env.remove(&d.name.name),
                            };
                        }
                    }
                    StmtKind::Expr(e) => {
                        if let ExprKind::Assign { op: AssignOp::Assign, target, value } = &e.kind
                            && let ExprKind::Ident(name) = &target.kind
                            && let Symbol::Local { .. } = model.scopes.resolve(name, id)
                        {
                            match eval(value, model, &env, id) {
                                Some(c) => env.insert(name.clone(), c),
                                None => env.remove(name),
                            };
                            continue;
                        }
                        s.statement(stmt, model, &env, mark, diags);
                        forget_assigned(stmt, &mut env);
                    }
                    _ => forget_assigned(stmt, &mut env),
                }
            }
        }
        s
    }

    /// Runs `G = createFormat(...)` / `G = createVariable(...)` (or `var G = ...`).
    fn statement(
        &mut self,
        stmt: &Stmt,
        model: &Model,
        env: &HashMap<String, Const>,
        mark: char,
        diags: &mut Vec<Diagnostic>,
    ) {
        let (name, value) = match &stmt.kind {
            StmtKind::Var(ds) if ds.len() == 1 => match &ds[0].init {
                Some(init) => (ds[0].name.name.as_str(), init),
                None => return,
            },
            StmtKind::Expr(e) => match &e.kind {
                ExprKind::Assign { op: AssignOp::Assign, target, value } => match &target.kind {
                    ExprKind::Ident(n) => (n.as_str(), &**value),
                    _ => return,
                },
                _ => return,
            },
            _ => return,
        };
        if model.global(name).is_none_or(|g| g.assignments != 1) || self.bindings.contains_key(name) {
            return;
        }
        let at = model.scopes.top_fn_names.get("onInit").map_or(0, |&i| model.scopes.top_fns[i]);
        if let Some(b) = self.create(value, model, env, at, mark, name, diags) {
            if let Binding::Format(id) = b
                && let Some(f) = self.formats.get_mut(id.index())
            {
                f.name = Some(name.to_string());
            }
            self.bindings.insert(name.to_string(), b);
            self.done.insert(stmt.span.start);
        }
    }

    /// A `createFormat(...)` or `createVariable(...)` call with known arguments.
    #[allow(clippy::too_many_arguments)]
    fn create(
        &mut self,
        e: &Expr,
        model: &Model,
        env: &HashMap<String, Const>,
        at: usize,
        mark: char,
        name: &str,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<Binding> {
        let ExprKind::Call { callee, args } = &e.kind else { return None };
        let ExprKind::Ident(f) = &callee.kind else { return None };
        if !matches!(model.scopes.resolve(f, at), Symbol::Global(_)) || model.global(f).is_some() {
            return None;
        }
        match f.as_str() {
            "createFormat" => {
                let props = props(args.first(), model, env, at, FORMAT_KEYS, "createFormat", diags)?;
                let format = number_format(&props, mark, args.first().map_or(e.span, |a| a.span), diags);
                self.formats.push(format);
                Some(Binding::Format(FormatId::new((self.formats.len() - 1) as u16)))
            }
            "createVariable" => {
                let vprops = props(args.first(), model, env, at, VARIABLE_KEYS, "createVariable", diags)?;
                let format = match args.get(1).map(|a| &a.kind) {
                    Some(ExprKind::Ident(fname)) => match self.bindings.get(fname.as_str()) {
                        Some(Binding::Format(id)) => *id,
                        _ => return None,
                    },
                    Some(ExprKind::Call { .. }) => match self.create(&args[1], model, env, at, mark, name, diags)? {
                        Binding::Format(id) => id,
                        Binding::Var(_) => return None,
                    },
                    None => {
                        self.formats.push(number_format(&[], mark, e.span, diags));
                        FormatId::new((self.formats.len() - 1) as u16)
                    }
                    _ => return None,
                };
                let get = |k: &str| vprops.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone());
                let prefix = get("prefix").map(|p| p.text()).unwrap_or_default();
                let force = get("force").is_some_and(|f| f.truthy());
                self.variables.push(Variable {
                    name: name.to_string(),
                    source: ValueSource::Assigned,
                    prefix: prefix.into_bytes(),
                    format,
                    modality: if force { Modality::Always } else { Modality::OnChange },
                    span: Some(e.span),
                });
                Some(Binding::Var(VarId::new((self.variables.len() - 1) as u16)))
            }
            _ => None,
        }
    }
}

/// The decimal mark the post asks for.
pub fn decimal_mark(model: &Model) -> char {
    match model.setting("decimalMark") {
        Some(Const::Str(s)) if s == "," => ',',
        _ => '.',
    }
}

fn eval(e: &Expr, model: &Model, env: &HashMap<String, Const>, at: usize) -> Option<Const> {
    const_eval(
        e,
        &|name| match model.scopes.resolve(name, at) {
            Symbol::Local { .. } => env.get(name).cloned(),
            Symbol::Global(g) => {
                if model.global(&g).is_some() {
                    model.constant(&g).cloned()
                } else {
                    super::builtins::constant(&g)
                }
            }
            Symbol::TopFn(_) => None,
        },
        &|e| model.flattened_name(e),
    )
}

/// The properties of an object literal argument, all known.
fn props(
    arg: Option<&Expr>,
    model: &Model,
    env: &HashMap<String, Const>,
    at: usize,
    keys: &[&str],
    what: &str,
    diags: &mut Vec<Diagnostic>,
) -> Option<Vec<(String, Const)>> {
    let Some(arg) = arg else { return Some(Vec::new()) };
    let ExprKind::Object(props) = &arg.kind else { return None };
    let mut out = Vec::new();
    for p in props {
        let v = eval(&p.value, model, env, at)?;
        if !keys.contains(&p.key.name.as_str()) {
            diags.push(
                Diagnostic::warning(
                    codes::JS101,
                    format!("`{}` is not a property of {what}; it is ignored", p.key.name),
                )
                .at(p.key.span, "unknown property")
                .help(format!("{what} knows {}", keys.join(", "))),
            );
        }
        out.push((p.key.name.clone(), v));
    }
    Some(out)
}

/// The IR format of `createFormat` properties (see docs/cimco.md).
fn number_format(
    props: &[(String, Const)],
    mark: char,
    span: postc_ir::Span,
    diags: &mut Vec<Diagnostic>,
) -> NumberFormat {
    let get = |k: &str| props.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone());
    let mut decimals = get("decimals").map(|d| d.num()).unwrap_or(0.0);
    if !decimals.is_finite() || decimals < 0.0 {
        decimals = 0.0;
    }
    if decimals > 15.0 {
        diags.push(
            Diagnostic::warning(codes::JS104, "a format prints at most 15 decimals")
                .at(span, "more decimals than that"),
        );
        decimals = 15.0;
    }
    let width = get("width").map(|w| w.num()).unwrap_or(0.0);
    let width = if width.is_finite() { width.clamp(0.0, 64.0) as u8 } else { 0 };
    let force_decimal = get("forceDecimal").is_some_and(|f| f.truthy());
    let scale = get("scale").map(|s| s.num()).unwrap_or(1.0);
    NumberFormat {
        decimals: decimals as u8,
        width,
        width_of: WidthOf::IntegerDigits,
        padding: if get("zeropad").is_some_and(|z| z.truthy()) { Padding::Zero } else { Padding::Space },
        justify: postc_ir::Justify::Right,
        sign: if get("forceSign").is_some_and(|f| f.truthy()) { SignStyle::Always } else { SignStyle::Negative },
        point: if force_decimal { PointStyle::Always } else { PointStyle::WithDecimals },
        trim_zeros: !force_decimal,
        leading_zero: true,
        decimal_mark: mark,
        multiplier: if scale.is_finite() { scale } else { 1.0 },
        prefix: get("prefix").map(|p| p.text()).unwrap_or_default(),
        // A post is JavaScript: numbers round as its engine rounds them.
        rounding: postc_ir::Rounding::Binary,
        negative_zero: false,
        span: Some(span),
        name: None,
    }
}

/// Forgets the locals a statement assigns.
fn forget_assigned(stmt: &Stmt, env: &mut HashMap<String, Const>) {
    struct Forget<'e>(&'e mut HashMap<String, Const>);
    impl<'a> Visit<'a> for Forget<'_> {
        fn stmt(&mut self, s: &'a Stmt) -> bool {
            match &s.kind {
                StmtKind::Var(ds) => ds.iter().for_each(|d| {
                    self.0.remove(&d.name.name);
                }),
                StmtKind::ForIn { name, .. } => {
                    self.0.remove(&name.name);
                }
                _ => {}
            }
            true
        }
        fn expr(&mut self, e: &'a Expr) -> bool {
            if let ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } = &e.kind
                && let ExprKind::Ident(n) = &target.kind
            {
                self.0.remove(n);
            }
            true
        }
        fn function_decl(&mut self, _f: &'a Function) {}
    }
    walk_stmt(stmt, &mut Forget(env));
}
