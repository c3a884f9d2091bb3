//! The tokens of a CIMCO post: what the lexer produces and the parser reads.
//!
//! A [`Token`] knows whether a line break came before it; that is what
//! automatic semicolon insertion and the "no line break here" rules
//! (`return`, postfix `++`) look at. Two tokens compare equal when their
//! kinds are equal, whatever came before them, so the parser can match
//! punctuation with `just`.

use std::fmt;

/// One token.
#[derive(Clone, Copy, Debug)]
pub struct Token<'src> {
    pub kind: TokenKind<'src>,
    /// A line break (or a comment containing one) came before this token.
    pub newline_before: bool,
}

impl PartialEq for Token<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.kind == other.kind
    }
}

impl<'src> Token<'src> {
    pub fn new(kind: TokenKind<'src>) -> Token<'src> {
        Token { kind, newline_before: false }
    }

    pub fn punct(p: Punct) -> Token<'static> {
        Token::new(TokenKind::Punct(p))
    }

    pub fn keyword(k: Keyword) -> Token<'static> {
        Token::new(TokenKind::Keyword(k))
    }

    pub fn is_punct(&self, p: Punct) -> bool {
        self.kind == TokenKind::Punct(p)
    }

    pub fn is_keyword(&self, k: Keyword) -> bool {
        self.kind == TokenKind::Keyword(k)
    }

    pub fn is_ident(&self, name: &str) -> bool {
        self.kind == TokenKind::Ident(name)
    }

    /// Whether a line that starts with this token goes on with the
    /// statement of the line before: a binary operator, a member dot, a
    /// closing bracket, a comma or `?`/`:` (`+` and `-` too: a line that
    /// starts with one is the rest of a sum far more often than a unary
    /// expression statement).
    pub fn continues_before(&self) -> bool {
        match self.kind {
            TokenKind::Punct(p) => !matches!(
                p,
                Punct::LBrace
                    | Punct::RBrace
                    | Punct::Semi
                    | Punct::LParen
                    | Punct::LBracket
                    | Punct::Bang
                    | Punct::Tilde
                    | Punct::PlusPlus
                    | Punct::MinusMinus
            ),
            TokenKind::Keyword(k) => matches!(k, Keyword::In | Keyword::Instanceof),
            _ => false,
        }
    }

    /// Whether the statement cannot end after this token: an operator, an
    /// opening bracket or a comma waits for what follows on the next line.
    pub fn continues_after(&self) -> bool {
        match self.kind {
            TokenKind::Punct(p) => !matches!(
                p,
                Punct::RBrace | Punct::RParen | Punct::RBracket | Punct::Semi | Punct::PlusPlus | Punct::MinusMinus
            ),
            TokenKind::Keyword(k) => matches!(
                k,
                Keyword::In | Keyword::Instanceof | Keyword::New | Keyword::Typeof | Keyword::Void | Keyword::Delete
            ),
            _ => false,
        }
    }

    /// Whether the token can start an expression (used to tell `await x`
    /// from a variable called `await`).
    pub fn starts_expression(&self) -> bool {
        match self.kind {
            TokenKind::Ident(_)
            | TokenKind::Number(_)
            | TokenKind::String(_)
            | TokenKind::Regex { .. }
            | TokenKind::Template(_) => true,
            TokenKind::TemplatePart { head, .. } => head,
            TokenKind::Keyword(k) => matches!(
                k,
                Keyword::This
                    | Keyword::Null
                    | Keyword::True
                    | Keyword::False
                    | Keyword::Function
                    | Keyword::New
                    | Keyword::Typeof
                    | Keyword::Void
                    | Keyword::Delete
            ),
            TokenKind::Punct(p) => matches!(
                p,
                Punct::LParen
                    | Punct::LBracket
                    | Punct::LBrace
                    | Punct::Bang
                    | Punct::Tilde
                    | Punct::Minus
                    | Punct::Plus
                    | Punct::PlusPlus
                    | Punct::MinusMinus
            ),
        }
    }
}

/// The kinds of tokens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TokenKind<'src> {
    /// A name. Contextual words (`let`, `of`, `get`, `set`, `async`,
    /// `await`, `yield`, `undefined`) are names too.
    Ident(&'src str),
    Keyword(Keyword),
    Number(f64),
    /// A string literal: the text between the quotes, escapes not decoded.
    String(&'src str),
    /// `/pattern/flags`
    Regex {
        pattern: &'src str,
        flags: &'src str,
    },
    /// A whole template literal, as CNC-Calc's JavaScript reads it (not
    /// supported; lexed so it can be named): the text between the
    /// backquotes.
    Template(&'src str),
    /// A piece of a template literal as Fusion's JavaScript reads it: the
    /// raw text from a backquote or the `}` that ends a substitution to the
    /// next `${` or backquote, escapes not decoded. `head`: it starts the
    /// literal (after `` ` ``); `tail`: it ends it (before `` ` ``).
    TemplatePart {
        raw: &'src str,
        head: bool,
        tail: bool,
    },
    Punct(Punct),
}

macro_rules! words {
    ($(#[$doc:meta])* $name:ident { $($variant:ident = $text:literal,)* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name { $($variant,)* }

        impl $name {
            /// Every variant, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$variant,)*];

            /// The text of the token.
            pub fn as_str(self) -> &'static str {
                match self { $($name::$variant => $text,)* }
            }
        }
    };
}

words! {
    /// Reserved words: the ES5 keywords and the words ES5 reserves.
    Keyword {
        Break = "break",
        Case = "case",
        Catch = "catch",
        Class = "class",
        Const = "const",
        Continue = "continue",
        Debugger = "debugger",
        Default = "default",
        Delete = "delete",
        Do = "do",
        Else = "else",
        Enum = "enum",
        Export = "export",
        Extends = "extends",
        False = "false",
        Finally = "finally",
        For = "for",
        Function = "function",
        If = "if",
        Import = "import",
        In = "in",
        Instanceof = "instanceof",
        New = "new",
        Null = "null",
        Return = "return",
        Super = "super",
        Switch = "switch",
        This = "this",
        Throw = "throw",
        True = "true",
        Try = "try",
        Typeof = "typeof",
        Var = "var",
        Void = "void",
        While = "while",
        With = "with",
    }
}

words! {
    /// Punctuators, including the newer ones the lexer recognises so that
    /// the parser can name them.
    Punct {
        UShrAssign = ">>>=",
        Ellipsis = "...",
        StrictEq = "===",
        StrictNe = "!==",
        StarStarAssign = "**=",
        ShlAssign = "<<=",
        ShrAssign = ">>=",
        UShr = ">>>",
        AndAssign = "&&=",
        OrAssign = "||=",
        NullishAssign = "??=",
        Arrow = "=>",
        EqEq = "==",
        NotEq = "!=",
        LtEq = "<=",
        GtEq = ">=",
        AmpAmp = "&&",
        PipePipe = "||",
        Nullish = "??",
        QuestionDot = "?.",
        PlusPlus = "++",
        MinusMinus = "--",
        PlusAssign = "+=",
        MinusAssign = "-=",
        StarAssign = "*=",
        SlashAssign = "/=",
        PercentAssign = "%=",
        AmpAssign = "&=",
        PipeAssign = "|=",
        CaretAssign = "^=",
        StarStar = "**",
        Shl = "<<",
        Shr = ">>",
        LBrace = "{",
        RBrace = "}",
        LParen = "(",
        RParen = ")",
        LBracket = "[",
        RBracket = "]",
        Semi = ";",
        Comma = ",",
        Dot = ".",
        Question = "?",
        Colon = ":",
        Lt = "<",
        Gt = ">",
        Plus = "+",
        Minus = "-",
        Star = "*",
        Slash = "/",
        Percent = "%",
        Amp = "&",
        Pipe = "|",
        Caret = "^",
        Bang = "!",
        Tilde = "~",
        Assign = "=",
    }
}

impl Keyword {
    pub fn from_word(word: &str) -> Option<Keyword> {
        Keyword::ALL.iter().copied().find(|k| k.as_str() == word)
    }
}

impl Punct {
    /// The closing bracket for an opening one.
    pub fn closer(self) -> Option<Punct> {
        match self {
            Punct::LBrace => Some(Punct::RBrace),
            Punct::LParen => Some(Punct::RParen),
            Punct::LBracket => Some(Punct::RBracket),
            _ => None,
        }
    }
}

impl fmt::Display for Token<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.kind {
            TokenKind::Ident(name) => write!(f, "the name `{name}`"),
            TokenKind::Keyword(k) => write!(f, "`{}`", k.as_str()),
            TokenKind::Number(n) => write!(f, "the number `{n}`"),
            TokenKind::String(s) => {
                let shown: String = s.chars().take(24).collect();
                let more = if shown.len() < s.len() { "..." } else { "" };
                write!(f, "the text \"{shown}{more}\"")
            }
            TokenKind::Regex { .. } => f.write_str("a regular expression"),
            TokenKind::Template(_) => f.write_str("a template literal"),
            TokenKind::TemplatePart { head: true, .. } => f.write_str("a template literal"),
            TokenKind::TemplatePart { .. } => f.write_str("the rest of a template literal"),
            TokenKind::Punct(p) => write!(f, "`{}`", p.as_str()),
        }
    }
}
