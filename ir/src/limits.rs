//! The ranges of the numbers a toolpath may carry. Every toolpath reader
//! (APT CL, native RON / JSON Lines) checks each event it gives out with a
//! [`RangeCheck`] and refuses the toolpath when one has coordinates, feeds,
//! speeds, angles, times or power outside these ranges (or numbers that are
//! not finite), with an error at the record's line: a CL file that says
//! `GOTO/1e308,5,0` would otherwise post as a 309-digit `X` word. The event
//! is still given out, so that the stream keeps the order of its events
//! (a drilling cycle's holes inside it); the error stops `postc post`
//! before the event reaches a post. `docs/toolpath-format.md`
//! ("Ranges") lists them.
//!
//! The limits are generous and physical: no machine tool has an axis a
//! kilometre long, a feed of a kilometre a minute or a spindle turning a
//! million times a minute, so a value past them is a fault of the file, not
//! a job.

use crate::event::{Event, Point};
use crate::units::Units;

/// The largest length, in millimetres: coordinates, centres, heights,
/// diameters, pecks and pitches lie within ±1 km.
pub const MAX_LENGTH_MM: f64 = 1e6;

/// The largest feed, in millimetres per minute (or per revolution): 1 km
/// a minute.
pub const MAX_FEED_MM: f64 = 1e6;

/// The largest spindle speed, revolutions per minute (or surface speed).
pub const MAX_SPEED: f64 = 1e6;

/// The largest rotary axis position, degrees (about 2,800 turns).
pub const MAX_ANGLE_DEG: f64 = 1e6;

/// The longest dwell, seconds (or spindle revolutions): about 11 days.
pub const MAX_DWELL: f64 = 1e6;

/// The largest jet power, in the post's scale (percent, watts, S units).
pub const MAX_POWER: f64 = 1e6;

/// What kind of number a value is, which decides its range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A coordinate or other length: within ±[`MAX_LENGTH_MM`].
    Length,
    /// A feed: from 0 to [`MAX_FEED_MM`].
    Feed,
    /// A spindle speed: within ±[`MAX_SPEED`] (a tool's negative speed
    /// means "no spindle").
    Speed,
    /// A rotary axis position: within ±[`MAX_ANGLE_DEG`].
    Angle,
    /// A dwell: from 0 to [`MAX_DWELL`].
    Dwell,
    /// Jet power: from 0 to [`MAX_POWER`].
    Power,
    /// A component of a tool axis vector: finite (a unit vector's are
    /// within ±1, but a vector the reader normalises may be longer), within
    /// ±[`MAX_LENGTH_MM`] as a plain number.
    Axis,
}

impl Kind {
    /// The lowest and highest value allowed, in `units` where the kind is
    /// a length or a feed.
    pub fn range(self, units: Units) -> (f64, f64) {
        let per_unit = units.mm_per_unit();
        match self {
            Kind::Length => (-MAX_LENGTH_MM / per_unit, MAX_LENGTH_MM / per_unit),
            Kind::Feed => (0.0, MAX_FEED_MM / per_unit),
            Kind::Speed => (-MAX_SPEED, MAX_SPEED),
            Kind::Angle => (-MAX_ANGLE_DEG, MAX_ANGLE_DEG),
            Kind::Dwell => (0.0, MAX_DWELL),
            Kind::Power => (0.0, MAX_POWER),
            Kind::Axis => (-MAX_LENGTH_MM, MAX_LENGTH_MM),
        }
    }

    /// What a value of this kind is, for messages.
    fn noun(self) -> &'static str {
        match self {
            Kind::Length => "a coordinate or length",
            Kind::Feed => "a feed",
            Kind::Speed => "a spindle speed",
            Kind::Angle => "a rotary axis position",
            Kind::Dwell => "a dwell",
            Kind::Power => "a jet power",
            Kind::Axis => "a tool axis component",
        }
    }

    fn unit(self, units: Units) -> &'static str {
        match (self, units) {
            (Kind::Length, Units::Mm) => " mm",
            (Kind::Length, Units::Inch) => " in",
            (Kind::Feed, Units::Mm) => " mm/min",
            (Kind::Feed, Units::Inch) => " in/min",
            (Kind::Speed, _) => " rpm",
            (Kind::Angle, _) => " degrees",
            (Kind::Dwell, _) => " s",
            (Kind::Power | Kind::Axis, _) => "",
        }
    }
}

/// A value outside its range.
#[derive(Clone, Debug, PartialEq)]
pub struct OutOfRange {
    /// The field, as the native format names it (`x`, `feed`, `cx`, ...).
    pub field: &'static str,
    pub value: f64,
    pub kind: Kind,
    /// The units the value is in.
    pub units: Units,
}

impl OutOfRange {
    /// The message a reader gives, naming the event.
    pub fn message(&self, event: &str) -> String {
        let (lo, hi) = self.kind.range(self.units);
        let unit = self.kind.unit(self.units);
        let value = match self.value {
            v if !v.is_finite() => "not a finite number".to_string(),
            v if v.abs() >= 1e9 => format!("{v:e}"),
            v => format!("{v}"),
        };
        let range = if lo == -hi {
            format!("within ±{}{unit}", round(hi))
        } else {
            format!("from {} to {}{unit}", round(lo), round(hi))
        };
        format!("{event} {} is {value}: {} must be {range}", self.field, self.kind.noun())
    }
}

/// A limit as people read it: whole, or to two decimals.
fn round(v: f64) -> String {
    if v.fract() == 0.0 { format!("{v}") } else { format!("{v:.2}") }
}

/// Checks events in stream order: the `Job` says the units of what
/// follows. A value the check refused once is not reported again while it
/// comes back unchanged in the same field (the feed every later move
/// carries after one bad `FEDRAT`), so a reader reports it once
/// ([`Verdict::RefuseAgain`]).
#[derive(Clone, Debug)]
pub struct RangeCheck {
    units: Units,
    last: Option<(&'static str, u64)>,
    /// The largest length and feed in `units`, for the moves' fast path.
    length: f64,
    feed: f64,
}

impl Default for RangeCheck {
    fn default() -> RangeCheck {
        RangeCheck::in_units(Units::Mm)
    }
}

/// The verdict on one event.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    Fine,
    /// Out of range: report it.
    Refuse(OutOfRange),
    /// Out of range again with the value last reported: refuse it without
    /// a second report.
    RefuseAgain,
}

impl RangeCheck {
    pub fn new() -> RangeCheck {
        RangeCheck::default()
    }

    fn in_units(units: Units) -> RangeCheck {
        RangeCheck { units, last: None, length: Kind::Length.range(units).1, feed: Kind::Feed.range(units).1 }
    }

    /// Whether a move (nearly every event of a toolpath) is plainly within
    /// range: its coordinates, feed, rotary axes and tool axis. A NaN fails
    /// every comparison, so it takes the slow path, which reports it. (A
    /// tool axis within the length limit of the units is within its own.)
    #[inline]
    fn plain_move(&self, event: &Event) -> bool {
        let l = self.length;
        let within = |x: f64, y: f64, z: f64| x.abs() <= l && y.abs() <= l && z.abs() <= l;
        let feed = |f: Option<f64>| f.is_none_or(|f| (0.0..=self.feed).contains(&f));
        let angle = |v: Option<f64>| v.is_none_or(|v| v.abs() <= MAX_ANGLE_DEG);
        let axis = |v: Option<[f64; 3]>| v.is_none_or(|[i, j, k]| within(i, j, k));
        match event {
            Event::Rapid(m) => within(m.x, m.y, m.z) && angle(m.a) && angle(m.b) && angle(m.c) && axis(m.tool_axis),
            Event::Feed(m) => {
                within(m.x, m.y, m.z) && feed(m.feed) && angle(m.a) && angle(m.b) && angle(m.c) && axis(m.tool_axis)
            }
            Event::Arc(a) => within(a.x, a.y, a.z) && within(a.cx, a.cy, a.cz) && feed(a.feed),
            _ => false,
        }
    }

    /// The verdict on `event`.
    #[inline]
    pub fn check(&mut self, event: &Event) -> Verdict {
        if self.plain_move(event) {
            self.last = None;
            return Verdict::Fine;
        }
        self.check_slowly(event)
    }

    fn check_slowly(&mut self, event: &Event) -> Verdict {
        if let Event::Job(job) = event {
            let last = self.last;
            *self = RangeCheck::in_units(job.units);
            self.last = last;
        }
        match first_out_of_range(event, self.units) {
            None => {
                self.last = None;
                Verdict::Fine
            }
            Some(bad) => {
                let key = (bad.field, bad.value.to_bits());
                if self.last == Some(key) {
                    Verdict::RefuseAgain
                } else {
                    self.last = Some(key);
                    Verdict::Refuse(bad)
                }
            }
        }
    }
}

/// The first value of `event` outside its range, its values read in `units`.
pub fn first_out_of_range(event: &Event, units: Units) -> Option<OutOfRange> {
    use Kind::*;
    let mut found = None;
    let mut check = |field: &'static str, value: f64, kind: Kind| {
        let (lo, hi) = kind.range(units);
        if found.is_none() && !(lo..=hi).contains(&value) {
            found = Some(OutOfRange { field, value, kind, units });
        }
    };
    let point = |p: &Point, names: [&'static str; 3], check: &mut dyn FnMut(&'static str, f64, Kind)| {
        check(names[0], p.x, Length);
        check(names[1], p.y, Length);
        check(names[2], p.z, Length);
    };
    let rotary = |a: Option<f64>,
                  b: Option<f64>,
                  c: Option<f64>,
                  axis: Option<[f64; 3]>,
                  check: &mut dyn FnMut(&'static str, f64, Kind)| {
        for (name, v) in [("a", a), ("b", b), ("c", c)] {
            if let Some(v) = v {
                check(name, v, Angle);
            }
        }
        for v in axis.into_iter().flatten() {
            check("tool_axis", v, Axis);
        }
    };
    match event {
        Event::Job(job) => {
            if let Some(m) = &job.material {
                point(&m.min, ["material.min.x", "material.min.y", "material.min.z"], &mut check);
                point(&m.max, ["material.max.x", "material.max.y", "material.max.z"], &mut check);
            }
            if let Some(o) = &job.origin {
                check("origin.x", o.x, Length);
                check("origin.y", o.y, Length);
            }
            if let Some(h) = &job.home {
                point(h, ["home.x", "home.y", "home.z"], &mut check);
            }
            if let Some(z) = job.safe_z {
                check("safe_z", z, Length);
            }
            if let Some(d) = job.wrap_diameter {
                check("wrap_diameter", d, Length);
            }
        }
        Event::Tool(t) => {
            check("diameter", t.diameter, Length);
            check("spindle_speed", t.spindle_speed, Speed);
            check("cut_feed", t.cut_feed, Feed);
            check("plunge_feed", t.plunge_feed, Feed);
            if let Some(p) = t.power {
                check("power", p, Power);
            }
        }
        Event::Rapid(m) => {
            point(&Point { x: m.x, y: m.y, z: m.z }, ["x", "y", "z"], &mut check);
            rotary(m.a, m.b, m.c, m.tool_axis, &mut check);
        }
        Event::Feed(m) => {
            point(&Point { x: m.x, y: m.y, z: m.z }, ["x", "y", "z"], &mut check);
            if let Some(f) = m.feed {
                check("feed", f, Feed);
            }
            rotary(m.a, m.b, m.c, m.tool_axis, &mut check);
        }
        Event::Arc(a) => {
            point(&Point { x: a.x, y: a.y, z: a.z }, ["x", "y", "z"], &mut check);
            point(&Point { x: a.cx, y: a.cy, z: a.cz }, ["cx", "cy", "cz"], &mut check);
            if let Some(f) = a.feed {
                check("feed", f, Feed);
            }
        }
        Event::Dwell(d) => check("seconds", d.seconds, Dwell),
        Event::SpindleOn(s) => {
            if let Some(v) = s.speed {
                check("speed", v, Speed);
            }
            if let Some(v) = s.max_rpm {
                check("max_rpm", v, Speed);
            }
        }
        Event::Power(p) => check("value", p.value, Power),
        Event::DrillCycle(c) => {
            check("retract_plane", c.retract_plane, Length);
            check("reference_plane", c.reference_plane, Length);
            if let Some(s) = c.surface {
                check("surface", s, Length);
            }
            check("depth", c.depth, Length);
            if let Some(f) = c.feed {
                check("feed", f, Feed);
            }
            if let Some(p) = c.peck {
                check("peck", p, Length);
            }
            if let Some(d) = c.dwell {
                check("dwell", d, Dwell);
            }
            if let Some(p) = c.pitch {
                check("pitch", p, Length);
            }
        }
        Event::DrillPoint(p) => point(&Point { x: p.x, y: p.y, z: p.z }, ["x", "y", "z"], &mut check),
        Event::FeedRate(f) => {
            let units = f.unit.and_then(|u| u.units()).unwrap_or(units);
            let (lo, hi) = Feed.range(units);
            if !(lo..=hi).contains(&f.value) {
                return Some(OutOfRange { field: "value", value: f.value, kind: Feed, units });
            }
        }
        Event::ToolpathStart(_)
        | Event::ToolpathEnd
        | Event::SpindleOff
        | Event::JetOn
        | Event::JetOff
        | Event::Coolant(_)
        | Event::CutterComp(_)
        | Event::DrillEnd
        | Event::Comment(_)
        | Event::Insert(_)
        | Event::Command(_)
        | Event::End => {}
    }
    found
}
