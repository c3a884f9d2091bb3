//! The job's outline: what a post that reads ahead (a Fusion post's
//! `getSection(i)`, `getToolTable()`, `getNextTool()`) knows of every
//! toolpath before it comes, made by reading the toolpath's events once
//! more ([`crate::event::EventSource::outline`]).
//!
//! A section is what the runtime starts at a toolpath's first move: a
//! toolpath, or the part of one after a tool change. A toolpath that never
//! moves is no section.

use crate::event::{Coolant, DrillKind, Event, Tool};
use crate::units::Units;

/// One section of the job, as far as reading ahead can tell.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SectionOutline {
    /// The tool that cuts it, its spindle speed the last one set before
    /// the section's first move.
    pub tool: Tool,
    /// The toolpath's name and notes.
    pub toolpath: String,
    pub toolpath_notes: String,
    /// The coolant in force at the first move.
    pub coolant: Coolant,
    /// Where the first move goes; for a section that starts with a
    /// drilling cycle, over its first hole at the cycle's clearance plane.
    pub first: [f64; 3],
    /// The lowest and highest Z the section reaches (moves, holes'
    /// bottoms, cycles' clearance planes).
    pub z_min: f64,
    pub z_max: f64,
    /// The kind of the drilling cycle that starts the section, and whether
    /// it dwells.
    pub starts_with_cycle: Option<(DrillKind, bool)>,
    /// Drilling cycles in the section and their holes.
    pub cycles: u32,
    pub cycle_points: u32,
}

/// The job's sections in order, in the toolpath's units.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JobOutline {
    pub units: Units,
    pub sections: Vec<SectionOutline>,
}

impl JobOutline {
    /// The outline of a job read from its events.
    pub fn of(events: impl IntoIterator<Item = Event>) -> JobOutline {
        let mut out = JobOutline::default();
        let mut tool = Tool::default();
        let mut toolpath = String::new();
        let mut toolpath_notes = String::new();
        let mut coolant = Coolant::Off;
        let mut cycle: Option<crate::event::DrillCycle> = None;
        // The section being read, once it has moved.
        let mut open: Option<SectionOutline> = None;
        // Whether the next move starts a section.
        let mut fresh = true;
        let close = |open: &mut Option<SectionOutline>, out: &mut JobOutline| {
            if let Some(s) = open.take() {
                out.sections.push(s);
            }
        };
        for event in events {
            let reached = match &event {
                Event::Job(j) => {
                    out.units = j.units;
                    None
                }
                Event::Tool(t) => {
                    if t.number != tool.number {
                        close(&mut open, &mut out);
                        fresh = true;
                    }
                    tool = t.clone();
                    None
                }
                Event::ToolpathStart(t) => {
                    close(&mut open, &mut out);
                    fresh = true;
                    toolpath.clone_from(&t.name);
                    toolpath_notes.clone_from(&t.notes);
                    None
                }
                Event::SpindleOn(s) => {
                    // A constant surface speed is no rpm of the tool's.
                    if let (true, Some(speed), false) = (fresh, s.speed, s.css) {
                        tool.spindle_speed = speed;
                    }
                    None
                }
                Event::Coolant(c) => {
                    coolant = c.coolant;
                    None
                }
                Event::Rapid(m) => Some(([m.x, m.y, m.z], m.z, m.z)),
                Event::Feed(m) => Some(([m.x, m.y, m.z], m.z, m.z)),
                Event::Arc(a) => Some(([a.x, a.y, a.z], a.z, a.z)),
                Event::DrillCycle(c) => {
                    cycle = Some(c.clone());
                    if let Some(s) = open.as_mut() {
                        s.cycles += 1;
                    }
                    None
                }
                Event::DrillPoint(p) => cycle.as_ref().map(|c| {
                    let (low, high) = (c.depth.min(c.retract_plane), c.depth.max(c.retract_plane));
                    ([p.x, p.y, c.retract_plane], low, high)
                }),
                Event::DrillEnd => {
                    cycle = None;
                    None
                }
                _ => None,
            };
            let Some((at, low, high)) = reached else { continue };
            if fresh {
                fresh = false;
                let starts_with_cycle = match (&event, &cycle) {
                    (Event::DrillPoint(_), Some(c)) => Some((c.kind, c.dwell.is_some_and(|d| d > 0.0))),
                    _ => None,
                };
                open = Some(SectionOutline {
                    tool: tool.clone(),
                    toolpath: toolpath.clone(),
                    toolpath_notes: toolpath_notes.clone(),
                    coolant,
                    first: at,
                    z_min: low,
                    z_max: high,
                    starts_with_cycle,
                    cycles: u32::from(starts_with_cycle.is_some()),
                    cycle_points: 0,
                });
            }
            if let Some(s) = open.as_mut() {
                s.z_min = s.z_min.min(low);
                s.z_max = s.z_max.max(high);
                if matches!(event, Event::DrillPoint(_)) {
                    s.cycle_points += 1;
                }
            }
        }
        close(&mut open, &mut out);
        out
    }
}
