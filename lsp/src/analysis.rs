//! Hover, definition, completion and code actions, from the document's
//! text with small dialect-aware scanners (the IR keeps no symbols).

use postc_front_cimco::fusion;
use postc_front_vectric::names::{VAR_NAMES, label_of_var_name, var_name_of_label};
use postc_ir::Dialect;
use postc_ir::post::Section;

use crate::text::{edit_distance, leading_name, line_around, lines, strip_keyword, word_at};
use crate::vocab::{self, lookup};

/// What a hover shows: markdown, and the byte range it is about.
pub struct Hover {
    pub markdown: String,
    pub start: usize,
    pub end: usize,
}

/// One completion: label, kind and a one-line detail.
pub struct Completion {
    pub label: String,
    pub kind: CompletionKind,
    pub detail: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompletionKind {
    Section,
    Variable,
    Function,
    Constant,
    Keyword,
    Property,
}

/// `text` with `fixes` applied (they must not overlap).
pub fn apply(text: &str, fixes: &[Fix]) -> String {
    let mut order: Vec<&Fix> = fixes.iter().collect();
    order.sort_by_key(|f| std::cmp::Reverse(f.start));
    let mut out = text.to_string();
    for f in order {
        if f.start <= f.end && f.end <= out.len() && out.is_char_boundary(f.start) && out.is_char_boundary(f.end) {
            out.replace_range(f.start..f.end, &f.replacement);
        }
    }
    out
}

/// A fix: replace a byte range with a text.
pub struct Fix {
    pub title: String,
    pub start: usize,
    pub end: usize,
    pub replacement: String,
}

fn entry(name: &str, what: &str, doc: &str) -> String {
    format!("**{name}** — {what}\n\n{doc}")
}

/// The hover at a byte offset.
pub fn hover(dialect: Dialect, text: &str, at: usize) -> Option<Hover> {
    // On the opening `[` or `<` of a label or register: the name after it.
    let at = match text.as_bytes().get(at) {
        Some(b'[' | b'<') => at + 1,
        _ => at,
    };
    let (start, end) = word_at(text, at)?;
    let word = &text[start..end];
    let before = text.as_bytes()[..start].last().copied();
    let (line_start, _) = line_around(text, start);
    let line_head = text[line_start..start].trim();
    let markdown = match dialect {
        Dialect::Vectric => vectric_hover(text, word, before, line_head)?,
        Dialect::Cimco => cimco_hover(text, word)?,
        Dialect::Fusion => fusion_hover(text, word, before)?,
        Dialect::VcPost => vcpost_hover(text, word, before)?,
        Dialect::Ron => return None,
    };
    Some(Hover { markdown, start, end })
}

fn vectric_hover(text: &str, word: &str, before: Option<u8>, line_head: &str) -> Option<String> {
    let label = |label: &str| {
        let (name, doc) = lookup(vocab::VECTRIC_LABELS, label)?;
        let var = var_name_of_label(name).unwrap_or("?");
        let mut s = entry(&format!("[{name}]"), &format!("label of `VAR {var}`"), doc);
        if let Some((line, _, _)) = vectric_var_line(text, name) {
            s.push_str(&format!("\n\n```\n{}\n```", line.trim()));
        }
        Some(s)
    };
    let section = |word: &str| lookup(vocab::VECTRIC_SECTIONS, word).map(|(n, d)| entry(n, "section", d));
    if before == Some(b'[') {
        return label(word);
    }
    if line_head.eq_ignore_ascii_case("begin") {
        return section(word);
    }
    if line_head.eq_ignore_ascii_case("var") {
        return label(label_of_var_name(word)?);
    }
    if let Some((n, d)) = lookup(vocab::VECTRIC_GLOBALS, word) {
        return Some(entry(n, "global setting", d));
    }
    section(word).or_else(|| label(label_of_var_name(word)?))
}

fn cimco_hover(text: &str, word: &str) -> Option<String> {
    if let Some((n, sig, d)) = vocab::CIMCO_FUNCTIONS.iter().copied().find(|(n, _, _)| *n == word) {
        let what = if n.starts_with("on") { "called by the host" } else { "host function" };
        return Some(format!("**{n}** — {what}\n\n```js\n{sig}\n```\n\n{d}"));
    }
    if let Some((n, d)) = vocab::CIMCO_GLOBALS.iter().copied().find(|(n, _)| *n == word) {
        return Some(entry(n, "host constant or global", d));
    }
    let (line, _, _) = cimco_definition(text, word)?;
    Some(format!("```js\n{}\n```", line.trim()))
}

/// A Fusion post's name: the post's own definition, and the declaration of
/// Fusion's host API with what postc's host does with it.
fn fusion_hover(text: &str, word: &str, before: Option<u8>) -> Option<String> {
    let own = cimco_definition(text, word).map(|(line, _, _)| format!("```js\n{}\n```", line.trim()));
    let host = (before != Some(b'.')).then(|| fusion::api::declaration(word)).flatten().map(fusion_entry);
    match (own, host) {
        (Some(own), Some(host)) => Some(format!("{own}\n\n---\n\n{host}")),
        (own, host) => own.or(host),
    }
}

/// The hover of a declared name of Fusion's host API.
fn fusion_entry(d: &fusion::api::Declaration) -> String {
    let what = match d.kind {
        fusion::api::Kind::Function if d.name.starts_with("on") => "entry point, called by the host",
        fusion::api::Kind::Function => "host function",
        fusion::api::Kind::Constant => "host constant",
        fusion::api::Kind::Variable => "host setting or object",
    };
    let mut s = format!("**{}** — Fusion {what}\n\n```ts\n{}\n```", d.name, d.signature);
    if !d.doc.is_empty() {
        s.push_str(&format!("\n\n{}", d.doc));
    }
    let postc = match fusion::support(d.name) {
        fusion::Support::Runs { value: Some(v) } if v.len() <= 60 && !v.contains('\n') => {
            format!("postc's host: `{} = {v}`", d.name)
        }
        fusion::Support::Runs { .. } => "postc's host defines it.".to_string(),
        fusion::Support::Stub => {
            "postc does not run it yet: a post that reaches it stops with a message naming it (JS110).".to_string()
        }
        fusion::Support::Missing => {
            "postc's host does not define it: a post that uses it is refused (JS109), unless it defines it itself."
                .to_string()
        }
    };
    s.push_str(&format!("\n\n{postc}\n\n*(declaration: Autodesk/cam-posteditor, MIT)*"));
    s
}

fn vcpost_hover(text: &str, word: &str, before: Option<u8>) -> Option<String> {
    if before == Some(b'.')
        && let Some((n, d)) = lookup(vocab::VCPOST_PROPERTIES, word)
    {
        return Some(entry(n, "register property", d));
    }
    if let Some((line, _, _)) = vcpost_definition(text, word) {
        let mut s = format!("```vb\n{}\n```", line.trim());
        if let Some((_, d)) = lookup(vocab::VCPOST_WORDS, word) {
            s.push_str(&format!("\n\nAPT record handler: {d}"));
        }
        return Some(s);
    }
    if let Some((n, d)) = lookup(vocab::VCPOST_REGISTERS, word) {
        return Some(entry(n, "register set by the runtime", d));
    }
    if let Some((n, d)) = lookup(vocab::VCPOST_BUILTINS, word) {
        return Some(entry(n, "built-in function", d));
    }
    if let Some((n, d)) = lookup(vocab::VCPOST_WORDS, word) {
        return Some(entry(n, "APT record (Sub name)", d));
    }
    None
}

/// The `VAR` line whose bracket prints `label`: the line, and the byte
/// range of its `VAR` name.
fn vectric_var_line<'t>(text: &'t str, label: &str) -> Option<(&'t str, usize, usize)> {
    for (at, line) in lines(text) {
        let trimmed = line.trim_start();
        let Some(rest) = strip_keyword(trimmed, "VAR") else { continue };
        let name = leading_name(rest);
        let Some(open) = rest.find('[') else { continue };
        let inside = &rest[open + 1..];
        let this = inside.split(['|', ']']).next().unwrap_or("").trim();
        if this.eq_ignore_ascii_case(label) {
            let start = at + (line.len() - trimmed.len()) + (trimmed.len() - rest.len());
            return Some((line, start, start + name.len()));
        }
    }
    None
}

/// The line defining a CIMCO name: `function name(`, `var name`, or
/// `name = ...` at the start of a line.
fn cimco_definition<'t>(text: &'t str, name: &str) -> Option<(&'t str, usize, usize)> {
    let mut fallback = None;
    for (at, line) in lines(text) {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        let found = |rest: &str| {
            let n = leading_name(rest);
            (n == name).then(|| {
                let start = at + indent + (trimmed.len() - rest.len());
                (line, start, start + n.len())
            })
        };
        if let Some(rest) = strip_keyword(trimmed, "function")
            && let Some(hit) = found(rest)
        {
            return Some(hit);
        }
        if fallback.is_some() {
            continue;
        }
        let rest = strip_keyword(trimmed, "var")
            .or_else(|| strip_keyword(trimmed, "let"))
            .or_else(|| strip_keyword(trimmed, "const"))
            .unwrap_or(trimmed);
        if let Some(hit) = found(rest) {
            let after = rest[name.len()..].trim_start();
            if (after.starts_with('=') && !after.starts_with("=="))
                || after.starts_with(';')
                || rest.len() != trimmed.len()
            {
                fallback = Some(hit);
            }
        }
    }
    fallback
}

/// The `Sub`/`Function` line of a VcPost name (any case).
fn vcpost_definition<'t>(text: &'t str, name: &str) -> Option<(&'t str, usize, usize)> {
    for (at, line) in lines(text) {
        let trimmed = line.trim_start();
        let mut rest = trimmed;
        for scope in ["Public", "Private"] {
            rest = strip_keyword(rest, scope).unwrap_or(rest);
        }
        let Some(rest) = strip_keyword(rest, "Sub").or_else(|| strip_keyword(rest, "Function")) else { continue };
        let n = leading_name(rest);
        if n.eq_ignore_ascii_case(name) {
            let start = at + (line.len() - trimmed.len()) + (trimmed.len() - rest.len());
            return Some((line, start, start + n.len()));
        }
    }
    None
}

/// The functions and top-level `var`s a CIMCO post defines, with their
/// lines (host names the tables describe are left to the tables).
fn cimco_names(text: &str) -> Vec<(&str, CompletionKind, &str)> {
    let mut out: Vec<(&str, CompletionKind, &str)> = Vec::new();
    for (_, line) in lines(text) {
        let (rest, kind) = if let Some(rest) = strip_keyword(line, "function") {
            (rest, CompletionKind::Function)
        } else if let Some(rest) = strip_keyword(line, "var") {
            (rest, CompletionKind::Variable)
        } else {
            continue;
        };
        let name = leading_name(rest);
        let known =
            vocab::CIMCO_FUNCTIONS.iter().any(|f| f.0 == name) || vocab::CIMCO_GLOBALS.iter().any(|g| g.0 == name);
        if !name.is_empty() && !known && !out.iter().any(|o| o.0 == name) {
            out.push((name, kind, line));
        }
    }
    out
}

/// The Subs and Functions a VcPost post defines, with their lines.
fn vcpost_subs(text: &str) -> Vec<(&str, &str)> {
    let mut out: Vec<(&str, &str)> = Vec::new();
    for (_, line) in lines(text) {
        let mut rest = line.trim_start();
        for scope in ["Public", "Private"] {
            rest = strip_keyword(rest, scope).unwrap_or(rest);
        }
        let Some(rest) = strip_keyword(rest, "Sub").or_else(|| strip_keyword(rest, "Function")) else { continue };
        let name = leading_name(rest);
        if !name.is_empty() && !out.iter().any(|o| o.0.eq_ignore_ascii_case(name)) {
            out.push((name, line));
        }
    }
    out
}

/// Where the name at a byte offset is defined in the same document.
pub fn definition(dialect: Dialect, text: &str, at: usize) -> Option<(usize, usize)> {
    let (start, end) = word_at(text, at)?;
    let word = &text[start..end];
    let found = match dialect {
        Dialect::Vectric => {
            let label = if text[..start].ends_with('[') { Some(word) } else { label_of_var_name(word) };
            vectric_var_line(text, label?)
        }
        Dialect::Cimco | Dialect::Fusion => cimco_definition(text, word),
        Dialect::VcPost => vcpost_definition(text, word),
        Dialect::Ron => None,
    };
    found.map(|(_, s, e)| (s, e))
}

/// Completions at a byte offset. `after_space`: the editor asks because
/// a blank was typed; only a section name after `begin ` (or a `VAR`
/// name after `VAR `) is worth offering then.
pub fn completion(dialect: Dialect, text: &str, at: usize, after_space: bool) -> Vec<Completion> {
    let at = at.min(text.len());
    let (line_start, _) = line_around(text, at);
    let head = &text[line_start..at];
    let word_start = head.len() - head.bytes().rev().take_while(|&b| crate::text::is_name_byte(b)).count();
    let before_word = &head[..word_start];
    let mut out = Vec::new();
    let keyword_before = ["begin", "var"].iter().any(|k| before_word.trim().eq_ignore_ascii_case(k));
    if after_space && (dialect != Dialect::Vectric || !keyword_before) {
        return Vec::new();
    }
    let mut add = |label: &str, kind, detail: &str| {
        out.push(Completion { label: label.to_owned(), kind, detail: detail.to_owned() })
    };
    match dialect {
        Dialect::Vectric => {
            let open_bracket = before_word.ends_with('[');
            if before_word.trim().eq_ignore_ascii_case("begin") {
                for s in Section::ALL {
                    let d = lookup(vocab::VECTRIC_SECTIONS, s.name()).map_or("", |e| e.1);
                    add(s.name(), CompletionKind::Section, d);
                }
            } else if open_bracket {
                for (var, label) in VAR_NAMES {
                    let d = lookup(vocab::VECTRIC_LABELS, label).map_or("", |e| e.1);
                    add(label, CompletionKind::Variable, &format!("VAR {var}: {d}"));
                }
            } else if before_word.trim().eq_ignore_ascii_case("var") {
                for (var, label) in VAR_NAMES {
                    add(var, CompletionKind::Variable, &format!("prints [{label}]"));
                }
            } else if before_word.trim().is_empty() {
                add("begin", CompletionKind::Keyword, "starts a section");
                add("VAR", CompletionKind::Keyword, "declares how a label is formatted");
                for (n, d) in vocab::VECTRIC_GLOBALS {
                    add(n, CompletionKind::Constant, d);
                }
            }
        }
        Dialect::Cimco => {
            if before_word.ends_with('.') {
                add("format", CompletionKind::Function, "formats a value");
                add("getLast", CompletionKind::Function, "the last value written");
            } else {
                for (n, sig, _) in vocab::CIMCO_FUNCTIONS {
                    if *n != "format" && *n != "getLast" {
                        add(n, CompletionKind::Function, sig);
                    }
                }
                for (n, d) in vocab::CIMCO_GLOBALS {
                    add(n, CompletionKind::Constant, d);
                }
                for (name, kind, line) in cimco_names(text) {
                    add(name, kind, line.trim());
                }
            }
        }
        Dialect::Fusion => {
            if !before_word.ends_with('.') {
                let own = cimco_names(text);
                for (name, kind, line) in &own {
                    add(name, *kind, line.trim());
                }
                for d in fusion::api::declarations().iter().filter(|d| own.iter().all(|(n, _, _)| *n != d.name)) {
                    let kind = match d.kind {
                        fusion::api::Kind::Function => CompletionKind::Function,
                        fusion::api::Kind::Constant => CompletionKind::Constant,
                        fusion::api::Kind::Variable => CompletionKind::Variable,
                    };
                    add(d.name, kind, d.signature);
                }
            }
        }
        Dialect::VcPost => {
            let open_angle = before_word.ends_with('<');
            if open_angle {
                for (n, d) in vocab::VCPOST_REGISTERS {
                    add(n, CompletionKind::Variable, d);
                }
            } else if before_word.ends_with('.') {
                for (n, d) in vocab::VCPOST_PROPERTIES {
                    add(n, CompletionKind::Property, d);
                }
            } else {
                for k in vocab::VCPOST_KEYWORDS {
                    add(k, CompletionKind::Keyword, "keyword");
                }
                for (n, d) in vocab::VCPOST_BUILTINS {
                    add(n, CompletionKind::Function, d);
                }
                for (n, d) in vocab::VCPOST_WORDS {
                    add(n, CompletionKind::Function, d);
                }
                for (n, d) in vocab::VCPOST_REGISTERS {
                    add(n, CompletionKind::Variable, d);
                }
                for (name, line) in vcpost_subs(text) {
                    add(name, CompletionKind::Function, line.trim());
                }
            }
        }
        Dialect::Ron => {}
    }
    out
}

/// The fixes within a byte range, each certain: a misspelt section after
/// `begin` with exactly one known section within edit distance 2, and a
/// label in an output string whose `]` is missing (`"G0 [X"`: the name
/// after the `[` is a whole known label, and no `]` follows it).
pub fn fixes(dialect: Dialect, text: &str, start: usize, end: usize) -> Vec<Fix> {
    let mut out = Vec::new();
    if dialect != Dialect::Vectric {
        return out;
    }
    for (at, line) in lines(text) {
        if at > end || at + line.len() < start {
            continue;
        }
        out.extend(missing_brackets(at, line));
        let trimmed = line.trim_start();
        let Some(rest) = strip_keyword(trimmed, "begin") else { continue };
        let name = leading_name(rest);
        if name.is_empty() || Section::from_name(name).is_some() {
            continue;
        }
        let mut close = Section::ALL.iter().map(|s| s.name()).filter(|s| edit_distance(s, name) <= 2);
        if let (Some(only), None) = (close.next(), close.next()) {
            let name_start = at + (line.len() - trimmed.len()) + (trimmed.len() - rest.len());
            out.push(Fix {
                title: format!("Replace `{name}` with `{only}`"),
                start: name_start,
                end: name_start + name.len(),
                replacement: only.to_owned(),
            });
        }
    }
    out
}

/// `]` for each label of an output line that is not closed.
fn missing_brackets(at: usize, line: &str) -> Vec<Fix> {
    let mut out = Vec::new();
    let trimmed = line.trim_start();
    if !trimmed.starts_with('"') {
        return out;
    }
    let body_start = line.len() - trimmed.len() + 1;
    let body = &line[body_start..];
    let body = body.rfind('"').map_or(body, |q| &body[..q]);
    let mut i = 0;
    while let Some(open) = body[i..].find('[') {
        let name_start = i + open + 1;
        let name_len = body[name_start..]
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(body.len() - name_start);
        let name = &body[name_start..name_start + name_len];
        let after = body[name_start + name_len..].chars().next();
        i = name_start + name_len;
        if after == Some(']') || name.is_empty() || postc_ir::Quantity::from_label(name).is_none() {
            continue;
        }
        let closed = body[name_start + name_len..].find(']');
        let reopened = body[name_start + name_len..].find('[');
        // A `]` further on that no `[` comes before belongs to this label.
        if closed.is_some_and(|c| reopened.is_none_or(|r| c < r)) {
            continue;
        }
        let insert = at + body_start + name_start + name_len;
        out.push(Fix {
            title: format!("Close `[{name}` with `]`"),
            start: insert,
            end: insert,
            replacement: "]".into(),
        });
    }
    out
}
