//! Arc geometry: sweep, mid point and length of circular and helical moves,
//! their linearization into chords, and the radius-exact centre used by
//! `--exact-arcs`.
//!
//! Arcs in the ZX and YZ planes are handled in plane coordinates (u, v, w):
//! XY is (x, y, z), ZX is (z, x, y), YZ is (y, z, x), so that clockwise and
//! counter-clockwise mean what G2 and G3 mean in G17, G18 and G19.

use std::f64::consts::TAU;

use postc_ir::event::{ArcDir, Plane};

/// Geometry of one arc, in output units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ArcGeometry {
    pub start: [f64; 3],
    pub end: [f64; 3],
    pub centre: [f64; 3],
    pub mid: [f64; 3],
    pub radius: f64,
    /// Signed sweep in radians, counter-clockwise positive.
    pub sweep: f64,
    pub plane: Plane,
}

/// Axis indices (u, v, w) of a plane.
fn axes(plane: Plane) -> [usize; 3] {
    match plane {
        Plane::Xy => [0, 1, 2],
        Plane::Zx => [2, 0, 1],
        Plane::Yz => [1, 2, 0],
    }
}

impl ArcGeometry {
    /// The arc from `start` to `end` around `centre`, turning `dir` in `plane`.
    pub fn new(start: [f64; 3], end: [f64; 3], centre: [f64; 3], dir: ArcDir, plane: Plane) -> ArcGeometry {
        let [u, v, w] = axes(plane);
        let mut centre = centre;
        centre[w] = start[w];
        let (su, sv) = (start[u] - centre[u], start[v] - centre[v]);
        let (eu, ev) = (end[u] - centre[u], end[v] - centre[v]);
        let radius = su.hypot(sv);
        let a0 = sv.atan2(su);
        let a1 = ev.atan2(eu);
        let closed = (end[u] - start[u]).hypot(end[v] - start[v]) <= 1e-9 * radius.max(1.0);
        let ccw = if closed { TAU } else { (a1 - a0).rem_euclid(TAU) };
        let sweep = match dir {
            ArcDir::Ccw => {
                if ccw <= 1e-12 {
                    TAU
                } else {
                    ccw
                }
            }
            ArcDir::Cw => {
                let cw = if closed { TAU } else { (a0 - a1).rem_euclid(TAU) };
                -(if cw <= 1e-12 { TAU } else { cw })
            }
        };
        let mut arc = ArcGeometry { start, end, centre, mid: start, radius, sweep, plane };
        arc.mid = arc.point_at(0.5);
        arc
    }

    /// The point a fraction `t` of the way along the arc (Z, or the plane's
    /// normal, moves linearly).
    pub fn point_at(&self, t: f64) -> [f64; 3] {
        let [u, v, w] = axes(self.plane);
        let a0 = (self.start[v] - self.centre[v]).atan2(self.start[u] - self.centre[u]);
        let a = a0 + self.sweep * t;
        let mut p = [0.0; 3];
        p[u] = self.centre[u] + self.radius * a.cos();
        p[v] = self.centre[v] + self.radius * a.sin();
        p[w] = self.start[w] + (self.end[w] - self.start[w]) * t;
        if t >= 1.0 {
            return self.end;
        }
        p
    }

    /// Whether the arc moves along the plane's normal (a helix).
    pub fn is_helical(&self) -> bool {
        let w = axes(self.plane)[2];
        (self.end[w] - self.start[w]).abs() > 1e-9
    }

    /// Length along the path.
    pub fn length(&self) -> f64 {
        let w = axes(self.plane)[2];
        (self.radius * self.sweep.abs()).hypot(self.end[w] - self.start[w])
    }

    /// Number of equal-angle chords that keep within `tolerance` of the arc:
    /// n = ceil(sweep / (2 acos(1 - tol / r))), at least one.
    pub fn segments(&self, tolerance: f64) -> u32 {
        if self.radius <= 0.0 || !self.radius.is_finite() {
            return 1;
        }
        let ratio = (tolerance / self.radius).clamp(0.0, 1.0);
        let step = 2.0 * (1.0 - ratio).acos();
        if step <= 0.0 {
            return 1_000_000;
        }
        ((self.sweep.abs() / step).ceil() as u32).clamp(1, 1_000_000)
    }

    /// The same arc with the start and end the controller reads (the
    /// printed points) and a centre on their perpendicular bisector, so the
    /// radius at both ends is the same.
    pub fn exact(&self, printed_start: [f64; 3], printed_end: [f64; 3], dir: ArcDir) -> ArcGeometry {
        let [u, v, _] = axes(self.plane);
        let (du, dv) = (printed_end[u] - printed_start[u], printed_end[v] - printed_start[v]);
        let chord = du.hypot(dv);
        let mut centre = self.centre;
        if chord > 1e-12 {
            let (mu, mv) = ((printed_start[u] + printed_end[u]) / 2.0, (printed_start[v] + printed_end[v]) / 2.0);
            let (nu, nv) = (-dv / chord, du / chord);
            let along = (self.centre[u] - mu) * nu + (self.centre[v] - mv) * nv;
            centre[u] = mu + nu * along;
            centre[v] = mv + nv * along;
        }
        ArcGeometry::new(printed_start, printed_end, centre, dir, self.plane)
    }
}
