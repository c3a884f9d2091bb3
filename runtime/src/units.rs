//! The one place where a toolpath's units become the post's: every event
//! is converted before it is dispatched, whatever the dialect, so that
//! handlers, script hosts, the machine state and the drilling and arc
//! geometry all see lengths and feeds in the post's output units
//! ([`postc_ir::Post::output_units`]; docs/units.md).
//!
//! The first `Job` fixes the toolpath's units (millimetres until one
//! comes, as a stream without a `Job` is read) and so the factor; a later
//! `Job` (ignored by the dispatchers, RT011) is converted from its own.

use postc_ir::Units;
use postc_ir::event::{Event, Point};

/// Converts events from the toolpath's units to the post's.
#[derive(Clone, Copy, Debug)]
pub struct Conversion {
    /// The post's units; `None` writes the toolpath's own.
    post: Option<Units>,
    /// The units every event is converted to.
    output: Units,
    /// Toolpath length units to output units.
    factor: f64,
    /// Whether a `Job` fixed the factor.
    fixed: bool,
}

/// Metres per minute in feet per minute, for constant surface speeds.
const M_PER_FT: f64 = 0.3048;

impl Conversion {
    /// A conversion into `post` units (the toolpath's own when `None`).
    pub fn new(post: Option<Units>) -> Conversion {
        let output = post.unwrap_or_default();
        Conversion { post, output, factor: Units::Mm.factor_to(output), fixed: false }
    }

    /// The units events come out in.
    pub fn output(&self) -> Units {
        self.output
    }

    /// The units the events of `job` come out in: the post's, else the
    /// job's own.
    pub fn units_for(&self, job: &postc_ir::event::Job) -> Units {
        self.post.unwrap_or(job.units)
    }

    /// Converts `event` in place.
    #[inline]
    pub fn convert(&mut self, event: &mut Event) {
        if let Event::Job(job) = event {
            if !self.fixed {
                self.fixed = true;
                self.output = self.units_for(job);
                self.factor = job.units.factor_to(self.output);
            }
            let f = job.units.factor_to(self.output);
            job.units = self.output;
            if f != 1.0 {
                scale_job(job, f);
            }
            return;
        }
        if self.factor != 1.0 {
            scale(event, self.factor);
        }
    }
}

fn times<const N: usize>(f: f64, values: [&mut f64; N]) {
    for v in values {
        *v *= f;
    }
}

fn scale_point(p: &mut Point, f: f64) {
    times(f, [&mut p.x, &mut p.y, &mut p.z]);
}

fn scale_job(job: &mut postc_ir::event::Job, f: f64) {
    if let Some(m) = &mut job.material {
        scale_point(&mut m.min, f);
        scale_point(&mut m.max, f);
    }
    if let Some(o) = &mut job.origin {
        o.x *= f;
        o.y *= f;
    }
    if let Some(h) = &mut job.home {
        scale_point(h, f);
    }
    job.safe_z = job.safe_z.map(|z| z * f);
    job.wrap_diameter = job.wrap_diameter.map(|d| d * f);
}

/// Every length and feed of an event times `f`: positions, centres,
/// heights, diameters, pecks, pitches and feeds (per minute or per
/// revolution). Spindle speeds in rpm, angles, times and power are not
/// lengths; a constant surface speed goes from feet to metres a minute or
/// back. A `FeedRate` keeps what the toolpath wrote, with its unit (posts
/// never see it; `postp` reads it as written), and `Command` arguments are
/// passed as written.
fn scale(event: &mut Event, f: f64) {
    match event {
        Event::Tool(t) => {
            t.diameter *= f;
            t.cut_feed *= f;
            t.plunge_feed *= f;
        }
        Event::Rapid(m) => times(f, [&mut m.x, &mut m.y, &mut m.z]),
        Event::Feed(m) => {
            times(f, [&mut m.x, &mut m.y, &mut m.z]);
            m.feed = m.feed.map(|v| v * f);
        }
        Event::Arc(a) => {
            times(f, [&mut a.x, &mut a.y, &mut a.z, &mut a.cx, &mut a.cy, &mut a.cz]);
            a.feed = a.feed.map(|v| v * f);
        }
        Event::DrillCycle(c) => {
            c.retract_plane *= f;
            c.reference_plane *= f;
            c.surface = c.surface.map(|v| v * f);
            c.depth *= f;
            c.feed = c.feed.map(|v| v * f);
            c.peck = c.peck.map(|v| v * f);
            c.pitch = c.pitch.map(|v| v * f);
        }
        Event::DrillPoint(p) => times(f, [&mut p.x, &mut p.y, &mut p.z]),
        Event::SpindleOn(s) if s.css => {
            let surface = if f > 1.0 { M_PER_FT } else { 1.0 / M_PER_FT };
            s.speed = s.speed.map(|v| v * surface);
        }
        Event::Job(_)
        | Event::ToolpathStart(_)
        | Event::ToolpathEnd
        | Event::Dwell(_)
        | Event::SpindleOn(_)
        | Event::SpindleOff
        | Event::JetOn
        | Event::JetOff
        | Event::Power(_)
        | Event::Coolant(_)
        | Event::CutterComp(_)
        | Event::DrillEnd
        | Event::Comment(_)
        | Event::Insert(_)
        | Event::Command(_)
        | Event::End
        | Event::FeedRate(_) => {}
    }
}
