//! The grammar's error type: what chumsky's `Rich` holds (a span, and
//! either one of the grammar's own [`Problem`]s or the tokens and labels
//! expected with the token found), merged by the same rules, with the
//! expected set kept as a list in the order it was met beside a bit set of
//! the punctuators and keywords in it.
//!
//! Every operand of every expression ends with all the binary, assignment
//! and postfix operators tried at one position, and each failure merges
//! its token into the expected set of that position. `Rich` tests each
//! against its whole list (about 40 tokens after an operand): most of the
//! instructions of parsing a Fusion post went there. Here a punctuator or
//! keyword is one bit test; only names, labels and the rest scan the list.

use chumsky::DefaultExpected;
use chumsky::input::Input;
use chumsky::label::LabelError;
use chumsky::span::SimpleSpan;
use chumsky::util::MaybeRef;

use super::Problem;
use crate::token::{Token, TokenKind};

/// One thing the grammar expected at a position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Expected<'s> {
    Token(Token<'s>),
    Label(&'static str),
    EndOfInput,
    /// Any token; never listed.
    Any,
    /// Something the parser did not name; never listed.
    SomethingElse,
}

/// Why the grammar failed.
#[derive(Clone, Debug)]
pub(crate) enum Reason<'s> {
    Custom(Problem),
    ExpectedFound { expected: ExpectedSet<'s>, found: Option<Token<'s>> },
}

/// The expected alternatives of one position, in the order they were met.
#[derive(Clone, Debug, Default)]
pub(crate) struct ExpectedSet<'s> {
    list: Vec<Expected<'s>>,
    /// Bit `p as u32` for each punctuator `p` in `list`.
    puncts: u128,
    /// Bit `k as u32` for each keyword `k` in `list`.
    keywords: u128,
    /// [`Kind`]'s bits of the end of input, any token and something else.
    unnamed: u8,
}

/// Where an [`ExpectedSet`] records that it holds an alternative.
enum Kind {
    Punct(u128),
    Keyword(u128),
    Unnamed(u8),
    /// Labels and the other tokens (names, numbers, text): the few looked
    /// for in the list.
    Listed,
}

impl<'s> ExpectedSet<'s> {
    /// The alternatives, in the order they were met.
    pub(crate) fn iter(&self) -> std::slice::Iter<'_, Expected<'s>> {
        self.list.iter()
    }

    fn kind(e: &Expected<'s>) -> Kind {
        match e {
            Expected::Token(t) => match t.kind {
                TokenKind::Punct(p) => Kind::Punct(1 << (p as u32)),
                TokenKind::Keyword(k) => Kind::Keyword(1 << (k as u32)),
                _ => Kind::Listed,
            },
            Expected::EndOfInput => Kind::Unnamed(1),
            Expected::Any => Kind::Unnamed(2),
            Expected::SomethingElse => Kind::Unnamed(4),
            Expected::Label(_) => Kind::Listed,
        }
    }

    fn contains(&self, e: &Expected<'s>) -> bool {
        match Self::kind(e) {
            Kind::Punct(bit) => self.puncts & bit != 0,
            Kind::Keyword(bit) => self.keywords & bit != 0,
            Kind::Unnamed(bit) => self.unnamed & bit != 0,
            Kind::Listed => self.list.contains(e),
        }
    }

    /// Adds `e`, even when it is already there (as `Rich` collects the
    /// alternatives of one failure).
    fn push(&mut self, e: Expected<'s>) {
        match Self::kind(&e) {
            Kind::Punct(bit) => self.puncts |= bit,
            Kind::Keyword(bit) => self.keywords |= bit,
            Kind::Unnamed(bit) => self.unnamed |= bit,
            Kind::Listed => {}
        }
        self.list.push(e);
    }

    /// Adds `e` unless it is already there.
    fn insert(&mut self, e: Expected<'s>) {
        if !self.contains(&e) {
            self.push(e);
        }
    }

    fn clear(&mut self) {
        self.list.clear();
        self.puncts = 0;
        self.keywords = 0;
        self.unnamed = 0;
    }

    fn len(&self) -> usize {
        self.list.len()
    }

    fn collect(expected: impl IntoIterator<Item = Option<Expected<'s>>>) -> Self {
        let mut set = ExpectedSet::default();
        for e in expected.into_iter().flatten() {
            set.push(e);
        }
        set
    }
}

/// A label or chumsky's expected pattern, as an [`Expected`] (`None` for
/// "nothing else", which `Rich` drops too).
pub(crate) trait IntoExpected<'s> {
    fn into_expected(self) -> Option<Expected<'s>>;
}

impl<'t, 's> IntoExpected<'s> for DefaultExpected<'t, Token<'s>> {
    fn into_expected(self) -> Option<Expected<'s>> {
        Some(match self {
            DefaultExpected::Token(t) => Expected::Token(*t),
            DefaultExpected::EndOfInput => Expected::EndOfInput,
            DefaultExpected::Any => Expected::Any,
            DefaultExpected::NothingElse => return None,
            _ => Expected::SomethingElse,
        })
    }
}

impl<'s> IntoExpected<'s> for &'static str {
    fn into_expected(self) -> Option<Expected<'s>> {
        Some(Expected::Label(self))
    }
}

/// An error of the grammar at a span.
#[derive(Clone, Debug)]
pub(crate) struct SyntaxError<'s> {
    span: SimpleSpan,
    reason: Box<Reason<'s>>,
}

impl<'s> SyntaxError<'s> {
    /// One of the grammar's own problems at `span`.
    pub(crate) fn custom(span: SimpleSpan, problem: Problem) -> Self {
        SyntaxError { span, reason: Box::new(Reason::Custom(problem)) }
    }

    pub(crate) fn span(&self) -> &SimpleSpan {
        &self.span
    }

    pub(crate) fn reason(&self) -> &Reason<'s> {
        &self.reason
    }

    /// The expected alternatives (none for a problem of the grammar's own).
    pub(crate) fn expected(&self) -> impl Iterator<Item = &Expected<'s>> {
        let set = match &*self.reason {
            Reason::ExpectedFound { expected, .. } => Some(expected.iter()),
            Reason::Custom(_) => None,
        };
        set.into_iter().flatten()
    }

    /// Makes the error "expected `expected`, found `found`", as `Rich`
    /// replaces and labels (its set's allocation kept when it has one).
    fn reset(&mut self, expected: impl IntoIterator<Item = Expected<'s>>, found: Option<Token<'s>>) {
        let mut set = match &mut *self.reason {
            Reason::ExpectedFound { expected, .. } => std::mem::take(expected),
            Reason::Custom(_) => ExpectedSet::default(),
        };
        set.clear();
        for e in expected {
            set.push(e);
        }
        *self.reason = Reason::ExpectedFound { expected: set, found };
    }
}

fn found<'s>(found: Option<MaybeRef<'_, Token<'s>>>) -> Option<Token<'s>> {
    found.map(|t| *t)
}

impl<'t, 's: 't, I> chumsky::error::Error<'t, I> for SyntaxError<'s>
where
    I: Input<'t, Token = Token<'s>, Span = SimpleSpan>,
{
    /// `Rich`'s merge: a problem of the grammar's own wins (the first one
    /// when both are); else the expected sets are joined, the longer first.
    fn merge(mut self, other: Self) -> Self {
        let reason = match (*self.reason, *other.reason) {
            (a @ Reason::Custom(_), _) => a,
            (_, b @ Reason::Custom(_)) => b,
            (Reason::ExpectedFound { expected: mut this, found }, Reason::ExpectedFound { expected: mut that, .. }) => {
                if that.len() > this.len() {
                    std::mem::swap(&mut this, &mut that);
                }
                for e in that.list {
                    this.insert(e);
                }
                Reason::ExpectedFound { expected: this, found }
            }
        };
        self.reason = Box::new(reason);
        self
    }
}

impl<'t, 's: 't, I, L> LabelError<'t, I, L> for SyntaxError<'s>
where
    I: Input<'t, Token = Token<'s>, Span = SimpleSpan>,
    L: IntoExpected<'s>,
{
    fn expected_found<E: IntoIterator<Item = L>>(
        expected: E,
        found_token: Option<MaybeRef<'t, Token<'s>>>,
        span: SimpleSpan,
    ) -> Self {
        let expected = ExpectedSet::collect(expected.into_iter().map(IntoExpected::into_expected));
        SyntaxError { span, reason: Box::new(Reason::ExpectedFound { expected, found: found(found_token) }) }
    }

    fn merge_expected_found<E: IntoIterator<Item = L>>(
        mut self,
        new_expected: E,
        new_found: Option<MaybeRef<'t, Token<'s>>>,
        _span: SimpleSpan,
    ) -> Self {
        if let Reason::ExpectedFound { expected, found: old } = &mut *self.reason {
            for e in new_expected.into_iter().filter_map(IntoExpected::into_expected) {
                expected.insert(e);
            }
            *old = old.take().or(found(new_found));
        }
        self
    }

    fn replace_expected_found<E: IntoIterator<Item = L>>(
        mut self,
        new_expected: E,
        new_found: Option<MaybeRef<'t, Token<'s>>>,
        span: SimpleSpan,
    ) -> Self {
        self.span = span;
        self.reset(new_expected.into_iter().filter_map(IntoExpected::into_expected), found(new_found));
        self
    }

    fn label_with(&mut self, label: L) {
        let found = match &*self.reason {
            Reason::ExpectedFound { found, .. } => *found,
            Reason::Custom(_) => None,
        };
        self.reset(label.into_expected(), found);
    }
}
