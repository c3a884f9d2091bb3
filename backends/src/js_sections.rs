//! JavaScript posts made from posts driven by the kind of each move (a
//! Vectric post), for the two JavaScript engines postc converts to: a
//! native CNC-Calc post (`onOpen(isClipboard)`, `onLinear(vx, vy, vz,
//! movement)`, `onCircular(cx, cy, cz, ex, ey, ez, isCW, movement)`,
//! `onClose()`; docs/convert.md, "Native CNC-Calc posts") and an Autodesk
//! Fusion `.cps` post (`onOpen`, `onSection`, `onRapid`, `onLinear`,
//! `onCircular`, `onDwell`, `onClose`; docs/convert.md, "Fusion posts").
//! This module owns what both share: the Vectric rules (which section
//! prints a move: `FIRST_` sections, plunge, retract and helix fallbacks,
//! arcs cut into feed moves, FEED_RATE_CHANGE, `[N]` numbering, modal
//! words) as ordinary JavaScript state in the printed post, Vectric's
//! number formats as a JavaScript function, and each section printed as a
//! JavaScript function; [`Host`] says which engine's entry points call them.
//!
//! What the engine cannot do is refused or converted with a warning, per
//! construct, at the source's line and column:
//!
//! - a value the engine never hands the post (for CNC-Calc `[T]`,
//!   `[TOOLNAME]`, the material, `[SAFEZ]`, the home position, the
//!   origin offsets, file names, the date and time; for Fusion `[FI]`
//!   and an `[A]` no axis wraps, ...) in a section the post prints is
//!   `CV007` (Fusion hands the tool's feeds, clearance height and notes
//!   as operation parameters, the home position, the origin offsets and
//!   the wrap diameter are the converted post's properties,
//!   which the user sets, jet power is no value in a milling post, and
//!   the job's texts are made from what it hands: [`JOB_TEXTS`]);
//! - a section the engine never calls (CNC-Calc: `TOOLCHANGE`,
//!   `NEW_SEGMENT`, `DWELL_MOVE`, ...) is left out with warning `CV008`;
//! - a rule the engine gives the post no way to follow (CNC-Calc's
//!   helical plunge sections: its engine does not say which arcs plunge,
//!   where Fusion's `movement` does; an empty line, which CNC-Calc does
//!   not write) is `CV010`;
//! - a feed printed finer than the tenth CNC-Calc's `getFeedrate` hands is
//!   warned of (`CV011`);
//! - output options the printed post does not carry are `CV004`, code is
//!   `CV002`, a post driven by APT words is `CV001`.

use postc_ir::codes;
use postc_ir::post::{Dispatch, Section, WrappedAxis};
use postc_ir::{
    CommentTarget, Diagnostic, HandlerKey, Justify, Modality, NumberFormat, OutputOptions, Padding, Piece, PointStyle,
    Post, Quantity, SignStyle, Span, Stmt, TextEncoding, Units, ValueSource, WidthOf,
};

/// A converted post and the warnings of its conversion.
pub type Printed = (Vec<u8>, Vec<Diagnostic>);

/// The engine whose entry points call the printed post.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Host {
    /// CIMCO CNC-Calc (the CNC-Calc manual's entry points).
    Cimco,
    /// Autodesk Fusion (`.cps`; docs/fusion.md).
    Fusion,
}

impl Host {
    /// The engine's name as machinists know it.
    fn engine(self) -> &'static str {
        match self {
            Host::Cimco => "CNC-Calc",
            Host::Fusion => "Fusion",
        }
    }
}

/// Prints `post` as a post `host` runs, or says why it cannot be one.
pub fn print(post: &Post, host: Host) -> Result<Printed, Vec<Diagnostic>> {
    let mut p = Printer { post, host, out: String::new(), errors: Vec::new(), warnings: Vec::new(), names: Vec::new() };
    p.check_shape();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    p.check_sections();
    p.header();
    p.variables();
    p.state();
    p.section_functions();
    p.entry_points();
    if p.errors.is_empty() { Ok((p.out.into_bytes(), p.warnings)) } else { Err(p.errors) }
}

/// The sections CNC-Calc's entry points print, with the call that prints them.
const CALLED: &[(Section, &str)] = &[
    (Section::RevisionComment, "onOpen"),
    (Section::Header, "onOpen"),
    (Section::SpindleOn, "onOpen"),
    (Section::InitialRapidMove, "onLinear"),
    (Section::RapidMove, "onLinear"),
    (Section::RetractMove, "onLinear"),
    (Section::FirstFeedMove, "onLinear"),
    (Section::FeedMove, "onLinear"),
    (Section::FirstPlungeMove, "onLinear"),
    (Section::PlungeMove, "onLinear"),
    (Section::FeedRateChange, "onLinear"),
    (Section::FirstCwArcMove, "onCircular"),
    (Section::CwArcMove, "onCircular"),
    (Section::FirstCcwArcMove, "onCircular"),
    (Section::CcwArcMove, "onCircular"),
    (Section::FirstCwHelicalArcMove, "onCircular"),
    (Section::CwHelicalArcMove, "onCircular"),
    (Section::FirstCcwHelicalArcMove, "onCircular"),
    (Section::CcwHelicalArcMove, "onCircular"),
    (Section::Footer, "onClose"),
];

/// The sections Fusion's entry points print, with the call that prints them.
const FUSION_CALLED: &[(Section, &str)] = &[
    (Section::RevisionComment, "onSection"),
    (Section::Header, "onSection"),
    (Section::SpindleOn, "onSection"),
    (Section::ToolChange, "onSection"),
    (Section::NewSegment, "onSection"),
    (Section::InitialRapidMove, "onRapid"),
    (Section::RapidMove, "onRapid"),
    (Section::RetractMove, "onRapid"),
    (Section::FirstFeedMove, "onLinear"),
    (Section::FeedMove, "onLinear"),
    (Section::FirstPlungeMove, "onLinear"),
    (Section::PlungeMove, "onLinear"),
    (Section::FeedRateChange, "onLinear"),
    (Section::FirstCwArcMove, "onCircular"),
    (Section::CwArcMove, "onCircular"),
    (Section::FirstCcwArcMove, "onCircular"),
    (Section::CcwArcMove, "onCircular"),
    (Section::FirstCwHelicalArcMove, "onCircular"),
    (Section::CwHelicalArcMove, "onCircular"),
    (Section::FirstCcwHelicalArcMove, "onCircular"),
    (Section::CcwHelicalArcMove, "onCircular"),
    (Section::FirstCwHelicalArcPlungeMove, "onCircular"),
    (Section::CwHelicalArcPlungeMove, "onCircular"),
    (Section::FirstCcwHelicalArcPlungeMove, "onCircular"),
    (Section::CcwHelicalArcPlungeMove, "onCircular"),
    (Section::DwellMove, "onDwell"),
    (Section::Footer, "onClose"),
];

/// Sections printed before the first move, where no position, feed or
/// arc has been handed yet.
const BEFORE_MOVES: &[Section] = &[Section::RevisionComment, Section::Header, Section::SpindleOn];

/// The converted post's property for the job's wrap diameter.
const WRAP_PROPERTY: &str = "wrapDiameter";

/// Sections Fusion prints at the start of a section (its `onSection`),
/// where the section's feed and arcs have not been handed yet.
const SECTION_START: &[Section] =
    &[Section::RevisionComment, Section::Header, Section::SpindleOn, Section::ToolChange, Section::NewSegment];

/// Sections chosen only for arcs the toolpath marks as plunging, which
/// CNC-Calc's `onCircular` does not say (Fusion's `movement` does:
/// `MOVEMENT_RAMP_HELIX`).
const PLUNGE_ARCS: &[Section] = &[
    Section::FirstCwHelicalArcPlungeMove,
    Section::CwHelicalArcPlungeMove,
    Section::FirstCcwHelicalArcPlungeMove,
    Section::CcwHelicalArcPlungeMove,
];

/// What the printed post reads each quantity from, when the engine hands it.
fn handed(q: Quantity, host: Host) -> Option<&'static str> {
    if host == Host::Fusion {
        // What Fusion hands at each section (`tool`, `spindleSpeed`, the
        // operation's parameters) and the job's stock (`getWorkpiece()`),
        // kept by the printed post's `onSection`; the dwell `onDwell` hands.
        let fusion = match q {
            Quantity::Tool => Some("toolNumber"),
            Quantity::ToolDiameter => Some("toolDiameter"),
            Quantity::SpindleSpeed => Some("spindleOutput(spindle)"),
            Quantity::ToolName => Some("toolName"),
            Quantity::ToolNotes => Some("toolNotes"),
            Quantity::ToolpathName => Some("toolpathName"),
            // The operation's notes, its `notes` parameter.
            Quantity::ToolpathNotes => Some("toolpathNotes"),
            // A milling section has no jet power: Vectric prints nothing
            // for `[P]` while a spindle tool is loaded (docs/vectric.md,
            // decision 46), and the converted post is a milling post.
            Quantity::Power => Some("NaN"),
            Quantity::DwellTime => Some("dwellTime"),
            Quantity::XMin => Some("stockLower.x"),
            Quantity::YMin => Some("stockLower.y"),
            Quantity::ZMin => Some("stockLower.z"),
            Quantity::XMax => Some("stockUpper.x"),
            Quantity::YMax => Some("stockUpper.y"),
            Quantity::ZMax => Some("stockUpper.z"),
            Quantity::XLength => Some("(stockUpper.x - stockLower.x)"),
            Quantity::YLength => Some("(stockUpper.y - stockLower.y)"),
            Quantity::ZLength => Some("(stockUpper.z - stockLower.z)"),
            // The operation's tool feeds and clearance height
            // (`getParameter`), kept at `onSection`.
            Quantity::CutFeed => Some("toolFeedCut"),
            Quantity::PlungeFeed => Some("toolFeedPlunge"),
            Quantity::SafeZ => Some("safeZ"),
            // The home position: the post's properties, which the user
            // sets in Fusion's post dialog (docs/convert.md).
            Quantity::HomeX => Some("homeX"),
            Quantity::HomeY => Some("homeY"),
            Quantity::HomeZ => Some("homeZ"),
            // The origin's offset from the material's datum corner: the
            // post's properties too.
            Quantity::XOrigin => Some("originX"),
            Quantity::YOrigin => Some("originY"),
            // The last section's tool when this section's differs.
            Quantity::PreviousTool => Some("previousTool"),
            // The job's texts, each made in `onOpen` from what Fusion
            // hands ([`JOB_TEXTS`]).
            q => JOB_TEXTS.iter().find(|(t, ..)| *t == q).map(|(_, name, _)| *name),
        };
        if fusion.is_some() {
            return fusion;
        }
    }
    Some(match q {
        Quantity::X => "x",
        Quantity::Y => "y",
        Quantity::Z => "z",
        Quantity::I => "arcI",
        Quantity::J => "arcJ",
        Quantity::IA => "arcIA",
        Quantity::JA => "arcJA",
        Quantity::K => "arcK",
        Quantity::KA => "arcKA",
        Quantity::ArcStartX => "arcStartX",
        Quantity::ArcStartY => "arcStartY",
        Quantity::ArcMidX => "arcMidX",
        Quantity::ArcMidY => "arcMidY",
        Quantity::ArcMidXI => "arcMidXI",
        Quantity::ArcMidYI => "arcMidYI",
        Quantity::Angle => "arcAngle",
        Quantity::Radius => "arcRadius",
        Quantity::Feed => "feed",
        Quantity::BlockNumber => "blockNumber",
        _ => return None,
    })
}

struct Printer<'p> {
    post: &'p Post,
    host: Host,
    out: String,
    errors: Vec<Diagnostic>,
    warnings: Vec<Diagnostic>,
    /// Each variable's JavaScript name.
    names: Vec<String>,
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        self.errors.push(crate::cimco::refusal(code, span, message, why));
    }

    /// The sections the engine's entry points print, with their calls.
    fn called(&self) -> &'static [(Section, &'static str)] {
        match self.host {
            Host::Cimco => CALLED,
            Host::Fusion => FUSION_CALLED,
        }
    }

    /// Sections printed where no feed or arc has been handed yet.
    fn before_moves(&self) -> &'static [Section] {
        match self.host {
            Host::Cimco => BEFORE_MOVES,
            Host::Fusion => SECTION_START,
        }
    }

    fn has(&self, s: Section) -> bool {
        self.post.handlers.iter().any(|h| h.key == HandlerKey::Section(s))
    }

    fn check_shape(&mut self) {
        let post = self.post;
        if post.info.dispatch != Dispatch::Sections {
            self.refuse(
                codes::CV001.code,
                None,
                "this post is driven by APT words or application calls, which a CNC-Calc post has no form for".into(),
                "a CNC-Calc post runs per kind of move",
            );
            return;
        }
        let code = post.handlers.iter().find(|h| {
            !h.body.iter().all(|s| {
                matches!(s, Stmt::Line { pieces, .. } if pieces.iter().all(|p| matches!(p, Piece::Text(_) | Piece::Var(_))))
            })
        });
        if let Some(h) = code {
            self.refuse(
                codes::CV002.code,
                h.span,
                "this post's handlers are code, which a native CNC-Calc post made from sections has no form for".into(),
                "only a post whose sections are output lines prints as a native CNC-Calc post (docs/convert.md)",
            );
        }
        if !post.scripts.is_empty() {
            self.refuse(codes::CV002.code, None, "this post has scripts".into(), "a converted post has none");
        }
        let o = &post.options;
        let d = OutputOptions::default();
        for (what, yes) in [
            ("exact arcs", o.exact_arcs != d.exact_arcs),
            ("a step budget", o.step_budget != d.step_budget),
            ("a lathe mapping", o.lathe != d.lathe),
            ("modal memory kept across toolpaths", !o.forget_modal_at_toolpath_start),
            ("tape splitting (TAPE_SPLITTING)", o.tape_splitting.is_some()),
            (
                "a wrapped rotary axis (ROTARY_WRAP), whose angle comes from the job's wrap diameter, never handed to the converted post",
                self.host == Host::Cimco && o.rotary_wrap.is_some(),
            ),
            ("a smallest arc radius (MIN_ARC_RADIUS)", o.min_arc_radius.is_some()),
            ("a largest arc radius (MAX_ARC_RADIUS)", o.max_arc_radius.is_some()),
            ("inverse-time feeds (INVERSE_TIME_MODE)", o.inverse_time_feed),
            (
                "text substitutions (SUBSTITUTE) that are not ASCII",
                self.host == Host::Fusion && o.substitutions.iter().any(|s| !s.from.is_ascii() || !s.to.is_ascii()),
            ),
            (
                "a line ending (LINE_ENDING) that is not text, which setEOL cannot be given",
                self.host == Host::Fusion && std::str::from_utf8(&o.line_ending).is_err(),
            ),
        ] {
            if yes {
                self.refuse(
                    codes::CV004.code,
                    post.info.span,
                    format!("the post sets {what}, which the converted post does not carry"),
                    "a converted post carries the Vectric rules of moves, arcs and block numbers, and a line ending (docs/convert.md)",
                );
            }
        }
    }

    /// Refuses what a section the engine calls prints but the engine
    /// never hands, and warns of sections it never calls.
    fn check_sections(&mut self) {
        let post = self.post;
        for h in &post.handlers {
            let HandlerKey::Section(section) = h.key else { continue };
            if PLUNGE_ARCS.contains(&section) && self.host == Host::Cimco {
                self.refuse(
                    codes::CV010.code,
                    h.span,
                    format!("{} prints arcs the toolpath marks as plunging, and {}'s onCircular does not say which arcs plunge", section.name(), self.host.engine()),
                    "onCircular hands the centre, the end point and the direction",
                );
                continue;
            }
            if matches!(section, Section::DrillHeader | Section::DrillPoint | Section::DrillFooter) {
                self.refuse(
                    codes::CV010.code,
                    h.span,
                    format!("{} is postc's drilling section; the converted post drills each hole with moves, as a Vectric post without it does", section.name()),
                    "the engine hands a drilling operation to its cycle functions, whose lines the converted post makes from its move sections",
                );
                continue;
            }
            let Some(&(_, call)) = self.called().iter().find(|(s, _)| *s == section) else {
                self.warnings.push(
                    Diagnostic::warning(
                        codes::CV008.code,
                        format!(
                            "{} is left out: {} calls no function where Vectric prints it",
                            section.name(),
                            self.host.engine()
                        ),
                    )
                    .note(never_called(section, self.host).to_string()),
                );
                if let (Some(span), Some(d)) = (h.span, self.warnings.pop()) {
                    self.warnings.push(d.at(span, "left out"));
                }
                continue;
            };
            for s in &h.body {
                let Stmt::Line { pieces, span } = s else { continue };
                if pieces.is_empty() && self.host == Host::Cimco {
                    self.refuse(
                        codes::CV010.code,
                        *span,
                        "an empty line, which CNC-Calc does not write".into(),
                        "the engine writes each line a function returns that is not empty (docs/cimco.md, \"Returned text\")",
                    );
                }
                for p in pieces {
                    match p {
                        Piece::Var(v) => {
                            let var = &post.variables[v.index()];
                            let ValueSource::Quantity(q) = var.source else { continue };
                            // Before a section's first feed move Vectric's feed is the
                            // tool's cut feed, which Fusion hands (the operation's
                            // `tool_feedCutting`) and CNC-Calc does not.
                            let tool_feed = self.host == Host::Fusion && q == Quantity::Feed;
                            let before = handed(q, self.host).is_some()
                                && self.before_moves().contains(&section)
                                && handed(q, Host::Cimco).is_some()
                                && !tool_feed
                                && !matches!(q, Quantity::X | Quantity::Y | Quantity::Z | Quantity::BlockNumber);
                            // Before the first move Vectric's position is the
                            // job's home, which neither engine hands.
                            // (Under ROTARY_WRAP `[A]` is a position too.)
                            let at_home = BEFORE_MOVES.contains(&section)
                                && (matches!(q, Quantity::X | Quantity::Y | Quantity::Z)
                                    || q == Quantity::A
                                        && self.host == Host::Fusion
                                        && post.options.rotary_wrap.is_some());
                            let before = before || at_home;
                            // A rapid prints the feed Vectric holds, the tool's
                            // before the first feed move: not handed.
                            let before = before
                                || handed(q, self.host).is_some()
                                    && !tool_feed
                                    && (matches!(section, Section::RapidMove | Section::InitialRapidMove)
                                        && q == Quantity::Feed);
                            if self.host == Host::Cimco
                                && q == Quantity::Feed
                                && feed_finer_than_handed(&post.formats[var.format.index()])
                            {
                                let mut d = Diagnostic::warning(
                                    codes::CV011.code,
                                    format!("`[F]` in {} prints the feed finer than CNC-Calc hands it: to a tenth", section.name()),
                                )
                                .note("the converted post reads the feed from getFeedrate, which formats it to a tenth (docs/cimco.md)");
                                if let Some(span) = *span {
                                    d = d.at(span, "printed finer than a tenth");
                                }
                                self.warnings.push(d);
                            }
                            if self.printed(q).is_none() || before {
                                let engine = self.host.engine();
                                let when = match (before, q) {
                                    (false, _) => "",
                                    (true, _) if at_home => {
                                        " before the first move, where Vectric prints the job's home position"
                                    }
                                    (true, _) if self.before_moves().contains(&section) => match self.host {
                                        Host::Cimco => " before the first move",
                                        Host::Fusion => " where a section starts, before its first move",
                                    },
                                    _ => " in a rapid: Vectric prints the tool's feed there before the first feed move",
                                };
                                let why = match self.host {
                                    Host::Cimco => format!(
                                        "the section prints in {call}; the CNC-Calc manual hands the post the end point and movement of each move, the centre and direction of each arc and the feed (getFeedrate), and nothing of the job, the tool or the toolpath"
                                    ),
                                    Host::Fusion => format!(
                                        "the section prints in {call}; Fusion hands the post each move's end point and feed, each arc's centre and direction, the section's tool (number, name, diameter, spindle speed), its operation's name, notes, tool feeds and clearance height, the stock (and so where the work origin is on it), the output file, the program comment, the CAM product, the sections to come and the clock, and the user sets the home position, the origin offsets and the wrap diameter in the post's properties (docs/convert.md, \"Fusion posts\")"
                                    ),
                                };
                                self.refuse(
                                    codes::CV007.code,
                                    *span,
                                    format!(
                                        "`[{}]` in {}: {engine} never hands a post this value{when}",
                                        q.label(),
                                        section.name()
                                    ),
                                    &why,
                                );
                            }
                        }
                        Piece::Text(bytes) if self.decode(bytes).is_none_or(|t| t.contains(['\n', '\r'])) => {
                            self.refuse(
                                codes::CV002.code,
                                *span,
                                "output text that is not ASCII or UTF-8, or holds a line break".into(),
                                "the engine writes the text of JavaScript strings and ends lines itself",
                            );
                        }
                        _ => {}
                    }
                }
            }
        }
    }

    /// Output text as characters: any UTF-8 text, and the text of a
    /// Windows-1252 post, which a Fusion post writes in that code page
    /// (`setCodePage("ansi")`) and CNC-Calc's engine only as ASCII.
    fn decode(&self, bytes: &[u8]) -> Option<String> {
        if self.post.info.text_encoding == TextEncoding::Windows1252 && !bytes.is_ascii() {
            return (self.host == Host::Fusion)
                .then(|| encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes).0.into_owned());
        }
        String::from_utf8(bytes.to_vec()).ok()
    }

    fn header(&mut self) {
        if self.host == Host::Fusion {
            self.fusion_header();
            return;
        }
        self.out.push_str(&crate::cimco::header(self.post));
        self.out.push_str("//\n");
        self.out.push_str(NATIVE_NOTE);
        self.out.push('\n');
        let le = &self.post.options.line_ending;
        let Some(text) = std::str::from_utf8(le).ok().filter(|t| !t.is_empty()).map(str::to_string) else {
            self.refuse(
                codes::CV004.code,
                self.post.info.span,
                "a line ending (LINE_ENDING) that is not text".into(),
                "the converted post sets `linebreak`, a JavaScript string",
            );
            return;
        };
        self.out.push_str(&format!("var linebreak = {};\n\n", js_string(&text)));
    }

    /// The `.cps` settings: what the post is, the units of its source, and
    /// the arcs Fusion hands it (every arc in XY, helical ones too, whole:
    /// the printed post chooses its section or cuts it into chords as
    /// Vectric does, so Fusion's own limits are set out of the way).
    fn fusion_header(&mut self) {
        let post = self.post;
        self.out.push_str(&crate::cimco::header(post));
        self.out.push_str("//\n");
        self.out.push_str(FUSION_NOTE);
        self.out.push('\n');
        let name =
            if post.info.name.is_empty() { crate::source_name(post).to_string() } else { post.info.name.clone() };
        let mut extension = post.info.file_extension.clone();
        if extension.is_empty() {
            extension = "nc".into();
        }
        self.out.push_str(&fusion_settings(&name, "Vectric", &extension));
        self.out.push('\n');
        // A Windows-1252 post's text is written in that code page, as
        // Vectric writes the post's own bytes.
        if post.info.text_encoding == TextEncoding::Windows1252 {
            self.out.push_str(
                "// The source's text is Windows-1252: the program is written in it.\nsetCodePage(\"ansi\");\n\n",
            );
        }
        // Lines end with the source's LINE_ENDING: Fusion's own is CR LF.
        let le = &post.options.line_ending;
        if le.as_slice() != b"\r\n"
            && let Ok(text) = std::str::from_utf8(le)
        {
            self.out.push_str(&format!(
                "// Each line ends with the source's LINE_ENDING.\nsetEOL({});\n\n",
                js_string(text)
            ));
        }
        // The home position and the origin offsets, which Fusion hands no
        // post: the user sets them in the post dialog, as for Autodesk's
        // posts' home positions.
        let homes: Vec<String> = DIALOG_PROPERTIES
            .iter()
            .filter(|(q, ..)| self.prints(*q))
            .map(|(q, name, _, group, title, what)| {
                format!(
                    "  {name}: {{\n    title: {},\n    description: {},\n    group: \"{group}\",\n    type: \"number\",\n    value: 0,\n    scope: \"post\"\n  }}",
                    js_string(title),
                    js_string(&format!(
                        "{what}, in the program's units ({}): what [{}] prints.",
                        post.info.units.map_or("the document's", |u| u.name()),
                        q.label()
                    )),
                )
            })
            .collect();
        let mut properties = homes;
        if self.wrap_diameter_property() {
            properties.push(format!(
                "  {WRAP_PROPERTY}: {{\n    title: \"Wrap diameter\",\n    description: {},\n    group: \"rotary\",\n    type: \"number\",\n    value: 0,\n    scope: \"post\"\n  }}",
                js_string(&format!(
                    "The diameter of the cylinder the toolpath is wrapped around, in the program's units ({}): {}",
                    post.info.units.map_or("the document's", |u| u.name()),
                    match post.options.rotary_wrap {
                        Some(w) => format!(
                            "{} prints the angle that unrolls its distance on it, and is printed as a length while this is 0.",
                            if w.axis == WrappedAxis::X { "X" } else { "Y" }
                        ),
                        None => "what [WRAP_DIA] prints.".into(),
                    }
                )),
            ));
        }
        if !properties.is_empty() {
            self.out.push_str(&format!(
                "// The job's values Fusion does not hand a post (home position, origin\n// offsets, wrap diameter): set them in the post dialog.\nproperties = {{\n{}\n}};\n\n",
                properties.join(",\n")
            ));
        }
    }

    /// Whether the converted post declares the wrap diameter property: a
    /// post that wraps an axis, or prints `[WRAP_DIA]` (Fusion).
    fn wrap_diameter_property(&self) -> bool {
        self.host == Host::Fusion && (self.post.options.rotary_wrap.is_some() || self.prints(Quantity::WrapDiameter))
    }

    /// What the printed post prints for a quantity: what the engine hands
    /// ([`handed`]), under ROTARY_WRAP (Fusion) the wrapped axis and `[A]`
    /// as the angle that unrolls the distance (`wrapAngle`).
    fn printed(&self, q: Quantity) -> Option<String> {
        if self.host == Host::Fusion {
            if let Some(w) = self.post.options.rotary_wrap {
                let axis = if w.axis == WrappedAxis::X { "x" } else { "y" };
                if q == Quantity::A {
                    return Some(format!("wrapAngle({axis})"));
                }
                if w.wraps(q) {
                    return handed(q, self.host).map(|v| format!("wrapAngle({v})"));
                }
            }
            if q == Quantity::WrapDiameter && self.wrap_diameter_property() {
                return Some("wrapDiameter".into());
            }
        }
        handed(q, self.host).map(str::to_string)
    }

    /// Whether a section the engine calls prints a quantity.
    fn prints(&self, q: Quantity) -> bool {
        let post = self.post;
        post.handlers.iter().any(|h| {
            matches!(h.key, HandlerKey::Section(s) if self.called().iter().any(|(c, _)| *c == s))
                && h.body.iter().any(|st| {
                    matches!(st, Stmt::Line { pieces, .. } if pieces.iter().any(|p| matches!(p, Piece::Var(v)
                        if post.variables[v.index()].source == ValueSource::Quantity(q))))
                })
        })
    }

    fn variables(&mut self) {
        let post = self.post;
        let mut taken: Vec<String> = Vec::new();
        self.out.push_str(LIBRARY);
        self.out.push('\n');
        if self.host == Host::Fusion {
            let subs: Vec<String> = post
                .options
                .substitutions
                .iter()
                .map(|s| {
                    format!(
                        "[{}, {}]",
                        js_string(&String::from_utf8_lossy(&s.from)),
                        js_string(&String::from_utf8_lossy(&s.to))
                    )
                })
                .collect();
            self.out.push_str(&format!(
                "// The source's SUBSTITUTE pairs, applied to the text a text word prints.\nvar substitutions = [{}];\n\n",
                subs.join(", ")
            ));
            self.out.push_str(TEXT_WORD);
            self.out.push('\n');
        }
        for (id, v) in post.variables.iter().enumerate() {
            let label = match v.source {
                ValueSource::Quantity(q) => q.label().to_string(),
                _ => format!("v{id}"),
            };
            let wanted = if is_identifier(&v.name) { v.name.clone() } else { format!("v_{label}") };
            let mut name = wanted.clone();
            let mut n = 1;
            while taken.contains(&name) || !is_identifier(&name) {
                n += 1;
                name = format!("{wanted}_{n}");
            }
            taken.push(name.clone());
            // Under ROTARY_WRAP the wrapped axis prints with the rotary letter.
            let prefix = match (self.host, post.options.rotary_wrap) {
                (Host::Fusion, Some(w)) => self.decode(&w.prefix(v)),
                _ => self.decode(&v.prefix),
            }
            .unwrap_or_default();
            let format = post.formats.get(v.format.index()).cloned().unwrap_or_default();
            self.out.push_str(&crate::cimco::comment(post, &CommentTarget::Variable(postc_ir::VarId::new(id as u16))));
            self.out.push_str(&format!(
                "var {name} = createWord({}, {}, {}, {});\n",
                js_string(&prefix),
                v.modality == Modality::OnChange,
                post.options.on_change_by_value,
                format_object(&format)
            ));
            self.names.push(name);
        }
        self.out.push('\n');
    }

    fn state(&mut self) {
        let o = &self.post.options;
        let b = o.block_numbers;
        // Arcs are cut into chords within the tolerance in the output's
        // units (the runtime's: `arc_tolerance` is in mm).
        let tolerance = match self.post.info.units {
            Some(Units::Inch) => o.arc_tolerance * Units::Inch.factor_to(Units::Mm).recip(),
            _ => o.arc_tolerance,
        };
        let feed_words: Vec<String> = if o.rapid_forgets_feed {
            self.post
                .variables
                .iter()
                .zip(&self.names)
                .filter(|(v, _)| v.source == ValueSource::Quantity(Quantity::Feed))
                .map(|(_, n)| format!("{n}.last = null;\n    {n}.lastValue = NaN;"))
                .collect()
        } else {
            Vec::new()
        };
        self.out.push_str(&format!(
            r#"// The machine as the moves handed so far leave it. Vectric's modal
// memory starts afresh with the program, as each of its toolpaths does.
var x = NaN, y = NaN, z = NaN;
var feed = NaN;
var arcI = NaN, arcJ = NaN, arcK = NaN, arcIA = NaN, arcJA = NaN, arcKA = NaN, arcRadius = NaN, arcAngle = NaN;
var arcStartX = NaN, arcStartY = NaN, arcMidX = NaN, arcMidY = NaN, arcMidXI = NaN, arcMidYI = NaN;
// FIRST_ sections print the first move of a run of one kind and again
// when the feed changes: the kind and feed of the last move printed.
var lastKind = "";
var lastFeed = NaN;
var firstRapid = true;
var blockNumber = {start};
var chordTolerance = {tolerance};

function nextBlock() {{
    blockNumber += {increment};
    if (blockNumber > {maximum}) {{
        blockNumber = {start};
    }}
}}

// After a rapid the feed words print again (the source's feed variables).
function afterRapid() {{
    {forget}
}}

"#,
            start = number(b.start),
            increment = number(b.increment),
            maximum = number(b.maximum),
            tolerance = number(tolerance),
            forget = feed_words.join("\n    "),
        ));
    }

    fn section_functions(&mut self) {
        let post = self.post;
        for &(section, _) in self.called() {
            let Some(h) = post.handlers.iter().find(|h| h.key == HandlerKey::Section(section)) else { continue };
            self.out.push_str(&crate::cimco::comment(post, &CommentTarget::Handler(h.key.clone())));
            // A CNC-Calc section returns its lines; a Fusion one writes them.
            let (open, close) = match self.host {
                Host::Cimco => ("    var out = \"\";\n", "    return out;\n}\n\n"),
                Host::Fusion => ("", "    return \"\";\n}\n\n"),
            };
            self.out.push_str(&format!("function {}() {{\n{open}", section_function(section)));
            for s in &h.body {
                let Stmt::Line { pieces, .. } = s else { continue };
                let mut parts: Vec<String> = Vec::new();
                let mut numbered = false;
                // The values the line prints, and whether it prints the
                // position of a move (which every move has).
                let mut values: Vec<String> = Vec::new();
                let mut position = false;
                for p in pieces {
                    match p {
                        Piece::Text(bytes) => parts.push(js_string(&self.decode(bytes).unwrap_or_default())),
                        Piece::Var(v) => {
                            let var = &post.variables[v.index()];
                            let ValueSource::Quantity(q) = var.source else { continue };
                            let Some(value) = self.printed(q) else { continue };
                            numbered |= q == Quantity::BlockNumber;
                            // In a move section X, Y and Z are the move's
                            // position (the runtime's `is_move_section`).
                            let moves =
                                (Section::InitialRapidMove..=Section::CcwHelicalArcPlungeMove).contains(&section);
                            let wrapped_a = q == Quantity::A && post.options.rotary_wrap.is_some();
                            if (matches!(q, Quantity::X | Quantity::Y | Quantity::Z) || wrapped_a) && moves {
                                position = true;
                            } else if q != Quantity::BlockNumber {
                                values.push(value.clone());
                            }
                            let word = if q.is_text() { "textWord" } else { "word" };
                            parts.push(format!("{word}({}, {value})", self.names[v.index()]));
                        }
                        _ => {}
                    }
                }
                // A line every value of which the job does not give (no
                // number, an empty text) is left out, its block number
                // unused, as Vectric's runtime leaves it out
                // (docs/vectric.md, decision 51).
                if self.host == Host::Fusion && !position && !values.is_empty() {
                    self.out.push_str(&format!(
                        "    var line = {};\n    if (!allMissing([{}])) {{\n        writeln(line);\n{}    }}\n",
                        parts.join(" + "),
                        values.join(", "),
                        if numbered { "        nextBlock();\n" } else { "" }
                    ));
                    continue;
                }
                match self.host {
                    Host::Cimco => {
                        parts.push("\"\\n\"".into());
                        self.out.push_str(&format!("    out += {};\n", parts.join(" + ")));
                    }
                    // Fusion writes each line itself, ending it with its EOL.
                    Host::Fusion => {
                        if parts.is_empty() {
                            parts.push("\"\"".into());
                        }
                        self.out.push_str(&format!("    writeln({});\n", parts.join(" + ")));
                    }
                }
                if numbered {
                    self.out.push_str("    nextBlock();\n");
                }
            }
            self.out.push_str(close);
        }
    }

    /// Fusion's entry points: the section's tool and operation kept at
    /// `onSection`, which prints the program's head at the first section,
    /// TOOLCHANGE at a new tool and NEW_SEGMENT at every later section, as
    /// Vectric does at each toolpath; the moves through the shared rules.
    fn fusion_entry_points(&self, arcs: &str) -> String {
        let call = |s: Section| {
            if self.has(s) { format!("{}();\n        ", section_function(s)) } else { String::new() }
        };
        // SPINDLE_ON after the head or a tool change, indented `pad`.
        let spindle_on = |pad: &str| {
            if self.has(Section::SpindleOn) {
                format!("if (spindle > 0) {{\n{pad}    {}();\n{pad}}}\n{pad}", section_function(Section::SpindleOn))
            } else {
                String::new()
            }
        };
        let head = format!("{}{}{}", call(Section::RevisionComment), call(Section::Header), spindle_on("        "));
        let tool_change = match call(Section::ToolChange) {
            t if t.is_empty() => spindle_on("            "),
            t => format!("{t}    {}", spindle_on("            ")),
        };
        let new_segment = call(Section::NewSegment);
        let new_segment = match new_segment.trim_end() {
            "" => String::new(),
            call => format!("\n        {call}"),
        };
        let (words, forget) = if self.post.options.forget_modal_at_toolpath_start {
            (
                format!(
                    "\n// The words whose modal memory Vectric clears at each toolpath start.\nvar words = [{}];\n",
                    self.names.join(", ")
                ),
                "for (var i = 0; i < words.length; i++) {\n        words[i].last = null;\n        words[i].lastValue = NaN;\n    }\n    ",
            )
        } else {
            (String::new(), "")
        };
        let spindle_speed = if self.has(Section::SpindleOn) {
            format!(
                "\n// A new spindle speed within a section prints SPINDLE_ON again.\nfunction onSpindleSpeed(speed) {{\n    spindle = speed;\n    {}();\n}}\n",
                section_function(Section::SpindleOn)
            )
        } else {
            String::new()
        };
        let dwell = if self.has(Section::DwellMove) {
            format!(
                "\nfunction onDwell(seconds) {{\n    dwellTime = seconds;\n    {}();\n}}\n",
                section_function(Section::DwellMove)
            )
        } else {
            String::new()
        };
        let footer = if self.has(Section::Footer) {
            format!("{}();\n", section_function(Section::Footer))
        } else {
            String::new()
        };
        let steps = match self.post.options.spindle_speed_range {
            Some(r) if r.rpm_max > r.rpm_min => format!(
                "var t = Math.min(Math.max((rpm - {rmin}) / ({rmax} - {rmin}), 0), 1);\n    var v = {omin} + t * ({omax} - {omin});\n    return v < 0 ? -Math.floor(-v + 0.5) : Math.floor(v + 0.5);",
                rmin = number(r.rpm_min),
                rmax = number(r.rpm_max),
                omin = number(r.out_min),
                omax = number(r.out_max),
            ),
            _ => "return rpm;".into(),
        };
        // The home position and the origin offsets from the post's
        // properties, in the program's units.
        let homes: String = DIALOG_PROPERTIES
            .iter()
            .filter(|(q, ..)| self.prints(*q))
            .map(|(_, name, var, ..)| format!("{var} = getProperty(\"{name}\");\n    "))
            .collect();
        // The wrap diameter the user set (0: none), and the angle that
        // unrolls a distance on it, as the runtime computes it
        // (`MachineState::wrap_angle`).
        let mut homes = homes;
        let mut wrap = String::new();
        if self.wrap_diameter_property() {
            homes.push_str(&format!(
                "wrapDiameter = getProperty(\"{WRAP_PROPERTY}\") > 0 ? getProperty(\"{WRAP_PROPERTY}\") : NaN;\n    "
            ));
            wrap.push_str(
                "// The wrap diameter the user set in the post dialog (none while 0).\nvar wrapDiameter = NaN;\n",
            );
        }
        if let Some(w) = self.post.options.rotary_wrap {
            wrap.push_str(&format!(
                "\n// ROTARY_WRAP: the degrees of rotation that unroll a distance on the wrap\n// cylinder; the distance itself while no wrap diameter is set.\nfunction wrapAngle(distance) {{\n    if (!(wrapDiameter > 0)) {{\n        return distance;\n    }}\n    var angle = distance / (Math.PI * wrapDiameter) * 360;\n    return {};\n}}\n",
                if w.reversed { "-angle" } else { "angle" }
            ));
        }
        // The job's texts the post prints, made in `onOpen`.
        let mut text_vars = String::new();
        let mut text_set = String::new();
        let mut made: Vec<&str> = Vec::new();
        for &(q, name, code) in JOB_TEXTS.iter().filter(|(q, ..)| self.prints(*q)) {
            if made.contains(&name) {
                continue;
            }
            made.push(name);
            text_vars.push_str(&format!("var {name} = \"\";\n"));
            let code = match q {
                // The program's units: the source's UNITS, else the document's.
                Quantity::UnitsText => match self.post.info.units {
                    Some(u) => format!("{name} = {};", js_string(u.name())),
                    None => format!(
                        "{name} = unit == MM ? {} : {};",
                        js_string(Units::Mm.name()),
                        js_string(Units::Inch.name())
                    ),
                },
                // The source post's revision, a text of the post itself.
                Quantity::Revision => format!("{name} = {};", js_string(&self.post.info.revision)),
                _ => code.to_string(),
            };
            text_set.push_str(&format!("{code}\n    "));
        }
        let text_functions = if [Quantity::Date, Quantity::Time, Quantity::XyOriginText, Quantity::ZOriginText]
            .into_iter()
            .any(|q| self.prints(q))
        {
            format!("\n{JOB_TEXT_FUNCTIONS}")
        } else {
            String::new()
        };
        if !text_vars.is_empty() {
            text_vars.insert_str(0, "// The job's texts, made from what Fusion hands at onOpen.\n");
        }
        // The runtime's factors (`Units::factor_to`), as JavaScript computes them.
        let scale = match self.post.info.units {
            Some(Units::Mm) => "scale = unit == MM ? 1 : 25.4;",
            Some(Units::Inch) => "scale = unit == MM ? 1 / 25.4 : 1;",
            None => "scale = 1;",
        };
        format!(
            r#"// The section's tool and operation as Fusion hands them, and the job's stock.
var toolNumber = NaN;
var toolDiameter = NaN;
var spindle = NaN;
var dwellTime = NaN;
var toolName = "";
var toolNotes = "";
var toolpathName = "";
var toolpathNotes = "";
var lastTool = NaN;
var previousTool = NaN;
var stockLower = {{x: NaN, y: NaN, z: NaN}};
var stockUpper = {{x: NaN, y: NaN, z: NaN}};
// The operation's tool feeds and clearance height, and the home position
// and origin offsets the user set in the post's properties.
var toolFeedCut = NaN;
var toolFeedPlunge = NaN;
var safeZ = NaN;
var homeX = NaN, homeY = NaN, homeZ = NaN;
var originX = NaN, originY = NaN;
{wrap}{text_vars}{words}
// Fusion hands lengths and feeds in the document's units; the post
// prints them in its source's UNITS, each multiplied by `scale`.
var scale = 1;
{text_functions}
function onOpen() {{
    {scale}
    {homes}{text_set}if (isWorkpieceDefined()) {{
        var stock = getWorkpiece();
        stockLower = {{x: stock.lower.x * scale, y: stock.lower.y * scale, z: stock.lower.z * scale}};
        stockUpper = {{x: stock.upper.x * scale, y: stock.upper.y * scale, z: stock.upper.z * scale}};
    }}
}}

// Each toolpath is a section: the first prints the program's head, a
// new tool TOOLCHANGE, each later section NEW_SEGMENT; then Vectric's
// modal memory starts afresh.
function onSection() {{
    toolNumber = tool.number;
    // The tool before a new one ([TP]): none until a second tool comes.
    if (toolNumber != lastTool && lastTool === lastTool) {{
        previousTool = lastTool;
    }}
    toolDiameter = tool.diameter * scale;
    toolName = tool.description;
    toolNotes = tool.comment;
    toolpathName = getParameter("operation-comment", "");
    toolpathNotes = getParameter("notes", "");
    toolFeedCut = hasParameter("operation:tool_feedCutting") ? getParameter("operation:tool_feedCutting") * scale : NaN;
    toolFeedPlunge = hasParameter("operation:tool_feedPlunge") ? getParameter("operation:tool_feedPlunge") * scale : NaN;
    safeZ = hasParameter("operation:clearanceHeight_value") ? getParameter("operation:clearanceHeight_value") * scale : NaN;
    spindle = spindleSpeed;
    // A new tool's feed is its cut feed until a feed move gives another,
    // as Vectric's is.
    if (toolNumber != lastTool) {{
        feed = toolFeedCut;
    }}
    if (isFirstSection()) {{
        {head}firstRapid = true;
    }} else {{
        if (toolNumber != lastTool) {{
            {tool_change}firstRapid = true;
        }}{new_segment}
    }}
    lastTool = toolNumber;
    {forget}lastKind = "";
    lastFeed = NaN;
}}

// The spindle speed as the post prints it: the rpm, or its step of
// SPINDLE_SPEED_RANGE (rounded half away from zero).
function spindleOutput(rpm) {{
    {steps}
}}
{spindle_speed}
function onRapid(vx, vy, vz) {{
    rapidTo(vx * scale, vy * scale, vz * scale);
}}

// A feed move; a move straight down is a plunge, as Vectric reads it.
function onLinear(vx, vy, vz, f) {{
    vx *= scale;
    vy *= scale;
    vz *= scale;
    feedTo(vx, vy, vz, movement == MOVEMENT_PLUNGE || (vx == x && vy == y && vz < z), f * scale);
}}

// Fusion hands every arc whole (the settings above): the post prints an
// arc in XY through its section or cuts it into chords, and cuts arcs in
// other planes into chords, as Vectric does.
function onCircular(isCW, cx, cy, cz, ex, ey, ez, f) {{
    cx *= scale;
    cy *= scale;
    cz *= scale;
    ex *= scale;
    ey *= scale;
    ez *= scale;
    f *= scale;
    // A helix the toolpath marks as plunging: Fusion's helical ramp.
    var plunging = movement == MOVEMENT_RAMP_HELIX;
    if (getCircularPlane() != PLANE_XY) {{
        planeChords(getCircularPlane() == PLANE_ZX ? [2, 0, 1] : [1, 2, 0], [cx, cy, cz], [ex, ey, ez], isCW, f, plunging);
        return;
    }}
    var helical = Math.abs(ez - z) > 1e-9;
    {arcs}
}}

// An arc in the plane of the axes (u, v) about w, from the last end point
// to e around c, cut into equal-angle chords within the chord tolerance;
// plunge moves when the arc plunges.
function planeChords(axes, c, e, isCW, f, plunge) {{
    var u = axes[0], v = axes[1], w = axes[2];
    var s = [x, y, z];
    var r = distance(s[u] - c[u], s[v] - c[v]);
    var a0 = Math.atan2(s[v] - c[v], s[u] - c[u]);
    var a1 = Math.atan2(e[v] - c[v], e[u] - c[u]);
    var TAU = 2 * Math.PI;
    var closed = distance(e[u] - s[u], e[v] - s[v]) <= 1e-9 * Math.max(r, 1);
    var turn = closed ? TAU : remainder(isCW ? a0 - a1 : a1 - a0, TAU);
    if (turn <= 1e-12) {{
        turn = TAU;
    }}
    var sweep = isCW ? -turn : turn;
    var n = 1;
    if (r > 0 && r < Infinity) {{
        var ratio = Math.min(Math.max(chordTolerance / r, 0), 1);
        var step = 2 * Math.acos(1 - ratio);
        n = step <= 0 ? 1000000 : Math.min(Math.max(Math.ceil(Math.abs(sweep) / step), 1), 1000000);
    }}
    n = Math.min(n, 10000);
    for (var i = 1; i <= n; i++) {{
        var t = i / n;
        if (t >= 1) {{
            feedTo(e[0], e[1], e[2], plunge, f);
        }} else {{
            var a = a0 + sweep * t;
            var p = [0, 0, 0];
            p[u] = c[u] + r * Math.cos(a);
            p[v] = c[v] + r * Math.sin(a);
            p[w] = s[w] + (e[w] - s[w]) * t;
            feedTo(p[0], p[1], p[2], plunge, f);
        }}
    }}
}}

// Fusion expands each hole into moves (expandCyclePoint, the moves
// Vectric makes of a hole); the tool's place over the first hole, where
// the section starts, comes with no move, so the post moves there first.
function onCyclePoint(px, py, pz) {{
    var p = getCurrentPosition();
    if (p.x * scale !== x || p.y * scale !== y || p.z * scale !== z) {{
        rapidTo(p.x * scale, p.y * scale, p.z * scale);
    }}
    expandCyclePoint(px, py, pz);
}}
{dwell}
function onClose() {{
    {footer}}}
"#
        )
    }

    /// The JavaScript expression of the section Vectric prints: the
    /// `FIRST_` one when `first` holds and it exists, else the plain one,
    /// else the `FIRST_` one; `None` when the post has neither.
    fn pick(&self, first: Section, plain: Section, cond: &str) -> Option<String> {
        match (self.has(first), self.has(plain)) {
            (true, true) => Some(format!("({cond} ? {} : {})", section_function(first), section_function(plain))),
            (true, false) => Some(section_function(first)),
            (false, true) => Some(section_function(plain)),
            (false, false) => None,
        }
    }

    /// Whether a section prints `[Z]`.
    fn prints_z(&self, s: Section) -> bool {
        self.post.handlers.iter().filter(|h| h.key == HandlerKey::Section(s)).any(|h| {
            h.body.iter().any(|st| {
                matches!(st, Stmt::Line { pieces, .. } if pieces.iter().any(|p| matches!(p, Piece::Var(v)
                    if self.post.variables[v.index()].source == ValueSource::Quantity(Quantity::Z))))
            })
        })
    }

    fn entry_points(&mut self) {
        let call = |s: Section, this: &Self| {
            if this.has(s) { format!("out += {}();\n    ", section_function(s)) } else { String::new() }
        };
        // onOpen: REVISION_COMMENT, HEADER, SPINDLE_ON.
        let open = format!(
            "{}{}{}",
            call(Section::RevisionComment, self),
            call(Section::Header, self),
            call(Section::SpindleOn, self)
        );
        // FEED_RATE_CHANGE before a move whose feed changed, when the post has it.
        let rate_change = match call(Section::FeedRateChange, self) {
            c if c.is_empty() => String::new(),
            c => format!("if (lastFeed !== f) {{\n        {}\n    }}\n    ", c.trim_end()),
        };
        // Rapids.
        let mut rapid = String::new();
        let plain_rapid = if self.has(Section::RapidMove) {
            format!("{}()", section_function(Section::RapidMove))
        } else {
            "\"\"".into()
        };
        let retract_rapid = if self.has(Section::RetractMove) {
            format!("(retract ? {}() : {plain_rapid})", section_function(Section::RetractMove))
        } else {
            plain_rapid
        };
        if self.has(Section::InitialRapidMove) {
            rapid.push_str(&format!(
                "out += firstRapid ? {}() : {retract_rapid};",
                section_function(Section::InitialRapidMove)
            ));
        } else {
            rapid.push_str(&format!("out += {retract_rapid};"));
        }
        // Feed moves.
        let mut feeds = String::new();
        if self.has(Section::FirstPlungeMove) {
            feeds.push_str(&format!(
                "if (kind == \"plunge\" && (lastKind != \"plunge\" || lastFeed !== f)) {{\n        return feedSection(\"plunge\", f, {});\n    }}\n    ",
                section_function(Section::FirstPlungeMove)
            ));
        }
        if self.has(Section::PlungeMove) {
            feeds.push_str(&format!(
                "if (kind == \"plunge\") {{\n        return feedSection(\"plunge\", f, {});\n    }}\n    ",
                section_function(Section::PlungeMove)
            ));
        }
        if self.has(Section::RetractMove) {
            feeds.push_str(&format!(
                "if (kind == \"retract\") {{\n        return feedSection(\"retract\", f, {});\n    }}\n    ",
                section_function(Section::RetractMove)
            ));
        }
        let feed_section = self
            .pick(Section::FirstFeedMove, Section::FeedMove, "(lastKind != \"feed\" || lastFeed !== f)")
            .unwrap_or_else(|| "null".into());
        feeds.push_str(&format!("return feedSection(\"feed\", f, {feed_section});"));
        // Arcs, each direction.
        let mut arcs = String::new();
        for (cw, flat, helical) in [
            (
                true,
                (Section::FirstCwArcMove, Section::CwArcMove),
                (Section::FirstCwHelicalArcMove, Section::CwHelicalArcMove),
            ),
            (
                false,
                (Section::FirstCcwArcMove, Section::CcwArcMove),
                (Section::FirstCcwHelicalArcMove, Section::CcwHelicalArcMove),
            ),
        ] {
            let dir = if cw { "cw" } else { "ccw" };
            let mut body = String::new();
            // A helix the toolpath marks as plunging (Fusion's helical ramp)
            // prints through the helical plunge sections where the post has them.
            let plunge_kind = format!("{dir} plunge helix");
            let (plunge_first, plunge_plain) = if cw {
                (Section::FirstCwHelicalArcPlungeMove, Section::CwHelicalArcPlungeMove)
            } else {
                (Section::FirstCcwHelicalArcPlungeMove, Section::CcwHelicalArcPlungeMove)
            };
            if let Some(s) =
                self.pick(plunge_first, plunge_plain, &format!("(lastKind != \"{plunge_kind}\" || lastFeed !== f)"))
            {
                body.push_str(&format!(
                    "if (helical && plunging) {{\n            return arcSection(\"{plunge_kind}\", f, {s}, cx, cy, ex, ey, ez, isCW);\n        }}\n        "
                ));
            }
            let helix_kind = format!("{dir} helix");
            if let Some(s) =
                self.pick(helical.0, helical.1, &format!("(lastKind != \"{helix_kind}\" || lastFeed !== f)"))
            {
                body.push_str(&format!(
                    "if (helical) {{\n            return arcSection(\"{helix_kind}\", f, {s}, cx, cy, ex, ey, ez, isCW);\n        }}\n        "
                ));
            }
            if let Some(s) = self.pick(flat.0, flat.1, &format!("(lastKind != \"{dir}\" || lastFeed !== f)")) {
                // A helix prints through the arc section only when the
                // section that would print it prints [Z].
                let first_z = self.has(flat.0) && self.prints_z(flat.0);
                let plain_z = self.has(flat.1) && self.prints_z(flat.1);
                let helix_ok = match (self.has(flat.0), self.has(flat.1)) {
                    (true, true) => match (first_z, plain_z) {
                        (true, true) => "true".to_string(),
                        (false, false) => "false".to_string(),
                        (true, false) => format!("(lastKind != \"{dir}\" || lastFeed !== f)"),
                        (false, true) => format!("!(lastKind != \"{dir}\" || lastFeed !== f)"),
                    },
                    (true, false) => first_z.to_string(),
                    _ => plain_z.to_string(),
                };
                let call = format!("return arcSection(\"{dir}\", f, {s}, cx, cy, ex, ey, ez, isCW);");
                match helix_ok.as_str() {
                    // Every arc, flat or helical, prints through the section.
                    "true" => {
                        body.push_str(&call);
                        arcs.push_str(&format!(
                            "if ({}isCW) {{\n        {body}\n    }}\n    ",
                            if cw { "" } else { "!" }
                        ));
                        continue;
                    }
                    "false" => body.push_str(&format!("if (!helical) {{\n            {call}\n        }}\n        ")),
                    _ => body
                        .push_str(&format!("if (!helical || {helix_ok}) {{\n            {call}\n        }}\n        ")),
                }
            }
            body.push_str("return chords(cx, cy, ex, ey, ez, isCW, f, plunging);");
            arcs.push_str(&format!("if ({}isCW) {{\n        {body}\n    }}\n    ", if cw { "" } else { "!" }));
        }
        // Under ROTARY_WRAP (Fusion) every arc is cut into feed moves: one of
        // its axes turns the rotary axis, which a G2/G3 cannot (docs/vectric.md,
        // decision 42).
        let arcs = if self.host == Host::Fusion && self.post.options.rotary_wrap.is_some() {
            "return chords(cx, cy, ex, ey, ez, isCW, f, plunging);"
        } else {
            arcs.trim_end()
        };
        let footer = call(Section::Footer, self);
        let open = format!(
            r#"function onOpen(isClipboard) {{
    var out = "";
    {open}firstRapid = true;
    return out;
}}

"#
        );
        let feed_section = format!(
            r#"// A feed (or plunge, or retract) section: FEED_RATE_CHANGE first when the
// feed changed, then the section; the run's kind and feed are kept.
function feedSection(kind, f, section) {{
    var out = "";
    // A feed of zero is none: [F] prints nothing.
    feed = f == 0 ? NaN : f;
    {rate_change}lastKind = kind;
    lastFeed = f;
    if (section != null) {{
        out += section();
    }}
    return out;
}}

"#
        );
        let feed_of = r#"// The feed getFeedrate gives for a movement, as a number (it returns the
// word, "F" and the number).
function feedOf(movement) {
    return parseFloat(getFeedrate(movement).substring(1));
}

"#;
        let moves = format!(
            r#"// A straight feed move to (vx, vy, vz): a plunge when the engine says so,
// a retract when it rises straight up, otherwise a feed.
function feedTo(vx, vy, vz, plunge, f) {{
    var kind = "feed";
    if (plunge) {{
        kind = "plunge";
    }} else if (vx == x && vy == y && vz > z) {{
        kind = "retract";
    }}
    x = vx;
    y = vy;
    z = vz;
    {feeds}
}}

// A rapid to (vx, vy, vz): INITIAL_RAPID_MOVE first, RETRACT_MOVE straight up.
function rapidTo(vx, vy, vz) {{
    var out = "";
    var retract = vx == x && vy == y && vz > z;
    x = vx;
    y = vy;
    z = vz;
    {rapid}
    firstRapid = false;
    lastKind = "rapid";
    afterRapid();
    return out;
}}

"#
        );
        let linear_drilling = r#"function onLinear(vx, vy, vz, movement) {
    if (movement == MOVEMENT_RAPID) {
        return rapidTo(vx, vy, vz);
    }
    return feedTo(vx, vy, vz, movement == MOVEMENT_PLUNGE, feedOf(movement));
}

// The drilling operations the post offers. Vectric posts have no cycle
// sections: each hole is drilled with moves, as Vectric drills it (rapid
// to the retract plane and the safe distance, feed down, in pecks for
// peck drilling and chip breaking, rapid back to the retract plane).
var MillDrillingFields = [
    {name: "Drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false, firstDepth: false, degressionType: false, degression: false, peckingRetract: false, minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false, pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false, firstDepth: true, degressionType: false, degression: false, peckingRetract: false, minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false, pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Chip breaking", isLonghand: true, plungingFeedrate: true, retractFeedrate: false, firstDepth: true, degressionType: false, degression: false, peckingRetract: false, minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false, pitch: false, tappingSpeed: false, retractSpeed: false}
];
var drilling = null;

function onDrillingHeader(drillHeader) {
    drilling = drillHeader;
    return "";
}

function onDrillingPoint(px, py) {
    var h = drilling;
    var clear = h.retractPlane;
    var reference = h.safeDistanceIsAbsolute ? h.safeDistance : h.referencePlane + h.safeDistance;
    var depth = h.endDepthIsAbsolute ? h.endDepth : h.referencePlane - h.endDepth;
    var f = h.plungingFeedrate;
    var pecking = h.name == "Peck drilling" || h.name == "Chip breaking";
    var peck = pecking && h.firstDepth > 0 ? h.firstDepth : 0;
    if (peck > 0 && (reference - depth) / peck > 1000) {
        peck = (reference - depth) / 1000;
    }
    var out = "";
    if (z < clear) {
        out += rapidTo(x, y, clear);
    }
    out += rapidTo(px, py, clear);
    if (reference < clear) {
        out += rapidTo(px, py, reference);
    }
    if (peck > 0) {
        var at = reference;
        while (at - depth > 1e-9) {
            at = Math.max(at - peck, depth);
            out += feedTo(px, py, at, true, f);
            if (at > depth) {
                out += rapidTo(px, py, h.name == "Peck drilling" ? reference : at + 0.5 * peck);
                out += rapidTo(px, py, at);
            }
        }
    } else {
        out += feedTo(px, py, depth, true, f);
    }
    return out + rapidTo(px, py, clear);
}

function onDrillingFooter() {
    drilling = null;
    return "";
}

"#;
        let arc_library = r#"// An arc through its section: the arc words from the centre, the start
// (the last end point) and the sweep.
function arcSection(kind, f, section, cx, cy, ex, ey, ez, isCW) {
    var g = arcGeometry(cx, cy, ex, ey, isCW);
    arcI = cx - x;
    arcJ = cy - y;
    arcK = 0;
    arcIA = cx;
    arcJA = cy;
    arcKA = z;
    arcRadius = g.r;
    arcAngle = g.sweep;
    arcStartX = x;
    arcStartY = y;
    arcMidX = cx + g.r * Math.cos(g.a0 + g.sweep * 0.5);
    arcMidY = cy + g.r * Math.sin(g.a0 + g.sweep * 0.5);
    arcMidXI = arcMidX - x;
    arcMidYI = arcMidY - y;
    x = ex;
    y = ey;
    z = ez;
    return feedSection(kind, f, section);
}

// An arc the post has no section for, cut into equal-angle chords within
// the chord tolerance, each a feed move (a plunge move when the arc plunges).
function chords(cx, cy, ex, ey, ez, isCW, f, plunge) {
    var g = arcGeometry(cx, cy, ex, ey, isCW);
    var sz = z;
    var r = g.r, a0 = g.a0, sweep = g.sweep;
    var n = 1;
    if (r > 0 && r < Infinity) {
        var ratio = Math.min(Math.max(chordTolerance / r, 0), 1);
        var step = 2 * Math.acos(1 - ratio);
        n = step <= 0 ? 1000000 : Math.min(Math.max(Math.ceil(Math.abs(sweep) / step), 1), 1000000);
    }
    n = Math.min(n, 10000);
    var out = "";
    for (var i = 1; i <= n; i++) {
        var t = i / n;
        if (t >= 1) {
            out += feedTo(ex, ey, ez, plunge, f);
        } else {
            var a = a0 + sweep * t;
            out += feedTo(cx + r * Math.cos(a), cy + r * Math.sin(a), sz + (ez - sz) * t, plunge, f);
        }
    }
    return out;
}

// The arc from the last end point to (ex, ey) around (cx, cy): its
// radius, start angle and signed sweep (counter-clockwise positive; a
// closed arc is a full turn).
function arcGeometry(cx, cy, ex, ey, isCW) {
    var TAU = 2 * Math.PI;
    var r = distance(x - cx, y - cy);
    var a0 = Math.atan2(y - cy, x - cx);
    var a1 = Math.atan2(ey - cy, ex - cx);
    var closed = distance(ex - x, ey - y) <= 1e-9 * Math.max(r, 1);
    var turn = closed ? TAU : remainder(isCW ? a0 - a1 : a1 - a0, TAU);
    if (turn <= 1e-12) {
        turn = TAU;
    }
    return {r: r, a0: a0, sweep: isCW ? -turn : turn};
}

// The length of (dx, dy), in ECMAScript 5 (CNC-Calc's JavaScript has no Math.hypot).
function distance(dx, dy) {
    return Math.sqrt(dx * dx + dy * dy);
}

function remainder(a, b) {
    var r = a % b;
    return r < 0 ? r + b : r;
}

"#;
        let circular_close = format!(
            r#"function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {{
    var f = feedOf(movement);
    // CNC-Calc does not say which arcs plunge.
    var plunging = false;
    var helical = Math.abs(ez - z) > 1e-9;
    {arcs}
}}

function onClose() {{
    var out = "";
    {footer}return out;
}}
"#
        );
        let shared = format!("{feed_section}{moves}{arc_library}");
        match self.host {
            Host::Cimco => self.out.push_str(&format!(
                "{open}{feed_section}{feed_of}{moves}{linear_drilling}{arc_library}{circular_close}"
            )),
            Host::Fusion => {
                let _ = (open, feed_of, linear_drilling, circular_close);
                let fusion = self.fusion_entry_points(arcs);
                self.out.push_str(&format!("{shared}{fusion}"));
            }
        }
    }
}

/// Whether a feed format prints finer steps than the tenth getFeedrate
/// hands (in the feed's units, before the multiplier).
fn feed_finer_than_handed(f: &NumberFormat) -> bool {
    let step = 10f64.powi(-i32::from(f.decimals)) / f.multiplier.abs();
    f.multiplier != 0.0 && step < 0.1 - 1e-12
}

/// Why the engine never calls a section.
fn never_called(s: Section, host: Host) -> &'static str {
    if host == Host::Fusion {
        return match s {
            Section::JetToolOn | Section::JetToolOff | Section::JetToolPower => {
                "the converted post is a milling post: jet sections are not yet printed at onPower"
            }
            Section::SpindleOff => "Fusion hands no spindle stop: the spindle stops with the program",
            Section::Coolant => "the converted post does not yet print coolant at onCommand",
            Section::CutterComp => "the converted post does not yet print onRadiusCompensation",
            _ => "Fusion calls no function for it",
        };
    }
    match s {
        Section::ToolChange | Section::NewSegment => {
            "the CNC-Calc manual calls no function at a tool change or at the start of a toolpath: the converted post prints as its source for a job of one toolpath"
        }
        Section::DwellMove => "the CNC-Calc manual has no dwell call: dwells are not written",
        Section::JetToolOn | Section::JetToolOff | Section::JetToolPower => {
            "the CNC-Calc manual has no call for a laser, plasma or water jet"
        }
        Section::SpindleOff | Section::Coolant => "the CNC-Calc manual has no spindle or coolant call",
        Section::CutterComp => "the converted post does not yet print onCompensation",
        _ => "the CNC-Calc manual has no call for it",
    }
}

/// The note under the conversion note: what the engine calls.
const NATIVE_NOTE: &str = "// A CNC-Calc post: CNC-Calc calls onOpen, onLinear, onCircular, the
// onDrilling functions and onClose;
// the Vectric rules of the source (which section prints each move) are
// the state below.
";

/// The job's values Fusion hands no post, which the user sets in the post
/// dialog of a converted `.cps` post: the quantity, the post property it
/// is read from (the home position's are the names of Autodesk's posts'
/// home positions), the post's variable, the property's group and title,
/// and what it is (docs/convert.md, "Fusion posts").
const DIALOG_PROPERTIES: &[(Quantity, &str, &str, &str, &str, &str)] = &[
    (
        Quantity::HomeX,
        "homePositionX",
        "homeX",
        "homePositions",
        "Home position X",
        "The X of the machine's home position",
    ),
    (
        Quantity::HomeY,
        "homePositionY",
        "homeY",
        "homePositions",
        "Home position Y",
        "The Y of the machine's home position",
    ),
    (
        Quantity::HomeZ,
        "homePositionZ",
        "homeZ",
        "homePositions",
        "Home position Z",
        "The Z of the machine's home position",
    ),
    (
        Quantity::XOrigin,
        "originOffsetX",
        "originX",
        "origin",
        "Origin offset X",
        "The X offset of the work origin from the material's datum corner",
    ),
    (
        Quantity::YOrigin,
        "originOffsetY",
        "originY",
        "origin",
        "Origin offset Y",
        "The Y offset of the work origin from the material's datum corner",
    ),
];

/// The job's texts a converted `.cps` post makes in `onOpen` from what
/// Fusion hands it (docs/convert.md, "Fusion posts"): the quantity, the
/// post's variable and the JavaScript that sets it. `[DATE]` and `[TIME]`
/// are Fusion's clock (`new Date()`) in the forms Vectric's runtime
/// prints an instant in (`runtime/src/clock.rs`); the file's name and
/// folder come from `getOutputPath()`; the tools and toolpaths from the
/// sections Fusion hands in advance (`getToolTable()`, as Autodesk's posts
/// list their tools at `onOpen`, and each section's `operation-comment`);
/// the file notes are the program comment; the product is the global
/// parameter `generated-by`; the origin texts say where the
/// stock lies about the work origin (`getWorkpiece()`).
const JOB_TEXTS: &[(Quantity, &str, &str)] = &[
    (
        Quantity::FileName,
        "fileName",
        "var outputName = FileSystem.getFilename(getOutputPath());\n    var dot = outputName.lastIndexOf(\".\");\n    fileName = dot >= 0 ? outputName.substring(0, dot) : outputName;",
    ),
    (Quantity::FileDir, "fileDir", "fileDir = FileSystem.getFolderPath(getOutputPath());"),
    (Quantity::PathName, "fileDir", "fileDir = FileSystem.getFolderPath(getOutputPath());"),
    (Quantity::Date, "jobDate", "jobDate = vectricDate(jobClock());"),
    (Quantity::Time, "jobTime", "jobTime = vectricTime(jobClock());"),
    (
        Quantity::ToolsUsed,
        "toolsUsed",
        "var tools = getToolTable();\n    var toolNames = [];\n    for (var t = 0; t < tools.getNumberOfTools(); t++) {\n        toolNames.push(tools.getTool(t).description);\n    }\n    toolsUsed = toolNames.join(\", \");",
    ),
    (
        Quantity::ToolpathsOutput,
        "toolpathsOutput",
        "var operations = [];\n    for (var s = 0; s < getNumberOfSections(); s++) {\n        operations.push(getSection(s).getParameter(\"operation-comment\", \"\"));\n    }\n    toolpathsOutput = operations.join(\", \");",
    ),
    (Quantity::FileNotes, "fileNotes", "fileNotes = programComment;"),
    (Quantity::Product, "product", "product = getGlobalParameter(\"generated-by\", \"\");"),
    (Quantity::XyOriginText, "xyOrigin", "xyOrigin = isWorkpieceDefined() ? xyOriginOf(getWorkpiece()) : \"\";"),
    (
        Quantity::ZOriginText,
        "zOrigin",
        "zOrigin = isWorkpieceDefined() && !nearZero(getWorkpiece().upper.z, getWorkpiece()) && nearZero(getWorkpiece().lower.z, getWorkpiece()) ? \"Table Surface\" : \"Material Surface\";",
    ),
    (Quantity::UnitsText, "unitsText", ""),
    (Quantity::Revision, "revisionText", ""),
];

/// What the converted post's `onOpen` uses to make the job's texts: the
/// long date VCarve writes and the time as HH:MM (`runtime/src/clock.rs`),
/// and where the stock lies about the work origin.
const JOB_TEXT_FUNCTIONS: &str = r#"// The instant the program is made, read once, so that [DATE] and [TIME]
// are of one instant.
var jobNow = null;
function jobClock() {
    if (jobNow === null) {
        jobNow = new Date();
    }
    return jobNow;
}

// A date as Vectric prints one: "Tuesday, November 15, 2011".
function vectricDate(d) {
    var days = ["Sunday", "Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday"];
    var months = ["January", "February", "March", "April", "May", "June", "July", "August", "September",
        "October", "November", "December"];
    return days[d.getDay()] + ", " + months[d.getMonth()] + " " + d.getDate() + ", " + d.getFullYear();
}

// A time as Vectric prints one: HH:MM.
function vectricTime(d) {
    var two = function (n) { return n < 10 ? "0" + n : "" + n; };
    return two(d.getHours()) + ":" + two(d.getMinutes());
}

// Whether a coordinate of the stock is at the work origin's.
function nearZero(v, stock) {
    var size = Math.max(Math.abs(stock.lower.x), Math.abs(stock.upper.x), Math.abs(stock.lower.y),
        Math.abs(stock.upper.y), Math.abs(stock.lower.z), Math.abs(stock.upper.z), 1);
    return Math.abs(v) <= 1e-9 * size;
}

// Vectric's XY datum ("Bottom Left", ..., "Centre") where the work origin
// is on the stock; "" where it is none of them.
function xyOriginOf(stock) {
    var side = function (lower, upper, low, high) {
        if (nearZero(lower, stock)) {
            return low;
        }
        if (nearZero(upper, stock)) {
            return high;
        }
        return nearZero(lower + upper, stock) ? "centre" : "";
    };
    var x = side(stock.lower.x, stock.upper.x, "Left", "Right");
    var y = side(stock.lower.y, stock.upper.y, "Bottom", "Top");
    if (x == "centre" && y == "centre") {
        return "Centre";
    }
    return x == "" || y == "" || x == "centre" || y == "centre" ? "" : y + " " + x;
}
"#;

/// The settings of a `.cps` post converted from another dialect: what it
/// is, a milling post, and Fusion asked for every arc whole (every plane,
/// helices, no smallest radius, chord or sweep, a full turn the largest
/// sweep), so that the post itself cuts an arc as its source's engine does.
pub(crate) fn fusion_settings(description: &str, vendor: &str, extension: &str) -> String {
    format!(
        r#"description = {description};
vendor = {vendor};
legal = "";
certificationLevel = 2;
minimumRevision = 45702;
extension = {extension};
capabilities = CAPABILITY_MILLING;
tolerance = spatial(0.002, MM);
allowedCircularPlanes = (1 << PLANE_XY) | (1 << PLANE_ZX) | (1 << PLANE_YZ);
allowHelicalMoves = true;
minimumChordLength = 0;
minimumCircularRadius = 0;
maximumCircularRadius = 1e300;
minimumCircularSweep = 0;
maximumCircularSweep = 2 * Math.PI;
"#,
        description = js_string(description),
        vendor = js_string(vendor),
        extension = js_string(extension),
    )
}

/// The note under the conversion note of a `.cps` post.
const FUSION_NOTE: &str = "// An Autodesk Fusion post: Fusion calls onOpen, onSection (each toolpath),
// onRapid, onLinear, onCircular, onDwell and onClose, and expands
// drilling cycles into moves; the Vectric rules of the source (which
// section prints each move) are the state below.
";

/// A text word (`[TOOLNAME]`): the prefix and the text; nothing for a
/// modal word whose text is the one it printed last.
const TEXT_WORD: &str = r#"function substitute(text) {
    var out = "";
    var i = 0;
    while (i < text.length) {
        var done = false;
        for (var k = 0; k < substitutions.length && !done; k++) {
            var from = substitutions[k][0];
            if (from != "" && text.substring(i, i + from.length) == from) {
                out += substitutions[k][1];
                i += from.length;
                done = true;
            }
        }
        if (!done) {
            out += text.charAt(i);
            i++;
        }
    }
    return out;
}

// Whether a line's every value is one the job does not give: no number,
// an empty text.
function allMissing(values) {
    for (var i = 0; i < values.length; i++) {
        var v = values[i];
        if (typeof v == "number" ? v === v : String(v) !== "") {
            return false;
        }
    }
    return true;
}

function textWord(w, value) {
    var text = w.prefix + substitute(String(value));
    if (w.modal && text === w.last) {
        return "";
    }
    w.last = text;
    return text;
}
"#;

/// The number formats and modal words of Vectric variables, written out
/// in the post (docs/convert.md, \"Native CNC-Calc posts\").
pub(crate) const LIBRARY: &str = r#"// Vectric's number formats: the value times the multiplier, rounded half
// away from zero on its shortest decimal form, padded to the width.
// A modal word prints when its value differs from the one it printed
// last (`byValue`, Vectric's rule) or when its text does.
function createWord(prefix, modal, byValue, format) {
    return {prefix: prefix, modal: modal, byValue: byValue, format: format, last: null, lastValue: NaN};
}

function repeatText(text, n) {
    var s = "";
    for (var i = 0; i < n; i++) {
        s += text;
    }
    return s;
}

// The shortest decimal digits of a number that is not negative, without an exponent.
function plainDigits(m) {
    var s = String(m);
    var e = s.indexOf("e");
    if (e < 0) {
        return s;
    }
    var mantissa = s.substring(0, e);
    var exponent = parseInt(s.substring(e + 1), 10);
    var dot = mantissa.indexOf(".");
    var digits = dot < 0 ? mantissa : mantissa.substring(0, dot) + mantissa.substring(dot + 1);
    var whole = (dot < 0 ? mantissa.length : dot) + exponent;
    if (whole <= 0) {
        return "0." + repeatText("0", -whole) + digits;
    }
    if (whole >= digits.length) {
        return digits + repeatText("0", whole - digits.length);
    }
    return digits.substring(0, whole) + "." + digits.substring(whole);
}

function formatNumber(f, value) {
    var v = value * f.multiplier;
    var negative = v < 0;
    var text = plainDigits(Math.abs(v));
    var dot = text.indexOf(".");
    var whole = dot < 0 ? text : text.substring(0, dot);
    var frac = dot < 0 ? "" : text.substring(dot + 1);
    var digits = "0" + whole + (frac + repeatText("0", f.decimals)).substring(0, f.decimals);
    if (frac.length > f.decimals && frac.charAt(f.decimals) >= "5") {
        var d = digits.split("");
        for (var i = d.length - 1; i >= 0; i--) {
            if (d[i] == "9") {
                d[i] = "0";
            } else {
                d[i] = String(Number(d[i]) + 1);
                break;
            }
        }
        digits = d.join("");
    }
    var start = 0;
    while (start < digits.length - f.decimals - 1 && digits.charAt(start) == "0") {
        start++;
    }
    digits = digits.substring(start);
    var integer = digits.substring(0, digits.length - f.decimals);
    var fraction = digits.substring(digits.length - f.decimals);
    if (f.trimZeros) {
        while (fraction.length > 0 && fraction.charAt(fraction.length - 1) == "0") {
            fraction = fraction.substring(0, fraction.length - 1);
        }
    }
    var isZero = /^0*$/.test(integer + fraction);
    var sign = negative && (!isZero || f.negativeZero) ? "-" : f.signAlways ? "+" : "";
    if (!f.leadingZero && integer == "0" && fraction != "") {
        integer = "";
    }
    var mark = fraction != "" || f.pointAlways ? f.mark : "";
    var core = sign.length + integer.length + mark.length + fraction.length;
    var intPad = f.integerWidth ? Math.max(f.width - integer.length, 0) : 0;
    var outerPad = f.integerWidth ? 0 : Math.max(f.width - core, 0);
    var padZeros = f.zeroPad && !f.left;
    var s = f.prefix;
    if (!f.left && !padZeros) {
        s += repeatText(" ", outerPad);
    }
    s += sign;
    if (padZeros) {
        s += repeatText("0", outerPad);
    }
    s += repeatText(f.zeroPad ? "0" : " ", intPad);
    s += integer + mark + fraction;
    if (f.left) {
        s += repeatText(" ", outerPad);
    }
    return s;
}

// A word: the prefix and the formatted value; nothing for a value the
// engine has not handed, or for a modal word whose text is the one it
// printed last.
function word(w, value) {
    if (value !== value) {
        return "";
    }
    if (w.modal && w.byValue) {
        if (value === w.lastValue) {
            return "";
        }
        w.lastValue = value;
        return w.prefix + formatNumber(w.format, value);
    }
    var text = w.prefix + formatNumber(w.format, value);
    if (w.modal && text === w.last) {
        return "";
    }
    w.last = text;
    return text;
}
"#;

/// A format as the object `formatNumber` reads.
pub(crate) fn format_object(f: &NumberFormat) -> String {
    format!(
        "{{decimals: {}, width: {}, integerWidth: {}, zeroPad: {}, left: {}, signAlways: {}, pointAlways: {}, trimZeros: {}, leadingZero: {}, mark: {}, multiplier: {}, prefix: {}, negativeZero: {}}}",
        f.decimals,
        f.width,
        f.width_of == WidthOf::IntegerDigits,
        f.padding == Padding::Zero,
        f.justify == Justify::Left,
        f.sign == SignStyle::Always,
        f.point == PointStyle::Always,
        f.trim_zeros,
        f.leading_zero,
        js_string(&f.decimal_mark.to_string()),
        number(f.multiplier),
        js_string(&f.prefix),
        f.negative_zero
    )
}

/// The JavaScript function that prints a section's lines.
fn section_function(s: Section) -> String {
    format!("section{}", s.name())
}

fn is_identifier(name: &str) -> bool {
    is_js_name(name, PRINTED_NAMES)
}

/// Whether `name` can name a variable of a printed post: a JavaScript
/// identifier that is no word JavaScript reserves, no function of
/// [`LIBRARY`] (which every printed post carries) and none of `taken`, the
/// other names the printed post gives a meaning of its own.
pub(crate) fn is_js_name(name: &str, taken: &[&str]) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_' || c == '$')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$')
        && !JS_RESERVED.contains(&name)
        && !taken.contains(&name)
        && !LIBRARY.lines().any(|l| l.strip_prefix("function ").and_then(|r| r.split('(').next()) == Some(name))
}

/// Words JavaScript reserves, and the global values a post cannot rename.
const JS_RESERVED: &[&str] = &[
    "break",
    "case",
    "catch",
    "class",
    "const",
    "continue",
    "debugger",
    "default",
    "delete",
    "do",
    "else",
    "export",
    "extends",
    "false",
    "finally",
    "for",
    "function",
    "if",
    "import",
    "in",
    "instanceof",
    "new",
    "null",
    "return",
    "super",
    "switch",
    "this",
    "throw",
    "true",
    "try",
    "typeof",
    "var",
    "void",
    "while",
    "with",
    "yield",
    "let",
    "static",
    "enum",
    "await",
    "implements",
    "package",
    "protected",
    "interface",
    "private",
    "public",
    "undefined",
    "NaN",
    "Infinity",
];

/// The names a post printed here gives a meaning of its own.
const PRINTED_NAMES: &[&str] = &[
    "x",
    "y",
    "z",
    "feed",
    "arcI",
    "arcJ",
    "arcIA",
    "arcJA",
    "arcRadius",
    "lastKind",
    "lastFeed",
    "firstRapid",
    "blockNumber",
    "chordTolerance",
    "nextBlock",
    "afterRapid",
    "feedSection",
    "feedOf",
    "feedTo",
    "arcSection",
    "chords",
    "linearize",
    "remainder",
    "linebreak",
    "onOpen",
    "onLinear",
    "onCircular",
    "onClose",
    "getFeedrate",
    "MOVEMENT_RAPID",
    "MOVEMENT_PLUNGE",
    "MOVEMENT_RAMP_HELIX",
    "plunging",
    "Math",
    "String",
    "parseFloat",
    "parseInt",
    "isFinite",
    "toolNumber",
    "toolDiameter",
    "spindle",
    "dwellTime",
    "toolName",
    "toolNotes",
    "toolpathName",
    "toolpathNotes",
    "lastTool",
    "stockLower",
    "stockUpper",
    "textWord",
    "toolFeedCut",
    "toolFeedPlunge",
    "safeZ",
    "homeX",
    "homeY",
    "homeZ",
    "originX",
    "originY",
    "wrapDiameter",
    "wrapAngle",
    "properties",
    "getProperty",
    "getParameter",
    "hasParameter",
    "setEOL",
    "planeChords",
    "spindleOutput",
    "scale",
    "stock",
    "words",
    "onCyclePoint",
    "substitute",
    "substitutions",
    "onSection",
    "onRapid",
    "onDwell",
    "onSpindleSpeed",
    "tool",
    "unit",
    "movement",
    "spindleSpeed",
    "description",
    "vendor",
    "extension",
    "capabilities",
    "tolerance",
    "writeln",
    "EOL",
    "MM",
    "IN",
    "X",
    "Y",
    "Z",
];

/// A number as JavaScript reads it back exactly.
pub(crate) fn number(n: f64) -> String {
    if n == 0.0 { "0".into() } else { format!("{n}") }
}

/// A JavaScript string literal.
pub(crate) fn js_string(t: &str) -> String {
    let mut s = String::with_capacity(t.len() + 2);
    s.push('"');
    for c in t.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '\n' => s.push_str("\\n"),
            '\r' => s.push_str("\\r"),
            '\t' => s.push_str("\\t"),
            '\u{2028}' | '\u{2029}' => s.push_str(&format!("\\u{:04x}", c as u32)),
            c if c.is_control() => s.push_str(&format!("\\u{:04x}", c as u32)),
            c => s.push(c),
        }
    }
    s.push('"');
    s
}
