//! Lowering: the syntax tree to a [`postc_ir::Post`].
//!
//! - Each Sub or Function becomes a [`Function`] with a native body. A Sub
//!   whose name is an APT major word or a composites routine (see
//!   [`crate::routines`]) also becomes a [`Handler`] keyed
//!   `Word(NAME in upper case)` whose body calls the function.
//! - Statements outside any Sub become `Post::init`, in file order;
//!   register properties among them are applied when compiling.
//! - Registers become [`Variable`]s (`ValueSource::Assigned`, or the block
//!   number for `N`) with one [`postc_ir::NumberFormat`] each; every other
//!   name outside a Sub's locals is a [`Global`].
//! - Keyword comments are kept as `PostInfo::subs`
//!   ([`mod@crate::signatures`]).
//!
//! The passes: collect Subs, collect registers, collect what each global
//! holds (number or text) and which names are ever set; then lower the items
//! in file order; then build variables, handlers and notes and warn about
//! variables that are read but never set.

mod control;
mod expr;
mod names;
pub mod options;
mod stmt;
pub(crate) mod template;
mod walk;

use std::collections::{HashMap, HashSet};

use postc_ir::post::{FormatId, FunctionId, GlobalId, LocalId, Section, VarId};
use postc_ir::{
    Body, CommentTarget, Diagnostic, Dialect, Dispatch, Expr as IrExpr, Function, Global, Handler, HandlerKey, Post,
    Quantity, Stmt as IrStmt, ValueSource, Variable,
};

use crate::ast::{CommentKind, Item, ProcKind, Program};
use crate::diagnostics as codes;
use crate::registers::RegisterSpec;

pub use template::{TemplatePart, out_parts, split};

/// Deepest expression (in tree levels) a statement may hold.
pub const MAX_EXPR_DEPTH: usize = 200;

/// A Sub or Function as callers see it.
#[derive(Clone, Debug)]
struct ProcInfo {
    id: FunctionId,
    kind: ProcKind,
    params: usize,
}

/// A global as the lowering tracks it.
#[derive(Clone, Debug)]
struct GlobalInfo {
    index: GlobalId,
    constant: bool,
    declared: bool,
    first_read: Option<postc_ir::Span>,
}

/// The locals of the Sub being lowered.
#[derive(Debug, Default)]
struct Scope {
    locals: HashMap<String, (LocalId, bool)>,
    names: Vec<String>,
    function: Option<String>,
    ret: Option<LocalId>,
}

/// Kinds of loops `Exit` can leave.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LoopFrame {
    For,
    Do,
    While,
}

pub(crate) struct Lowerer<'a> {
    program: &'a Program,
    legacy_encoding: bool,
    post: Post,
    diagnostics: Vec<Diagnostic>,
    procs: HashMap<String, ProcInfo>,
    proc_ids: Vec<FunctionId>,
    registers: HashMap<String, VarId>,
    specs: Vec<RegisterSpec>,
    sequence: Option<VarId>,
    globals: HashMap<String, GlobalInfo>,
    text_globals: HashMap<String, bool>,
    assigned: HashSet<String>,
    host_functions: HashMap<String, FunctionId>,
    scope: Option<Scope>,
    loops: Vec<LoopFrame>,
    hidden: u32,
    /// The post names Subs after Vectric sections (`Sub FEED_MOVE`): it is
    /// driven by the kind of each move, and registers named after Vectric
    /// labels print those values (postc's extension, docs/vcpost.md).
    sections: bool,
}

/// Lowers a parsed post. `legacy_encoding` says the file was Windows-1252,
/// so literal output text is written back in that encoding.
pub fn lower(program: &Program, legacy_encoding: bool) -> (Post, Vec<Diagnostic>) {
    let mut l = Lowerer {
        program,
        legacy_encoding,
        post: Post::default(),
        diagnostics: Vec::new(),
        procs: HashMap::new(),
        proc_ids: Vec::new(),
        registers: HashMap::new(),
        specs: Vec::new(),
        sequence: None,
        globals: HashMap::new(),
        text_globals: HashMap::new(),
        assigned: HashSet::new(),
        host_functions: HashMap::new(),
        scope: None,
        loops: Vec::new(),
        hidden: 0,
        sections: is_section_post(program),
    };
    l.post.info.dialect = Dialect::VcPost;
    l.post.info.dispatch = if l.sections { Dispatch::Sections } else { Dispatch::AptWords };
    if legacy_encoding {
        l.post.info.text_encoding = postc_ir::post::TextEncoding::Windows1252;
    }
    l.collect_procs();
    names::collect(&mut l);
    let mut index = 0;
    for item in &program.items {
        match item {
            Item::Stmt(s) => {
                let lowered = l.stmt(s);
                l.post.init.extend(lowered);
            }
            Item::Proc(p) => {
                l.proc(p, index);
                index += 1;
            }
        }
    }
    l.finish();
    l.comments();
    (l.post, l.diagnostics)
}

/// A post driven by sections: a Sub is named after a section, and none
/// is an APT word or composites routine handler or has a keyword comment
/// (those posts are driven by records and calls; their `Sub INSERT` or
/// `Sub Comment` is not a section).
fn is_section_post(program: &Program) -> bool {
    let procs = || {
        program.items.iter().filter_map(|i| match i {
            Item::Proc(p) => Some(p),
            Item::Stmt(_) => None,
        })
    };
    procs().any(|p| Section::from_name(&p.name.text).is_some())
        && !procs().any(|p| {
            crate::routines::handler_word(&p.name.text).is_some()
                || p.keyword_comments.iter().any(|k| matches!(k.kind, CommentKind::Keyword(_)))
        })
}

impl Lowerer<'_> {
    /// The source's comments: the file's head, and each Sub's before its
    /// section (in a post driven by sections) or its function.
    fn comments(&mut self) {
        self.post.add_comment(CommentTarget::Post, self.program.doc.clone());
        let procs = self.program.items.iter().filter_map(|i| match i {
            Item::Proc(p) => Some(p),
            Item::Stmt(_) => None,
        });
        for (p, id) in procs.zip(self.proc_ids.clone()) {
            let section = Section::from_name(&p.name.text)
                .map(HandlerKey::Section)
                .filter(|k| self.sections && self.post.handlers.iter().any(|h| &h.key == k));
            let on = match section {
                Some(k) if !self.post.comments.iter().any(|c| c.on == CommentTarget::Handler(k.clone())) => {
                    CommentTarget::Handler(k)
                }
                _ => CommentTarget::Function(id),
            };
            self.post.add_comment(on, p.doc.clone());
        }
    }

    fn collect_procs(&mut self) {
        for item in &self.program.items {
            let Item::Proc(p) = item else { continue };
            let id = FunctionId::new(self.post.functions.len() as u16);
            self.proc_ids.push(id);
            self.post.functions.push(Function {
                name: p.name.text.clone(),
                params: p.params.iter().map(|f| f.name.text.clone()).collect(),
                slots: 0,
                locals: Vec::new(),
                body: Body::Native(Vec::new()),
                span: Some(p.header),
                why_script: None,
                source: Vec::new(),
                uses_arguments: false,
                starts_undefined: false,
            });
            let key = p.name.key();
            if !crate::token::is_valid_name(&p.name.text) {
                continue;
            }
            if crate::builtins::lookup(&key).is_some() {
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::DUPLICATE_SUB,
                        format!("`{}` is a built-in function and cannot name a {}", p.name.text, p.kind.as_str()),
                    )
                    .at(p.name.span, "choose another name"),
                );
                continue;
            }
            if let Some(first) = self.procs.get(&key) {
                let first_span = self.post.functions[first.id.index()].span.unwrap_or(p.header);
                self.diagnostics.push(
                    Diagnostic::error(codes::DUPLICATE_SUB, format!("`{}` is defined twice", p.name.text))
                        .at(p.name.span, "second definition")
                        .also(first_span, "first definition; calls go there")
                        .help("rename or remove one of them"),
                );
                continue;
            }
            self.procs.insert(key, ProcInfo { id, kind: p.kind, params: p.params.len() });
        }
    }

    fn finish(&mut self) {
        if self.post.options.tape_splitting.as_ref().is_some_and(|t| t.max_lines == 0) {
            self.diagnostics.push(
                Diagnostic::error(codes::BAD_PROPERTY_VALUE, "tape splitting is set up without `Postc.TapeSplitLines`")
                    .help("say how many lines each part holds: `Postc.TapeSplitLines = 5000`"),
            );
        }
        let mut variables = Vec::with_capacity(self.specs.len());
        for (index, spec) in self.specs.iter().enumerate() {
            let (prefix, format, modality) = spec.finish(&mut self.diagnostics);
            let format_id = FormatId::new(self.post.formats.len() as u16);
            self.post.formats.push(format);
            let label = if self.sections { Quantity::from_label(&spec.name) } else { None };
            let source = if VarId::from_usize(index) == self.sequence {
                ValueSource::Quantity(Quantity::BlockNumber)
            } else if let Some(q) = label {
                ValueSource::Quantity(q)
            } else {
                ValueSource::Assigned
            };
            variables.push(Variable {
                name: spec.name.clone(),
                source,
                prefix,
                format: format_id,
                modality,
                span: spec.span,
            });
        }
        self.post.variables = variables;
        self.handlers();
        self.never_set();
        let signatures = crate::signatures::signatures(self.program);
        self.post.info.subs = crate::signatures::to_ir(&signatures);
    }

    fn handlers(&mut self) {
        if self.sections {
            self.section_handlers();
            return;
        }
        let mut seen = HashSet::new();
        let mut index = 0;
        for item in &self.program.items {
            let Item::Proc(p) = item else { continue };
            let id = self.proc_ids[index];
            index += 1;
            let Some(word) = crate::routines::handler_word(&p.name.text) else { continue };
            if !seen.insert(word.clone()) {
                continue;
            }
            if p.keyword_comments.iter().any(|k| matches!(k.kind, CommentKind::Keyword(_))) {
                continue;
            }
            if !p.params.is_empty() {
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::HANDLER_WITH_PARAMS,
                        format!(
                            "Sub `{}` is called for each {word} record or event and cannot take parameters",
                            p.name.text
                        ),
                    )
                    .at(p.header, "remove the parameter list")
                    .help("the values it needs arrive as registers and variables (X, Y, Z, F, ...)"),
                );
                continue;
            }
            self.post.handlers.push(Handler {
                key: HandlerKey::Word(word),
                body: vec![IrStmt::Eval(IrExpr::Call(id, Vec::new()))],
                span: Some(p.header),
            });
        }
    }

    /// The handlers of a post driven by sections: each `Sub` named after a
    /// section. A Sub of output lines only is those lines (as a Vectric
    /// section is); any other calls the Sub.
    fn section_handlers(&mut self) {
        let mut index = 0;
        for item in &self.program.items {
            let Item::Proc(p) = item else { continue };
            let id = self.proc_ids[index];
            index += 1;
            let Some(section) = Section::from_name(&p.name.text) else { continue };
            if self.post.handlers.iter().any(|h| h.key == HandlerKey::Section(section)) {
                continue;
            }
            if !p.params.is_empty() {
                self.diagnostics.push(
                    Diagnostic::error(
                        codes::HANDLER_WITH_PARAMS,
                        format!("Sub `{}` runs for its section and cannot take parameters", p.name.text),
                    )
                    .at(p.header, "remove the parameter list")
                    .help("the values it prints arrive as registers named after the labels (X, Y, Z, F, ...)"),
                );
                continue;
            }
            let body = match self.post.functions.get(id.index()).map(|f| &f.body) {
                Some(Body::Native(b)) if b.iter().all(|s| matches!(s, IrStmt::Line { .. })) => b.clone(),
                _ => vec![IrStmt::Eval(IrExpr::Call(id, Vec::new()))],
            };
            self.post.handlers.push(Handler { key: HandlerKey::Section(section), body, span: Some(p.header) });
        }
    }

    fn never_set(&mut self) {
        let mut unset: Vec<(String, postc_ir::Span)> = Vec::new();
        for (key, g) in &self.globals {
            let Some(at) = g.first_read else { continue };
            if g.declared
                || g.constant
                || self.assigned.contains(key)
                || crate::routines::runtime_variable(key).is_some()
            {
                continue;
            }
            let name = self.post.globals.get(g.index.index()).map_or(key.clone(), |g| g.name.clone());
            unset.push((name, at));
        }
        unset.sort_by_key(|(_, at)| at.start);
        let candidates: Vec<String> = self
            .post
            .globals
            .iter()
            .filter(|g| self.assigned.contains(&g.name.to_lowercase()))
            .map(|g| g.name.clone())
            .chain(self.specs.iter().map(|s| s.name.clone()))
            .collect();
        for (name, at) in unset {
            let mut d =
                Diagnostic::warning(codes::NEVER_SET, format!("`{name}` is read but never set, so it is always 0"))
                    .at(at, "never assigned anywhere in the post");
            d = match codes::suggest(&name, candidates.iter().map(String::as_str)) {
                Some(s) => d.help(format!("did you mean `{s}`?")),
                None => {
                    d.help(format!("assign it (`{name} = ...`) or declare it with `Dim {name}` if the runtime sets it"))
                }
            };
            self.diagnostics.push(d);
        }
    }

    /// A new global; its initial value is text when the post only ever
    /// assigns text to it or the runtime sets it to text.
    fn new_global(&mut self, name: &str, initial: Option<IrExpr>, constant: bool, declared: bool) -> GlobalId {
        let key = name.to_lowercase();
        if let Some(g) = self.globals.get(&key) {
            return g.index;
        }
        let index = match u16::try_from(self.post.globals.len()) {
            Ok(i) if i < u16::MAX => GlobalId::new(i),
            _ => return GlobalId::new(self.too_many("variables")),
        };
        let text = self.text_globals.get(&key).copied().unwrap_or(false)
            || crate::routines::runtime_variable(name) == Some(crate::routines::VarType::Text);
        let initial = initial.unwrap_or(if text { IrExpr::Text(String::new()) } else { IrExpr::Number(0.0) });
        self.post.globals.push(Global { name: name.to_string(), initial, implicit: false, span: None });
        self.globals.insert(key, GlobalInfo { index, constant, declared, first_read: None });
        index
    }

    fn too_many(&mut self, what: &str) -> u16 {
        if !self.diagnostics.iter().any(|d| d.code == codes::TOO_COMPLEX && d.labels.is_empty()) {
            self.diagnostics
                .push(Diagnostic::error(codes::TOO_COMPLEX, format!("this post has too many {what} (at most 65535)")));
        }
        0
    }
}
