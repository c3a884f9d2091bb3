//! The VcPost backend: a post IR printed as a Vericut VcPost post, laid out
//! the way VcPost posts are written: a comment naming the source, register
//! properties (`X.Prefix = " X"`, `X.Decimals = 3`, `N.Start = 10`), the
//! global variables (`Dim`), the statements that run first, then one `Sub`
//! or `Function` per post function, with the keyword comments (`' #Cycle
//! !X !Y Depth`) the applications read.
//!
//! VcPost posts run over APT records (one Sub per major word: `Sub GOTO`)
//! and the calls of the probe-table and composites applications. A post
//! driven by the kind of each move (a Vectric post) prints as a *section
//! post*, postc's extension (docs/vcpost.md): one `Sub` per section,
//! registers named after the labels they print, and `Postc.` options for
//! Vectric's global statements. What VcPost has no form for is refused:
//!
//! - a handler that is not an APT word's or a section's Sub is `CV001`;
//! - code VcPost cannot say (scripts, JavaScript operators and
//!   conversions, `Continue`, null) is `CV002`;
//! - a register format the register properties cannot set is `CV003`;
//! - an output option no VcPost statement sets (a lathe, a chord
//!   tolerance) is `CV004`;
//! - a runtime value no register can print (outside a section post, or a
//!   second variable of one label) is `CV005`.
//!
//! What converts is printed in a canonical form: loops as `Do While ...
//! Loop` (a `For` or `Select Case` of the source was lowered to a loop or
//! an `If` chain and prints as one), every register with its `Prefix`,
//! variables the frontend made up (a `For`'s bound) as `L1`, `L2`, ...
//! Printing the
//! converted post again gives the same text.

use std::collections::HashSet;

use postc_front_vcpost::{routines, token};
use postc_ir::codes;
use postc_ir::post::{BlockNumbers, CommentTarget, Dispatch, FunctionId, Section};
use postc_ir::{
    BinaryOp, Body, Builtin, Diagnostic, Expr, Function, HandlerKey, Justify, Modality, NumberFormat, OutputOptions,
    Padding, Piece, Place, PointStyle, Post, SignStyle, Span, Stmt, TextEncoding, UnaryOp, ValueSource, WidthOf,
};

/// Prints `post` as a VcPost post that Vericut runs, or says why it cannot
/// be one: a post of another dialect driven by the kind of each move is
/// refused (`CV001`), as postc prints no VcPost milling post from one;
/// [`print_extension`] prints it as a section post.
pub fn print(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    if post.info.dispatch == Dispatch::Sections && post.info.dialect != postc_ir::Dialect::VcPost {
        let mut d = Diagnostic::error(
            codes::CV001.code,
            format!(
                "this {} post prints a section for each kind of move, and postc does not yet print such a post as a VcPost milling post (one Sub per APT word)",
                super::dialect_name(post.info.dialect)
            ),
        )
        .note("Vericut runs VcPost posts one Sub per APT record; a section post is postc's extension, which Vericut does not run")
        .help("`--postc-extension` writes it as a VcPost section post, which only postc runs");
        if let Some(span) = post.handlers.iter().find_map(|h| h.span) {
            d = d.at(span, "a section of the post");
        }
        return Err(vec![d]);
    }
    print_extension(post)
}

/// Prints `post` as a VcPost post, a post of another dialect driven by the
/// kind of each move as a *section post* (postc's extension, which only
/// postc runs), or says why it cannot be one.
pub fn print_extension(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    // As written, when the IR keeps the file and it compiles back to `post`.
    let note = format!(
        "' {}{} ({}).",
        postc_ir::post::CONVERSION_NOTE,
        super::source_name(post),
        super::dialect_name(post.info.dialect)
    );
    if let Some(bytes) =
        super::as_written(post, postc_ir::Dialect::VcPost, &note, postc_front_vcpost::compile, |t| encode(post, t).ok())
    {
        return Ok(bytes);
    }
    let mut p = Printer { post, out: String::new(), errors: Vec::new(), names: Names::default(), within: None };
    p.check_shape();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    p.name_everything();
    p.header();
    p.registers();
    p.globals();
    p.sections();
    p.functions();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    encode(post, &p.out)
}

/// The bytes of the post file: UTF-8, or Windows-1252 for a source read in
/// it (its output text is in that encoding).
fn encode(post: &Post, text: &str) -> Result<Vec<u8>, Vec<Diagnostic>> {
    if post.info.text_encoding != TextEncoding::Windows1252 {
        return Ok(text.as_bytes().to_vec());
    }
    let (bytes, _, lost) = encoding_rs::WINDOWS_1252.encode(text);
    if lost {
        return Err(vec![Diagnostic::error(
            codes::CV002.code,
            "the post's text has characters Windows-1252 cannot hold, and its output is in Windows-1252",
        )]);
    }
    Ok(bytes.into_owned())
}

/// The name each global, register, function and local prints as.
#[derive(Default)]
struct Names {
    globals: Vec<String>,
    registers: Vec<String>,
    functions: Vec<String>,
    /// Per function: each slot's name.
    locals: Vec<Vec<String>>,
    /// Every name given, lower case.
    taken: HashSet<String>,
}

impl Names {
    /// `wanted` when it is a valid VcPost name not taken yet, else a
    /// fresh `stem1`, `stem2`, ...
    fn give(&mut self, wanted: &str, stem: &str) -> String {
        let ok = |n: &str, taken: &HashSet<String>| {
            token::is_valid_name(n) && !token::is_reserved(n) && !taken.contains(&n.to_lowercase())
        };
        let keyword = token::Kw::from_word(wanted).is_some();
        let name = if ok(wanted, &self.taken) {
            wanted.to_string()
        } else if keyword && token::is_valid_name(wanted) && !self.taken.contains(&wanted.to_lowercase()) {
            // A keyword as a name is written in brackets: `Sub [End]`.
            self.taken.insert(wanted.to_lowercase());
            return format!("[{wanted}]");
        } else {
            (1..).map(|i| format!("{stem}{i}")).find(|n| ok(n, &self.taken)).unwrap_or_default()
        };
        self.taken.insert(name.to_lowercase());
        name
    }
}

/// How a function prints.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// Made by the frontend for a host function (`getNthLength1`): not
    /// printed; calls name it and the frontend makes it again.
    Host,
    Sub,
    /// A `Function`; its result lives in this slot (named like the function).
    Function(usize),
}

struct Printer<'p> {
    post: &'p Post,
    out: String,
    errors: Vec<Diagnostic>,
    names: Names,
    /// The Sub, Function or section being printed, and where it is in the
    /// source: a construct without a place of its own is refused there.
    within: Option<(String, Option<Span>)>,
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        let mut d = Diagnostic::error(code, message).note(why.to_string());
        if let Some(span) = span {
            d = d.at(span, "here");
        }
        self.errors.push(d);
    }

    fn line(&mut self, indent: usize, text: &str) {
        for _ in 0..indent {
            self.out.push_str("  ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    /// What the post as a whole must be to be a VcPost post.
    fn check_shape(&mut self) {
        let post = self.post;
        for h in &post.handlers {
            match (&h.key, post.info.dispatch) {
                (HandlerKey::Word(word), Dispatch::AptWords) => {
                    let calls_its_sub = matches!(h.body.as_slice(), [Stmt::Eval(Expr::Call(f, args))]
                        if args.is_empty() && post.functions.get(f.index()).is_some_and(|f| f.name.eq_ignore_ascii_case(word)));
                    if !calls_its_sub {
                        self.refuse(
                            codes::CV002.code,
                            h.span,
                            format!("the handler of `{word}` does more than call `Sub {word}`"),
                            "in VcPost the Sub named after the word is the handler",
                        );
                    }
                }
                (HandlerKey::Section(_), Dispatch::Sections) => {}
                (key, _) => self.refuse(
                    codes::CV001.code,
                    h.span,
                    format!("a handler for {key:?} in a post driven by {:?}", post.info.dispatch),
                    "VcPost Subs handle APT words, or (postc's extension) sections",
                ),
            }
        }
        let o = &post.options;
        let d = OutputOptions::default();
        let multi = o.substitutions.iter().any(|s| {
            std::str::from_utf8(&s.from).map_or(true, |t| t.chars().count() != 1)
                || std::str::from_utf8(&s.to).map_or(true, |t| t.chars().count() != 1)
        });
        let line_ending = [&b"\r\n"[..], b"\n", b"\r"].contains(&o.line_ending.as_slice());
        let differs = [
            ("a line ending other than CR LF, LF or CR", !line_ending),
            ("substitutions of more than one character", multi),
            ("a chord tolerance", o.arc_tolerance != d.arc_tolerance),
            ("exact arcs", o.exact_arcs != d.exact_arcs),
            ("a step budget", o.step_budget != d.step_budget),
            ("a lathe mapping", o.lathe != d.lathe),
        ];
        for (what, yes) in differs {
            if yes {
                self.refuse(
                    codes::CV004.code,
                    None,
                    format!("the post sets {what}, which no VcPost statement sets"),
                    "VcPost sets register properties, block numbering and postc's `Postc.` options",
                );
            }
        }
    }

    fn kind(&self, f: &Function) -> Kind {
        if f.span.is_none() && routines::host_function(&f.name).is_some() {
            return Kind::Host;
        }
        let Body::Native(body) = &f.body else { return Kind::Sub };
        let ret = f.params.len();
        match body.last() {
            Some(Stmt::Return(Some(Expr::Local(r)))) if r.index() == ret => Kind::Function(ret),
            _ => Kind::Sub,
        }
    }

    fn name_everything(&mut self) {
        let post = self.post;
        for f in &post.functions {
            // Function names first: APT words and routines must keep theirs.
            let name = self.names.give(&f.name, "Routine");
            self.names.functions.push(name);
        }
        let sections = post.info.dispatch == Dispatch::Sections;
        for v in &post.variables {
            let name = match v.source {
                ValueSource::Quantity(postc_ir::Quantity::BlockNumber) => {
                    self.names.taken.insert("n".into());
                    "N".to_string()
                }
                // Under sections a register named after a label prints it.
                ValueSource::Quantity(q) if sections && !self.names.taken.contains(&q.label().to_lowercase()) => {
                    self.names.taken.insert(q.label().to_lowercase());
                    q.label().to_string()
                }
                ValueSource::Quantity(_) => String::new(),
                ValueSource::Assigned if sections && postc_ir::Quantity::from_label(&v.name).is_some() => {
                    self.names.give(&format!("{}_", v.name), "Register")
                }
                ValueSource::Assigned => self.names.give(&v.name, "Register"),
            };
            self.names.registers.push(name);
        }
        for g in &post.globals {
            let name = self.names.give(&g.name, "Hidden");
            self.names.globals.push(name);
        }
        for (i, f) in post.functions.iter().enumerate() {
            let kind = self.kind(f);
            // Locals are per function: they may reuse names of other functions' locals.
            let saved = self.names.taken.clone();
            let mut slots = Vec::new();
            for k in 0..(f.slots as usize).max(f.params.len()) {
                let name = match (f.params.get(k), kind) {
                    (Some(p), _) => self.names.give(p, "P"),
                    (None, Kind::Function(r)) if r == k => self.names.functions[i].clone(),
                    _ => {
                        // The source's name; `$` marks a variable the frontend made up.
                        let wanted = f
                            .locals
                            .get(k - f.params.len())
                            .filter(|n| !n.starts_with('$'))
                            .cloned()
                            .unwrap_or_else(|| format!("L{k}"));
                        self.names.give(&wanted, "L")
                    }
                };
                slots.push(name);
            }
            self.names.locals.push(slots);
            self.names.taken = saved;
        }
    }

    fn header(&mut self) {
        let post = self.post;
        let source = super::source_name(post).to_string();
        let dialect = super::dialect_name(post.info.dialect);
        self.line(0, &format!("' {}{source} ({dialect}).", postc_ir::post::CONVERSION_NOTE));
        self.comment(&CommentTarget::Post);
        self.line(0, "");
        self.options(&source);
    }

    /// The source's comment lines before `on`, as `'` lines. A line that
    /// would read as a keyword comment (`#Cycle`) gets a blank after its
    /// `#`: it documents, it does not declare.
    fn comment(&mut self, on: &CommentTarget) {
        let post = self.post;
        for l in post.comment(on) {
            let text = match l.trim_start().strip_prefix('#') {
                Some(rest) if rest.starts_with(char::is_alphabetic) => {
                    format!("{}# {rest}", &l[..l.len() - l.trim_start().len()])
                }
                _ => l.clone(),
            };
            self.line(0, &format!("'{text}"));
        }
    }

    /// postc's options (`Postc.Units = "MM"`), those that differ from the
    /// defaults: what Vectric's global statements say.
    fn options(&mut self, source: &str) {
        let post = self.post;
        let (info, o) = (&post.info, &post.options);
        let mut lines = Vec::new();
        let stem = source.rsplit_once('.').map_or(source, |s| s.0);
        if !info.name.is_empty() && info.name != stem {
            lines.push(format!("Postc.Name = {}", text_literal(&info.name)));
        }
        if !info.file_extension.is_empty() {
            lines.push(format!("Postc.FileExtension = {}", text_literal(&info.file_extension)));
        }
        match info.units {
            Some(postc_ir::Units::Mm) => lines.push("Postc.Units = \"MM\"".into()),
            Some(postc_ir::Units::Inch) => lines.push("Postc.Units = \"INCH\"".into()),
            None => {}
        }
        match o.line_ending.as_slice() {
            b"\r\n" => lines.push("Postc.LineEnding = \"CRLF\"".into()),
            b"\r" => lines.push("Postc.LineEnding = \"CR\"".into()),
            _ => {}
        }
        for sub in &o.substitutions {
            let text = format!("{}{}", String::from_utf8_lossy(&sub.from), String::from_utf8_lossy(&sub.to));
            lines.push(format!("Postc.Substitute = {}", text_literal(&text)));
        }
        if let Some(r) = o.spindle_speed_range {
            let n = [r.out_min, r.out_max, r.rpm_min, r.rpm_max].map(number);
            lines.push(format!("Postc.SpindleSpeedRange = \"{}\"", n.join(" ")));
        }
        if let Some(w) = o.rotary_wrap {
            let axis = match w.axis {
                postc_ir::post::WrappedAxis::X => "X",
                postc_ir::post::WrappedAxis::Y => "Y",
            };
            let letter = w.letter.map(|l| format!(" {}{l}", if w.reversed { "-" } else { "" })).unwrap_or_default();
            if w.letter.is_none() && w.reversed {
                self.refuse(codes::CV004.code, None, "a reversed rotary wrap without a letter".into(), "");
            }
            lines.push(format!("Postc.RotaryWrap = \"{axis}{letter}\""));
        }
        for (name, value) in [("MinArcRadius", o.min_arc_radius), ("MaxArcRadius", o.max_arc_radius)] {
            if let Some(v) = value {
                lines.push(format!("Postc.{name} = {}", number(v)));
            }
        }
        for (name, value) in [
            ("InverseTimeFeed", o.inverse_time_feed),
            ("LaserSupport", info.laser_support),
            ("PrintDirect", info.print_direct),
            ("RapidPlungeToStartZ", info.rapid_plunge_to_start_z),
            ("OnChangeByValue", o.on_change_by_value),
            ("RapidForgetsFeed", o.rapid_forgets_feed),
        ] {
            if value {
                lines.push(format!("Postc.{name} = True"));
            }
        }
        if !o.forget_modal_at_toolpath_start {
            lines.push("Postc.ModalMemory = \"Program\"".into());
        }
        if let Some(d) = &info.direct_output {
            lines.push(format!("Postc.DirectOutput = {}", text_literal(d)));
        }
        if !info.revision.is_empty() {
            lines.push(format!("Postc.Revision = {}", text_literal(&info.revision)));
        }
        if let Some(t) = &o.tape_splitting {
            lines.push(format!("Postc.TapeSplitLines = {}", t.max_lines));
            lines.push(format!("Postc.TapeSplitTolerance = {}", t.tolerance));
            lines.push(format!("Postc.TapeSplitName = {}", text_literal(&t.name_format)));
            lines.push(format!("Postc.TapeSplitStart = {}", t.start_index));
            lines.push(format!("Postc.TapeSplitIndexFirst = {}", if t.index_on_first_file { "True" } else { "False" }));
            if t.max_lines == 0 {
                self.refuse(codes::CV004.code, None, "tape splitting at 0 lines".into(), "");
            }
        }
        if lines.is_empty() {
            return;
        }
        self.line(0, "' ---- postc's options (docs/vcpost.md) ----");
        for l in lines {
            self.line(0, &l);
        }
        self.line(0, "");
    }

    /// Register properties, in the order the registers were first named.
    fn registers(&mut self) {
        let post = self.post;
        if post.variables.is_empty() {
            return;
        }
        self.line(0, "' ---- Register properties ----");
        // The frontend makes `N` when it first needs it, after the others: it goes last.
        let is_n = |v: &postc_ir::Variable| v.source == ValueSource::Quantity(postc_ir::Quantity::BlockNumber);
        let order: Vec<usize> = (0..post.variables.len())
            .filter(|&i| !is_n(&post.variables[i]))
            .chain((0..post.variables.len()).filter(|&i| is_n(&post.variables[i])))
            .collect();
        for i in order {
            let v = &post.variables[i];
            let name = self.names.registers[i].clone();
            let sequence = v.source == ValueSource::Quantity(postc_ir::Quantity::BlockNumber);
            let label = matches!(v.source, ValueSource::Quantity(_)) && post.info.dispatch == Dispatch::Sections;
            if name.is_empty() || !(sequence || label || v.source == ValueSource::Assigned) {
                self.refuse(
                    codes::CV005.code,
                    v.span,
                    format!("`{}` prints a value the runtime gives ({:?}), which no register can here", v.name, v.source),
                    "VcPost registers hold what the post or the APT record assigns; under sections, one register per label",
                );
                continue;
            }
            let prefix = match self.decode(&v.prefix) {
                Some(p) if !p.chars().any(char::is_control) => p,
                _ => {
                    self.refuse(
                        codes::CV005.code,
                        v.span,
                        format!("the prefix of `{}` is not plain text", v.name),
                        "a register's Prefix is a string literal",
                    );
                    continue;
                }
            };
            self.line(0, &format!("{name}.Prefix = {}", text_literal(&prefix)));
            let Some(format) = post.formats.get(v.format.index()) else { continue };
            let properties = self.format_properties(format, sequence, v.span, &v.name);
            for (property, value) in properties {
                self.line(0, &format!("{name}.{property} = {value}"));
            }
            if v.modality == Modality::OnChange {
                self.line(0, &format!("{name}.Modal = True"));
            }
            if sequence {
                let (b, d) = (post.options.block_numbers, BlockNumbers::default());
                for (property, value, default) in [
                    ("Start", b.start, d.start),
                    ("Increment", b.increment, d.increment),
                    ("Maximum", b.maximum, d.maximum),
                ] {
                    if value != default {
                        self.line(0, &format!("N.{property} = {}", number(value)));
                    }
                }
            }
        }
        self.line(0, "");
    }

    /// The properties that give a register `format` (those that differ
    /// from the defaults), or a refusal.
    fn format_properties(
        &mut self,
        f: &NumberFormat,
        sequence: bool,
        span: Option<Span>,
        name: &str,
    ) -> Vec<(&'static str, String)> {
        let mut out = Vec::new();
        let mut cannot = Vec::new();
        if f.decimals != if sequence { 0 } else { 4 } {
            out.push(("Decimals", f.decimals.to_string()));
        }
        if !f.trim_zeros {
            out.push(("TrailingZeros", "True".into()));
        }
        match (f.width, f.width_of, f.padding) {
            (0, _, _) => {}
            (w, WidthOf::IntegerDigits, Padding::Zero) => out.push(("LeadingZeros", w.to_string())),
            (w, WidthOf::Whole, Padding::Space) if w <= 40 => out.push(("Width", w.to_string())),
            (w, WidthOf::Whole, Padding::Zero) if w <= 40 => {
                out.push(("Width", w.to_string()));
                out.push(("Padding", "\"Zero\"".into()));
            }
            _ => cannot.push("its padding"),
        }
        if f.point == PointStyle::Always {
            out.push(("DecimalPoint", "True".into()));
        }
        if !f.leading_zero {
            out.push(("ZeroBeforePoint", "False".into()));
        }
        if f.sign == SignStyle::Always {
            out.push(("Sign", "\"+\"".into()));
        }
        if f.justify == Justify::Left {
            out.push(("Justify", "\"Left\"".into()));
        }
        match f.decimal_mark {
            '.' => {}
            ',' => out.push(("DecimalMark", "\",\"".into())),
            _ => cannot.push("its decimal mark"),
        }
        if f.multiplier != 1.0 {
            if f.multiplier.is_finite() && f.multiplier != 0.0 {
                out.push(("Multiplier", number(f.multiplier)));
            } else {
                cannot.push("its multiplier");
            }
        }
        if !f.prefix.is_empty() {
            cannot.push("a prefix of the format's own");
        }
        if f.rounding != postc_ir::format::Rounding::Decimal {
            cannot.push("its rounding of the binary value");
        }
        if f.negative_zero {
            out.push(("NegativeZero", "True".into()));
        }
        if f.decimals > 9 {
            cannot.push("more than 9 decimals");
        }
        if !cannot.is_empty() {
            self.refuse(
                codes::CV003.code,
                span,
                format!("register properties cannot give `{name}` {}", cannot.join(", ")),
                "VcPost formats are set by Decimals, TrailingZeros, LeadingZeros, Width, DecimalPoint, Sign, Justify, DecimalMark and Multiplier",
            );
        }
        out
    }

    fn globals(&mut self) {
        let post = self.post;
        let mut starts = Vec::new();
        let mut dims = Vec::new();
        for (i, g) in post.globals.iter().enumerate() {
            let name = self.names.globals[i].clone();
            let (ty, default) = match &g.initial {
                Expr::Text(t) => (" As String", t.is_empty()),
                Expr::Bool(b) => (" As Boolean", !b),
                Expr::Number(n) => ("", *n == 0.0 && n.is_sign_positive()),
                other => {
                    self.refuse(
                        codes::CV002.code,
                        g.span,
                        format!("global `{}` starts as {other:?}", g.name),
                        "VcPost variables start as a number, a text or a Boolean",
                    );
                    continue;
                }
            };
            // Variables the runtime sets (Text, Minor, Metric, ...) are not declared.
            if routines::runtime_variable(&g.name).is_some() && default {
                continue;
            }
            dims.push(format!("Dim {name}{ty}"));
            if !default {
                starts.push(format!("{name} = {}", self.expr(&g.initial, None)));
            }
        }
        if !dims.is_empty() || !post.init.is_empty() {
            self.line(0, "' ---- Variables, and what runs first ----");
        }
        for d in dims {
            self.line(0, &d);
        }
        for s in starts {
            self.line(0, &s);
        }
        let init = post.init.clone();
        self.block(&init, None, 0);
        if !self.out.ends_with("\n\n") {
            self.line(0, "");
        }
    }

    /// Under sections, each section whose handler is its lines (not a call
    /// of a Sub) as `Sub SECTION_NAME`.
    fn sections(&mut self) {
        let post = self.post;
        for section in Section::ALL.iter().copied() {
            let Some(h) = post.handlers.iter().find(|h| h.key == HandlerKey::Section(section)) else { continue };
            if self.calls_its_sub(&h.body, section) {
                continue;
            }
            self.comment(&CommentTarget::Handler(h.key.clone()));
            self.line(0, &format!("Sub {}", section.name()));
            let body = h.body.clone();
            self.within = Some((format!("the {} section", section.name()), h.span));
            self.block(&body, None, 1);
            self.within = None;
            self.line(0, "End Sub");
            self.line(0, "");
        }
    }

    /// Whether a section's handler is a call of the Sub named after it.
    fn calls_its_sub(&self, body: &[Stmt], section: Section) -> bool {
        matches!(body, [Stmt::Eval(Expr::Call(f, args))] if args.is_empty()
            && self.post.functions.get(f.index()).is_some_and(|f| f.name.eq_ignore_ascii_case(section.name())))
    }

    fn functions(&mut self) {
        let post = self.post;
        for (i, f) in post.functions.iter().enumerate() {
            let kind = self.kind(f);
            if kind == Kind::Host {
                continue;
            }
            // A section's Sub whose handler holds its lines printed with the sections.
            if post.info.dispatch == Dispatch::Sections
                && let Some(section) = Section::from_name(&f.name)
                && let Some(h) = post.handlers.iter().find(|h| h.key == HandlerKey::Section(section))
                && !self.calls_its_sub(&h.body, section)
            {
                continue;
            }
            let Body::Native(body) = &f.body else {
                self.refuse(
                    codes::CV002.code,
                    f.why_script.as_ref().and_then(|w| w.span).or(f.span),
                    format!("`{}` runs as a script, which VcPost cannot hold", f.name),
                    "only code the IR holds natively converts",
                );
                continue;
            };
            let name = self.names.functions[i].clone();
            let params = self.names.locals[i][..f.params.len()].join(", ");
            let (word, mut body) = match kind {
                Kind::Function(_) => ("Function", &body[..body.len() - 1]),
                _ => ("Sub", &body[..]),
            };
            if post.info.dispatch == Dispatch::Sections
                && let Some(section) = Section::from_name(&f.name)
            {
                self.comment(&CommentTarget::Handler(HandlerKey::Section(section)));
            }
            self.comment(&CommentTarget::Function(FunctionId::new(i as u16)));
            if params.is_empty() && word == "Sub" {
                self.line(0, &format!("Sub {name}"));
            } else {
                self.line(0, &format!("{word} {name}({params})"));
            }
            self.keyword_comments(&f.name);
            // The prologue the frontend writes for `Dim`: each local set to
            // its type's starting value, in declaration order.
            let mut declared: Vec<usize> = Vec::new();
            if let Kind::Function(r) = kind
                && let [Stmt::Assign(Place::Local(k), Expr::Number(n)), rest @ ..] = body
                && k.index() == r
                && *n == 0.0
            {
                body = rest;
                declared.push(r);
            }
            let mut dims = Vec::new();
            while let [Stmt::Assign(Place::Local(k), value), rest @ ..] = body {
                let ty = match value {
                    Expr::Number(n) if *n == 0.0 && n.is_sign_positive() => "",
                    Expr::Text(t) if t.is_empty() => " As String",
                    Expr::Bool(false) => " As Boolean",
                    _ => break,
                };
                if k.index() < f.params.len() || declared.contains(&k.index()) {
                    break;
                }
                declared.push(k.index());
                dims.push((k.index(), ty));
                body = rest;
            }
            // Slots the body uses that no `Dim` declared (hidden variables).
            for k in f.params.len()..(f.slots as usize) {
                if !declared.contains(&k) {
                    dims.push((k, ""));
                }
            }
            dims.sort_by_key(|d| d.0);
            for (k, ty) in dims {
                match self.names.locals[i].get(k).cloned() {
                    Some(local) => self.line(1, &format!("Dim {local}{ty}")),
                    None => self.cannot("a local past the function's slots", f.span),
                }
            }
            let body = body.to_vec();
            self.within = Some((format!("`{}`", f.name), f.span));
            self.block(&body, Some(i), 1);
            self.within = None;
            self.line(0, &format!("End {word}"));
            self.line(0, "");
        }
    }

    /// The keyword comments and tips of a Sub, from the post's signatures.
    fn keyword_comments(&mut self, name: &str) {
        let Some(sig) = self.post.info.subs.iter().find(|s| s.name.eq_ignore_ascii_case(name)) else { return };
        let sig = sig.clone();
        if let Some(k) = &sig.keyword {
            let params: Vec<String> =
                sig.params.iter().map(|p| format!("{}{}", if p.required { "!" } else { "" }, p.name)).collect();
            let text = if params.is_empty() { format!("' #{k}") } else { format!("' #{k} {}", params.join(" ")) };
            self.line(1, &text);
        }
        for tip in &sig.tips {
            self.line(1, &format!("' #{} {}", tip.slot, tip.text));
        }
    }

    fn block(&mut self, stmts: &[Stmt], f: Option<usize>, indent: usize) {
        for s in stmts {
            self.stmt(s, f, indent);
        }
    }

    fn stmt(&mut self, s: &Stmt, f: Option<usize>, indent: usize) {
        match s {
            Stmt::Line { pieces, span } => {
                let text = self.out_line(pieces, f, *span);
                self.line(indent, &text);
            }
            Stmt::Assign(place, e) => {
                let target = self.place(*place, f);
                let value = self.expr(e, f);
                self.line(indent, &format!("{target} = {value}"));
            }
            Stmt::Eval(Expr::Call(id, args)) => {
                let name = self.names.functions.get(id.index()).cloned().unwrap_or_default();
                let args: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                self.line(indent, &format!("Call {name}({})", args.join(", ")));
            }
            Stmt::If { branches, otherwise } => {
                for (n, (cond, body)) in branches.iter().enumerate() {
                    let c = self.expr(cond, f);
                    self.line(indent, &format!("{} {c} Then", if n == 0 { "If" } else { "ElseIf" }));
                    self.block(body, f, indent + 1);
                }
                if branches.is_empty() {
                    self.block(otherwise, f, indent);
                    return;
                }
                if !otherwise.is_empty() {
                    self.line(indent, "Else");
                    self.block(otherwise, f, indent + 1);
                }
                self.line(indent, "End If");
            }
            Stmt::While { cond, body, .. } => {
                let c = self.expr(cond, f);
                self.line(indent, &format!("Do While {c}"));
                self.block(body, f, indent + 1);
                self.line(indent, "Loop");
            }
            Stmt::Break => self.line(indent, "Exit Do"),
            Stmt::Return(None) if self.in_kind(f) == Some(Kind::Sub) => self.line(indent, "Exit Sub"),
            Stmt::Return(Some(Expr::Local(r))) if matches!(self.in_kind(f), Some(Kind::Function(slot)) if slot == r.index()) => {
                self.line(indent, "Exit Function")
            }
            Stmt::Origin(_) => {}
            other => self.cannot(other_name(other), None),
        }
    }

    fn in_kind(&self, f: Option<usize>) -> Option<Kind> {
        f.and_then(|i| self.post.functions.get(i)).map(|func| self.kind(func))
    }

    /// Refuses one construct, once per Sub (or section) it stands in, at
    /// its place in the source, else at the Sub's.
    fn cannot(&mut self, what: &str, span: Option<Span>) {
        let (message, span) = match &self.within {
            Some((name, at)) => (format!("{name} uses {what}, which VcPost has no form for"), span.or(*at)),
            None => (format!("the post uses {what}, which VcPost has no form for"), span),
        };
        if self.errors.iter().any(|e| e.message == message) {
            return;
        }
        self.refuse(codes::CV002.code, span, message, "VcPost has BASIC's statements and operators only");
    }

    fn place(&mut self, place: Place, f: Option<usize>) -> String {
        match place {
            Place::Local(k) => self.local(k.index(), f),
            Place::Global(g) => self.names.globals.get(g.index()).cloned().unwrap_or_default(),
            Place::Var(v) => self.names.registers.get(v.index()).cloned().unwrap_or_default(),
        }
    }

    fn local(&mut self, k: usize, f: Option<usize>) -> String {
        match f.and_then(|i| self.names.locals.get(i)).and_then(|l| l.get(k)) {
            Some(n) => n.clone(),
            None => {
                self.cannot("a local outside a Sub", None);
                String::new()
            }
        }
    }

    /// `Out` and its operands: text and `<REGISTER>` in string literals
    /// (templates), other values joined with `&`. Text joined with `&` and
    /// text written piece by piece print the same, so text values inside an
    /// expression piece go into the templates too.
    fn out_line(&mut self, pieces: &[Piece], f: Option<usize>, span: Option<Span>) -> String {
        let mut t = Template::default();
        for piece in pieces {
            match piece {
                Piece::Text(bytes) => match self.decode(bytes) {
                    Some(text) => t.text(&text),
                    None => self.cannot("output bytes that are not text in the post's encoding", span),
                },
                Piece::Var(v) => {
                    let name = self.names.registers.get(v.index()).cloned().unwrap_or_default();
                    t.register(&name);
                }
                Piece::Expr(e) => {
                    let mut operands = Vec::new();
                    concat_operands(e, &mut operands);
                    for o in operands {
                        match o {
                            Expr::Text(text) => t.text(text),
                            other => {
                                let value = self.atom(other, f);
                                t.value(value);
                            }
                        }
                    }
                }
            }
        }
        let parts = t.finish();
        if parts.is_empty() { "Out \"\"".into() } else { format!("Out {}", parts.join(" & ")) }
    }

    fn decode(&self, bytes: &[u8]) -> Option<String> {
        if self.post.info.text_encoding == TextEncoding::Windows1252 {
            Some(encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes).0.into_owned())
        } else {
            String::from_utf8(bytes.to_vec()).ok()
        }
    }

    /// An expression that can stand as an operand: parenthesised unless it
    /// is a name, a literal or a call.
    fn atom(&mut self, e: &Expr, f: Option<usize>) -> String {
        let text = self.expr(e, f);
        match e {
            Expr::Binary(..) | Expr::Unary(..) => format!("({text})"),
            Expr::Number(n) if *n < 0.0 || (*n == 0.0 && n.is_sign_negative()) => format!("({text})"),
            Expr::Text(t) if text_parts(t).len() > 1 => format!("({text})"),
            _ => text,
        }
    }

    fn expr(&mut self, e: &Expr, f: Option<usize>) -> String {
        match e {
            Expr::Number(n) if n.is_finite() => number(*n),
            Expr::Text(t) => text_parts(t).join(" & "),
            Expr::Bool(b) => if *b { "True" } else { "False" }.into(),
            Expr::Local(k) => self.local(k.index(), f),
            Expr::Global(g) => self.names.globals.get(g.index()).cloned().unwrap_or_default(),
            Expr::Var(v) => self.names.registers.get(v.index()).cloned().unwrap_or_default(),
            Expr::Previous(v) => {
                format!("{}.Previous", self.names.registers.get(v.index()).cloned().unwrap_or_default())
            }
            Expr::Unary(UnaryOp::Neg, a) => format!("-{}", self.atom(a, f)),
            Expr::Unary(UnaryOp::Not, a) => format!("Not {}", self.atom(a, f)),
            Expr::Unary(op, _) => {
                self.cannot(&format!("the operator {op:?}"), None);
                String::new()
            }
            Expr::Binary(BinaryOp::Concat, ..) => {
                // `&` is associative on text: a chain prints flat, and text
                // with control characters joins it as `"a" & Chr(10)`.
                let mut operands = Vec::new();
                concat_operands(e, &mut operands);
                let parts: Vec<String> = operands
                    .into_iter()
                    .map(|o| match o {
                        Expr::Text(t) => text_parts(t).join(" & "),
                        other => self.atom(other, f),
                    })
                    .collect();
                parts.join(" & ")
            }
            Expr::Binary(op, a, b) => {
                let Some(sym) = binary(*op) else {
                    self.cannot(&format!("the operator {op:?}"), None);
                    return String::new();
                };
                format!("{} {sym} {}", self.atom(a, f), self.atom(b, f))
            }
            Expr::Choose(c, a, b) => {
                format!("IIf({}, {}, {})", self.expr(c, f), self.expr(a, f), self.expr(b, f))
            }
            Expr::Call(id, args) => {
                let name = self.names.functions.get(id.index()).cloned().unwrap_or_default();
                if let Some(func) = self.post.functions.get(id.index())
                    && self.kind(func) == Kind::Sub
                {
                    self.cannot("a Sub's value", func.span);
                }
                let args: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                format!("{name}({})", args.join(", "))
            }
            Expr::Builtin(b, args) => {
                let name = match (b, args.len()) {
                    (Builtin::FormatPicture, 2) => "Format",
                    (b, _) => match builtin_name(*b) {
                        Some(n) => n,
                        None => {
                            self.cannot(&format!("the built-in {b:?}"), None);
                            return String::new();
                        }
                    },
                };
                let args: Vec<String> = args.iter().map(|a| self.expr(a, f)).collect();
                format!("{name}({})", args.join(", "))
            }
            other => {
                // A regular expression is named wherever it stands (in a
                // method call's arguments, say), at its place in the post.
                match regex_in(other) {
                    Some(span) => self.cannot("a regular expression", span),
                    None => self.cannot(expr_name(other), None),
                }
                String::new()
            }
        }
    }
}

/// The operands of a chain of `&`, left to right.
fn concat_operands<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    match e {
        Expr::Binary(BinaryOp::Concat, a, b) => {
            concat_operands(a, out);
            concat_operands(b, out);
        }
        other => out.push(other),
    }
}

fn binary(op: BinaryOp) -> Option<&'static str> {
    Some(match op {
        BinaryOp::Add => "+",
        BinaryOp::Sub => "-",
        BinaryOp::Mul => "*",
        BinaryOp::Div => "/",
        BinaryOp::IntDiv => "\\",
        BinaryOp::Rem => "Mod",
        BinaryOp::Pow => "^",
        BinaryOp::Concat => "&",
        BinaryOp::Eq => "=",
        BinaryOp::Ne => "<>",
        BinaryOp::Lt => "<",
        BinaryOp::Le => "<=",
        BinaryOp::Gt => ">",
        BinaryOp::Ge => ">=",
        BinaryOp::And => "And",
        BinaryOp::Or => "Or",
        _ => return None,
    })
}

/// The VcPost name of a built-in: the inverse of the frontend's table.
fn builtin_name(b: Builtin) -> Option<&'static str> {
    use postc_front_vcpost::builtins::{BUILTINS, Lowering};
    BUILTINS.iter().find(|f| f.lowering == Lowering::Ir(b)).map(|f| f.name)
}

fn other_name(s: &Stmt) -> &'static str {
    match s {
        Stmt::Write(_) => "a statement that writes computed text as blocks",
        Stmt::Continue => "`continue`",
        Stmt::Script(_) => "a script call",
        Stmt::Forget(_) => "making a variable forget what it printed",
        Stmt::Return(_) => "a `return` with a value in a Sub",
        Stmt::Eval(_) => "a value computed for nothing",
        _ => "a statement",
    }
}

/// The span of the first regular expression in `e`, if it holds one.
fn regex_in(e: &Expr) -> Option<Option<Span>> {
    struct Find(Option<Option<Span>>);
    impl postc_ir::visit::Visit for Find {
        fn visit_expr(&mut self, e: &Expr) {
            if self.0.is_none() {
                if let Expr::Regex { span, .. } = e {
                    self.0 = Some(*span);
                }
                postc_ir::visit::walk_expr(self, e);
            }
        }
    }
    let mut find = Find(None);
    postc_ir::visit::Visit::visit_expr(&mut find, e);
    find.0
}

fn expr_name(e: &Expr) -> &'static str {
    match e {
        Expr::Null => "null",
        Expr::Number(_) => "a number that is not finite",
        Expr::Quantity(_) => "a value the runtime gives by name (a Vectric label)",
        Expr::FormatVar { .. } | Expr::Format { .. } => "formatting a value through a CIMCO variable or format",
        Expr::Undefined => "`undefined`",
        Expr::Array(_) => "an array",
        Expr::Object(_) => "an object",
        Expr::Member { .. } => "a property or an element of an object or array",
        Expr::Invoke { .. } | Expr::CallValue(..) => "a method call",
        Expr::Output(_) => "an output variable or format as a value",
        Expr::Closure { .. } => "a function as a value",
        Expr::Host { .. } => "a host object's function",
        Expr::This | Expr::Arguments => "`this` or `arguments`",
        _ => "an expression",
    }
}

/// A number as VcPost reads it back exactly (Rust's shortest round-trip form).
fn number(n: f64) -> String {
    if n == 0.0 { "0".into() } else { format!("{n}") }
}

/// A string literal: `"` doubled; control characters as `Chr(n)`
/// (then the parts are joined with `&`, in parentheses).
fn text_literal(t: &str) -> String {
    let parts = text_parts(t);
    if parts.len() == 1 { parts[0].clone() } else { format!("({})", parts.join(" & ")) }
}

/// The literals and `Chr(n)` that make up a text.
fn text_parts(t: &str) -> Vec<String> {
    let mut parts = Vec::new();
    let mut current = String::new();
    for c in t.chars() {
        if c.is_control() {
            if !current.is_empty() {
                parts.push(format!("\"{}\"", current.replace('"', "\"\"")));
                current.clear();
            }
            parts.push(format!("Chr({})", c as u32));
        } else {
            current.push(c);
        }
    }
    if !current.is_empty() || parts.is_empty() {
        parts.push(format!("\"{}\"", current.replace('"', "\"\"")));
    }
    parts
}

/// The operands of an `Out` as they are built: string literals the
/// frontend reads as templates, and values.
#[derive(Default)]
struct Template {
    parts: Vec<String>,
    /// The literal being built, without quotes.
    literal: String,
}

impl Template {
    /// Literal text: a `<` ends its literal, so that no `<NAME>` of the
    /// text reads as a register; control characters go out as `Chr(n)`.
    fn text(&mut self, text: &str) {
        for c in text.chars() {
            if c.is_control() {
                self.flush();
                self.parts.push(format!("Chr({})", c as u32));
                continue;
            }
            self.literal.push(c);
            if c == '<' {
                self.flush();
            }
        }
    }

    fn register(&mut self, name: &str) {
        self.literal.push('<');
        self.literal.push_str(name);
        self.literal.push('>');
    }

    fn value(&mut self, value: String) {
        self.flush();
        self.parts.push(value);
    }

    fn flush(&mut self) {
        if !self.literal.is_empty() {
            self.parts.push(format!("\"{}\"", self.literal.replace('"', "\"\"")));
            self.literal.clear();
        }
    }

    fn finish(mut self) -> Vec<String> {
        self.flush();
        self.parts
    }
}
