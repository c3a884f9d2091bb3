//! The single-stroke font LETTER engraves with: every printable ASCII
//! character (32 to 126) as polylines on a small grid.
//!
//! The grid is 4 units wide; the baseline is y = 0, capitals and digits
//! reach y = 6, lowercase letters y = 4, descenders (g j p q y , ;) go down
//! to y = -2. A glyph is a list of strokes separated by blanks; a stroke is
//! a list of points, each two digits: x (0-4) and y + 2 (0-8). A stroke of
//! one point is a dot (the tool plunges and comes back up). Curves are cut
//! as short chords, which is what a single-stroke engraving font does.

/// Glyphs of characters 32 (blank) to 126 (`~`), in order.
#[doc(hidden)]
pub const GLYPHS: [&str; 95] = [
    "",                                 // ' '
    "2824 22",                          // !
    "1816 3836",                        // "
    "1317 3337 0444 0646",              // #
    "4717061535443303 2822",            // $
    "0248 0818170708 3343423233",       // %
    "4216172837360403122244",           // &
    "2826",                             // '
    "38272332",                         // (
    "18272312",                         // )
    "2723 0644 0446",                   // *
    "2723 0545",                        // +
    "232210",                           // ,
    "0545",                             // -
    "22",                               // .
    "0248",                             // /
    "120307183847433212 4703",          // 0
    "172822 1232",                      // 1
    "07183847460242",                   // 2
    "07183847463515 354443321203",      // 3
    "32380444",                         // 4
    "480806364543321203",               // 5
    "38180703123243443505",             // 6
    "084812",                           // 7
    "15060718384746351504031232434435", // 8
    "45150607183847433212",             // 9
    "26 23",                            // :
    "26 232210",                        // ;
    "470543",                           // <
    "0646 0444",                        // =
    "074503",                           // >
    "07183847462524 22",                // ?
    "343616144447381807031242",         // @
    "022842 1535",                      // A
    "02083847463505 3544433202",        // B
    "4738180703123243",                 // C
    "02082846442202",                   // D
    "48080242 0535",                    // E
    "480802 0535",                      // F
    "47381807031232434525",             // G
    "0208 4248 0545",                   // H
    "1838 2822 1232",                   // I
    "484332120304",                     // J
    "0208 4804 1542",                   // K
    "080242",                           // L
    "0208254842",                       // M
    "02084248",                         // N
    "120307183847433212",               // O
    "02083847463505",                   // P
    "120307183847433212 2442",          // Q
    "02083847463505 2542",              // R
    "473818070615354443321203",         // S
    "0848 2822",                        // T
    "080312324348",                     // U
    "082248",                           // V
    "0812253248",                       // W
    "0842 4802",                        // X
    "082548 2522",                      // Y
    "08480242",                         // Z
    "38282232",                         // [
    "0842",                             // \
    "18282212",                         // ]
    "062846",                           // ^
    "0141",                             // _
    "1827",                             // `
    "16364542 441403123243",            // a
    "08023243453606",                   // b
    "461605031242",                     // c
    "48421203051646",                   // d
    "044445361605031242",               // e
    "382722 1636",                      // f
    "421203051646413000",               // g
    "0802 0516364542",                  // h
    "2622 28",                          // i
    "36312010 38",                      // j
    "0802 3603 1432",                   // k
    "282332",                           // l
    "0206 05162522 25364542",           // m
    "0206 0516364542",                  // n
    "120305163645433212",               // o
    "00063645433202",                   // p
    "40461605031242",                   // q
    "0206 042646",                      // r
    "4616051434433202",                 // s
    "28233242 1636",                    // t
    "0603123243 4642",                  // u
    "062246",                           // v
    "0612243246",                       // w
    "0642 4602",                        // x
    "0622 4610",                        // y
    "06460242",                         // z
    "38272615242332",                   // {
    "2821",                             // |
    "18272635242312",                   // }
    "05163445",                         // ~
];

/// Width of the grid, in grid units.
pub const WIDTH: f64 = 4.0;
/// Height of capitals, in grid units: the "1 inch" of LETTER's scale 1.
pub const CAP_HEIGHT: f64 = 6.0;

/// The strokes of a character in grid units, or `None` when the font
/// lacks it (anything but printable ASCII).
pub fn strokes(c: char) -> Option<Vec<Vec<(f64, f64)>>> {
    let i = (c as u32).checked_sub(32)? as usize;
    let glyph = GLYPHS.get(i)?;
    Some(
        glyph
            .split_ascii_whitespace()
            .map(|stroke| {
                stroke
                    .as_bytes()
                    .chunks_exact(2)
                    .map(|p| (f64::from(p[0].wrapping_sub(b'0')), f64::from(p[1].wrapping_sub(b'0')) - 2.0))
                    .collect()
            })
            .collect(),
    )
}
