//! The words of CL records: which major word a parsed record is
//! ([`Major`]), and a typed view of its arguments ([`Rec`], [`Arg`]) that
//! the record handlers read.
//!
//! Major words are matched without regard to case. Words the reader has no
//! handler for but knows to be post-processor words (the seed's list and the
//! vendor words found in real CL files) pass through as `Command` events;
//! any other word is unknown and reported.

use postc_ir::diagnostic::{FileId, Span};
use postc_ir::event::Arg as EventArg;

use crate::grammar::{Item, ItemKind};

/// The major word of a record, as far as the reader treats it specially.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Major {
    Goto,
    From,
    Godlta,
    Gohome,
    Rapid,
    Circle,
    Fedrat,
    Spindl,
    Coolnt,
    Cutcom,
    Cycle,
    /// `DELAY` and `DWELL`.
    Delay,
    Loadtl,
    /// `LOAD/TOOL,n` (other `LOAD` forms pass through).
    Load,
    Cutter,
    Tldata,
    /// `UNITS` and `UNIT`.
    Units,
    /// NX `TOOL PATH/name,TOOL,tool`.
    ToolPath,
    /// NX `END-OF-PATH`.
    EndOfPath,
    Fini,
    /// `INDIRV/i,j,k`: the start direction of the next `TLON,GOFWD` arc.
    Indirv,
    /// `TLON,GOFWD/...` and the other tool-position and direction pairs.
    DriveMotion,
    /// `GO/...`, `GOFWD/` and the like without a tool-position word: part program only.
    SourceMotion,
    /// `MULTAX/ON|OFF`: passes through and may end the tool axis.
    Multax,
    /// `TLAXIS/i,j,k`: passes through and sets the tool axis.
    Tlaxis,
    /// `NURBS/`: a spline move the reader cannot follow.
    Nurbs,
    /// Coordinate system changes (`CSYS`, `MSYS`, `TRNTYP`): pass through and end the tool axis.
    Csys,
    /// A post-processor word passed through as a `Command`.
    Pass,
    /// Not a word the reader knows.
    Unknown,
}

/// Classifies the head words of a record (already upper case).
pub(crate) fn classify(first: &str, second: Option<&str>) -> Major {
    match (first, second) {
        ("GOTO", None) => Major::Goto,
        ("TOOL", Some("PATH")) => Major::ToolPath,
        (
            "TLON" | "TLLFT" | "TLRGT" | "TLOFPS" | "TLONPS",
            Some("GOFWD" | "GOLFT" | "GORGT" | "GOBACK" | "GOUP" | "GODOWN"),
        ) => Major::DriveMotion,
        (_, Some(_)) => Major::Unknown,
        (word, None) => match word {
            "FROM" => Major::From,
            "GODLTA" => Major::Godlta,
            "GOHOME" => Major::Gohome,
            "RAPID" => Major::Rapid,
            "CIRCLE" => Major::Circle,
            "FEDRAT" => Major::Fedrat,
            "SPINDL" => Major::Spindl,
            "COOLNT" => Major::Coolnt,
            "CUTCOM" => Major::Cutcom,
            "CYCLE" => Major::Cycle,
            "DELAY" | "DWELL" => Major::Delay,
            "LOADTL" => Major::Loadtl,
            "LOAD" => Major::Load,
            "CUTTER" => Major::Cutter,
            "TLDATA" => Major::Tldata,
            "UNITS" | "UNIT" => Major::Units,
            "END-OF-PATH" => Major::EndOfPath,
            "FINI" => Major::Fini,
            "INDIRV" => Major::Indirv,
            "GO" | "GOFWD" | "GOLFT" | "GORGT" | "GOBACK" | "GOUP" | "GODOWN" | "TLLFT" | "TLRGT" | "TLON" => {
                Major::SourceMotion
            }
            "MULTAX" => Major::Multax,
            "TLAXIS" => Major::Tlaxis,
            "NURBS" => Major::Nurbs,
            "CSYS" | "MSYS" | "TRNTYP" => Major::Csys,
            _ if is_post_word(word) => Major::Pass,
            _ => Major::Unknown,
        },
    }
}

/// Post-processor words passed through as `Command`s: the seed's words, the
/// usual APT post vocabulary, and the vendor words of real CL files.
fn is_post_word(word: &str) -> bool {
    matches!(
        word,
        // The seed (an APT post's word list).
        "AUXFUN" | "CLEARP" | "CLRSRF" | "DELETE" | "END" | "LETTER" | "MACHIN" | "MODE" | "OPSKIP" | "OPSTOP"
            | "ORIGIN" | "PREFUN" | "RESET" | "RETRCT" | "REWIND" | "ROTABL" | "SELCTL" | "SEQNO" | "STOP"
            | "THREAD" | "TMARK" | "TOOLNO" | "TRANS" | "TURRET"
            // The rest of the classic APT post vocabulary.
            | "AIR" | "ARCSLP" | "BREAK" | "CALSUB" | "CHECK" | "CLAMP" | "COUPLE" | "CUTANG" | "DISPLY" | "DRAFT"
            | "HEAD" | "INTCOD" | "LEADER" | "LINTOL" | "MAXDPM" | "MAXIPM" | "MAXRPM" | "MCHFIN" | "MCHTOL"
            | "OVPLOT" | "PENDWN" | "PENUP" | "PICKUP" | "PITCH" | "PIVOTZ" | "PLABEL" | "PLOT" | "POSMAP"
            | "PPLOT" | "PUNCH" | "REVERS" | "ROTHED" | "ROTATE" | "SAFETY" | "SAFPOS" | "SWITCH" | "UNLOAD"
            | "AUTOPS" | "INTOL" | "OUTTOL" | "TOLER" | "TRACUT" | "INDEX" | "COPY" | "CLRPLN" | "POSTN"
            | "OPTION" | "OPERATION" | "PLUNGE" | "THRU" | "LINTYP"
            // Vendor words found in real CL files.
            | "SELECT" | "SETUP" | "PAINT" | "BOX" | "MOVE_ATTRIB" | "CSI_SET_FLUTE_LENGTH"
            | "CSI_SET_EXTENSION_LENGTH" | "KNOT" | "CNTRL" | "MCS" | "FEATNO" | "MFGNO" | "OPNAME"
            | "OPSKIPS" | "TOOLPATH" | "CUTCOM_GEOMETRY_TYPE"
    )
}

/// Upper-cases a head word into `buf`; `None` when it is too long or not text.
pub(crate) fn upper<'b>(word: &[u8], buf: &'b mut [u8; 48]) -> Option<&'b str> {
    let out = buf.get_mut(..word.len())?;
    for (o, &b) in out.iter_mut().zip(word) {
        *o = b.to_ascii_uppercase();
    }
    std::str::from_utf8(out).ok()
}

/// Maps byte offsets of the assembled record back to the file.
#[derive(Clone, Copy)]
pub(crate) struct SpanMap<'a> {
    pub file: FileId,
    /// (offset in the record, offset in the file) of each piece.
    pub segments: &'a [(usize, usize)],
    /// The whole record.
    pub record: Span,
}

impl SpanMap<'_> {
    fn offset(&self, at: usize) -> usize {
        let i = self.segments.partition_point(|&(r, _)| r <= at).saturating_sub(1);
        match self.segments.get(i) {
            Some(&(r, f)) => f + at.saturating_sub(r),
            None => self.record.start + at,
        }
    }

    /// The file span of record bytes `start..end`.
    pub fn span(&self, start: usize, end: usize) -> Span {
        let a = self.offset(start).clamp(self.record.start, self.record.end);
        let b = self.offset(end.max(start + 1) - 1).saturating_add(1).clamp(a, self.record.end.max(a));
        Span::new(self.file, a, b)
    }
}

/// A record that cannot be read: what is wrong, and the argument it is
/// about (the whole record when `None`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Problem {
    pub message: String,
    pub arg: Option<usize>,
}

impl Problem {
    pub fn new(message: impl Into<String>, arg: Option<usize>) -> Problem {
        Problem { message: message.into(), arg }
    }
}

/// One argument of a record.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Arg<'a> {
    Num(f64),
    Word(&'a [u8]),
    /// `(WORD/` of a nested record.
    Open(&'a [u8]),
    /// The `)` of a nested record.
    Close,
}

impl<'a> Arg<'a> {
    /// Whether this is the word `name` (any case).
    pub fn is(&self, name: &str) -> bool {
        matches!(self, Arg::Word(w) if w.eq_ignore_ascii_case(name.as_bytes()))
    }

    pub fn num(&self) -> Option<f64> {
        match self {
            Arg::Num(v) => Some(*v),
            _ => None,
        }
    }

    pub fn word(&self) -> Option<&'a [u8]> {
        match self {
            Arg::Word(w) => Some(w),
            _ => None,
        }
    }
}

/// A parsed record: its text, items and span map.
#[derive(Clone, Copy)]
pub(crate) struct Rec<'a> {
    pub text: &'a [u8],
    pub items: &'a [Item],
    /// How many items are head words.
    pub heads: usize,
    pub map: SpanMap<'a>,
}

impl<'a> Rec<'a> {
    /// The record's span in the file.
    pub fn span(&self) -> Span {
        self.map.record
    }

    fn bytes(&self, item: &Item) -> &'a [u8] {
        self.text.get(item.start as usize..item.end as usize).unwrap_or_default()
    }

    /// The major word(s) as written, joined by `,` (`TOOL PATH` by a blank).
    pub fn word(&self) -> String {
        let mut word = String::new();
        for (i, item) in self.items[..self.heads].iter().enumerate() {
            if i > 0 {
                let gap = self.text.get(self.items[i - 1].end as usize..item.start as usize).unwrap_or_default();
                word.push(if gap.contains(&b',') { ',' } else { ' ' });
            }
            word.push_str(&String::from_utf8_lossy(self.bytes(item)).to_ascii_uppercase());
        }
        word
    }

    pub fn len(&self) -> usize {
        self.items.len() - self.heads
    }

    pub fn arg(&self, i: usize) -> Option<Arg<'a>> {
        let item = self.items.get(self.heads + i)?;
        Some(match item.kind {
            ItemKind::Number => Arg::Num(item.value),
            ItemKind::Open => Arg::Open(self.bytes(item)),
            ItemKind::Close => Arg::Close,
            _ => Arg::Word(self.bytes(item)),
        })
    }

    pub fn args(&self) -> impl Iterator<Item = Arg<'a>> + '_ {
        (0..self.len()).filter_map(|i| self.arg(i))
    }

    /// Argument `i` as written.
    pub fn arg_text(&self, i: usize) -> String {
        match self.items.get(self.heads + i) {
            Some(item) => String::from_utf8_lossy(self.bytes(item)).trim().to_string(),
            None => String::new(),
        }
    }

    /// The span of argument `i` (the whole record when there is none).
    pub fn arg_span(&self, i: usize) -> Span {
        match self.items.get(self.heads + i) {
            Some(item) => self.map.span(item.start as usize, item.end as usize),
            None => self.span(),
        }
    }

    /// The numbers among the arguments, in order, as long as `out` has room;
    /// returns how many there are in all.
    pub fn numbers(&self, out: &mut [f64]) -> usize {
        let mut n = 0;
        for item in &self.items[self.heads..] {
            if item.kind == ItemKind::Number {
                if let Some(slot) = out.get_mut(n) {
                    *slot = item.value;
                }
                n += 1;
            }
        }
        n
    }

    /// Index of the first argument that is not a number.
    pub fn first_non_number(&self) -> Option<usize> {
        self.items[self.heads..].iter().position(|i| i.kind != ItemKind::Number)
    }

    /// The arguments as a `Command`'s: nested records are flattened into
    /// their word followed by their values.
    pub fn command_args(&self) -> Vec<EventArg> {
        self.args()
            .filter_map(|a| match a {
                Arg::Num(v) => Some(EventArg::Number(v)),
                Arg::Word(w) | Arg::Open(w) => Some(EventArg::Word(String::from_utf8_lossy(w).into_owned())),
                Arg::Close => None,
            })
            .collect()
    }
}
