//! Probe-cycle tables: Vericut's Inspection Programming table as a CSV file
//! (see [`crate::csv`] for the cell syntax), read against a post's keyword
//! comments into the Sub calls the runtime makes.
//!
//! Each row names a Sub (by its name, without case), then gives values for
//! the parameters of its keyword comment, by position (the comment's order,
//! over all its lines) or as `NAME=VALUE`; positional cells come first. A
//! cell that is empty, or that still holds the parameter's name (`FeedRate`
//! or `!X`, as [`template`] prints it), gives no value: the register keeps
//! the value it had. Values are numbers; a quoted cell is text. Blank lines
//! and lines starting with `#` are skipped.
//!
//! The rows follow the seed's table (a grammar over the rows' keywords):
//!
//! ```text
//! table   = [ Init ] { Rapid | Move | feature } [ End ]
//! feature = [ Approach ] Cycle [ Save ] [ Retract ]
//! ```
//!
//! and the runtime calls: the #Init Sub first (even without its row), each
//! Rapid and Move row's Sub, for each feature the #Approach Sub, the row's
//! #Cycle Sub, the #Save Sub when the feature has a Save row, the #Retract
//! Sub, and the #End Sub last (even without its row). Approach and Retract
//! run around every cycle, with the values of the feature's Approach and
//! Retract rows when it has them. A mandatory (`!`) parameter needs a value
//! wherever its Sub is called: a feature without an Approach row is an
//! error when the #Approach Sub has mandatory parameters.
//!
//! Its diagnostic codes are declared in the registry `postc_ir::codes`
//! (rendered as docs/diagnostics.md; `postc explain CODE`).

use postc_ir::codes;
use postc_ir::{CallValue, Diagnostic, FileId, MissingSub, Post, Span, SubCall};

use crate::ast::SubKeyword;
use crate::csv::{self, Field};
use crate::diagnostics::suggest;
use crate::signatures::{SubSignature, from_post};

/// One row, checked.
struct Row {
    sig: usize,
    keyword: SubKeyword,
    vars: Vec<(String, CallValue)>,
    /// Parameters that got a value.
    given: Vec<bool>,
    /// Where each positional cell is, to point at a missing value.
    cells: Vec<Span>,
    /// The whole row, and its end (for a value that is not there at all).
    span: Span,
    end: Span,
}

/// Keywords that make table rows.
const TABLE_KEYWORDS: &[SubKeyword] = &[
    SubKeyword::Init,
    SubKeyword::Rapid,
    SubKeyword::Move,
    SubKeyword::Approach,
    SubKeyword::Cycle,
    SubKeyword::Save,
    SubKeyword::Retract,
    SubKeyword::End,
];

/// Reads a probe table against a post: the calls in the order the runtime
/// makes them, and every problem found (the calls are only meant to run
/// when there is no error).
pub fn read(text: &str, file: FileId, post: &Post) -> (Vec<SubCall>, Vec<Diagnostic>) {
    let sigs: Vec<SubSignature> =
        from_post(post).into_iter().filter(|s| s.keyword.is_some_and(|k| TABLE_KEYWORDS.contains(&k))).collect();
    let subs: Vec<&str> = post.functions.iter().filter(|f| f.span.is_some()).map(|f| f.name.as_str()).collect();
    let mut diagnostics = Vec::new();
    let mut rows = Vec::new();
    let mut offset = 0;
    for raw in text.split_inclusive('\n') {
        let base = offset;
        offset += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        let lead = line.len() - line.trim_start().len();
        if line.trim().is_empty() || line[lead..].starts_with('#') {
            continue;
        }
        match csv::split(line, base, file) {
            Ok(fields) if !fields.is_empty() => {
                let end = Span::new(file, base + line.len(), base + line.len());
                let span = Span::new(file, base + lead, base + line.len());
                if let Some(row) = row(&fields, &sigs, &subs, span, end, &mut diagnostics) {
                    rows.push(row);
                }
            }
            Ok(_) => {}
            Err(d) => diagnostics.push(d),
        }
    }
    if rows.is_empty() && !postc_ir::diagnostic::has_errors(&diagnostics) {
        diagnostics.push(
            Diagnostic::warning(codes::PT015, "this probe table has no rows")
                .help("`postc probe-table POST` prints a template with one row per probe-cycle Sub"),
        );
    }
    let calls = sequence(&rows, &sigs, file, &mut diagnostics);
    (calls, diagnostics)
}

fn row(
    fields: &[Field],
    sigs: &[SubSignature],
    subs: &[&str],
    span: Span,
    end: Span,
    diags: &mut Vec<Diagnostic>,
) -> Option<Row> {
    let head = &fields[0];
    let name = head.value.trim();
    let listing = || sigs.iter().map(|s| s.name.as_str()).collect::<Vec<_>>().join(", ");
    if !sigs.iter().any(|s| s.name.eq_ignore_ascii_case(name)) && subs.iter().any(|s| s.eq_ignore_ascii_case(name)) {
        diags.push(
            Diagnostic::error(codes::PT003, format!("`{name}` is not a probe-cycle Sub"))
                .at(
                    head.value_span,
                    "it has no #Init, #Rapid, #Move, #Approach, #Cycle, #Save, #Retract or #End comment",
                )
                .help(format!("the post's probe-cycle Subs are: {}", listing())),
        );
        return None;
    }
    let Some(index) = sigs.iter().position(|s| s.name.eq_ignore_ascii_case(name)) else {
        let mut d = Diagnostic::error(codes::PT002, format!("the post has no probe-cycle Sub `{name}`"))
            .at(head.value_span, "the first cell names the Sub the row calls");
        d = match suggest(name, sigs.iter().map(|s| s.name.as_str())) {
            Some(s) => d.help(format!("did you mean `{s}`?")),
            None => d.help(format!("the post's probe-cycle Subs are: {}", listing())),
        };
        diags.push(d);
        return None;
    };
    let sig = &sigs[index];
    let keyword = sig.keyword?;
    let params = &sig.params;
    let mut row =
        Row { sig: index, keyword, vars: Vec::new(), given: vec![false; params.len()], cells: Vec::new(), span, end };
    let mut named_seen = false;
    let mut positional = 0;
    for field in &fields[1..] {
        let slot = match &field.name {
            None => {
                if named_seen {
                    if !field.is_empty() {
                        diags.push(
                            Diagnostic::error(codes::PT004, "a value by position after a named one")
                                .at(field.span, "which parameter is this?")
                                .help("give values by position first, then as NAME=VALUE"),
                        );
                    }
                    continue;
                }
                let k = positional;
                positional += 1;
                row.cells.push(field.value_span);
                if k >= params.len() {
                    if !field.is_empty() {
                        diags.push(
                            Diagnostic::error(
                                codes::PT005,
                                format!("`{}` has {} parameters; this is value {}", sig.name, params.len(), k + 1),
                            )
                            .at(field.span, "one value too many")
                            .also(sig.span, "the Sub's keyword comment lists its parameters"),
                        );
                    }
                    continue;
                }
                k
            }
            Some((name, name_span)) => {
                named_seen = true;
                let Some(k) = params.iter().position(|(p, _)| p.eq_ignore_ascii_case(name)) else {
                    let mut d = Diagnostic::error(codes::PT006, format!("`{}` has no parameter `{name}`", sig.name))
                        .at(*name_span, "unknown parameter");
                    d = match suggest(name, params.iter().map(|(p, _)| p.as_str())) {
                        Some(s) => d.help(format!("did you mean `{s}`?")),
                        None => d.help(format!("its parameters are: {}", names(params))),
                    };
                    diags.push(d);
                    continue;
                };
                if row.given[k] {
                    diags.push(
                        Diagnostic::error(codes::PT007, format!("`{name}` is given twice"))
                            .at(field.span, "second value"),
                    );
                    continue;
                }
                k
            }
        };
        match value(field, &params[slot].0) {
            Ok(Some(v)) => {
                row.given[slot] = true;
                row.vars.push((params[slot].0.clone(), v));
            }
            Ok(None) => {}
            Err(d) => diags.push(d),
        }
    }
    for (k, (param, mandatory)) in params.iter().enumerate() {
        if *mandatory && !row.given[k] {
            let at = row.cells.get(k).copied().unwrap_or(row.end);
            diags.push(missing(sig, param, at, "this row gives it no value"));
        }
    }
    Some(row)
}

/// The value of a cell: `None` when it is empty or still holds the name.
fn value(field: &Field, param: &str) -> Result<Option<CallValue>, Diagnostic> {
    if field.quoted {
        return Ok(Some(CallValue::Text(field.value.clone())));
    }
    let v = field.value.as_str();
    if v.is_empty()
        || v.eq_ignore_ascii_case(param)
        || v.strip_prefix('!').is_some_and(|n| n.eq_ignore_ascii_case(param))
    {
        return Ok(None);
    }
    let numeric = v.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.'));
    match v.parse::<f64>() {
        Ok(n) if numeric && n.is_finite() => Ok(Some(CallValue::Number(n))),
        _ => Err(Diagnostic::error(codes::PT009, format!("`{v}` is not a number"))
            .at(field.value_span, format!("value of `{param}`"))
            .help(format!(
                "quote text values (\"{v}\"); leave the cell empty, or write `{param}`, to keep the register's value"
            ))),
    }
}

fn missing(sig: &SubSignature, param: &str, at: Span, label: &str) -> Diagnostic {
    Diagnostic::error(codes::PT008, format!("`{}` needs a value for its mandatory parameter `{param}`", sig.name))
        .at(at, label)
        .also(sig.span, format!("`!{param}` in its keyword comment makes it mandatory"))
}

fn names(params: &[(String, bool)]) -> String {
    params.iter().map(|(p, m)| if *m { format!("!{p}") } else { p.clone() }).collect::<Vec<_>>().join(" ")
}

/// Checks the order of the rows and makes the calls.
fn sequence(rows: &[Row], sigs: &[SubSignature], file: FileId, diags: &mut Vec<Diagnostic>) -> Vec<SubCall> {
    let find = |k: SubKeyword| sigs.iter().position(|s| s.keyword == Some(k));
    let start = rows.first().map_or(Span::new(file, 0, 0), |r| r.span);
    let mut calls = Vec::new();
    let call = |sig: usize, vars: Vec<(String, CallValue)>, span: Span| SubCall {
        sub: sigs[sig].name.clone(),
        vars,
        span,
        missing: MissingSub::Warn,
    };
    // A Sub called without its row: its mandatory parameters are missing.
    let implicit = |sig: usize, at: Span, what: &str, diags: &mut Vec<Diagnostic>| {
        for (p, _) in sigs[sig].params.iter().filter(|(_, m)| *m) {
            diags.push(missing(&sigs[sig], p, at, what));
        }
    };
    let mut i = 0;
    match (rows.first(), find(SubKeyword::Init)) {
        (Some(r), _) if r.keyword == SubKeyword::Init => {
            calls.push(call(r.sig, r.vars.clone(), r.span));
            i = 1;
        }
        (_, Some(init)) => {
            implicit(init, start, "the table has no #Init row first", diags);
            calls.push(call(init, Vec::new(), start));
        }
        _ => {}
    }
    let mut ended = false;
    while i < rows.len() {
        let r = &rows[i];
        i += 1;
        match r.keyword {
            SubKeyword::Init => diags.push(order(codes::PT010.code, r, "an #Init row must be the first row")),
            SubKeyword::End if i < rows.len() => {
                diags.push(order(codes::PT011.code, r, "the #End row must be the last row"))
            }
            SubKeyword::End => {
                ended = true;
                calls.push(call(r.sig, r.vars.clone(), r.span));
            }
            SubKeyword::Rapid | SubKeyword::Move => calls.push(call(r.sig, r.vars.clone(), r.span)),
            SubKeyword::Approach if rows.get(i).is_none_or(|n| n.keyword != SubKeyword::Cycle) => {
                diags.push(order(codes::PT012.code, r, "an #Approach row must be followed by a #Cycle row"));
            }
            SubKeyword::Approach => {}
            SubKeyword::Save => {
                diags.push(order(codes::PT013.code, r, "a #Save row must come right after a #Cycle row"))
            }
            SubKeyword::Retract => {
                diags.push(order(codes::PT014.code, r, "a #Retract row must come after a #Cycle or #Save row"))
            }
            SubKeyword::Cycle => {
                let approach_row = (i >= 2).then(|| &rows[i - 2]).filter(|p| p.keyword == SubKeyword::Approach);
                match (approach_row, find(SubKeyword::Approach)) {
                    (Some(a), _) => calls.push(call(a.sig, a.vars.clone(), a.span)),
                    (None, Some(a)) => {
                        implicit(a, r.span, "this feature has no #Approach row", diags);
                        calls.push(call(a, Vec::new(), r.span));
                    }
                    (None, None) => {}
                }
                calls.push(call(r.sig, r.vars.clone(), r.span));
                if let Some(s) = rows.get(i).filter(|s| s.keyword == SubKeyword::Save) {
                    calls.push(call(s.sig, s.vars.clone(), s.span));
                    i += 1;
                }
                match (rows.get(i).filter(|s| s.keyword == SubKeyword::Retract), find(SubKeyword::Retract)) {
                    (Some(t), _) => {
                        calls.push(call(t.sig, t.vars.clone(), t.span));
                        i += 1;
                    }
                    (None, Some(t)) => {
                        implicit(t, r.span, "this feature has no #Retract row", diags);
                        calls.push(call(t, Vec::new(), r.span));
                    }
                    (None, None) => {}
                }
            }
            SubKeyword::Primer | SubKeyword::Option | SubKeyword::Probe => {}
        }
    }
    if !ended && let Some(end) = find(SubKeyword::End) {
        let at = rows.last().map_or(start, |r| r.end);
        implicit(end, at, "the table has no #End row last", diags);
        calls.push(call(end, Vec::new(), at));
    }
    calls
}

fn order(code: &'static str, r: &Row, message: &str) -> Diagnostic {
    Diagnostic::error(code, message.to_string()).at(r.span, "this row").help(
        "rows run: #Init, then #Rapid/#Move rows and features (#Approach, a #Cycle Sub, #Save, #Retract), then #End",
    )
}

/// An empty table for a post: a comment header, then one row per probe
/// Sub, each cell the name of a parameter (`!` for a mandatory one), in the
/// seed's order: #Init, #Rapid, #Move, #Approach, the #Cycle Subs sorted by
/// name, #Save, #Retract, #End. `None` when the post has no probe Sub.
pub fn template(post: &Post) -> Option<String> {
    let sigs = from_post(post);
    let mut out = String::new();
    let mut rows = 0;
    for k in TABLE_KEYWORDS {
        let mut subs: Vec<&SubSignature> = sigs.iter().filter(|s| s.keyword == Some(*k)).collect();
        subs.sort_by_key(|s| s.name.to_lowercase());
        if *k == SubKeyword::Cycle && !subs.is_empty() {
            out.push_str("# #Cycle Subs: one per feature, between its #Approach row and its #Save/#Retract rows\n");
        }
        for s in subs {
            out.push_str(&csv::quote(&s.name));
            for (p, mandatory) in &s.params {
                out.push(',');
                out.push_str(&csv::quote(&if *mandatory { format!("!{p}") } else { p.clone() }));
            }
            out.push('\n');
            rows += 1;
        }
    }
    if rows == 0 {
        return None;
    }
    let name = if post.info.source.is_empty() { post.info.name.clone() } else { post.info.source.clone() };
    let header = format!(
        "# Probe-cycle table for {name}\n\
         # One row per line: a Sub's name, then its parameters by position or as NAME=VALUE.\n\
         # Replace each parameter name with a number (quote text: \"abc\"); a cell left as\n\
         # the name, or empty, keeps the register's value. `!` marks a mandatory parameter.\n\
         # Rows: #Init first; #Rapid and #Move rows; features (#Approach, one #Cycle Sub,\n\
         # optional #Save, #Retract); #End last. Lines starting with # are comments.\n"
    );
    Some(header + &out)
}
