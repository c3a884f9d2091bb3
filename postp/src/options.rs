//! The options file: the seed's per-controller settings (startup string,
//! END, GOHOME, REWIND, tmark, retractz, maxspeed, tool height offset
//! placement) and a few more (program number, sequence numbering, decimals,
//! diameter programming), as RON.
//!
//! Each controller has a complete embedded file (`corpus/posts/postp/NAME.ron`);
//! `--options FILE` names a file with any subset of the fields, which
//! replace the embedded ones. Strings are written as they are (`end: "M30"`,
//! no `Some(...)`); `\n` in a string separates blocks and `{units}` becomes
//! G20 or G21 from the CL file's units. The values reach the post as
//! globals set before its first statement runs ([`Options::globals`]).

use postc_ir::{Expr, Post, Units};
use serde::{Deserialize, Serialize};

/// Where RETRCT goes when no CLEARP plane is in force.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum RetractZ {
    /// The `zhome` blocks (the Z home position).
    Home,
    /// A rapid to this Z (in the CL file's coordinates).
    At(f64),
}

/// Where LOADTL's height and diameter offsets go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum HeightOffset {
    /// Into the first block with a Z word after the tool change.
    NextZ,
    /// A block of their own right after the tool change.
    OwnBlock,
}

/// Sequence numbers before the first SEQNO.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Sequence {
    Off,
    On { start: f64, increment: f64 },
}

/// A controller's options, complete.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Options {
    /// RESET: the safe startup string.
    pub startup: String,
    /// END.
    pub end: String,
    /// GOHOME.
    pub gohome: String,
    /// REWIND.
    pub rewind: String,
    /// TMARK without a character code.
    pub tmark: String,
    /// RETRCT without a clearance plane.
    pub retractz: RetractZ,
    /// The blocks RETRCT writes for `retractz: Home`.
    pub zhome: String,
    /// Lathes: spindle limit written (G50 S, or the controller's form)
    /// each time the spindle starts at constant surface speed; 0 = none.
    pub maxspeed: f64,
    /// Where LOADTL's H and D offsets go.
    pub height_offset: HeightOffset,
    /// The program number a SEQNO without one writes; 0 = none.
    pub program_number: u32,
    /// Sequence numbers before the first SEQNO.
    pub sequence: Sequence,
    /// Decimals of coordinates; 0 = 4 for inch, 3 for millimetre files.
    pub decimals: u8,
    /// Lathes: X is written as a diameter (twice the CL file's X).
    pub diameter: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            startup: String::new(),
            end: "M30".into(),
            gohome: String::new(),
            rewind: "M30".into(),
            tmark: "%".into(),
            retractz: RetractZ::Home,
            zhome: String::new(),
            maxspeed: 0.0,
            height_offset: HeightOffset::NextZ,
            program_number: 0,
            sequence: Sequence::Off,
            decimals: 0,
            diameter: true,
        }
    }
}

/// Some of the fields: what an options file holds.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Patch {
    startup: Option<String>,
    end: Option<String>,
    gohome: Option<String>,
    rewind: Option<String>,
    tmark: Option<String>,
    retractz: Option<RetractZ>,
    zhome: Option<String>,
    maxspeed: Option<f64>,
    height_offset: Option<HeightOffset>,
    program_number: Option<u32>,
    sequence: Option<Sequence>,
    decimals: Option<u8>,
    diameter: Option<bool>,
}

impl Patch {
    /// Reads an options file; an error has the 1-based line and column.
    pub fn parse(text: &str) -> Result<Patch, (String, usize, usize)> {
        ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str(text)
            .map_err(|e| (e.code.to_string(), e.span.start.line, e.span.start.col))
    }

    /// Whether every field is given (the embedded files are complete).
    pub fn is_complete(&self) -> bool {
        let p = self;
        p.startup.is_some()
            && p.end.is_some()
            && p.gohome.is_some()
            && p.rewind.is_some()
            && p.tmark.is_some()
            && p.retractz.is_some()
            && p.zhome.is_some()
            && p.maxspeed.is_some()
            && p.height_offset.is_some()
            && p.program_number.is_some()
            && p.sequence.is_some()
            && p.decimals.is_some()
            && p.diameter.is_some()
    }
}

impl Options {
    /// These options with the fields a patch gives replaced.
    pub fn apply(mut self, p: Patch) -> Options {
        macro_rules! take {
            ($($f:ident),*) => { $( if let Some(v) = p.$f { self.$f = v; } )* };
        }
        take!(
            startup,
            end,
            gohome,
            rewind,
            tmark,
            retractz,
            zhome,
            maxspeed,
            height_offset,
            program_number,
            sequence,
            decimals,
            diameter
        );
        self
    }

    /// The decimals of coordinates for a file in `units`.
    pub fn decimals_for(&self, units: Units) -> u8 {
        match (self.decimals, units) {
            (0, Units::Inch) => 4,
            (0, _) => 3,
            (d, _) => d.min(6),
        }
    }

    /// The globals the post reads, by name (see `docs/apt.md`).
    pub fn globals(&self, units: Units, axis_type: u8, machine: &str) -> Vec<(&'static str, Expr)> {
        let code = if units == Units::Inch { "G20" } else { "G21" };
        let text = |s: &str| Expr::Text(s.replace("{units}", code));
        let (seq_on, start, incr) = match self.sequence {
            Sequence::Off => (false, 10.0, 10.0),
            Sequence::On { start, increment } => (true, start, increment),
        };
        vec![
            ("OptStartup", text(&self.startup)),
            ("OptEnd", text(&self.end)),
            ("OptGohome", text(&self.gohome)),
            ("OptRewind", text(&self.rewind)),
            ("OptTmark", text(&self.tmark)),
            ("OptZHome", text(&self.zhome)),
            ("OptMaxSpeed", Expr::Number(self.maxspeed)),
            (
                "OptHeightOffset",
                Expr::Text(if self.height_offset == HeightOffset::NextZ { "NEXTZ" } else { "BLOCK" }.into()),
            ),
            ("OptProgram", Expr::Number(f64::from(self.program_number))),
            ("OptSeqOn", Expr::Bool(seq_on)),
            ("OptSeqStart", Expr::Number(start)),
            ("OptSeqIncr", Expr::Number(incr)),
            ("OptDecimals", Expr::Number(f64::from(self.decimals_for(units)))),
            ("OptDiameter", Expr::Bool(self.diameter)),
            ("OptUnits", Expr::Text(if units == Units::Inch { "INCH" } else { "MM" }.into())),
            ("OptAxisType", Expr::Number(f64::from(axis_type))),
            ("OptMachine", Expr::Text(machine.into())),
        ]
    }

    /// Sets the post's globals of these names to the options' values, so
    /// they hold them before the post's first statement runs. Globals the
    /// post does not have are left out.
    pub fn inject(&self, post: &mut Post, units: Units, axis_type: u8, machine: &str) {
        for (name, value) in self.globals(units, axis_type, machine) {
            if let Some(g) = post.globals.iter_mut().find(|g| g.name.eq_ignore_ascii_case(name)) {
                g.initial = value;
            }
        }
    }
}
