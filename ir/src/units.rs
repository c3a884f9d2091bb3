//! Length units, and the conversion between the units a toolpath is written
//! in and the units a post writes.
//!
//! A post's output units are what it states (Vectric `UNITS`, VcPost
//! `Postc.Units`, a CIMCO section post's `postcOptions.units`, a RON post's
//! `info.units`); a post that states none and writes a units word of one
//! system only in its text (`G21` and no `G20`, or the reverse; `G71` or
//! `G70` in a post that writes neither) writes that system ([`Post::output_units`], docs/units.md). The runtime converts the
//! toolpath's lengths and feeds into them before the post sees an event.

use serde::{Deserialize, Serialize};

use crate::code::{Expr, Piece};
use crate::post::Post;
use crate::visit::{Visit, walk_expr};

/// The unit of every length (and of every feed, per minute) in a toolpath or
/// in a post's output.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Units {
    /// Millimetres; feeds in mm/min.
    #[default]
    Mm,
    /// Inches; feeds in inch/min.
    Inch,
}

impl Units {
    /// Millimetres per one unit.
    pub fn mm_per_unit(self) -> f64 {
        match self {
            Units::Mm => 1.0,
            Units::Inch => 25.4,
        }
    }

    /// The factor that turns a length in `self` into a length in `to`.
    pub fn factor_to(self, to: Units) -> f64 {
        match (self, to) {
            (Units::Mm, Units::Inch) => 1.0 / 25.4,
            (Units::Inch, Units::Mm) => 25.4,
            _ => 1.0,
        }
    }

    /// The word a post prints for these units (`[UNITS]` in Vectric
    /// posts): the guides' own words for the UNITS statement, "INCHES or
    /// MM" (the 2012 Vectric post guide), which every inch post of the corpus writes.
    pub fn name(self) -> &'static str {
        match self {
            Units::Mm => "MM",
            Units::Inch => "INCHES",
        }
    }
}

/// The units words a post's text holds: `G21` (millimetres) and `G20`
/// (inches), and `G71` and `G70`, the same words of Siemens, Heidenhain
/// ISO, OSAI and Fagor controls, as G words (not after a letter, not
/// followed by a digit or a point), in its literal output text, its text
/// constants (globals, code) and its scripts' source.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WrittenUnits {
    /// `G21`.
    pub mm: bool,
    /// `G20`.
    pub inch: bool,
    /// `G71`.
    pub mm_iso: bool,
    /// `G70`.
    pub inch_iso: bool,
}

impl WrittenUnits {
    /// The one system the post writes, if it writes words of one only:
    /// by `G21` and `G20`, and, in a post that writes neither, by `G71`
    /// and `G70` (Fanuc and LinuxCNC lathes write `G70` and `G71` as
    /// turning cycles, beside `G20` or `G21`).
    pub fn only(self) -> Option<Units> {
        let (mm, inch) = if self.mm || self.inch { (self.mm, self.inch) } else { (self.mm_iso, self.inch_iso) };
        match (mm, inch) {
            (true, false) => Some(Units::Mm),
            (false, true) => Some(Units::Inch),
            _ => None,
        }
    }

    /// The word that says `units` in the family of words the post writes
    /// (`G21` or `G71` for millimetres).
    pub fn word(self, units: Units) -> &'static str {
        let iso = !(self.mm || self.inch) && (self.mm_iso || self.inch_iso);
        match (units, iso) {
            (Units::Mm, false) => "G21",
            (Units::Inch, false) => "G20",
            (Units::Mm, true) => "G71",
            (Units::Inch, true) => "G70",
        }
    }

    /// Adds the units words of `text`.
    pub fn scan(&mut self, text: &[u8]) {
        for (i, &b) in text.iter().enumerate() {
            if b != b'G' && b != b'g' {
                continue;
            }
            if i > 0 && text[i - 1].is_ascii_alphabetic() {
                continue;
            }
            let rest = &text[i + 1..];
            let unit = match rest {
                [b'2', b'1', ..] => &mut self.mm,
                [b'2', b'0', ..] => &mut self.inch,
                [b'7', b'1', ..] => &mut self.mm_iso,
                [b'7', b'0', ..] => &mut self.inch_iso,
                _ => continue,
            };
            if !rest.get(2).is_some_and(|c| c.is_ascii_digit() || *c == b'.') {
                *unit = true;
            }
        }
    }
}

impl Post {
    /// The units words the post's text holds.
    pub fn written_units(&self) -> WrittenUnits {
        struct Scan(WrittenUnits);
        impl Visit for Scan {
            fn visit_piece(&mut self, piece: &Piece) {
                match piece {
                    Piece::Text(bytes) => self.0.scan(bytes),
                    Piece::Expr(e) => self.visit_expr(e),
                    Piece::Var(_) => {}
                }
            }
            fn visit_expr(&mut self, expr: &Expr) {
                if let Expr::Text(t) = expr {
                    self.0.scan(t.as_bytes());
                }
                walk_expr(self, expr);
            }
        }
        let mut scan = Scan(WrittenUnits::default());
        scan.visit_post(self);
        for g in &self.globals {
            scan.visit_expr(&g.initial);
        }
        for s in &self.scripts {
            scan.0.scan(s.source.as_bytes());
        }
        scan.0
    }

    /// The units the post writes: the ones it states, else (unless it
    /// reads the units it is handed: [`PostInfo::reads_units`]) the one
    /// system whose units word its text holds, else `None` (the
    /// toolpath's own).
    ///
    /// [`PostInfo::reads_units`]: crate::post::PostInfo::reads_units
    pub fn output_units(&self) -> Option<Units> {
        self.info.units.or_else(|| if self.info.reads_units { None } else { self.written_units().only() })
    }
}
