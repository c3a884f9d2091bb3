//! The error type the grammar runs with. The grammar is written so that it
//! never fails: every line is read as something, and every problem is a
//! [`Diagnostic`] emitted with a machinist's message. Chumsky's own
//! "expected ... found ..." errors would only appear if the grammar had a
//! hole; they become one plain "could not read this line" diagnostic.

use chumsky::error::{Error, LabelError};
use chumsky::span::SimpleSpan;
use chumsky::util::MaybeRef;
use postc_ir::Diagnostic;

/// A problem found while parsing.
#[derive(Clone, Debug, PartialEq)]
pub enum ParseIssue {
    /// A diagnostic the grammar reported.
    Report(Box<Diagnostic>),
    /// The grammar failed at this span (a bug in the grammar, never
    /// expected; reported without parser jargon).
    Unexpected(SimpleSpan),
}

impl From<Diagnostic> for ParseIssue {
    fn from(d: Diagnostic) -> ParseIssue {
        ParseIssue::Report(Box::new(d))
    }
}

impl<'a> Error<'a, &'a str> for ParseIssue {
    fn merge(self, other: Self) -> Self {
        match (&self, &other) {
            (ParseIssue::Unexpected(_), ParseIssue::Report(_)) => other,
            _ => self,
        }
    }
}

impl<'a, L> LabelError<'a, &'a str, L> for ParseIssue {
    fn expected_found<E: IntoIterator<Item = L>>(
        _expected: E,
        _found: Option<MaybeRef<'a, char>>,
        span: SimpleSpan,
    ) -> Self {
        ParseIssue::Unexpected(span)
    }
}
