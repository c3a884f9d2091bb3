//! Section posts: postc's extension of CNC-Calc JavaScript for posts driven
//! by the kind of each move, so that any Vectric post converts to CIMCO
//! (`postc convert --to cimco`, docs/cimco.md "Section posts").
//!
//! A post is a section post when it defines a function named after a
//! Vectric section (`FEED_MOVE`, exactly so written) and no CNC-Calc entry
//! point (`on...`). It has one narrow form, and anything else in it is
//! JS107:
//!
//! ```js
//! var postcOptions = {name: "G-code (mm)", fileExtension: "nc", units: "MM", lineEnding: "\r\n"};
//! var X = createVariable({prefix: "X", label: "X", modal: true}, createFormat({decimals: 3, trim: false}));
//! function FEED_MOVE() {
//!   return "G1" + X + Y + Z + F + "\n";
//! }
//! ```
//!
//! - `postcOptions` holds what Vectric's global statements say (and
//!   `textEncoding: "windows-1252"` for output text in that encoding);
//! - each variable prints a Vectric label (`label`), with a prefix, a
//!   modality (`modal`) and a format whose keys name [`NumberFormat`]'s
//!   fields (defaults are the IR's);
//! - each section function returns the section's lines: text and
//!   variables joined with `+`, each line ended by `"\n"` (the post's line
//!   ending is `lineEnding`).
//!
//! CNC-Calc itself does not run such a post (it calls only its `on...`
//! functions): a section post runs in postc.

use postc_ir::codes;
use postc_ir::post::{
    BlockNumbers, Dispatch, RotaryWrap, Section, SpindleSpeedRange, Substitution, TapeSplitting, WrappedAxis,
};
use postc_ir::{
    CommentTarget, Diagnostic, FormatId, Handler, HandlerKey, Justify, Modality, NumberFormat, Padding, Piece,
    PointStyle, Post, Quantity, SignStyle, Span, Stmt, Units, ValueSource, VarId, Variable, WidthOf,
};

use crate::ast::{BinaryOp, Expr, ExprKind, Program, StmtKind};

/// The name of the options object.
pub const OPTIONS: &str = "postcOptions";

/// Whether a program is a section post.
pub fn is_section_post(program: &Program) -> bool {
    let functions = || {
        program.body.iter().filter_map(|s| match &s.kind {
            StmtKind::Function(f) => f.name.as_ref().map(|n| n.name.as_str()),
            _ => None,
        })
    };
    functions().any(|n| Section::from_name(n).is_some_and(|s| s.name() == n))
        && !functions().any(|n| n.strip_prefix("on").is_some_and(|r| r.starts_with(|c: char| c.is_ascii_uppercase())))
}

/// Lowers a section post into `post`.
pub fn lower(program: &Program, text: &str, post: &mut Post, diags: &mut Vec<Diagnostic>) {
    post.info.dispatch = Dispatch::Sections;
    post.info.file_extension.clear();
    post.options.forget_modal_at_toolpath_start = true;
    // Text is JavaScript's: `"a" + null` is "anull".
    post.options.js_text = true;
    let mut l = Lowerer { post, diags, names: Vec::new() };
    for s in &program.body {
        match &s.kind {
            StmtKind::Var(ds) => {
                for d in ds {
                    let Some(init) = &d.init else {
                        l.refuse(d.span, "a variable without a value");
                        continue;
                    };
                    if d.name.name == OPTIONS {
                        l.options(init);
                    } else {
                        l.variable(&d.name.name, init, d.span);
                    }
                }
            }
            StmtKind::Function(f) => {
                let name = f.name.as_ref().map(|n| n.name.as_str()).unwrap_or_default();
                let Some(section) = Section::from_name(name).filter(|s| s.name() == name) else {
                    l.refuse(f.span, "a function that is not named after a section");
                    continue;
                };
                if !f.params.is_empty() {
                    l.refuse(f.span, "a section function with parameters");
                    continue;
                }
                let body = match f.body.as_slice() {
                    [one] => match &one.kind {
                        StmtKind::Return(Some(e)) => l.lines(e),
                        _ => None,
                    },
                    _ => None,
                };
                match body {
                    Some(body) => {
                        if l.post.handlers.iter().any(|h| h.key == HandlerKey::Section(section)) {
                            l.refuse(f.span, "a second function for one section");
                        } else {
                            l.post.handlers.push(Handler {
                                key: HandlerKey::Section(section),
                                body,
                                span: Some(f.span),
                            });
                        }
                    }
                    None => l.refuse(f.span, "a section function that does more than `return` its lines"),
                }
            }
            StmtKind::Empty => {}
            _ => l.refuse(s.span, "a statement other than `var` and section functions"),
        }
    }
    // The comments: the head, each variable's, and each section's (above
    // its function).
    let (head, floor) = crate::docs::head(text);
    l.post.add_comment(CommentTarget::Post, head);
    for s in &program.body {
        let on = match &s.kind {
            StmtKind::Function(f) => f
                .name
                .as_ref()
                .and_then(|n| Section::from_name(&n.name))
                .map(|section| CommentTarget::Handler(HandlerKey::Section(section)))
                .filter(|on| matches!(on, CommentTarget::Handler(k) if l.post.handlers.iter().any(|h| &h.key == k))),
            StmtKind::Var(ds) => match ds.as_slice() {
                [d] => l
                    .names
                    .iter()
                    .position(|n| n == &d.name.name)
                    .map(|i| CommentTarget::Variable(VarId::new(i as u16))),
                _ => None,
            },
            _ => None,
        };
        if let Some(on) = on {
            l.post.add_comment(on, crate::docs::before(text, s.span.start, floor));
        }
    }
}

struct Lowerer<'a> {
    post: &'a mut Post,
    diags: &'a mut Vec<Diagnostic>,
    /// Variable names, by id.
    names: Vec<String>,
}

/// A constant of the options and formats.
#[derive(Clone, Debug)]
enum Value {
    Number(f64),
    Text(String),
    Bool(bool),
    List(Vec<Value>),
}

fn value(e: &Expr) -> Option<Value> {
    Some(match &e.kind {
        ExprKind::Number(n) => Value::Number(*n),
        ExprKind::String(s) => Value::Text(s.clone()),
        ExprKind::Bool(b) => Value::Bool(*b),
        ExprKind::Unary { op: crate::ast::UnaryOp::Neg, operand } => match value(operand)? {
            Value::Number(n) => Value::Number(-n),
            _ => return None,
        },
        ExprKind::Array(items) => Value::List(items.iter().map(value).collect::<Option<_>>()?),
        _ => return None,
    })
}

/// The properties of an object literal, as constants.
fn object(e: &Expr) -> Option<Vec<(String, Value, Span)>> {
    let ExprKind::Object(props) = &e.kind else { return None };
    props.iter().map(|p| Some((p.key.name.clone(), value(&p.value)?, p.span))).collect()
}

impl Lowerer<'_> {
    fn refuse(&mut self, span: Span, what: &str) {
        self.diags.push(
            Diagnostic::error(codes::JS107.code, format!("a section post cannot hold {what}"))
                .at(span, "here")
                .help("a section post (postc's extension, docs/cimco.md) holds `var postcOptions = {...}`, `var NAME = createVariable({...}, createFormat({...}))` and `function SECTION() { return ...; }`"),
        );
    }

    fn options(&mut self, e: &Expr) {
        let Some(props) = object(e) else {
            self.refuse(e.span, "`postcOptions` other than an object of constants");
            return;
        };
        for (key, v, span) in props {
            let (info, o) = (&mut self.post.info, &mut self.post.options);
            if let (Some(flag), Value::Bool(b)) = (flag_of(&key, info, o), &v) {
                *flag = *b;
                continue;
            }
            let ok = match (key.as_str(), v) {
                ("name", Value::Text(t)) => {
                    info.name = t;
                    true
                }
                ("fileExtension", Value::Text(t)) => {
                    info.file_extension = t;
                    true
                }
                ("units", Value::Text(t)) if t == "MM" || t == "INCH" => {
                    info.units = Some(if t == "MM" { Units::Mm } else { Units::Inch });
                    true
                }
                ("lineEnding", Value::Text(t)) if !t.is_empty() => {
                    o.line_ending = t.into_bytes();
                    true
                }
                ("substitute", Value::List(pairs)) => {
                    let mut ok = true;
                    for p in pairs {
                        match p {
                            Value::List(ft) => match ft.as_slice() {
                                [Value::Text(f), Value::Text(t)] => o
                                    .substitutions
                                    .push(Substitution { from: f.clone().into_bytes(), to: t.clone().into_bytes() }),
                                _ => ok = false,
                            },
                            _ => ok = false,
                        }
                    }
                    ok
                }
                ("spindleSpeedRange", Value::List(n)) => match n.as_slice() {
                    [Value::Number(a), Value::Number(b), Value::Number(c), Value::Number(d)] => {
                        o.spindle_speed_range =
                            Some(SpindleSpeedRange { out_min: *a, out_max: *b, rpm_min: *c, rpm_max: *d });
                        true
                    }
                    _ => false,
                },
                ("rotaryWrap", Value::List(w)) => {
                    let axis = match w.first() {
                        Some(Value::Text(a)) if a == "X" => Some(WrappedAxis::X),
                        Some(Value::Text(a)) if a == "Y" => Some(WrappedAxis::Y),
                        _ => None,
                    };
                    match (axis, w.get(1), w.get(2)) {
                        (Some(axis), Some(Value::Text(l)), Some(Value::Bool(reversed))) if l.chars().count() <= 1 => {
                            o.rotary_wrap = Some(RotaryWrap { axis, letter: l.chars().next(), reversed: *reversed });
                            true
                        }
                        _ => false,
                    }
                }
                ("minArcRadius", Value::Number(n)) => {
                    o.min_arc_radius = Some(n);
                    true
                }
                ("maxArcRadius", Value::Number(n)) => {
                    o.max_arc_radius = Some(n);
                    true
                }
                ("textEncoding", Value::Text(t)) if t == "windows-1252" => {
                    info.text_encoding = postc_ir::post::TextEncoding::Windows1252;
                    true
                }
                ("directOutput", Value::Text(t)) => {
                    info.direct_output = Some(t);
                    true
                }
                ("revision", Value::Text(t)) => {
                    info.revision = t;
                    true
                }
                ("blockNumbers", Value::List(n)) => match n.as_slice() {
                    [Value::Number(start), Value::Number(increment), Value::Number(maximum)] => {
                        o.block_numbers = BlockNumbers { start: *start, increment: *increment, maximum: *maximum };
                        true
                    }
                    _ => false,
                },
                ("tapeSplitting", Value::List(t)) => match t.as_slice() {
                    [
                        Value::Number(max),
                        Value::Number(tol),
                        Value::Text(name),
                        Value::Number(start),
                        Value::Bool(first),
                    ] if *max >= 1.0 && *tol >= 0.0 && *start >= 0.0 => {
                        o.tape_splitting = Some(TapeSplitting {
                            max_lines: *max as u64,
                            tolerance: *tol as u64,
                            name_format: name.clone(),
                            start_index: *start as u64,
                            index_on_first_file: *first,
                        });
                        true
                    }
                    _ => false,
                },
                _ => false,
            };
            if !ok {
                self.refuse(span, &format!("the option `{key}` with this value"));
            }
        }
    }

    fn variable(&mut self, name: &str, e: &Expr, span: Span) {
        let parts = match &e.kind {
            ExprKind::Call { callee, args } if matches!(&callee.kind, ExprKind::Ident(n) if n == "createVariable") => {
                match args.as_slice() {
                    [v, f] => match (&f.kind, object(v)) {
                        (ExprKind::Call { callee, args }, Some(v))
                            if matches!(&callee.kind, ExprKind::Ident(n) if n == "createFormat") && args.len() == 1 =>
                        {
                            object(&args[0]).map(|f| (v, f))
                        }
                        _ => None,
                    },
                    _ => None,
                }
            }
            _ => None,
        };
        let Some((var_props, format_props)) = parts else {
            self.refuse(span, "a variable other than `createVariable({...}, createFormat({...}))` of constants");
            return;
        };
        let mut format = NumberFormat::default();
        for (key, v, at) in format_props {
            let ok = match (key.as_str(), v) {
                ("decimals", Value::Number(n)) if (0.0..=15.0).contains(&n) && n.fract() == 0.0 => {
                    format.decimals = n as u8;
                    true
                }
                ("width", Value::Number(n)) if (0.0..=255.0).contains(&n) && n.fract() == 0.0 => {
                    format.width = n as u8;
                    true
                }
                ("widthOfIntegerDigits", Value::Bool(b)) => {
                    format.width_of = if b { WidthOf::IntegerDigits } else { WidthOf::Whole };
                    true
                }
                ("zeropad", Value::Bool(b)) => {
                    format.padding = if b { Padding::Zero } else { Padding::Space };
                    true
                }
                ("justifyLeft", Value::Bool(b)) => {
                    format.justify = if b { Justify::Left } else { Justify::Right };
                    true
                }
                ("forceSign", Value::Bool(b)) => {
                    format.sign = if b { SignStyle::Always } else { SignStyle::Negative };
                    true
                }
                ("forceDecimal", Value::Bool(b)) => {
                    format.point = if b { PointStyle::Always } else { PointStyle::WithDecimals };
                    true
                }
                ("trim", Value::Bool(b)) => {
                    format.trim_zeros = b;
                    true
                }
                ("leadingZero", Value::Bool(b)) => {
                    format.leading_zero = b;
                    true
                }
                ("decimalMark", Value::Text(t)) if t.chars().count() == 1 => {
                    format.decimal_mark = t.chars().next().unwrap_or('.');
                    true
                }
                ("scale", Value::Number(n)) if n.is_finite() => {
                    format.multiplier = n;
                    true
                }
                ("prefix", Value::Text(t)) => {
                    format.prefix = t;
                    true
                }
                ("binaryRounding", Value::Bool(b)) => {
                    format.rounding =
                        if b { postc_ir::format::Rounding::Binary } else { postc_ir::format::Rounding::Decimal };
                    true
                }
                ("negativeZero", Value::Bool(b)) => {
                    format.negative_zero = b;
                    true
                }
                _ => false,
            };
            if !ok {
                self.refuse(at, &format!("the format key `{key}` with this value"));
            }
        }
        let (mut prefix, mut label, mut modality) = (Vec::new(), None, Modality::Always);
        for (key, v, at) in var_props {
            match (key.as_str(), v) {
                ("prefix", Value::Text(t)) => prefix = t.into_bytes(),
                ("label", Value::Text(t)) => label = Quantity::from_label(&t).filter(|q| q.label() == t),
                ("modal", Value::Bool(b)) => modality = if b { Modality::OnChange } else { Modality::Always },
                _ => self.refuse(at, &format!("the variable key `{key}` with this value")),
            }
        }
        let Some(label) = label else {
            self.refuse(span, "a variable without the `label` of a Vectric value it prints");
            return;
        };
        let Some(format_id) = self.post.push_format(format) else { return };
        let variable = Variable {
            name: name.to_string(),
            source: ValueSource::Quantity(label),
            prefix,
            format: format_id,
            modality,
            span: Some(span),
        };
        if self.post.push_variable(variable).is_some() {
            self.names.push(name.to_string());
        }
        let _: FormatId = format_id;
    }

    /// The lines a section returns: `"text" + VARIABLE + ... + "\n"`.
    fn lines(&mut self, e: &Expr) -> Option<Vec<Stmt>> {
        let mut leaves = Vec::new();
        concat_leaves(e, &mut leaves);
        let mut lines = Vec::new();
        let mut pieces: Vec<Piece> = Vec::new();
        let mut line_span: Option<Span> = None;
        for leaf in leaves {
            match &leaf.kind {
                ExprKind::String(s) => {
                    let mut rest = s.as_str();
                    let legacy = self.post.info.text_encoding == postc_ir::post::TextEncoding::Windows1252;
                    while let Some(i) = rest.find('\n') {
                        push_text(&mut pieces, &rest[..i], legacy);
                        let span = line_span.map_or(leaf.span, |s| s.to(leaf.span));
                        lines.push(Stmt::Line { pieces: std::mem::take(&mut pieces), span: Some(span) });
                        line_span = None;
                        rest = &rest[i + 1..];
                    }
                    push_text(&mut pieces, rest, legacy);
                    if !rest.is_empty() {
                        line_span.get_or_insert(leaf.span);
                    }
                }
                ExprKind::Ident(name) => {
                    let id = self.names.iter().position(|n| n == name).and_then(VarId::from_usize)?;
                    pieces.push(Piece::Var(id));
                    line_span = Some(line_span.map_or(leaf.span, |s| s.to(leaf.span)));
                }
                _ => return None,
            }
        }
        // Text after the last "\n" would be a line without its ending.
        pieces.is_empty().then_some(lines)
    }
}

/// Appends text to the pieces, in the post's encoding (`textEncoding`).
fn push_text(pieces: &mut Vec<Piece>, text: &str, legacy: bool) {
    if text.is_empty() {
        return;
    }
    let bytes = if legacy { encoding_rs::WINDOWS_1252.encode(text).0.into_owned() } else { text.as_bytes().to_vec() };
    match pieces.last_mut() {
        Some(Piece::Text(t)) => t.extend_from_slice(&bytes),
        _ => pieces.push(Piece::Text(bytes)),
    }
}

/// The parts of a left-associated chain of `+`.
fn concat_leaves<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    match &e.kind {
        ExprKind::Binary { op: BinaryOp::Add, left, right } => {
            concat_leaves(left, out);
            concat_leaves(right, out);
        }
        _ => out.push(e),
    }
}

/// The yes/no setting a `true`/`false` option of `postcOptions` names.
fn flag_of<'a>(
    key: &str,
    info: &'a mut postc_ir::PostInfo,
    o: &'a mut postc_ir::OutputOptions,
) -> Option<&'a mut bool> {
    Some(match key {
        "inverseTimeFeed" => &mut o.inverse_time_feed,
        "laserSupport" => &mut info.laser_support,
        "printDirect" => &mut info.print_direct,
        "rapidPlungeToStartZ" => &mut info.rapid_plunge_to_start_z,
        "onChangeByValue" => &mut o.on_change_by_value,
        "rapidForgetsFeed" => &mut o.rapid_forgets_feed,
        _ => return None,
    })
}
