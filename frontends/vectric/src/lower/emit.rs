//! Turns the merged [`Model`] into the IR [`Post`]: post info and output
//! options from the global statements, one number format and one variable
//! per `VAR`, a variable with the seed's default format for each label the
//! sections use without declaring it, and one handler per section whose
//! lines are literal bytes and variables.

use std::collections::HashMap;

use postc_ir::post::{BlockNumbers, VarId};
use postc_ir::{
    CommentTarget, Diagnostic, Dialect, Dispatch, FormatId, Handler, HandlerKey, NumberFormat, OutputOptions, Piece,
    Post, PostInfo, Quantity, Script, ScriptId, ScriptLanguage, Span, Stmt, Units, ValueSource, Variable,
};

use crate::defaults::default_format;
use crate::diagnostics::Code;
use crate::format_spec::FormatSpec;
use crate::lower::model::{GlobalValue, LineDef, Model, PieceDef, ScriptDef};
use crate::names::{GlobalName, var_name_of_label};

/// Block numbering when the post says nothing: the values the seed's
/// "Block Numbering" section shows.
const DEFAULT_BLOCK_NUMBERS: BlockNumbers = BlockNumbers { start: 0.0, increment: 10.0, maximum: 999_999.0 };

/// Builds the post. `source` names the post file; `anchor` is where
/// diagnostics about the whole post point.
pub fn emit(model: &Model, source: &str, anchor: Span, diags: &mut Vec<Diagnostic>) -> Post {
    let mut post = Post { info: info(model, source), options: options(model, diags), ..Post::default() };
    let no_units = (model.global(GlobalName::Units).is_none() && !model.has_post_base).then(|| {
        diags.push(
            Code::NoUnits
                .diag("this post has no UNITS statement: it writes the toolpath's own units")
                .at(model.global(GlobalName::PostName).map_or(anchor, |g| g.span), "no UNITS in this post")
                .help("add UNITS = \"MM\" or UNITS = \"INCHES\""),
        );
        diags.len() - 1
    });
    let mut vars = Variables::default();
    for def in &model.vars {
        let id = vars.add(
            &mut post,
            Variable {
                name: def.name.clone(),
                source: ValueSource::Quantity(def.quantity),
                prefix: def.prefix.clone(),
                format: FormatId::new(0),
                modality: def.modality,
                span: Some(def.span),
            },
            def.format,
            Some(def.format_span),
            def.multiplier,
            Some((&def.label, def.seq)),
        );
        if let Some(id) = id {
            vars.declared_at.insert(id, def.label_span);
            post.add_comment(CommentTarget::Variable(id), def.doc.clone());
        }
    }
    post.add_comment(CommentTarget::Post, model.doc.clone());
    for block in &model.script_blocks {
        push_script(&mut post, block);
    }
    for section in &model.sections {
        let mut body = Vec::with_capacity(section.lines.len());
        for line in &section.lines {
            match line {
                LineDef::Output(pieces, span) => body
                    .push(Stmt::Line { pieces: line_pieces(&mut post, &mut vars, pieces, diags), span: Some(*span) }),
                LineDef::Script(script) => {
                    if let Some(id) = push_script(&mut post, script) {
                        body.push(Stmt::Script(id));
                    }
                }
            }
        }
        post.handlers.push(Handler { key: HandlerKey::Section(section.section), body, span: Some(section.span) });
        post.add_comment(CommentTarget::Handler(HandlerKey::Section(section.section)), section.doc.clone());
    }
    crate::lower::lint::coarse_arc_words(&post, &vars, diags);
    // A post that writes G21 (or G20) and no other units word writes that
    // system (docs/units.md): the warning says which.
    if let Some(d) = no_units.and_then(|at| diags.get_mut(at))
        && let Some(units) = post.output_units()
    {
        let (word, name) = if units == Units::Mm { ("G21", "millimetres") } else { ("G20", "inches") };
        d.message = format!(
            "this post has no UNITS statement: it writes {word}, so its output is in {name} (toolpaths in other units are converted)"
        );
    }
    post
}

/// The variables of the post, by label.
#[derive(Default)]
pub struct Variables {
    /// Upper-case label to variable and the sequence number that set it.
    by_label: HashMap<String, (VarId, usize)>,
    /// Where each declared variable's label is written.
    pub declared_at: HashMap<VarId, Span>,
    /// The first use of each default variable.
    pub first_use: HashMap<VarId, Span>,
}

impl Variables {
    fn add(
        &mut self,
        post: &mut Post,
        mut variable: Variable,
        format: FormatSpec,
        format_span: Option<Span>,
        multiplier: f64,
        label: Option<(&str, usize)>,
    ) -> Option<VarId> {
        variable.format =
            post.push_format(NumberFormat { span: format_span, ..format.to_number_format(multiplier) })?;
        let id = post.push_variable(variable)?;
        if let Some((label, seq)) = label {
            let key = label.to_ascii_uppercase();
            if self.by_label.get(&key).is_none_or(|&(_, s)| s < seq) {
                self.by_label.insert(key, (id, seq));
            }
        }
        Some(id)
    }

    /// The variable a label prints: a declared one, or a new one with the
    /// default format of the label's quantity.
    fn resolve(&mut self, post: &mut Post, label: &str, at: Span) -> Option<VarId> {
        let key = label.to_ascii_uppercase();
        if let Some(&(id, _)) = self.by_label.get(&key) {
            return Some(id);
        }
        let quantity = Quantity::from_label(label)?;
        let default = default_format(quantity);
        let variable = Variable {
            name: var_name_of_label(quantity.label()).unwrap_or(quantity.label()).to_string(),
            source: ValueSource::Quantity(quantity),
            prefix: default.prefix.as_bytes().to_vec(),
            format: FormatId::new(0),
            modality: default.modality,
            span: Some(at),
        };
        let id = self.add(post, variable, default.format, None, 1.0, Some((label, 0)))?;
        self.first_use.insert(id, at);
        Some(id)
    }
}

/// The pieces of one output line, adjacent literal bytes merged.
fn line_pieces(post: &mut Post, vars: &mut Variables, pieces: &[PieceDef], diags: &mut Vec<Diagnostic>) -> Vec<Piece> {
    let mut out: Vec<Piece> = Vec::with_capacity(pieces.len());
    let push_bytes = |out: &mut Vec<Piece>, bytes: &[u8]| match out.last_mut() {
        Some(Piece::Text(t)) => t.extend_from_slice(bytes),
        _ if bytes.is_empty() => {}
        _ => out.push(Piece::Text(bytes.to_vec())),
    };
    for piece in pieces {
        match piece {
            PieceDef::Bytes(b) => push_bytes(&mut out, b),
            PieceDef::Label { label, span, literal } => match vars.resolve(post, label, *span) {
                Some(id) => out.push(Piece::Var(id)),
                None => {
                    diags.push(
                        Code::UnknownLabel
                            .diag(format!("[{label}] is not a variable postc knows; it prints as written"))
                            .at(*span, "unknown variable")
                            .help("write [91] and [93] to print square brackets; variables are [X], [Y], [Z], [F], [S], [T], ... or a label declared with VAR"),
                    );
                    push_bytes(&mut out, literal);
                }
            },
        }
    }
    out
}

/// Adds a Lua script to the post.
fn push_script(post: &mut Post, script: &ScriptDef) -> Option<ScriptId> {
    post.push_script(Script {
        language: ScriptLanguage::Lua,
        source: script.code.clone(),
        span: Some(script.span),
        span_map: vec![(0, u32::try_from(script.span.start).unwrap_or(u32::MAX))],
    })
}

fn text(model: &Model, name: GlobalName) -> Option<String> {
    match model.global(name).map(|g| &g.value) {
        Some(GlobalValue::Text(t)) => Some(t.clone()),
        _ => None,
    }
}

fn flag(model: &Model, name: GlobalName) -> bool {
    matches!(model.global(name).map(|g| &g.value), Some(GlobalValue::Flag(true)))
}

fn number(model: &Model, name: GlobalName) -> Option<f64> {
    match model.global(name).map(|g| &g.value) {
        Some(GlobalValue::Number(n)) => Some(*n),
        _ => None,
    }
}

fn info(model: &Model, source: &str) -> PostInfo {
    PostInfo {
        name: text(model, GlobalName::PostName).unwrap_or_default(),
        dialect: Dialect::Vectric,
        source: source.to_string(),
        file_extension: text(model, GlobalName::FileExtension)
            .map(|e| e.trim().trim_start_matches('.').to_string())
            .unwrap_or_default(),
        units: match model.global(GlobalName::Units).map(|g| &g.value) {
            Some(GlobalValue::Units(u)) => Some(*u),
            _ => None,
        },
        reads_units: false,
        dispatch: Dispatch::Sections,
        laser_support: flag(model, GlobalName::LaserSupport),
        direct_output: text(model, GlobalName::DirectOutput),
        print_direct: flag(model, GlobalName::PrintDirect),
        rapid_plunge_to_start_z: flag(model, GlobalName::RapidPlungeToStartZ),
        text_encoding: postc_ir::post::TextEncoding::Utf8,
        subs: Vec::new(),
        notes: Vec::new(),
        revision: String::new(),
        span: model.global(GlobalName::PostName).map(|g| g.span),
        host_file: None,
        written: String::new(),
    }
}

fn options(model: &Model, diags: &mut Vec<Diagnostic>) -> OutputOptions {
    let mut options = OutputOptions {
        line_ending: b"\r\n".to_vec(),
        block_numbers: DEFAULT_BLOCK_NUMBERS,
        // Decision 4 (docs/vectric.md): all modal memory is cleared when a
        // toolpath starts.
        forget_modal_at_toolpath_start: true,
        // What VCarve's own programs show (docs/vectric.md): a `C` word
        // prints when its value changes, and the feed prints again on the
        // first feed move after a rapid.
        on_change_by_value: true,
        rapid_forgets_feed: true,
        ..OutputOptions::default()
    };
    for global in &model.globals {
        match (&global.name, &global.value) {
            (GlobalName::LineEnding, GlobalValue::Bytes(b)) => options.line_ending = b.clone(),
            (GlobalName::Substitute, GlobalValue::Substitutions(s)) => options.substitutions = s.clone(),
            (GlobalName::TapeSplitting, GlobalValue::Tape(t)) => options.tape_splitting = t.clone(),
            (GlobalName::SpindleSpeedRange, GlobalValue::SpindleRange(r)) => options.spindle_speed_range = Some(*r),
            _ => {}
        }
    }
    if let Some(n) = number(model, GlobalName::LineNumberStart) {
        options.block_numbers.start = n;
    }
    if let Some(n) = number(model, GlobalName::LineNumberIncrement) {
        options.block_numbers.increment = n;
    }
    if let Some(n) = number(model, GlobalName::LineNumberMaximum) {
        options.block_numbers.maximum = n;
    }
    options.min_arc_radius = number(model, GlobalName::MinArcRadius);
    options.max_arc_radius = number(model, GlobalName::MaxArcRadius);
    options.inverse_time_feed = flag(model, GlobalName::InverseTimeMode);
    // A wrap set to "NO" is no wrap: it neither conflicts nor wins.
    let on = |name| model.global(name).filter(|g| matches!(g.value, GlobalValue::Wrap(Some(_))));
    let x = on(GlobalName::RotaryWrapX);
    let y = on(GlobalName::RotaryWrapY);
    if let (Some(x), Some(y)) = (x, y) {
        let (used, ignored) = if x.seq > y.seq { (x, y) } else { (y, x) };
        diags.push(
            Code::TwoRotaryWraps
                .diag(format!("both ROTARY_WRAP_X and ROTARY_WRAP_Y are set; only {} is used", used.name.name()))
                .at(used.span, "used")
                .also(ignored.span, "ignored"),
        );
    }
    let wrap = [x, y].into_iter().flatten().max_by_key(|g| g.seq);
    if let Some(GlobalValue::Wrap(w)) = wrap.map(|g| &g.value) {
        options.rotary_wrap = *w;
    }
    options
}
