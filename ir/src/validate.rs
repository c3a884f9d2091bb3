//! Validation: what every reader of a [`Post`] may take for granted.
//!
//! Frontends build posts that hold these by construction; a post read from
//! RON holds whatever its text says. [`validate`] runs on every post before
//! the runtime or a backend sees it (`postc_driver::compile_post_bytes`),
//! so that they can index without checking:
//!
//! - every id is in range: variables' formats, `Var`/`Previous`/`Forget`/
//!   `FormatVar` variables, `Format` formats, `Call` functions, `Global`
//!   globals, `Script` and script bodies' scripts;
//! - a native function has at least as many slots as parameters;
//! - a regular expression's flags are among `g`, `i`, `m`, each at most
//!   once (whether its pattern is one postc runs is the runtime's to say:
//!   `postc_driver` compiles each pattern after validating);
//! - numbers that steer the output are finite and sensible: format
//!   multipliers, the decimal mark (ASCII), block numbering, the chord
//!   tolerance (above zero), arc radius limits, tape splitting (at least
//!   one line per part), the step budget (at least one);
//! - every comment stands before something the post has, and holds whole
//!   lines.
//!
//! Each problem names the item that holds it ([`Item`]), so the RON
//! loader can point at that item in the text.

use crate::code::{Expr, Piece, Place, Stmt};
use crate::post::{Body, CommentTarget, Post};
use crate::visit::{Visit, walk_expr, walk_piece, walk_stmt};

/// Where in a post a problem sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    /// `options`.
    Options,
    /// `formats[i]`.
    Format(usize),
    /// `variables[i]`.
    Variable(usize),
    /// `globals[i]`.
    Global(usize),
    /// `functions[i]`.
    Function(usize),
    /// `init`.
    Init,
    /// `handlers[i]`.
    Handler(usize),
    /// `call_lists[i]`.
    CallList(usize),
    /// `comments[i]`.
    Comment(usize),
}

impl Item {
    /// The field of [`Post`] (or of `Post::options`) that holds the item,
    /// and its index in that list.
    pub fn field(self) -> (&'static str, Option<usize>) {
        match self {
            Item::Options => ("options", None),
            Item::Format(i) => ("formats", Some(i)),
            Item::Variable(i) => ("variables", Some(i)),
            Item::Global(i) => ("globals", Some(i)),
            Item::Function(i) => ("functions", Some(i)),
            Item::Init => ("init", None),
            Item::Handler(i) => ("handlers", Some(i)),
            Item::CallList(i) => ("call_lists", Some(i)),
            Item::Comment(i) => ("comments", Some(i)),
        }
    }
}

/// One inconsistency.
#[derive(Clone, Debug, PartialEq)]
pub struct Invalid {
    pub at: Item,
    pub message: String,
}

/// Every inconsistency of `post`; empty when the runtime and the backends
/// may trust it.
pub fn validate(post: &Post) -> Vec<Invalid> {
    let mut out = Vec::new();
    let mut bad = |at: Item, message: String| out.push(Invalid { at, message });
    for (i, f) in post.formats.iter().enumerate() {
        if !f.multiplier.is_finite() {
            bad(Item::Format(i), format!("the multiplier {} is not a finite number", f.multiplier));
        }
        if !f.decimal_mark.is_ascii() {
            bad(Item::Format(i), format!("the decimal mark `{}` is not an ASCII character", f.decimal_mark));
        }
    }
    for (i, v) in post.variables.iter().enumerate() {
        if usize::from(v.format) >= post.formats.len() {
            bad(
                Item::Variable(i),
                format!("`{}` uses format {}, and the post has {} formats", v.name, v.format, post.formats.len()),
            );
        }
    }
    let o = &post.options;
    let b = o.block_numbers;
    if ![b.start, b.increment, b.maximum].iter().all(|n| n.is_finite()) {
        bad(Item::Options, "block numbering has a number that is not finite".into());
    }
    if !(o.arc_tolerance.is_finite() && o.arc_tolerance > 0.0) {
        bad(Item::Options, format!("the chord tolerance {} is not a number above zero", o.arc_tolerance));
    }
    for r in [o.min_arc_radius, o.max_arc_radius].into_iter().flatten() {
        if !(r.is_finite() && r >= 0.0) {
            bad(Item::Options, format!("the arc radius limit {r} is not a number of 0 or more"));
        }
    }
    if o.tape_splitting.as_ref().is_some_and(|t| t.max_lines == 0) {
        bad(Item::Options, "tape splitting allows no line per part".into());
    }
    if o.step_budget == 0 {
        bad(Item::Options, "the step budget is 0: no handler could run".into());
    }
    for (i, l) in post.call_lists.iter().enumerate() {
        if usize::from(l.first) + usize::from(l.len) > post.globals.len() {
            bad(
                Item::CallList(i),
                format!(
                    "the list `{}` fills globals {} to {}, and the post has {} globals",
                    l.name,
                    l.first,
                    usize::from(l.first) + usize::from(l.len),
                    post.globals.len()
                ),
            );
        }
    }
    for (i, c) in post.comments.iter().enumerate() {
        let stands_before = match &c.on {
            CommentTarget::Post => true,
            CommentTarget::Variable(v) => usize::from(*v) < post.variables.len(),
            CommentTarget::Function(f) => usize::from(*f) < post.functions.len(),
            CommentTarget::Handler(k) => post.handlers.iter().any(|h| &h.key == k),
        };
        if !stands_before {
            bad(Item::Comment(i), format!("the comment stands before {:?}, which the post does not have", c.on));
        }
        if c.lines.iter().any(|l| l.contains(['\n', '\r'])) {
            bad(Item::Comment(i), "a comment line holds a line break".into());
        }
    }
    let mut ids = Ids { post, at: Item::Init, out: Vec::new() };
    for (i, g) in post.globals.iter().enumerate() {
        ids.at = Item::Global(i);
        ids.visit_expr(&g.initial);
    }
    ids.at = Item::Init;
    post.init.iter().for_each(|s| ids.visit_stmt(s));
    for (i, h) in post.handlers.iter().enumerate() {
        ids.at = Item::Handler(i);
        h.body.iter().for_each(|s| ids.visit_stmt(s));
    }
    for (i, f) in post.functions.iter().enumerate() {
        ids.at = Item::Function(i);
        match &f.body {
            Body::Native(body) => {
                if f.params.len() > usize::from(f.slots) {
                    ids.bad(format!("`{}` has {} parameters and only {} slots", f.name, f.params.len(), f.slots));
                }
                body.iter().for_each(|s| ids.visit_stmt(s));
            }
            Body::Script(id) => ids.script(*id),
        }
    }
    out.append(&mut ids.out);
    out
}

/// Checks the ids the code refers to.
struct Ids<'p> {
    post: &'p Post,
    at: Item,
    out: Vec<Invalid>,
}

impl Ids<'_> {
    fn bad(&mut self, message: String) {
        self.out.push(Invalid { at: self.at, message });
    }

    fn check(&mut self, what: &str, id: usize, len: usize) {
        if id >= len {
            self.bad(format!("{what} {id} does not exist (the post has {len})"));
        }
    }

    fn var(&mut self, id: crate::VarId) {
        self.check("variable", id.index(), self.post.variables.len());
    }

    fn script(&mut self, id: crate::ScriptId) {
        self.check("script", id.index(), self.post.scripts.len());
    }
}

impl Visit for Ids<'_> {
    fn visit_stmt(&mut self, stmt: &Stmt) {
        match stmt {
            Stmt::Script(id) => self.script(*id),
            Stmt::Assign(Place::Var(id), _) | Stmt::Forget(id) => self.var(*id),
            Stmt::Assign(Place::Global(g), _) => self.check("global", usize::from(*g), self.post.globals.len()),
            _ => {}
        }
        walk_stmt(self, stmt);
    }

    fn visit_piece(&mut self, piece: &Piece) {
        if let Piece::Var(id) = piece {
            self.var(*id);
        }
        walk_piece(self, piece);
    }

    fn visit_expr(&mut self, expr: &Expr) {
        match expr {
            Expr::Var(id) | Expr::Previous(id) | Expr::FormatVar { var: id, .. } => self.var(*id),
            Expr::Format { format, .. } => self.check("format", usize::from(*format), self.post.formats.len()),
            Expr::Call(f, _) => self.check("function", usize::from(*f), self.post.functions.len()),
            Expr::Closure { function, captures } => match self.post.functions.get(function.index()) {
                None => self.check("function", function.index(), self.post.functions.len()),
                Some(f) if f.params.len() < captures.len() => self.bad(format!(
                    "a closure of `{}` captures {} values and the function has {} parameters",
                    f.name,
                    captures.len(),
                    f.params.len()
                )),
                Some(_) => {}
            },
            Expr::Global(g) => self.check("global", usize::from(*g), self.post.globals.len()),
            Expr::Regex { flags, .. } => {
                let mut seen = String::new();
                for c in flags.chars() {
                    if !matches!(c, 'g' | 'i' | 'm') || seen.contains(c) {
                        self.bad(format!(
                            "the regular expression flags `{flags}` are not `g`, `i` and `m`, each at most once"
                        ));
                        break;
                    }
                    seen.push(c);
                }
            }
            _ => {}
        }
        walk_expr(self, expr);
    }
}
