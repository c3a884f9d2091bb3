//! Blocks beyond letter-and-number words: parameters, expressions and the
//! statements of the Fanuc/Haas macro, LinuxCNC and Siemens Sinumerik
//! families, and Okuma's variables, read into the same [`Item`]s as
//! [`crate::grammar`] gives.
//!
//! ```text
//! line       = ( "/" )? ( item )*
//! item       = word | assignment | statement | "(" comment ")" | ";" comment | "%" rest
//! word       = letter value | letter "=" expr       X[#1+2.]  G#100  Z=#102  X=R1
//!            | "CR" "=" expr                          Sinumerik arc radius, read as R
//! value      = number | sign? ( "#" ref | "[" expr "]" )
//! assignment = "#" ref "=" expr | "R" digits "=" expr     #100=5  #<_a>=1.5  R1=5
//! ref        = digits | "<" name ">" | "[" expr "]"
//! expr       = operands joined by + - * / MOD ** EQ NE GT GE LT LE AND OR XOR
//!              (Sinumerik also == <> < > <= >=), unary - +, [ ] and ( ) groups,
//!              functions SIN COS TAN ASIN ACOS ATAN SQRT ABS ROUND FIX FUP
//!              TRUNC LN EXP, AC( ) IC( ), R parameters by name (R1),
//!              Okuma common variables (VC1, VC[2])
//! heidenhain = "P" digit digit value               Heidenhain ISO cycle parameter: P01 -4.
//! okuma      = "VC" digits "=" expr | "V" name ( "[" expr "]" )? "=" expr
//! statement  = Sinumerik keywords and cycle calls (SUPA, MCALL, CYCLE81( .. ),
//!              WORKPIECE( .. ), MSG( .. ), T="name"), jumps and loops of the
//!              families (IF GOTO WHILE DO END, O-word subroutines, GOTOF),
//!              output statements (DPRNT[ .. ], POPEN, PCLOS)
//! ```
//!
//! Only a line that the plain grammar does not read comes here, so the
//! words of an ISO program are never slowed by it. Parameter values are
//! the ones the program assigns; every other parameter (a machine's
//! `#5183`, a Sinumerik system variable) is not known, and so is any
//! expression that uses it: a word with a value not known is an item whose
//! value is NaN, which the interpreter reports (VF005) and does not compare.
//! `#` assignments take effect after the line, as LinuxCNC applies them;
//! Sinumerik's R parameters at once, in the order of the block.

use std::collections::HashMap;

use crate::grammar::{self, Item, ItemKind};

/// What a statement of the line is, for the interpreter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Note {
    /// A jump, loop, condition or subroutine statement: verify reads the
    /// lines in order and does not follow it.
    Flow,
    /// A frame (Sinumerik TRANS, ROT, ...) or other statement that moves
    /// the program's coordinates or the tool in a way verify does not
    /// replay.
    NotReplayed,
    /// A call of a block or subroutine written elsewhere in the program
    /// (Sinumerik `CALL BLOCK ... TO ...`, LinuxCNC `o<name> call`), or the
    /// definition of one: its moves run in another order than they are
    /// written, which verify, reading the program once, does not follow.
    Call,
    /// An assignment to a parameter whose value is not known (an
    /// expression of parameters the program never set).
    UnknownValue,
    /// A command of Klipper's extended G-code (`SET_SERVO SERVO=a
    /// ANGLE=5.3`, `START_PRINT X=-3,5`): a name and `NAME=VALUE`
    /// parameters, which runs the firmware's command or a macro of the
    /// machine's configuration that verify does not know.
    Macro,
}

/// A Sinumerik drilling cycle call: `CYCLE81(RTP, RFP, SDIS, DP, DPR, ...)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cycle {
    /// 81 for CYCLE81, 840 for CYCLE840.
    pub number: u32,
    /// The first five parameters (NaN where empty or not known), in the
    /// program's units: return plane, reference plane, safety distance,
    /// final depth (absolute), final depth relative to the reference plane.
    pub rtp: f64,
    pub rfp: f64,
    pub sdis: f64,
    pub dp: f64,
    pub dpr: f64,
    /// Called with MCALL: after every later block that moves the axes.
    pub modal: bool,
    pub start: u32,
    pub end: u32,
}

/// The statements of one line besides its words and comments.
#[derive(Default, Debug)]
pub struct Extras {
    /// Statements verify reads and does not replay, with their span and
    /// the word that names them (for [`Note::NotReplayed`], what the
    /// statement is: the span names the word).
    pub notes: Vec<(Note, u32, u32, &'static str)>,
    /// A drilling cycle called on the line.
    pub cycle: Option<Cycle>,
    /// Heidenhain ISO cycle parameters `P01 -4.` ... `P09`, NaN where not
    /// given; `parameters` says whether the line had any.
    pub p: [f64; 9],
    pub parameters: bool,
    /// `MCALL` alone: the modal call ends.
    pub mcall_off: bool,
    /// `SUPA` (Sinumerik): the block's axis words are machine coordinates.
    pub machine: bool,
}

/// The parameters a program has set, and the reader of the lines that use them.
#[derive(Default)]
pub struct Reader {
    values: HashMap<Box<str>, f64>,
    /// Assignments of the line being read, applied after it.
    pending: Vec<(Box<str>, f64)>,
    key: String,
}

/// The longest statement or function name read.
const NAME: usize = 24;

/// A name, upper case.
struct Name([u8; NAME], usize);

impl std::ops::Deref for Name {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        &self.0[..self.1]
    }
}

/// The reader's place in a line.
struct Cursor<'t> {
    text: &'t [u8],
    at: usize,
}

impl Cursor<'_> {
    fn blanks(&mut self) {
        while matches!(self.text.get(self.at), Some(b' ' | b'\t' | b'\r')) {
            self.at += 1;
        }
    }

    /// The next byte after blanks, upper case.
    fn peek(&mut self) -> Option<u8> {
        self.blanks();
        self.text.get(self.at).map(u8::to_ascii_uppercase)
    }

    fn eat(&mut self, b: u8) -> bool {
        if self.peek() == Some(b) {
            self.at += 1;
            true
        } else {
            false
        }
    }

    /// A run of letters, `_` and then digits from here (no blanks
    /// skipped), upper case, without allocating: `None` past [`NAME`]
    /// bytes (no name verify knows is that long).
    fn name(&mut self) -> Option<Name> {
        let start = self.at;
        while self.text.get(self.at).is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_' || *b == b'$') {
            self.at += 1;
        }
        while self.text.get(self.at).is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_') {
            self.at += 1;
        }
        let bytes = &self.text[start..self.at];
        let mut name = Name([0; NAME], bytes.len());
        name.0.get_mut(..bytes.len())?.copy_from_slice(bytes);
        name.0.make_ascii_uppercase();
        Some(name)
    }

    /// `=` and not `==`.
    fn assigns(&mut self) -> bool {
        self.peek() == Some(b'=') && self.text.get(self.at + 1) != Some(&b'=')
    }

    /// Skips a `"..."` string; false when there is none here.
    fn string(&mut self) -> bool {
        if self.peek() != Some(b'"') {
            return false;
        }
        match self.text[self.at + 1..].iter().position(|&b| b == b'"') {
            Some(n) => {
                self.at += n + 2;
                true
            }
            None => false,
        }
    }
}

/// Sinumerik statements that neither move the tool nor change the
/// coordinates verify compares in (settings, messages, the blank's
/// description for the control's simulation).
const QUIET: &[&str] = &[
    "WORKPIECE",
    "MSG",
    "SOFT",
    "BRISK",
    "FFWON",
    "FFWOF",
    "COMPCAD",
    "COMPCURV",
    "COMPOF",
    "CFC",
    "CFTCP",
    "CFIN",
    "STOPRE",
    "DIAMON",
    "DIAMOF",
    "DIAM90",
    "SPOS",
    "SPOSA",
    "SETMS",
    "CUT2D",
    "CUT3DC",
    "ORIWKS",
    "ORIMKS",
    "TOFFL",
    "TOFFOF",
    "FGROUP",
    "DPRNT",
    "BPRNT",
    "POPEN",
    "PCLOS",
    "SETVN",
    "CPRECON",
    "CPRECOF",
    "UPATH",
    "SPATH",
    "DEF",
    "RET",
];

/// Statements of the families that change the flow of the program.
const FLOW: &[&str] = &[
    "IF",
    "THEN",
    "ELSE",
    "ENDIF",
    "GOTO",
    "GOTOF",
    "GOTOB",
    "GOTOC",
    "WHILE",
    "ENDWHILE",
    "DO",
    "END",
    "REPEAT",
    "UNTIL",
    "LOOP",
    "ENDLOOP",
    "FOR",
    "ENDFOR",
    "ENDSUB",
    "ELSEIF",
    "ENDREPEAT",
    "RETURN",
    "BREAK",
    "CONTINUE",
    "CASE",
];

/// Calls and definitions of blocks and subroutines ([`Note::Call`]).
const CALLS: &[&str] = &["CALL", "PCALL", "SUB", "PROC"];

/// Sinumerik frames and other statements that move the coordinates or the
/// tool in ways verify does not replay.
const NOT_REPLAYED: &[&str] = &[
    "TRANS", "ATRANS", "ROT", "AROT", "SCALE", "ASCALE", "MIRROR", "AMIRROR", "TRAORI", "TRAFOOF", "TRANSMIT",
    "TRACYL", "RND", "RNDM", "CHF", "CHR", "AP", "RP", "AR", "CIP", "CT", "OFFN",
];

/// Whether `rest` (after a command name) is Klipper's parameters: blank,
/// or `NAME=VALUE` pairs apart by blanks (a name of letters, digits and
/// `_`; a value of anything but blanks and `;`), then perhaps a `;`
/// comment.
fn klipper_parameters(rest: &[u8]) -> bool {
    let text = rest.split(|b| *b == b';').next().unwrap_or(rest);
    if text.first().is_some_and(|b| !matches!(b, b' ' | b'\t' | b'\r')) {
        return false;
    }
    text.split(|b| matches!(b, b' ' | b'\t' | b'\r')).filter(|t| !t.is_empty()).all(|t| {
        let Some(eq) = t.iter().position(|b| *b == b'=') else { return false };
        let (name, value) = (&t[..eq], &t[eq + 1..]);
        name.first().is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_')
            && name.iter().all(|b| b.is_ascii_alphanumeric() || *b == b'_')
            && !value.is_empty()
            && !value.contains(&b'=')
    })
}

/// Functions of one argument, by name.
fn function(name: &[u8]) -> Option<fn(f64) -> f64> {
    Some(match name {
        b"SIN" => |v: f64| v.to_radians().sin(),
        b"COS" => |v: f64| v.to_radians().cos(),
        b"TAN" => |v: f64| v.to_radians().tan(),
        b"ASIN" => |v: f64| v.asin().to_degrees(),
        b"ACOS" => |v: f64| v.acos().to_degrees(),
        b"ATAN" => |v: f64| v.atan().to_degrees(),
        b"SQRT" | b"SQR" => f64::sqrt,
        b"ABS" => f64::abs,
        b"ROUND" => f64::round,
        b"FIX" | b"TRUNC" => f64::trunc,
        b"FUP" => f64::ceil,
        b"LN" => f64::ln,
        b"EXP" => f64::exp,
        b"AC" => |v: f64| v,
        // IC(..): incremental for this word alone, which a value cannot say.
        b"IC" => |_: f64| f64::NAN,
        _ => return None,
    })
}

impl Reader {
    /// Reads `text` into `items` (cleared first) and `extras`; on an
    /// error, the byte offset where reading stopped.
    pub fn line(&mut self, text: &[u8], items: &mut Vec<Item>, extras: &mut Extras) -> Result<(), usize> {
        items.clear();
        extras.notes.clear();
        extras.cycle = None;
        extras.p = [f64::NAN; 9];
        extras.parameters = false;
        extras.mcall_off = false;
        extras.machine = false;
        self.pending.clear();
        let mut c = Cursor { text, at: 0 };
        let push = |items: &mut Vec<Item>, kind, start: usize, end: usize, value, decimals| {
            items.push(Item { kind, start: start as u32, end: end as u32, value, decimals })
        };
        if c.peek() == Some(b'/') {
            push(items, ItemKind::Delete, c.at, c.at + 1, 0.0, 0);
            c.at += 1;
        }
        while let Some(b) = c.peek() {
            let start = c.at;
            match b {
                b'(' => {
                    let mut depth = 0;
                    let close = text[start..].iter().position(|&b| {
                        depth += i32::from(b == b'(') - i32::from(b == b')');
                        depth == 0
                    });
                    let Some(n) = close else { return Err(text.len()) };
                    c.at += n + 1;
                    push(items, ItemKind::Comment, start, c.at, 0.0, 0);
                }
                b';' => {
                    push(items, ItemKind::Comment, start, text.len(), 0.0, 0);
                    c.at = text.len();
                }
                b'%' => {
                    push(items, ItemKind::Percent, start, text.len(), 0.0, 0);
                    c.at = text.len();
                }
                b'#' => {
                    c.at += 1;
                    let key = self.reference(&mut c)?;
                    if !c.assigns() {
                        return Err(c.at);
                    }
                    c.at += 1;
                    let value = self.expr(&mut c)?;
                    if value.is_nan() {
                        extras.notes.push((Note::UnknownValue, start as u32, c.at as u32, "#"));
                    }
                    self.pending.push((key, value));
                }
                b'A'..=b'Z' | b'$' => {
                    let letters = text[start + 1..].iter().take_while(|b| b.is_ascii_alphabetic() || **b == b'_');
                    if b != b'$' && letters.count() == 0 {
                        self.word(&mut c, b, items, extras)?;
                    } else if self.statement(&mut c, items, extras)? {
                        break;
                    }
                }
                _ => return Err(start),
            }
        }
        for (key, value) in self.pending.drain(..) {
            if value.is_nan() {
                self.values.remove(&key);
            } else {
                self.values.insert(key, value);
            }
        }
        Ok(())
    }

    /// A word of one letter: `X1.5`, `X[#1+2]`, `X-#3`, `X=R1`, `T="name"`;
    /// or an R parameter's assignment, `R1=5`.
    fn word(&mut self, c: &mut Cursor, letter: u8, items: &mut Vec<Item>, extras: &mut Extras) -> Result<(), usize> {
        let start = c.at;
        c.at += 1;
        // LinuxCNC's named O-words, `o<probe> call`: the statement after the name says what it does.
        if letter == b'O' && c.text.get(c.at) == Some(&b'<') {
            let end = c.text[c.at..].iter().position(|&b| b == b'>').ok_or(c.at)?;
            c.at += end + 1;
            return Ok(());
        }
        let (value, decimals) = if c.assigns() {
            c.at += 1;
            if c.string() {
                // `T="6 mm end mill"`: a tool by its name; M6 changes it.
                return Ok(());
            }
            self.valued(c)?
        } else {
            let digits = c.at;
            let (value, decimals) = self.operand(c)?;
            // Heidenhain ISO's cycle parameters: `P01 -4.`, a two-digit
            // number and then the value (`P05 F120.`: the feed word that follows).
            if letter == b'P' && c.at - digits == 2 && decimals == 0 && (1.0..=9.0).contains(&value) {
                extras.parameters = true;
                if c.peek().is_some_and(|b| matches!(b, b'+' | b'-' | b'.' | b'0'..=b'9')) {
                    extras.p[value as usize - 1] = self.operand(c)?.0;
                }
                return Ok(());
            }
            if letter == b'R' && c.assigns() {
                // `R1=5`: Sinumerik's R parameters.
                // They take effect at once: a later word of the block reads the new value.
                let key = format!("R{value}");
                c.at += 1;
                let value = self.expr(c)?;
                if value.is_nan() {
                    extras.notes.push((Note::UnknownValue, start as u32, c.at as u32, "R"));
                    self.values.remove(key.as_str());
                } else {
                    self.values.insert(key.into(), value);
                }
                return Ok(());
            }
            (value, decimals)
        };
        items.push(Item { kind: ItemKind::Word(letter), start: start as u32, end: c.at as u32, value, decimals });
        Ok(())
    }

    /// An expression standing for a word's value, with the decimals of a
    /// lone number (4 for a computed one).
    fn valued(&mut self, c: &mut Cursor) -> Result<(f64, u8), usize> {
        c.blanks();
        let from = c.at;
        let value = self.expr(c)?;
        let lone = grammar::scan_at(c.text, from).filter(|(end, ..)| *end == c.at);
        Ok(lone.map_or((value, 4), |(_, _, d)| (value, d)))
    }

    /// A statement that starts with a name: true when it takes the rest of
    /// the line.
    fn statement(&mut self, c: &mut Cursor, items: &mut Vec<Item>, extras: &mut Extras) -> Result<bool, usize> {
        let start = c.at;
        let name = c.name().ok_or(start)?;
        let name = &*name;
        let note = |extras: &mut Extras, note, what: &'static str, end: usize| {
            extras.notes.push((note, start as u32, end as u32, what));
        };
        // `CR=5`: the Sinumerik arc radius.
        if name == b"CR" && c.assigns() {
            c.at += 1;
            let (value, decimals) = self.valued(c)?;
            items.push(Item { kind: ItemKind::Word(b'R'), start: start as u32, end: c.at as u32, value, decimals });
            return Ok(false);
        }
        // `LABEL1:`, a Sinumerik jump label.
        if c.text.get(c.at) == Some(&b':') {
            c.at += 1;
            return Ok(false);
        }
        if name == b"SUPA" {
            extras.machine = true;
            return Ok(false);
        }
        if name == b"MCALL" {
            let at = c.at;
            if c.peek().is_some_and(|b| b.is_ascii_alphabetic()) {
                let call = c.at;
                self.statement(c, items, extras)?;
                match extras.cycle.as_mut() {
                    Some(cycle) => cycle.modal = true,
                    None => return Err(call),
                }
            } else {
                c.at = at;
                extras.mcall_off = true;
            }
            return Ok(false);
        }
        if let Some(digits) = name.strip_prefix(b"CYCLE").filter(|d| !d.is_empty() && d.iter().all(u8::is_ascii_digit))
        {
            let number: u32 = std::str::from_utf8(digits).ok().and_then(|d| d.parse().ok()).ok_or(start)?;
            let args = self.arguments(c)?;
            match number {
                81..=89 | 840 => {
                    extras.cycle = Some(Cycle {
                        number,
                        rtp: args[0],
                        rfp: args[1],
                        sdis: args[2],
                        dp: args[3],
                        dpr: args[4],
                        modal: false,
                        start: start as u32,
                        end: c.at as u32,
                    })
                }
                // CYCLE832: the high-speed settings (tolerance, smoothing); no motion.
                832 => {}
                _ => note(extras, Note::NotReplayed, "a Sinumerik cycle that is not a drilling cycle", c.at),
            }
            return Ok(false);
        }
        // `DWT=1.5`: OSAI's dwell, in seconds (Autodesk's `osai.cps` writes
        // it for `onDwell` and a cycle's dwell); no motion.
        if name == b"DWT" && c.assigns() {
            c.at += 1;
            self.expr(c)?;
            return Ok(false);
        }
        let upper = std::str::from_utf8(name).unwrap_or("");
        if QUIET.contains(&upper) {
            if c.peek() == Some(b'(') || c.peek() == Some(b'[') {
                self.skip_group(c)?;
            }
            return Ok(!matches!(upper, "SOFT" | "BRISK" | "FFWON" | "FFWOF" | "CFC" | "CFTCP" | "CFIN" | "STOPRE"));
        }
        if let Some(w) = CALLS.iter().find(|w| **w == upper) {
            note(extras, Note::Call, w, c.text.len());
            c.at = c.text.len();
            return Ok(true);
        }
        // Okuma's common variables, `VC1=0`, `VC[2]=VC1*2`; its system
        // variables (`VZOFX[21]=0.`, a work offset) are set and not replayed.
        if name[0] == b'V' && name.len() > 1 {
            let common = name.starts_with(b"VC") && name[2..].iter().all(u8::is_ascii_digit);
            let index = if c.peek() == Some(b'[') { Some(self.operand(c)?.0) } else { None };
            if !c.assigns() {
                return Err(start);
            }
            c.at += 1;
            let value = self.expr(c)?;
            let key = match (common, index) {
                (true, None) if name.len() > 2 => Some(upper.to_string()),
                (true, Some(i)) if name.len() == 2 => Some(format!("VC{i}")),
                _ => None,
            };
            match key {
                Some(key) if value.is_nan() => {
                    note(extras, Note::UnknownValue, "VC", c.at);
                    self.values.remove(key.as_str());
                }
                Some(key) => {
                    self.values.insert(key.into(), value);
                }
                None => note(extras, Note::NotReplayed, "an Okuma system variable set", c.at),
            }
            return Ok(false);
        }
        // `$P_UIFR[1,X,TR]=120.05`: a Sinumerik system variable (here a
        // work offset), set and not replayed.
        if name[0] == b'$' {
            if c.peek() == Some(b'[') {
                self.skip_group(c)?;
            }
            if !c.assigns() {
                return Err(start);
            }
            c.at += 1;
            self.expr(c)?;
            note(extras, Note::NotReplayed, "a Sinumerik system variable set", c.at);
            return Ok(false);
        }
        if let Some(w) =
            FLOW.iter().find(|w| upper.strip_prefix(**w).is_some_and(|d| d.bytes().all(|b| b.is_ascii_digit())))
        {
            note(extras, Note::Flow, w, c.text.len());
            c.at = c.text.len();
            return Ok(true);
        }
        // Klipper's extended G-code: a command name first on the line and
        // `NAME=VALUE` parameters after it, or none (Klipper's G-Codes
        // reference: "they start with a command name and may be followed
        // by one or more parameters", `SET_SERVO SERVO=myservo ANGLE=5.3`).
        let first = items.iter().all(|i| matches!(i.kind, ItemKind::Delete | ItemKind::Word(b'N')));
        if first && !NOT_REPLAYED.contains(&upper) && klipper_parameters(&c.text[c.at..]) {
            note(extras, Note::Macro, "a command of Klipper's extended G-code, or a macro it runs", c.text.len());
            c.at = c.text.len();
            return Ok(true);
        }
        if NOT_REPLAYED.contains(&upper) {
            // A frame statement alone resets it: nothing to replay.
            let alone = c.peek().is_none_or(|b| b == b';');
            if !alone {
                note(extras, Note::NotReplayed, "a Sinumerik frame or contour statement", c.text.len());
            }
            c.at = c.text.len();
            return Ok(true);
        }
        Err(start)
    }

    /// `( ... )` or `[ ... ]` with what it holds (strings, nested groups).
    fn skip_group(&mut self, c: &mut Cursor) -> Result<(), usize> {
        let mut depth = 0i32;
        let mut quoted = false;
        while let Some(&b) = c.text.get(c.at) {
            c.at += 1;
            match b {
                b'"' => quoted = !quoted,
                b'(' | b'[' if !quoted => depth += 1,
                b')' | b']' if !quoted => {
                    depth -= 1;
                    if depth == 0 {
                        return Ok(());
                    }
                }
                _ => {}
            }
        }
        Err(c.text.len())
    }

    /// A cycle's arguments `( a, b, , d )`: the first five, NaN where empty.
    fn arguments(&mut self, c: &mut Cursor) -> Result<[f64; 5], usize> {
        let mut args = [f64::NAN; 5];
        if !c.eat(b'(') {
            return Err(c.at);
        }
        let mut i = 0;
        loop {
            match c.peek() {
                Some(b')') => {
                    c.at += 1;
                    return Ok(args);
                }
                Some(b',') => {
                    c.at += 1;
                    i += 1;
                }
                Some(b'"') => {
                    if !c.string() {
                        return Err(c.at);
                    }
                }
                Some(_) => {
                    let v = self.expr(c)?;
                    if let Some(a) = args.get_mut(i) {
                        *a = v;
                    }
                }
                None => return Err(c.at),
            }
        }
    }

    /// The key of a `#` parameter (after the `#`): `#100`, `#<name>`, `#[expr]`.
    fn reference(&mut self, c: &mut Cursor) -> Result<Box<str>, usize> {
        self.key.clear();
        self.key.push('#');
        match c.text.get(c.at) {
            Some(b'<') => {
                let end = c.text[c.at..].iter().position(|&b| b == b'>').ok_or(c.at)?;
                // LinuxCNC names are read without case and blanks.
                for &b in &c.text[c.at..c.at + end + 1] {
                    if b != b' ' && b != b'\t' {
                        self.key.push(b.to_ascii_lowercase() as char);
                    }
                }
                c.at += end + 1;
            }
            Some(b'[') | Some(b'#') => {
                let (v, _) = self.operand(c)?;
                self.key.push_str(&format!("{v}"));
            }
            _ => {
                let (end, v, decimals) = grammar::scan_at(c.text, c.at).ok_or(c.at)?;
                if decimals > 0 || c.text[c.at] == b'-' {
                    return Err(c.at);
                }
                c.at = end;
                self.key.push_str(&format!("{v}"));
            }
        }
        Ok(self.key.as_str().into())
    }

    fn get(&self, key: &str) -> f64 {
        self.values.get(key).copied().unwrap_or(f64::NAN)
    }

    /// An operand: a number, a parameter, a group, a function, with its sign.
    fn operand(&mut self, c: &mut Cursor) -> Result<(f64, u8), usize> {
        let Some(b) = c.peek() else { return Err(c.at) };
        match b {
            b'-' => {
                c.at += 1;
                let (v, d) = self.operand(c)?;
                Ok((-v, d))
            }
            b'+' => {
                c.at += 1;
                self.operand(c)
            }
            b'0'..=b'9' | b'.' => {
                let (end, v, d) = grammar::scan_at(c.text, c.at).ok_or(c.at)?;
                c.at = end;
                Ok((v, d))
            }
            b'#' => {
                c.at += 1;
                let key = self.reference(c)?;
                Ok((self.get(&key), 4))
            }
            b'[' | b'(' => {
                c.at += 1;
                let v = self.expr(c)?;
                if !c.eat(if b == b'[' { b']' } else { b')' }) {
                    return Err(c.at);
                }
                Ok((v, 4))
            }
            b'A'..=b'Z' | b'$' | b'_' => {
                let start = c.at;
                let name = c.name().ok_or(start)?;
                if let Some(f) = function(&name) {
                    let (v, _) = self.operand(c)?;
                    // ATAN[a]/[b]: the angle of b, a.
                    if *name == *b"ATAN" && c.peek() == Some(b'/') && c.text.get(c.at + 1) == Some(&b'[') {
                        c.at += 1;
                        let (b, _) = self.operand(c)?;
                        return Ok((v.atan2(b).to_degrees(), 4));
                    }
                    return Ok((f(v), 4));
                }
                // Sinumerik R parameters (R1, R[2]) and system variables ($P_...), and the constant PI.
                if *name == *b"PI" {
                    return Ok((std::f64::consts::PI, 4));
                }
                if *name == *b"R" && c.peek() == Some(b'[') {
                    let (i, _) = self.operand(c)?;
                    return Ok((self.get(&format!("R{i}")), 4));
                }
                // Okuma's common variables.
                if name.starts_with(b"VC") {
                    if name.len() == 2 && c.peek() == Some(b'[') {
                        let (i, _) = self.operand(c)?;
                        return Ok((self.get(&format!("VC{i}")), 4));
                    }
                    if name.len() > 2 && name[2..].iter().all(u8::is_ascii_digit) {
                        return Ok((self.get(std::str::from_utf8(&name).unwrap_or("")), 4));
                    }
                }
                if name.len() > 1 && name[0] == b'R' && name[1..].iter().all(u8::is_ascii_digit) {
                    let i: u32 = std::str::from_utf8(&name[1..]).ok().and_then(|d| d.parse().ok()).ok_or(start)?;
                    return Ok((self.get(&format!("R{i}")), 4));
                }
                // Sinumerik system variables and the cycles' constants (`_SEMIFIN`): not known.
                if name[0] == b'$' || name[0] == b'_' {
                    if c.peek() == Some(b'[') {
                        self.skip_group(c)?;
                    }
                    return Ok((f64::NAN, 4));
                }
                Err(start)
            }
            _ => Err(c.at),
        }
    }

    /// An expression: operands and binary operators, by precedence.
    fn expr(&mut self, c: &mut Cursor) -> Result<f64, usize> {
        self.binary(c, 0)
    }

    fn binary(&mut self, c: &mut Cursor, level: u8) -> Result<f64, usize> {
        if level == 6 {
            return Ok(self.operand(c)?.0);
        }
        let mut left = self.binary(c, level + 1)?;
        loop {
            let save = c.at;
            let Some(op) = self.operator(c, level) else {
                c.at = save;
                return Ok(left);
            };
            let right = self.binary(c, level + 1)?;
            let truth = |b: bool| f64::from(u8::from(b));
            left = match op {
                "OR" => truth(left != 0.0 || right != 0.0),
                "XOR" => truth((left != 0.0) != (right != 0.0)),
                "AND" => truth(left != 0.0 && right != 0.0),
                "EQ" | "==" => truth(left == right),
                "NE" | "<>" => truth(left != right),
                "GT" | ">" => truth(left > right),
                "GE" | ">=" => truth(left >= right),
                "LT" | "<" => truth(left < right),
                "LE" | "<=" => truth(left <= right),
                "+" => left + right,
                "-" => left - right,
                "*" => left * right,
                "/" => left / right,
                "MOD" => left % right,
                _ => left.powf(right),
            };
            if left.is_infinite() {
                left = f64::NAN;
            }
        }
    }

    /// The binary operator of `level` at the cursor, if any (consumed).
    fn operator(&mut self, c: &mut Cursor, level: u8) -> Option<&'static str> {
        c.peek()?;
        let rest = &c.text[c.at..];
        let word = |w: &str| {
            rest.len() > w.len()
                && rest[..w.len()].eq_ignore_ascii_case(w.as_bytes())
                && !rest[w.len()].is_ascii_alphanumeric()
        };
        let ops: &[&'static str] = match level {
            0 => &["OR", "XOR"],
            1 => &["AND"],
            2 => &["EQ", "NE", "GT", "GE", "LT", "LE", "==", "<>", ">=", "<=", ">", "<"],
            3 => &["+", "-"],
            4 => &["*", "/", "MOD"],
            _ => &["**"],
        };
        // `**` is a power, not a product.
        if level == 4 && rest.starts_with(b"**") {
            return None;
        }
        let op = ops.iter().find(|op| {
            if op.as_bytes()[0].is_ascii_alphabetic() { word(op) } else { rest.starts_with(op.as_bytes()) }
        })?;
        c.at += op.len();
        Some(op)
    }
}
