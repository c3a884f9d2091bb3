//! The modal interpreter and the comparison with the toolpath.
//!
//! Each line is parsed by [`crate::grammar`]; the block's words set the
//! modal state of the RS274/NGC groups (motion, plane, units, distance
//! modes, feed mode, spindle, canned cycles) and its motion, if any, is
//! replayed in millimetres and compared with the expected path:
//!
//! 1. a move whose end point is the end of the next expected move (after
//!    expected moves it covers on its way, and expected rapids a rapid
//!    makes unnecessary) is that move: its kind, arc direction and centre,
//!    chord error, feed and spindle are checked;
//! 2. a move that ends on the next expected move is part of it (a split
//!    move, a chord of a linearized arc, a peck of a drilling cycle);
//! 3. any other rapid is the post's own (header, footer, tool change):
//!    it must not go below the toolpath's rapid heights into the material;
//! 4. any other cutting move is off the toolpath.

use postc_ir::codes;
use std::io::BufRead;

use postc_ir::event::{ArcDir, Intent, Plane};
use postc_ir::{Diagnostic, FileId, Severity, Span};

use crate::expect::{Expected, ExpectedPath, Kind, RecordSource};
use crate::geometry::{Arc, axes, dist, known, r_centre, to_segment};
use crate::grammar::{self, ItemKind, Items};
use crate::params::{self, Cycle, Note};
use crate::{Controller, MAX_SHOWN, Move, Observer, Report, Settings};

/// Longest line read; the rest of a longer line is skipped with a finding.
const MAX_LINE: usize = 64 * 1024;
/// Unreadable blocks before the first move after which a program is taken for another language.
pub const NOT_GCODE: u32 = 20;
/// How many expected moves one program move may cover or skip.
const LOOKAHEAD: usize = 64;

/// Counts of a verification.
#[derive(Clone, Copy, Debug, Default)]
pub struct Stats {
    pub lines: u64,
    pub motions: u64,
    /// Expected moves (toolpath moves, drilled holes counted as their moves).
    pub expected: u64,
    /// Expected moves the program made.
    pub matched: u64,
    /// The program's units at its end were inches (G20, or the post's).
    pub inch: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MKind {
    Rapid,
    Feed,
    Arc,
}

#[derive(Clone, Copy, Debug)]
struct Motion {
    kind: MKind,
    start: [f64; 3],
    end: [f64; 3],
    centre: [f64; 3],
    dir: ArcDir,
    plane: Plane,
    /// The R word of an R-form arc.
    r: Option<f64>,
    span: Span,
}

impl Motion {
    /// A straight move (a rapid or a feed) in `plane`.
    fn straight(kind: MKind, start: [f64; 3], end: [f64; 3], plane: Plane, span: Span) -> Motion {
        Motion { kind, start, end, centre: [f64::NAN; 3], dir: ArcDir::Cw, plane, r: None, span }
    }

    fn cutting(&self) -> bool {
        self.kind != MKind::Rapid
    }

    fn arc(&self) -> Arc {
        Arc { start: self.start, end: self.end, centre: self.centre, dir: self.dir, plane: self.plane }
    }
}

/// A word of the current block: value, decimals, span in the line.
#[derive(Clone, Copy, Debug)]
struct Word {
    value: f64,
    decimals: u8,
    start: u32,
    end: u32,
}

const MAX_CODES: usize = 8;

/// The words of one block: a word of letter L is in `letters[L - 'A']`
/// when bit `L - 'A'` of `present` is set.
#[doc(hidden)]
pub struct Block {
    letters: [Word; 26],
    present: u32,
    g: [(f64, u32, u32); MAX_CODES],
    gs: usize,
    m: [(f64, u32, u32); MAX_CODES],
    ms: usize,
    /// The most decimals of its X, Y and Z words ([`words_line`] only).
    decimals: Option<u8>,
}

impl Default for Block {
    fn default() -> Block {
        let word = Word { value: 0.0, decimals: 0, start: 0, end: 0 };
        Block {
            letters: [word; 26],
            present: 0,
            g: [(0.0, 0, 0); MAX_CODES],
            gs: 0,
            m: [(0.0, 0, 0); MAX_CODES],
            ms: 0,
            decimals: None,
        }
    }
}

impl Block {
    fn clear(&mut self) {
        self.present = 0;
        self.gs = 0;
        self.ms = 0;
    }

    fn has(&self, letter: u8) -> bool {
        self.present & (1 << (letter - b'A')) != 0
    }

    fn get(&self, letter: u8) -> Option<Word> {
        self.has(letter).then(|| self.letters[(letter - b'A') as usize])
    }

    /// Whether the block has a word of any of `letters`.
    fn any(&self, letters: &[u8]) -> bool {
        self.present & letters.iter().fold(0, |mask, l| mask | 1 << (l - b'A')) != 0
    }

    fn set(&mut self, letter: u8, word: Word) {
        self.letters[(letter - b'A') as usize] = word;
        self.present |= 1 << (letter - b'A');
    }
}

/// The letters verify reads, as bits of `letter - 'A'`.
const KNOWN_LETTERS: u32 = {
    let letters = b"NXYZABCIJKRFSTPQLHDOUVW";
    let mut mask = 0u32;
    let mut i = 0;
    while i < letters.len() {
        mask |= 1 << (letters[i] - b'A');
        i += 1;
    }
    mask
};

struct Run<'a, O: Observer + ?Sized> {
    settings: &'a Settings,
    /// Generic, so that the observer of a verification that draws nothing
    /// (`()`) costs nothing.
    observer: &'a mut O,
    /// Where each kept finding is (mm), parallel to `findings`.
    at: Vec<[f64; 3]>,
    /// The program line of each kept finding, parallel to `findings`.
    lines: Vec<(u64, usize)>,
    file: FileId,
    path: ExpectedPath<'a>,
    findings: Vec<Diagnostic>,
    shown: Vec<(&'static str, usize)>,
    errors: u64,
    warnings: u64,
    stats: Stats,
    line_start: usize,
    line_len: usize,
    /// The line's bytes before its line feed, carriage returns included
    /// (LinuxCNC counts them).
    line_bytes: usize,
    /// Bytes of the program read before the current line.
    offset: usize,
    // Modal state.
    unit: f64,
    units_stated: bool,
    units_reported: bool,
    absolute: bool,
    arc_absolute: bool,
    plane: Plane,
    motion: Option<u32>,
    /// The G0/G1 mode in force when a canned cycle began, which a Fanuc
    /// family control moves in after the cycle's G80.
    motion_before_cycle: Option<u32>,
    feed: f64,
    /// The feed's rounding as printed, mm/min.
    feed_step: f64,
    inverse_time: bool,
    /// G95: F is a feed per spindle revolution.
    per_rev: bool,
    /// G96: S is a surface speed, the spindle's rpm changes with the
    /// diameter (G97 ends it).
    css: bool,
    /// The toolpath's first tool is a lathe's turning tool: the program is
    /// read as a lathe program (docs/verify.md, "Lathe programs").
    lathe: bool,
    /// G7: X words are diameters (G8: radii). A lathe program starts in
    /// G7.
    diameter: bool,
    /// The last S word, revolutions a minute.
    speed: f64,
    spindle: bool,
    pos: [f64; 3],
    cycle_initial_z: f64,
    cycle_r: f64,
    cycle_z: f64,
    retract_to_r: bool,
    last_n: Option<f64>,
    first_n: Option<f64>,
    max_decimals: Option<u8>,
    stopped: bool,
    // Comparison state.
    progress: f64,
    no_feed_reported: bool,
    spindle_reported: bool,
    /// The spindle was switched on by `M3` with `S0` in the same block
    /// (`S0 M3`), and no S since gave it a speed.
    started_at_zero: bool,
    feed_reported: (f64, f64),
    /// The last surface speed difference reported (VF036), as `feed_reported`.
    surface_reported: (f64, f64),
    stop_comparing: bool,
    syntax_errors: u32,
    /// Lines read as named commands (Klipper's extended G-code), which
    /// count with the syntax errors toward VF001 until the tool moves.
    named_commands: u32,
    /// The tolerance ([`Run::tol`]) for the `units_key` it was computed at.
    tol: (f64, (f64, Option<u8>)),
    /// Lines of words only are read by [`words_line`] (the tests turn it
    /// off to hold it to the general path).
    fast: bool,
    /// The parameters the program sets, and the reader of lines beyond
    /// plain words ([`params`]).
    params: params::Reader,
    extras: params::Extras,
    /// The block being executed was read by [`params`]: its axis words may
    /// have values verify does not know, and `supa` may be set. Blocks of
    /// plain words never look further.
    extended: bool,
    /// The block's axis words are machine coordinates (Sinumerik `SUPA`).
    supa: bool,
    /// A Sinumerik cycle called modally (`MCALL CYCLE81(...)`), in mm:
    /// drilled after every block that moves the axes.
    mcall: Option<Cycle>,
    /// Moves to a position verify could not compute ([`Run::unknown_move`]):
    /// toolpath moves they may have made are not reported as missing.
    uncomputed: u64,
    /// The program is Heidenhain ISO (its `%name G71` line): I J K are the
    /// circle centre, G30/G31 the blank, `G83 P01 ...` defines a cycle that
    /// `M99` calls.
    heidenhain: bool,
    /// The last circle centre (Heidenhain ISO's I J K are modal), mm.
    centre: [f64; 3],
    /// The Heidenhain ISO cycle defined: its G code and parameters P01..P03
    /// (set-up clearance and depth, signed toward the work, mm).
    defined: Option<(u32, [f64; 3])>,
    /// The line of the last `%` (0: none yet).
    percent_line: u64,
    /// A program end (M2, M30) was read.
    ended: bool,
    /// In the header of a Boxford file (`[GM HEADER]` up to `[PROGRAM]`).
    boxford_header: bool,
    /// The program has written a Z word (in work or machine coordinates):
    /// a move with Z unknown after it is at a height verify does not know
    /// (G53, G28), not a move of a program that never writes Z.
    z_written: bool,
    /// Andronic's `G282 A1` is in force: positions are machine
    /// coordinates until `G282 A-1`.
    machine_frame: bool,
}

pub fn run<O: Observer + ?Sized>(
    program: &mut dyn BufRead,
    file: FileId,
    toolpath: &mut dyn RecordSource,
    settings: &Settings,
    observer: &mut O,
) -> Report {
    replay(program, file, toolpath, settings, observer, true)
}

/// [`run`]; `fast`: lines of words only are read by [`words_line`].
#[doc(hidden)]
pub fn replay<O: Observer + ?Sized>(
    program: &mut dyn BufRead,
    file: FileId,
    toolpath: &mut dyn RecordSource,
    settings: &Settings,
    observer: &mut O,
    fast: bool,
) -> Report {
    let mut run = Run {
        settings,
        observer,
        at: Vec::new(),
        lines: Vec::new(),
        file,
        path: ExpectedPath::new(toolpath),
        findings: Vec::new(),
        shown: Vec::new(),
        errors: 0,
        warnings: 0,
        stats: Stats::default(),
        line_start: 0,
        line_len: 0,
        line_bytes: 0,
        offset: 0,
        unit: settings.units.map_or(1.0, |u| u.mm_per_unit()),
        units_stated: false,
        units_reported: false,
        absolute: true,
        arc_absolute: false,
        plane: Plane::Xy,
        motion: None,
        motion_before_cycle: None,
        feed: f64::NAN,
        feed_step: 0.0,
        inverse_time: false,
        per_rev: false,
        css: false,
        lathe: false,
        diameter: false,
        speed: f64::NAN,
        spindle: false,
        pos: [f64::NAN; 3],
        cycle_initial_z: f64::NAN,
        cycle_r: f64::NAN,
        cycle_z: f64::NAN,
        retract_to_r: false,
        last_n: None,
        first_n: None,
        max_decimals: None,
        stopped: false,
        progress: 0.0,
        no_feed_reported: false,
        spindle_reported: false,
        started_at_zero: false,
        feed_reported: (f64::NAN, f64::NAN),
        surface_reported: (f64::NAN, f64::NAN),
        stop_comparing: false,
        syntax_errors: 0,
        named_commands: 0,
        tol: (f64::NAN, (f64::NAN, None)),
        fast,
        params: params::Reader::default(),
        extras: params::Extras::default(),
        extended: false,
        supa: false,
        mcall: None,
        uncomputed: 0,
        heidenhain: false,
        centre: [f64::NAN; 3],
        defined: None,
        percent_line: 0,
        ended: false,
        boxford_header: false,
        z_written: false,
        machine_frame: false,
    };
    let mut block = Block::default();
    run.path.apt_words = settings.apt_words;
    run.path.start();
    // A lathe program: X is a diameter and arcs turn in the ZX plane
    // until the program says otherwise (G8; G17, G19).
    if run.path.lathe == Some(true) {
        run.lathe = true;
        run.diameter = true;
        run.plane = Plane::Zx;
    }
    let mut items: Items = chumsky::inspector::TruncateState(Vec::with_capacity(32));
    let mut buf: Vec<u8> = Vec::with_capacity(256);
    loop {
        // A line whole in the reader's buffer is read where it is; one across
        // two buffers, or longer than MAX_LINE, is gathered into `buf`.
        let avail = match program.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => {
                run.read_error(&e);
                break;
            }
        };
        if avail.is_empty() {
            break;
        }
        // The lines of words only the buffer holds, one after the other.
        let mut used = 0;
        while run.fast
            && !run.stopped
            && !run.boxford_header
            && let Some(i) = words_line(&avail[used..], &mut block, run.settings.controller.word_digits())
        {
            run.words(&avail[used..used + i], i + 1, &block);
            used += i + 1;
        }
        if used > 0 {
            program.consume(used);
            continue;
        }
        if let Some(i) = memchr::arch::all::memchr::One::new(b'\n').find(avail).filter(|&i| i < MAX_LINE) {
            run.one_line(&avail[..i], i + 1, false, &mut items, &mut block);
            program.consume(i + 1);
            continue;
        }
        buf.clear();
        let (consumed, overlong) = match read_line(program, &mut buf) {
            Ok(r) => r,
            Err(e) => {
                run.read_error(&e);
                break;
            }
        };
        if consumed == 0 {
            break;
        }
        if buf.last() == Some(&b'\n') {
            buf.pop();
        }
        run.one_line(&buf, consumed, overlong, &mut items, &mut block);
    }
    run.finish();
    let mut stats = run.stats;
    stats.inch = run.unit > 1.0;
    let Run { findings, at, lines, errors, warnings, .. } = run;
    Report { findings, at, lines, errors, warnings, stats }
}

/// Reads a line of words only (each a letter, blanks and a number, with
/// blanks between them) from the start of `bytes` up to its `\n` into
/// `block`: the words [`grammar::parse_plain`] reads from such a line, put
/// in the block as [`Run::line`] puts them. The index of the `\n`; `None`
/// when the line holds anything else (a comment, `%`, `/`, bytes that are
/// not words), ends past `bytes` or [`MAX_LINE`], or has a word that gives
/// a finding in [`Run::line`] or a message (an M word, a second word of
/// one letter but G, a letter verify does not know, more digits than
/// `digits` when the controller has that limit): the general path reads
/// those lines.
#[doc(hidden)]
pub fn words_line(bytes: &[u8], block: &mut Block, digits: Option<usize>) -> Option<usize> {
    let bytes = &bytes[..bytes.len().min(MAX_LINE)];
    block.clear();
    // The most decimals of the X, Y and Z words, one more than it (0: none yet).
    let mut xyz = 0u8;
    let mut i = 0;
    loop {
        let b = *bytes.get(i)?;
        // `b & 0xDF` is the upper case of a letter and no letter for any other byte.
        let index = (b & 0xDF).wrapping_sub(b'A');
        if index >= 26 {
            match b {
                b' ' | b'\t' | b'\r' => {
                    i += 1;
                    continue;
                }
                b'\n' => {
                    block.decimals = xyz.checked_sub(1);
                    return Some(i);
                }
                _ => return None,
            }
        }
        if index == b'M' - b'A' {
            return None;
        }
        let start = i;
        i += 1;
        if bytes.get(i).is_some_and(|&c| c <= b' ') {
            while matches!(bytes.get(i), Some(b' ' | b'\t' | b'\r')) {
                i += 1;
            }
        }
        let (end, value, decimals) = grammar::scan_at(bytes, i)?;
        i = end;
        if let Some(limit) = digits
            && i - start > limit + 1
            && bytes[start..i].iter().filter(|b| b.is_ascii_digit()).count() > limit
        {
            return None;
        }
        let (start, end) = (start as u32, i as u32);
        if index == b'G' - b'A' {
            if block.gs < MAX_CODES {
                block.g[block.gs] = (value, start, end);
                block.gs += 1;
            }
            continue;
        }
        let bit = 1 << index;
        if block.present & bit != 0 || KNOWN_LETTERS & bit == 0 {
            return None;
        }
        block.present |= bit;
        block.letters[usize::from(index)] = Word { value, decimals, start, end };
        if XYZ & bit != 0 {
            xyz = xyz.max(decimals + 1);
        }
    }
}

/// X, Y and Z, as bits of `letter - 'A'`.
const XYZ: u32 = 1 << (b'X' - b'A') | 1 << (b'Y' - b'A') | 1 << (b'Z' - b'A');

/// Reads one line (up to and with its `\n`) into `buf`, keeping at most
/// [`MAX_LINE`] bytes; the bytes consumed and whether the line was longer.
fn read_line(r: &mut dyn BufRead, buf: &mut Vec<u8>) -> std::io::Result<(usize, bool)> {
    let (mut total, mut overlong) = (0, false);
    loop {
        let avail = match r.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if avail.is_empty() {
            return Ok((total, overlong));
        }
        let (take, done) = match avail.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (avail.len(), false),
        };
        let room = MAX_LINE.saturating_sub(buf.len());
        if take > room {
            overlong = true;
            buf.extend_from_slice(&avail[..room]);
        } else {
            buf.extend_from_slice(&avail[..take]);
        }
        r.consume(take);
        total += take;
        if done {
            return Ok((total, overlong));
        }
    }
}

fn fmt_point(p: [f64; 3]) -> String {
    let f = |v: f64| {
        if v.is_finite() {
            format!("{:.4}", v).trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            "?".into()
        }
    };
    format!("X{} Y{} Z{}", f(p[0]), f(p[1]), f(p[2]))
}

impl<O: Observer + ?Sized> Run<'_, O> {
    // ----- findings -----

    fn push(&mut self, d: Diagnostic, error: bool) {
        let at = self.pos;
        self.push_at(d, error, at);
    }

    /// A finding at a point of the path (mm): the move it concerns.
    fn push_at(&mut self, d: Diagnostic, error: bool, at: [f64; 3]) {
        if error {
            self.errors += 1;
        } else {
            self.warnings += 1;
        }
        let code = d.code;
        let shown = match self.shown.iter_mut().find(|(c, _)| *c == code) {
            Some((_, n)) => n,
            None => {
                self.shown.push((code, 0));
                &mut self.shown.last_mut().expect("just pushed").1
            }
        };
        *shown += 1;
        if *shown <= MAX_SHOWN {
            self.findings.push(d);
            self.at.push(at);
            self.lines.push((self.stats.lines, self.line_start));
        }
    }

    /// A finding at bytes `start..end` of the current line, with the
    /// toolpath move it concerns.
    fn finding(
        &mut self,
        severity: Severity,
        code: &'static str,
        message: impl Into<String>,
        start: usize,
        end: usize,
        expected: Option<&Expected>,
    ) -> Option<&mut Diagnostic> {
        let start = start.min(self.line_len);
        let end = end.min(self.line_len).max(start + usize::from(self.line_len > start));
        let span = Span::new(self.file, self.line_start + start, self.line_start + end);
        let mut d = Diagnostic::new(severity, code, message).at(span, "here");
        if let Some(e) = expected {
            d = d.also(e.span, "the toolpath move");
        }
        let before = self.findings.len();
        self.push(d, severity == Severity::Error);
        if self.findings.len() > before { self.findings.last_mut() } else { None }
    }

    fn help(d: Option<&mut Diagnostic>, help: impl Into<String>) {
        if let Some(d) = d {
            d.help = Some(help.into());
        }
    }

    fn whole_line(&self) -> Span {
        Span::new(self.file, self.line_start, self.line_start + self.line_len)
    }

    /// A finding on a motion (the whole block).
    fn motion_finding(
        &mut self,
        severity: Severity,
        code: &'static str,
        message: impl Into<String>,
        m: &Motion,
        expected: Option<&Expected>,
        help: Option<String>,
    ) {
        let mut d = Diagnostic::new(severity, code, message).at(m.span, "this move");
        if let Some(e) = expected {
            d = d.also(e.span, "the toolpath move it should make");
        }
        d.help = help;
        self.push(d, severity == Severity::Error);
    }

    /// The program cannot be read on from here.
    fn read_error(&mut self, e: &std::io::Error) {
        self.line_start = self.offset;
        self.line_len = 0;
        let d = Diagnostic::error(codes::VF002, format!("cannot read the program: {e}"));
        self.push(d, true);
    }

    /// One line of the program, without its `\n`; `consumed` is its length
    /// in the program, `\n` included.
    fn one_line(&mut self, line: &[u8], consumed: usize, overlong: bool, items: &mut Items, block: &mut Block) {
        self.line_start = self.offset;
        self.offset += consumed;
        self.stats.lines += 1;
        self.line_bytes = line.len();
        let mut line = line;
        while let [rest @ .., b'\n' | b'\r'] = line {
            line = rest;
        }
        self.line_len = line.len();
        if overlong {
            self.finding(
                Severity::Error,
                codes::VF003.code,
                format!("this line is longer than {} KiB; verify skipped it", MAX_LINE / 1024),
                0,
                1,
                None,
            );
            return;
        }
        if self.stopped {
            return;
        }
        // A Boxford file: a header of `key=value` lines from `[GM HEADER]`
        // (its first line) up to `[PROGRAM]`, then the program.
        if self.stats.lines == 1 && line.trim_ascii() == b"[GM HEADER]" {
            self.boxford_header = true;
        }
        if self.boxford_header {
            if line.trim_ascii() == b"[PROGRAM]" {
                self.boxford_header = false;
            }
            return;
        }
        // A plain line (words, blanks, simple comments) holds no NUL byte.
        let plain = grammar::parse_plain(line, items);
        if !plain && line.contains(&0) {
            self.finding(
                Severity::Error,
                codes::VF002.code,
                "this line holds binary data (NUL bytes), not G-code",
                0,
                1,
                None,
            );
            return;
        }
        self.line(line, items, block, plain);
    }

    /// A line of words only, read into `block` by [`words_line`]: what
    /// [`Run::one_line`] and [`Run::line`] do with such a line, which has no
    /// comment, no NUL byte and no M word (so no message), one word of each
    /// letter but G, only letters verify knows, and no word longer than the
    /// controller reads (so the words give no finding of their own).
    fn words(&mut self, line: &[u8], consumed: usize, block: &Block) {
        self.line_start = self.offset;
        self.offset += consumed;
        self.stats.lines += 1;
        self.line_bytes = line.len();
        let mut text = line;
        while let [rest @ .., b'\r'] = text {
            text = rest;
        }
        self.line_len = text.len();
        if let Some(d) = block.decimals {
            self.max_decimals = Some(self.max_decimals.map_or(d, |m| m.max(d)));
        }
        self.block_length(text);
        self.execute_block(block);
    }

    // ----- tolerances -----

    fn tol(&mut self) -> f64 {
        // Without the post, the program's own rounding: the most decimals its
        // X Y Z words have shown, but no coarser than three decimals.
        let key = (self.unit, self.max_decimals);
        if self.tol.1 != key {
            let decimals = self.settings.decimals.unwrap_or(self.max_decimals.unwrap_or(3).max(3));
            let unit = self.settings.units.map_or(self.unit, |u| u.mm_per_unit());
            self.tol = (self.settings.tolerance.max(1.0 / grammar::pow10(u32::from(decimals)) * unit + 1e-6), key);
        }
        self.tol.0
    }

    // ----- blocks -----

    /// A block; `plain`: `items` already holds the items of all of `text`.
    fn line(&mut self, text: &[u8], items: &mut Items, block: &mut Block, plain: bool) {
        // Marlin's M117/M118 show the rest of the line as a message.
        let (text, message) = match message_word(text) {
            Some(k) => (&text[..k], Some(k)),
            None => (text, None),
        };
        let mut parsed = if plain && message.is_none() { Ok(()) } else { grammar::parse(text, items) };
        // Marlin's M0/M1 take a message too: `M0 Load the 6 mm end mill`.
        if let Err(at) = parsed
            && message.is_none()
            && let Some(k) = stop_with_message(&text[..at.min(text.len())])
        {
            parsed = grammar::parse(&text[..k], items);
        }
        if parsed.is_err() && self.path.inserted(text) {
            // The toolpath's own text, written as it asked: not a fault of
            // the post, but a controller may stop at it.
            let d = self.finding(
                Severity::Warning,
                codes::VF004.code,
                "this line is text the toolpath inserts as it is, and it does not read as G-code",
                0,
                text.len(),
                None,
            );
            Self::help(
                d,
                "a controller may stop at it: make it a comment in the CAM system, if it is not meant for the controller",
            );
            return;
        }
        // Parameters, expressions and the statements of the macro and
        // Sinumerik families: only for a line the grammar does not read.
        let mut extended = false;
        if parsed.is_err() && self.params.line(text, &mut items.0, &mut self.extras).is_ok() {
            parsed = Ok(());
            extended = true;
        }
        if parsed.is_err() && self.marker(text) {
            return;
        }
        if let Err(at) = parsed {
            let (message, help) = match text.get(at) {
                None if text.contains(&b'(') && !text.contains(&b')') => {
                    ("this comment is not closed".to_string(), "close it with `)` on the same line")
                }
                None => (
                    "the block ends where a number is expected".into(),
                    "every word is a letter and a number, as `X1.5`",
                ),
                Some(b) if b.is_ascii_digit() || *b == b'.' || *b == b'-' => {
                    ("a number without a letter".into(), "every word is a letter and a number, as `X1.5`")
                }
                Some(b) if b.is_ascii_alphabetic() => (
                    format!("`{}` is not followed by a number", *b as char),
                    "every word is a letter and a number, as `X1.5`",
                ),
                Some(&b) if b.is_ascii_graphic() => (
                    format!(
                        "unexpected `{}`: this is no word, comment, parameter or statement verify reads",
                        b as char
                    ),
                    "verify reads words, ( ) and ; comments, block delete, `%`, `#` and R parameters, [ ] expressions and the Sinumerik statements of docs/verify.md",
                ),
                Some(&b) => (
                    format!("unexpected byte 0x{b:02X} in a block"),
                    "the program holds bytes that are not G-code text",
                ),
            };
            let d = self.finding(Severity::Error, codes::VF004.code, message, at, at + 1, None);
            Self::help(d, help);
            self.syntax_errors += 1;
            self.not_gcode();
            return;
        }
        self.block_length(text);
        let word_digits = self.settings.controller.word_digits();
        block.clear();
        for item in items.iter() {
            let (start, end) = (item.start as usize, item.end as usize);
            if let (Some(limit), ItemKind::Word(letter)) = (word_digits, item.kind)
                && end - start > limit + 1
            {
                self.word_digits(&text[start..end], letter, limit, start, end);
            }
            match item.kind {
                ItemKind::Comment => self.comment(&text[start..end], start),
                ItemKind::Delete => {}
                ItemKind::Percent => self.percent(&text[start..end]),
                ItemKind::Word(letter) => {
                    let w = Word { value: item.value, decimals: item.decimals, start: item.start, end: item.end };
                    // A word whose value is a parameter the program never set: an
                    // axis word leaves its axis unknown (the block says, when it
                    // moves); any other is ignored.
                    if extended && w.value.is_nan() && !matches!(letter, b'X' | b'Y' | b'Z') {
                        let d = self.finding(
                            Severity::Warning,
                            codes::VF005.code,
                            format!(
                                "verify does not know the value of this {} word (a parameter the program does not set); it is ignored",
                                letter as char
                            ),
                            start,
                            end,
                            None,
                        );
                        Self::help(
                            d,
                            "the controller reads the value from its own parameters; verify cannot check what it does",
                        );
                        continue;
                    }
                    match letter {
                        b'G' => {
                            if block.gs < MAX_CODES {
                                block.g[block.gs] = (w.value, w.start, w.end);
                                block.gs += 1;
                            }
                        }
                        b'M' => {
                            if block.ms < MAX_CODES {
                                block.m[block.ms] = (w.value, w.start, w.end);
                                block.ms += 1;
                            }
                        }
                        _ => {
                            let cycle = block.g[..block.gs].iter().any(|g| matches!(tenths(g.0), 730 | 810..=890));
                            if block.has(letter) && letter == b'R' && cycle {
                                // A cycle with two R planes (OSAI's `G82 R2. R5. Z4.`): a
                                // control's own form, which verify does not read.
                                if !self.stop_comparing {
                                    let d = self.finding(
                                        Severity::Note,
                                        codes::VF044.code,
                                        "this drilling cycle has two R words, a controller's own cycle form that verify does not read: the moves from here on are not compared",
                                        start,
                                        end,
                                        None,
                                    );
                                    Self::help(
                                        d,
                                        "the program is verified up to this line; the rest is read for its syntax only",
                                    );
                                    self.stop_comparing = true;
                                }
                            } else if block.has(letter) {
                                let d = self.finding(
                                    Severity::Error,
                                    codes::VF004.code,
                                    format!("a second {} word in one block", letter as char),
                                    start,
                                    end,
                                    None,
                                );
                                Self::help(d, "a controller reads one word of each letter per block");
                            }
                            block.set(letter, w);
                            if KNOWN_LETTERS & (1 << (letter - b'A')) == 0 {
                                let d = self.finding(
                                    Severity::Warning,
                                    codes::VF005.code,
                                    format!("verify does not know the {} word; it is ignored", letter as char),
                                    start,
                                    end,
                                    None,
                                );
                                Self::help(d, "a controller that does not know it either refuses the block");
                            }
                            if matches!(letter, b'X' | b'Y' | b'Z') && !extended {
                                self.max_decimals = Some(self.max_decimals.map_or(w.decimals, |d| d.max(w.decimals)));
                            }
                        }
                    }
                }
            }
        }
        if extended {
            self.statements(text);
            if self.extras.parameters && self.heidenhain {
                self.define_cycle(block);
            }
        }
        self.extended = extended;
        self.execute_block(block);
        self.extended = false;
        if self.heidenhain && block.m[..block.ms].iter().any(|m| tenths(m.0) == 990) {
            self.heidenhain_cycle();
        }
        if extended && let Some(cycle) = self.extras.cycle.take() {
            let cycle = self.cycle_in_mm(cycle);
            if cycle.modal {
                self.mcall = Some(cycle);
            } else {
                self.sinumerik_cycle(&cycle);
            }
        }
    }

    /// VF001, and the end of the replay, when [`NOT_GCODE`] blocks have
    /// not read as G-code (or were named commands, Klipper's form, which
    /// a program of another family's `NAME X=1` lines also reads as) and
    /// none has moved the tool.
    fn not_gcode(&mut self) {
        if self.syntax_errors + self.named_commands >= NOT_GCODE && self.stats.motions == 0 && !self.stopped {
            let d = self.finding(
                Severity::Error,
                codes::VF001.code,
                format!("{NOT_GCODE} blocks could not be read as G-code (or were named commands) and none moved the tool: this is not a G-code program; verify stops here"),
                0,
                self.line_len,
                None,
            );
            Self::help(d, format!("verify reads {}", crate::FAMILIES));
            self.stopped = true;
            self.stop_comparing = true;
        }
    }

    /// The statements of a line read by [`params`], before its block runs:
    /// what verify does not replay is a warning that names it; `SUPA` and
    /// the end of a modal call take effect.
    fn statements(&mut self, text: &[u8]) {
        self.supa = self.extras.machine;
        if self.extras.mcall_off {
            self.mcall = None;
        }
        for i in 0..self.extras.notes.len() {
            let (note, start, end, word) = self.extras.notes[i];
            if note == Note::Macro {
                self.named_commands += 1;
                self.not_gcode();
                if self.stopped {
                    continue;
                }
            }
            let (message, help) = match note {
                Note::Flow => (
                    format!("verify reads the program line by line and does not follow `{word}` (a jump, loop, condition or subroutine)"),
                    "the moves are compared in the order they are written; a program whose jumps repeat or skip moves may show findings where the machine has none",
                ),
                Note::NotReplayed => (
                    format!("verify does not replay `{}` ({word}); the moves after it are compared as written",
                        name_at(text, start as usize)),
                    "a frame that shifts, rotates or scales the coordinates makes the moves after it differ from the toolpath",
                ),
                Note::Macro => (
                    format!("verify does not replay `{}` ({word}); the moves after it are compared as written",
                        name_at(text, start as usize)),
                    "what the command or the machine's macro does is in the firmware and its configuration, not in the program: its own moves are not compared",
                ),
                Note::Call => {
                    let d = self.finding(
                        Severity::Note,
                        codes::VF044.code,
                        format!("verify does not follow `{word}` (a call or definition of a block or subroutine, whose moves run in another order than they are written): the moves from here on are not compared"),
                        start as usize,
                        end as usize,
                        None,
                    );
                    Self::help(d, "the program is verified up to this line; the rest is read for its syntax only");
                    self.stop_comparing = true;
                    continue;
                }
                Note::UnknownValue => (
                    "verify does not know the value this parameter is set to (it uses a parameter the program does not set)".to_string(),
                    "words that use this parameter are not compared",
                ),
            };
            let d = self.finding(Severity::Warning, codes::VF005.code, message, start as usize, end as usize, None);
            Self::help(d, help);
        }
    }

    /// Lines that are no block but mark the program, as two families
    /// write them: Okuma OSP's program name (a bare name of letters and
    /// digits on the line after the opening `%`, before any move: Okuma's
    /// posts write `%`, then the name, which must not start with the
    /// reserved `O`), and Hurco's `E`, the end of the program file, on a
    /// line of its own after the program's M2 or M30.
    fn marker(&self, text: &[u8]) -> bool {
        let t = text.trim_ascii();
        let name = self.percent_line > 0
            && self.stats.lines == self.percent_line + 1
            && self.stats.motions == 0
            && (1..=16).contains(&t.len())
            && t.iter().all(u8::is_ascii_alphanumeric);
        name || (t == b"E" && self.ended)
    }

    /// A `%` line: `%1001 G71`, the start (and end) of a Heidenhain ISO
    /// program, says the family and its units.
    fn percent(&mut self, text: &[u8]) {
        self.percent_line = self.stats.lines;
        let name = text[1..].iter().take_while(|b| b.is_ascii_alphanumeric() || **b == b'_').count();
        let rest = std::str::from_utf8(&text[1 + name..]).unwrap_or("").trim().to_ascii_uppercase();
        let inch = match rest.split_whitespace().next() {
            Some("G70") => true,
            Some("G71") => false,
            _ => return,
        };
        if name == 0 {
            return;
        }
        self.heidenhain = true;
        self.unit = if inch { 25.4 } else { 1.0 };
        self.units_stated = true;
    }

    /// A Heidenhain ISO cycle definition (`G83 P01 -4. P02 -8. ...`): its G
    /// code is no motion mode; the cycle runs where `M99` calls it.
    fn define_cycle(&mut self, block: &mut Block) {
        let Some(i) = block.g[..block.gs].iter().position(|g| matches!(tenths(g.0), 830 | 840 | 850 | 860)) else {
            return;
        };
        let code = tenths(block.g[i].0);
        block.g.copy_within(i + 1..block.gs, i);
        block.gs -= 1;
        let p = self.extras.p;
        self.defined = Some((code, [p[0] * self.unit, p[1] * self.unit, p[2] * self.unit]));
    }

    /// The Heidenhain ISO cycle defined, called by `M99` where the block
    /// ends, as the TNC's DIN/ISO pecking and tapping cycles (G83, G84,
    /// G85) run: from the start position, set-up clearance (P01) above the
    /// surface, a feed to the depth (P02, from the surface), then back to
    /// the start, at rapid (G83) or at the feed (tapping).
    fn heidenhain_cycle(&mut self) {
        let Some((code, [setup, depth, _])) = self.defined else {
            self.finding(
                Severity::Error,
                codes::VF024.code,
                "M99 calls a cycle, but no cycle (G83 P01 ...) is defined",
                0,
                self.line_len,
                None,
            );
            return;
        };
        let [x, y, z0] = self.pos;
        let bottom = z0 + setup + depth;
        if !bottom.is_finite() {
            self.finding(
                Severity::Error,
                codes::VF024.code,
                "a cycle without its set-up clearance and depth (P01, P02)",
                0,
                self.line_len,
                None,
            );
            return;
        }
        let span = self.whole_line();
        let make = |kind, start, end| Motion::straight(kind, start, end, Plane::Xy, span);
        self.emit(make(MKind::Feed, self.pos, [x, y, bottom]));
        let out = if code == 830 { MKind::Rapid } else { MKind::Feed };
        self.emit(make(out, self.pos, [x, y, z0]));
    }

    /// A Sinumerik cycle's planes in mm.
    fn cycle_in_mm(&self, c: Cycle) -> Cycle {
        let u = self.unit;
        Cycle { rtp: c.rtp * u, rfp: c.rfp * u, sdis: c.sdis * u, dp: c.dp * u, dpr: c.dpr * u, ..c }
    }

    /// A Sinumerik drilling cycle (`CYCLE81`..`CYCLE89`, `CYCLE840`) at the
    /// current position, as Siemens' cycle documentation describes it: a
    /// rapid to the reference plane plus the safety distance (RFP + SDIS),
    /// a feed to the final depth (DP, or RFP - DPR when DPR is given, which
    /// then wins), for the tapping and reaming cycles (84, 840, 85, 89) a
    /// feed back to RFP + SDIS, and a rapid to the return plane (RTP).
    fn sinumerik_cycle(&mut self, c: &Cycle) {
        let depth = if c.dpr.is_finite() { c.rfp - c.dpr.abs() } else { c.dp };
        let span = Span::new(self.file, self.line_start + c.start as usize, self.line_start + c.end as usize);
        if !(c.rtp.is_finite() && c.rfp.is_finite() && depth.is_finite()) {
            self.finding(
                Severity::Error,
                codes::VF024.code,
                format!("CYCLE{} without its return plane, reference plane and depth (RTP, RFP, DP or DPR)", c.number),
                c.start as usize,
                c.end as usize,
                None,
            );
            return;
        }
        let start = c.rfp + if c.sdis.is_finite() { c.sdis.abs() } else { 0.0 };
        let [x, y, _] = self.pos;
        let make = |kind, start, end| Motion::straight(kind, start, end, Plane::Xy, span);
        self.emit(make(MKind::Rapid, self.pos, [x, y, start]));
        self.emit(make(MKind::Feed, self.pos, [x, y, depth]));
        if matches!(c.number, 84 | 840 | 85 | 89) {
            self.emit(make(MKind::Feed, self.pos, [x, y, start]));
        }
        self.emit(make(MKind::Rapid, self.pos, [x, y, c.rtp]));
    }

    /// A word whose number has more digits than the controller reads
    /// (VF043).
    fn word_digits(&mut self, word: &[u8], letter: u8, limit: usize, start: usize, end: usize) {
        let digits = word.iter().filter(|b| b.is_ascii_digit()).count();
        if digits > limit {
            let name = self.settings.controller.name();
            let d = self.finding(
                Severity::Error,
                codes::VF043.code,
                format!(
                    "this {} word has {digits} digits; {name} reads at most {limit} (alarm \"TOO MANY DIGITS\")",
                    letter as char
                ),
                start,
                end,
                None,
            );
            Self::help(
                d,
                "a number this long is no position or feed a machine has: check the toolpath and the post's format",
            );
        }
    }

    /// A block longer than the controller reads (VF043).
    #[inline]
    fn block_length(&mut self, text: &[u8]) {
        let Some((limit, all_count)) = self.settings.controller.block_length() else { return };
        let bytes = if all_count { self.line_bytes.max(text.len()) } else { text.len() };
        if bytes > limit {
            self.long_block(text, limit, all_count, bytes);
        }
    }

    fn long_block(&mut self, text: &[u8], limit: usize, all_count: bool, bytes: usize) {
        let length = if all_count { bytes } else { counted_length(text) };
        if length > limit {
            let name = self.settings.controller.name();
            let what = if all_count { "characters" } else { "characters besides blanks and comments" };
            let d = self.finding(
                Severity::Error,
                codes::VF043.code,
                format!("this block has {length} {what}; {name} reads at most {limit}"),
                limit,
                text.len(),
                None,
            );
            Self::help(
                d,
                "a word this long is no position or feed a machine has: check the toolpath and the post's format",
            );
        }
    }

    fn comment(&mut self, text: &[u8], start: usize) {
        let controller = self.settings.controller;
        let strict = matches!(controller, Controller::Fanuc | Controller::Haas | Controller::Grbl);
        if text.first() == Some(&b';') && matches!(controller, Controller::Fanuc | Controller::Haas) {
            let d = self.finding(
                Severity::Error,
                codes::VF042.code,
                format!("{} reads `;` as the end of a block, not as a comment", controller.name()),
                start,
                start + 1,
                None,
            );
            Self::help(d, "write the comment in parentheses");
            return;
        }
        let body = if text.first() == Some(&b'(') { &text[1..text.len().saturating_sub(1)] } else { &text[1..] };
        if text.first() == Some(&b'(')
            && let Some(i) = body.iter().position(|&b| b == b'(')
        {
            let (severity, what) = match controller {
                Controller::Generic => (Severity::Warning, "LinuxCNC, Fanuc, Haas and grbl refuse".to_string()),
                c => (Severity::Error, format!("{} refuses", c.name())),
            };
            let d = self.finding(
                severity,
                codes::VF042.code,
                format!("{what} a `(` inside a comment"),
                start + 1 + i,
                start + 2 + i,
                None,
            );
            Self::help(d, "the post should replace `(` in comment text (Vectric: SUBSTITUTE)");
            return;
        }
        if let Some(i) = body.iter().position(|&b| b < 32 && b != b'\t' || b == 127) {
            self.finding(
                Severity::Error,
                codes::VF042.code,
                "a control character in a comment",
                start + 1 + i,
                start + 2 + i,
                None,
            );
            return;
        }
        if matches!(controller, Controller::Fanuc | Controller::Haas)
            && let Some(i) = body.iter().position(|&b| b == b'%')
        {
            let d = self.finding(
                Severity::Error,
                codes::VF042.code,
                format!("{} reads `%` as the end of the program, even in a comment", controller.name()),
                start + 1 + i,
                start + 2 + i,
                None,
            );
            Self::help(d, "the post should replace `%` in comment text");
            return;
        }
        if let Some(i) = body.iter().position(|&b| b >= 128) {
            let severity = if strict { Severity::Error } else { Severity::Warning };
            let d = self.finding(
                severity,
                codes::VF042.code,
                format!("a character outside ASCII in a comment; {} may refuse it", controller.name()),
                start + 1 + i,
                start + 2 + i,
                None,
            );
            Self::help(d, "the post should replace accented and other non-ASCII characters in comment text");
        }
    }

    fn execute_block(&mut self, b: &Block) {
        // Block number.
        if let Some(n) = b.get(b'N') {
            self.block_number(n);
        }
        // G codes that set modes, in the RS274/NGC order of execution.
        let mut home = false;
        let mut machine = self.extended && self.supa;
        let mut dwell = false;
        // A lathe's `G50 S` (Fanuc G code system A) or `G92 S` (systems B
        // and C), with no axis word, clamps the spindle's speed: its S is
        // no speed to run at.
        let clamp = self.lathe
            && !b.any(b"XYZ")
            && b.has(b'S')
            && b.g[..b.gs].iter().any(|&(code, ..)| matches!(tenths(code), 500 | 920));
        for &(code, start, end) in &b.g[..b.gs] {
            let tenths = tenths(code);
            match tenths {
                0 | 10 | 20 | 30 | 810..=890 | 730 | 740 | 760 => {
                    let cycle = |m: u32| (810..=890).contains(&m) || matches!(m, 730 | 740 | 760);
                    if cycle(tenths) && !self.motion.is_some_and(cycle) {
                        self.cycle_initial_z = self.pos[2];
                        self.motion_before_cycle = self.motion.filter(|m| *m == 0 || *m == 10);
                    }
                    self.motion = Some(tenths);
                }
                // Fagor's deep drilling cycle (8055 manual, "G69: complex deep
                // hole drilling"), in Fagor's form `G69 X Y Z I B ...` (Z the
                // reference plane, I the depth, B the peck): drilled as G83.
                // Fanuc's G69 (rotation off) takes no Z and I.
                690 if b.has(b'Z') && b.has(b'I') && !b.has(b'R') => {
                    if !self.motion.is_some_and(|m| (810..=890).contains(&m) || matches!(m, 730 | 740 | 760)) {
                        self.cycle_initial_z = self.pos[2];
                        self.motion_before_cycle = self.motion.filter(|m| *m == 0 || *m == 10);
                    }
                    self.motion = Some(830);
                }
                800 => {
                    // The G0/G1 of before the cycle is kept only when G80 ends a cycle.
                    if self.motion.is_none_or(|m| m < 730) {
                        self.motion_before_cycle = None;
                    }
                    self.motion = None;
                }
                40 => dwell = true,
                // LinuxCNC's lathe modes: X a diameter (G7) or a radius (G8).
                70 => self.diameter = true,
                80 => self.diameter = false,
                // Constant surface speed on (G96) and off (G97).
                960 => self.css = true,
                970 => self.css = false,
                170 => self.plane = Plane::Xy,
                180 => self.plane = Plane::Zx,
                190 => self.plane = Plane::Yz,
                200 | 210 | 700 | 710 | 7000 | 7100 => {
                    // G20/G21, G70/G71 of the ISO dialects (Heidenhain, Siemens, NUM), Sinumerik's G700/G710.
                    let inch = matches!(tenths, 200 | 700 | 7000);
                    self.unit = if inch { 25.4 } else { 1.0 };
                    self.units_stated = true;
                    if let Some(units) = self.settings.units
                        && (units == postc_ir::Units::Inch) != inch
                    {
                        let post = self.settings.post.as_deref().unwrap_or("the post");
                        let d = self.finding(
                            Severity::Error,
                            codes::VF031.code,
                            format!(
                                "the program says {} but {post} writes {}",
                                if inch { "inches (G20/G70)" } else { "millimetres (G21/G71)" },
                                if inch { "millimetres" } else { "inches" }
                            ),
                            start as usize,
                            end as usize,
                            None,
                        );
                        Self::help(d, "the units word must match the units the post prints its numbers in");
                    }
                }
                // Heidenhain ISO: G30/G31 define the blank (its corners).
                300 | 310 if self.heidenhain => dwell = true,
                280 | 300 | 382..=385 => home = true,
                530 | 1530 => machine = true,
                // Andronic: `G282 A1` machine coordinates, `G282 A-1` the part's
                // (Autodesk's `andronic.cps`: "machine coordinate system", "part
                // coordinate system"), modal.
                2820 if b.has(b'A') => {
                    self.machine_frame = b.get(b'A').is_some_and(|a| a.value > 0.0);
                }
                400 | 410 | 420 | 430 | 431 | 490 | 540..=599 | 610 | 611 | 640 | 150 | 500 | 510 | 641 => {}
                // Sinumerik: G500 and G505-G599 settable frames, G60/G601/G602
                // exact stop, G642 smoothing, G450/G451 corners.
                5000 | 5050..=5990 | 600 | 6010 | 6020 | 6420 | 4500 | 4510 => {}
                100 => dwell = true,
                900 => self.absolute = true,
                910 => self.absolute = false,
                901 => self.arc_absolute = true,
                911 => self.arc_absolute = false,
                930 => {
                    self.inverse_time = true;
                    self.per_rev = false;
                }
                940 => {
                    self.inverse_time = false;
                    self.per_rev = false;
                }
                950 => {
                    self.inverse_time = false;
                    self.per_rev = true;
                }
                // A lathe's G98 and G99 are feeds per minute and per
                // revolution (Fanuc's and Haas' lathe G codes).
                980 | 990 if self.lathe => {
                    self.inverse_time = false;
                    self.per_rev = tenths == 990;
                }
                980 => self.retract_to_r = false,
                990 => self.retract_to_r = true,
                920 if clamp => {}
                920..=923 => {
                    let d = self.finding(
                        Severity::Warning,
                        codes::VF008.code,
                        "verify does not replay G92 coordinate offsets; positions after it are not compared",
                        start as usize,
                        end as usize,
                        None,
                    );
                    Self::help(d, "posts that shift coordinates with G92 are verified without the shift");
                    self.pos = [f64::NAN; 3];
                    dwell = true;
                }
                _ => {
                    let d = self.finding(
                        Severity::Warning,
                        codes::VF005.code,
                        format!("verify does not know G{}; it is ignored", format_code(code)),
                        start as usize,
                        end as usize,
                        None,
                    );
                    Self::help(d, "a controller that does not know it refuses the block");
                }
            }
        }
        // Feed, spindle, tool change.
        if let Some(f) = b.get(b'F')
            && !self.inverse_time
            && !dwell
        {
            self.feed = f.value * self.unit / self.settings.feed_multiplier;
            self.feed_step = 1.0 / grammar::pow10(u32::from(f.decimals)) * self.unit / self.settings.feed_multiplier;
        }
        if let Some(s) = b.get(b'S')
            && !clamp
        {
            self.speed = s.value;
            // `S0 M3`: switched on at no speed (M4 S0 is a laser's dynamic
            // power, M84 S0 or M300 S440 are no speed at all).
            self.started_at_zero = s.value == 0.0 && b.m[..b.ms].iter().any(|&(code, _, _)| tenths(code) == 30);
        }
        for &(code, start, end) in &b.m[..b.ms] {
            match tenths(code) {
                30 | 40 | 130 | 140 | 1060 | 620 | 640 => {
                    if !self.spindle {
                        self.spindle_reported = false;
                    }
                    self.spindle = true;
                }
                50 | 1070 | 630 | 650 => self.spindle = false,
                60 => self.tool_change(start, end),
                // `M98 P1234`: a subprogram call, whose moves run where the
                // subprogram is, not where the call is written.
                980 if b.has(b'P') && !self.stop_comparing => {
                    let d = self.finding(
                        Severity::Note,
                        codes::VF044.code,
                        "verify does not follow `M98` (a call of a subprogram, whose moves run in another order than they are written): the moves from here on are not compared",
                        start as usize,
                        end as usize,
                        None,
                    );
                    Self::help(d, "the program is verified up to this line; the rest is read for its syntax only");
                    self.stop_comparing = true;
                }
                20 | 300 => {
                    // The end of the program (or of a tape part): what follows
                    // is read as the next part, from the modes a program starts in.
                    self.ended = true;
                    self.spindle = false;
                    self.motion = None;
                    self.absolute = true;
                    self.inverse_time = false;
                    self.per_rev = false;
                    self.css = false;
                    self.diameter = self.lathe;
                }
                _ => {}
            }
        }
        // Motion.
        if dwell {
            return; // G4, G10 and G92 read the block's axis words as their own arguments
        }
        let any_axis = b.any(b"XYZ");
        self.z_written |= b.has(b'Z');
        machine |= self.machine_frame;
        if home {
            // G28/G30 (through the given point to a home position) and G38.x
            // probes end where verify cannot know.
            let axes_given = [b'X', b'Y', b'Z'].map(|l| b.has(l));
            for (i, given) in axes_given.iter().enumerate() {
                if *given || !any_axis {
                    self.pos[i] = f64::NAN;
                }
            }
            return;
        }
        if machine {
            // G53: machine coordinates; the work position is unknown on those axes.
            for (i, l) in [b'X', b'Y', b'Z'].iter().enumerate() {
                if b.has(*l) {
                    self.pos[i] = f64::NAN;
                }
            }
            return;
        }
        let has_ijkr = b.any(b"IJKR");
        if !(any_axis || has_ijkr && matches!(self.motion, Some(20 | 30))) {
            return;
        }
        let before_cycle = if self.motion.is_none() { self.motion_before_cycle.take() } else { None };
        let motion = match (self.motion, before_cycle) {
            (Some(m), _) => m,
            // After a cycle's G80, a Fanuc family control moves in the G0
            // or G1 of before the cycle (its own modal group); LinuxCNC
            // refuses the block.
            (None, Some(before)) => {
                self.finding(
                    Severity::Warning,
                    codes::VF005.code,
                    format!(
                        "axis words with no motion mode after G80: a Fanuc family control moves in the G{} of before the cycle, LinuxCNC refuses this block",
                        before / 10
                    ),
                    0,
                    self.line_len,
                    None,
                );
                self.motion = Some(before);
                before
            }
            (None, None) => {
                self.finding(
                    Severity::Warning,
                    codes::VF005.code,
                    "axis words with no motion mode (after G80 or before any G0/G1); a controller refuses this block",
                    0,
                    self.line_len,
                    None,
                );
                return;
            }
        };
        if !self.units_stated && !self.units_reported {
            self.units_reported = true;
            let unit = if self.unit > 1.0 { "inches" } else { "millimetres" };
            let d = self.finding(
                Severity::Warning,
                codes::VF032.code,
                format!("the program moves before it says G20 or G21; verify reads it in {unit}"),
                0,
                self.line_len,
                None,
            );
            Self::help(d, "a controller uses whatever units were last active; state them in the header");
        }
        let mut target = self.pos;
        // A lathe's tool stays on the spindle's centre plane: Y is 0 until
        // the program moves a Y axis.
        if self.lathe && target[1].is_nan() {
            target[1] = 0.0;
        }
        for (i, l) in [b'X', b'Y', b'Z'].iter().enumerate() {
            if let Some(w) = b.get(*l) {
                let mut v = w.value * self.unit;
                // In diameter mode the X word is twice the radius the tool goes to.
                if i == 0 && self.diameter {
                    v /= 2.0;
                }
                target[i] = if self.absolute { v } else { self.pos[i] + v };
            }
        }
        if self.extended && [b'X', b'Y', b'Z'].iter().any(|l| b.get(*l).is_some_and(|w| w.value.is_nan())) {
            self.unknown_move(target);
            return;
        }
        let span = self.whole_line();
        match motion {
            0 => self.emit(Motion::straight(MKind::Rapid, self.pos, target, self.plane, span)),
            10 => self.emit(Motion::straight(MKind::Feed, self.pos, target, self.plane, span)),
            20 | 30 => self.arc(b, motion == 20, target, span),
            _ => self.cycle(b, motion, target, span),
        }
        if let Some(cycle) = self.mcall
            && motion <= 10
        {
            self.sinumerik_cycle(&cycle);
        }
    }

    /// A move to a position with an axis word whose value is a parameter
    /// the program never set: not compared, the axis unknown until the
    /// program sets it.
    #[cold]
    fn unknown_move(&mut self, target: [f64; 3]) {
        let d = self.finding(
            Severity::Warning,
            codes::VF005.code,
            "this move goes to a position verify cannot compute (a parameter the program does not set); it is not compared",
            0,
            self.line_len,
            None,
        );
        Self::help(d, "the position is unknown to verify until the program moves that axis to a number");
        self.pos = target;
        self.uncomputed += 1;
    }

    fn block_number(&mut self, n: Word) {
        let (start, end) = (n.start as usize, n.end as usize);
        let maximum = self.settings.block_maximum.unwrap_or(self.settings.controller.block_maximum());
        if n.value > maximum {
            let d = self.finding(
                Severity::Error,
                codes::VF041.code,
                format!("block number {} is over the maximum {maximum}", n.value),
                start,
                end,
                None,
            );
            Self::help(d, "the post's LINE_NUMBER_MAXIMUM (or the controller's limit) must bound its block numbers");
        }
        if let Some(prev) = self.last_n
            && n.value <= prev
        {
            let wrapped = match (self.settings.block_start, self.settings.block_maximum) {
                (Some(s), Some(_)) => n.value <= s + 1e-9,
                _ => self.first_n.is_some_and(|f| (n.value - f).abs() < 1e-9),
            };
            if !wrapped {
                let d = self.finding(
                    Severity::Error,
                    codes::VF040.code,
                    format!("block number {} does not increase (the block before is N{prev})", n.value),
                    start,
                    end,
                    None,
                );
                Self::help(
                    d,
                    "block numbers must increase; a controller that searches by number finds the wrong block",
                );
            }
        }
        self.first_n.get_or_insert(n.value);
        self.last_n = Some(n.value);
    }

    fn tool_change(&mut self, start: u32, end: u32) {
        let z = self.pos[2];
        if !z.is_finite() {
            return; // after G28/G53 Z: at the machine's home height
        }
        // In the material (below its top) when the job gives the material box;
        // otherwise below the toolpath's safe height.
        let (limit, what) = match (self.path.job.material, self.path.job.safe_z) {
            (Some((_, max)), _) => (max[2], "the top of the material"),
            (None, Some(safe)) => (safe, "the toolpath's safe height"),
            (None, None) if self.path.max_rapid_z.is_finite() => {
                (self.path.max_rapid_z, "the toolpath's highest rapid")
            }
            _ => return,
        };
        if z < limit - self.tol() {
            let d = self.finding(
                Severity::Error,
                codes::VF038.code,
                format!("tool change with the tool at Z{z:.3} mm, below {what} (Z{limit:.3} mm)"),
                start as usize,
                end as usize,
                None,
            );
            Self::help(d, "the post must raise Z (to safe Z or machine home, e.g. G53 G0 Z0 or G28 G91 Z0) before M6");
        }
    }

    fn arc(&mut self, b: &Block, cw: bool, target: [f64; 3], span: Span) {
        let dir = if cw { ArcDir::Cw } else { ArcDir::Ccw };
        let start = self.pos;
        let [u, v, w] = axes(self.plane);
        let letters = [b'I', b'J', b'K'];
        let plane_name = match self.plane {
            Plane::Xy => "G17 (XY)",
            Plane::Zx => "G18 (XZ)",
            Plane::Yz => "G19 (YZ)",
        };
        if let Some(off) = b.get(letters[w]) {
            let d = self.finding(
                Severity::Error,
                codes::VF021.code,
                format!("{} word in an arc of the {plane_name} plane", letters[w] as char),
                off.start as usize,
                off.end as usize,
                None,
            );
            Self::help(
                d,
                format!(
                    "in {plane_name} an arc's centre is given by the plane's two offset words only; LinuxCNC and grbl refuse the block"
                ),
            );
        }
        if !(start[u].is_finite() && start[v].is_finite()) {
            return; // the start is unknown (after G28/G53): nothing to replay
        }
        let tol = self.tol();
        // A lathe program's arc with B and no I J K R: B is the radius, the
        // Sinumerik 810/820 T's word for it (R words are its parameters).
        let radius = b.get(b'R').or_else(|| if self.lathe && !b.any(b"IJK") { b.get(b'B') } else { None });
        let (centre, r) = if let Some(rw) = radius {
            let r = rw.value * self.unit;
            let closed = (target[u] - start[u]).hypot(target[v] - start[v]) <= 1e-9;
            if closed {
                let d = self.finding(
                    Severity::Error,
                    codes::VF023.code,
                    "an R arc that ends where it starts: R cannot describe a full circle",
                    rw.start as usize,
                    rw.end as usize,
                    None,
                );
                Self::help(d, "full circles need the I J K form");
                self.pos = target;
                return;
            }
            match r_centre(start, target, r, dir, self.plane, tol) {
                Some(c) => (c, Some(r)),
                None => {
                    let d = self.finding(
                        Severity::Error,
                        codes::VF023.code,
                        format!("R{} is smaller than half the distance to the arc's end", rw.value),
                        rw.start as usize,
                        rw.end as usize,
                        None,
                    );
                    Self::help(d, "the controller refuses an arc whose radius cannot reach its end point");
                    self.pos = target;
                    return;
                }
            }
        } else {
            let mut c = start;
            // Heidenhain ISO's I J K are the circle centre, kept until the next.
            let absolute = self.arc_absolute || self.heidenhain && self.absolute;
            for axis in [u, v] {
                c[axis] = match b.get(letters[axis]) {
                    Some(x) if absolute => x.value * self.unit,
                    Some(x) => start[axis] + x.value * self.unit,
                    None if self.heidenhain => self.centre[axis],
                    None => start[axis],
                };
            }
            self.centre = c;
            let arc = Arc { start, end: target, centre: c, dir, plane: self.plane };
            let (r0, r1) = (arc.start_radius(), arc.end_radius());
            if let Some(limit) = self.settings.controller.radius_error(r0, r1, self.unit > 1.0) {
                let word = b.get(letters[u]).or(b.get(letters[v]));
                let (s, e) = word.map_or((0, self.line_len), |x| (x.start as usize, x.end as usize));
                let d = self.finding(
                    Severity::Error,
                    codes::VF020.code,
                    format!(
                        "the arc's radius is {r0:.4} mm at its start and {r1:.4} mm at its end ({:.4} mm apart)",
                        (r0 - r1).abs()
                    ),
                    s,
                    e,
                    None,
                );
                Self::help(
                    d,
                    format!(
                        "{limit}; print the arc words with more decimals, or compute them from the printed end points (--exact-arcs)"
                    ),
                );
            }
            (c, None)
        };
        self.emit(Motion { kind: MKind::Arc, start, end: target, centre, dir, plane: self.plane, r, span });
    }

    /// A canned drilling cycle, expanded into its moves.
    fn cycle(&mut self, b: &Block, code: u32, target: [f64; 3], span: Span) {
        // Fagor's form (8055 and 8070 manuals, "Canned cycles"): `G8x X Y Z I
        // K`, with Z the reference plane, I the depth (K the dwell, in
        // hundredths of a second); it has no R word, which every Fanuc
        // family cycle that takes I (G76, G87: a shift) has.
        let foreign = !b.has(b'R') && !self.cycle_r.is_finite() && b.any(b"BE");
        if !b.has(b'R')
            && !foreign
            && let (Some(z), Some(i)) = (b.get(b'Z'), b.get(b'I'))
        {
            let (z, i) = (z.value * self.unit, i.value * self.unit);
            self.cycle_r = if self.absolute { z } else { self.cycle_initial_z + z };
            self.cycle_z = if self.absolute { i } else { self.cycle_r + i };
        } else {
            if let Some(r) = b.get(b'R') {
                let r = r.value * self.unit;
                self.cycle_r = if self.absolute { r } else { self.cycle_initial_z + r };
            }
            if let Some(z) = b.get(b'Z') {
                let z = z.value * self.unit;
                self.cycle_z = if self.absolute { z } else { self.cycle_r + z };
            }
        }
        let (r, depth) = (self.cycle_r, self.cycle_z);
        if foreign || (self.stop_comparing && !(r.is_finite() && depth.is_finite())) {
            // The note was given at the cycle's first block (the cycle's
            // later blocks, as Andronic's `G79 X40 Z-7`, are in its form too).
            if !foreign {
                return;
            }
            // Another controller's cycle words (Andronic's `G83 Z8 B4 K3 ... E120`):
            // verify does not know what they mean, and says so.
            let d = self.finding(
                Severity::Note,
                codes::VF044.code,
                "this drilling cycle is in a controller's own form (no R plane, and B or E words no RS274 cycle takes), which verify does not read: the moves from here on are not compared",
                0,
                self.line_len,
                None,
            );
            Self::help(d, "the program is verified up to this line; the rest is read for its syntax only");
            self.stop_comparing = true;
            return;
        }
        if !r.is_finite() || !depth.is_finite() {
            self.finding(
                Severity::Error,
                codes::VF024.code,
                "a drilling cycle without its R and Z words",
                0,
                self.line_len,
                None,
            );
            return;
        }
        let (x, y) = (target[0], target[1]);
        let make = |kind, start, end| Motion::straight(kind, start, end, Plane::Xy, span);
        if self.pos[2] < r {
            let to = [self.pos[0], self.pos[1], r];
            self.emit(make(MKind::Rapid, self.pos, to));
        }
        let z0 = self.pos[2];
        self.emit(make(MKind::Rapid, self.pos, [x, y, z0]));
        self.emit(make(MKind::Rapid, self.pos, [x, y, r]));
        self.emit(make(MKind::Feed, self.pos, [x, y, depth]));
        let clear = if self.retract_to_r { r } else { self.cycle_initial_z.max(r) };
        if matches!(code, 850 | 890 | 840 | 740) {
            self.emit(make(MKind::Feed, self.pos, [x, y, r]));
        }
        self.emit(make(MKind::Rapid, self.pos, [x, y, clear]));
    }

    // ----- comparison -----

    fn emit(&mut self, p: Motion) {
        let kind = match p.kind {
            MKind::Rapid => Kind::Rapid,
            MKind::Feed => Kind::Feed,
            MKind::Arc => Kind::Arc,
        };
        self.observer.motion(&Move {
            kind,
            start: p.start,
            end: p.end,
            centre: p.centre,
            dir: p.dir,
            plane: p.plane,
            span: p.span,
        });
        self.pos = p.end;
        self.stats.motions += 1;
        if p.cutting() {
            self.cut_state(&p);
        }
        if self.settings.rotary_wrap || self.stop_comparing || !(p.end[0].is_finite() && p.end[1].is_finite()) {
            return;
        }
        // A move at the height G53 or G28 left unknown (the machine's
        // home, above the work): the post's own, not compared.
        if self.z_written && !p.end[2].is_finite() {
            return;
        }
        self.compare(&p);
    }

    /// Feed and spindle state of a cutting move (before the comparison, which checks them against the toolpath).
    fn cut_state(&mut self, p: &Motion) {
        if self.inverse_time {
            return;
        }
        if !self.feed.is_finite() && !self.no_feed_reported {
            self.no_feed_reported = true;
            self.motion_finding(
                Severity::Error,
                codes::VF034.code,
                "a cutting move before any feed rate (F) is set",
                p,
                None,
                Some(
                    "the post must print F on the first cutting move (Vectric: FIRST_FEED_MOVE with [F]); a toolpath \
                     that gives no feed rate before it (a CL file with no FEDRAT: CL025) has none to print"
                        .into(),
                ),
            );
        }
    }

    /// The next expected moves, flattened onto Z0 when the program writes no Z.
    fn expected(&mut self, k: usize, flat: bool) -> Option<Expected> {
        let mut e = self.path.get(k).copied()?;
        if flat {
            e.start[2] = 0.0;
            e.end[2] = 0.0;
            e.centre[2] = 0.0;
            if e.kind == Kind::Arc && e.plane != Plane::Xy {
                // Seen from above, an arc across Z is a straight move.
                e.kind = Kind::Feed;
            }
        }
        Some(e)
    }

    fn compare(&mut self, p: &Motion) {
        let tol = self.tol();
        // A program that has not written Z (2D laser and plasma posts) is compared in X and Y.
        let flat = !p.end[2].is_finite();
        let flattened;
        let p = if flat {
            let mut q = *p;
            q.start[2] = 0.0;
            q.end[2] = 0.0;
            q.centre[2] = 0.0;
            flattened = q;
            &flattened
        } else {
            p
        };
        // Moves that flattening made zero-length (straight plunges) are made where the program is.
        while flat
            && let Some(e) = self.expected(0, flat)
            && e.kind != Kind::Arc
            && dist(e.start, e.end) <= 1e-9
        {
            self.skip();
        }
        // Most moves end where the next expected move does (the loop's first
        // turn, without copying the expected move twice).
        if !flat
            && self.path.get(0).is_some_and(|e| dist(p.end, e.end) <= tol)
            && let Some(e) = self.path.pop()
        {
            self.stats.matched += 1;
            self.made(p, &e, tol);
            self.progress = 0.0;
            return;
        }
        let mut k = 0;
        while let Some(e) = self.expected(k, flat) {
            if dist(p.end, e.end) <= tol {
                for _ in 0..k {
                    self.skip();
                }
                self.path.pop();
                self.stats.matched += 1;
                self.made(p, &e, tol);
                self.progress = 0.0;
                return;
            }
            if k >= LOOKAHEAD || !self.skippable(p, &e, tol) {
                break;
            }
            k += 1;
        }
        if let Some(e) = self.expected(0, flat)
            && let Some(t) = self.on_path(p, &e, tol)
        {
            if p.kind == MKind::Rapid && e.cutting() && t > self.progress + 1e-6 && !Self::retract_like(&e) {
                self.motion_finding(
                    Severity::Error,
                    codes::VF012.code,
                    "a rapid move along a cut of the toolpath",
                    p,
                    Some(&e),
                    Some("the toolpath cuts here at a feed rate".into()),
                );
            }
            if p.cutting() {
                self.made(p, &e, tol);
            }
            self.progress = self.progress.max(t);
            return;
        }
        if p.kind == MKind::Rapid {
            if let Some(e) = self.expected(0, flat)
                && e.cutting()
                && !Self::retract_like(&e)
                && known(p.start)
                && dist(e.end, p.start) > tol
                && to_segment(e.end, p.start, p.end).0 <= tol
            {
                // The rapid passes over the end of the next cut: it makes that cut at rapid.
                self.motion_finding(
                    Severity::Error,
                    codes::VF012.code,
                    "a rapid move over a cut of the toolpath",
                    p,
                    Some(&e),
                    Some("the toolpath makes this move at a feed rate".into()),
                );
                self.skip();
                self.progress = 0.0;
                return;
            }
            if !self.wrong_units(p, tol, flat) {
                self.extra_rapid(p, tol);
            }
            return;
        }
        if !flat && self.in_the_air(p, tol) {
            return; // a header or footer feed move above the material cuts nothing
        }
        self.off_path(p, tol, flat);
    }

    /// Moves over an expected move the program skipped (covered on its way).
    fn skip(&mut self) {
        if self.path.pop().is_some() {
            self.stats.matched += 1;
        }
    }

    fn skippable(&self, p: &Motion, e: &Expected, tol: f64) -> bool {
        if e.kind == Kind::Rapid && (p.kind == MKind::Rapid || dist(e.end, p.start) <= tol) {
            return true;
        }
        if p.kind == MKind::Rapid && !Self::retract_like(e) {
            return false; // a rapid never makes a cut (VF012 below)
        }
        if !known(p.start) {
            return false;
        }
        match (p.kind, e.kind) {
            // A straight move never covers an arc of the toolpath.
            (_, Kind::Arc) if p.kind != MKind::Arc => false,
            (MKind::Arc, _) => p.arc().deviation(e.end, tol).0 <= tol && dist(e.end, p.start) > tol,
            _ => to_segment(e.end, p.start, p.end).0 <= tol,
        }
    }

    fn on_path(&self, p: &Motion, e: &Expected, tol: f64) -> Option<f64> {
        if !known(e.start) {
            return None;
        }
        match e.kind {
            Kind::Arc => {
                let arc = Arc { start: e.start, end: e.end, centre: e.centre, dir: e.dir, plane: e.plane };
                let (d, t) = arc.deviation(p.end, tol);
                (d <= tol + self.settings.chord_tolerance).then_some(t)
            }
            _ => {
                let (d, t) = to_segment(p.end, e.start, e.end);
                (d <= tol).then_some(t)
            }
        }
    }

    fn retract_like(e: &Expected) -> bool {
        e.intent == Intent::Retract
            || (known(e.start)
                && e.end[2] > e.start[2]
                && (e.end[0] - e.start[0]).abs() < 1e-6
                && (e.end[1] - e.start[1]).abs() < 1e-6)
    }

    /// Checks a program move that makes (all or part of) expected move `e`.
    fn made(&mut self, p: &Motion, e: &Expected, tol: f64) {
        match (p.kind, e.kind) {
            (MKind::Rapid, Kind::Feed | Kind::Arc) => {
                if !Self::retract_like(e) {
                    self.motion_finding(
                        Severity::Error,
                        codes::VF012.code,
                        "a rapid move where the toolpath cuts",
                        p,
                        Some(e),
                        Some("the toolpath makes this move at a feed rate".into()),
                    );
                }
                return;
            }
            (MKind::Arc, Kind::Arc) => self.same_arc(p, e, tol),
            (MKind::Feed, Kind::Arc) if known(p.start) => {
                let arc = Arc { start: e.start, end: e.end, centre: e.centre, dir: e.dir, plane: e.plane };
                let chord = self.settings.chord_tolerance;
                let on = !known(e.start) || arc.deviation(p.start, tol).0 <= tol + chord;
                let sag = arc.chord_error(p.start, p.end);
                if known(e.start) && on && sag > chord + tol {
                    self.motion_finding(
                        Severity::Error,
                        codes::VF014.code,
                        format!(
                            "this chord of a linearized arc lies {sag:.4} mm from the arc (chord tolerance {chord} mm)"
                        ),
                        p,
                        Some(e),
                        Some("the post's arc tolerance bounds how far chords may stray from the arc".into()),
                    );
                }
            }
            (MKind::Arc, Kind::Feed) => {
                let arc = p.arc();
                let sweep = arc.sweep(tol);
                let r = arc.end_radius();
                let bulge = if sweep <= std::f64::consts::PI { r * (1.0 - (sweep / 2.0).cos()) } else { r };
                if bulge > tol {
                    self.motion_finding(
                        Severity::Error,
                        codes::VF010.code,
                        format!("an arc where the toolpath moves straight (it bulges {bulge:.3} mm off the line)"),
                        p,
                        Some(e),
                        None,
                    );
                }
            }
            _ => {}
        }
        if p.cutting() && e.cutting() {
            self.check_feed_and_spindle(p, e);
        }
    }

    fn same_arc(&mut self, p: &Motion, e: &Expected, tol: f64) {
        if p.plane != e.plane {
            self.motion_finding(
                Severity::Error,
                codes::VF013.code,
                "this arc is in another plane than the toolpath's",
                p,
                Some(e),
                None,
            );
            return;
        }
        let [u, v, _] = axes(e.plane);
        let off = |c: [f64; 3]| (c[u] - e.centre[u]).hypot(c[v] - e.centre[v]);
        if p.dir != e.dir {
            let (g, other) = if p.dir == ArcDir::Cw {
                ("G2 (clockwise)", "counter-clockwise")
            } else {
                ("G3 (counter-clockwise)", "clockwise")
            };
            self.motion_finding(
                Severity::Error,
                codes::VF013.code,
                format!("this arc turns {g}; the toolpath's turns {other}"),
                p,
                Some(e),
                Some("the post prints the arc sections' G codes the wrong way round".into()),
            );
            return;
        }
        let centre_off = off(p.centre);
        if centre_off <= 2.0 * tol {
            return;
        }
        if let Some(r) = p.r
            && let Some(other) = r_centre(p.start, p.end, -r, p.dir, p.plane, tol)
            && off(other) <= 2.0 * tol
        {
            let sweep = Arc { centre: other, ..p.arc() }.sweep(tol).to_degrees();
            let (form, why) = if r > 0.0 {
                ("positive", "R arcs over 180° need a negative R")
            } else {
                ("negative", "R arcs under 180° need a positive R")
            };
            self.motion_finding(
                Severity::Error,
                codes::VF022.code,
                format!("this arc turns {sweep:.1}° but R is {form}: the controller cuts the other arc"),
                p,
                Some(e),
                Some(why.into()),
            );
            return;
        }
        self.motion_finding(
            Severity::Error,
            codes::VF013.code,
            format!("this arc's centre is {}, {centre_off:.4} mm from the toolpath's", fmt_point(p.centre)),
            p,
            Some(e),
            Some(format!("the toolpath's centre is {}", fmt_point(e.centre))),
        );
    }

    fn check_feed_and_spindle(&mut self, p: &Motion, e: &Expected) {
        if e.powered && !self.spindle && !self.spindle_reported {
            self.spindle_reported = true;
            let post = self.settings.post.as_deref().unwrap_or("the post");
            // A post that cannot switch it on at all is one for a spindle
            // started by hand (or not a jet post): a property of the post.
            let (severity, message, help) = match e.jet {
                true if !self.settings.jet_on => (
                    Severity::Warning,
                    match self.settings.apt_words {
                        false => format!(
                            "a jet cut with the jet off: {post} has no JET_TOOL_ON section, so it cannot switch a jet on"
                        ),
                        true => format!(
                            "a jet cut with the jet off: {post} is given no record that switches a jet on (APT-word posts get none for jet events)"
                        ),
                    },
                    "post jet toolpaths (laser, plasma, waterjet) with a post that has a JET_TOOL_ON section",
                ),
                false if !self.settings.spindle_on => (
                    Severity::Warning,
                    format!(
                        "a cut with the spindle off: {post} never prints M3 or M4, so the spindle must be started by hand"
                    ),
                    "start the spindle by hand before the first cut, or post with a post that starts it",
                ),
                false if e.implied => (
                    Severity::Warning,
                    format!(
                        "a cut with the spindle off: the toolpath gives the tool a speed but never switches the spindle on, and {post} starts it only from the toolpath's spindle records (SPINDL)"
                    ),
                    "give the toolpath a spindle-on event (SpindleOn, or SPINDL/ON in a CL file)",
                ),
                _ => (
                    Severity::Error,
                    "a cut with the spindle (or jet) off".to_string(),
                    "the spindle must run (M3/M4; jets: M3/M4, M106, M62/M64) before the first cut",
                ),
            };
            self.motion_finding(severity, codes::VF035.code, message, p, Some(e), Some(help.into()));
        }
        // `S0 M3` turns nothing (a jet's S is its power, and 0 may be
        // meant; under G96 S is a surface speed).
        if e.powered && !e.jet && self.spindle && !self.css && self.started_at_zero && !self.spindle_reported {
            self.spindle_reported = true;
            self.motion_finding(
                Severity::Error,
                codes::VF035.code,
                "a cut with the spindle at 0 rpm: it was switched on with `S0 M3` and given no speed since".to_string(),
                p,
                Some(e),
                Some("the spindle must run at a speed before the first cut; a toolpath that asks for 0 rpm (SPINDL/RPM,0) cannot be cut".into()),
            );
        }
        // Constant surface speed: the S of G96 is metres (G21) or feet
        // (G20) a minute.
        if self.css && e.surface.is_finite() && self.speed.is_finite() {
            let got = self.speed.abs() * if self.unit > 1.0 { 0.3048 } else { 1.0 };
            let want = e.surface;
            if (got - want).abs() > 0.005 * want + 1e-6 && self.surface_reported != (got, want) {
                self.surface_reported = (got, want);
                self.motion_finding(
                    Severity::Error,
                    codes::VF036.code,
                    format!("this cut runs at a surface speed of {got:.1} m/min (G96); the toolpath's is {want:.1} m/min"),
                    p,
                    Some(e),
                    Some("the S of G96 is metres a minute under G21, feet under G20; check how the post converts the tool's surface speed".into()),
                );
            }
        }
        if self.inverse_time || !self.feed.is_finite() || !e.feed.is_finite() {
            return;
        }
        // A feed per revolution is compared with the toolpath's when both
        // are per revolution; otherwise per minute, through the spindle's
        // rpm, which constant surface speed (G96) leaves unknown.
        let rpm = if self.css { f64::NAN } else { self.speed.abs() };
        let (got, want, step) = match (self.per_rev, e.per_rev) {
            (true, true) | (false, false) => (self.feed, e.feed, self.feed_step),
            (true, false) => (self.feed * rpm, e.feed, self.feed_step * rpm),
            (false, true) => (self.feed, e.feed * rpm, self.feed_step),
        };
        if !got.is_finite() || !want.is_finite() {
            return;
        }
        if (got - want).abs() > (0.005 * want).max(0.5 * step + 1e-6) && self.feed_reported != (got, want) {
            self.feed_reported = (got, want);
            let per_unit = match (self.per_rev, self.unit > 1.0) {
                (true, true) if e.per_rev => "in/rev (G95)",
                (true, false) if e.per_rev => "mm/rev (G95)",
                (true, true) => "in/rev times the spindle's S (G95)",
                (true, false) => "mm/rev times the spindle's S (G95)",
                (false, true) => "in/min (G94)",
                (false, false) => "mm/min (G94)",
            };
            let (per, digits) = if self.per_rev && e.per_rev { ("mm/rev", 3) } else { ("mm/min", 1) };
            self.motion_finding(
                Severity::Error,
                codes::VF033.code,
                format!("this cut runs at {got:.digits$} {per}; the toolpath's feed is {want:.digits$} {per}"),
                p,
                Some(e),
                Some(format!(
                    "the program's F is read in {per_unit}; check the post's feed variable, its units and multiplier"
                )),
            );
        }
    }

    fn extra_rapid(&mut self, p: &Motion, tol: f64) {
        let floor = self.path.min_rapid_z;
        let z = p.end[2];
        if !floor.is_finite() || z >= floor - tol {
            return;
        }
        if let Some((min, max)) = self.path.job.material {
            let inside = p.end[0] >= min[0] - tol
                && p.end[0] <= max[0] + tol
                && p.end[1] >= min[1] - tol
                && p.end[1] <= max[1] + tol;
            if z >= max[2] || !inside {
                return;
            }
        }
        self.motion_finding(
            Severity::Error,
            codes::VF037.code,
            format!("a rapid move to Z{z:.3} mm, below the toolpath's lowest rapid height (Z{floor:.3} mm), into the material"),
            p,
            None,
            Some("the post moves at rapid where the toolpath does not: raise Z first".into()),
        );
    }

    /// Whether a move stays above the material (its top, or without a
    /// material box, the toolpath's lowest rapid height).
    fn in_the_air(&self, p: &Motion, tol: f64) -> bool {
        let top = match self.path.job.material {
            Some((_, max)) => max[2],
            None if self.path.min_rapid_z.is_finite() => self.path.min_rapid_z,
            None => return false,
        };
        // A helix's Z runs monotonically from start to end, so the ends bound it.
        let low = p.start[2].min(p.end[2]);
        known(p.start) && low >= top - tol
    }

    /// Whether a move off the toolpath lands on one of its next moves once
    /// its numbers are read in the other unit; reports it (VF030) if so.
    fn wrong_units(&mut self, p: &Motion, tol: f64, flat: bool) -> bool {
        for k in 0..8 {
            let Some(e) = self.expected(k, flat) else { break };
            for (scale, what) in [
                (25.4, "inches in a program read in millimetres"),
                (1.0 / 25.4, "millimetres in a program read in inches"),
            ] {
                let scaled = p.end.map(|v| v * scale);
                if dist(p.end, e.end) > tol && dist(scaled, e.end) <= tol * scale.max(1.0) {
                    self.stop_comparing = true;
                    self.motion_finding(
                        Severity::Error,
                        codes::VF030.code,
                        format!(
                            "the numbers of this move are {what}: read as written it goes to {}, the toolpath to {}",
                            fmt_point(p.end),
                            fmt_point(e.end)
                        ),
                        p,
                        Some(&e),
                        Some(
                            "the post's units and the program's G20/G21 must agree: a post that states no units writes the \
                             system of the one units word its text holds (`G21`, `G20`, or `G71`, `G70`), and is handed \
                             the toolpath's units when it holds none (docs/units.md); verify stops comparing motion here"
                                .into(),
                        ),
                    );
                    return true;
                }
            }
        }
        false
    }

    fn off_path(&mut self, p: &Motion, tol: f64, flat: bool) {
        let Some(e) = self.expected(0, flat) else {
            self.motion_finding(
                Severity::Error,
                codes::VF010.code,
                format!("a cutting move to {} after the toolpath's last move", fmt_point(p.end)),
                p,
                None,
                None,
            );
            return;
        };
        if self.wrong_units(p, tol, flat) {
            return;
        }
        self.motion_finding(
            Severity::Error,
            codes::VF010.code,
            format!(
                "this cutting move goes to {}, off the toolpath: its next move goes to {} ({:.4} mm away)",
                fmt_point(p.end),
                fmt_point(e.end),
                dist(p.end, e.end)
            ),
            p,
            Some(&e),
            None,
        );
        // Resynchronise on a later toolpath move this one ends at.
        for k in 1..LOOKAHEAD {
            let Some(later) = self.expected(k, flat) else { break };
            if dist(p.end, later.end) <= tol {
                for _ in 0..=k {
                    self.skip();
                }
                self.progress = 0.0;
                return;
            }
        }
    }

    fn finish(&mut self) {
        let mut missing = 0u64;
        let mut first: Option<Expected> = None;
        if !self.settings.rotary_wrap && !self.stop_comparing {
            while let Some(e) = self.path.pop() {
                if e.cutting() {
                    missing += 1;
                    first.get_or_insert(e);
                }
            }
        } else {
            while self.path.pop().is_some() {}
        }
        self.stats.expected = self.path.count;
        if let Some(e) = first {
            let line = Span::new(self.file, self.line_start, self.line_start + self.line_len);
            // Moves verify could not compute may be these: a warning that says so.
            let (severity, help) = match self.uncomputed {
                0 => (Severity::Error, "the program is truncated, or the post dropped moves".to_string()),
                n => (
                    Severity::Warning,
                    format!(
                        "{n} move(s) of the program go to positions verify cannot compute (VF005): they may be these"
                    ),
                ),
            };
            let d = Diagnostic::new(
                severity,
                codes::VF011,
                format!(
                    "the program ends before {missing} cutting move(s) of the toolpath; the first goes to {}",
                    fmt_point(e.end)
                ),
            )
            .at(e.span, "the first move the program does not make")
            .also(line, "the program's last line")
            .help(help);
            self.push_at(d, severity == Severity::Error, e.end);
        }
        for d in std::mem::take(&mut self.path.diagnostics) {
            let error = d.is_error();
            self.push(d, error);
        }
    }
}

/// The characters of a block grbl keeps: blanks and comments (`( ... )`,
/// `;` to the end) left out.
fn counted_length(text: &[u8]) -> usize {
    let mut in_paren = false;
    let mut n = 0;
    for &b in text {
        match b {
            b'(' => in_paren = true,
            b')' if in_paren => in_paren = false,
            b';' if !in_paren => break,
            b' ' | b'\t' | b'\r' => {}
            _ if !in_paren => n += 1,
            _ => {}
        }
    }
    n
}

/// The name that starts at `text[at..]` (`TRANS`, `CYCLE800`, `$P_UIFR`,
/// `VZOFX`), for a message.
fn name_at(text: &[u8], at: usize) -> String {
    let rest = text.get(at..).unwrap_or_default();
    let n = rest.iter().take_while(|b| b.is_ascii_alphanumeric() || matches!(b, b'_' | b'$')).count();
    String::from_utf8_lossy(&rest[..n]).into_owned()
}

/// Where the message of an `M117`/`M118` word starts (after the word).
fn message_word(text: &[u8]) -> Option<usize> {
    let m = memchr::arch::all::memchr::Two::new(b'M', b'm');
    let mut from = 0;
    while let Some(k) = text.get(from..).and_then(|rest| m.find(rest)) {
        let i = from + k;
        let boundary = i == 0 || !text[i - 1].is_ascii_alphanumeric();
        let word = text.get(i + 1..i + 4).is_some_and(|d| d == b"117" || d == b"118");
        let after = text.get(i + 4).is_none_or(|b| !b.is_ascii_digit() && *b != b'.');
        if boundary && word && after {
            return Some(i + 4);
        }
        from = i + 1;
    }
    None
}

/// When a block that failed to read has an `M0`/`M1` word (followed by a
/// blank) before the failure: where its message starts.
fn stop_with_message(prefix: &[u8]) -> Option<usize> {
    (0..prefix.len()).find_map(|i| {
        let boundary = i == 0 || !prefix[i - 1].is_ascii_alphanumeric();
        if !boundary || !prefix[i].eq_ignore_ascii_case(&b'M') {
            return None;
        }
        let digits = prefix[i + 1..].iter().take_while(|b| b.is_ascii_digit()).count();
        let end = i + 1 + digits;
        let code = std::str::from_utf8(&prefix[i + 1..end]).ok()?.parse::<u32>().ok()?;
        (digits > 0 && code <= 1 && matches!(prefix.get(end), Some(b' ' | b'\t'))).then_some(end)
    })
}

/// A G or M code in tenths (`G91.1` is 911), as `(code * 10.0).round() as
/// u32` gives it; a whole number of tenths (every code a post prints)
/// without the library's rounding call.
#[inline]
#[doc(hidden)]
pub fn tenths(code: f64) -> u32 {
    let t = code * 10.0;
    if (t as i64) as f64 == t { t as u32 } else { t.round() as u32 }
}

fn format_code(code: f64) -> String {
    if code.fract().abs() < 1e-9 { format!("{}", code as i64) } else { format!("{code}") }
}
