//! LETTER: engraving the next PPRINT string with the built-in font.
//!
//! `LETTER/x,y,z,dx,r,sx,sy,zc,zr,f,zf`: the first character's cell has its
//! bottom left (on the baseline) at (x, y); the tool cuts at height z;
//! characters start dx apart along the baseline (dx ≤ 0: the font's own
//! advance, 1.5 grid widths); the whole string turns r degrees
//! counter-clockwise about (x, y); sx and sy scale the width and height, a
//! capital being 1 inch tall at sy = 1 (25.4 in a millimetre file). Each
//! stroke is cut as: rapid to its start at zc, rapid down to zr, feed down
//! to z at zf, feed along the stroke at f, rapid up to zc. The tool first
//! rises to zc where it stands, and ends at zc over the last stroke.

use crate::font;

/// A LETTER statement's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Letter {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub dx: f64,
    pub r: f64,
    pub sx: f64,
    pub sy: f64,
    pub zc: f64,
    pub zr: f64,
    pub f: f64,
    pub zf: f64,
}

/// A computed move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    Rapid([f64; 3]),
    /// End point and feed rate.
    Feed([f64; 3], f64),
}

impl Letter {
    /// From the 11 numbers of the statement.
    pub fn from_numbers(n: &[f64]) -> Option<Letter> {
        let [x, y, z, dx, r, sx, sy, zc, zr, f, zf] = *n else { return None };
        Some(Letter { x, y, z, dx, r, sx, sy, zc, zr, f, zf })
    }

    /// The moves that engrave `text`, starting from `from` (the tool's
    /// position, when known); `inch` is the length of an inch in the file's
    /// units. Characters the font lacks are cut as `?` and returned.
    pub fn motions(&self, text: &str, from: Option<[f64; 3]>, inch: f64) -> (Vec<Motion>, Vec<char>) {
        let unit_y = self.sy * inch / font::CAP_HEIGHT;
        let unit_x = self.sx * inch / font::CAP_HEIGHT;
        let pitch = if self.dx > 0.0 { self.dx } else { 1.5 * font::WIDTH * unit_x };
        let (sin, cos) = self.r.to_radians().sin_cos();
        let at = |u: f64, v: f64| [self.x + u * cos - v * sin, self.y + u * sin + v * cos];
        let mut out = Vec::new();
        let mut missing = Vec::new();
        if let Some(p) = from
            && p[2] != self.zc
        {
            out.push(Motion::Rapid([p[0], p[1], self.zc]));
        }
        for (i, c) in text.chars().enumerate() {
            let strokes = font::strokes(c).unwrap_or_else(|| {
                missing.push(c);
                font::strokes('?').unwrap_or_default()
            });
            let origin = i as f64 * pitch;
            for stroke in strokes {
                let points: Vec<[f64; 2]> =
                    stroke.iter().map(|&(gx, gy)| at(origin + gx * unit_x, gy * unit_y)).collect();
                let (Some(first), Some(last)) = (points.first(), points.last()) else { continue };
                out.push(Motion::Rapid([first[0], first[1], self.zc]));
                if self.zr != self.zc {
                    out.push(Motion::Rapid([first[0], first[1], self.zr]));
                }
                out.push(Motion::Feed([first[0], first[1], self.z], self.zf));
                for p in &points[1..] {
                    out.push(Motion::Feed([p[0], p[1], self.z], self.f));
                }
                out.push(Motion::Rapid([last[0], last[1], self.zc]));
            }
        }
        (out, missing)
    }
}
