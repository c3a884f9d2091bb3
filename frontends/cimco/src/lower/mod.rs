//! Lowering: a parsed CIMCO post to the IR.
//!
//! 1. [`model`]: the globals (bare, and the `globals = {...}` and
//!    `PostInfo = {...}` objects flattened), constants, and which globals
//!    can hold objects;
//! 2. [`setup`]: `createFormat` / `createVariable` calls run at compile
//!    time into IR formats and output variables;
//! 3. [`native`]: each function as native IR, when it only formats,
//!    compares, computes and concatenates; [`rhai`]: every function (and
//!    postc's glue) as Rhai, for the ones that are not native and for
//!    scripts calling each other;
//!    When any function would be a script, [`general`] lowers the whole
//!    post again with JavaScript's values in the IR (objects, arrays,
//!    closures, `undefined`), and that replaces the shaped form when every
//!    function has a general form;
//! 4. [`handlers`]: the sections the post's entry points occupy, each a
//!    call of its entry point (`Write(onLinear(x, y, z, 1))`); [`fold`]:
//!    constant folding of what the settings make known.
//!
//! The IR says what the post means; how the runtime runs it fast (the
//! entry point's text built straight in the output) is the runtime's
//! preparation, not the lowering's.
//!
//! `docs/cimco.md` describes the host semantics this implements.

pub mod builtins;
mod consts;
mod fold;
pub(crate) mod fusion;
mod general;
mod handlers;
mod layout;
mod model;
mod native;
mod rhai;
pub(crate) mod scope;
mod setup;
mod warn;

use crate::host_names as names;
use postc_ir::codes;
use std::collections::HashMap;
use std::path::Path;

use postc_ir::{
    Body, CommentTarget, Diagnostic, Dialect, Expr, FormatId, Function, FunctionId, LocalId, Modality, NumberFormat,
    Post, Quantity, Script, ScriptId, ScriptLanguage, SourceMap, SourceText, Span, Stmt, ValueSource, VarId, Variable,
};

use crate::ast::{self, AssignOp, ExprKind, Ident, Program, StmtKind};

use consts::Const;
use layout::Layout;
use model::Model;
pub use native::to_number;
use setup::Setup;

/// Compiles a CIMCO post: the IR and every diagnostic, sorted by position.
pub fn compile(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<Diagnostic>) {
    let text = String::from_utf8_lossy(bytes).into_owned();
    let file = sources.add(path.display().to_string(), text);
    let text = sources.text(file).unwrap_or_default();
    let (program, mut diagnostics) = crate::parse(text, file);
    let mut post = Post::default();
    post.info.dialect = Dialect::Cimco;
    post.info.source = path.display().to_string();
    post.info.name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    post.info.file_extension = "nc".into();
    if !postc_ir::diagnostic::has_errors(&diagnostics) {
        // A section post (postc's extension for converted Vectric posts) has a lowering of its own.
        if crate::sections::is_section_post(&program) {
            crate::sections::lower(&program, text, &mut post, &mut diagnostics);
        } else {
            lower(&program, text, Span::new(file, 0, text.len()), &mut post, &mut diagnostics);
        }
    }
    diagnostics.sort_by_key(|d| d.primary_span().map(|s| (s.start, s.end)));
    (post, diagnostics)
}

/// Lowers a program without errors into `post`, in phases: the post's
/// settings, its formats and variables ([`feed_variables`]), its functions
/// as native IR where they can be ([`functions`]), the Rhai script of the
/// rest ([`script`]), and the handlers with their fast path ([`handlers`]).
fn lower(program: &Program, text: &str, whole: Span, post: &mut Post, diags: &mut Vec<Diagnostic>) {
    let model = Model::build(program);
    let setup = Setup::build(program, &model, diags);
    warn::check(program, &model, &setup, diags);
    let mut layout = Layout::new(&model);
    let arity = |name: &str| top_fn(&model, name).map(|f| f.params.len());
    settings(&model, post, diags);
    post.options.lathe = is_lathe(&model, arity("onLinear"));
    // The CNC-Calc Post Processor Manual: a variable without force "will only be written if it has
    // changed since the last time it was used" -- a toolpath start does not
    // make it forget (a post that wants that calls `reset()`).
    post.options.forget_modal_at_toolpath_start = false;
    // Text is JavaScript's: `"a" + null` is "anull".
    post.options.js_text = true;
    let feed = feed_variables(&model, &setup, post);

    // postc's functions after the post's own.
    let own_feedrate = top_fn(&model, layout::FEEDRATE).is_some();
    if !own_feedrate {
        layout.add_fn(layout::FEEDRATE);
    }
    let init_fn = layout.add_fn(layout::INIT);
    for g in GLUE {
        layout.add_fn(g.0);
    }
    // The forms of functions that read `arguments`, one per number of
    // arguments they are called with.
    for (id, n) in native::variadic::arities(&model, program) {
        let name = model.scopes.funcs[id].name.clone().unwrap_or_default();
        let f = layout.add_fn(&crate::made::specialization(&name, n));
        layout.variadic.insert((id, n), f);
        layout.clones.push((id, n));
    }
    let init_stmts = init_statements(program, &model, &setup);
    let mut functions =
        self::functions(&model, &setup, &mut layout, whole, &init_stmts, (!own_feedrate).then_some(feed));
    keep_source(program, &model, &setup, &layout, text, &mut functions);
    let script = self::script(&model, &setup, &layout, whole, &init_stmts, own_feedrate);
    if let Some(d) = warn::check_script(&script, whole) {
        diags.push(d);
    }
    post.handlers = handlers(&model, &layout, post.options.lathe, &functions);
    post.init = vec![Stmt::Eval(Expr::Call(init_fn, vec![]))];
    if let (Some(_), Some(f)) = (arity("onInit"), layout.function("onInit")) {
        post.init.push(Stmt::Eval(Expr::Call(f, vec![])));
    }
    let mut uses_script = functions.iter().any(|f| matches!(f.body, Body::Script(_)));
    let shaped_script =
        functions.iter().any(|f| matches!(f.body, Body::Script(_)) && !GLUE.iter().any(|g| g.0 == f.name));
    let general =
        if shaped_script { Some(general_post(&model, &setup, whole, &init_stmts, own_feedrate, feed)) } else { None };
    if let Some(Err(w)) = &general {
        // `postc inspect` says why the post keeps its scripts.
        for f in functions.iter_mut() {
            if let Some(r) = &mut f.why_script {
                r.what = format!("{}; the post has no general form: {}", r.what, w.what);
            }
        }
    }
    if let Some(Ok((general, general_layout))) = general {
        // Every function has a general form. Where the shaped form of a
        // function is native and takes and returns plain values, it stays
        // (it runs faster); the others take their general form. A shaped
        // function that hands an object back through hidden globals
        // (`native::aggregates`) has callers that expect that, so then the
        // whole post takes the general form.
        let returns_aggregate = layout.returns.values().any(|r| r.is_ok());
        if returns_aggregate {
            functions = general;
            layout = general_layout;
        } else {
            functions = mixed(&model, functions, general);
        }
        layout.reshaped.extend(model.scopes.top_fns.iter().copied());
        keep_source(program, &model, &setup, &layout, text, &mut functions);
        post.handlers = handlers(&model, &layout, post.options.lathe, &functions);
        post.init = vec![Stmt::Eval(Expr::Call(init_fn, vec![]))];
        if let (Some(_), Some(f)) = (arity("onInit"), layout.function("onInit")) {
            post.init.push(Stmt::Eval(Expr::Call(f, vec![])));
        }
        uses_script = false;
    }
    post.functions = functions;
    post.globals = layout.globals;
    if uses_script {
        post.scripts = vec![script];
    } else {
        // No function runs as a script: drop the script bodies of the glue.
        post.scripts.clear();
    }
    comments(program, text, post);
}

/// The post lowered whole by [`general`]: its functions (in the order of
/// the layout it returns) or why it has no such form.
fn general_post(
    model: &Model,
    setup: &Setup,
    whole: Span,
    init_stmts: &[ast::Stmt],
    own_feedrate: bool,
    feed: (VarId, VarId),
) -> Result<(Vec<Function>, Layout), native::Why> {
    // Globals start as the shaped lowering starts them, so that a post
    // and the post printed from it lower the same way.
    let mut layout = Layout::new(model);
    // Its IR says what each function does, not in the words it was written
    // in (a `switch` as a loop, statements before expressions): the CIMCO
    // backend prints each from its source.
    layout.reshaped.extend(model.scopes.top_fns.iter().copied());
    if !own_feedrate {
        layout.add_fn(layout::FEEDRATE);
    }
    layout.add_fn(layout::INIT);
    for g in GLUE {
        layout.add_fn(g.0);
    }
    let glue_ids: Vec<_> = GLUE.iter().map(|g| layout.function(g.0)).collect();
    let mut shared = general::Shared::new(model, setup, &mut layout);
    let mut functions = Vec::new();
    for &id in &model.scopes.top_fns {
        let f = &model.scopes.funcs[id];
        let func = f.func.expect("top-level functions have a body");
        let entry = f.name.as_deref().is_some_and(is_entry_point);
        functions.push(shared.function(id, &func.body, entry, func.span)?);
    }
    if !own_feedrate {
        functions.push(feedrate_function(feed));
    }
    let mut init = shared.function(0, init_stmts, false, whole)?;
    init.name = layout::INIT.into();
    init.params.clear();
    functions.push(init);
    for ((glue, entry, host), id) in GLUE.iter().zip(glue_ids) {
        let target = shared.layout.function(entry).filter(|_| top_fn(model, entry).is_some());
        let span = top_fn(model, entry).and_then(|f| f.func).map(|f| f.span);
        let fields = match *host {
            names::DRILL_HEADER => Some(names::MILL_DRILLING_FIELDS),
            names::TURN_DRILL => Some(names::TURN_DRILLING_FIELDS),
            _ => None,
        };
        let arg = fields.and_then(|f| shared.layout.global_index.get(f)).map_or(Expr::Undefined, |g| Expr::Global(*g));
        let body = match target {
            Some(f) => {
                vec![Stmt::Return(Some(Expr::Call(f, vec![Expr::Host { name: (*host).to_string(), args: vec![arg] }])))]
            }
            None => vec![],
        };
        debug_assert_eq!(id.map(|i| i.index()), Some(functions.len()));
        functions.push(Function {
            name: (*glue).to_string(),
            params: vec![],
            slots: 0,
            locals: Vec::new(),
            body: Body::Native(body),
            span,
            why_script: None,
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: true,
        });
    }
    for (id, f) in shared.nested_functions()? {
        if id.index() != functions.len() {
            return Err(native::Why { what: "a nested function out of order".into(), span: whole });
        }
        functions.push(f);
    }
    for f in &mut functions {
        if let Body::Native(b) = &mut f.body {
            *b = fold::stmts(std::mem::take(b));
        }
    }
    Ok((functions, layout))
}

/// The shaped functions, with the general form of each top-level function
/// that is a script or reads `arguments` (its general form takes any
/// number of arguments; the shaped forms for each number stay for shaped
/// callers), of `__postc_init` when it is a script, and of the bridges;
/// the general form's closures come last.
fn mixed(model: &Model, mut shaped: Vec<Function>, general: Vec<Function>) -> Vec<Function> {
    let tops = model.scopes.top_fns.len();
    // The general form's functions after the bridges are its closures.
    let closures_from =
        general.iter().rposition(|f| GLUE.iter().any(|g| g.0 == f.name)).map_or(general.len(), |i| i + 1);
    let first_closure = shaped.len();
    struct Renumber(usize, usize);
    impl postc_ir::visit::VisitMut for Renumber {
        fn visit_expr_mut(&mut self, e: &mut Expr) {
            if let Expr::Call(f, _) | Expr::Closure { function: f, .. } = e
                && f.index() >= self.0
            {
                *f = FunctionId::new((f.index() - self.0 + self.1) as u16);
            }
            postc_ir::visit::walk_expr_mut(self, e);
        }
    }
    let mut renumber = Renumber(closures_from, first_closure);
    let mut general: Vec<Function> = general
        .into_iter()
        .map(|mut f| {
            if let Body::Native(b) = &mut f.body {
                for s in b.iter_mut() {
                    postc_ir::visit::VisitMut::visit_stmt_mut(&mut renumber, s);
                }
            }
            f
        })
        .collect();
    let closures = general.split_off(closures_from);
    for (i, g) in general.into_iter().enumerate() {
        let takes_general = if i < tops {
            matches!(shaped[i].body, Body::Script(_)) || model.scopes.funcs[model.scopes.top_fns[i]].uses_arguments
        } else {
            matches!(shaped[i].body, Body::Script(_)) || GLUE.iter().any(|gl| gl.0 == g.name)
        };
        if takes_general {
            shaped[i] = g;
        }
    }
    // A shaped form for some number of arguments that runs the script
    // (`specialization`) calls the general form instead.
    for f in shaped.iter_mut().skip(tops) {
        if matches!(f.body, Body::Script(_))
            && let Some(&base) = model.scopes.top_fn_names.get(&f.name)
        {
            let args = (0..f.params.len()).map(|k| Expr::Local(LocalId::new(k as u16))).collect();
            f.body = Body::Native(vec![Stmt::Return(Some(Expr::Call(FunctionId::new(base as u16), args)))]);
            f.slots = f.params.len() as u16;
            f.why_script = None;
        }
    }
    shaped.extend(closures);
    shaped
}

/// postc's `getFeedrate(movement)` for a post that has none: nothing for
/// a rapid, else the feed through the per-minute or per-revolution variable.
fn feedrate_function((feed_var, feed_rev_var): (VarId, VarId)) -> Function {
    Function {
        name: layout::FEEDRATE.into(),
        params: vec!["movement".into()],
        slots: 1,
        locals: Vec::new(),
        body: Body::Native(vec![
            Stmt::If {
                branches: vec![(
                    Expr::Binary(
                        postc_ir::BinaryOp::Eq,
                        Box::new(Expr::Local(LocalId::new(0))),
                        Box::new(Expr::Number(builtins::MOVEMENT_RAPID)),
                    ),
                    vec![Stmt::Return(Some(Expr::Text(String::new())))],
                )],
                otherwise: vec![],
            },
            Stmt::If {
                branches: vec![(
                    Expr::Quantity(Quantity::FeedPerRev),
                    vec![Stmt::Return(Some(Expr::FormatVar {
                        var: feed_rev_var,
                        value: Box::new(Expr::Quantity(Quantity::Feed)),
                        span: None,
                    }))],
                )],
                otherwise: vec![],
            },
            Stmt::Return(Some(Expr::FormatVar {
                var: feed_var,
                value: Box::new(Expr::Quantity(Quantity::Feed)),
                span: None,
            })),
        ]),
        span: None,
        why_script: None,
        source: Vec::new(),
        uses_arguments: false,
        starts_undefined: false,
    }
}

/// The source's comments the IR keeps ([`crate::docs`]): the file's head,
/// and the `//` lines above each function and each `createVariable`.
pub(crate) fn comments(program: &Program, text: &str, post: &mut Post) {
    let (head, floor) = crate::docs::head(text);
    post.add_comment(CommentTarget::Post, head);
    for s in &program.body {
        let on = match &s.kind {
            StmtKind::Function(f) => f
                .name
                .as_ref()
                .and_then(|n| post.functions.iter().position(|g| g.name == n.name))
                .map(|i| CommentTarget::Function(FunctionId::new(i as u16))),
            StmtKind::Var(ds) => match ds.as_slice() {
                [d] => post
                    .variables
                    .iter()
                    .position(|v| v.name == d.name.name)
                    .map(|i| CommentTarget::Variable(VarId::new(i as u16))),
                _ => None,
            },
            _ => None,
        };
        if let Some(on) = on {
            post.add_comment(on, crate::docs::before(text, s.span.start, floor));
        }
    }
}

/// Keeps the JavaScript the IR does not say all of, for the CIMCO backend
/// (`Function::source`): the declaration of each function that runs as a
/// script, reads `arguments` (its IR functions are the forms for each
/// number of arguments), keeps arrays or objects in slots (its IR is
/// reshaped: `native::Native::reshaped`) or makes formats and variables when the post is
/// compiled (`onInit`; the names of what it makes are its `declares`),
/// and on `__postc_init` every top-level statement but the functions, in
/// order, each with the globals it declares: as written, or with no text
/// where the IR holds it (a constant, a format or variable made at compile
/// time, a `globals` or `PostInfo` object of constants), so that a backend
/// prints the IR's there.
fn keep_source(
    program: &Program,
    model: &Model,
    setup: &Setup,
    layout: &Layout,
    text: &str,
    functions: &mut [Function],
) {
    let slice = |span: Span| text.get(span.start..span.end).unwrap_or_default().to_string();
    let written = written_items(program, text);
    for (function, &id) in functions.iter_mut().zip(&model.scopes.top_fns) {
        let info = &model.scopes.funcs[id];
        let Some(func) = info.func else { continue };
        // The formats and variables `onInit` makes when the post is compiled.
        let made: Vec<String> = func
            .body
            .iter()
            .filter(|s| setup.done.contains(&s.span.start))
            .filter_map(|s| match &s.kind {
                StmtKind::Var(ds) => ds.first().map(|d| d.name.name.clone()),
                StmtKind::Expr(e) => match &e.kind {
                    ExprKind::Assign { target, .. } => match &target.kind {
                        ExprKind::Ident(n) => Some(n.clone()),
                        _ => None,
                    },
                    _ => None,
                },
                _ => None,
            })
            .collect();
        if matches!(function.body, Body::Script(_))
            || info.uses_arguments
            || layout.reshaped.contains(&id)
            || !made.is_empty()
        {
            function.source = vec![SourceText { text: slice(func.span), declares: made, ..SourceText::default() }];
        }
        if let Some((at, w)) = written.get(&func.span.start) {
            if function.source.is_empty() {
                function.source = vec![SourceText::default()];
            }
            function.source[0].written = w.clone();
            function.source[0].written_at = *at;
        }
    }
    let mut top = Vec::new();
    for s in &program.body {
        if matches!(s.kind, StmtKind::Function(_) | StmtKind::Empty) {
            continue;
        }
        let mut hoisted = Vec::new();
        scope::hoist_stmt(s, &mut hoisted, &mut Vec::new());
        let mut declares: Vec<String> = hoisted.iter().map(|v| v.name.clone()).collect();
        // Implicit globals whose first value this statement gives.
        for g in &model.globals {
            if !g.declared
                && g.init.is_some_and(|e| s.span.start <= e.span.start && e.span.end <= s.span.end)
                && !declares.contains(&g.name)
            {
                declares.push(g.name.clone());
            }
        }
        // What the IR holds: formats and variables made at compile time,
        // constants, and the `globals` and `PostInfo` objects of constants.
        let mut held = setup.done.contains(&s.span.start)
            || matches!(&s.kind, StmtKind::Var(ds)
                if ds.iter().all(|d| d.init.is_some() && model.constant(&d.name.name).is_some()));
        for &name in model::FLATTENED {
            if model.flattened.contains(name)
                && let Some(props) = model::object_literal_assignment(s, name)
            {
                let names: Vec<String> = props.iter().map(|p| format!("{name}.{}", p.key.name)).collect();
                held = names.iter().all(|n| model.constant(n).is_some());
                declares = vec![name.to_string()];
                if !held {
                    declares.extend(names);
                }
            }
        }
        let (written_at, written) = written.get(&s.span.start).cloned().unwrap_or_default();
        top.push(SourceText { text: if held { String::new() } else { slice(s.span) }, declares, written, written_at });
    }
    if let Some(init) = functions.iter_mut().find(|f| f.name == layout::INIT) {
        init.source = top;
    }
}

/// Each top-level statement's text exactly as the file has it, by where
/// the statement starts (a function declaration: where `function` starts),
/// with what stands between it and the statement before (the file's head,
/// comments, blank lines and their line endings), and where that text
/// starts ([`postc_ir::SourceText::written`]).
fn written_items(program: &Program, text: &str) -> HashMap<usize, (usize, String)> {
    let mut out = HashMap::new();
    let mut from = crate::docs::after_notes(text);
    for s in &program.body {
        if matches!(s.kind, StmtKind::Empty) {
            continue;
        }
        let start = match &s.kind {
            StmtKind::Function(f) => f.span.start,
            _ => s.span.start,
        };
        let end = s.span.end.max(start);
        if let Some(piece) = text.get(from.min(end)..end) {
            out.insert(start, (from, piece.to_string()));
        }
        from = end;
    }
    out
}

/// postc's glue: the function name, the post's entry point it bridges to,
/// and the host function that gives the entry point its data.
const GLUE: [(&str, &str, &str); 3] = [
    (layout::COMPENSATION, "onCompensation", names::COMPENSATION),
    (layout::DRILL_HEADER, "onDrillingHeader", names::DRILL_HEADER),
    (layout::TURN_DRILL, "onDrilling", names::TURN_DRILL),
];

/// A top-level function of the post, by name.
/// Whether a function is one CNC-Calc calls: its entry points are named
/// `on` and a capital (`onOpen`, `onLinear`, `onDrillingPoint`, ...).
pub(crate) fn is_entry_point(name: &str) -> bool {
    name.strip_prefix("on").is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_uppercase()))
}

fn top_fn<'m, 'a>(model: &'m Model<'a>, name: &str) -> Option<&'m scope::FuncInfo<'a>> {
    model.scopes.top_fn_names.get(name).map(|&i| &model.scopes.funcs[model.scopes.top_fns[i]])
}

/// The post's formats and variables, and the two `getFeedrate` formats
/// through (per minute, per revolution).
fn feed_variables(model: &Model, setup: &Setup, post: &mut Post) -> (VarId, VarId) {
    post.formats = setup.formats.clone();
    post.variables = setup.variables.clone();
    let mark = setup::decimal_mark(model);
    let feed_var = feed_variable(post, layout::FEED_VAR, 1, mark);
    // Feeds per revolution (mm/rev, in/rev) keep four decimals: 0.15
    // mm/rev prints F0.15, 0.0025 in/rev F0.0025.
    let feed_rev_var = feed_variable(post, layout::FEED_REV_VAR, layout::FEED_PER_REV_DECIMALS, mark);
    (feed_var, feed_rev_var)
}

/// One `F` variable `getFeedrate` formats through: trailing zeros dropped,
/// rounded as JavaScript rounds.
fn feed_variable(post: &mut Post, name: &str, decimals: u8, decimal_mark: char) -> VarId {
    post.formats.push(NumberFormat {
        decimals,
        trim_zeros: true,
        width: 0,
        width_of: postc_ir::WidthOf::IntegerDigits,
        decimal_mark,
        rounding: postc_ir::Rounding::Binary,
        ..NumberFormat::default()
    });
    post.variables.push(Variable {
        name: name.into(),
        source: ValueSource::Assigned,
        prefix: b"F".to_vec(),
        format: FormatId::new((post.formats.len() - 1) as u16),
        modality: Modality::Always,
        span: None,
    });
    VarId::new((post.variables.len() - 1) as u16)
}

/// Every function of the post, native where it can be, then postc's:
/// `getFeedrate` (when the post has none; `feed` its two variables), the
/// top-level code, and the glue.
fn functions(
    model: &Model,
    setup: &Setup,
    layout: &mut Layout,
    whole: Span,
    init_stmts: &[ast::Stmt],
    feed: Option<(VarId, VarId)>,
) -> Vec<Function> {
    let arity = |name: &str| top_fn(model, name).map(|f| f.params.len());
    let mut functions: Vec<Function> = Vec::new();
    for &id in &model.scopes.top_fns {
        let f = &model.scopes.funcs[id];
        let func = f.func.expect("top-level functions have a body");
        // A caller may have lowered it already (it returns an object).
        native::lower_top(model, setup, layout, id);
        let native::Lowered { body: lowered, slots, reshaped } =
            layout.lowered.remove(&id).expect("lower_top lowers every top-level function once");
        if reshaped {
            layout.reshaped.insert(id);
        }
        let (body, why_script) = match lowered {
            Ok(b) => (Body::Native(fold::stmts(b)), None),
            Err(w) => {
                (Body::Script(ScriptId::new(0)), Some(postc_ir::ScriptReason { what: w.what, span: Some(w.span) }))
            }
        };
        functions.push(Function {
            name: f.name.clone().unwrap_or_default(),
            params: f.params.clone(),
            slots,
            // Temporaries past the `var`s have no name.
            locals: f.locals.iter().skip(f.params.len()).cloned().collect(),
            body,
            span: Some(func.span),
            why_script,
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: true,
        });
    }
    if let Some(feed) = feed {
        functions.push(feedrate_function(feed));
    }
    let init_native = {
        let mut n = native::Native::new(model, setup, layout, 0);
        n.stmts(init_stmts).map(|b| (fold::stmts(b), n.slots))
    };
    functions.push(Function {
        name: layout::INIT.into(),
        params: vec![],
        slots: init_native.as_ref().map_or(0, |(_, s)| *s),
        locals: Vec::new(),
        body: match &init_native {
            Ok((b, _)) => Body::Native(b.clone()),
            Err(_) => Body::Script(ScriptId::new(0)),
        },
        span: Some(whole),
        why_script: init_native.err().map(|w| postc_ir::ScriptReason { what: w.what, span: Some(w.span) }),
        source: Vec::new(),
        uses_arguments: false,
        starts_undefined: false,
    });
    for (g, entry, _) in GLUE {
        let body = if arity(entry).is_some() { Body::Script(ScriptId::new(0)) } else { Body::Native(vec![]) };
        // The glue stands where the post's own entry point is defined.
        let span = functions.iter().find(|f| f.name == entry).and_then(|f| f.span);
        let why_script = matches!(body, Body::Script(_)).then(|| postc_ir::ScriptReason {
            what: format!("postc's bridge to `{entry}`: it hands the post the host's data as an object"),
            span,
        });
        functions.push(Function {
            name: g.into(),
            params: vec![],
            locals: Vec::new(),
            slots: 0,
            body,
            span,
            why_script,
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: false,
        });
    }
    // Lowering may add forms (`f.apply(null, words)` with a list whose
    // length it found), and so may the forms themselves.
    let mut next = 0;
    while let Some(&(id, arity)) = layout.clones.get(next) {
        functions.push(specialization(model, setup, layout, id, arity));
        next += 1;
    }
    debug_assert_eq!(functions.len(), layout.fn_names.len());

    functions
}

/// The form of function `id`, which reads `arguments`, for calls with
/// `arity` arguments. When it has no native form it runs the function's
/// script, which takes any number of arguments.
fn specialization(model: &Model, setup: &Setup, layout: &mut Layout, id: scope::FnId, arity: usize) -> Function {
    let f = &model.scopes.funcs[id];
    let func = f.func.expect("top-level functions have a body");
    let name = f.name.clone().unwrap_or_default();
    let mut params: Vec<String> = f.params.iter().take(arity).cloned().collect();
    params.extend((f.params.len()..arity).map(|k| format!("arguments[{k}]")));
    let mut n = native::Native::new(model, setup, layout, id);
    n.arity = Some(arity);
    match n.lower_function(&func.body, func.span) {
        Ok(b) => Function {
            name: crate::made::specialization(&name, arity),
            params,
            slots: n.slots,
            locals: Vec::new(),
            body: Body::Native(fold::stmts(b)),
            span: Some(func.span),
            why_script: None,
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: true,
        },
        Err(w) => Function {
            // Runs the script of the same name.
            name,
            params,
            slots: 0,
            locals: Vec::new(),
            body: Body::Script(ScriptId::new(0)),
            span: Some(func.span),
            why_script: Some(postc_ir::ScriptReason {
                what: format!("{} (its form for {arity} arguments)", w.what),
                span: Some(w.span),
            }),
            source: Vec::new(),
            uses_arguments: false,
            starts_undefined: false,
        },
    }
}

/// The Rhai script of the functions that do not lower to native IR, and
/// of postc's glue.
fn script(
    model: &Model,
    setup: &Setup,
    layout: &Layout,
    whole: Span,
    init_stmts: &[ast::Stmt],
    own_feedrate: bool,
) -> Script {
    {
        let mut g = rhai::Gen::new(model, setup, layout);
        for &id in &model.scopes.top_fns {
            let name = model.scopes.funcs[id].name.clone().unwrap_or_default();
            g.function(&rhai::fn_name(&name), id);
        }
        if !own_feedrate {
            g.glue(&rhai::fn_name(layout::FEEDRATE), whole, &format!("{}({}(a, 0))\n", names::FEEDRATE, names::ARG));
        }
        g.init(&rhai::fn_name(layout::INIT), init_stmts, whole);
        for (glue_name, entry, arg) in GLUE {
            let body = if top_fn(model, entry).is_some() {
                format!(
                    "{CALL}({FUNCTION_OBJECT}({}), [{arg}()])\n",
                    rhai::quote(&rhai::fn_name(entry)),
                    CALL = names::CALL,
                    FUNCTION_OBJECT = names::FUNCTION_OBJECT
                )
            } else {
                "()\n".to_string()
            };
            let span = top_fn(model, entry).and_then(|f| f.func).map_or(whole, |f| f.span);
            g.glue(&rhai::fn_name(glue_name), span, &body);
        }
        Script { language: ScriptLanguage::Rhai, source: g.out, span: Some(whole), span_map: g.span_map }
    }
}

/// The handlers: each calls the entry point of its section.
fn handlers(model: &Model, layout: &Layout, lathe: bool, functions: &[Function]) -> Vec<postc_ir::Handler> {
    let arity = |name: &str| top_fn(model, name).map(|f| f.params.len());
    let use_radius = match model.setting("useRadius") {
        Some(c) => handlers::RadiusSetting::Known(c.truthy()),
        None => match model.global("useRadius").or_else(|| model.global("globals.useRadius")) {
            Some(g) if g.assignments > 0 => handlers::RadiusSetting::Global(layout.global_index[&g.name]),
            _ => handlers::RadiusSetting::Known(false),
        },
    };
    let entry = handlers::Entry { layout, lathe, use_radius, arity: &arity };
    let mut hs = entry.handlers();
    for h in &mut hs {
        // A handler stands where the JavaScript function it calls is defined.
        h.span = first_call(&h.body).and_then(|f| functions.get(f.index())).and_then(|f| f.span);
        h.body = fold::stmts(std::mem::take(&mut h.body));
    }
    hs
}

/// The top-level statements that run at start: everything but function
/// declarations, calls the compiler ran, and constant declarations; the
/// properties of `globals` and `PostInfo` that are not constants are
/// assigned one by one.
fn init_statements(program: &Program, model: &Model, setup: &Setup) -> Vec<ast::Stmt> {
    let mut out = Vec::new();
    for s in &program.body {
        if setup.done.contains(&s.span.start) {
            continue;
        }
        match &s.kind {
            StmtKind::Function(_) | StmtKind::Empty => {}
            StmtKind::Var(ds) => {
                // A constant's declarator is folded away; the others of the
                // statement (`var a = NaN, b = NaN;` with only `a` ever
                // assigned) still run.
                if ds.iter().any(|d| d.init.is_some() && model.constant(&d.name.name).is_none()) {
                    let kept: Vec<_> = ds.iter().filter(|d| model.constant(&d.name.name).is_none()).cloned().collect();
                    out.push(ast::Stmt::new(StmtKind::Var(kept), s.span));
                }
            }
            StmtKind::Expr(e) => {
                if let ExprKind::Assign { op: AssignOp::Assign, target, value } = &e.kind
                    && let ExprKind::Ident(name) = &target.kind
                {
                    if model.flattened.contains(name)
                        && let ExprKind::Object(props) = &value.kind
                    {
                        for p in props {
                            if model.constant(&format!("{name}.{}", p.key.name)).is_some() {
                                continue;
                            }
                            let object = ast::Expr::new(ExprKind::Ident(name.clone()), target.span);
                            let member = ast::Expr::new(
                                ExprKind::Member {
                                    object: Box::new(object),
                                    property: Ident { name: p.key.name.clone(), span: p.key.span },
                                },
                                p.span,
                            );
                            let assign = ast::Expr::new(
                                ExprKind::Assign {
                                    op: AssignOp::Assign,
                                    target: Box::new(member),
                                    value: Box::new(p.value.clone()),
                                },
                                p.span,
                            );
                            out.push(ast::Stmt::new(StmtKind::Expr(assign), p.span));
                        }
                        continue;
                    }
                    if model.constant(name).is_some() {
                        continue;
                    }
                }
                out.push(s.clone());
            }
            _ => out.push(s.clone()),
        }
    }
    out
}

/// Output options and post information from the settings.
fn settings(model: &Model, post: &mut Post, diags: &mut Vec<Diagnostic>) {
    let text = |name: &str| match model.constant(name) {
        Some(Const::Str(s)) => Some(s.clone()),
        Some(Const::Num(n)) => Some(postc_ir::js::number_to_string(*n)),
        _ => None,
    };
    if let Some(Const::Str(lb)) = model.setting("linebreak")
        && !lb.is_empty()
    {
        post.options.line_ending = lb.as_bytes().to_vec();
    }
    if let Some(Const::Num(t)) = model.setting("tolerance")
        && *t > 0.0
        && t.is_finite()
    {
        post.options.arc_tolerance = *t;
    }
    if let Some(Const::Str(m)) = model.setting("decimalMark")
        && m != "."
        && m != ","
        && let Some(g) = model.global("decimalMark").or_else(|| model.global("globals.decimalMark"))
        && let Some(init) = g.init
    {
        diags.push(
            Diagnostic::warning(codes::JS103, format!("decimalMark is {m:?}; postc writes '.' or ','"))
                .at(init.span, "here")
                .help("use '.' or ','; postc uses '.'"),
        );
    }
    if let Some(title) = text("PostInfo.title") {
        post.info.name = title;
    }
    for field in ["summary", "author", "version"] {
        if let Some(v) = text(&format!("PostInfo.{field}")) {
            post.info.notes.push(format!("{field}: {v}"));
        }
    }
}

/// Whether the post is for a lathe: `PostInfo.type` says so, or it has
/// turning's `onLinear(vx, vz, movement)` or only `TurnDrillingFields`.
fn is_lathe(model: &Model, on_linear: Option<usize>) -> bool {
    if let Some(Const::Num(t)) = model.constant("PostInfo.type") {
        return *t == 1.0;
    }
    if on_linear == Some(3) {
        return true;
    }
    model.global("TurnDrillingFields").is_some() && model.global("MillDrillingFields").is_none()
}

/// The first function a body calls.
fn first_call(body: &[Stmt]) -> Option<postc_ir::FunctionId> {
    use postc_ir::visit::{Visit, walk_expr};
    struct First(Option<postc_ir::FunctionId>);
    impl Visit for First {
        fn visit_expr(&mut self, e: &Expr) {
            if let (None, Expr::Call(f, _)) = (self.0, e) {
                self.0 = Some(*f);
            }
            walk_expr(self, e);
        }
    }
    let mut first = First(None);
    body.iter().for_each(|s| first.visit_stmt(s));
    first.0
}
