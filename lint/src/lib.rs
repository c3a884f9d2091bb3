//! # postc lint
//!
//! Checks over a compiled, validated post ([`postc_ir::Post`]) for the
//! mistakes that compile cleanly and only show on the machine: a feed or
//! spindle speed the post never prints, a comment a tool name can break, a
//! tool change with the tool still in the work, what a Vectric product
//! does not support, a `POST_NAME` that promises what the post does not
//! do, and things declared and never used.
//!
//! One rule per file under [`rules`], each with its code (`LN0xx`, listed in
//! docs/diagnostics.md), a test of a post that fires it and of one that
//! does not. [`lint`] runs every rule; `postc check` (through
//! [`check_post`], shared with the Python package) and the language server
//! call it on every post that compiles.
//!
//! Rules read the IR, not a dialect's syntax: what a rule needs to know
//! about the output (which sections print a feed) it learns from the
//! output lines of the handlers. A post whose handlers run code (CIMCO
//! functions, VcPost Subs) writes text the rule cannot see before running
//! it; the rules that need the whole output skip such posts rather than
//! guess.

use postc_ir::{Diagnostic, Dispatch, Expr, HandlerKey, Piece, Post, Quantity, Section, Stmt, ValueSource};

pub mod check;
pub mod config;
pub mod product;
pub mod rules;

pub use check::{check_post, check_post_bytes};
pub use product::Product;

/// What a lint run may be told besides the post.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// The Vectric product the post is for (`postc check --product`).
    pub product: Option<Product>,
}

/// Every lint finding for `post`.
pub fn lint(post: &Post, options: &Options) -> Vec<Diagnostic> {
    let cx = Context { post };
    let mut out = Vec::new();
    for rule in rules::ALL {
        (rule.check)(&cx, options, &mut out);
    }
    out
}

/// One rule: its code (its summary and documentation are the registry's,
/// `postc_ir::codes`), what it is called, and its check.
pub struct Rule {
    pub code: &'static str,
    pub name: &'static str,
    pub check: fn(&Context, &Options, &mut Vec<Diagnostic>),
}

/// The post being linted, with the questions rules ask of it.
pub struct Context<'p> {
    pub post: &'p Post,
}

impl<'p> Context<'p> {
    /// Whether every handler is output lines only (a Vectric post, or any
    /// post written that way): then the lines are all the post writes.
    pub fn straight_lines(&self) -> bool {
        self.post.info.dispatch == Dispatch::Sections
            && self.post.scripts.iter().all(|s| s.language != postc_ir::ScriptLanguage::Rhai)
            && self
                .post
                .handlers
                .iter()
                .all(|h| h.body.iter().all(|s| matches!(s, Stmt::Line { .. } | Stmt::Script(_))))
    }

    /// Whether the post writes G-code (some line has a G0-G3 move word).
    pub fn writes_gcode(&self) -> bool {
        self.post.handlers.iter().flat_map(|h| &h.body).any(|s| match s {
            Stmt::Line { pieces, .. } => {
                let t = literal_text(pieces).to_ascii_uppercase();
                ["G0", "G1", "G2", "G3", "G00", "G01", "G02", "G03"].iter().any(|g| rules::has_word(&t, g))
            }
            _ => false,
        })
    }

    /// The output lines of a section's handler, with their spans.
    pub fn lines(&self, section: Section) -> impl Iterator<Item = (&'p [Piece], Option<postc_ir::Span>)> {
        self.post.section(section).into_iter().flat_map(|h| {
            h.body.iter().filter_map(|s| match s {
                Stmt::Line { pieces, span } => Some((pieces.as_slice(), *span)),
                _ => None,
            })
        })
    }

    /// The quantity a piece prints, when it is a variable reading one.
    pub fn quantity(&self, piece: &Piece) -> Option<Quantity> {
        match piece {
            Piece::Var(v) => match self.post.variables.get(v.index())?.source {
                ValueSource::Quantity(q) => Some(q),
                ValueSource::Assigned => None,
            },
            _ => None,
        }
    }

    /// Whether any line of the section prints one of `quantities`.
    pub fn prints(&self, section: Section, quantities: &[Quantity]) -> bool {
        self.lines(section)
            .any(|(pieces, _)| pieces.iter().any(|p| self.quantity(p).is_some_and(|q| quantities.contains(&q))))
    }

    /// Whether the post has a handler for the section.
    pub fn has(&self, section: Section) -> bool {
        self.post.section(section).is_some()
    }

    /// The span of a section's handler (its `begin` line).
    pub fn section_span(&self, section: Section) -> Option<postc_ir::Span> {
        self.post.section(section).and_then(|h| h.span)
    }

    /// The sections the post has, in the order of its handlers.
    pub fn sections(&self) -> impl Iterator<Item = Section> + '_ {
        self.post.handlers.iter().filter_map(|h| match h.key {
            HandlerKey::Section(s) => Some(s),
            HandlerKey::Word(_) => None,
        })
    }
}

/// The literal text of a line's pieces, variables left out.
pub fn literal_text(pieces: &[Piece]) -> String {
    let mut s = String::new();
    for p in pieces {
        if let Piece::Text(bytes) = p {
            s.push_str(&String::from_utf8_lossy(bytes));
        }
    }
    s
}

/// Every expression of a post's code, for rules that look for uses.
pub fn each_expr(post: &Post, f: &mut dyn FnMut(&Expr)) {
    use postc_ir::visit::{Visit, walk_expr};
    struct Each<'f>(&'f mut dyn FnMut(&Expr));
    impl Visit for Each<'_> {
        fn visit_expr(&mut self, e: &Expr) {
            (self.0)(e);
            walk_expr(self, e);
        }
    }
    Each(f).visit_post(post);
}
