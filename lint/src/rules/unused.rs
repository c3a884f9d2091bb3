//! LN007–LN009 and LN016: variables, formats, functions and VcPost Subs a
//! post defines and never uses. Each is dead text a reader of the post must still understand, and
//! often a sign of a typo (a `VAR` declared for a label no section prints,
//! a `createFormat` meant for a variable that got another).
//!
//! Uses are counted in the IR code and, for CIMCO posts, in the script the
//! functions that do not lower to native code run as (they name variables
//! and formats by index and post functions by their script name). VcPost
//! registers are left alone: the applications that call a post set them by
//! name. A VcPost Sub is used when a statement calls it, when it handles an
//! event (an APT word or composites routine: its handler calls it), or when
//! a keyword comment or tip offers it to the tables and option cards that
//! call Subs by name (Vericut's post-processor notes: those comments make a Sub's name appear in
//! the applications' choice lists).

use postc_ir::codes;
use std::collections::BTreeSet;

use postc_ir::visit::{Visit, walk_expr, walk_piece, walk_stmt};
use postc_ir::{Diagnostic, Dialect, Expr, OutputRef, Piece, Place, Script, Stmt};

use crate::{Context, Options, Rule};

pub const VARIABLE: Rule = Rule { code: codes::LN007.code, name: "unused-variable", check: variables };
pub const FORMAT: Rule = Rule { code: codes::LN008.code, name: "unused-format", check: formats };
pub const FUNCTION: Rule = Rule { code: codes::LN009.code, name: "unused-function", check: functions };
pub const SUB: Rule = Rule { code: codes::LN016.code, name: "unused-sub", check: subs };

/// What the post's code refers to.
#[derive(Default)]
struct Uses {
    vars: BTreeSet<usize>,
    formats: BTreeSet<usize>,
    functions: BTreeSet<usize>,
}

impl Visit for Uses {
    fn visit_stmt(&mut self, stmt: &Stmt) {
        match stmt {
            Stmt::Assign(Place::Var(v), _) | Stmt::Forget(v) => {
                self.vars.insert(v.index());
            }
            _ => {}
        }
        walk_stmt(self, stmt);
    }

    fn visit_piece(&mut self, piece: &Piece) {
        if let Piece::Var(v) = piece {
            self.vars.insert(v.index());
        }
        walk_piece(self, piece);
    }

    fn visit_expr(&mut self, e: &Expr) {
        match e {
            Expr::Var(v) | Expr::Previous(v) | Expr::FormatVar { var: v, .. } => {
                self.vars.insert(v.index());
            }
            Expr::Format { format, .. } | Expr::Output(OutputRef::Format(format)) => {
                self.formats.insert(format.index());
            }
            Expr::Output(OutputRef::Variable(v)) => {
                self.vars.insert(v.index());
            }
            // A function made a value (handed to `filter`, kept in an
            // object) is used as much as one called by name.
            Expr::Call(f, _) | Expr::Closure { function: f, .. } => {
                self.functions.insert(f.index());
            }
            _ => {}
        }
        walk_expr(self, e);
    }
}

fn uses(cx: &Context) -> Uses {
    let mut u = Uses::default();
    u.visit_post(cx.post);
    for v in &cx.post.variables {
        u.formats.insert(v.format.index());
    }
    for s in &cx.post.scripts {
        for (prefixes, set) in
            [(&["__vref(", "__vfmt(", "__vlast("][..], &mut u.vars), (&["__fref(", "__ffmt("][..], &mut u.formats)]
        {
            for p in prefixes {
                for (i, _) in s.source.match_indices(p) {
                    let digits: String = s.source[i + p.len()..].chars().take_while(char::is_ascii_digit).collect();
                    if let Ok(n) = digits.parse() {
                        set.insert(n);
                    }
                }
            }
        }
    }
    u
}

fn variables(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if cx.post.info.dialect == Dialect::VcPost {
        return;
    }
    let used = uses(cx);
    for (i, v) in cx.post.variables.iter().enumerate() {
        let Some(span) = v.span else { continue };
        if used.vars.contains(&i) || v.name.starts_with("__postc") || is_template_var(v) {
            continue;
        }
        out.push(
            Diagnostic::warning(VARIABLE.code, format!("`{}` is declared and never printed", v.name))
                .at(span, "declared here")
                .help("remove it, or print it where it belongs"),
        );
    }
}

fn formats(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if cx.post.info.dialect == Dialect::VcPost {
        return;
    }
    let used = uses(cx);
    for (i, f) in cx.post.formats.iter().enumerate() {
        let Some(span) = f.span else { continue };
        if used.formats.contains(&i) {
            continue;
        }
        out.push(
            Diagnostic::warning(FORMAT.code, "this format is created and never used")
                .at(span, "created here")
                .help("remove it, or format a value with it"),
        );
    }
}

fn functions(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if cx.post.info.dialect != Dialect::Cimco {
        return;
    }
    let used = uses(cx);
    let scripts: Vec<&str> = cx.post.scripts.iter().map(|s| s.source.as_str()).collect();
    for (i, f) in cx.post.functions.iter().enumerate() {
        let Some(span) = f.span else { continue };
        // The frontend's forms of a function that reads `arguments`
        // (`writeBlock/5`) are the function: a call of one uses it.
        if f.name.contains('/') {
            continue;
        }
        let called =
            |j: &usize| cx.post.functions.get(*j).is_some_and(|g| g.name.split('/').next() == Some(f.name.as_str()));
        if used.functions.contains(&i)
            || used.functions.iter().any(called)
            || is_entry_point(&f.name)
            || called_by_script(&scripts, &f.name)
        {
            continue;
        }
        out.push(
            Diagnostic::warning(FUNCTION.code, format!("function `{}` is never called", f.name))
                .at(span, "defined here")
                .help("remove it, or call it; CNC-Calc calls only its entry points (onOpen, onLinear, ...)"),
        );
    }
}

fn subs(cx: &Context, _: &Options, out: &mut Vec<Diagnostic>) {
    if cx.post.info.dialect != Dialect::VcPost {
        return;
    }
    let used = uses(cx);
    for (i, f) in cx.post.functions.iter().enumerate() {
        // Functions the frontend makes (composites list readers) have no place in the post.
        let Some(span) = f.span else { continue };
        let offered = cx.post.info.subs.iter().any(|s| s.name.eq_ignore_ascii_case(&f.name));
        // Under sections (postc's extension) a Sub named after a section is its handler.
        let section = postc_ir::post::Section::from_name(&f.name)
            .is_some_and(|s| cx.post.handlers.iter().any(|h| h.key == postc_ir::HandlerKey::Section(s)));
        if used.functions.contains(&i) || offered || section {
            continue;
        }
        out.push(
            Diagnostic::warning(SUB.code, format!("`{}` is never called", f.name))
                .at(span, "defined here")
                .note("no statement calls it, no event is named after it, and no keyword comment offers it to a table")
                .help("if a probe table or option card calls it by name, add its keyword comment (`' #Option`, `' #Cycle`, `' #Probe`, ...) after the `Sub` line; otherwise call it or remove it"),
        );
    }
}

/// A Vectric `VAR` under its standard name: the guides' template declares
/// every variable whether the post prints it or not, so an unused one is
/// the template, not a mistake. A `VAR` under a name of the post's own
/// that nothing prints is.
fn is_template_var(v: &postc_ir::Variable) -> bool {
    let postc_ir::ValueSource::Quantity(q) = v.source else { return false };
    // Also in a section post converted from Vectric (CIMCO, docs/cimco.md).
    postc_front_vectric::names::var_name_of_label(q.label()).is_some_and(|n| n.eq_ignore_ascii_case(&v.name))
}

/// Names CNC-Calc calls, and postc's own.
fn is_entry_point(name: &str) -> bool {
    name.starts_with("on") || name.starts_with("__postc") || name == "getFeedrate"
}

/// Whether a script calls the function by its script name (and does not
/// only define it).
fn called_by_script(scripts: &[&str], name: &str) -> bool {
    let rhai = Script::function_name(name);
    scripts.iter().any(|s| {
        s.match_indices(rhai.as_str()).any(|(i, _)| {
            let after = s[i + rhai.len()..].chars().next();
            let before = s[..i].trim_end();
            after == Some('(') && !before.ends_with("fn")
                || after.is_some_and(|c| !(c.is_ascii_alphanumeric() || c == '_')) && !before.ends_with("fn")
        })
    })
}
