//! Geometry of moves: planes, arcs, distances to the expected path.

use std::f64::consts::TAU;

use postc_ir::event::{ArcDir, Plane};

/// The indices of a plane's first and second axes and its normal, as
/// RS274/NGC orders them (G17 X Y, G18 Z X, G19 Y Z).
pub fn axes(plane: Plane) -> [usize; 3] {
    match plane {
        Plane::Xy => [0, 1, 2],
        Plane::Zx => [2, 0, 1],
        Plane::Yz => [1, 2, 0],
    }
}

pub fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

pub fn known(p: [f64; 3]) -> bool {
    p.iter().all(|v| v.is_finite())
}

/// Distance of a point from segment a-b, and where along it (0..1) it lies.
pub fn to_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> (f64, f64) {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if len2 < 1e-18 {
        return (dist(p, a), 1.0);
    }
    let t = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / len2).clamp(0.0, 1.0);
    let q = [a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]];
    (dist(p, q), t)
}

/// An arc: start, end, centre (only its in-plane coordinates count),
/// direction and plane.
#[derive(Clone, Copy, Debug)]
pub struct Arc {
    pub start: [f64; 3],
    pub end: [f64; 3],
    pub centre: [f64; 3],
    pub dir: ArcDir,
    pub plane: Plane,
}

impl Arc {
    fn uv(&self, p: [f64; 3]) -> (f64, f64) {
        let [u, v, _] = axes(self.plane);
        (p[u] - self.centre[u], p[v] - self.centre[v])
    }

    pub fn start_radius(&self) -> f64 {
        let (a, b) = self.uv(self.start);
        a.hypot(b)
    }

    pub fn end_radius(&self) -> f64 {
        let (a, b) = self.uv(self.end);
        a.hypot(b)
    }

    /// The angle turned from the start to `p`, in the arc's direction, in [0, 2π).
    fn turned(&self, p: [f64; 3]) -> f64 {
        let (su, sv) = self.uv(self.start);
        let (pu, pv) = self.uv(p);
        let mut a = pv.atan2(pu) - sv.atan2(su);
        if self.dir == ArcDir::Cw {
            a = -a;
        }
        a.rem_euclid(TAU)
    }

    /// The sweep in radians; a closed arc is a full circle.
    pub fn sweep(&self, tol: f64) -> f64 {
        let s = self.turned(self.end);
        let [u, v, _] = axes(self.plane);
        let closed = (self.start[u] - self.end[u]).hypot(self.start[v] - self.end[v]) <= tol;
        if closed || s < 1e-12 { TAU } else { s }
    }

    /// How far `p` lies from the arc (radially and along the helix axis),
    /// and the fraction of the sweep it is at.
    pub fn deviation(&self, p: [f64; 3], tol: f64) -> (f64, f64) {
        let [_, _, w] = axes(self.plane);
        let r = 0.5 * (self.start_radius() + self.end_radius());
        let (pu, pv) = self.uv(p);
        let radial = (pu.hypot(pv) - r).abs();
        let sweep = self.sweep(tol);
        let mut t = self.turned(p) / sweep;
        // Within the tolerance of the start (turned() near 2π for a point just behind it).
        if t > 1.0 {
            let back = (TAU - self.turned(p)) * r;
            t = if back <= tol { 0.0 } else { t };
        }
        if t > 1.0 {
            return (f64::INFINITY, t);
        }
        let along = (p[w] - (self.start[w] + t * (self.end[w] - self.start[w]))).abs();
        (radial.max(along), t)
    }

    /// The sagitta of the chord from `a` to `b` on this arc: how far the
    /// chord's middle lies from the circle.
    pub fn chord_error(&self, a: [f64; 3], b: [f64; 3]) -> f64 {
        let r = 0.5 * (self.start_radius() + self.end_radius());
        let m = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0];
        let (mu, mv) = self.uv(m);
        (r - mu.hypot(mv)).abs()
    }
}

/// The centre of an R-form arc in its plane (the other coordinate taken
/// from the start): the short arc for a positive radius, the long one for
/// a negative radius. None when the chord is longer than the diameter by
/// more than `tol`.
pub fn r_centre(start: [f64; 3], end: [f64; 3], r: f64, dir: ArcDir, plane: Plane, tol: f64) -> Option<[f64; 3]> {
    let [u, v, _] = axes(plane);
    let (du, dv) = (end[u] - start[u], end[v] - start[v]);
    let d = du.hypot(dv);
    if d < 1e-12 {
        return None;
    }
    let half = d / 2.0;
    let ra = r.abs();
    if half > ra + tol {
        return None;
    }
    let h = (ra * ra - half * half).max(0.0).sqrt();
    // Left normal of the chord.
    let (nu, nv) = (-dv / d, du / d);
    let mut side = if dir == ArcDir::Ccw { 1.0 } else { -1.0 };
    if r < 0.0 {
        side = -side;
    }
    let mut c = start;
    c[u] = start[u] + du / 2.0 + side * h * nu;
    c[v] = start[v] + dv / 2.0 + side * h * nv;
    Some(c)
}
