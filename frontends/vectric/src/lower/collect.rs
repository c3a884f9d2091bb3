//! Reads one parsed file into the [`Model`]: resolves section names, checks
//! `VAR` names and labels, interprets global statements, and applies each
//! definition over what earlier files (the `POST_BASE` chain) defined.
//! Within one file a repeated definition is reported; across files the
//! later file simply overrides.

use postc_ir::{Diagnostic, Modality, Quantity, Section, Span};

use crate::ast::{BeginLine, ItemKind, OutputMode, PostFile, QuotedText, Spanned, TextPiece, VarBody, VarFields};
use crate::decode::Encoding;
use crate::diagnostics::Code;
use crate::lower::globals::interpret;
use crate::lower::model::{GlobalEntry, LineDef, Model, PieceDef, ScriptDef, SectionDef, VarDef};
use crate::names::{GlobalName, label_of_var_name};

/// Where the lines being read go.
enum Target {
    /// Before the first `begin`.
    Nowhere,
    /// Into `model.sections[index]`.
    Section(usize),
    /// An unknown or nameless section: dropped.
    Dropped,
}

/// Applies one file to the model.
pub fn collect(model: &mut Model, post: &PostFile, encoding: Encoding, diags: &mut Vec<Diagnostic>) {
    let mut target = Target::Nowhere;
    // Comment lines not yet given to what they stand before.
    let mut comments: Vec<String> = Vec::new();
    let mut head = true;
    for item in &post.items {
        match &item.kind {
            ItemKind::Comment(text) => {
                // The file's first block of comments is its head (a
                // converted post's header note left out).
                if head && item.blank_before && !comments.is_empty() {
                    head = false;
                    model.doc.extend(without_conversion_note(std::mem::take(&mut comments)));
                }
                comments.push(text.clone());
                continue;
            }
            ItemKind::Stray(_) => continue,
            _ => {}
        }
        if head {
            head = false;
            comments = without_conversion_note(comments);
        }
        match &item.kind {
            ItemKind::Comment(_) | ItemKind::Stray(_) => {}
            ItemKind::Begin(begin) => {
                target = begin_section(model, begin, item.span, diags);
                match &target {
                    Target::Section(i) => model.sections[*i].doc.append(&mut comments),
                    _ => model.doc.append(&mut comments),
                }
            }
            ItemKind::Output(text) => {
                if let Target::Section(i) = &target {
                    model.sections[*i].doc.append(&mut comments);
                }
                if let Some(lines) = lines_of(model, &target, item.span, diags) {
                    lines.push(LineDef::Output(pieces(text, encoding), item.span));
                }
            }
            ItemKind::ScriptCall(code) => {
                diags.push(
                    Code::ScriptNotRun
                        .diag("postc keeps this Lua call but does not run it: the line is skipped when posting")
                        .at(code.span, "Lua call"),
                );
                if let Some(lines) = lines_of(model, &target, item.span, diags) {
                    lines.push(LineDef::Script(ScriptDef { code: code.value.clone(), span: code.span }));
                }
            }
            ItemKind::ScriptBlock(code) => {
                let first_line = Span::new(item.span.file, item.span.start, code.span.start.saturating_sub(1).max(item.span.start));
                diags.push(
                    Code::ScriptNotRun
                        .diag("postc keeps this SCRIPT block but does not run Lua")
                        .at(first_line, "Lua block"),
                );
                model.script_blocks.push(ScriptDef { code: code.value.clone(), span: code.span });
            }
            ItemKind::Global(g) => match GlobalName::from_name(&g.name.value) {
                Some(name) => set_global(model, name, item.span, &g.values, encoding, diags),
                None => diags.push(
                    Code::UnknownGlobal
                        .diag(format!("`{}` is not a statement postc knows", g.name.value))
                        .at(g.name.span, "unknown statement")
                        .help("statements are POST_NAME, FILE_EXTENSION, UNITS, LINE_ENDING, LINE_NUMBER_START, LINE_NUMBER_INCREMENT, LINE_NUMBER_MAXIMUM, SUBSTITUTE, TAPE_SPLITTING, SPINDLE_SPEED_RANGE, ROTARY_WRAP_X, ROTARY_WRAP_Y, DIRECT_OUTPUT, PRINT_DIRECT, RAPID_PLUNGE_TO_STARTZ, LASER_SUPPORT, INVERSE_TIME_MODE, MIN_ARC_RADIUS, MAX_ARC_RADIUS, POST_BASE"),
                ),
            },
            ItemKind::Var(var) => {
                let Some(name) = &var.name else { continue };
                match &var.body {
                    VarBody::Malformed | VarBody::Missing => {}
                    VarBody::Values(values) => match GlobalName::from_name(&name.value) {
                        Some(global) => set_global(model, global, item.span, values, encoding, diags),
                        None => diags.push(
                            Code::MalformedVar
                                .diag("this VAR line needs its format between [ and ] after `=`")
                                .at(item.span, "malformed VAR")
                                .help("write it like this: VAR X_POSITION = [X|C|X|1.3]"),
                        ),
                    },
                    VarBody::Fields(fields) => {
                        declare_var(model, name, fields, encoding, diags);
                        if let Some(v) = model.vars.iter_mut().find(|v| v.name.eq_ignore_ascii_case(&name.value)) {
                            v.doc.append(&mut comments);
                        }
                    }
                }
            }
        }
        // What stands before anything else belongs to the post.
        model.doc.append(&mut comments);
    }
    model.doc.extend(without_conversion_note(comments));
}

/// Comment lines without a backend's header note
/// ([`postc_ir::post::CONVERSION_NOTE`]).
fn without_conversion_note(mut lines: Vec<String>) -> Vec<String> {
    lines.retain(|l| !postc_ir::post::is_conversion_note(l));
    lines
}

/// The lines of the section being read; reports an output line outside
/// any section.
fn lines_of<'m>(
    model: &'m mut Model,
    target: &Target,
    line: Span,
    diags: &mut Vec<Diagnostic>,
) -> Option<&'m mut Vec<LineDef>> {
    match target {
        Target::Section(i) => model.sections.get_mut(*i).map(|s| &mut s.lines),
        Target::Dropped => None,
        Target::Nowhere => {
            diags.push(
                Code::OutputOutsideSection
                    .diag("this output line is not inside any section")
                    .at(line, "before the first `begin`")
                    .help("put a `begin SECTION` line (like `begin HEADER`) before the lines it outputs"),
            );
            None
        }
    }
}

/// `begin NAME`: starts (or replaces) a section.
fn begin_section(model: &mut Model, begin: &BeginLine, line: Span, diags: &mut Vec<Diagnostic>) -> Target {
    let Some(first) = begin.words.first() else {
        return Target::Dropped;
    };
    let joined: String = begin.words.iter().map(|w| w.value.as_str()).collect();
    let last = begin.words.last().map_or(first.span, |w| w.span);
    let section = if let Some(s) = Section::from_name(&joined).filter(|_| begin.words.len() > 1) {
        diags.push(
            Code::BlankInSectionName
                .diag(format!("stray blank in the section name; read as {}", s.name()))
                .at(first.span.to(last), "blank inside the name")
                .help(format!("write `begin {}`", s.name())),
        );
        s
    } else if let Some(s) = Section::from_name(&first.value) {
        if begin.words.len() > 1 {
            let rest = begin.words[1].span.to(last);
            diags.push(
                Code::StrayText
                    .diag("text after the section name is ignored")
                    .at(rest, "ignored")
                    .help("start a comment with + or |"),
            );
        }
        s
    } else {
        let name: Vec<&str> = begin.words.iter().map(|w| w.value.as_str()).collect();
        diags.push(
            Code::UnknownSection
                .diag(format!("`{}` is not a section postc knows; its lines are left out", name.join(" ")))
                .at(first.span.to(last), "unknown section")
                .help("sections are HEADER, FOOTER, TOOLCHANGE, NEW_SEGMENT, SPINDLE_ON, RAPID_MOVE, FEED_MOVE, CW_ARC_MOVE, ... (see the Vectric guide)"),
        );
        return Target::Dropped;
    };
    let fresh = SectionDef { section, span: line, lines: Vec::new(), doc: Vec::new() };
    match model.sections.iter().position(|d| d.section == section) {
        Some(i) => {
            let earlier = model.sections[i].span;
            if earlier.file == line.file {
                diags.push(
                    Code::DuplicateSection
                        .diag(format!(
                            "section {} appears twice; the later one replaces the earlier one",
                            section.name()
                        ))
                        .at(line, "this one is used")
                        .also(earlier, "this one is replaced"),
                );
            }
            model.sections[i] = fresh;
            Target::Section(i)
        }
        None => {
            model.sections.push(fresh);
            Target::Section(model.sections.len() - 1)
        }
    }
}

/// The pieces of an output line, literal text in the file's encoding.
fn pieces(text: &QuotedText, encoding: Encoding) -> Vec<PieceDef> {
    text.pieces
        .iter()
        .map(|p| match &p.value {
            TextPiece::Text(t) => PieceDef::Bytes(encoding.encode(t).into_owned()),
            TextPiece::Code(b) => PieceDef::Bytes(vec![*b]),
            TextPiece::Label(l) => PieceDef::Label {
                label: l.clone(),
                span: p.span,
                literal: encoding.encode(&format!("[{l}]")).into_owned(),
            },
        })
        .collect()
}

/// A global statement: interpreted, then set over earlier ones.
fn set_global(
    model: &mut Model,
    name: GlobalName,
    line: Span,
    values: &[Spanned<crate::ast::Value>],
    encoding: Encoding,
    diags: &mut Vec<Diagnostic>,
) {
    if name == GlobalName::PostBase {
        model.has_post_base = true;
    }
    let Some(value) = interpret(name, line, values, encoding, diags) else {
        return;
    };
    let seq = model.seq();
    let entry = GlobalEntry { name, value, span: line, seq };
    match model.globals.iter().position(|g| g.name == name) {
        Some(i) => {
            let earlier = model.globals[i].span;
            if earlier.file == line.file {
                diags.push(
                    Code::Duplicate
                        .diag(format!("{} is set twice; the later one is used", name.name()))
                        .at(line, "this one is used")
                        .also(earlier, "this one is overridden"),
                );
            }
            model.globals[i] = entry;
        }
        None => model.globals.push(entry),
    }
}

/// A `VAR` with fields: checks its name and label, then sets it over
/// earlier ones.
fn declare_var(
    model: &mut Model,
    name: &Spanned<String>,
    fields: &VarFields,
    encoding: Encoding,
    diags: &mut Vec<Diagnostic>,
) {
    let label = &fields.label;
    let by_label = Quantity::from_label(&label.value);
    let quantity = match label_of_var_name(&name.value) {
        None => {
            let mut d = Code::UnknownVarName
                .diag(format!("`{}` is not a variable name postc knows", name.value))
                .at(name.span, "unknown variable name");
            d = match GlobalName::from_name(&name.value) {
                Some(g) => d.help(format!("{} is a statement, not a variable: write {}", g.name(), g.example())),
                None => d.help("variable names are X_POSITION, FEED_RATE, SPINDLE_SPEED, ... (see the Vectric guide's table of variables)"),
            };
            diags.push(d);
            by_label
        }
        Some(name_label) => {
            let by_name = Quantity::from_label(name_label);
            match by_label {
                Some(q) if Some(q) != by_name => {
                    diags.push(
                        Code::LabelNameMismatch
                            .diag(format!(
                                "VAR {} uses label [{}], which prints {}; the label decides",
                                name.value,
                                label.value,
                                crate::names::var_name_of_label(q.label()).unwrap_or(q.label())
                            ))
                            .at(label.span, "label")
                            .also(name.span, "name")
                            .help(format!("did you mean [{name_label}]?")),
                    );
                    Some(q)
                }
                Some(q) => Some(q),
                None => {
                    diags.push(
                        Code::LabelNameMismatch
                            .diag(format!(
                                "[{}] is not a standard label; it prints {} because of the VAR's name",
                                label.value, name.value
                            ))
                            .at(label.span, "custom label")
                            .help(format!("the usual label of {} is [{name_label}]", name.value)),
                    );
                    by_name
                }
            }
        }
    };
    let Some(quantity) = quantity else { return };
    let seq = model.seq();
    let def = VarDef {
        name: name.value.to_ascii_uppercase(),
        label: label.value.clone(),
        label_span: label.span,
        quantity,
        modality: match fields.mode.value {
            OutputMode::Always => Modality::Always,
            OutputMode::OnChange => Modality::OnChange,
        },
        prefix: encoding.encode(&fields.prefix.value).into_owned(),
        format: fields.format.value,
        format_span: fields.format.span,
        multiplier: fields.multiplier.as_ref().map_or(1.0, |m| m.value),
        seq,
        span: fields.span,
        doc: Vec::new(),
    };
    if let Some(other) = model.vars.iter().find(|v| {
        v.label.eq_ignore_ascii_case(&def.label) && v.name != def.name && v.label_span.file == def.label_span.file
    }) {
        diags.push(
            Code::Duplicate
                .diag(format!(
                    "label [{}] is declared by {} and by {}; the later one is used",
                    def.label, other.name, def.name
                ))
                .at(def.label_span, "this one is used")
                .also(other.label_span, "this one is overridden"),
        );
    }
    match model.vars.iter().position(|v| v.name == def.name) {
        Some(i) => {
            let earlier = model.vars[i].label_span;
            if earlier.file == def.label_span.file {
                diags.push(
                    Code::Duplicate
                        .diag(format!("VAR {} is declared twice; the later one is used", def.name))
                        .at(name.span, "this one is used")
                        .also(earlier, "this one is overridden"),
                );
            }
            model.vars[i] = def;
        }
        None => model.vars.push(def),
    }
}
