//! Preparing a post to run: its IR becomes the runtime's [`Code`].
//!
//! The IR says what each handler means (`Write(onLinear(x, y, z, 1))`,
//! functions that return text). Here the runtime chooses how to run it
//! fast, for any dialect, without changing a byte of what it writes:
//!
//! 1. every function and handler in the runtime's form ([`crate::exec`]);
//!    a factory called by the one-time code with constants has its
//!    closures made into functions of their own, their state in globals
//!    ([`factories`]); an object a global holds for the whole run, never
//!    seen as a whole, becomes globals of its own and its methods plain
//!    functions ([`fields`]); a method of an object a global holds for the
//!    whole run that nothing can replace is called directly
//!    ([`factories`]); a function given a function expression it calls
//!    runs as a copy that calls it directly ([`callbacks`]); constants
//!    folded ([`fold`]);
//! 2. the fast path ([`emit`]): a handler that writes what a native
//!    function returns builds that text straight in the output instead;
//!    marks are tidied;
//! 3. calls of small value functions left in a handler become the
//!    functions' statements ([`splice`]);
//! 4. calls of expression functions left in a handler become the
//!    expressions ([`inline`]);
//! 5. a word of a block built in the output becomes one statement
//!    ([`fuse`]);
//! 6. copies and constants in locals are read through and stores nobody
//!    reads are dropped ([`locals`]), in handlers and functions;
//! 7. a block number moved back before its words is written first
//!    ([`unshift`]);
//! 8. a handler starts its locals as `null` only where some path may read
//!    one before writing it ([`fresh`]): the engine keeps the frame from
//!    event to event;
//! 9. a run of words joined into a block becomes one statement
//!    ([`fuse`]);
//! 10. a handler whose statements share locals runs as one statement, so
//!     its locals live in one frame (the engine runs its list).
//!
//! A handler of output lines only (every Vectric section) is kept as it
//! is: the engine runs its lines on a faster path still.

mod callbacks;
pub(crate) mod emit;
mod factories;
mod fields;
mod fold;
pub(crate) mod fresh;
pub(crate) mod fuse;
mod inline;
pub(crate) mod locals;
pub(crate) mod splice;
pub(crate) mod unshift;

use postc_ir::Post;

use crate::exec::{self, Code, Expr, Stmt};

/// Prepares a post's code to run.
pub fn prepare(post: &Post) -> Code {
    let mut functions: Vec<exec::Function> = functions_of(post);
    let mut handlers: Vec<Vec<Stmt>> = post.handlers.iter().map(|h| exec::stmts(&h.body)).collect();
    let mut init = exec::stmts(&post.init);
    let mut globals: Vec<Expr> = post.globals.iter().map(|g| exec::expr(&g.initial)).collect();
    let names: Vec<&str> = post.globals.iter().map(|g| g.name.as_str()).collect();
    factories::specialise(&mut functions, &mut handlers, &mut init, &mut globals);
    fields::replace(&names, &mut functions, &mut handlers, &mut init, &mut globals);
    factories::direct_calls(&mut functions, &mut handlers, &mut init);
    callbacks::specialise(&mut functions, &mut handlers, &mut init);
    for f in &mut functions {
        if let exec::Body::Native(body) = &mut f.body {
            *body = fold::stmts(std::mem::take(body));
        }
    }
    let objects = object_functions(&mut functions);
    let handlers: Vec<Vec<Stmt>> = handlers.into_iter().map(|h| handler(&functions, &objects, h)).collect();
    let handler_slots = handlers.iter().filter_map(|b| emit::max_slot(b)).map(|k| k.index() + 1).max().unwrap_or(0);
    for (f, objects) in functions.iter_mut().zip(&objects) {
        if let exec::Body::Native(body) = &mut f.body
            && !objects
        {
            *body = locals::tidy(std::mem::take(body));
            fuse::expressions(body);
        }
    }
    for f in &mut functions {
        f.returns = match &f.body {
            exec::Body::Native(body) => exec::returned(body),
            exec::Body::Script(_) => None,
        };
    }
    Code { handlers, handler_slots, init, globals, functions }
}

/// Which functions use JavaScript's objects ([`exec::uses_objects`]), or
/// call one that does, or a function value: the fast-path passes leave
/// them, and the handlers that call them, as they are.
fn object_functions(functions: &mut [exec::Function]) -> Vec<bool> {
    let mut objects: Vec<bool> = functions
        .iter_mut()
        .map(|f| match &mut f.body {
            exec::Body::Native(body) => exec::uses_objects(body),
            exec::Body::Script(_) => false,
        })
        .collect();
    let calls: Vec<Vec<usize>> = functions
        .iter_mut()
        .map(|f| match &mut f.body {
            exec::Body::Native(body) => called(body),
            exec::Body::Script(_) => Vec::new(),
        })
        .collect();
    // Until nothing changes: a caller of an object function is one.
    let mut changed = true;
    while changed {
        changed = false;
        for (i, callees) in calls.iter().enumerate() {
            if !objects[i] && callees.iter().any(|&c| objects.get(c).copied().unwrap_or(false)) {
                objects[i] = true;
                changed = true;
            }
        }
    }
    objects
}

/// The functions statements call.
fn called(body: &mut [Stmt]) -> Vec<usize> {
    fn expr(e: &mut Expr, out: &mut Vec<usize>) {
        if let Expr::Call(f, _) = e {
            out.push(f.index());
        }
        e.for_each_operand_mut(|a| expr(a, out));
    }
    let mut out = Vec::new();
    for s in body {
        s.for_each_expr_mut(|e| expr(e, &mut out));
        s.for_each_body_mut(|b| out.extend(called(b)));
    }
    out
}

/// A handler body, prepared.
fn handler(functions: &[exec::Function], objects: &[bool], mut body: Vec<Stmt>) -> Vec<Stmt> {
    if body.iter().all(|s| matches!(s, Stmt::Line { .. })) {
        return body;
    }
    if exec::uses_objects(&mut body) || called(&mut body).iter().any(|&f| objects.get(f).copied().unwrap_or(false)) {
        return one(fold::stmts(body));
    }
    let first_free = emit::max_slot(&body).map_or(0, |k| k.index().saturating_add(1).min(usize::from(u16::MAX)) as u16);
    let mut emitter = emit::Emitter::new(functions, first_free);
    let mut body = emit::tidy(fold::stmts(emitter.handler(fold::stmts(body))));
    splice::small_functions(functions, &mut body);
    inline::expression_functions(functions, &mut body);
    let top = emit::max_slot(&body);
    fuse::stmts(&mut body);
    let mut body = locals::tidy(body);
    fuse::expressions(&mut body);
    unshift::block_numbers(&mut body);
    match top {
        // The statements share the frame, which the engine keeps sized
        // for every handler.
        Some(_) => {
            let mut body = fresh::start_nulls(body);
            fuse::runs(&mut body);
            one(body)
        }
        None => body,
    }
}

/// The post's code as its IR says it, with none of the passes: a
/// handler's statements share one frame, as [`prepare`] gives them.
pub fn unprepared(post: &Post) -> Code {
    let handlers: Vec<Vec<Stmt>> = post
        .handlers
        .iter()
        .map(|h| {
            let body = exec::stmts(&h.body);
            if body.iter().all(|s| matches!(s, Stmt::Line { .. })) { body } else { one(body) }
        })
        .collect();
    let handler_slots = handlers.iter().filter_map(|b| emit::max_slot(b)).map(|k| k.index() + 1).max().unwrap_or(0);
    Code {
        handlers,
        handler_slots,
        init: exec::stmts(&post.init),
        globals: post.globals.iter().map(|g| exec::expr(&g.initial)).collect(),
        functions: functions_of(post),
    }
}

/// The post's functions in the runtime's form, each its own origin.
fn functions_of(post: &Post) -> Vec<exec::Function> {
    (0..post.functions.len())
        .filter_map(|i| Some(exec::function(postc_ir::FunctionId::from_usize(i)?, &post.functions[i])))
        .collect()
}

/// Statements as one, so that their locals share a frame (the engine
/// gives each top-level statement of a handler a fresh frame).
fn one(body: Vec<Stmt>) -> Vec<Stmt> {
    if body.len() == 1 && !matches!(body[0], Stmt::Assign(..) | Stmt::While { .. }) {
        return body;
    }
    vec![Stmt::If { branches: vec![(Expr::Bool(true), body)], otherwise: vec![] }]
}
