//! The Vectric backend: a post IR printed as a Vectric `.pp` post, in the
//! order the Vectric guides lay a post out: a comment block, the global
//! statements (`POST_NAME`, `FILE_EXTENSION`, `UNITS`, ...), the `VAR`
//! declarations, Lua `SCRIPT` blocks, then one `begin SECTION` per handler
//! in the guides' section order.
//!
//! What Vectric can say is narrow, and the backend refuses the rest:
//!
//! - handlers are sections whose bodies are output lines (literal bytes and
//!   variables) and Lua calls; any other statement (assignments,
//!   conditions, loops, calls: CIMCO functions, VcPost Subs) is `CV002`;
//! - a handler for an event Vectric has no section for (coolant, drill
//!   cycles, comments, ...) or a post dispatched by APT words is `CV001`;
//! - a number format Vectric's `W.D` formats cannot write (trimmed zeros,
//!   width of the integer digits, no leading zero, a format prefix,
//!   rounding of the binary double, a minus dropped from a negative value
//!   that rounds to zero) is `CV003`;
//! - an output option with no Vectric statement (a lathe, a chord
//!   tolerance, a step budget other than the defaults, modal memory kept
//!   across toolpaths) is `CV004`, and so is a rule VCarve's engine does
//!   not follow (on-change words that compare their text, a feed word that
//!   keeps its memory across rapids: docs/vectric.md);
//! - a variable Vectric cannot declare (assigned by code, a prefix holding
//!   `|`, `]` or a line break, two variables printing one quantity in one
//!   post) is `CV005`.
//!
//! Literal bytes that are not printable ASCII, and `"` and `[`, are
//! written as `[nn]` codes, so every byte (Windows-1252 or UTF-8) comes
//! back unchanged.

use postc_ir::codes;
use std::collections::HashMap;
use std::fmt::Write as _;

use postc_front_vectric::defaults::default_format;
use postc_front_vectric::names::{label_of_var_name, var_name_of_label};
use postc_ir::post::{CommentTarget, Dispatch, RotaryWrap, Section, WrappedAxis};
use postc_ir::{
    Diagnostic, HandlerKey, Justify, Modality, NumberFormat, OutputOptions, Padding, Piece, PointStyle, Post, ScriptId,
    SignStyle, Span, Stmt, Units, ValueSource, VarId, WidthOf,
};

/// The guides' order of sections.
const SECTION_ORDER: &[Section] = &[
    Section::RevisionComment,
    Section::Header,
    Section::SpindleOn,
    Section::ToolChange,
    Section::NewSegment,
    Section::InitialRapidMove,
    Section::RapidMove,
    Section::FirstFeedMove,
    Section::FeedMove,
    Section::FirstPlungeMove,
    Section::PlungeMove,
    Section::RetractMove,
    Section::FirstCwArcMove,
    Section::CwArcMove,
    Section::FirstCcwArcMove,
    Section::CcwArcMove,
    Section::FirstCwHelicalArcMove,
    Section::CwHelicalArcMove,
    Section::FirstCcwHelicalArcMove,
    Section::CcwHelicalArcMove,
    Section::FirstCwHelicalArcPlungeMove,
    Section::CwHelicalArcPlungeMove,
    Section::FirstCcwHelicalArcPlungeMove,
    Section::CcwHelicalArcPlungeMove,
    Section::FeedRateChange,
    Section::DwellMove,
    Section::JetToolOn,
    Section::JetToolPower,
    Section::JetToolOff,
    Section::Footer,
];

/// Prints `post` as a Vectric post, or says why it cannot be one: the
/// file as written when the IR keeps it and it compiles back to `post`
/// ([`as_written`]), from the IR otherwise.
pub fn print(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    if let Some(text) = as_written(post) {
        return Ok(text);
    }
    let mut p = Printer { post, out: Vec::new(), errors: Vec::new() };
    p.check_shape();
    if post.info.dispatch == Dispatch::AptWords {
        // Every handler would be refused for the same reason.
        return Err(p.errors);
    }
    let labels = p.labels();
    p.header();
    p.globals();
    p.variables();
    p.scripts();
    p.sections(&labels);
    if p.errors.is_empty() { Ok(p.out) } else { Err(p.errors) }
}

struct Printer<'p> {
    post: &'p Post,
    out: Vec<u8>,
    errors: Vec<Diagnostic>,
}

/// The post's file as written, when it compiles back to `post`
/// ([`crate::as_written`]). A file of Windows-1252 text that is not ASCII
/// is printed from the IR, whose `[nn]` codes keep every byte.
fn as_written(post: &Post) -> Option<Vec<u8>> {
    if post.info.text_encoding != postc_ir::post::TextEncoding::Utf8 && !post.info.written.is_ascii() {
        return None;
    }
    let note = format!(
        "+ {}{} ({})",
        postc_ir::post::CONVERSION_NOTE,
        crate::source_name(post),
        crate::dialect_name(post.info.dialect)
    );
    crate::as_written(post, postc_ir::Dialect::Vectric, &note, postc_front_vectric::compile, |t| {
        Some(t.as_bytes().to_vec())
    })
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        let mut d = Diagnostic::error(code, message).note(why.to_string());
        if let Some(span) = span {
            d = d.at(span, "here");
        }
        self.errors.push(d);
    }

    fn line(&mut self, text: &str) {
        self.out.extend_from_slice(text.as_bytes());
        self.out.extend_from_slice(b"\r\n");
    }

    /// What the post as a whole must be to be a Vectric post.
    fn check_shape(&mut self) {
        let post = self.post;
        if post.info.dispatch == Dispatch::AptWords {
            self.refuse(
                codes::CV001.code,
                None,
                "this post is driven by APT words (one Sub per GOTO, FEDRAT, ...), which Vectric has no form for"
                    .into(),
                "a Vectric post prints sections chosen by the kind of move; it cannot run a Sub per APT record",
            );
        }
        // A section post's Sub whose handler holds its lines (VcPost, docs/vcpost.md) is
        // those lines again, not code.
        let is_section_copy = |f: &postc_ir::Function| {
            Section::from_name(&f.name).is_some_and(|s| {
                post.section(s).is_some_and(|h| matches!(&f.body, postc_ir::Body::Native(b) if *b == h.body))
            })
        };
        // A Fusion post's own functions, not its host's.
        let own = |f: &&postc_ir::Function| {
            post.info.host_file.is_none() || f.span.is_some_and(|s| Some(s.file) != post.info.host_file)
        };
        let code: Vec<&postc_ir::Function> =
            post.functions.iter().filter(|f| !is_section_copy(f)).filter(own).collect();
        let host_code = post.functions.len() > code.len() && post.info.host_file.is_some();
        if !code.is_empty() || host_code || !post.globals.is_empty() || !post.init.is_empty() {
            let span = code.iter().find_map(|f| f.span);
            self.refuse(
                codes::CV002.code,
                span,
                format!(
                    "this post has code ({} functions, {} globals, {} statements run at start) and a Vectric post has none",
                    code.len(),
                    post.globals.len(),
                    post.init.len()
                ),
                "Vectric sections only print lines of text and variables",
            );
        }
        let o = &post.options;
        let d = OutputOptions::default();
        let mut no_statement = |what: &str, differs: bool| {
            if differs {
                self.refuse(
                    codes::CV004.code,
                    None,
                    format!("this post sets {what}, which no Vectric statement sets"),
                    "the converted post would behave differently",
                );
            }
        };
        no_statement("a lathe coordinate mapping", o.lathe);
        no_statement("a chord tolerance for linearized arcs", o.arc_tolerance != d.arc_tolerance);
        no_statement("exact arc words", o.exact_arcs);
        no_statement("modal memory kept across toolpaths", !o.forget_modal_at_toolpath_start);
        // VCarve compares an on-change word's value and prints the feed
        // again after a rapid (docs/vectric.md): a post that does neither
        // would print differently there.
        let on_change = |q: Option<postc_ir::Quantity>| {
            post.variables.iter().any(|v| {
                v.modality == postc_ir::Modality::OnChange
                    && matches!(v.source, ValueSource::Quantity(s) if !s.is_text() && q.is_none_or(|q| q == s))
            })
        };
        no_statement("on-change words that compare their printed text", !o.on_change_by_value && on_change(None));
        no_statement(
            "a feed word that keeps its memory across rapids",
            !o.rapid_forgets_feed && on_change(Some(postc_ir::Quantity::Feed)),
        );
        no_statement("a step budget", o.step_budget != d.step_budget);
        if let Some(w) = &o.rotary_wrap
            && w.letter.is_none()
            && w.reversed
        {
            self.refuse(
                codes::CV004.code,
                None,
                "this post wraps an axis the other way but keeps its letter, which ROTARY_WRAP cannot say".into(),
                "ROTARY_WRAP_X/Y = \"-A\" names the rotary letter",
            );
        }
    }

    /// The label each variable prints under, refusing variables Vectric
    /// cannot declare.
    fn labels(&mut self) -> HashMap<VarId, &'static str> {
        let mut labels = HashMap::new();
        let mut by_quantity: HashMap<&'static str, usize> = HashMap::new();
        let mut assigned = Vec::new();
        for (i, v) in self.post.variables.iter().enumerate() {
            let ValueSource::Quantity(q) = v.source else {
                assigned.push(format!("`{}`", v.name));
                continue;
            };
            // A later VAR with the same label replaces an earlier one, so
            // only the last of each label can be printed.
            by_quantity.insert(q.label(), i);
            labels.insert(VarId::new(i as u16), q.label());
        }
        if !assigned.is_empty() {
            self.refuse(
                codes::CV005.code,
                None,
                format!(
                    "the post's code sets what {} {} print, and Vectric variables only print what the job gives",
                    assigned.join(", "),
                    if assigned.len() == 1 { "variable" } else { "variables" }
                ),
                "a Vectric VAR reads one value of the job ([X], [F], [TOOLNAME], ...)",
            );
        }
        // Variables that lines print must be the ones their labels name.
        for h in &self.post.handlers {
            for stmt in &h.body {
                if let Stmt::Line { pieces, .. } = stmt {
                    for piece in pieces {
                        if let Piece::Var(id) = piece
                            && let Some(label) = labels.get(id)
                            && by_quantity.get(label) != Some(&id.index())
                        {
                            let name = &self.post.variables[id.index()].name;
                            self.refuse(
                                codes::CV005.code,
                                h.span,
                                format!(
                                    "two variables print [{label}] (`{name}` is one), and a Vectric label names one"
                                ),
                                "a Vectric line names a variable by its label",
                            );
                            return labels;
                        }
                    }
                }
            }
        }
        labels
    }

    /// The conversion note, then the source's notes and head comments in
    /// the same block (the frontend reads that block back as the head,
    /// without the note).
    fn header(&mut self) {
        let post = self.post;
        self.line(&format!(
            "+ {}{} ({})",
            postc_ir::post::CONVERSION_NOTE,
            crate::source_name(post),
            crate::dialect_name(post.info.dialect)
        ));
        // The source's encoding does not matter: the converted post writes
        // every byte that is not ASCII as a `[nn]` code.
        for note in &post.info.notes {
            for l in note.lines() {
                self.line(&format!("+ {l}"));
            }
        }
        self.comment(&CommentTarget::Post);
        self.line("");
    }

    /// The source's comment lines before `on`, as `+` lines.
    fn comment(&mut self, on: &CommentTarget) {
        let post = self.post;
        for l in post.comment(on) {
            self.line(&format!("+{l}"));
        }
    }

    fn globals(&mut self) {
        let post = self.post;
        let info = &post.info;
        self.line(&format!("POST_NAME = \"{}\"", quoted_text(&info.name)));
        if !info.file_extension.is_empty() {
            self.line(&format!("FILE_EXTENSION = \"{}\"", quoted_text(&info.file_extension)));
        }
        match info.units {
            Some(Units::Mm) => self.line("UNITS = \"MM\""),
            Some(Units::Inch) => self.line("UNITS = \"INCHES\""),
            None => {}
        }
        if let Some(d) = &info.direct_output {
            self.line(&format!("DIRECT_OUTPUT = \"{}\"", quoted_text(d)));
        }
        let yes = |b: bool| if b { "YES" } else { "NO" };
        if info.print_direct {
            self.line(&format!("PRINT_DIRECT = \"{}\"", yes(true)));
        }
        if info.rapid_plunge_to_start_z {
            self.line(&format!("RAPID_PLUNGE_TO_STARTZ = \"{}\"", yes(true)));
        }
        if info.laser_support {
            self.line(&format!("LASER_SUPPORT = \"{}\"", yes(true)));
        }
        let o = &post.options;
        self.line(&format!("LINE_ENDING = \"{}\"", codes(&o.line_ending)));
        let b = o.block_numbers;
        self.line(&format!("LINE_NUMBER_START = {}", number(b.start)));
        self.line(&format!("LINE_NUMBER_INCREMENT = {}", number(b.increment)));
        self.line(&format!("LINE_NUMBER_MAXIMUM = {}", number(b.maximum)));
        if !o.substitutions.is_empty() {
            let mut pairs = Vec::new();
            let mut ok = true;
            for s in &o.substitutions {
                ok &= s.from.len() == 1 && s.to.len() == 1;
                pairs.extend_from_slice(&s.from);
                pairs.extend_from_slice(&s.to);
            }
            if ok {
                self.line(&format!("SUBSTITUTE = \"{}\"", quoted(&pairs)));
            } else {
                self.refuse(
                    codes::CV004.code,
                    None,
                    "this post substitutes text longer than one character, and SUBSTITUTE takes single characters"
                        .into(),
                    "SUBSTITUTE holds pairs of characters",
                );
            }
        }
        if let Some(t) = &o.tape_splitting {
            self.line(&format!(
                "TAPE_SPLITTING = {} {} \"{}\" {} \"{}\"",
                t.max_lines,
                t.tolerance,
                quoted_text(&t.name_format),
                t.start_index,
                yes(t.index_on_first_file)
            ));
        }
        if let Some(r) = &o.spindle_speed_range {
            self.line(&format!(
                "SPINDLE_SPEED_RANGE = {} {} {} {}",
                number(r.out_min),
                number(r.out_max),
                number(r.rpm_min),
                number(r.rpm_max)
            ));
        }
        if let Some(RotaryWrap { axis, letter, reversed }) = o.rotary_wrap {
            let name = match axis {
                WrappedAxis::X => "ROTARY_WRAP_X",
                WrappedAxis::Y => "ROTARY_WRAP_Y",
            };
            match letter {
                Some(letter) => self.line(&format!("{name} = \"{}{letter}\"", if reversed { "-" } else { "" })),
                None => self.line(&format!("{name} = \"YES\"")),
            }
        }
        if let Some(r) = o.min_arc_radius {
            self.line(&format!("MIN_ARC_RADIUS = {}", number(r)));
        }
        if let Some(r) = o.max_arc_radius {
            self.line(&format!("MAX_ARC_RADIUS = {}", number(r)));
        }
        if o.inverse_time_feed {
            self.line("INVERSE_TIME_MODE = \"YES\"");
        }
        self.line("");
    }

    fn variables(&mut self) {
        let post = self.post;
        for (id, v) in post.variables.iter().enumerate() {
            let ValueSource::Quantity(q) = v.source else { continue };
            if var_name_of_label(q.label()).is_none() {
                // No VAR name prints this label: it must be its default,
                // which the label gets without a declaration.
                if !is_default(post, v, q) {
                    self.refuse(
                        codes::CV005.code,
                        None,
                        format!(
                            "`{}` prints [{}] in a way of its own, and Vectric has no VAR name to declare it",
                            v.name,
                            q.label()
                        ),
                        "a label without a VAR name always prints with its default format",
                    );
                }
                continue;
            }
            if v.prefix.iter().any(|b| matches!(b, b'|' | b']' | b'\r' | b'\n')) {
                self.refuse(
                    codes::CV005.code,
                    None,
                    format!("the prefix of `{}` holds `|`, `]` or a line break, which a VAR cannot hold", v.name),
                    "a VAR's prefix is everything between two bars",
                );
                continue;
            }
            let Some(format) = post.formats.get(v.format.index()) else { continue };
            let Some(spec) = self.format_spec(&v.name, format) else { continue };
            let modality = match v.modality {
                Modality::Always => "A",
                Modality::OnChange => "C",
            };
            // The VAR name the guides give this label (a name of the source
            // dialect, `xOutput`, is no VAR name).
            let name = match label_of_var_name(&v.name) {
                Some(label) if label.eq_ignore_ascii_case(q.label()) => var_name(&v.name),
                _ => var_name_of_label(q.label()).unwrap_or_default().to_string(),
            };
            self.comment(&CommentTarget::Variable(VarId::new(id as u16)));
            let mut line = format!("VAR {name} = [{}|{modality}|", q.label());
            let mut bytes = std::mem::take(&mut line).into_bytes();
            bytes.extend_from_slice(&v.prefix);
            bytes.extend_from_slice(format!("|{spec}").as_bytes());
            if format.multiplier != 1.0 {
                bytes.extend_from_slice(format!("|{}", number(format.multiplier)).as_bytes());
            }
            bytes.extend_from_slice(b"]\r\n");
            self.out.extend_from_slice(&bytes);
        }
        self.line("");
    }

    /// `-+0#W.D` for a format, or a refusal.
    fn format_spec(&mut self, name: &str, f: &NumberFormat) -> Option<String> {
        let mut why = Vec::new();
        if f.width_of != WidthOf::Whole {
            why.push("its width counts the integer digits only");
        }
        if f.trim_zeros {
            why.push("it drops trailing zeros");
        }
        if !f.leading_zero {
            why.push("it drops the leading zero");
        }
        if !f.prefix.is_empty() {
            why.push("it has a prefix of its own");
        }
        if !matches!(f.decimal_mark, '.' | ',') {
            why.push("its decimal mark is neither `.` nor `,`");
        }
        if f.decimals > 15 {
            why.push("it has more than 15 decimals");
        }
        if f.rounding == postc_ir::Rounding::Binary {
            why.push("it rounds the binary double (as JavaScript does), and Vectric rounds the decimal value");
        }
        if !f.negative_zero {
            why.push("it drops the minus of a negative value that rounds to zero, and Vectric keeps it (`-0.000`)");
        }
        if !why.is_empty() {
            self.refuse(
                codes::CV003.code,
                None,
                format!("the format of `{name}` cannot be written as a Vectric format: {}", why.join(", ")),
                "a Vectric format is flags - + 0 #, a width, `.` or `,`, and decimals",
            );
            return None;
        }
        let mut s = String::new();
        if f.justify == Justify::Left {
            s.push('-');
        }
        if f.sign == SignStyle::Always {
            s.push('+');
        }
        if f.padding == Padding::Zero {
            s.push('0');
        }
        if f.point == PointStyle::Always {
            s.push('#');
        }
        let _ = write!(s, "{}{}{}", f.width, f.decimal_mark, f.decimals);
        Some(s)
    }

    fn scripts(&mut self) {
        let post = self.post;
        let called: Vec<ScriptId> = post
            .handlers
            .iter()
            .flat_map(|h| h.body.iter())
            .filter_map(|s| if let Stmt::Script(id) = s { Some(*id) } else { None })
            .collect();
        for (i, script) in post.scripts.iter().enumerate() {
            if called.contains(&ScriptId::new(i as u16)) {
                continue;
            }
            self.line("SCRIPT");
            for l in script.source.lines() {
                self.line(l);
            }
            self.line("ENDSCRIPT");
            self.line("");
        }
    }

    fn sections(&mut self, labels: &HashMap<VarId, &'static str>) {
        let post = self.post;
        let mut order: Vec<&postc_ir::Handler> = Vec::new();
        for h in &post.handlers {
            match &h.key {
                HandlerKey::Section(s) if SECTION_ORDER.contains(s) => order.push(h),
                HandlerKey::Section(s) => self.refuse(
                    codes::CV001.code,
                    h.span,
                    format!("Vectric has no section for {} (`{}`)", section_event(*s), s.name()),
                    "a Vectric post has sections only for the moves, tools and jets of its guides",
                ),
                HandlerKey::Word(w) => self.refuse(
                    codes::CV001.code,
                    h.span,
                    format!("the handler for the APT word {w} has no Vectric section"),
                    "Vectric sections are chosen by the kind of move, not by APT words",
                ),
            }
        }
        order.sort_by_key(|h| match h.key {
            HandlerKey::Section(s) => SECTION_ORDER.iter().position(|x| *x == s).unwrap_or(usize::MAX),
            HandlerKey::Word(_) => usize::MAX,
        });
        for h in order {
            let HandlerKey::Section(s) = h.key else { continue };
            self.comment(&CommentTarget::Handler(h.key.clone()));
            self.line(&format!("begin {}", s.name()));
            let refused = self.errors.len();
            for stmt in &h.body {
                if self.errors.len() > refused {
                    // One reason per section is enough to act on.
                    break;
                }
                match stmt {
                    Stmt::Line { pieces, .. } => {
                        let mut bytes = vec![b'"'];
                        for piece in pieces {
                            match piece {
                                Piece::Text(t) => bytes.extend_from_slice(quoted(t).as_bytes()),
                                Piece::Var(id) => match labels.get(id) {
                                    Some(label) => bytes.extend_from_slice(format!("[{label}]").as_bytes()),
                                    None => {
                                        self.refuse(
                                            codes::CV005.code,
                                            h.span,
                                            format!("a line of {} prints a variable set by code", s.name()),
                                            "Vectric lines print job values only",
                                        );
                                    }
                                },
                                Piece::Expr(_) => self.refuse(
                                    codes::CV002.code,
                                    h.span,
                                    format!("a line of {} prints a computed value", s.name()),
                                    "Vectric lines print literal text and variables only",
                                ),
                            }
                        }
                        bytes.extend_from_slice(b"\"\r\n");
                        self.out.extend_from_slice(&bytes);
                    }
                    Stmt::Script(id) => match post.scripts.get(id.index()) {
                        Some(script) if !script.source.contains(['\r', '\n']) => {
                            self.line(&format!("<!>{}", script.source));
                        }
                        _ => self.refuse(
                            codes::CV002.code,
                            h.span,
                            format!("a Lua call in {} spans several lines", s.name()),
                            "a Vectric `<!>` call is one line",
                        ),
                    },
                    other => self.refuse(
                        codes::CV002.code,
                        h.span,
                        format!("{} runs {}, and Vectric sections only print lines", s.name(), statement_kind(other)),
                        "a Vectric section is a list of output lines",
                    ),
                }
            }
            self.line("");
        }
    }
}

fn section_event(s: Section) -> &'static str {
    match s {
        Section::SpindleOff => "the spindle stopping",
        Section::Coolant => "coolant",
        Section::CutterComp => "cutter compensation",
        Section::DrillHeader | Section::DrillPoint | Section::DrillFooter => "canned drilling cycles",
        Section::Comment => "comments",
        Section::Insert => "inserted text",
        Section::ToolpathEnd => "the end of a toolpath",
        _ => "this event",
    }
}

fn statement_kind(s: &Stmt) -> &'static str {
    match s {
        Stmt::Assign(..) => "an assignment",
        Stmt::If { .. } => "a condition",
        Stmt::While { .. } => "a loop",
        Stmt::Eval(_) => "a call",
        Stmt::Return(_) => "a return",
        Stmt::Write(_) => "code that writes computed text",
        _ => "code",
    }
}

/// Whether a variable prints its label exactly as the label's default does.
fn is_default(post: &Post, v: &postc_ir::Variable, q: postc_ir::Quantity) -> bool {
    let d = default_format(q);
    // Where the format was written does not matter, only how it prints.
    let format = post.formats.get(v.format.index()).map(|f| NumberFormat { span: None, ..f.clone() });
    v.prefix == d.prefix.as_bytes() && v.modality == d.modality && format == Some(d.format.to_number_format(1.0))
}

/// A name a VAR can have: letters, digits and `_`.
fn var_name(name: &str) -> String {
    let n: String = name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    if n.is_empty() { "VAR".into() } else { n }
}

/// Bytes inside a quoted Vectric string: printable ASCII as it is, `"`,
/// `[` and every other byte as a `[nn]` code.
fn quoted(bytes: &[u8]) -> String {
    let mut s = String::with_capacity(bytes.len());
    for &b in bytes {
        if (0x20..0x7f).contains(&b) && b != b'"' && b != b'[' {
            s.push(b as char);
        } else {
            let _ = write!(s, "[{b}]");
        }
    }
    s
}

/// Text of a global statement (`POST_NAME`, ...), which is read as text:
/// `"`, `[` and control characters as codes, the rest as it is.
fn quoted_text(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        if c == '"' || c == '[' || c.is_ascii_control() {
            let _ = write!(s, "[{}]", c as u32);
        } else {
            s.push(c);
        }
    }
    s
}

/// Every byte as a `[nn]` code (`LINE_ENDING`).
fn codes(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("[{b}]")).collect()
}

/// A number as Vectric statements write it: shortest round-trip text.
fn number(n: f64) -> String {
    if n == n.trunc() && n.abs() < 1e15 { format!("{}", n as i64) } else { format!("{n}") }
}
