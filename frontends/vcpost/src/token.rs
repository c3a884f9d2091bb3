//! Tokens of the VcPost language: what the lexer produces and the line
//! parser reads, the keyword table (case-insensitive, as in BASIC) and the
//! set of reserved names that cannot name a probe-cycle parameter.

use std::fmt;

/// One token.
#[derive(Clone, Debug, PartialEq)]
pub enum Token {
    /// End of a physical line (a `_` continuation joins two lines, so no
    /// newline token is produced there).
    Newline,
    /// `:` separates statements on one line.
    Colon,
    Comma,
    Dot,
    LParen,
    RParen,
    Op(Op),
    Number(f64),
    /// A string literal, with `""` already turned into `"`.
    Str(String),
    /// A name, as written (a trailing `$` type character is dropped;
    /// `[End]` gives the name `End`).
    Ident(String),
    Kw(Kw),
    /// A `'` or `Rem` comment: the text after the marker. Comments are taken
    /// out of the stream before parsing.
    Comment(String),
    /// Something the lexer could not read (already reported), or a line
    /// replaced because it was too long or too deeply nested.
    Error,
}

/// Operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    Plus,
    Minus,
    Star,
    Slash,
    Backslash,
    Caret,
    Amp,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

impl Op {
    pub fn as_str(self) -> &'static str {
        match self {
            Op::Plus => "+",
            Op::Minus => "-",
            Op::Star => "*",
            Op::Slash => "/",
            Op::Backslash => "\\",
            Op::Caret => "^",
            Op::Amp => "&",
            Op::Eq => "=",
            Op::Ne => "<>",
            Op::Lt => "<",
            Op::Le => "<=",
            Op::Gt => ">",
            Op::Ge => ">=",
        }
    }
}

macro_rules! keywords {
    ($($name:ident = $text:literal,)*) => {
        /// Language keywords. They are matched without regard to case and
        /// cannot be used as names (write `[End]` to name a Sub `End`).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Kw { $($name,)* }

        impl Kw {
            /// Every keyword.
            pub const ALL: &'static [Kw] = &[$(Kw::$name,)*];

            /// The keyword as the documentation spells it.
            pub fn as_str(self) -> &'static str {
                match self { $(Kw::$name => $text,)* }
            }
        }
    };
}

keywords! {
    And = "And",
    As = "As",
    Call = "Call",
    Case = "Case",
    Const = "Const",
    Dim = "Dim",
    Do = "Do",
    Else = "Else",
    ElseIf = "ElseIf",
    End = "End",
    Exit = "Exit",
    False = "False",
    For = "For",
    Function = "Function",
    If = "If",
    Is = "Is",
    Let = "Let",
    Loop = "Loop",
    Mod = "Mod",
    Next = "Next",
    Not = "Not",
    Or = "Or",
    Out = "Out",
    Private = "Private",
    Public = "Public",
    Rem = "Rem",
    Select = "Select",
    Step = "Step",
    Sub = "Sub",
    Then = "Then",
    To = "To",
    True = "True",
    Until = "Until",
    Wend = "Wend",
    While = "While",
    Xor = "Xor",
}

impl Kw {
    /// The keyword a word stands for, ignoring case.
    pub fn from_word(word: &str) -> Option<Kw> {
        Kw::ALL.iter().copied().find(|k| k.as_str().eq_ignore_ascii_case(word))
    }
}

/// Type names accepted after `As`; they are reserved as parameter names.
pub const TYPE_NAMES: &[&str] =
    &["Boolean", "Byte", "Currency", "Date", "Double", "Integer", "Long", "Object", "Single", "String", "Variant"];

/// Whether a name is reserved: a keyword, a built-in function, a type name,
/// or `N` (the sequence number). Reserved names cannot be parameters.
pub fn is_reserved(name: &str) -> bool {
    Kw::from_word(name).is_some()
        || crate::builtins::lookup(name).is_some()
        || TYPE_NAMES.iter().any(|t| t.eq_ignore_ascii_case(name))
        || name.eq_ignore_ascii_case("N")
}

/// Whether a word is a valid name: a letter, then letters, digits and `_`.
pub fn is_valid_name(word: &str) -> bool {
    let mut chars = word.chars();
    chars.next().is_some_and(char::is_alphabetic) && chars.all(|c| c.is_alphanumeric() || c == '_')
}

impl fmt::Display for Token {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Token::Newline => f.write_str("end of line"),
            Token::Colon => f.write_str("`:`"),
            Token::Comma => f.write_str("`,`"),
            Token::Dot => f.write_str("`.`"),
            Token::LParen => f.write_str("`(`"),
            Token::RParen => f.write_str("`)`"),
            Token::Op(op) => write!(f, "`{}`", op.as_str()),
            Token::Number(_) => f.write_str("a number"),
            Token::Str(_) => f.write_str("a string"),
            Token::Ident(name) => write!(f, "`{name}`"),
            Token::Kw(k) => write!(f, "`{}`", k.as_str()),
            Token::Comment(_) => f.write_str("a comment"),
            Token::Error => f.write_str("unreadable text"),
        }
    }
}
