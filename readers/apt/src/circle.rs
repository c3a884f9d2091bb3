//! CIRCLE records and the arcs they make.
//!
//! A `CIRCLE` record describes the circle the next `GOTO` moves along; the
//! vendors write it four ways and do not agree on which way the tool turns.
//! The direction of each convention was worked out from the geometry of the
//! corpus files (tangent continuity with the straight move before the arc,
//! and the short way from start to end); see the crate documentation for the
//! evidence.
//!
//! | values | writer | form | direction |
//! |---|---|---|---|
//! | 6 | SolidWorks CAM (CAMWorks) | `xc,yc,zc,i,j,k` | counter-clockwise about (i,j,k) |
//! | 7 | Creo, classic APT | `xc,yc,zc,i,j,k,r` | counter-clockwise about (i,j,k) |
//! | 7 + word | CLT export | `xc,yc,zc,i,j,k,r,CLOCKWISE` | the word, about (i,j,k) |
//! | 10-11 | Siemens NX CLSF | `xc,yc,zc,i,j,k,r,tol,..,dia,corner` | clockwise about (i,j,k) |
//! | 4 in `TLON,GOFWD` | CATIA | `(CIRCLE/xc,yc,zc,r),ON,(LINE/xc,yc,zc,xe,ye,ze)` | along the INDIRV before it |
//!
//! Evidence (corpus files under `shared/corpus/apt/`; "short way" is the
//! sense of the shorter arc from start to end, "tangent" compares the
//! straight move before the arc with the arc's start tangent):
//!
//! - SolidWorks: `Sacrifice-Board.apt` 64-66 starts below the centre
//!   (79.897916,145.1) and ends at 2.4°; the move before runs +X, the
//!   counter-clockwise tangent there; `boss.apt` 36-38 (axis -Z) turns
//!   clockwise seen from +Z. Over the six files with arcs, 1859 of 2010
//!   arcs turn less than half a turn this way and the other 151 more than
//!   300° (pocket circles between tangent lead-in and lead-out arcs);
//!   tangent checks 742 to 16 (the 16 are zig-zag reversals, not lead-ins).
//! - Creo: `profilfraesen_2.ncl.2` 17-20, axis -Z, from (0,1.5) around
//!   (0,0) to (1.5,0), then a move along -Y: clockwise seen from +Z, so
//!   counter-clockwise about the axis; 46 tangent checks in three files
//!   agree, and 674 of 700 arcs turn less than half a turn this way.
//! - NX: `cutcom.clsf` 17-21, axis -Z, from (-7.1838,23) (180°) around
//!   (5.3162,23) to (5.3162,10.5) (270°); the move before runs -Y and the
//!   one after +X, the counter-clockwise tangents seen from +Z: the tool
//!   turns clockwise about the written axis. All 459 NX arcs turn less than
//!   half a turn clockwise about their axis; 241 tangent checks agree.
//! - CLT: `Interface-glue.clt` 40-42, COUNTERCLOCKWISE, from 132.4° to
//!   177.4° with a tangent lead-in; all its axes are +Z, so whether the
//!   word is seen from the axis or from +Z is not shown by the corpus (the
//!   reader takes it about the axis).
//!
//! A direction word (`CLW`, `CCLW`, `CLOCKWISE`, `COUNTERCLOCKWISE`) in any
//! form wins over the convention. The event's [`ArcDir`] is the sense about
//! the positive axis of the arc's plane (+Z for XY, +Y for ZX, +X for YZ),
//! as RS274/NGC defines G2/G3; an axis that points the negative way flips
//! it. An arc whose plane is not XY, ZX or YZ is cut into straight feed
//! moves.

use postc_ir::event::{ArcDir, ArcMove, Intent, Plane};

use crate::words::{Arg, Problem, Rec};

#[doc(hidden)]
pub type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
#[doc(hidden)]
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}
#[doc(hidden)]
pub fn unit(a: V3) -> Option<V3> {
    let n = norm(a);
    (n > 1e-12 && n.is_finite()).then(|| scale(a, 1.0 / n))
}

/// Which writer's form a circle was given in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)]
pub enum Convention {
    SolidWorks,
    Apt,
    Clt,
    Nx,
    Catia,
}

/// A circle the next move follows.
#[derive(Clone, Copy, Debug, PartialEq)]
#[doc(hidden)]
pub struct CircleSpec {
    pub centre: V3,
    /// Unit axis.
    pub axis: V3,
    /// Whether the tool turns counter-clockwise about `axis` (right-hand rule).
    pub ccw: bool,
    pub convention: Convention,
}

/// Reads a direction word.
fn direction_word(arg: &Arg<'_>) -> Option<bool> {
    if arg.is("CCLW") || arg.is("COUNTERCLOCKWISE") || arg.is("CCW") {
        Some(true)
    } else if arg.is("CLW") || arg.is("CLOCKWISE") || arg.is("CW") {
        Some(false)
    } else {
        None
    }
}

/// Reads a top-level `CIRCLE/...` record. Returns the circle and the index
/// of the first word it did not understand (ignored).
pub(crate) fn parse_circle(rec: &Rec<'_>) -> Result<(CircleSpec, Option<usize>), Problem> {
    let mut v = [0.0; 12];
    let mut n = 0;
    let mut word_dir = None;
    let mut ignored = None;
    for (i, arg) in rec.args().enumerate() {
        match arg {
            Arg::Num(x) => {
                if n < v.len() {
                    v[n] = x;
                }
                n += 1;
            }
            other => match direction_word(&other) {
                Some(ccw) => word_dir = Some(ccw),
                None => {
                    ignored.get_or_insert(i);
                }
            },
        }
    }
    let (convention, default_ccw) = match n {
        6 => (Convention::SolidWorks, true),
        7..=9 if word_dir.is_some() => (Convention::Clt, true),
        7..=9 => (Convention::Apt, true),
        10..=12 => (Convention::Nx, false),
        _ => {
            return Err(Problem {
                message: format!("CIRCLE needs 6, 7 or 11 values (centre, axis, radius ...); this one has {n}"),
                arg: None,
            });
        }
    };
    let axis = unit([v[3], v[4], v[5]]).ok_or(Problem {
        message: "the axis of this CIRCLE (values 4 to 6) is a zero vector".to_string(),
        arg: Some(3),
    })?;
    Ok((CircleSpec { centre: [v[0], v[1], v[2]], axis, ccw: word_dir.unwrap_or(default_ccw), convention }, ignored))
}

/// What a CIRCLE and its end point become.
#[derive(Clone, Debug, PartialEq)]
#[doc(hidden)]
pub enum ArcOutcome {
    Arc {
        arc: ArcMove,
        /// Start and end distance from the centre, when they disagree.
        off_circle: Option<(f64, f64)>,
    },
    /// A tilted arc, cut into feed moves through these points.
    Linear(Vec<V3>),
}

/// The arc from `start` to `end` around `spec`. `tolerance` is the chord
/// error allowed when a tilted arc is cut into straight moves.
#[doc(hidden)]
pub fn build_arc(spec: &CircleSpec, start: Option<V3>, end: V3, feed: Option<f64>, tolerance: f64) -> ArcOutcome {
    let a = spec.axis;
    let (dominant, component) = (0..3)
        .map(|i| (i, a[i]))
        .fold((2usize, 0.0f64), |best, (i, c)| if c.abs() > best.1.abs() { (i, c) } else { best });
    if component.abs() < 0.99999 {
        return ArcOutcome::Linear(linearize(spec, start.unwrap_or(end), end, tolerance));
    }
    let plane = match dominant {
        0 => Plane::Yz,
        1 => Plane::Zx,
        _ => Plane::Xy,
    };
    let ccw_about_positive = spec.ccw == (component > 0.0);
    let mut off_circle = None;
    let mut intent = Intent::Cut;
    if let Some(s) = start {
        let rs = radial(spec, s);
        let re = radial(spec, end);
        if (rs - re).abs() > 1e-3 * rs.max(1.0) {
            off_circle = Some((rs, re));
        }
        if plane == Plane::Xy && end[2] < s[2] - 1e-9 {
            intent = Intent::Plunge;
        }
    }
    ArcOutcome::Arc {
        arc: ArcMove {
            dir: if ccw_about_positive { ArcDir::Ccw } else { ArcDir::Cw },
            x: end[0],
            y: end[1],
            z: end[2],
            cx: spec.centre[0],
            cy: spec.centre[1],
            cz: spec.centre[2],
            plane,
            intent,
            feed,
        },
        off_circle,
    }
}

/// Distance of `p` from the circle's axis line.
fn radial(spec: &CircleSpec, p: V3) -> f64 {
    let d = sub(p, spec.centre);
    norm(sub(d, scale(spec.axis, dot(d, spec.axis))))
}

/// Rotates `v` about unit axis `k` by `angle` (Rodrigues).
#[doc(hidden)]
pub fn rotate(v: V3, k: V3, angle: f64) -> V3 {
    let (s, c) = angle.sin_cos();
    add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1.0 - c)))
}

/// Points along a (possibly helical) arc in any plane, ending at `end`.
pub(crate) fn linearize(spec: &CircleSpec, start: V3, end: V3, tolerance: f64) -> Vec<V3> {
    let k = if spec.ccw { spec.axis } else { scale(spec.axis, -1.0) };
    let ds = sub(start, spec.centre);
    let de = sub(end, spec.centre);
    let (hs, he) = (dot(ds, k), dot(de, k));
    let ps = sub(ds, scale(k, hs));
    let pe = sub(de, scale(k, he));
    let r = norm(ps);
    let mut sweep = dot(cross(ps, pe), k).atan2(dot(ps, pe));
    if sweep <= 1e-9 {
        sweep += std::f64::consts::TAU;
    }
    let step = if r > tolerance { 2.0 * (1.0 - tolerance / r).acos() } else { sweep };
    let n = if step > 0.0 && step.is_finite() { (sweep / step).ceil().clamp(1.0, 10_000.0) as usize } else { 1 };
    let mut points = Vec::with_capacity(n);
    for i in 1..n {
        let t = i as f64 / n as f64;
        let p = rotate(ps, k, sweep * t);
        points.push(add(add(spec.centre, p), scale(k, hs + (he - hs) * t)));
    }
    points.push(end);
    points
}

/// A CATIA `TLON,GOFWD/(CIRCLE/...),ON,(LINE/...)` record: the circle and
/// the end point, with the direction taken from the INDIRV before it.
pub(crate) fn parse_drive_circle(
    rec: &Rec<'_>,
    start: Option<V3>,
    indirv: Option<V3>,
) -> Result<(CircleSpec, V3), Problem> {
    let mut circle = [0.0; 8];
    let mut line = [0.0; 7];
    let (mut nc, mut nl) = (0, 0);
    let mut inside: Option<bool> = None; // Some(true): circle, Some(false): line
    for (i, arg) in rec.args().enumerate() {
        match arg {
            Arg::Open(w) if w.eq_ignore_ascii_case(b"CIRCLE") => inside = Some(true),
            Arg::Open(w) if w.eq_ignore_ascii_case(b"LINE") => inside = Some(false),
            Arg::Open(_) => {
                return Err(Problem {
                    message: "only (CIRCLE/...) and (LINE/...) are read in a TLON,GOFWD record".to_string(),
                    arg: Some(i),
                });
            }
            Arg::Close => inside = None,
            Arg::Num(x) => match inside {
                Some(true) => {
                    if nc < circle.len() {
                        circle[nc] = x;
                    }
                    nc += 1;
                }
                Some(false) => {
                    if nl < line.len() {
                        line[nl] = x;
                    }
                    nl += 1;
                }
                None => {}
            },
            Arg::Word(_) => {}
        }
    }
    let centre = [circle[0], circle[1], circle[2]];
    let given_axis = match nc {
        4 => None,
        7 => unit([circle[3], circle[4], circle[5]]),
        _ => {
            return Err(Problem {
                message: format!(
                    "the (CIRCLE/...) of a TLON,GOFWD record needs 4 values (centre, radius) or 7; it has {nc}"
                ),
                arg: None,
            });
        }
    };
    if nl != 6 {
        return Err(Problem {
            message: format!("the (LINE/...) of a TLON,GOFWD record needs 6 values (centre, end point); it has {nl}"),
            arg: None,
        });
    }
    let end = [line[3], line[4], line[5]];
    let turned = match (start, indirv) {
        (Some(s), Some(t)) => unit(cross(sub(s, centre), t)),
        _ => None,
    };
    let axis = turned.or(given_axis).unwrap_or([0.0, 0.0, 1.0]);
    Ok((CircleSpec { centre, axis, ccw: true, convention: Convention::Catia }, end))
}
