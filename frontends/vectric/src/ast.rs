//! The syntax tree of a Vectric post: one [`Item`] per line (a `SCRIPT`
//! block spans several), in file order. The tree says what each line is and
//! keeps the spans of its parts; what the parts mean (is the label known, is
//! the section known, which value a global needs) is the lowering's job.

use postc_ir::{FileId, Span};

pub use crate::format_spec::FormatSpec;

/// A value with the span of the text it was read from.
#[derive(Clone, Debug, PartialEq)]
pub struct Spanned<T> {
    pub value: T,
    pub span: Span,
}

impl<T> Spanned<T> {
    pub fn new(value: T, span: Span) -> Spanned<T> {
        Spanned { value, span }
    }
}

/// A parsed post file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PostFile {
    pub file: FileId,
    pub items: Vec<Item>,
}

/// One line (or one `SCRIPT` block) of a post; blank lines are left out.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    pub kind: ItemKind,
    /// The whole line, without its line ending.
    pub span: Span,
    /// A blank line stands between this line and the one before (comment
    /// lines stand before what they directly precede).
    pub blank_before: bool,
}

/// What a line is.
#[derive(Clone, Debug, PartialEq)]
pub enum ItemKind {
    /// `+ ...` or `| ...`: the text after the comment character.
    Comment(String),
    /// `NAME = value ...` outside the `VAR` form.
    Global(GlobalStmt),
    /// `VAR NAME = [label|mode|prefix|format|multiplier]`.
    Var(VarDecl),
    /// `begin SECTION`.
    Begin(BeginLine),
    /// `"..."`: one output line.
    Output(QuotedText),
    /// `<!>call` or `"<!>call"`: a Lua call.
    ScriptCall(Spanned<String>),
    /// `SCRIPT` ... `ENDSCRIPT`: the Lua text between the two lines.
    ScriptBlock(Spanned<String>),
    /// Text the parser could not read as anything (already reported).
    Stray(String),
}

/// `NAME = value value ...`
#[derive(Clone, Debug, PartialEq)]
pub struct GlobalStmt {
    pub name: Spanned<String>,
    pub values: Vec<Spanned<Value>>,
}

/// One value of a global statement.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A quoted string.
    Text(QuotedText),
    /// A bare number.
    Number(f64),
    /// A bare word (`A`, `YES`, `-A`).
    Word(String),
}

/// A quoted string: its pieces, and whether it was closed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuotedText {
    pub pieces: Vec<Spanned<TextPiece>>,
    /// The text between the quotes, as written.
    pub raw: String,
    /// The closing quote was found (an unclosed string runs to the end of
    /// its line).
    pub closed: bool,
}

/// A piece of a quoted string.
#[derive(Clone, Debug, PartialEq)]
pub enum TextPiece {
    /// Literal text.
    Text(String),
    /// `[LABEL]`: the label as written, without the brackets.
    Label(String),
    /// `[nn]`: the character with that code.
    Code(u8),
}

impl QuotedText {
    /// The text of a string whose `[nn]` codes are decoded and whose labels
    /// are kept as written (for names, extensions and units).
    pub fn plain(&self) -> String {
        let mut out = String::new();
        for piece in &self.pieces {
            match &piece.value {
                TextPiece::Text(t) => out.push_str(t),
                TextPiece::Label(l) => {
                    out.push('[');
                    out.push_str(l);
                    out.push(']');
                }
                TextPiece::Code(c) => out.push(char::from(*c)),
            }
        }
        out
    }
}

/// `VAR NAME = ...`
#[derive(Clone, Debug, PartialEq)]
pub struct VarDecl {
    /// The variable name; `None` when the line has none (reported).
    pub name: Option<Spanned<String>>,
    pub body: VarBody,
}

/// What follows `VAR NAME =`.
#[derive(Clone, Debug, PartialEq)]
pub enum VarBody {
    /// `[label|mode|prefix|format|multiplier]`.
    Fields(Box<VarFields>),
    /// Plain values: `VAR MIN_ARC_RADIUS = 0.04` is a global statement.
    Values(Vec<Spanned<Value>>),
    /// Fields that could not be read (reported).
    Malformed,
    /// Nothing readable after `=` (reported).
    Missing,
}

/// The fields of a `VAR`, each already checked.
#[derive(Clone, Debug, PartialEq)]
pub struct VarFields {
    /// The label, blanks around it trimmed.
    pub label: Spanned<String>,
    /// `A` or `C`.
    pub mode: Spanned<OutputMode>,
    /// Every character between the bars, blanks included.
    pub prefix: Spanned<String>,
    /// The prefix field was left out (`[N|A|1.0]`).
    pub prefix_omitted: bool,
    pub format: Spanned<FormatSpec>,
    pub multiplier: Option<Spanned<f64>>,
    /// From `[` to `]`.
    pub span: Span,
}

/// When a variable prints.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum OutputMode {
    /// `A`: every time.
    #[default]
    Always,
    /// `C`: only when its text changes.
    OnChange,
}

/// `begin NAME`: the words after `begin` (more than one only when the name
/// has a stray blank or stray text follows it).
#[derive(Clone, Debug, PartialEq)]
pub struct BeginLine {
    pub words: Vec<Spanned<String>>,
}
