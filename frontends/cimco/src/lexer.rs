//! The lexer: post text to [`Token`]s with byte spans.
//!
//! It owns what depends on characters rather than grammar: comments,
//! line breaks (each token records whether one came before it, for
//! automatic semicolon insertion), string escapes, numbers, and telling a
//! regular expression from a division (a `/` starts a regular expression
//! where an expression may start: after `(`, `,`, `=`, an operator or a
//! keyword such as `return`; after a name, a number or a closing bracket it
//! divides). Bad characters and unclosed literals are reported and skipped,
//! so lexing always finishes.
//!
//! Read as Fusion's JavaScript ([`Syntax::Fusion`]), a template literal
//! is lexed in pieces around its substitutions (the tokens of each
//! `${...}` between them), a number with a leading zero is the legacy octal
//! number sloppy-mode JavaScript reads (`010` is 8, `08` is 8), and
//! `0b`/`0o` numbers are read.

use chumsky::span::SimpleSpan;
use postc_ir::{Diagnostic, FileId};

use crate::Syntax;
use crate::diagnostics::{self as d, Construct};
use crate::strings;
use crate::token::{Keyword, Punct, Token, TokenKind};

/// Tokens with their byte spans.
pub type Tokens<'src> = Vec<(Token<'src>, SimpleSpan)>;

/// Splits post text into tokens, as CNC-Calc's JavaScript reads it.
/// Problems are reported and lexing goes on.
pub fn lex(text: &str, file: FileId) -> (Tokens<'_>, Vec<Diagnostic>) {
    lex_as(text, file, Syntax::Cimco)
}

/// Splits post text into tokens, as the engine of `syntax` reads it.
pub fn lex_as(text: &str, file: FileId, syntax: Syntax) -> (Tokens<'_>, Vec<Diagnostic>) {
    let mut lexer = Lexer {
        text,
        pos: 0,
        file,
        tokens: Vec::new(),
        diagnostics: Vec::new(),
        newline: false,
        syntax,
        substitutions: Vec::new(),
    };
    lexer.run();
    (lexer.tokens, lexer.diagnostics)
}

struct Lexer<'src> {
    text: &'src str,
    pos: usize,
    file: FileId,
    tokens: Tokens<'src>,
    diagnostics: Vec<Diagnostic>,
    /// A line break was seen since the last token.
    newline: bool,
    syntax: Syntax,
    /// For each template substitution (`${`) open around the position, the
    /// number of `{` opened inside it and not yet closed (Fusion).
    substitutions: Vec<usize>,
}

fn is_line_break(c: char) -> bool {
    matches!(c, '\n' | '\r' | '\u{2028}' | '\u{2029}')
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_' || c == '$' || (!c.is_ascii() && c.is_alphabetic())
}

fn is_ident_part(c: char) -> bool {
    is_ident_start(c)
        || c.is_ascii_digit()
        || (!c.is_ascii() && (c.is_alphanumeric() || c == '\u{200c}' || c == '\u{200d}'))
}

impl<'src> Lexer<'src> {
    fn peek(&self) -> Option<char> {
        self.text[self.pos..].chars().next()
    }

    fn peek_at(&self, skip: usize) -> Option<char> {
        self.text[self.pos..].chars().nth(skip)
    }

    fn rest(&self) -> &'src str {
        &self.text[self.pos..]
    }

    fn error(&mut self, code: &'static str, start: usize, end: usize, message: impl Into<String>, label: &'static str) {
        self.diagnostics.push(d::lexical(code, self.file, start, end, message, label));
    }

    fn push(&mut self, kind: TokenKind<'src>, start: usize) {
        let token = Token { kind, newline_before: self.newline };
        self.tokens.push((token, SimpleSpan::from(start..self.pos)));
        self.newline = false;
    }

    fn run(&mut self) {
        loop {
            self.skip_blanks();
            let Some(c) = self.peek() else { break };
            let start = self.pos;
            if is_ident_start(c) {
                self.ident(start);
            } else if c.is_ascii_digit() || (c == '.' && self.peek_at(1).is_some_and(|n| n.is_ascii_digit())) {
                self.number(start);
            } else if c == '"' || c == '\'' {
                self.string(start, c);
            } else if c == '`' && self.syntax == Syntax::Fusion {
                self.pos += 1;
                self.template_part(start, true);
            } else if c == '`' {
                self.template(start);
            } else if c == '/' && self.regex_allowed() {
                self.regex(start);
            } else if c == '}' && self.substitutions.last() == Some(&0) {
                self.substitutions.pop();
                self.pos += 1;
                self.template_part(start, false);
            } else if c == '@' && self.text[..start].ends_with('.') {
                self.e4x_attribute(start);
            } else if let Some(p) = self.punct() {
                if let Some(open) = self.substitutions.last_mut() {
                    match p {
                        Punct::LBrace => *open += 1,
                        Punct::RBrace => *open -= 1,
                        _ => {}
                    }
                }
                self.pos += p.as_str().len();
                self.push(TokenKind::Punct(p), start);
            } else {
                self.pos += c.len_utf8();
                let message = match c {
                    '\\' => "a `\\` outside quotes; escapes belong inside text".to_string(),
                    '#' => "`#` is not allowed in JavaScript here".to_string(),
                    '@' => "`@` is not allowed in JavaScript here".to_string(),
                    c => format!(
                        "the character `{}` (U+{:04X}) is not allowed in JavaScript here",
                        c.escape_debug(),
                        c as u32
                    ),
                };
                self.error(d::UNEXPECTED_CHARACTER, start, self.pos, message, "unexpected character");
            }
        }
    }

    /// E4X's attribute after a `.` (`node.@name`, `node.@ss::Type`):
    /// refused as E4X, and read on as the property `name` so that the
    /// rest of the statement is checked.
    fn e4x_attribute(&mut self, start: usize) {
        self.pos += 1;
        let name = self.pos;
        while self.peek().is_some_and(|c| c == '_' || c == '$' || c == ':' || c.is_ascii_alphanumeric()) {
            self.pos += 1;
        }
        self.error(
            d::E4X,
            start,
            self.pos,
            "`.@` reads an attribute in E4X (ECMAScript for XML), which is not JavaScript postc reads",
            "E4X attribute",
        );
        let property = &self.text[name..self.pos];
        self.push(TokenKind::Ident(if property.is_empty() { "_" } else { property }), start);
    }

    /// Skips blanks and comments, noting line breaks.
    fn skip_blanks(&mut self) {
        while let Some(c) = self.peek() {
            if is_line_break(c) {
                self.newline = true;
                self.pos += c.len_utf8();
            } else if c.is_whitespace() || c == '\u{feff}' {
                self.pos += c.len_utf8();
            } else if self.rest().starts_with("//") {
                let len = self.rest().find(is_line_break).unwrap_or(self.rest().len());
                self.pos += len;
            } else if self.rest().starts_with("/*") {
                let start = self.pos;
                match self.rest()[2..].find("*/") {
                    Some(end) => {
                        let body = &self.rest()[2..2 + end];
                        if body.contains(is_line_break) {
                            self.newline = true;
                        }
                        self.pos += end + 4;
                    }
                    None => {
                        self.pos = self.text.len();
                        self.error(
                            d::UNTERMINATED_COMMENT,
                            start,
                            start + 2,
                            "this `/*` comment is never closed with `*/`",
                            "comment starts here",
                        );
                    }
                }
            } else {
                break;
            }
        }
    }

    fn ident(&mut self, start: usize) {
        let len = self.rest().find(|c: char| !is_ident_part(c)).unwrap_or(self.rest().len());
        self.pos += len;
        let word = &self.text[start..self.pos];
        if self.peek() == Some('\\') {
            self.error(
                d::UNEXPECTED_CHARACTER,
                self.pos,
                self.pos + 1,
                "escapes (`\\u0041`) are not allowed in names",
                "unexpected `\\`",
            );
        }
        let kind = match Keyword::from_word(word) {
            Some(k) => TokenKind::Keyword(k),
            None => TokenKind::Ident(word),
        };
        self.push(kind, start);
    }

    fn number(&mut self, start: usize) {
        let rest = self.rest();
        let lower = rest.get(..2).map(str::to_ascii_lowercase);
        let value = match lower.as_deref() {
            Some("0x") => {
                self.pos += 2;
                let digits = self.take_while(|c| c.is_ascii_hexdigit());
                if digits.is_empty() {
                    self.error(
                        d::MALFORMED_NUMBER,
                        start,
                        self.pos,
                        "`0x` must be followed by hex digits, as in `0x1F`",
                        "no digits",
                    );
                }
                digits.chars().fold(0.0, |v, c| v * 16.0 + f64::from(c.to_digit(16).unwrap_or(0)))
            }
            Some("0b") | Some("0o") => {
                self.pos += 2;
                let radix = if lower.as_deref() == Some("0b") { 2 } else { 8 };
                let digits = self.take_while(|c| c.is_ascii_digit());
                if self.syntax == Syntax::Cimco {
                    self.unsupported(Construct::BinaryOctal, start);
                } else if digits.is_empty() || digits.chars().any(|c| c.to_digit(10).is_none_or(|d| d >= radix)) {
                    self.error(
                        d::MALFORMED_NUMBER,
                        start,
                        self.pos,
                        format!("`{}` is not a number: its digits must be below {radix}", &self.text[start..self.pos]),
                        "malformed number",
                    );
                }
                digits.chars().fold(0.0, |v, c| v * f64::from(radix) + f64::from(c.to_digit(10).unwrap_or(0)))
            }
            _ if rest.starts_with('0') && rest[1..].starts_with(|c: char| c.is_ascii_digit()) => {
                if self.syntax == Syntax::Fusion {
                    self.legacy_octal(start)
                } else {
                    let digits = self.take_while(|c| c.is_ascii_digit());
                    self.unsupported(Construct::LegacyOctal, start);
                    digits.parse().unwrap_or(0.0)
                }
            }
            _ => self.decimal(start),
        };
        if self.peek().is_some_and(is_ident_part) {
            let suffix_start = self.pos;
            self.take_while(is_ident_part);
            if &self.text[suffix_start..self.pos] == "n" {
                self.unsupported(Construct::BigInt, start);
            } else {
                self.error(
                    d::MALFORMED_NUMBER,
                    start,
                    self.pos,
                    format!(
                        "`{}` is not a number: a number cannot run straight into letters",
                        &self.text[start..self.pos]
                    ),
                    "malformed number",
                );
            }
        }
        self.push(TokenKind::Number(value), start);
    }

    /// A number with a leading zero in sloppy-mode JavaScript: octal when
    /// every digit is below 8 (`010` is 8, and a `.` after it is a member
    /// access), else decimal with an optional fraction and exponent (`08`
    /// is 8, `09.5` is 9.5).
    fn legacy_octal(&mut self, start: usize) -> f64 {
        let digits = self.text[start..]
            .find(|c: char| !c.is_ascii_digit())
            .map_or(&self.text[start..], |n| &self.text[start..start + n]);
        if digits.bytes().all(|b| b < b'8') {
            self.pos += digits.len();
            return digits.bytes().fold(0.0, |v, b| v * 8.0 + f64::from(b - b'0'));
        }
        self.decimal(start)
    }

    /// Digits, an optional fraction and an optional exponent.
    fn decimal(&mut self, start: usize) -> f64 {
        self.take_while(|c| c.is_ascii_digit());
        if self.peek() == Some('.') {
            self.pos += 1;
            self.take_while(|c| c.is_ascii_digit());
        }
        if matches!(self.peek(), Some('e' | 'E')) {
            let sign = usize::from(matches!(self.peek_at(1), Some('+' | '-')));
            if self.peek_at(1 + sign).is_some_and(|c| c.is_ascii_digit()) {
                self.pos += 1 + sign;
                self.take_while(|c| c.is_ascii_digit());
            } else {
                self.pos += 1 + sign;
                self.error(
                    d::MALFORMED_NUMBER,
                    start,
                    self.pos,
                    "an exponent must have digits, as in `1e-3`",
                    "exponent without digits",
                );
                return self.text[start..self.pos - 1 - sign].parse().unwrap_or(0.0);
            }
        }
        self.text[start..self.pos].parse().unwrap_or(0.0)
    }

    fn take_while(&mut self, pred: impl Fn(char) -> bool) -> &'src str {
        let start = self.pos;
        let len = self.rest().find(|c: char| !pred(c)).unwrap_or(self.rest().len());
        self.pos += len;
        &self.text[start..self.pos]
    }

    fn unsupported(&mut self, construct: Construct, start: usize) {
        let span = postc_ir::Span::new(self.file, start, self.pos);
        self.diagnostics.push(construct.diagnostic_as(span, self.syntax));
    }

    fn string(&mut self, start: usize, quote: char) {
        self.pos += 1;
        let body_start = self.pos;
        let mut closed = false;
        while let Some(c) = self.peek() {
            if c == quote {
                closed = true;
                break;
            }
            if is_line_break(c) {
                break;
            }
            self.pos += c.len_utf8();
            if c == '\\'
                && let Some(e) = self.peek()
            {
                self.pos += e.len_utf8();
                if e == '\r' && self.peek() == Some('\n') {
                    self.pos += 1;
                }
            }
        }
        let body = &self.text[body_start..self.pos];
        if closed {
            self.pos += 1;
        } else {
            self.error(
                d::UNTERMINATED_TEXT,
                start,
                self.pos,
                format!("this text is not closed with {quote} before the end of the line"),
                "text starts here",
            );
        }
        for problem in strings::decode(body).1 {
            let (s, e) = (body_start + problem.range.start, body_start + problem.range.end.min(body.len()));
            self.error(d::BAD_ESCAPE, s, e, problem.message, "bad escape");
        }
        self.push(TokenKind::String(body), start);
    }

    fn template(&mut self, start: usize) {
        self.pos += 1;
        let mut braces = 0usize;
        let mut closed = false;
        while let Some(c) = self.peek() {
            self.pos += c.len_utf8();
            match c {
                '\\' => {
                    if let Some(e) = self.peek() {
                        self.pos += e.len_utf8();
                    }
                }
                '`' if braces == 0 => {
                    closed = true;
                    break;
                }
                '$' if braces == 0 && self.peek() == Some('{') => {
                    self.pos += 1;
                    braces = 1;
                }
                '{' if braces > 0 => braces += 1,
                '}' if braces > 0 => braces -= 1,
                _ => {}
            }
        }
        if !closed {
            self.unclosed_template(start);
        }
        let body = &self.text[start + 1..if closed { self.pos - 1 } else { self.pos }];
        self.push(TokenKind::Template(body), start);
    }

    /// A template literal (or the piece of one) starting at `start` that
    /// reaches the end of the text.
    fn unclosed_template(&mut self, start: usize) {
        self.error(
            d::UNTERMINATED_TEXT,
            start,
            start + 1,
            "this template literal is never closed with `` ` ``",
            "starts here",
        );
    }

    /// A piece of a template literal (Fusion), from just after its
    /// backquote (`head`) or the `}` that ends a substitution, to the next
    /// `${` (which opens a substitution) or the closing backquote.
    fn template_part(&mut self, start: usize, head: bool) {
        let body_start = self.pos;
        let mut end = None;
        while let Some(c) = self.peek() {
            match c {
                '\\' => {
                    self.pos += 1;
                    if let Some(e) = self.peek() {
                        self.pos += e.len_utf8();
                    }
                }
                '`' => {
                    end = Some((self.pos, true));
                    self.pos += 1;
                    break;
                }
                '$' if self.peek_at(1) == Some('{') => {
                    end = Some((self.pos, false));
                    self.pos += 2;
                    self.substitutions.push(0);
                    break;
                }
                c => self.pos += c.len_utf8(),
            }
        }
        let (body_end, tail) = end.unwrap_or_else(|| {
            self.unclosed_template(start);
            (self.pos, true)
        });
        let raw = &self.text[body_start..body_end];
        for problem in strings::decode_template(raw).1 {
            let (s, e) = (body_start + problem.range.start, body_start + problem.range.end.min(raw.len()));
            self.error(d::BAD_ESCAPE, s, e, problem.message, "bad escape");
        }
        self.push(TokenKind::TemplatePart { raw, head, tail }, start);
    }

    /// Whether a `/` here starts a regular expression rather than dividing.
    fn regex_allowed(&self) -> bool {
        let Some((last, _)) = self.tokens.last() else {
            return true;
        };
        match last.kind {
            TokenKind::Ident(_)
            | TokenKind::Number(_)
            | TokenKind::String(_)
            | TokenKind::Regex { .. }
            | TokenKind::Template(_) => false,
            // After `${` an expression starts; after the closing backquote
            // one has ended.
            TokenKind::TemplatePart { tail, .. } => !tail,
            TokenKind::Keyword(k) => {
                !matches!(k, Keyword::This | Keyword::Null | Keyword::True | Keyword::False | Keyword::Super)
            }
            TokenKind::Punct(p) => {
                !matches!(p, Punct::RParen | Punct::RBracket | Punct::RBrace | Punct::PlusPlus | Punct::MinusMinus)
            }
        }
    }

    fn regex(&mut self, start: usize) {
        self.pos += 1;
        let mut in_class = false;
        let mut closed = false;
        while let Some(c) = self.peek() {
            if is_line_break(c) {
                break;
            }
            self.pos += c.len_utf8();
            match c {
                '\\' => {
                    if let Some(e) = self.peek().filter(|e| !is_line_break(*e)) {
                        self.pos += e.len_utf8();
                    }
                }
                '[' => in_class = true,
                ']' => in_class = false,
                '/' if !in_class => {
                    closed = true;
                    break;
                }
                _ => {}
            }
        }
        if !closed {
            self.error(
                d::UNTERMINATED_REGEX,
                start,
                self.pos,
                "this regular expression is not closed with `/` before the end of the line",
                "regular expression starts here",
            );
            let pattern = &self.text[start + 1..self.pos];
            self.push(TokenKind::Regex { pattern, flags: "" }, start);
            return;
        }
        let pattern = &self.text[start + 1..self.pos - 1];
        let flags = self.take_while(is_ident_part);
        self.push(TokenKind::Regex { pattern, flags }, start);
    }

    /// The longest punctuator at the current position.
    fn punct(&self) -> Option<Punct> {
        let rest = self.rest();
        let first = *rest.as_bytes().first()?;
        // The first byte rules out most before their text is compared.
        let found = Punct::ALL
            .iter()
            .copied()
            .find(|p| p.as_str().as_bytes().first() == Some(&first) && rest.starts_with(p.as_str()))?;
        // `a?.5:b` is a conditional, not optional chaining.
        if found == Punct::QuestionDot && rest[2..].starts_with(|c: char| c.is_ascii_digit()) {
            return Some(Punct::Question);
        }
        Some(found)
    }
}
