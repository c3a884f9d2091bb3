//! Lints of the lowering: names the post uses that nothing defines,
//! function names assigned to, a post without `onLinear`, and a check that
//! the Rhai script made from the post compiles (a failure there is a bug
//! in postc, reported at the function it came from).

use postc_ir::codes;
use std::collections::HashSet;

use postc_ir::{Diagnostic, Script, Span};

use crate::ast::*;

use super::builtins;
use super::model::Model;
use super::scope::{Symbol, Visit, walk_stmts};
use super::setup::Setup;

/// Reports names nothing defines and assignments to function names.
pub fn check(program: &Program, model: &Model, setup: &Setup, diags: &mut Vec<Diagnostic>) {
    let mut seen = HashSet::new();
    let mut v = Names { model, at: 0, seen: &mut seen, diags: &mut *diags };
    walk_stmts(&program.body, &mut v);
    for id in 1..model.scopes.funcs.len() {
        if let Some(f) = model.scopes.funcs[id].func {
            let mut v = Names { model, at: id, seen: &mut seen, diags: &mut *diags };
            walk_stmts(&f.body, &mut v);
        }
    }
    let _ = setup;
    if !model.scopes.top_fn_names.contains_key("onLinear") {
        diags.push(
            Diagnostic::warning(codes::JS105, "this post has no `onLinear` function, so moves print nothing")
                .at(Span::new(program.span.file, 0, 0), "in this post")
                .help(
                    "CNC-Calc posts define onLinear(vx, vy, vz, movement) (or onLinear(vx, vz, movement) for lathes)",
                ),
        );
    }
}

struct Names<'m, 'a, 'd> {
    model: &'m Model<'a>,
    at: usize,
    seen: &'d mut HashSet<String>,
    diags: &'d mut Vec<Diagnostic>,
}

impl<'a> Visit<'a> for Names<'_, 'a, '_> {
    fn expr(&mut self, e: &'a Expr) -> bool {
        match &e.kind {
            ExprKind::Ident(name) => {
                if let Symbol::Global(g) = self.model.scopes.resolve(name, self.at)
                    && self.model.global(&g).is_none()
                    && !self.model.flattened.contains(&g)
                    && !builtins::knows(&g)
                    && self.seen.insert(g.clone())
                {
                    self.diags.push(
                        Diagnostic::warning(
                            codes::JS102,
                            format!("`{g}` is not defined in this post, and postc's host does not provide it"),
                        )
                        .at(e.span, "not defined")
                        .note("using it stops the post with an error when this line runs"),
                    );
                }
            }
            ExprKind::Assign { target, .. } | ExprKind::Update { target, .. } => {
                if let ExprKind::Ident(name) = &target.kind
                    && let Symbol::TopFn(_) = self.model.scopes.resolve(name, self.at)
                {
                    self.diags.push(
                        Diagnostic::error(
                            codes::JS106,
                            format!("`{name}` is a function; postc does not let a post assign to a function's name"),
                        )
                        .at(target.span, "assigned here")
                        .help("keep the function in a variable of its own: `var handler = name;`"),
                    );
                }
            }
            ExprKind::Unary { op: UnaryOp::Typeof, operand } if matches!(operand.kind, ExprKind::Ident(_)) => {
                return false;
            }
            ExprKind::Function(f) => {
                if let Some(id) = self.model.scopes.id_of(f) {
                    let at = self.at;
                    self.at = id;
                    walk_stmts(&f.body, self);
                    self.at = at;
                }
                return false;
            }
            _ => {}
        }
        true
    }

    fn function_decl(&mut self, _f: &'a Function) {}
}

/// Compiles the script as the runtime will; a failure is a postc bug,
/// reported where the script went wrong in the post.
pub fn check_script(script: &Script, whole: Span) -> Option<Diagnostic> {
    let mut engine = rhai::Engine::new_raw();
    engine.set_max_expr_depths(MAX_EXPR_DEPTH, MAX_EXPR_DEPTH);
    let err = engine.compile(&script.source).err()?;
    let pos = err.position();
    let offset = line_col_offset(&script.source, pos.line().unwrap_or(1), pos.position().unwrap_or(1));
    let js =
        script.span_map.iter().rev().find(|(r, _)| *r as usize <= offset).map_or(whole.start, |(_, j)| *j as usize);
    Some(
        Diagnostic::error(
            codes::JS100,
            format!("postc could not turn this part of the post into a script: {}", err.err_type()),
        )
        .at(Span::new(whole.file, js, js + 1), "here")
        .note("this is a bug in postc; please report it with the post"),
    )
}

/// How deeply expressions of the script may nest (the runtime uses the same).
pub const MAX_EXPR_DEPTH: usize = 256;

fn line_col_offset(text: &str, line: usize, col: usize) -> usize {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    (start + col.saturating_sub(1)).min(text.len())
}
