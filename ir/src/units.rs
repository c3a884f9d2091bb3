//! Length units, and the conversion between the units a toolpath is written
//! in and the units a post writes.

use serde::{Deserialize, Serialize};

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
    /// MM" (seed 000), which every inch post of the corpus writes.
    pub fn name(self) -> &'static str {
        match self {
            Units::Mm => "MM",
            Units::Inch => "INCHES",
        }
    }
}
