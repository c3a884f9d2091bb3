//! The line forms of a Vectric post: comments, output strings, script calls
//! and blocks, `VAR`, `begin`, global statements, and the stray-text catch
//! all. Each form reads its line to the end and never fails once its first
//! word matched, so every problem is reported with a message about that
//! form and parsing goes on with the next line.

use chumsky::prelude::*;
use postc_ir::{FileId, Span};

use crate::ast::{BeginLine, ItemKind, OutputMode, QuotedText, Spanned, TextPiece, VarBody, VarDecl, VarFields};
use crate::diagnostics::Code;
use crate::format_spec::parse_format;
use crate::names::GlobalName;
use crate::parser::common::{Extra, emit, eol, hspace, keyword, name, quoted, rest, span, trailing, values};
use crate::parser::error::ParseIssue;

const VAR_EXAMPLE: &str = "VAR X_POSITION = [X|C|X|1.3]";

/// A blank line (nothing to keep).
pub fn blank<'a>() -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    hspace().then(eol().or(end()).rewind()).to(None)
}

/// `+ ...` or `| ...`.
pub fn comment<'a>() -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    hspace().ignore_then(one_of("+|")).ignore_then(rest()).map(|text: &str| Some(ItemKind::Comment(text.to_string())))
}

/// `"..."`: an output line.
pub fn output<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    hspace()
        .ignore_then(quoted(file))
        .then_ignore(trailing(file, "after the closing quote"))
        .map(|text| Some(ItemKind::Output(text)))
}

/// `<!>call` and `"<!>call"`: a Lua call where the line stands.
pub fn script_call<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    let code = |stop: &'static str| {
        none_of(stop)
            .repeated()
            .to_slice()
            .map_with(move |s: &str, e| Spanned::new(s.to_string(), span(file, e.span())))
    };
    let quoted_call = just("\"<!>")
        .ignore_then(code("\"\r\n"))
        .then(just('"').or_not())
        .validate(move |(code, close), e, emitter| {
            if close.is_none() {
                emit(
                    emitter,
                    Code::UnterminatedString
                        .diag("this script call has no closing quote")
                        .at(span(file, e.span()), "the string starts here and runs to the end of the line")
                        .help("end the line with \""),
                );
            }
            code
        })
        .then_ignore(trailing(file, "after the closing quote"));
    let bare_call = just("<!>").ignore_then(code("\r\n"));
    hspace().ignore_then(choice((quoted_call, bare_call))).map(|code| Some(ItemKind::ScriptCall(code)))
}

/// `SCRIPT` ... `ENDSCRIPT`: a Lua block.
pub fn script_block<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    let end_line = hspace().then(keyword("ENDSCRIPT")).then(rest());
    let start = hspace()
        .then(keyword("SCRIPT"))
        .map_with(move |_, e| span(file, e.span()))
        .then_ignore(trailing(file, "after SCRIPT"));
    let body = eol().then(end_line.clone().not()).then(rest()).repeated().to_slice().map_with(move |s: &str, e| {
        let skip = if s.starts_with("\r\n") { 2 } else { usize::from(!s.is_empty()) };
        let start = e.span().start + skip;
        Spanned::new(s.get(skip..).unwrap_or("").to_string(), Span::new(file, start, e.span().end))
    });
    start.then(body).then(eol().then(end_line).or_not()).validate(move |((start, body), end), _, emitter| {
        if end.is_none() {
            emit(
                emitter,
                Code::UnterminatedScript
                    .diag("this SCRIPT block has no ENDSCRIPT line")
                    .at(start, "the block starts here and runs to the end of the file")
                    .help("end the Lua block with a line that says ENDSCRIPT"),
            );
        }
        Some(ItemKind::ScriptBlock(body))
    })
}

/// `begin NAME`.
pub fn begin<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    let word = none_of(" \t\r\n+|")
        .then(none_of(" \t\r\n").repeated())
        .to_slice()
        .map_with(move |s: &str, e| Spanned::new(s.to_string(), span(file, e.span())));
    hspace()
        .ignore_then(keyword("BEGIN"))
        .ignore_then(one_of(" \t").repeated().at_least(1).ignore_then(word).repeated().collect::<Vec<_>>())
        .validate(move |words, e, emitter| {
            if words.is_empty() {
                emit(
                    emitter,
                    Code::MissingSectionName
                        .diag("`begin` needs the name of a section")
                        .at(span(file, e.span()), "no section name")
                        .help("write, for example, `begin HEADER` or `begin FEED_MOVE`"),
                );
            }
            Some(ItemKind::Begin(BeginLine { words }))
        })
        .then_ignore(trailing(file, "after the section name"))
}

/// `NAME = value ...` outside the `VAR` form.
pub fn global<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    hspace()
        .ignore_then(name(file))
        .then_ignore(hspace())
        .then_ignore(just('='))
        .then_ignore(hspace())
        .then(values(file))
        .map(|(name, values)| Some(ItemKind::Global(crate::ast::GlobalStmt { name, values })))
}

/// A line made only of variables, without quotes (`[F]`): VCarve prints it
/// as if it were quoted (the ShopSabre post's HEADER, docs/vectric.md), so
/// it is an output line, with a warning that the guides want quotes.
/// Blanks around it and a trailing comment are allowed, none between the
/// variables.
pub fn bare_variables<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    let piece = just('[')
        .ignore_then(none_of("[]\" \t\r\n").repeated().at_least(1).to_slice())
        .then_ignore(just(']'))
        .try_map(move |inner: &str, s| {
            let value = if inner.bytes().all(|b| b.is_ascii_digit()) {
                TextPiece::Code(inner.parse::<u8>().map_err(|_| ParseIssue::Unexpected(s))?)
            } else {
                TextPiece::Label(inner.to_string())
            };
            Ok(Spanned::new(value, span(file, s)))
        });
    let end_of_line = hspace().then(one_of("+|").then(rest()).or_not()).then(eol().or(end()).rewind());
    hspace()
        .ignore_then(
            piece.repeated().at_least(1).collect::<Vec<_>>().map_with(|pieces, e| (pieces, e.slice(), e.span())),
        )
        .then_ignore(end_of_line)
        .validate(move |(pieces, raw, at): (Vec<Spanned<TextPiece>>, &str, SimpleSpan), _, emitter| {
            emit(
                emitter,
                Code::BareVariables
                    .diag("this line of variables has no quotes; it is printed as if it had, as VCarve prints it")
                    .at(span(file, at), "no quotes")
                    .help(format!("write it between double quotes: \"{raw}\"")),
            );
            Some(ItemKind::Output(QuotedText { pieces, raw: raw.to_string(), closed: true }))
        })
}

/// Anything else: a known statement name without `=` is an error, other
/// text is ignored with a warning.
pub fn stray<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    hspace().ignore_then(rest()).validate(move |text: &str, e, emitter| {
        let trimmed = text.trim_end();
        let at = Span::new(file, e.span().start, e.span().start + trimmed.len());
        let first: String = trimmed.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        if let Some(global) = GlobalName::from_name(&first) {
            emit(
                emitter,
                Code::GlobalWithoutValue
                    .diag(format!("{} needs `=` and a value", global.name()))
                    .at(at, "no `=` here")
                    .help(format!("write it like this: {}", global.example())),
            );
        } else {
            emit(
                emitter,
                Code::StrayText
                    .diag("text outside quotes is ignored")
                    .at(at, "not a comment, a statement or a quoted output line")
                    .help("output text goes between double quotes, like \"%\"; comments start with + or |"),
            );
        }
        Some(ItemKind::Stray(trimmed.to_string()))
    })
}

/// `VAR NAME = [label|mode|prefix|format|multiplier]` (or `VAR NAME = value`
/// for the global statements some posts write with `VAR`).
pub fn var<'a>(file: FileId) -> impl Parser<'a, &'a str, Option<ItemKind>, Extra> + Clone {
    let field = none_of("|]\r\n").repeated().to_slice().map_with(|s: &str, e| (s, e.span()));
    let fields = just('[')
        .ignore_then(field.separated_by(just('|')).collect::<Vec<_>>())
        .then(just(']').or_not())
        .validate(move |(fields, close), e, emitter| {
            check_fields(file, &fields, close.is_some(), span(file, e.span()), emitter)
        });
    let body =
        choice((fields, values(file).filter(|v| !v.is_empty()).map(VarBody::Values), rest().to(VarBody::Missing)));
    let head = hspace()
        .ignore_then(keyword("VAR"))
        .map_with(move |_, e| span(file, e.span()))
        .then_ignore(hspace())
        .then(name(file).or_not())
        .then_ignore(hspace())
        .then(just('=').or_not())
        .then_ignore(hspace());
    head.then(body).then_ignore(trailing(file, "after the closing ]")).validate(
        move |(((var_at, name), equals), body), e, emitter| {
            let line = span(file, e.span());
            let problem = if name.is_none() {
                Some("`VAR` must be followed by a variable name")
            } else if equals.is_none() {
                Some("this VAR line needs `=` after the variable name")
            } else if body == VarBody::Missing {
                Some("this VAR line needs its format between [ and ] after `=`")
            } else {
                None
            };
            if let Some(problem) = problem {
                emit(
                    emitter,
                    Code::MalformedVar
                        .diag(problem)
                        .at(if name.is_none() { var_at } else { line }, "malformed VAR")
                        .help(format!("write it like this: {VAR_EXAMPLE}")),
                );
            }
            let body = if name.is_some() && body != VarBody::Missing { body } else { VarBody::Malformed };
            Some(ItemKind::Var(VarDecl { name, body }))
        },
    )
}

/// Checks the fields between `[` and `]` and builds the VAR's format.
fn check_fields(
    file: FileId,
    fields: &[(&str, SimpleSpan)],
    closed: bool,
    whole: Span,
    emitter: &mut chumsky::input::Emitter<crate::parser::error::ParseIssue>,
) -> VarBody {
    let at = |s: SimpleSpan| span(file, s);
    if !closed {
        emit(
            emitter,
            Code::MalformedVar
                .diag("this VAR has no closing `]`")
                .at(whole, "no `]` after this")
                .help(format!("write it like this: {VAR_EXAMPLE}")),
        );
    }
    let n = fields.len();
    if !(3..=5).contains(&n) {
        emit(
            emitter,
            Code::MalformedVar
                .diag(format!("this VAR line needs 4 or 5 fields between [ and ], like [X|C|X|1.3]; it has {n}"))
                .at(whole, "label | A or C | prefix | format | optional multiplier")
                .help(format!("write it like this: {VAR_EXAMPLE}")),
        );
        return VarBody::Malformed;
    }
    let (label_text, label_span) = fields[0];
    let label = label_text.trim();
    if label.is_empty() {
        emit(
            emitter,
            Code::MalformedVar
                .diag("the label of this VAR is empty")
                .at(at(label_span), "no label")
                .help(format!("the first field is the label the output lines use, like X in {VAR_EXAMPLE}")),
        );
        return VarBody::Malformed;
    }
    let (mode_text, mode_span) = fields[1];
    let mode = match mode_text.trim().to_ascii_uppercase().as_str() {
        "A" => OutputMode::Always,
        "C" => OutputMode::OnChange,
        _ => {
            emit(
                emitter,
                Code::BadOutputMode
                    .diag(format!("`{}` is not A or C", mode_text.trim()))
                    .at(at(mode_span), "when to output")
                    .help("A prints the value every time, C only when it changed"),
            );
            OutputMode::Always
        }
    };
    let prefix_omitted = n == 3;
    let (prefix, format_field) = if prefix_omitted {
        let empty = SimpleSpan::new((), mode_span.end..mode_span.end);
        emit(
            emitter,
            Code::MissingPrefixField
                .diag(format!(
                    "this VAR has no prefix field; read as [{label}|{}||{}]",
                    mode_text.trim(),
                    fields[2].0.trim()
                ))
                .at(whole, "3 fields")
                .help("write the prefix between the second and third bar, even when it is empty: [N|A||1.0]"),
        );
        (("", empty), fields[2])
    } else {
        (fields[2], fields[3])
    };
    let format = match parse_format(format_field.0) {
        Ok(spec) => {
            if !spec.has_separator {
                emit(
                    emitter,
                    Code::FormatWithoutSeparator
                        .diag(format!(
                            "value format `{}` has no decimal separator; it prints whole numbers",
                            format_field.0.trim()
                        ))
                        .at(at(format_field.1), "no `.` or `,`")
                        .help(
                            "write the decimals after `.` or `,`, like 1.0 for whole numbers or 1.3 for three decimals",
                        ),
                );
            }
            spec
        }
        Err(error) => {
            let start = format_field.1.start + error.range.start;
            let end = format_field.1.start + error.range.end.max(error.range.start);
            let bad = if end > start { Span::new(file, start, end) } else { at(format_field.1) };
            emit(
                emitter,
                Code::BadFormat
                    .diag(error.message)
                    .at(bad, "bad value format")
                    .help("flags - + 0 #, then the width, then `.` or `,`, then the decimals: 1.3, 02.0, +1,3, -#5.0"),
            );
            Default::default()
        }
    };
    let multiplier = fields.get(4).and_then(|&(text, s)| {
        let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
        if compact.is_empty() {
            return None;
        }
        match compact.parse::<f64>() {
            Ok(m) if m.is_finite() && compact.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c)) => {
                Some(Spanned::new(m, at(s)))
            }
            _ => {
                emit(
                    emitter,
                    Code::BadMultiplier
                        .diag(format!("`{}` is not a number to multiply by", text.trim()))
                        .at(at(s), "bad multiplier")
                        .help("the fifth field is a plain number, like 0.01666 or -1"),
                );
                None
            }
        }
    });
    let label_start = label_span.start + (label_text.len() - label_text.trim_start().len());
    VarBody::Fields(Box::new(VarFields {
        label: Spanned::new(label.to_string(), Span::new(file, label_start, label_start + label.len())),
        mode: Spanned::new(mode, at(mode_span)),
        prefix: Spanned::new(prefix.0.to_string(), at(prefix.1)),
        prefix_omitted,
        format: Spanned::new(format, at(format_field.1)),
        multiplier,
        span: whole,
    }))
}
