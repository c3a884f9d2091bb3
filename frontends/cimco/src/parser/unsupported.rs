//! Statements outside the subset, parsed far enough to name them in a
//! diagnostic: labels, `with`, `debugger`, `class`, `import`, `export`,
//! `async function`, E4X's `default xml namespace`.

use chumsky::prelude::*;
use postc_ir::FileId;

use super::{Extra, TokenInput, kw, name, punct, same_line, span, terminator, unsupported, word};
use crate::ast::{Expr, Stmt};
use crate::diagnostics::Construct;
use crate::token::{Keyword, Punct, Token};

type Boxed<'t, 's, I, O> = chumsky::Boxed<'t, 't, I, O, Extra<'t, 's>>;

/// Statements outside the subset, parsed far enough to name them: labels,
/// `with`, `debugger`, `class`, `import`, `export`, `async function`,
/// E4X's `default xml namespace`.
pub(super) fn unsupported_statements<'t, 's: 't, I, S>(
    file: FileId,
    stmt: S,
    cond: Boxed<'t, 's, I, Expr>,
) -> Boxed<'t, 's, I, Stmt>
where
    I: TokenInput<'t, 's>,
    S: Parser<'t, I, Stmt, Extra<'t, 's>> + Clone + 't,
{
    let error = move |c: Construct, s: SimpleSpan, whole: SimpleSpan, emitter: &mut chumsky::input::Emitter<_>| {
        emitter.emit(unsupported(c, s));
        Stmt::error(span(file, whole))
    };
    let keyword_at = |k: Keyword| kw(k).map_with(|_, e| e.span());
    let label = name(file).map_with(|_, e| e.span()).then_ignore(punct(Punct::Colon)).then(stmt.clone()).validate(
        |(s, inner), _, emitter| {
            emitter.emit(unsupported(Construct::Label, s));
            inner
        },
    );
    let with = keyword_at(Keyword::With)
        .then_ignore(cond)
        .then_ignore(stmt.clone())
        .validate(move |s, e, emitter| error(Construct::With, s, e.span(), emitter));
    let debugger = keyword_at(Keyword::Debugger)
        .then_ignore(terminator())
        .validate(move |s, e, emitter| error(Construct::Debugger, s, e.span(), emitter));
    let class = keyword_at(Keyword::Class)
        .then_ignore(any().filter(|t: &Token<'s>| !t.is_punct(Punct::LBrace)).repeated())
        .then_ignore(super::balanced(Punct::LBrace))
        .validate(move |s, e, emitter| error(Construct::Class, s, e.span(), emitter));
    let import = keyword_at(Keyword::Import)
        .then_ignore(any().filter(|t: &Token<'s>| !t.newline_before && !t.is_punct(Punct::Semi)).repeated())
        .then_ignore(terminator())
        .validate(move |s, e, emitter| error(Construct::Module, s, e.span(), emitter));
    let export = keyword_at(Keyword::Export).then_ignore(kw(Keyword::Default).or_not()).then(stmt.clone()).validate(
        |(s, inner), _, emitter| {
            emitter.emit(unsupported(Construct::Module, s));
            inner
        },
    );
    // E4X's `default xml namespace = "...";`.
    let xml_namespace = keyword_at(Keyword::Default)
        .then_ignore(word("xml"))
        .then_ignore(word("namespace"))
        .then_ignore(any().filter(|t: &Token<'s>| !t.newline_before && !t.is_punct(Punct::Semi)).repeated())
        .then_ignore(terminator())
        .validate(move |s, e, emitter| error(Construct::E4x, s, e.span(), emitter));
    let async_function = word("async")
        .map_with(|_, e| e.span())
        .then_ignore(same_line().then(kw(Keyword::Function).rewind()))
        .then(stmt)
        .validate(|(s, inner), _, emitter| {
            emitter.emit(unsupported(Construct::Async, s));
            inner
        });
    choice((
        label.boxed(),
        with.boxed(),
        debugger.boxed(),
        class.boxed(),
        import.boxed(),
        export.boxed(),
        async_function.boxed(),
        xml_namespace.boxed(),
    ))
    .boxed()
}
