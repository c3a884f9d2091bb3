//! # postc verify
//!
//! Reads a G-code program (ISO/Fanuc/Haas/LinuxCNC/grbl style), replays it
//! with a modal interpreter of the RS274/NGC groups, and compares the
//! resulting tool motion, move by move, with the toolpath the program was
//! posted from. Every finding is a [`Diagnostic`] with a `VF` code, a span
//! in the program (line and column) and, where it came from a toolpath
//! move, a second label at that move.
//!
//! Both sides stream: the program is read line by line into one reused
//! buffer, the toolpath through a bounded window of expected moves
//! ([`expect::WINDOW`]); memory stays flat whatever the length.
//! `docs/verify.md` describes the checks, the tolerances and the
//! controllers' limits.

pub mod expect;
pub mod geometry;
pub mod grammar;
mod interp;
mod params;
pub mod plot;

use std::io::BufRead;

use postc_ir::post::{Dispatch, Section};
use postc_ir::{Diagnostic, EventSource, FileId, Post, Quantity, Units, ValueSource};

pub use interp::{NOT_GCODE, Stats};

/// The controller a program is checked for: its arc radius limit, block
/// number maximum and the comment characters it accepts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Controller {
    LinuxCnc,
    Fanuc,
    Haas,
    Grbl,
    #[default]
    Generic,
}

impl Controller {
    pub fn name(self) -> &'static str {
        match self {
            Controller::LinuxCnc => "LinuxCNC",
            Controller::Fanuc => "Fanuc",
            Controller::Haas => "Haas",
            Controller::Grbl => "grbl",
            Controller::Generic => "generic",
        }
    }

    /// Whether an arc whose start and end radii are `r0` and `r1` (mm)
    /// is out of this controller's limit. `inch` is the program's units.
    pub fn radius_error(self, r0: f64, r1: f64, inch: bool) -> Option<String> {
        let diff = (r0 - r1).abs();
        let r = r0.max(r1);
        match self {
            // interp_internal.hh: CENTER_ARC_RADIUS_TOLERANCE_{MM,INCH} = 2 * 0.01 mm (0.001 in) * sqrt(2);
            // interp_arc.cc: an error when the difference is over 100 times that, or over it and over 0.1% of the radius.
            Controller::LinuxCnc | Controller::Generic => {
                let abs = if inch { 2.0 * 0.001 * 25.4 } else { 2.0 * 0.01 } * std::f64::consts::SQRT_2;
                (diff > 100.0 * abs || (diff > abs && diff / r > 0.001)).then(|| {
                    format!("LinuxCNC refuses a difference over {abs:.4} mm that is also over 0.1% of the radius")
                })
            }
            // grbl gcode.c: STATUS_GCODE_INVALID_TARGET when the difference is over 0.005 mm and over 0.5 mm or 0.1% of the radius.
            Controller::Grbl => (diff > 0.005 && (diff > 0.5 || diff > 0.001 * r)).then(|| {
                "grbl refuses a difference over 0.005 mm that is also over 0.5 mm or 0.1% of the radius".into()
            }),
            // Fanuc parameter 3410 (and Haas' equivalent) is set by the machine builder; 0.01 mm is assumed.
            Controller::Fanuc | Controller::Haas => (diff > 0.01).then(|| {
                format!("{} refuses (by its arc radius parameter, assumed 0.01 mm) a larger difference", self.name())
            }),
        }
    }

    /// The most digits a word's number may have, for the controllers that
    /// refuse longer numbers: Fanuc's alarm PS0003 "TOO MANY DIGITS" (an
    /// address takes at most 8 digits: ±99999.999 mm, ±9999.9999 in), and
    /// Haas, which follows Fanuc's word format. LinuxCNC and grbl read a
    /// number of any length (grbl keeps its first 8 digits); their limit is
    /// the block's ([`Controller::block_length`]).
    pub fn word_digits(self) -> Option<usize> {
        match self {
            Controller::Fanuc | Controller::Haas => Some(8),
            Controller::LinuxCnc | Controller::Grbl | Controller::Generic => None,
        }
    }

    /// The longest block the controller reads, in characters, and whether
    /// blanks and comments count: LinuxCNC's interpreter reads a line of
    /// at most 252 characters, all counted, a carriage return before the
    /// line feed too (measured with `/usr/local/bin/rs274`: 253 are
    /// "Command too long"; its `LINELEN` is 255); grbl keeps 80
    /// characters of a line in its buffer, blanks and comments left out
    /// (`LINE_BUFFER_SIZE`; a longer one is error 11, "Max characters per
    /// line exceeded"). The generic controller follows LinuxCNC, as it does
    /// for arcs.
    pub fn block_length(self) -> Option<(usize, bool)> {
        match self {
            Controller::LinuxCnc | Controller::Generic => Some((252, true)),
            Controller::Grbl => Some((80, false)),
            Controller::Fanuc | Controller::Haas => None,
        }
    }

    /// The highest block number the controller reads.
    pub fn block_maximum(self) -> f64 {
        match self {
            Controller::Grbl => 9_999_999.0,
            Controller::LinuxCnc | Controller::Fanuc | Controller::Haas => 99_999.0,
            Controller::Generic => f64::INFINITY,
        }
    }
}

/// What verify knows about the program before reading it.
#[derive(Clone, Debug)]
pub struct Settings {
    pub controller: Controller,
    /// The tolerance asked for, mm (default 0.01).
    pub tolerance: f64,
    /// The post's output units, when the post is known.
    pub units: Option<Units>,
    /// Decimals of the post's X/Y/Z words, when the post is known.
    pub decimals: Option<u8>,
    /// Chord tolerance of arcs the post linearizes, mm.
    pub chord_tolerance: f64,
    /// The post's block numbering: start and maximum.
    pub block_start: Option<f64>,
    pub block_maximum: Option<f64>,
    /// The multiplier of the post's feed word (1 for per-minute feeds).
    pub feed_multiplier: f64,
    /// The post wraps an axis onto a rotary one.
    pub rotary_wrap: bool,
    /// The post can switch a jet on: false for a section post without a
    /// JET_TOOL_ON section and for an APT-word post (the runtime gives it
    /// no record for jet events), whose jet cuts VF035 then reports as
    /// warnings (a property of the post: it is not a jet post).
    pub jet_on: bool,
    /// The post can start a spindle: false for a section post with nothing
    /// in its SPINDLE_ON section and no M3 or M4 in any line it prints
    /// outside its jet sections (a post for a spindle switched on by hand),
    /// whose cuts VF035 then reports as warnings.
    pub spindle_on: bool,
    /// The post is an APT-word one (VcPost milling, postp): what the
    /// runtime hands it is the toolpath's records as they are
    /// ([`expect::ExpectedPath::apt_words`]).
    pub apt_words: bool,
    /// The post's name, for messages.
    pub post: Option<String>,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            controller: Controller::Generic,
            tolerance: 0.01,
            units: None,
            decimals: None,
            chord_tolerance: 0.01,
            block_start: None,
            block_maximum: None,
            feed_multiplier: 1.0,
            rotary_wrap: false,
            jet_on: true,
            spindle_on: true,
            apt_words: false,
            post: None,
        }
    }
}

impl Settings {
    /// Learns from a compiled post: output units, the decimals of its X
    /// word, the chord tolerance, block numbering and the feed multiplier.
    pub fn from_post(post: &Post, controller: Controller, tolerance: f64) -> Settings {
        let format_of = |q: Quantity| {
            post.variables
                .iter()
                .find(|v| v.source == ValueSource::Quantity(q))
                .and_then(|v| post.formats.get(v.format.index()))
        };
        let decimals =
            [Quantity::X, Quantity::Y, Quantity::Z].into_iter().filter_map(format_of).map(|f| f.decimals).min();
        let feed_multiplier = [Quantity::Feed, Quantity::CutFeed, Quantity::PlungeFeed]
            .into_iter()
            .filter_map(format_of)
            .map(|f| f.multiplier)
            .find(|m| m.is_finite() && *m > 0.0)
            .unwrap_or(1.0);
        let numbers = post.options.block_numbers;
        let has_n = post.variables.iter().any(|v| v.source == ValueSource::Quantity(Quantity::BlockNumber));
        Settings {
            controller,
            tolerance,
            units: post.output_units(),
            decimals,
            chord_tolerance: post.options.arc_tolerance,
            block_start: has_n.then_some(numbers.start),
            block_maximum: (has_n && numbers.maximum > 0.0).then_some(numbers.maximum),
            feed_multiplier,
            rotary_wrap: post.options.rotary_wrap.is_some(),
            // An APT-word post is given no record for jet events.
            jet_on: post.info.dispatch == Dispatch::Sections && post.section(Section::JetToolOn).is_some(),
            spindle_on: post.info.dispatch != Dispatch::Sections
                || post.section(Section::SpindleOn).is_some_and(|h| !h.body.is_empty())
                || prints_spindle_start(post),
            apt_words: post.info.dispatch == Dispatch::AptWords,
            post: Some(post.info.name.clone()),
        }
    }
}

/// The program families verify knows, for the refusal message.
pub const FAMILIES: &str = "G-code (ISO, Fanuc, Haas, LinuxCNC and grbl style, with `#` parameters and [ ] expressions, and Siemens Sinumerik)";

/// The note (VF044) that a program posted as `name` was not verified, and
/// why: what `postc post` and the Python package's `post` say alike.
pub fn unverified(name: &str, why: &str) -> Diagnostic {
    Diagnostic::new(postc_ir::Severity::Note, postc_ir::codes::VF044, format!("`{name}` was not verified: {why}"))
        .help(format!("`postc post` verifies {FAMILIES}"))
}

/// Why a replay that found VF001 (twenty blocks that do not read before
/// any move) did not verify the program: text output, not a G-code
/// program verify reads (docs/verify.md).
pub fn not_gcode(report: &Report) -> Option<String> {
    report
        .findings
        .iter()
        .any(|d| d.code == postc_ir::codes::VF001.code)
        .then(|| format!("its first {NOT_GCODE} blocks do not read as G-code and none moves the tool"))
}

/// Output extensions of families verify does not read.
/// `.ppg` is Tekna's part program (its `DL` tool length word and `G4=`
/// dwell are no RS274 words).
pub const FOREIGN_EXTENSIONS: &[(&str, &str)] = &[
    ("plt", "HPGL"),
    ("hpgl", "HPGL"),
    ("hpg", "HPGL"),
    ("sbp", "ShopBot"),
    ("h", "Heidenhain conversational"),
    ("ppg", "Tekna"),
];

/// Why a program cannot be verified, known before it is replayed: the
/// post (when given) writes another family, is a lathe post or wraps an
/// axis onto a rotary axis; the program named `name` (extension `ext`,
/// first bytes `head`) is binary or of another family. What `postc verify`
/// and the Python package's `verify` refuse, with the same diagnostic.
pub fn refusal(name: &str, post: Option<&Post>, ext: &str, head: &[u8]) -> Option<Diagnostic> {
    use postc_ir::codes;
    let refuse = |family: &str, why: &str| foreign_refusal(name, family, why);
    let foreign = |ext: &str| {
        let ext = ext.to_ascii_lowercase();
        FOREIGN_EXTENSIONS.iter().find(|(e, _)| *e == ext).map(|(_, family)| *family)
    };
    if let Some(refused) = post.and_then(|post| post_refusal(name, post)) {
        return Some(refused);
    }
    if looks_binary(head) {
        return Some(
            Diagnostic::error(codes::VF002, format!("`{name}` is binary data, not a G-code program"))
                .help("verify reads text programs as posts write them"),
        );
    }
    if let Some(family) = foreign(ext) {
        return Some(refuse(family, &format!("its extension is `.{}`", ext.to_ascii_lowercase())));
    }
    foreign_family(head).map(|family| refuse(family, "its first lines are in that language"))
}

/// Why no program of `post` can be verified (the first part of
/// [`refusal`], known before the program is read).
pub fn post_refusal(name: &str, post: &Post) -> Option<Diagnostic> {
    use postc_ir::codes;
    let ext = post.info.file_extension.to_ascii_lowercase();
    if let Some((_, family)) = FOREIGN_EXTENSIONS.iter().find(|(e, _)| *e == ext) {
        return Some(foreign_refusal(name, family, &format!("the post writes `.{ext}` files")));
    }
    if post.options.lathe {
        return Some(
            Diagnostic::error(
                codes::VF007,
                format!("`{}` is a lathe post; verify compares milling programs only", post.info.name),
            )
            .help("a lathe program's X is a diameter and its plane is XZ; verify does not replay turning"),
        );
    }
    if post.options.rotary_wrap.is_some() {
        return Some(
            Diagnostic::error(
                codes::VF006,
                format!(
                    "`{}` wraps an axis onto a rotary axis; verify does not compare rotary-wrapped programs",
                    post.info.name
                ),
            )
            .help("verify compares X Y Z motion; a wrapped program moves the rotary axis instead of the wrapped one"),
        );
    }
    None
}

/// VF001: `name` is a program of `family`, which verify does not read.
fn foreign_refusal(name: &str, family: &str, why: &str) -> Diagnostic {
    Diagnostic::error(postc_ir::codes::VF001, format!("`{name}` is {family}, not G-code: {why}"))
        .help(format!("verify reads {FAMILIES}; programs of other families (HPGL, ShopBot, Heidenhain conversational, Kawasaki AS, Selca, Acramatic, Bridgeport DNC tape, Tekna, CSV sheets) are not verified"))
}

/// ShopBot commands that start a line with a comma after them.
const SHOPBOT: &[&str] = &[
    "MS", "JS", "VS", "J2", "J3", "J4", "J5", "JX", "JY", "JZ", "JA", "JB", "M2", "M3", "M4", "M5", "MX", "MY", "MZ",
    "MA", "MB", "MH", "JH", "CG", "CR", "CP", "TR", "SO", "PA", "PS", "C2", "C3", "C6", "C7", "C9", "TC", "FP", "ZX",
    "ZY", "ZZ", "ZT", "SR", "SF", "VA", "VR",
];

/// Output families verify does not read, told apart by a program's first
/// bytes (docs/verify.md, "Families verify does not read", gives the
/// evidence of each):
///
/// - Heidenhain conversational: `BEGIN PGM`;
/// - HPGL: `IN;`, `PU;`, `SP1;` ...;
/// - ShopBot: two-letter commands with comma-separated arguments, `&` variables, `SA`;
/// - Kawasaki AS (robot language): `.PROGRAM name()`, `PRINT "text"`,
///   `LMOVE`/`JMOVE`/`LAPPRO` motion statements, `.END`;
/// - Selca: `[` starts a remark (a block `[ text`, never a Fanuc `[`
///   expression, which no block starts with);
/// - Acramatic: the program's name statement `(PGM, NAME="...")`;
/// - Bridgeport DNC tape: the DC1 (XON) byte alone on the first line, the
///   character that starts the control's tape reader, then blocks ended
///   by `;` with `'` comments;
/// - CSV sheets: the first line a header of at least four fields split by
///   `,` or `;`, and no line a block (setup and tool sheets).
pub fn foreign_family(head: &[u8]) -> Option<&'static str> {
    let text = String::from_utf8_lossy(&head[..head.len().min(4096)]);
    let lines = || text.lines().map(str::trim).filter(|l| !l.is_empty()).take(40);
    if let Some(first) = lines().next() {
        if first == "\u{11}" && lines().nth(1).is_some_and(|l| l.ends_with(';')) {
            return Some("Bridgeport DNC tape");
        }
        let fields = |l: &str, sep: char| l.split(sep).count();
        let sheet = |sep: char| {
            fields(first, sep) >= 4
                && lines().all(|l| fields(l, sep) >= 2 && !l.starts_with(['(', '%', 'N', 'G', 'O', ';']))
        };
        if sheet(',') || sheet(';') {
            return Some("a CSV sheet");
        }
    }
    for line in lines() {
        let upper = line.to_ascii_uppercase();
        if upper.starts_with(".PROGRAM ")
            || upper.starts_with("PRINT \"")
            || ["LMOVE ", "JMOVE ", "LAPPRO ", "JAPPRO "].iter().any(|m| upper.starts_with(m))
        {
            return Some("Kawasaki AS (robot language)");
        }
        if upper.starts_with("[ ") {
            return Some("Selca");
        }
        if upper.contains("(PGM, NAME=") || upper.contains("(PGM,NAME=") {
            return Some("Acramatic");
        }
        if upper.starts_with("BEGIN PGM") || upper.split_whitespace().nth(1) == Some("BEGIN") && upper.contains(" PGM ")
        {
            return Some("Heidenhain conversational");
        }
        if ["IN;", "PU;", "PD;", "SP1;", "DF;"].iter().any(|p| upper.starts_with(p))
            || (upper.starts_with("PU") && upper.ends_with(';'))
        {
            return Some("HPGL");
        }
        // ShopBot's two-character commands take comma-separated arguments (`MS,1,0.5`, `J3,0,0,1`).
        let b = upper.as_bytes();
        if b.len() >= 3 && b[2] == b',' && SHOPBOT.iter().any(|c| c.as_bytes() == &b[..2]) {
            return Some("ShopBot");
        }
        if upper.starts_with('&') || upper == "SA" {
            return Some("ShopBot");
        }
    }
    None
}

/// Whether the head of a file looks binary (NUL bytes or mostly control bytes).
pub fn looks_binary(head: &[u8]) -> bool {
    let head = &head[..head.len().min(4096)];
    let control = head.iter().filter(|&&b| b < 32 && !matches!(b, b'\n' | b'\r' | b'\t' | 12)).count();
    head.contains(&0) || control * 10 > head.len()
}

/// Whether any line of the post, its jet sections left aside, prints an
/// M3 or M4 word (`M3`, `M03`, `M4`, `M04`, not followed by a digit) in
/// its literal text.
fn prints_spindle_start(post: &Post) -> bool {
    use postc_ir::HandlerKey;
    use postc_ir::code::Piece;
    use postc_ir::visit::{Visit, walk_piece};
    struct Finds(bool);
    impl Visit for Finds {
        fn visit_piece(&mut self, piece: &Piece) {
            if let Piece::Text(bytes) = piece {
                self.0 |= (0..bytes.len()).any(|i| {
                    let after_m = &bytes[i + 1..];
                    let digits = after_m.iter().take_while(|b| b.is_ascii_digit()).count();
                    let number = &after_m[..digits];
                    bytes[i].eq_ignore_ascii_case(&b'M')
                        && (i == 0 || !bytes[i - 1].is_ascii_alphabetic())
                        && matches!(number, b"3" | b"03" | b"4" | b"04")
                });
            }
            walk_piece(self, piece);
        }
    }
    let jet = [Section::JetToolOn, Section::JetToolPower, Section::JetToolOff];
    let mut finds = Finds(false);
    post.init.iter().for_each(|s| finds.visit_stmt(s));
    for h in post.handlers.iter().filter(|h| !matches!(h.key, HandlerKey::Section(s) if jet.contains(&s))) {
        h.body.iter().for_each(|s| finds.visit_stmt(s));
    }
    for f in &post.functions {
        if let postc_ir::post::Body::Native(body) = &f.body {
            body.iter().for_each(|s| finds.visit_stmt(s));
        }
    }
    finds.0
}

/// What a verification found.
pub struct Report {
    /// Findings, at most [`MAX_SHOWN`] of each code; `counts` has them all.
    pub findings: Vec<Diagnostic>,
    /// Where each finding is on the path (mm; NaN where not known),
    /// parallel to `findings`: the end of the program move it concerns,
    /// or the toolpath move the program does not make.
    pub at: Vec<[f64; 3]>,
    /// The program line being read when each finding was made (parallel
    /// to `findings`): its number (1-based) and the byte offset where it
    /// starts, so that findings can be placed by line and column in a
    /// program that is not held in memory.
    pub lines: Vec<(u64, usize)>,
    pub errors: u64,
    pub warnings: u64,
    pub stats: Stats,
}

/// Findings kept of each code; the rest are counted.
pub const MAX_SHOWN: usize = 20;

/// Verifies a program (read from `program`, its spans in `file`) against
/// the toolpath it was posted from.
pub fn verify(program: &mut dyn BufRead, file: FileId, toolpath: &mut dyn EventSource, settings: &Settings) -> Report {
    interp::run(program, file, &mut expect::Records(toolpath), settings, &mut ())
}

/// [`verify`] against a toolpath given as [`expect::Record`]s.
pub fn verify_records(
    program: &mut dyn BufRead,
    file: FileId,
    toolpath: &mut dyn expect::RecordSource,
    settings: &Settings,
) -> Report {
    interp::run(program, file, toolpath, settings, &mut ())
}

/// One move of the program as the interpreter replayed it, in mm. A
/// coordinate the program has not set yet is NaN (the first moves, and Z
/// of programs that never write it).
#[derive(Clone, Copy, Debug)]
pub struct Move {
    pub kind: expect::Kind,
    pub start: [f64; 3],
    pub end: [f64; 3],
    /// The arc's centre (arcs only).
    pub centre: [f64; 3],
    pub dir: postc_ir::event::ArcDir,
    pub plane: postc_ir::event::Plane,
    /// The block in the program.
    pub span: postc_ir::Span,
}

/// Sees every program move as it is replayed (a backplot draws them);
/// called once per move, in order, before the move is compared.
pub trait Observer {
    fn motion(&mut self, m: &Move);
}

/// Observes nothing.
impl Observer for () {
    fn motion(&mut self, _: &Move) {}
}

/// [`verify`], showing each program move to `observer` as it is replayed.
pub fn verify_observed(
    program: &mut dyn BufRead,
    file: FileId,
    toolpath: &mut dyn EventSource,
    settings: &Settings,
    observer: &mut dyn Observer,
) -> Report {
    interp::run(program, file, &mut expect::Records(toolpath), settings, observer)
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/verify/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod grammar {
        pub use crate::grammar::{plain, scan_long};
    }
    pub mod interp {
        pub use crate::interp::{Block, replay, tenths, words_line};
    }
    pub mod plot {
        pub use crate::plot::nice_step;
    }
}
