//! How a label prints when the post uses it without declaring it with `VAR`.
//!
//! Both guides list defaults ("Default Formatting for Variables"), and
//! they disagree; a program VCarve wrote outranks both (docs/vectric.md,
//! "Defaults of undeclared labels"):
//!
//! - **Prefix: empty everywhere (the newer Vectric post guide).** The 2012 guide writes a one-blank
//!   prefix for positions, homes, arc words and the material block
//!   (`[XMIN|A| |1.3]`), the newer Vectric post guide none (`[XMIN|A||1.3]`). A ShopBot program
//!   VCarve wrote from a header line `"'Length of material in X = [XLENGTH]"`
//!   with `XLENGTH` undeclared reads `'Length of material in X = 24.000`: one
//!   blank, the post's own, so no prefix. The 2012 guide's blank is the same
//!   in every row of its table, so the newer Vectric post guide wins for all of them.
//! - **Format and modality: the 2012 Vectric post guide where the guides disagree and no
//!   program shows the label** (the project's dialect decisions, docs/vectric.md): positions and homes
//!   `1.3` (the newer Vectric post guide: `1.0`), `[FC]` on change (the newer Vectric post guide: always).
//! - **Where they agree**, as both write them; the real programs agree
//!   where they show one (`[XLENGTH]` prints `24.000`, three decimals).
//! - **Labels neither guide lists** have a default chosen here (*postc*):
//!   an empty prefix, printed every time, whole numbers for counts (`[T]`
//!   prints `T1`, `T8` in the ShopSabre programs from `"T[T]"`), three
//!   decimals for lengths and angles like the guides' lengths, two for
//!   dwell seconds as the corpus posts that declare `DWELL` do. Text labels
//!   print their text; their format does not matter.
//!
//! | label | the 2012 Vectric post guide | the newer Vectric post guide | postc | why |
//! |-------|----------|----------|-------|-----|
//! | N, S, F, FP | `[N\|A\|1.0]` | `[N\|A\|\|1.0]` | `[N\|A\|\|1.0]` | the guides agree |
//! | FC | `[FC\|C \|\|1.0]` | `[FC\|A\|\|1.0]` | `[FC\|C\|\|1.0]` | the 2012 Vectric post guide's modality, no program shows it |
//! | X Y Z, XH YH ZH | `[X\|A\| \|1.3]` | `[X\|A\|\|1.0]` | `[X\|A\|\|1.3]` | the newer Vectric post guide's prefix (program), the 2012 Vectric post guide's format |
//! | SAFEZ, ArcStartX/Y, I J, IA JA, ArcMidX/Y, ArcMidXI/YI, Radius, Angle | `[I\|A\| \|1.3]` | `[I\|A\|\|1.3]` | `[I\|A\|\|1.3]` | the newer Vectric post guide (program: the prefix) |
//! | XLENGTH YLENGTH ZLENGTH XMIN YMIN ZMIN XMAX YMAX ZMAX | `[XMIN\|A\| \|1.3]` | `[XMIN\|A\|\|1.3]` | `[XMIN\|A\|\|1.3]` | the newer Vectric post guide, as the ShopBot program prints `[XLENGTH]` |
//! | K KA | | | `[K\|A\|\|1.3]` (like I and J) | postc |
//! | A B C | | | `[A\|A\|\|1.3]` (degrees) | postc |
//! | T TP | | | `[T\|A\|\|1.0]` | postc; the ShopSabre programs print `T1` |
//! | P | | | `[P\|A\|\|1.0]` | postc |
//! | FI | | | `[FI\|A\|\|1.3]` | postc |
//! | DWELL | | | `[DWELL\|A\|\|1.2]` (corpus posts use `1.2`) | postc |
//! | TDIA | | | `[TDIA\|A\|\|1.3]` | postc |
//! | WRAP_DIA | | | `[WRAP_DIA\|A\|\|1.3]` | postc |
//! | X_ORIGIN_POS Y_ORIGIN_POS | | | `[X_ORIGIN_POS\|A\|\|1.3]` | postc |
//! | D H | | | `[D\|A\|\|1.0]` | postc |
//! | text labels (TOOLNAME, DATE, TIME, UNITS, REVISION, ...) | | | `[TOOLNAME\|A\|\|1.0]`: the text | postc |

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
#[doc(hidden)]
pub fn default_text(quantity: Quantity) -> (Modality, &'static str, &'static str) {
    use Quantity as Q;
    match quantity {
        Q::BlockNumber | Q::SpindleSpeed | Q::Feed | Q::PlungeFeed => (Modality::Always, "", "1.0"),
        Q::CutFeed => (Modality::OnChange, "", "1.0"),
        // Lengths and angles: the guides' rows, then postc's own (A B C,
        // FI, TDIA, WRAP_DIA, the origin).
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
        | Q::ZMax
        | Q::A
        | Q::B
        | Q::C
        | Q::InverseTimeFeed
        | Q::ToolDiameter
        | Q::WrapDiameter
        | Q::XOrigin
        | Q::YOrigin => (Modality::Always, "", "1.3"),
        Q::DwellTime => (Modality::Always, "", "1.2"),
        _ => (Modality::Always, "", "1.0"),
    }
}
