//! The post: what one post file compiles to.

use serde::{Deserialize, Serialize};

use crate::code::{Expr, Stmt};
use crate::diagnostic::Span;
use crate::format::NumberFormat;
use crate::quantity::Quantity;
use crate::units::Units;

pub use crate::id::{FormatId, FunctionId, GlobalId, LocalId, ScriptId, VarId};

/// A compiled post processor.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Post {
    pub info: PostInfo,
    pub options: OutputOptions,
    /// Number formats, referred to by [`FormatId`].
    pub formats: Vec<NumberFormat>,
    /// Output variables (Vectric `VAR`s, CIMCO output variables, VcPost
    /// registers), referred to by [`VarId`].
    pub variables: Vec<Variable>,
    /// Script-level globals (CIMCO globals, VcPost plain variables).
    pub globals: Vec<Global>,
    /// Functions handlers call.
    pub functions: Vec<Function>,
    /// What runs once before the first event (VcPost statements outside
    /// any Sub, CIMCO top-level code and `onInit`).
    pub init: Vec<Stmt>,
    /// What the post does for each kind of event.
    pub handlers: Vec<Handler>,
    /// Code in a language the IR does not express, kept with its source.
    pub scripts: Vec<Script>,
    /// Globals that a Sub call's lists fill ([`CallList`]); empty for
    /// posts run over toolpath events only.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub call_lists: Vec<CallList>,
    /// The source's comments, each with what it stands before: they do
    /// nothing when the post runs; a backend prints them where they belong
    /// in its dialect, so that a converted post says what its source said.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub comments: Vec<Comment>,
}

/// Comment lines of a post's source and what they stand before (the file's
/// head, a variable, a section or a function). Each line is the text after
/// its comment marker (`+`, `'`, `//`), blanks included, so that a post
/// converted to its own dialect keeps them as written.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Comment {
    pub on: CommentTarget,
    pub lines: Vec<String>,
}

/// What a [`Comment`] stands before.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CommentTarget {
    /// The head of the file: what the post is, who wrote it.
    Post,
    Variable(VarId),
    Handler(HandlerKey),
    Function(FunctionId),
}

/// The text a backend's header comment starts with (`Converted by postc
/// from gcode_mm.pp (Vectric)`). Frontends leave that line (and the rules
/// around it) out of the post's comments, so that converting a converted
/// post again gives the same text.
pub const CONVERSION_NOTE: &str = "Converted by postc from ";

/// Whether a comment line is a backend's header ([`CONVERSION_NOTE`]).
pub fn is_conversion_note(line: &str) -> bool {
    line.trim_start().starts_with(CONVERSION_NOTE)
}

impl Post {
    /// The comment lines that stand before `on`.
    pub fn comment(&self, on: &CommentTarget) -> &[String] {
        self.comments.iter().find(|c| &c.on == on).map_or(&[], |c| c.lines.as_slice())
    }

    /// Adds comment lines before `on` (after any it has already).
    /// A line that holds a line break (a lone `\r` in the source, which
    /// `str::lines` keeps) becomes as many lines: a comment line never
    /// holds one.
    pub fn add_comment(&mut self, on: CommentTarget, lines: Vec<String>) {
        let lines: Vec<String> = if lines.iter().any(|l| l.contains(['\n', '\r'])) {
            lines.iter().flat_map(|l| l.split(['\n', '\r']).map(str::to_string).collect::<Vec<_>>()).collect()
        } else {
            lines
        };
        if lines.is_empty() {
            return;
        }
        match self.comments.iter_mut().find(|c| c.on == on) {
            Some(c) => c.lines.extend(lines),
            None => self.comments.push(Comment { on, lines }),
        }
    }
}

/// Globals a [`crate::SubCall`]'s list fills: before the call, a
/// [`crate::CallValue::List`] named `name` (compared without case) sets
/// globals `first`, `first + 1`, ... to its numbers, and the rest of the
/// `len` globals to 0; a call without that list sets all `len` to 0, so no
/// value outlives its call. Numbers past `len` are dropped.
///
/// A frontend makes these for functions whose values come from the calls
/// (VcPost composites' `getNthLength1(tow)` is a function that reads the
/// `tow`-th of its globals); the runtime only fills them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CallList {
    /// The list's name in the calls.
    pub name: String,
    /// The first of its globals.
    pub first: GlobalId,
    /// How many globals, from `first`.
    pub len: u16,
}

/// What the post says about itself.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PostInfo {
    /// Display name (Vectric `POST_NAME`, CIMCO `PostInfo.title`).
    pub name: String,
    /// The dialect the post was written in.
    pub dialect: Dialect,
    /// Path of the post file.
    pub source: String,
    /// Extension of the files it writes, without the dot.
    pub file_extension: String,
    /// Units it writes; `None` writes the toolpath's own units.
    pub units: Option<Units>,
    /// The post reads the units it is handed and writes for them (a Fusion
    /// post that reads `unit`): without [`PostInfo::units`] it is handed
    /// the toolpath's units, whatever units words its text holds.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub reads_units: bool,
    /// How the runtime turns events into handler calls.
    pub dispatch: Dispatch,
    /// The post supports jet (laser) toolpaths.
    pub laser_support: bool,
    /// Vectric `DIRECT_OUTPUT` and `PRINT_DIRECT`, kept for the record.
    pub direct_output: Option<String>,
    pub print_direct: bool,
    /// Vectric `RAPID_PLUNGE_TO_STARTZ` (a CAM-side setting, kept).
    pub rapid_plunge_to_start_z: bool,
    /// The encoding of the post file's text: literal output bytes and
    /// prefixes are in it, and are written back unchanged.
    pub text_encoding: TextEncoding,
    /// What the post says about its Subs for the applications that call
    /// them by name (VcPost keyword comments).
    pub subs: Vec<crate::calls::SubSignature>,
    /// Free-form notes (CIMCO `PostInfo.summary`, author, version).
    pub notes: Vec<String>,
    /// What Vectric's `[REVISION]` prints in a `REVISION_COMMENT` section:
    /// a hash of the post file (docs/vectric.md); empty when the post
    /// prints no `[REVISION]`.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub revision: String,
    /// Where the post names itself (the Vectric `POST_NAME` statement).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub span: Option<Span>,
    /// The file of the dialect's host API when it is code compiled with the
    /// post (Fusion's `host.js`): an error there is also placed at the
    /// post's function it passed through.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub host_file: Option<crate::diagnostic::FileId>,
    /// A one-file post's file exactly as written (a Vectric post that
    /// names no `POST_BASE`, a VcPost post): what the backend of its dialect prints when
    /// it compiles back to this post, so that converting the post to its
    /// own dialect keeps its layout, comments and line endings. It says
    /// nothing the rest of the IR does not: a post is compared without it.
    /// (A CIMCO post keeps its pieces per statement: [`SourceText::written`].)
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub written: String,
}

/// The encoding a post file was read in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TextEncoding {
    #[default]
    Utf8,
    /// Windows-1252 (a file that is not UTF-8: older Vectric and VcPost posts).
    Windows1252,
}

/// Post dialects.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Dialect {
    #[default]
    Vectric,
    Cimco,
    VcPost,
    /// A post written directly as IR (RON).
    Ron,
    /// An Autodesk Fusion / HSM `.cps` post (JavaScript, Fusion's host API).
    Fusion,
}

/// How toolpath events reach handlers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Dispatch {
    /// Events select a [`Section`]; missing `FIRST_` and special sections
    /// fall back to plainer ones (Vectric rules, used by CIMCO too).
    #[default]
    Sections,
    /// Events become APT records and each record calls the handler named
    /// by its major word (VcPost milling).
    AptWords,
}

/// Output options: everything about the shape of the output that is not a
/// handler.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct OutputOptions {
    /// Bytes written after each block.
    pub line_ending: Vec<u8>,
    /// Block numbers printed by the block-number quantity.
    pub block_numbers: BlockNumbers,
    /// Characters replaced in variable text (not in literal text).
    pub substitutions: Vec<Substitution>,
    /// Split long programs into several files.
    pub tape_splitting: Option<TapeSplitting>,
    /// Spindle speeds printed as steps of a range.
    pub spindle_speed_range: Option<SpindleSpeedRange>,
    /// An axis wrapped around a cylinder and printed as a rotary axis.
    pub rotary_wrap: Option<RotaryWrap>,
    /// Arcs smaller than `min_arc_radius` print as one straight move; arcs
    /// larger than `max_arc_radius` are linearized.
    pub min_arc_radius: Option<f64>,
    pub max_arc_radius: Option<f64>,
    /// Feeds print as inverse time (`[FI]`).
    pub inverse_time_feed: bool,
    /// Chord tolerance, in mm, when arcs are linearized.
    pub arc_tolerance: f64,
    /// Arc words computed from the printed start and end points so the
    /// radius at both ends agrees after rounding.
    pub exact_arcs: bool,
    /// Arcs in the ZX and YZ planes reach the arc sections (with the
    /// `ARC_PLANE` quantity) instead of being linearized: for posts that
    /// write G18 and G19 arcs themselves (Fusion posts). Written to RON
    /// only when set.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub arcs_in_every_plane: bool,
    /// The post reads later toolpaths before they come (Fusion's
    /// `getSection(i)`, tool table, next tool): the runtime asks the
    /// toolpath source for the job's outline (`JOB_OUTLINE`). Written to
    /// RON only when set.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub reads_ahead: bool,
    /// `text.replace(pattern, function)` calls the function for each
    /// match: a post with no script tier (Fusion) sets it; without it the
    /// interpreter refuses a function replacement (RT038), as CIMCO's
    /// script tier does, so the two tiers of a CIMCO post agree. Written
    /// to RON only when set.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub function_replacements: bool,
    /// Text is made as JavaScript's ToString makes it: `+` joins null as
    /// `null` (and arrays, objects and booleans as JavaScript writes them),
    /// where a post without it joins null as nothing (VcPost's empty
    /// value). The JavaScript front end sets it for CIMCO and Fusion
    /// posts. Written to RON only when set.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub js_text: bool,
    /// The post makes its text as UTF-8 and asks for its program in
    /// Windows-1252 (a Fusion post's `setCodePage("ansi")`): the output
    /// is transcoded, a character Windows-1252 lacks written `?`.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub windows_1252_output: bool,
    /// Maximum number of interpreter steps per handler call before a
    /// runaway loop is stopped.
    pub step_budget: u64,
    /// A lathe post (CIMCO `POST_TYPE_TURN`): the toolpath's turning plane
    /// (X the radius, Z along the spindle, ZX-plane arcs) is turned into
    /// the runtime's XY plane (x, y, z become z, x, y) before dispatch, so
    /// that turning arcs reach the arc sections instead of being linearized.
    pub lathe: bool,
    /// Every output variable forgets what it printed when a toolpath
    /// starts, so the first block of each toolpath prints every word: the
    /// Vectric rule (docs/vectric.md, decision 4). A CIMCO post keeps its
    /// modal memory for the whole program, as the CNC-Calc Post Processor Manual says a variable
    /// without `force` "will only be written if it has changed since the
    /// last time it was used"; it forgets through [`crate::Stmt::Forget`]
    /// (`xOutput.reset()`). Each frontend sets this explicitly. Written
    /// out (RON) only when it is `false`.
    #[serde(skip_serializing_if = "is_true")]
    pub forget_modal_at_toolpath_start: bool,
    /// An on-change variable that prints a runtime quantity (`[X]`, `[F]`)
    /// prints when the number changes, not when its printed text does: a
    /// coordinate that moved by less than the last printed digit prints
    /// again with the same text. Values a post's code assigns compare text.
    /// The Vectric rule (docs/vectric.md, "Modal words compare values");
    /// CIMCO and VcPost compare the text. Written out (RON) only when set.
    #[serde(skip_serializing_if = "is_false")]
    pub on_change_by_value: bool,
    /// A rapid move makes the feed variables forget what they printed, so
    /// the first feed move after a rapid prints its feed again, changed or
    /// not: the Vectric rule (docs/vectric.md, "The feed after a rapid").
    /// Written out (RON) only when set.
    #[serde(skip_serializing_if = "is_false")]
    pub rapid_forgets_feed: bool,
}

fn is_true(b: &bool) -> bool {
    *b
}

impl Default for OutputOptions {
    fn default() -> Self {
        OutputOptions {
            line_ending: b"\n".to_vec(),
            block_numbers: BlockNumbers::default(),
            substitutions: Vec::new(),
            tape_splitting: None,
            spindle_speed_range: None,
            rotary_wrap: None,
            min_arc_radius: None,
            max_arc_radius: None,
            inverse_time_feed: false,
            arc_tolerance: 0.01,
            exact_arcs: false,
            arcs_in_every_plane: false,
            reads_ahead: false,
            function_replacements: false,
            js_text: false,
            windows_1252_output: false,
            step_budget: 10_000_000,
            lathe: false,
            forget_modal_at_toolpath_start: true,
            on_change_by_value: false,
            rapid_forgets_feed: false,
        }
    }
}

/// Block numbering: the first number printed, the step, and the number past
/// which numbering starts again.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BlockNumbers {
    pub start: f64,
    pub increment: f64,
    pub maximum: f64,
}

impl Default for BlockNumbers {
    fn default() -> Self {
        BlockNumbers { start: 1.0, increment: 1.0, maximum: 999_999.0 }
    }
}

/// One substitution: `from` is replaced by `to` in variable text.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Substitution {
    pub from: Vec<u8>,
    pub to: Vec<u8>,
}

/// Vectric `TAPE_SPLITTING = MAX TOL "FORMAT" START "INDEX_ON_FIRST"`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TapeSplitting {
    /// Lines per part (footer not counted).
    pub max_lines: u64,
    /// A part may end at a retract once it has `max_lines - tolerance` lines.
    pub tolerance: u64,
    /// File name format: `%s` is the output name without extension, `%d`
    /// the part index.
    pub name_format: String,
    /// Index of the first part.
    pub start_index: u64,
    /// The first part carries an index too (`name_1.tap`, not `name.tap`).
    pub index_on_first_file: bool,
}

/// Vectric `SPINDLE_SPEED_RANGE = OUT_MIN OUT_MAX RPM_MIN RPM_MAX`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpindleSpeedRange {
    pub out_min: f64,
    pub out_max: f64,
    pub rpm_min: f64,
    pub rpm_max: f64,
}

/// Vectric `ROTARY_WRAP_X` / `ROTARY_WRAP_Y`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RotaryWrap {
    /// The linear axis that is wrapped.
    pub axis: WrappedAxis,
    /// The letter that replaces the wrapped axis's letter in its prefix
    /// (`A`); `None` keeps the prefix.
    pub letter: Option<char>,
    /// Rotation runs the other way (`"-A"`).
    pub reversed: bool,
}

impl RotaryWrap {
    /// Whether `q` is a value of the wrapped axis: its position or its
    /// home position, which print as angles.
    pub fn wraps(&self, q: Quantity) -> bool {
        match self.axis {
            WrappedAxis::X => matches!(q, Quantity::X | Quantity::HomeX),
            WrappedAxis::Y => matches!(q, Quantity::Y | Quantity::HomeY),
        }
    }

    /// A variable's prefix as printed: the wrapped axis's letter in the
    /// prefix of its position and its home position (`[X]`, `[XH]`)
    /// becomes the rotary letter. VCarve writes the home of a post with
    /// `ROTARY_WRAP_Y = "A"` as `G0X0.000A0.000` (docs/vectric.md).
    pub fn prefix(&self, var: &Variable) -> Vec<u8> {
        let mut prefix = var.prefix.clone();
        let (Some(letter), ValueSource::Quantity(q)) = (self.letter, var.source) else { return prefix };
        if !self.wraps(q) {
            return prefix;
        }
        let axis = if self.axis == WrappedAxis::X { b'X' } else { b'Y' };
        if let Some(p) = prefix.iter().position(|b| b.eq_ignore_ascii_case(&axis)) {
            prefix[p] = letter as u8;
        }
        prefix
    }
}

/// Which linear axis a rotary wrap maps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum WrappedAxis {
    X,
    Y,
}

/// An output variable: where its value comes from, how it prints, and when.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Variable {
    /// The name the post gave it (`X_POSITION`, `xOutput`, `X`).
    pub name: String,
    /// Where its value comes from.
    pub source: ValueSource,
    /// Text written before the formatted value.
    pub prefix: Vec<u8>,
    /// How the value prints.
    pub format: FormatId,
    /// When the value prints.
    pub modality: Modality,
    /// Where the post defines the variable (a Vectric `VAR` line or the
    /// first use of a label left to its default, a CIMCO
    /// `createVariable` call, a VcPost register's first use).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub span: Option<Span>,
}

/// Where a variable's value comes from.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum ValueSource {
    /// A runtime quantity (Vectric labels).
    Quantity(Quantity),
    /// Whatever the post assigns or formats through it (CIMCO output
    /// variables, VcPost registers). A register may also start from a
    /// quantity the runtime loads before each handler call.
    Assigned,
}

/// When a variable prints.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Modality {
    /// Every time.
    #[default]
    Always,
    /// Only when its text differs from what it printed last; all memory is
    /// cleared at the start of each toolpath.
    OnChange,
}

/// A global value of a post script.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Global {
    pub name: String,
    pub initial: Expr,
    /// The post gives the global its values without declaring it (a
    /// JavaScript global set by `x = ...` and no `var`): a backend of its
    /// dialect declares it no more than the source did. Written out (RON)
    /// only when it is `true`.
    #[serde(default, skip_serializing_if = "is_false")]
    pub implicit: bool,
    /// Where the post declares it, if it does.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub span: Option<Span>,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// A callable body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Function {
    pub name: String,
    pub params: Vec<String>,
    /// Parameters plus locals.
    pub slots: u16,
    /// The source's names of the locals after the parameters, by slot,
    /// when its frontend keeps them (backends print them); may be shorter
    /// than the locals.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub locals: Vec<String>,
    pub body: Body,
    /// Where the function is defined.
    pub span: Option<Span>,
    /// Why the function runs as a script, when its frontend knows: the
    /// first construct with no native form, and where it is (`postc
    /// inspect` shows it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub why_script: Option<ScriptReason>,
    /// The function as written in its source dialect, for a backend of that
    /// dialect: kept where the IR does not say all of the function, so
    /// that a post converted to its own dialect keeps it. A CIMCO function
    /// that runs as a script or reads `arguments` (its IR functions are
    /// the forms for each number of arguments) keeps its declaration; the
    /// frontend's start-up function (`__postc_init`) keeps the post's
    /// top-level statements in order, one each, with the globals they
    /// declare; one the IR holds (a constant, a format) has no text.
    /// Only the backend of the function's own dialect prints this text;
    /// another backend refuses what the IR does not say (a script is
    /// `CV002` there), since the text means nothing in its dialect.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub source: Vec<SourceText>,
    /// The function reads `arguments` ([`crate::Expr::Arguments`]): the
    /// runtime keeps the arguments of its calls.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub uses_arguments: bool,
    /// What a parameter the caller did not pass, and a local before it is
    /// given a value, hold: `null` (BASIC's empty value; the CIMCO native
    /// tier's stand-in for both), or JavaScript's `undefined`.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub starts_undefined: bool,
}

/// A piece of a post as written in its dialect (see [`Function::source`]).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SourceText {
    /// The text, as written; empty where the IR holds what the text said
    /// (a constant, a format), which a backend prints from the IR there.
    pub text: String,
    /// The globals the text declares (`var a = 1, b;` declares `a` and
    /// `b`), in order: a backend prints the text where the first of them
    /// stands among the post's globals.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub declares: Vec<String>,
    /// The piece exactly as the source file has it, with the comments and
    /// blank lines between it and the piece before: what the backend of
    /// the source's dialect prints, when what it compiles to is what the
    /// IR holds, so that converting a post to its own dialect keeps its
    /// settings' spellings, its comments and its line endings. Empty where
    /// the IR was not read from a file of that dialect. It says nothing the
    /// IR does not: a post is compared without it.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub written: String,
    /// Where [`Self::written`] starts in the source file (bytes): pieces
    /// printed as written are printed in this order.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub written_at: usize,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

/// Why a function runs as a script rather than as native IR.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScriptReason {
    /// The construct, as a post author would name it ("reads `arguments`").
    pub what: String,
    pub span: Option<Span>,
}

/// A body is native IR or a script.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Body {
    /// Runs as IR statements (native speed).
    Native(Vec<Stmt>),
    /// Runs as a script.
    Script(ScriptId),
}

/// What a post does for one kind of event.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Handler {
    pub key: HandlerKey,
    pub body: Vec<Stmt>,
    /// Where the handler is defined (Vectric `begin` line, Sub header).
    pub span: Option<Span>,
}

/// What selects a handler.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum HandlerKey {
    Section(Section),
    /// An APT major word (VcPost Subs), upper case.
    Word(String),
}

/// Code in a language the IR does not express.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Script {
    pub language: ScriptLanguage,
    /// The script's source text.
    pub source: String,
    /// Where it sits in the post file.
    pub span: Option<Span>,
    /// Maps offsets in `source` back to the post file, as (offset in
    /// source, offset in post) pairs sorted by the first.
    pub span_map: Vec<(u32, u32)>,
}

impl Script {
    /// The name a post function has in a Rhai script: `js_` and the name,
    /// with each character other than an ASCII letter, digit or `_` written
    /// as `_uHEX_`. The runtime calls script functions by this name.
    pub fn function_name(name: &str) -> String {
        let mut out = String::from("js_");
        for c in name.chars() {
            if c.is_ascii_alphanumeric() || c == '_' {
                out.push(c);
            } else {
                out.push_str(&format!("_u{:x}_", c as u32));
            }
        }
        out
    }
}

/// Languages of scripts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum ScriptLanguage {
    /// Rhai (CIMCO JavaScript that does not lower to IR).
    Rhai,
    /// Lua (Vectric `SCRIPT` blocks and `<!>` calls; kept, not run).
    Lua,
}

macro_rules! sections {
    ($( $(#[$doc:meta])* $name:ident = $text:literal; )*) => {
        /// Kinds of output sections. The names are Vectric's; the other
        /// dialects lower onto the same set.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        pub enum Section {
            $( $(#[$doc])* $name, )*
        }

        impl Section {
            /// Every section, in declaration order.
            pub const ALL: &'static [Section] = &[$(Section::$name,)*];

            /// The name a Vectric post writes after `begin`.
            pub fn name(self) -> &'static str {
                match self { $(Section::$name => $text,)* }
            }
        }
    };
}

sections! {
    /// Start of the program; the first tool's data is known.
    Header = "HEADER";
    /// End of the program.
    Footer = "FOOTER";
    /// After the header and each tool change, for spindle tools.
    SpindleOn = "SPINDLE_ON";
    /// A later toolpath uses another tool.
    ToolChange = "TOOLCHANGE";
    /// A later toolpath starts.
    NewSegment = "NEW_SEGMENT";
    /// The first rapid after the header or a tool change.
    InitialRapidMove = "INITIAL_RAPID_MOVE";
    RapidMove = "RAPID_MOVE";
    FirstFeedMove = "FIRST_FEED_MOVE";
    FeedMove = "FEED_MOVE";
    FirstPlungeMove = "FIRST_PLUNGE_MOVE";
    PlungeMove = "PLUNGE_MOVE";
    RetractMove = "RETRACT_MOVE";
    FirstCwArcMove = "FIRST_CW_ARC_MOVE";
    CwArcMove = "CW_ARC_MOVE";
    FirstCcwArcMove = "FIRST_CCW_ARC_MOVE";
    CcwArcMove = "CCW_ARC_MOVE";
    FirstCwHelicalArcMove = "FIRST_CW_HELICAL_ARC_MOVE";
    CwHelicalArcMove = "CW_HELICAL_ARC_MOVE";
    FirstCcwHelicalArcMove = "FIRST_CCW_HELICAL_ARC_MOVE";
    CcwHelicalArcMove = "CCW_HELICAL_ARC_MOVE";
    FirstCwHelicalArcPlungeMove = "FIRST_CW_HELICAL_ARC_PLUNGE_MOVE";
    CwHelicalArcPlungeMove = "CW_HELICAL_ARC_PLUNGE_MOVE";
    FirstCcwHelicalArcPlungeMove = "FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE";
    CcwHelicalArcPlungeMove = "CCW_HELICAL_ARC_PLUNGE_MOVE";
    /// Before a move whose feed differs from the last one.
    FeedRateChange = "FEED_RATE_CHANGE";
    DwellMove = "DWELL_MOVE";
    JetToolOn = "JET_TOOL_ON";
    JetToolOff = "JET_TOOL_OFF";
    JetToolPower = "JET_TOOL_POWER";
    /// Not Vectric: the spindle stops.
    SpindleOff = "SPINDLE_OFF";
    /// Not Vectric: coolant changes.
    Coolant = "COOLANT";
    /// Not Vectric: cutter compensation changes.
    CutterComp = "CUTTER_COMP";
    /// Not Vectric: a canned drilling cycle starts.
    DrillHeader = "DRILL_HEADER";
    /// Not Vectric: one hole.
    DrillPoint = "DRILL_POINT";
    /// Not Vectric: the cycle ends.
    DrillFooter = "DRILL_FOOTER";
    /// Not Vectric: an operator comment.
    Comment = "COMMENT";
    /// Not Vectric: verbatim text.
    Insert = "INSERT";
    /// Not Vectric: the end of a toolpath.
    ToolpathEnd = "TOOLPATH_END";
    /// Printed first, before the header: the stock post's revision
    /// (`(VECTRIC POST REVISION)` and `[REVISION]`).
    RevisionComment = "REVISION_COMMENT";
}

impl Section {
    /// The section a Vectric `begin` name (case-insensitive) stands for.
    pub fn from_name(name: &str) -> Option<Section> {
        Section::ALL.iter().copied().find(|s| s.name().eq_ignore_ascii_case(name))
    }
}

impl Post {
    /// Adds a format; `None` when the post has 65,536 already.
    pub fn push_format(&mut self, format: NumberFormat) -> Option<FormatId> {
        let id = FormatId::from_usize(self.formats.len())?;
        self.formats.push(format);
        Some(id)
    }

    /// Adds a variable; `None` when the post has 65,536 already.
    pub fn push_variable(&mut self, variable: Variable) -> Option<VarId> {
        let id = VarId::from_usize(self.variables.len())?;
        self.variables.push(variable);
        Some(id)
    }

    /// Adds a global; `None` when the post has 65,536 already.
    pub fn push_global(&mut self, global: Global) -> Option<GlobalId> {
        let id = GlobalId::from_usize(self.globals.len())?;
        self.globals.push(global);
        Some(id)
    }

    /// Adds a function; `None` when the post has 65,536 already.
    pub fn push_function(&mut self, function: Function) -> Option<FunctionId> {
        let id = FunctionId::from_usize(self.functions.len())?;
        self.functions.push(function);
        Some(id)
    }

    /// Adds a script; `None` when the post has 65,536 already.
    pub fn push_script(&mut self, script: Script) -> Option<ScriptId> {
        let id = ScriptId::from_usize(self.scripts.len())?;
        self.scripts.push(script);
        Some(id)
    }

    /// A variable of the post (the id must be valid: [`crate::validate`]).
    #[inline]
    pub fn variable(&self, id: VarId) -> &Variable {
        &self.variables[id.index()]
    }

    /// A format of the post (the id must be valid: [`crate::validate`]).
    #[inline]
    pub fn format(&self, id: FormatId) -> &NumberFormat {
        &self.formats[id.index()]
    }

    /// A function of the post (the id must be valid: [`crate::validate`]).
    #[inline]
    pub fn function(&self, id: FunctionId) -> &Function {
        &self.functions[id.index()]
    }

    /// Forgets the source's text kept as written ([`PostInfo::written`],
    /// [`SourceText::written`]): a post read from RON alone, or one
    /// compared with another by what it means.
    pub fn drop_written(&mut self) {
        self.info.written.clear();
        for t in self.functions.iter_mut().flat_map(|f| &mut f.source) {
            t.written.clear();
            t.written_at = 0;
        }
    }

    /// Forgets every span: of the post's name, handlers, functions, scripts, variables,
    /// formats, output lines, loops, members and names, and the `Origin` statements. A post whose spans point into
    /// files it does not come with (a RON conversion) drops them, so that
    /// no diagnostic points into the wrong file.
    pub fn drop_spans(&mut self) {
        struct Drop;
        impl crate::visit::VisitMut for Drop {
            fn visit_stmt_mut(&mut self, stmt: &mut Stmt) {
                match stmt {
                    Stmt::While { span, .. } | Stmt::Line { span, .. } | Stmt::Throw { span, .. } => *span = None,
                    Stmt::SetMember { span, .. } => span.0 = None,
                    _ => {}
                }
                crate::visit::walk_stmt_mut(self, stmt);
            }
            fn visit_expr_mut(&mut self, expr: &mut crate::code::Expr) {
                if let crate::code::Expr::FormatVar { span, .. }
                | crate::code::Expr::Format { span, .. }
                | crate::code::Expr::Invoke { span, .. }
                | crate::code::Expr::Regex { span, .. } = expr
                {
                    *span = None;
                }
                if let crate::code::Expr::Member { span, .. } | crate::code::Expr::Undeclared { span, .. } = expr {
                    span.0 = None;
                }
                crate::visit::walk_expr_mut(self, expr);
            }
        }
        self.info.span = None;
        self.handlers.iter_mut().for_each(|h| h.span = None);
        for f in &mut self.functions {
            f.span = None;
            if let Some(w) = &mut f.why_script {
                w.span = None;
            }
        }
        self.variables.iter_mut().for_each(|v| v.span = None);
        self.formats.iter_mut().for_each(|f| f.span = None);
        self.globals.iter_mut().for_each(|g| g.span = None);
        for s in &mut self.scripts {
            s.span = None;
            s.span_map.clear();
        }
        crate::visit::VisitMut::visit_post_mut(&mut Drop, self);
        // `Origin` statements are spans too.
        fn drop_origins(stmts: &mut Vec<Stmt>) {
            stmts.retain(|s| !matches!(s, Stmt::Origin(_)));
            for s in stmts {
                crate::visit::for_each_body_mut(s, drop_origins);
            }
        }
        drop_origins(&mut self.init);
        self.handlers.iter_mut().for_each(|h| drop_origins(&mut h.body));
        for f in &mut self.functions {
            if let Body::Native(body) = &mut f.body {
                drop_origins(body);
            }
        }
    }

    /// The handler for a key, if the post has one.
    pub fn handler(&self, key: &HandlerKey) -> Option<&Handler> {
        self.handlers.iter().find(|h| &h.key == key)
    }

    /// The handler for a section, if the post has one.
    pub fn section(&self, section: Section) -> Option<&Handler> {
        self.handlers.iter().find(|h| h.key == HandlerKey::Section(section))
    }
}
