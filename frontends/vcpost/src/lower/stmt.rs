//! Lowering statements and Sub bodies: locals, declarations, assignments,
//! register properties, calls and `Out`; control flow is in `control`.

use postc_ir::{Body, Diagnostic, Expr as IrExpr, Function, LocalId, Stmt as IrStmt};

use super::{Lowerer, Scope};
use crate::ast::{DimItem, Name, ProcKind, Procedure, Stmt, StmtKind};
use crate::diagnostics as codes;
use crate::token::TYPE_NAMES;

impl Lowerer<'_> {
    /// Lowers a Sub or Function into its function slot.
    pub(super) fn proc(&mut self, p: &Procedure, index: usize) {
        let id = self.proc_ids[index];
        let mut scope = Scope::default();
        let mut prologue = Vec::new();
        for param in &p.params {
            self.check_type(param.ty.as_ref());
            if param.by_ref {
                self.diagnostics.push(
                    Diagnostic::warning(codes::BYREF, format!("`{}` is passed by value", param.name.text))
                        .at(param.name.span, "postc passes every argument by value")
                        .help("changes the Sub makes to this parameter are not seen by the caller; use a global variable to hand back a value"),
                );
            }
            self.declare_local(&mut scope, &param.name, false);
        }
        if p.kind == ProcKind::Function {
            let slot = self.declare_local(&mut scope, &p.name, false);
            scope.locals.remove(&p.name.key());
            scope.function = Some(p.name.key());
            scope.ret = Some(slot);
            prologue.push(IrStmt::Assign(postc_ir::Place::Local(slot), IrExpr::Number(0.0)));
        }
        let mut declared = Vec::new();
        super::walk::each_stmt(&p.body, &mut |s| match &s.kind {
            StmtKind::Dim(items) => declared.extend(items.iter().map(|i| (i.name.clone(), i.ty.clone(), false))),
            StmtKind::Const(items) => declared.extend(items.iter().map(|(n, _)| (n.clone(), None, true))),
            _ => {}
        });
        for (name, ty, constant) in declared {
            if scope.locals.contains_key(&name.key()) {
                self.diagnostics.push(
                    Diagnostic::warning(
                        codes::DECLARED_TWICE,
                        format!("`{}` is declared twice in `{}`", name.text, p.name.text),
                    )
                    .at(name.span, "declared again here"),
                );
                continue;
            }
            let slot = self.declare_local(&mut scope, &name, constant);
            if !constant {
                prologue.push(IrStmt::Assign(postc_ir::Place::Local(slot), default_value(ty.as_ref())));
            }
        }
        self.scope = Some(scope);
        self.loops.clear();
        let mut body = prologue;
        body.extend(self.block(&p.body));
        let scope = self.scope.take().unwrap_or_default();
        if let Some(ret) = scope.ret {
            body.push(IrStmt::Return(Some(IrExpr::Local(ret))));
        }
        if let Some(f) = self.post.functions.get_mut(id.index()) {
            *f = Function {
                name: p.name.text.clone(),
                params: p.params.iter().map(|f| f.name.text.clone()).collect(),
                slots: u16::try_from(scope.names.len()).unwrap_or(u16::MAX),
                // The function's own name names its result; `$` marks a hidden variable.
                locals: scope.names.iter().skip(p.params.len()).cloned().collect(),
                body: Body::Native(body),
                span: Some(p.header),
                why_script: None,
                source: Vec::new(),
                uses_arguments: false,
                starts_undefined: false,
            };
        }
    }

    fn declare_local(&mut self, scope: &mut Scope, name: &Name, constant: bool) -> LocalId {
        let key = name.key();
        if let Some((slot, _)) = scope.locals.get(&key) {
            self.diagnostics.push(
                Diagnostic::warning(codes::DECLARED_TWICE, format!("`{}` is declared twice", name.text))
                    .at(name.span, "declared again here"),
            );
            return *slot;
        }
        if self.registers.contains_key(&key) {
            self.diagnostics.push(
                Diagnostic::warning(
                    codes::DECLARED_TWICE,
                    format!("local `{}` hides the register of the same name", name.text),
                )
                .at(name.span, "inside this Sub the name means the local")
                .help(format!(
                    "`<{}>` in an Out string still prints the register; rename the local to avoid confusion",
                    name.text
                )),
            );
        }
        let slot = LocalId::new(u16::try_from(scope.names.len()).unwrap_or(u16::MAX));
        scope.names.push(name.text.clone());
        scope.locals.insert(key, (slot, constant));
        slot
    }

    fn check_type(&mut self, ty: Option<&Name>) {
        if let Some(ty) = ty
            && !TYPE_NAMES.iter().any(|t| ty.is(t))
        {
            self.diagnostics.push(
                Diagnostic::error(codes::UNSUPPORTED, format!("`{}` is not a type VcPost knows", ty.text))
                    .at(ty.span, "unknown type")
                    .help(format!("types are {}", TYPE_NAMES.join(", "))),
            );
        }
    }

    pub(super) fn block(&mut self, stmts: &[Stmt]) -> Vec<IrStmt> {
        stmts.iter().flat_map(|s| self.stmt(s)).collect()
    }

    /// Lowers one statement (to none, one or several IR statements).
    pub(super) fn stmt(&mut self, s: &Stmt) -> Vec<IrStmt> {
        match &s.kind {
            StmtKind::Assign { target, value } => {
                let value = self.expr_checked(value);
                self.place(target).map(|p| IrStmt::Assign(p, value)).into_iter().collect()
            }
            StmtKind::SetProperty { register, property, value } => {
                self.set_property(register, property, value);
                Vec::new()
            }
            StmtKind::Dim(items) => items.iter().flat_map(|i| self.dim(i)).collect(),
            StmtKind::Const(items) => items.iter().flat_map(|(n, v)| self.constant(n, v)).collect(),
            StmtKind::Call { name, args } => self.call_stmt(name, args, s.span).into_iter().collect(),
            StmtKind::Out(e) => vec![self.out_line(e.as_ref(), s.span)],
            StmtKind::Exit(kind) => self.exit(*kind, s).into_iter().collect(),
            StmtKind::If { branches, otherwise } => {
                let branches = branches.iter().map(|(c, b)| (self.expr_checked(c), self.block(b))).collect();
                vec![IrStmt::If { branches, otherwise: self.block(otherwise) }]
            }
            StmtKind::Select { subject, cases, otherwise } => self.select(subject, cases, otherwise),
            StmtKind::For(f) => self.for_loop(f, s),
            StmtKind::Loop { test, at_end, body, kind } => self.loop_stmt(test.as_ref(), *at_end, body, *kind, s),
            StmtKind::Error => Vec::new(),
        }
    }

    fn set_property(&mut self, register: &Name, property: &Name, value: &crate::ast::Expr) {
        if self.scope.is_some() {
            self.diagnostics.push(
                Diagnostic::error(
                    codes::PROPERTY_IN_SUB,
                    format!("`{}.{}` is set inside a Sub", register.text, property.text),
                )
                .at(register.span.to(value.span), "register properties are fixed when the post is compiled")
                .help("set register properties at the top of the file, outside every Sub"),
            );
            return;
        }
        if register.is(super::options::OPTIONS) {
            self.postc_option(property, value);
            return;
        }
        let Some(var) = self.register_var(&register.text) else { return };
        let Some(spec) = self.specs.get_mut(var.index()) else { return };
        if let Err(d) = crate::registers::apply(spec, property, value, &mut self.post.options.block_numbers) {
            self.diagnostics.push(d);
        }
    }

    fn dim(&mut self, item: &DimItem) -> Vec<IrStmt> {
        if let Some(at) = item.array {
            self.diagnostics.push(
                Diagnostic::error(
                    codes::UNSUPPORTED,
                    format!("`{}` is declared as an array; VcPost in postc has no arrays", item.name.text),
                )
                .at(at, "array bounds")
                .help("use separate variables (`P1`, `P2`, ...)"),
            );
        }
        self.check_type(item.ty.as_ref());
        let key = item.name.key();
        let place = if self.scope.is_some() {
            self.place(&item.name)
        } else if self.registers.contains_key(&key) {
            None
        } else {
            if let Some(g) = self.globals.get_mut(&key) {
                if g.declared {
                    self.diagnostics.push(
                        Diagnostic::warning(codes::DECLARED_TWICE, format!("`{}` is declared twice", item.name.text))
                            .at(item.name.span, "declared again here"),
                    );
                }
                g.declared = true;
                let index = g.index.index();
                if let (Some(ty), Some(global)) = (&item.ty, self.post.globals.get_mut(index)) {
                    global.initial = default_value(Some(ty));
                }
            }
            let index = self.new_global(&item.name.text, Some(default_value(item.ty.as_ref())), false, true);
            Some(postc_ir::Place::Global(index))
        };
        match (&item.init, place) {
            (Some(init), Some(place)) => vec![IrStmt::Assign(place, self.expr_checked(init))],
            _ => Vec::new(),
        }
    }

    fn constant(&mut self, name: &Name, value: &crate::ast::Expr) -> Vec<IrStmt> {
        let lowered = self.expr_checked(value);
        if let Some(scope) = &self.scope {
            return match scope.locals.get(&name.key()) {
                Some((slot, _)) => vec![IrStmt::Assign(postc_ir::Place::Local(*slot), lowered)],
                None => Vec::new(),
            };
        }
        if self.globals.contains_key(&name.key()) || self.registers.contains_key(&name.key()) {
            self.diagnostics.push(
                Diagnostic::warning(codes::DECLARED_TWICE, format!("`{}` is already a variable", name.text))
                    .at(name.span, "this `Const` is ignored"),
            );
            return Vec::new();
        }
        let literal = matches!(lowered, IrExpr::Number(_) | IrExpr::Text(_) | IrExpr::Bool(_));
        let index = self.new_global(&name.text, literal.then(|| lowered.clone()), true, true);
        if literal { Vec::new() } else { vec![IrStmt::Assign(postc_ir::Place::Global(index), lowered)] }
    }
}
/// The starting value of a declared variable of a type.
fn default_value(ty: Option<&Name>) -> IrExpr {
    match ty {
        Some(t) if t.is("String") => IrExpr::Text(String::new()),
        Some(t) if t.is("Boolean") => IrExpr::Bool(false),
        _ => IrExpr::Number(0.0),
    }
}
