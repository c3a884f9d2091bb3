//! The meaning of a post before it becomes IR: its global settings, `VAR`s
//! and sections, merged over the `POST_BASE` chain (base first, each later
//! file overriding: sections as wholes, `VAR`s and globals one by one).
//! Output lines keep their labels unresolved until every file is in, so a
//! derived post's `VAR` changes how a base post's section prints.

use postc_ir::post::{RotaryWrap, SpindleSpeedRange, Substitution, TapeSplitting};
use postc_ir::{Modality, Quantity, Section, Span, Units};

use crate::format_spec::FormatSpec;
use crate::names::GlobalName;

/// A merged post.
#[derive(Debug, Default)]
pub struct Model {
    pub globals: Vec<GlobalEntry>,
    pub vars: Vec<VarDef>,
    pub sections: Vec<SectionDef>,
    pub script_blocks: Vec<ScriptDef>,
    /// Some file of the chain names a `POST_BASE`.
    pub has_post_base: bool,
    /// Comment lines that stand before no `VAR` or section: the file's
    /// head, and comments among the global statements.
    pub doc: Vec<String>,
    /// Counts definitions, so that "the later one" is known across files.
    pub next_seq: usize,
}

/// The value of a global statement, interpreted.
#[derive(Clone, Debug, PartialEq)]
pub enum GlobalValue {
    Text(String),
    Flag(bool),
    Number(f64),
    Units(Units),
    Bytes(Vec<u8>),
    Substitutions(Vec<Substitution>),
    /// `None`: splitting is off.
    Tape(Option<TapeSplitting>),
    SpindleRange(SpindleSpeedRange),
    /// `None`: no wrapping (`"NO"`).
    Wrap(Option<RotaryWrap>),
}

/// One global statement in force.
#[derive(Clone, Debug)]
pub struct GlobalEntry {
    pub name: GlobalName,
    pub value: GlobalValue,
    pub span: Span,
    pub seq: usize,
}

/// One `VAR` in force.
#[derive(Clone, Debug)]
pub struct VarDef {
    /// Upper case.
    pub name: String,
    pub label: String,
    /// The label as written in the `VAR`.
    pub label_span: Span,
    pub quantity: Quantity,
    pub modality: Modality,
    /// In the bytes of its file's encoding.
    pub prefix: Vec<u8>,
    pub format: FormatSpec,
    /// The format as written in the `VAR`.
    pub format_span: Span,
    pub multiplier: f64,
    pub seq: usize,
    /// The `VAR`'s fields, `[` to `]`.
    pub span: Span,
    /// The comment lines before the `VAR`.
    pub doc: Vec<String>,
}

/// One section in force.
#[derive(Clone, Debug)]
pub struct SectionDef {
    pub section: Section,
    /// The `begin` line.
    pub span: Span,
    pub lines: Vec<LineDef>,
    /// The comment lines before `begin` and among the section's lines.
    pub doc: Vec<String>,
}

/// A line of a section.
#[derive(Clone, Debug)]
pub enum LineDef {
    /// An output line and where it is in its file.
    Output(Vec<PieceDef>, Span),
    Script(ScriptDef),
}

/// A piece of an output line.
#[derive(Clone, Debug)]
pub enum PieceDef {
    /// Literal bytes (text in its file's encoding, `[nn]` codes as bytes).
    Bytes(Vec<u8>),
    /// `[LABEL]`, resolved when the post is emitted; `literal` is what
    /// prints if no variable has that label.
    Label { label: String, span: Span, literal: Vec<u8> },
}

/// Lua code and where it sits.
#[derive(Clone, Debug)]
pub struct ScriptDef {
    pub code: String,
    pub span: Span,
}

impl Model {
    /// The number for the next definition.
    pub fn seq(&mut self) -> usize {
        self.next_seq += 1;
        self.next_seq
    }

    /// The global statement in force for `name`.
    pub fn global(&self, name: GlobalName) -> Option<&GlobalEntry> {
        self.globals.iter().find(|g| g.name == name)
    }
}
