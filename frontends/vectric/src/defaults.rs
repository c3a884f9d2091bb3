//! How a label prints when the post uses it without declaring it with `VAR`.
//!
//! Seed 000 ("Default Formatting for Variables") lists the defaults of the
//! rows marked *seed 000*; they are copied as written there, including the
//! single blank prefix of the position, home, arc and material labels
//! (`[X|A| |1.3]`) and the on-change `C` of `[FC|C ||1.0]`, and the empty
//! prefix of `[N|A|1.0]`, `[S|A|1.0]`, `[F|A|1.0]` and `[FP|A|1.0]`, which
//! leave the prefix field out. Seed 001 lists other defaults (`[X|A||1.0]`,
//! `[FC|A||1.0]`); seed 000 wins (brief, decision 8). Every other label has
//! a default chosen here (*postc*): an empty prefix, printed every time,
//! whole numbers for counts and numbers, three decimals for lengths and
//! angles like the seed's lengths, two for dwell seconds as the corpus posts
//! that declare `DWELL` do. Text labels print their text; their format does
//! not matter.
//!
//! | label | default | source |
//! |-------|---------|--------|
//! | N | `[N\|A\|1.0]` (empty prefix) | seed 000 |
//! | S | `[S\|A\|1.0]` (empty prefix) | seed 000 |
//! | F | `[F\|A\|1.0]` (empty prefix) | seed 000 |
//! | FP | `[FP\|A\|1.0]` (empty prefix) | seed 000 |
//! | FC | `[FC\|C\|\|1.0]` | seed 000 |
//! | X Y Z | `[X\|A\| \|1.3]` | seed 000 |
//! | XH YH ZH | `[XH\|A\| \|1.3]` | seed 000 |
//! | SAFEZ | `[SAFEZ\|A\| \|1.3]` | seed 000 |
//! | ArcStartX ArcStartY | `[ArcStartX\|A\| \|1.3]` | seed 000 |
//! | I J | `[I\|A\| \|1.3]` | seed 000 |
//! | IA JA | `[IA\|A\| \|1.3]` | seed 000 |
//! | ArcMidX ArcMidY ArcMidXI ArcMidYI | `[ArcMidX\|A\| \|1.3]` | seed 000 |
//! | Radius | `[Radius\|A\| \|1.3]` | seed 000 |
//! | Angle | `[Angle\|A\| \|1.3]` | seed 000 |
//! | XLENGTH YLENGTH ZLENGTH XMIN YMIN ZMIN XMAX YMAX ZMAX | `[XLENGTH\|A\| \|1.3]` | seed 000 |
//! | K KA | `[K\|A\| \|1.3]` (like I and J) | postc |
//! | A B C | `[A\|A\|\|1.3]` (degrees) | postc |
//! | T TP | `[T\|A\|\|1.0]` | postc |
//! | P | `[P\|A\|\|1.0]` | postc |
//! | FI | `[FI\|A\|\|1.3]` | postc |
//! | DWELL | `[DWELL\|A\|\|1.2]` (corpus posts use `1.2`) | postc |
//! | TDIA | `[TDIA\|A\|\|1.3]` | postc |
//! | WRAP_DIA | `[WRAP_DIA\|A\|\|1.3]` | postc |
//! | X_ORIGIN_POS Y_ORIGIN_POS | `[X_ORIGIN_POS\|A\|\|1.3]` | postc |
//! | D H | `[D\|A\|\|1.0]` | postc |
//! | text labels (TOOLNAME, DATE, TIME, UNITS, ...) | `[TOOLNAME\|A\|\|1.0]`: the text | postc |

use postc_ir::{Modality, Quantity};

use crate::format_spec::{FormatSpec, parse_format};

/// How an undeclared label prints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DefaultFormat {
    pub modality: Modality,
    pub prefix: &'static str,
    pub format: FormatSpec,
}

/// The default of a quantity (every quantity has one).
pub fn default_format(quantity: Quantity) -> DefaultFormat {
    let (modality, prefix, format) = default_text(quantity);
    DefaultFormat { modality, prefix, format: parse_format(format).unwrap_or_default() }
}

/// The default of a quantity as written: modality, prefix, format text.
fn default_text(quantity: Quantity) -> (Modality, &'static str, &'static str) {
    use Quantity as Q;
    match quantity {
        Q::BlockNumber | Q::SpindleSpeed | Q::Feed | Q::PlungeFeed => (Modality::Always, "", "1.0"),
        Q::CutFeed => (Modality::OnChange, "", "1.0"),
        Q::X
        | Q::Y
        | Q::Z
        | Q::HomeX
        | Q::HomeY
        | Q::HomeZ
        | Q::SafeZ
        | Q::ArcStartX
        | Q::ArcStartY
        | Q::I
        | Q::J
        | Q::K
        | Q::IA
        | Q::JA
        | Q::KA
        | Q::ArcMidX
        | Q::ArcMidY
        | Q::ArcMidXI
        | Q::ArcMidYI
        | Q::Radius
        | Q::Angle
        | Q::XLength
        | Q::YLength
        | Q::ZLength
        | Q::XMin
        | Q::YMin
        | Q::ZMin
        | Q::XMax
        | Q::YMax
        | Q::ZMax => (Modality::Always, " ", "1.3"),
        Q::A | Q::B | Q::C | Q::InverseTimeFeed | Q::ToolDiameter | Q::WrapDiameter | Q::XOrigin | Q::YOrigin => {
            (Modality::Always, "", "1.3")
        }
        Q::DwellTime => (Modality::Always, "", "1.2"),
        Q::Tool | Q::PreviousTool | Q::Power | Q::CompRegister | Q::LengthOffset => (Modality::Always, "", "1.0"),
        _ => (Modality::Always, "", "1.0"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_defaults() {
        let x = default_format(Quantity::X);
        assert_eq!((x.modality, x.prefix, x.format.decimals), (Modality::Always, " ", 3));
        let fc = default_format(Quantity::CutFeed);
        assert_eq!((fc.modality, fc.prefix, fc.format.decimals), (Modality::OnChange, "", 0));
        let n = default_format(Quantity::BlockNumber);
        assert_eq!((n.prefix, n.format.decimals), ("", 0));
    }

    #[test]
    fn every_format_parses() {
        for &q in Quantity::ALL {
            let (_, _, text) = default_text(q);
            assert!(parse_format(text).is_ok(), "{q:?}: {text}");
        }
        assert_eq!(default_format(Quantity::DwellTime).format.decimals, 2);
    }
}
