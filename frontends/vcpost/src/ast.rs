//! The syntax tree of a VcPost file: statements outside any Sub, Subs and
//! Functions with their bodies and keyword comments, statements and
//! expressions, every node with the byte span it came from.

use postc_ir::{FileId, Span};

/// A parsed post.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub file: FileId,
    /// Statements outside any Sub and the Subs, in file order.
    pub items: Vec<Item>,
    /// Keyword comments found outside every Sub (ignored, warned).
    pub stray_keyword_comments: Vec<KeywordComment>,
    /// The comment lines at the head of the file (a converted post's
    /// header note left out), each the text after `'` or `Rem`.
    pub doc: Vec<String>,
}

/// One thing at the top of a file.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Stmt(Stmt),
    Proc(Procedure),
}

/// A name as written, with its span. Names ignore case; [`Name::key`] is
/// the form to compare.
#[derive(Clone, Debug, PartialEq)]
pub struct Name {
    pub text: String,
    pub span: Span,
}

impl Name {
    /// The name folded to lower case, for lookups.
    pub fn key(&self) -> String {
        self.text.to_lowercase()
    }

    /// Whether it is the given name, ignoring case.
    pub fn is(&self, other: &str) -> bool {
        self.text.eq_ignore_ascii_case(other) || self.key() == other.to_lowercase()
    }
}

/// `Sub` or `Function`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProcKind {
    Sub,
    Function,
}

impl ProcKind {
    pub fn as_str(self) -> &'static str {
        match self {
            ProcKind::Sub => "Sub",
            ProcKind::Function => "Function",
        }
    }
}

/// A Sub or Function.
#[derive(Clone, Debug, PartialEq)]
pub struct Procedure {
    pub kind: ProcKind,
    pub name: Name,
    /// Formal parameters (`Sub Name(A, B)`); locals passed by value.
    pub params: Vec<FormalParam>,
    pub body: Vec<Stmt>,
    /// The `Sub ...` line.
    pub header: Span,
    /// The `End Sub` line, when there is one.
    pub end: Option<Span>,
    /// Keyword comments between the header and the end, in order.
    pub keyword_comments: Vec<KeywordComment>,
    /// The comment lines directly before the header.
    pub doc: Vec<String>,
}

/// A formal parameter of a Sub or Function.
#[derive(Clone, Debug, PartialEq)]
pub struct FormalParam {
    pub name: Name,
    /// Declared `ByRef` (postc passes by value anyway).
    pub by_ref: bool,
    pub ty: Option<Name>,
}

/// A keyword comment line: `' #Cycle !X !Y Width` or `' #C1 Operator message`.
#[derive(Clone, Debug, PartialEq)]
pub struct KeywordComment {
    pub kind: CommentKind,
    /// The `#word`.
    pub keyword_span: Span,
    /// Parameters after a cycle keyword (empty for tips).
    pub params: Vec<ParamDecl>,
    /// The whole comment.
    pub span: Span,
}

/// What a keyword comment says.
#[derive(Clone, Debug, PartialEq)]
pub enum CommentKind {
    /// One of the cycle keywords.
    Keyword(SubKeyword),
    /// A tip (`#C1 text`): the slot and the text.
    Tip(TipSlot, String),
    /// A `#word` postc does not know.
    Unknown(String),
}

/// A parameter named in a keyword comment.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamDecl {
    pub name: String,
    pub mandatory: bool,
    pub span: Span,
}

macro_rules! named_enum {
    ($(#[$doc:meta])* $ty:ident { $($name:ident = $text:literal,)* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
        pub enum $ty { $($name,)* }

        impl $ty {
            pub const ALL: &'static [$ty] = &[$($ty::$name,)*];

            /// The word after `#`, as the documentation spells it.
            pub fn as_str(self) -> &'static str {
                match self { $($ty::$name => $text,)* }
            }

            /// The value a word (without `#`, any case) stands for.
            pub fn from_word(word: &str) -> Option<$ty> {
                $ty::ALL.iter().copied().find(|k| k.as_str().eq_ignore_ascii_case(word))
            }
        }
    };
}

named_enum! {
    /// The keywords of keyword comments: the probe-cycle programming ones
    /// (`#Init` ... `#Save`) and the composites ones (`#Primer`, `#Option`,
    /// `#Probe`).
    SubKeyword {
        Init = "Init",
        End = "End",
        Rapid = "Rapid",
        Move = "Move",
        Approach = "Approach",
        Retract = "Retract",
        Cycle = "Cycle",
        Save = "Save",
        Primer = "Primer",
        Option = "Option",
        Probe = "Probe",
    }
}

impl SubKeyword {
    /// Keywords at most one Sub of a post may carry.
    pub fn is_unique(self) -> bool {
        matches!(
            self,
            SubKeyword::Init
                | SubKeyword::End
                | SubKeyword::Rapid
                | SubKeyword::Move
                | SubKeyword::Approach
                | SubKeyword::Retract
                | SubKeyword::Save
        )
    }
}

named_enum! {
    /// Tip slots of composites option Subs: the two text, two number and two
    /// switch parameters.
    TipSlot {
        C1 = "C1",
        C2 = "C2",
        N1 = "N1",
        N2 = "N2",
        S1 = "S1",
        S2 = "S2",
    }
}

/// A statement.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

/// Kinds of statements.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// `X = 1`, `Let X = 1`.
    Assign {
        target: Name,
        value: Expr,
    },
    /// `X.Format = "4.3"`: a register property.
    SetProperty {
        register: Name,
        property: Name,
        value: Expr,
    },
    /// `Dim A, B As String`.
    Dim(Vec<DimItem>),
    /// `Const Safe = 50`.
    Const(Vec<(Name, Expr)>),
    /// `Call Name(args)`, `Name args`, `Name`.
    Call {
        name: Name,
        args: Vec<Expr>,
    },
    /// `Out expr` (or `Out` alone: an empty block).
    Out(Option<Expr>),
    Exit(ExitKind),
    If {
        branches: Vec<(Expr, Vec<Stmt>)>,
        otherwise: Vec<Stmt>,
    },
    Select {
        subject: Expr,
        cases: Vec<CaseArm>,
        otherwise: Vec<Stmt>,
    },
    For(Box<ForLoop>),
    /// `While c ... Wend`, `Do While c ... Loop`, `Do Until c ... Loop`
    /// (`until` set), `Do ... Loop While c` (`at_end` set), `Do ... Loop`.
    Loop {
        test: Option<LoopTest>,
        at_end: bool,
        body: Vec<Stmt>,
        kind: LoopKind,
    },
    /// A line that could not be read (already reported).
    Error,
}

/// `For var = from To to [Step step] ... Next`.
#[derive(Clone, Debug, PartialEq)]
pub struct ForLoop {
    pub var: Name,
    pub from: Expr,
    pub to: Expr,
    pub step: Option<Expr>,
    pub body: Vec<Stmt>,
}

/// `While ... Wend` or `Do ... Loop`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoopKind {
    While,
    Do,
}

/// The test of a loop.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopTest {
    /// `Until`: the loop runs while the condition is false.
    pub until: bool,
    pub cond: Expr,
}

/// One `Dim` entry.
#[derive(Clone, Debug, PartialEq)]
pub struct DimItem {
    pub name: Name,
    /// `Dim A(10)`: arrays are not supported; the span of the bounds.
    pub array: Option<Span>,
    pub ty: Option<Name>,
    pub init: Option<Expr>,
}

/// What `Exit` leaves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExitKind {
    Sub,
    Function,
    For,
    Do,
    While,
}

/// One `Case` line and its statements.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseArm {
    pub tests: Vec<CaseTest>,
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// One test of a `Case` line.
#[derive(Clone, Debug, PartialEq)]
pub enum CaseTest {
    /// `Case 3`
    Value(Expr),
    /// `Case 1 To 5`
    Range(Expr, Expr),
    /// `Case Is > 3`
    Is(BinaryOp, Expr),
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

/// Kinds of expressions.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number(f64),
    Text(String),
    Bool(bool),
    /// A variable, register, constant, or a Function without arguments.
    Name(Name),
    /// `X.Previous`
    Previous(Name),
    /// `X.Something` other than `Previous` (an error when read).
    Property {
        target: Name,
        property: Name,
    },
    /// `Name(args)`: a built-in or a Function.
    Call {
        name: Name,
        args: Vec<Expr>,
    },
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    Paren(Box<Expr>),
    /// Could not be read (already reported).
    Error,
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
}

/// Binary operators, in BASIC's terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    IntDiv,
    Mod,
    Pow,
    Concat,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
    Xor,
}

impl Expr {
    /// Depth of the tree (1 for a leaf).
    pub fn depth(&self) -> usize {
        match &self.kind {
            ExprKind::Call { args, .. } => 1 + args.iter().map(Expr::depth).max().unwrap_or(0),
            ExprKind::Unary(_, e) | ExprKind::Paren(e) => 1 + e.depth(),
            ExprKind::Binary(_, a, b) => 1 + a.depth().max(b.depth()),
            _ => 1,
        }
    }
}
