//! A backplot: the toolpath and the re-read program drawn over each other,
//! seen from the top (XY) and from the front (XZ), written as SVG text.
//!
//! Moves are added one by one ([`Plot::toolpath`], and [`Plot`] as a
//! verify [`Observer`] for the program) into eight layers (toolpath or
//! program, rapid or feed, per view) of path commands in mm. Consecutive
//! collinear segments are merged, and a layer stops growing at
//! [`MAX_POINTS`] points (the moves left out are counted and said under
//! the views), so memory and the SVG stay bounded whatever the program's
//! length. Arcs in the view's plane are SVG arcs (`A`); arcs seen from the
//! side are drawn through points on them. `docs/plot.md` describes the
//! drawing.

use std::f64::consts::PI;
use std::fmt::Write;

use postc_ir::event::{ArcDir, Plane};

use std::io::BufRead;

use postc_ir::{EventSource, FileId, Severity, SourceMap};

use crate::expect::{Expected, ExpectedPath, Kind, Records};
use crate::geometry::{Arc, axes};
use crate::{Move, Observer, Report, Settings};

/// Draws a program over its toolpath: the toolpath is read from `toolpath`
/// for the drawing, and again from `again` for the verification (two
/// sources over the same toolpath); the program's findings are marked, at
/// their program lines as `sources` knows them. The plot and verify's report.
pub fn draw(
    program: &mut dyn BufRead,
    file: FileId,
    toolpath: &mut dyn EventSource,
    again: &mut dyn EventSource,
    settings: &Settings,
    sources: &SourceMap,
) -> (Plot, Report) {
    let mut plot = Plot::new();
    let mut records = Records(toolpath);
    let mut path = ExpectedPath::new(&mut records);
    path.apt_words = settings.apt_words;
    path.start();
    while let Some(e) = path.pop() {
        plot.toolpath(&e);
    }
    let report = crate::verify_observed(program, file, again, settings, &mut plot);
    plot.inch = report.stats.inch;
    let marks = report
        .findings
        .iter()
        .zip(&report.at)
        .map(|(d, at)| {
            let line = d
                .labels
                .iter()
                .find(|l| l.span.file == file)
                .and_then(|l| sources.line_column(l.span.file, l.span.start))
                .map(|(line, _)| line);
            Mark {
                code: d.code.to_string(),
                error: d.severity == Severity::Error,
                line,
                message: d.message.clone(),
                at: *at,
            }
        })
        .collect();
    plot.marks(marks);
    (plot, report)
}

/// Path points kept per layer; the moves after are counted, not drawn.
pub const MAX_POINTS: usize = 50_000;
/// Findings listed under the views (all are marked).
pub const MAX_LISTED: usize = 60;
/// Segments closer than this to the line through their neighbours are merged (mm).
#[doc(hidden)]
pub const MERGE: f64 = 0.002;

/// One path command of a layer, in mm in the view's axes (u right, v up).
#[derive(Clone, Copy, Debug)]
#[doc(hidden)]
pub enum Cmd {
    Move(f64, f64),
    Line(f64, f64),
    /// An arc of at most half a turn to (u, v): radius, and whether it
    /// turns clockwise as seen in the view.
    Arc(f64, f64, f64, bool),
    /// A feed along Z seen from the top (a plunge, a drilled hole): a small ring.
    Dot(f64, f64),
}

#[derive(Clone)]
#[doc(hidden)]
pub struct Layer {
    #[doc(hidden)]
    pub cmds: Vec<Cmd>,
    /// The end of the last command written (None before the first, and after a dot).
    pen: Option<(f64, f64)>,
    /// Where the tool is: ahead of the pen by less than `res` when short moves were held back.
    at: Option<(f64, f64)>,
    /// The start of the last line command (for merging).
    anchor: Option<(f64, f64)>,
    /// The resolution (mm): points closer than this to the pen are held back.
    /// It doubles each time the layer fills, and the layer is thinned to it.
    #[doc(hidden)]
    pub res: f64,
    /// Moves not drawn because the layer was full even so.
    #[doc(hidden)]
    pub dropped: u64,
}

impl Default for Layer {
    fn default() -> Layer {
        Layer { cmds: Vec::new(), pen: None, at: None, anchor: None, res: MERGE, dropped: 0 }
    }
}

fn near(a: (f64, f64), b: (f64, f64), d: f64) -> bool {
    (a.0 - b.0).hypot(a.1 - b.1) <= d
}

impl Layer {
    /// Whether there is room for a move's commands: a full layer is thinned
    /// at a coarser resolution first; counted as dropped when even that fails.
    fn room(&mut self, finest: f64) -> bool {
        if self.cmds.len() + 8 > MAX_POINTS {
            self.coarsen(finest);
        }
        if self.cmds.len() + 8 > MAX_POINTS {
            self.dropped += 1;
            false
        } else {
            true
        }
    }

    /// Doubles the resolution until the layer is at most half full, leaving
    /// out the points of a chain closer than it to the last one kept; but
    /// not past `coarsest` (about a pixel of the drawing): what does not fit
    /// then is left out, and said.
    fn coarsen(&mut self, coarsest: f64) {
        while self.cmds.len() > MAX_POINTS / 2 && self.res * 2.0 <= coarsest {
            self.res *= 2.0;
            let res = self.res;
            let mut kept = 0;
            let mut last = (f64::NAN, f64::NAN);
            for i in 0..self.cmds.len() {
                let c = self.cmds[i];
                let chained = matches!(self.cmds.get(i + 1), Some(Cmd::Line(..) | Cmd::Arc(..)));
                let keep = match c {
                    Cmd::Move(x, y) => {
                        last = (x, y);
                        true
                    }
                    Cmd::Dot(..) => true,
                    Cmd::Line(x, y) | Cmd::Arc(x, y, ..) => {
                        let keep = !chained || !near((x, y), last, res);
                        if keep {
                            last = (x, y);
                        }
                        keep
                    }
                };
                if keep {
                    // An arc whose start was left out is drawn as a line.
                    let c = match c {
                        Cmd::Arc(x, y, ..) if i > 0 && kept > 0 && !same_end(self.cmds[kept - 1], self.cmds[i - 1]) => {
                            Cmd::Line(x, y)
                        }
                        c => c,
                    };
                    self.cmds[kept] = c;
                    kept += 1;
                }
            }
            self.cmds.truncate(kept);
        }
        self.anchor = None;
    }

    /// Starts a stroke at `a` unless the tool is there already.
    fn pen_to(&mut self, a: (f64, f64)) {
        let continuing = self.at.is_some_and(|p| near(p, a, MERGE));
        if continuing && self.pen.is_some() {
            return;
        }
        self.flush();
        self.cmds.push(Cmd::Move(a.0, a.1));
        self.pen = Some(a);
        self.at = Some(a);
        self.anchor = None;
    }

    /// Draws to where the tool is, when short moves were held back.
    fn flush(&mut self) {
        if let (Some(pen), Some(at)) = (self.pen, self.at)
            && !near(pen, at, MERGE)
        {
            self.cmds.push(Cmd::Line(at.0, at.1));
            self.anchor = Some(pen);
            self.pen = Some(at);
        }
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64)) {
        if near(a, b, MERGE) {
            return;
        }
        self.pen_to(a);
        self.at = Some(b);
        let Some(pen) = self.pen else { return };
        if near(pen, b, self.res) && self.res > MERGE {
            return;
        }
        // pen..b continues the last line anchor..pen: move its end.
        if let (Some(o), Some(Cmd::Line(..))) = (self.anchor, self.cmds.last()) {
            let (dx, dy) = (b.0 - o.0, b.1 - o.1);
            let len = dx.hypot(dy);
            let off = ((pen.0 - o.0) * dy - (pen.1 - o.1) * dx).abs() / len.max(1e-12);
            let forward =
                (pen.0 - o.0) * dx + (pen.1 - o.1) * dy > 0.0 && (b.0 - pen.0) * dx + (b.1 - pen.1) * dy > 0.0;
            if off <= self.res && forward {
                *self.cmds.last_mut().expect("a line") = Cmd::Line(b.0, b.1);
                self.pen = Some(b);
                return;
            }
        }
        self.cmds.push(Cmd::Line(b.0, b.1));
        self.anchor = Some(pen);
        self.pen = Some(b);
    }

    fn dot(&mut self, a: (f64, f64)) {
        if let Some(Cmd::Dot(x, y)) = self.cmds.last()
            && near((*x, *y), a, self.res)
        {
            return;
        }
        self.flush();
        self.cmds.push(Cmd::Dot(a.0, a.1));
        // The ring moves SVG's current point: the next stroke starts afresh.
        self.pen = None;
        self.anchor = None;
    }

    fn arc(&mut self, a: (f64, f64), b: (f64, f64), r: f64, cw: bool) {
        self.pen_to(a);
        self.flush();
        if self.pen.is_some_and(|p| !near(p, a, MERGE)) {
            // Held back points put the pen off the arc's start: a line there.
            self.cmds.push(Cmd::Line(a.0, a.1));
        }
        if r <= self.res && self.res > MERGE {
            self.cmds.push(Cmd::Line(b.0, b.1));
        } else {
            self.cmds.push(Cmd::Arc(b.0, b.1, r, cw));
        }
        self.anchor = None;
        self.pen = Some(b);
        self.at = Some(b);
    }
}

/// Whether two commands end at the same point.
fn same_end(a: Cmd, b: Cmd) -> bool {
    let end = |c: Cmd| match c {
        Cmd::Move(x, y) | Cmd::Line(x, y) | Cmd::Arc(x, y, ..) | Cmd::Dot(x, y) => (x, y),
    };
    near(end(a), end(b), 1e-12)
}

/// The two views: top (X right, Y up) and front (X right, Z up).
const VIEWS: [(usize, usize, &str); 2] = [(0, 1, "XY (top)"), (0, 2, "XZ (front)")];

/// Bounds in mm.
#[derive(Clone, Copy, Debug)]
#[doc(hidden)]
pub struct Bounds {
    #[doc(hidden)]
    pub min: [f64; 3],
    #[doc(hidden)]
    pub max: [f64; 3],
}

impl Bounds {
    /// Widens the bounds to take in `p`; coordinates beyond 10 km (a wild
    /// move) are left out so that the job stays visible.
    fn add(&mut self, p: [f64; 3]) {
        for (i, v) in p.into_iter().enumerate() {
            if v.is_finite() && v.abs() <= 1e7 {
                self.min[i] = self.min[i].min(v);
                self.max[i] = self.max[i].max(v);
            }
        }
    }
}

/// A finding to mark: its number is its place in the list (from 1).
#[derive(Clone, Debug)]
pub struct Mark {
    pub code: String,
    pub error: bool,
    /// The program line (1-based), when known.
    pub line: Option<usize>,
    pub message: String,
    /// Where on the path (mm; NaN where not known).
    pub at: [f64; 3],
}

/// The backplot being drawn.
pub struct Plot {
    /// [view][source: 0 toolpath, 1 program][0 rapid, 1 feed]
    #[doc(hidden)]
    pub layers: [[[Layer; 2]; 2]; 2],
    #[doc(hidden)]
    pub bounds: Bounds,
    marks: Vec<Mark>,
    /// Show numbers in inches.
    pub inch: bool,
    /// A title line (the program's name).
    pub title: String,
    tol: f64,
    moves: [u64; 2],
}

impl Default for Plot {
    fn default() -> Plot {
        Plot::new()
    }
}

impl Observer for Plot {
    fn motion(&mut self, m: &Move) {
        self.add(1, m.kind, m.start, m.end, m.centre, m.dir, m.plane);
    }
}

impl Plot {
    pub fn new() -> Plot {
        Plot {
            layers: Default::default(),
            bounds: Bounds { min: [f64::INFINITY; 3], max: [f64::NEG_INFINITY; 3] },
            marks: Vec::new(),
            inch: false,
            title: String::new(),
            tol: 0.001,
            moves: [0; 2],
        }
    }

    /// Adds one toolpath move.
    pub fn toolpath(&mut self, e: &Expected) {
        self.add(0, e.kind, e.start, e.end, e.centre, e.dir, e.plane);
    }

    /// Marks the findings (numbered in this order).
    pub fn marks(&mut self, marks: Vec<Mark>) {
        for m in &marks {
            self.bounds.add(m.at);
        }
        self.marks = marks;
    }

    /// Moves drawn or counted: (toolpath, program).
    pub fn counts(&self) -> (u64, u64) {
        (self.moves[0], self.moves[1])
    }

    #[allow(clippy::too_many_arguments)]
    fn add(
        &mut self,
        src: usize,
        kind: Kind,
        start: [f64; 3],
        end: [f64; 3],
        centre: [f64; 3],
        dir: ArcDir,
        plane: Plane,
    ) {
        self.moves[src] += 1;
        let feed = usize::from(kind != Kind::Rapid);
        self.bounds.add(start);
        self.bounds.add(end);
        if kind == Kind::Arc && start.iter().chain(&end).chain(&centre).all(|v| v.is_finite()) {
            self.add_arc(src, Arc { start, end, centre, dir, plane });
            return;
        }
        let coarsest = self.coarsest();
        for (v, &(u, w, _)) in VIEWS.iter().enumerate() {
            let layer = &mut self.layers[v][src][feed];
            if ![start[u], start[w], end[u], end[w]].iter().all(|c| c.is_finite()) {
                continue;
            }
            if !layer.room(coarsest) {
                continue;
            }
            let seen = (end[u] - start[u]).hypot(end[w] - start[w]);
            if v == 0 && feed == 1 && seen <= MERGE && (end[2] - start[2]).abs() > 10.0 * MERGE {
                layer.dot((end[u], end[w]));
                continue;
            }
            layer.line((start[u], start[w]), (end[u], end[w]));
        }
    }

    fn add_arc(&mut self, src: usize, arc: Arc) {
        let [a, b, n] = axes(arc.plane);
        let sweep = arc.sweep(self.tol);
        let r0 = arc.start_radius();
        let r1 = arc.end_radius();
        let a0 = (arc.start[b] - arc.centre[b]).atan2(arc.start[a] - arc.centre[a]);
        let sign = if arc.dir == ArcDir::Ccw { 1.0 } else { -1.0 };
        // The point a fraction t along the arc (a spiral when the radii differ, a helix along the normal).
        let at = |t: f64| -> [f64; 3] {
            if t >= 1.0 {
                return arc.end;
            }
            let ang = a0 + sign * sweep * t;
            let r = r0 + (r1 - r0) * t;
            let mut p = [0.0; 3];
            p[a] = arc.centre[a] + r * ang.cos();
            p[b] = arc.centre[b] + r * ang.sin();
            p[n] = arc.start[n] + (arc.end[n] - arc.start[n]) * t;
            p
        };
        // Bounds through points on the arc (its extremes lie between the ends).
        let samples = ((sweep / (PI / 16.0)).ceil() as usize).clamp(2, 64);
        for k in 1..samples {
            self.bounds.add(at(k as f64 / samples as f64));
        }
        let coarsest = self.coarsest();
        for (v, &(u, w, _)) in VIEWS.iter().enumerate() {
            let layer = &mut self.layers[v][src][1];
            if !layer.room(coarsest) {
                continue;
            }
            let in_view = (a == u && b == w) || (a == w && b == u);
            if in_view {
                // Seen along the arc's normal: true arcs, at most half a turn each.
                // CCW runs from the plane's first axis to its second; the view shows
                // it mirrored when its axes are in the other order (G18 seen from the front).
                let cw = (arc.dir == ArcDir::Cw) == (a == u);
                let pieces = ((sweep / (PI * 0.999)).ceil() as usize).max(1);
                let r = 0.5 * (r0 + r1);
                let mut p = arc.start;
                for k in 1..=pieces {
                    let q = at(k as f64 / pieces as f64);
                    layer.arc((p[u], p[w]), (q[u], q[w]), r, cw);
                    p = q;
                }
            } else {
                let mut p = arc.start;
                for k in 1..=samples {
                    let q = at(k as f64 / samples as f64);
                    layer.line((p[u], p[w]), (q[u], q[w]));
                    p = q;
                }
            }
        }
    }

    /// The coarsest resolution a full layer is thinned to: a 2000th of the
    /// largest extent so far (half a pixel of the 900 px wide drawing, or finer).
    fn coarsest(&self) -> f64 {
        let b = &self.bounds;
        (0..3).map(|i| b.max[i] - b.min[i]).filter(|d| d.is_finite()).fold(0.0, f64::max) / 2000.0
    }

    /// Writes the SVG document.
    pub fn svg(&self) -> String {
        let mut out = String::with_capacity(1 << 16);
        let unit = if self.inch { 25.4 } else { 1.0 };
        let unit_name = if self.inch { "in" } else { "mm" };
        let mut b = self.bounds;
        for i in 0..3 {
            if !(b.min[i].is_finite() && b.max[i].is_finite()) {
                b.min[i] = 0.0;
                b.max[i] = 0.0;
            }
            // At least 1 mm (or 0.05 in) across, and a margin of 4% of the largest range.
            let least: f64 = if self.inch { 1.27 } else { 1.0 };
            if b.max[i] - b.min[i] < least {
                let mid = 0.5 * (b.max[i] + b.min[i]);
                b.min[i] = mid - least / 2.0;
                b.max[i] = mid + least / 2.0;
            }
        }
        let span = (0..3).map(|i| b.max[i] - b.min[i]).fold(0.0, f64::max);
        for i in 0..3 {
            b.min[i] -= 0.04 * span;
            b.max[i] += 0.04 * span;
        }
        let (xr, yr, zr) = (b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]);
        // Shared scale: the width fills 900 px, the two views together at most 1300 px high.
        let scale = (900.0 / xr).min(1300.0 / (yr + zr));
        let left = 80.0;
        let width = 1000.0f64.max(left + xr * scale + 40.0);
        let top = 60.0;
        let gap = 70.0;
        let heights = [yr * scale, zr * scale];
        let origins = [top, top + heights[0] + gap];
        let legend_y = origins[1] + heights[1] + 60.0;
        let dropped: Vec<String> = self.dropped_notes();
        let listed = self.marks.len().min(MAX_LISTED);
        let list_y = legend_y + 40.0 + 18.0 * dropped.len() as f64;
        let height = list_y + 20.0 + 18.0 * (listed as f64 + 1.0 + f64::from(self.marks.len() > MAX_LISTED));
        let _ = writeln!(
            out,
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" font-family="DejaVu Sans, Arial, Helvetica, sans-serif" font-size="13">"##,
            w = width,
            h = height
        );
        let _ = writeln!(out, r##"<rect width="100%" height="100%" fill="#ffffff"/>"##);
        let _ = writeln!(
            out,
            r##"<text x="{left}" y="28" font-size="16" font-weight="bold">{}</text>"##,
            escape(&self.title)
        );
        for (v, &(u, w, name)) in VIEWS.iter().enumerate() {
            let ox = left;
            let oy = origins[v];
            let h = heights[v];
            // Points far outside the drawing (a wild move) are clamped to a finite distance off it.
            let tx = |x: f64| (ox + (x - b.min[u]) * scale).clamp(-1e6, 1e6);
            let ty = |y: f64| (oy + h - (y - b.min[w]) * scale).clamp(-1e6, 1e6);
            let _ = writeln!(out, r##"<g class="view" id="view-{}">"##, if v == 0 { "xy" } else { "xz" });
            let _ = writeln!(
                out,
                r##"<rect x="{ox:.2}" y="{oy:.2}" width="{:.2}" height="{h:.2}" fill="#fbfbf8" stroke="#888888" stroke-width="1"/>"##,
                xr * scale
            );
            let _ = writeln!(out, r##"<text x="{ox:.2}" y="{:.2}" font-weight="bold">{name}</text>"##, oy - 8.0);
            // Axes: ticks and labels in the program's units.
            let axis = |out: &mut String, lo: f64, hi: f64, horizontal: bool| {
                let step = nice_step((hi - lo) / unit / 8.0);
                let decimals = (-step.log10().floor()).max(0.0) as usize;
                let first = (lo / unit / step).ceil();
                for k in 0..40 {
                    let t = (first + f64::from(k)) * step;
                    if t > hi / unit + 1e-9 {
                        break;
                    }
                    let label = format!("{:.*}", decimals, if t.abs() < step * 1e-6 { 0.0 } else { t });
                    if horizontal {
                        let x = tx(t * unit);
                        let _ = writeln!(
                            out,
                            r##"<line x1="{x:.2}" y1="{:.2}" x2="{x:.2}" y2="{:.2}" stroke="#888888"/>"##,
                            oy + h,
                            oy + h + 5.0
                        );
                        let _ = writeln!(
                            out,
                            r##"<line x1="{x:.2}" y1="{oy:.2}" x2="{x:.2}" y2="{:.2}" stroke="#e4e4e4" stroke-width="0.5"/>"##,
                            oy + h
                        );
                        let _ = writeln!(
                            out,
                            r##"<text x="{x:.2}" y="{:.2}" text-anchor="middle" font-size="11">{label}</text>"##,
                            oy + h + 17.0
                        );
                    } else {
                        let y = ty(t * unit);
                        let _ = writeln!(
                            out,
                            r##"<line x1="{:.2}" y1="{y:.2}" x2="{ox:.2}" y2="{y:.2}" stroke="#888888"/>"##,
                            ox - 5.0
                        );
                        let _ = writeln!(
                            out,
                            r##"<line x1="{ox:.2}" y1="{y:.2}" x2="{:.2}" y2="{y:.2}" stroke="#e4e4e4" stroke-width="0.5"/>"##,
                            ox + xr * scale
                        );
                        let _ = writeln!(
                            out,
                            r##"<text x="{:.2}" y="{:.2}" text-anchor="end" font-size="11">{label}</text>"##,
                            ox - 8.0,
                            y + 4.0
                        );
                    }
                }
            };
            axis(&mut out, b.min[u], b.max[u], true);
            axis(&mut out, b.min[w], b.max[w], false);
            let axis_name = |i: usize| ["X", "Y", "Z"][i];
            let _ = writeln!(
                out,
                r##"<text x="{:.2}" y="{:.2}" text-anchor="end" font-size="12">{} ({unit_name})</text>"##,
                ox + xr * scale,
                oy + h + 32.0,
                axis_name(u)
            );
            let _ = writeln!(
                out,
                r##"<text x="{:.2}" y="{:.2}" text-anchor="start" font-size="12">{} ({unit_name})</text>"##,
                ox - 70.0,
                oy - 8.0,
                axis_name(w)
            );
            // Layers: the toolpath wide and light under the program, thin and dark.
            for src in 0..2 {
                for feed in 0..2 {
                    let layer = &self.layers[v][src][feed];
                    if layer.cmds.is_empty() {
                        continue;
                    }
                    let (class, style) = layer_style(src, feed);
                    let _ = write!(
                        out,
                        r##"<path class="{class}" {style} fill="none" stroke-linecap="round" stroke-linejoin="round" d=""##
                    );
                    // Points closer than half a pixel to the last one written are left out.
                    let mut last = (f64::NAN, f64::NAN);
                    let mut written = 0usize;
                    for c in &layer.cmds {
                        if written > 0 && written.is_multiple_of(8) {
                            out.push('\n');
                        }
                        written += 1;
                        match *c {
                            Cmd::Move(x, y) => {
                                last = (tx(x), ty(y));
                                let _ = write!(out, "M{:.2} {:.2} ", last.0, last.1);
                            }
                            Cmd::Line(x, y) => {
                                let p = (tx(x), ty(y));
                                if (p.0 - last.0).hypot(p.1 - last.1) < 0.5 {
                                    written -= 1;
                                    continue;
                                }
                                last = p;
                                let _ = write!(out, "L{:.2} {:.2} ", p.0, p.1);
                            }
                            Cmd::Dot(x, y) => {
                                last = (f64::NAN, f64::NAN);
                                let _ = write!(out, "M{:.2} {:.2} m-3 0 a3 3 0 1 0 6 0 a3 3 0 1 0 -6 0 ", tx(x), ty(y));
                            }
                            Cmd::Arc(x, y, r, cw) => {
                                // The view flips its vertical axis: clockwise in the view is SVG's positive sweep.
                                last = (tx(x), ty(y));
                                let rs = (r * scale).min(1e7);
                                let _ =
                                    write!(out, "A {rs:.2} {rs:.2} 0 0 {} {:.2} {:.2} ", u8::from(cw), last.0, last.1);
                            }
                        }
                    }
                    if let (Some(pen), Some(at)) = (layer.pen, layer.at)
                        && !near(pen, at, MERGE)
                    {
                        let _ = write!(out, "L{:.2} {:.2}", tx(at.0), ty(at.1));
                    }
                    let _ = writeln!(out, r##""/>"##);
                }
            }
            // Findings; markers at the same place are set side by side, a leader to the place.
            let mut placed: Vec<(f64, f64)> = Vec::new();
            for (i, m) in self.marks.iter().enumerate() {
                let (x, y) = (m.at[u], m.at[w]);
                if !(x.is_finite() && y.is_finite()) {
                    continue;
                }
                let (cx, cy) = (tx(x), ty(y));
                let (mut px, mut py) = (cx, cy);
                let mut turn = 0;
                while turn < 64 && placed.iter().any(|&(qx, qy)| (qx - px).hypot(qy - py) < 17.0) {
                    turn += 1;
                    // Around the place, a ring of 8 then a wider one.
                    let ring = 20.0 * f64::from(1 + (turn - 1) / 8);
                    let angle = f64::from(turn) * PI / 4.0 - PI / 4.0;
                    px = cx + ring * angle.cos();
                    py = cy - ring * angle.sin();
                }
                placed.push((px, py));
                let fill = if m.error { "#d62728" } else { "#ff9f1c" };
                if turn > 0 {
                    let _ = writeln!(
                        out,
                        r##"<line x1="{cx:.2}" y1="{cy:.2}" x2="{px:.2}" y2="{py:.2}" stroke="{fill}" stroke-width="1"/>"##
                    );
                }
                let _ = writeln!(
                    out,
                    r##"<g class="finding"><circle cx="{px:.2}" cy="{py:.2}" r="9" fill="{fill}" fill-opacity="0.85" stroke="#ffffff" stroke-width="1.5"/><text x="{px:.2}" y="{:.2}" text-anchor="middle" font-size="10" font-weight="bold" fill="#ffffff">{}</text></g>"##,
                    py + 3.5,
                    i + 1
                );
            }
            let _ = writeln!(out, "</g>");
        }
        // Legend.
        let lx = left;
        let _ = writeln!(out, r##"<g class="legend">"##);
        let entries =
            [(0, 1, "toolpath feed"), (0, 0, "toolpath rapid"), (1, 1, "program feed / arc"), (1, 0, "program rapid")];
        let mut x = lx;
        for (src, feed, label) in entries {
            let (class, style) = layer_style(src, feed);
            let _ = writeln!(
                out,
                r##"<path class="{class}" {style} fill="none" d="M{x:.2} {legend_y:.2} L{:.2} {legend_y:.2}"/>"##,
                x + 40.0
            );
            let _ = writeln!(out, r##"<text x="{:.2}" y="{:.2}">{label}</text>"##, x + 48.0, legend_y + 4.0);
            x += 48.0 + 7.5 * label.len() as f64 + 28.0;
        }
        let _ = writeln!(
            out,
            r##"<circle cx="{:.2}" cy="{legend_y:.2}" r="7" fill="#d62728"/><text x="{:.2}" y="{:.2}">error</text>"##,
            x + 7.0,
            x + 20.0,
            legend_y + 4.0
        );
        let _ = writeln!(
            out,
            r##"<circle cx="{:.2}" cy="{legend_y:.2}" r="7" fill="#ff9f1c"/><text x="{:.2}" y="{:.2}">warning</text>"##,
            x + 77.0,
            x + 90.0,
            legend_y + 4.0
        );
        let _ = writeln!(out, "</g>");
        let mut y = legend_y + 30.0;
        for note in &dropped {
            let _ =
                writeln!(out, r##"<text class="note" x="{lx:.2}" y="{y:.2}" fill="#555555">{}</text>"##, escape(note));
            y += 18.0;
        }
        // The findings' list.
        let _ = writeln!(out, r##"<g class="findings">"##);
        let heading = match self.marks.len() {
            0 => "No findings: the program makes the toolpath.".to_string(),
            n => format!("{n} finding(s) (code, program line, message):"),
        };
        let _ = writeln!(out, r##"<text x="{lx:.2}" y="{list_y:.2}" font-weight="bold">{}</text>"##, escape(&heading));
        let mut y = list_y + 18.0;
        for (i, m) in self.marks.iter().take(MAX_LISTED).enumerate() {
            let line = m.line.map_or("-".to_string(), |l| l.to_string());
            let fill = if m.error { "#d62728" } else { "#c47600" };
            let message = truncate(&m.message, 130);
            let _ = writeln!(
                out,
                r##"<text x="{lx:.2}" y="{y:.2}"><tspan font-weight="bold" fill="{fill}">{}. {}</tspan> line {line}: {}</text>"##,
                i + 1,
                escape(&m.code),
                escape(&message)
            );
            y += 18.0;
        }
        if self.marks.len() > MAX_LISTED {
            let _ = writeln!(
                out,
                r##"<text x="{lx:.2}" y="{y:.2}">… and {} more (all are marked above; `postc verify` lists them)</text>"##,
                self.marks.len() - MAX_LISTED
            );
        }
        let _ = writeln!(out, "</g>\n</svg>");
        out
    }

    fn dropped_notes(&self) -> Vec<String> {
        let mut notes = Vec::new();
        for (v, &(_, _, name)) in VIEWS.iter().enumerate() {
            for (src, who) in ["toolpath", "program"].iter().enumerate() {
                let n: u64 = self.layers[v][src].iter().map(|l| l.dropped).sum();
                if n > 0 {
                    notes.push(format!("{name}: {n} later {who} move(s) not drawn (a layer holds {MAX_POINTS} path points; the findings cover them all)"));
                }
                let res = self.layers[v][src].iter().map(|l| l.res).fold(MERGE, f64::max);
                if res > MERGE {
                    let (r, u) = if self.inch { (res / 25.4, "in") } else { (res, "mm") };
                    notes.push(format!(
                        "{name}: the {who} is drawn to {r:.3} {u} (at most {MAX_POINTS} path points per layer)"
                    ));
                }
            }
        }
        notes
    }
}

/// Class and stroke of a layer.
fn layer_style(src: usize, feed: usize) -> (&'static str, &'static str) {
    match (src, feed) {
        (0, 1) => ("toolpath-feed", r##"stroke="#8ec5f0" stroke-width="6""##),
        (0, _) => ("toolpath-rapid", r##"stroke="#8ec5f0" stroke-width="3" stroke-dasharray="10 6""##),
        (_, 1) => ("program-feed", r##"stroke="#1f2a44" stroke-width="1.3""##),
        _ => ("program-rapid", r##"stroke="#1f2a44" stroke-width="1" stroke-dasharray="4 4""##),
    }
}

/// 1, 2 or 5 times a power of ten, at least `raw`.
#[doc(hidden)]
pub fn nice_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0].into_iter().map(|m| m * p).find(|s| *s >= raw * 0.999).unwrap_or(10.0 * p)
}

fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n { s.to_string() } else { s.chars().take(n).chain("…".chars()).collect() }
}

/// Escapes text for SVG.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c if (c as u32) < 0x20 && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}
