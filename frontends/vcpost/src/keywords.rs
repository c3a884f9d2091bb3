//! Keyword comments: the `' #Cycle !X !Y Width` and `' #C1 tip text` lines
//! that tell Vericut's probe-cycle table and composites cards what each Sub
//! is for and which parameters it takes.
//!
//! A keyword comment is a whole-line comment (`'` or `Rem`) whose text
//! starts, after blanks, with `#` and a letter. The word after `#` is a
//! keyword (`Init End Rapid Move Approach Retract Cycle Save Primer Option
//! Probe`, any case), a tip slot (`C1 C2 N1 N2 S1 S2`, followed by free
//! text), or unknown (VC017). After a keyword come parameter names separated
//! by blanks, `!` in front marking a mandatory one. This module reads them,
//! attaches them to the Sub they sit in, and checks the rules of Vericut's post-processor notes:
//! one keyword per Sub (VC012), at most 16 parameters (VC013), parameter
//! names valid (VC015) and not reserved (VC014), the probe keywords on one
//! Sub only (VC018).

use postc_ir::{Diagnostic, FileId, Span};

use crate::ast::{CommentKind, Item, KeywordComment, ParamDecl, Program, SubKeyword, TipSlot};
use crate::blocks::ProcRange;
use crate::diagnostics as codes;
use crate::lexer::Comment;
use crate::token::{is_reserved, is_valid_name};

/// Most parameters one Sub may list.
pub const MAX_PARAMS: usize = 16;

/// Reads a comment as a keyword comment, if it is one.
pub fn read(comment: &Comment, file: FileId) -> Option<KeywordComment> {
    if !comment.whole_line {
        return None;
    }
    let trimmed = comment.text.trim_start();
    let offset = comment.text_start + (comment.text.len() - trimmed.len());
    let after_hash = trimmed.strip_prefix('#')?;
    if !after_hash.chars().next().is_some_and(char::is_alphabetic) {
        return None;
    }
    let word_len = after_hash.find(char::is_whitespace).unwrap_or(after_hash.len());
    let word = &after_hash[..word_len];
    let keyword_span = Span::new(file, offset, offset + 1 + word_len);
    let rest = &after_hash[word_len..];
    let rest_start = offset + 1 + word_len;
    let kind = if let Some(k) = SubKeyword::from_word(word) {
        CommentKind::Keyword(k)
    } else if let Some(slot) = TipSlot::from_word(word) {
        CommentKind::Tip(slot, rest.trim().to_string())
    } else {
        CommentKind::Unknown(word.to_string())
    };
    let params = match kind {
        CommentKind::Keyword(_) => words(rest, rest_start)
            .map(|(w, start)| {
                let (name, mandatory) = match w.strip_prefix('!') {
                    Some(n) => (n, true),
                    None => (w, false),
                };
                ParamDecl { name: name.to_string(), mandatory, span: Span::new(file, start, start + w.len()) }
            })
            .collect(),
        _ => Vec::new(),
    };
    Some(KeywordComment { kind, keyword_span, params, span: comment.span })
}

/// Blank-separated words with their byte offsets.
fn words(text: &str, base: usize) -> impl Iterator<Item = (&str, usize)> {
    let mut rest = text;
    let mut consumed = 0;
    std::iter::from_fn(move || {
        let skip = rest.len() - rest.trim_start().len();
        rest = &rest[skip..];
        consumed += skip;
        if rest.is_empty() {
            return None;
        }
        let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let word = &rest[..len];
        let start = base + consumed;
        rest = &rest[len..];
        consumed += len;
        Some((word, start))
    })
}

/// Attaches keyword comments to the Subs they sit in and checks them.
pub fn attach(program: &mut Program, comments: &[Comment], ranges: &[ProcRange]) -> Vec<Diagnostic> {
    let mut diagnostics = Vec::new();
    for comment in comments {
        let Some(kc) = read(comment, program.file) else { continue };
        let at = kc.span.start;
        let owner = ranges.iter().find(|r| r.start <= at && at < r.end);
        match owner.and_then(|r| program.items.get_mut(r.item)) {
            Some(Item::Proc(p)) => p.keyword_comments.push(kc),
            _ => {
                diagnostics.push(
                    Diagnostic::warning(codes::KEYWORD_OUTSIDE_SUB, "a keyword comment outside any Sub is ignored")
                        .at(kc.keyword_span, "not between `Sub` and `End Sub`")
                        .help("move the comment inside the Sub it describes, after the `Sub` line"),
                );
                program.stray_keyword_comments.push(kc);
            }
        }
    }
    check(program, &mut diagnostics);
    diagnostics
}

fn check(program: &Program, diagnostics: &mut Vec<Diagnostic>) {
    let mut unique_owners: Vec<(SubKeyword, Span, &str)> = Vec::new();
    for item in &program.items {
        let Item::Proc(p) = item else { continue };
        let mut first: Option<(SubKeyword, Span)> = None;
        let mut seen: Vec<(String, Span)> = Vec::new();
        for kc in &p.keyword_comments {
            match &kc.kind {
                CommentKind::Unknown(word) => {
                    let known =
                        SubKeyword::ALL.iter().map(|k| k.as_str()).chain(TipSlot::ALL.iter().map(|t| t.as_str()));
                    let mut d =
                        Diagnostic::warning(codes::UNKNOWN_KEYWORD, format!("`#{word}` is not a keyword VcPost knows"))
                            .at(kc.keyword_span, "unknown keyword; this comment line is ignored");
                    d = match codes::suggest(word, known) {
                        Some(s) => d.help(format!("did you mean `#{s}`?")),
                        None => d.help("keywords are #Init #End #Rapid #Move #Approach #Retract #Cycle #Save #Primer #Option #Probe; tips are #C1 #C2 #N1 #N2 #S1 #S2"),
                    };
                    diagnostics.push(d);
                }
                CommentKind::Tip(..) => {}
                CommentKind::Keyword(k) => {
                    match first {
                        None => {
                            first = Some((*k, kc.keyword_span));
                            if k.is_unique() {
                                if let Some((_, other, other_name)) = unique_owners.iter().find(|(u, ..)| u == k) {
                                    diagnostics.push(
                                        Diagnostic::error(
                                            codes::DUPLICATE_KEYWORD_SUB,
                                            format!("two Subs carry `#{}`", k.as_str()),
                                        )
                                        .at(
                                            kc.keyword_span,
                                            format!("`{}` is marked `#{}` too", p.name.text, k.as_str()),
                                        )
                                        .also(*other, format!("`{other_name}` is already the #{} Sub", k.as_str()))
                                        .help(format!("only one Sub of a post may be the #{} Sub", k.as_str())),
                                    );
                                } else {
                                    unique_owners.push((*k, kc.keyword_span, &p.name.text));
                                }
                            }
                        }
                        Some((f, fspan)) if f != *k => diagnostics.push(
                            Diagnostic::error(
                                codes::TWO_KEYWORDS,
                                format!("Sub `{}` has two keywords, #{} and #{}", p.name.text, f.as_str(), k.as_str()),
                            )
                            .at(kc.keyword_span, "second keyword")
                            .also(fspan, "first keyword")
                            .help("a Sub can be only one kind of routine; split it into two Subs"),
                        ),
                        Some(_) => {}
                    }
                    for param in &kc.params {
                        check_param(param, &mut seen, diagnostics);
                        if seen.len() == MAX_PARAMS + 1 && seen.last().is_some_and(|(_, s)| *s == param.span) {
                            diagnostics.push(
                                Diagnostic::error(codes::TOO_MANY_PARAMS, format!("Sub `{}` lists more than {MAX_PARAMS} parameters", p.name.text))
                                    .at(param.span, format!("parameter {}", MAX_PARAMS + 1))
                                    .also(p.name.span, "in this Sub")
                                    .help("the probe table has 16 parameter columns; move common parameters to the #Approach Sub"),
                            );
                        }
                    }
                }
            }
        }
        if !p.params.is_empty() && first.is_some() {
            diagnostics.push(
                Diagnostic::error(
                    codes::HANDLER_WITH_PARAMS,
                    format!("Sub `{}` is called from Vericut's table and cannot take parameters", p.name.text),
                )
                .at(p.header, "remove the parameter list")
                .help("list the values it needs in its keyword comment; they arrive as registers"),
            );
        }
    }
}

fn check_param(param: &ParamDecl, seen: &mut Vec<(String, Span)>, diagnostics: &mut Vec<Diagnostic>) {
    if !is_valid_name(&param.name) {
        let shown = if param.name.is_empty() { "!" } else { &param.name };
        diagnostics.push(
            Diagnostic::error(codes::BAD_PARAM_NAME, format!("`{shown}` is not a valid parameter name"))
                .at(param.span, "not a name")
                .help("a parameter name starts with a letter and holds only letters, digits and `_`; `!` in front marks it mandatory"),
        );
        return;
    }
    if is_reserved(&param.name) {
        let why = if param.name.eq_ignore_ascii_case("N") {
            "`N` is the sequence number".to_string()
        } else if crate::builtins::lookup(&param.name).is_some() {
            format!("`{}` is a built-in function", param.name)
        } else {
            format!("`{}` is a word of the VcPost language", param.name)
        };
        diagnostics.push(
            Diagnostic::error(codes::RESERVED_PARAM, format!("`{}` cannot be a parameter name", param.name))
                .at(param.span, why)
                .help("choose another name, for example with a prefix: `P_{}`".replace("{}", &param.name)),
        );
        return;
    }
    let key = param.name.to_lowercase();
    if let Some((_, first)) = seen.iter().find(|(k, _)| *k == key) {
        diagnostics.push(
            Diagnostic::warning(codes::DUPLICATE_PARAM, format!("parameter `{}` is listed twice", param.name))
                .at(param.span, "listed again here")
                .also(*first, "first listed here"),
        );
        return;
    }
    seen.push((key, param.span));
}
