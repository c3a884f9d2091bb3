//! Machine state: everything the runtime knows at a moment of the toolpath,
//! in the post's output units, and the [`Quantity`] values posts print.
//!
//! Events arrive already in the post's output units (the runtime converts
//! each one before dispatch, `units.rs`), so every quantity is in output
//! units when a handler formats it.
//!
//! A quantity nothing has given a value (jet power while a spindle tool
//! cuts, the A axis before any move sets it, a spindle speed or feed of 0,
//! the home position of a job that has none, ...) is [`NO_VALUE`] (NaN):
//! the variable that prints it prints nothing, prefix included, never a
//! made-up number the machine would obey (`S0` in a router's feed moves,
//! `G0 Z0` for a home Z the job never gave). `docs/vectric.md` lists every
//! quantity and what it prints without a source.

use postc_ir::event::{CompSide, Coolant, DrillCycle, DrillKind, Job, Plane, Tool, ToolpathStart, ZOrigin};
use postc_ir::post::{RotaryWrap, SpindleSpeedRange, WrappedAxis};
use postc_ir::{Quantity, Units};

use crate::geometry::ArcGeometry;

/// The value of a quantity that has no source: the word prints nothing.
/// Events never carry NaN (they are checked on the way in, RT016), so NaN
/// here always means "no value".
pub const NO_VALUE: f64 = f64::NAN;

/// A number that means "not given" when it is 0 (a tool's feeds and speed:
/// the toolpath format writes 0 for a value it does not know).
#[inline]
fn given(v: f64) -> f64 {
    if v == 0.0 { NO_VALUE } else { v }
}

/// The `COOLANT_KIND` number of a coolant: 0 off, 1 flood, 2 mist, 3
/// through the tool, 4 air.
pub fn coolant_kind(coolant: Coolant) -> f64 {
    match coolant {
        Coolant::Off => 0.0,
        Coolant::Flood => 1.0,
        Coolant::Mist => 2.0,
        Coolant::Through => 3.0,
        Coolant::Air => 4.0,
    }
}

/// The `DRILL_KIND` number of a cycle: 0 drill, 1 deep, 2 chip breaking,
/// 3 tap, 4 bore, 5 ream.
pub fn drill_kind(kind: DrillKind) -> f64 {
    match kind {
        DrillKind::Drill => 0.0,
        DrillKind::Deep => 1.0,
        DrillKind::ChipBreak => 2.0,
        DrillKind::Tap => 3.0,
        DrillKind::Bore => 4.0,
        DrillKind::Ream => 5.0,
    }
}

/// The current state of the machine and the job.
#[derive(Clone, Debug)]
pub struct MachineState {
    pub output_units: Units,
    pub job: Job,
    pub tool: Tool,
    pub previous_tool: Option<u32>,
    pub toolpath: ToolpathStart,
    /// Current position (end of the last move).
    pub pos: [f64; 3],
    /// Whether `pos` is known: after the first move, or from the job's home.
    pub pos_known: bool,
    /// Rotary positions (degrees) as the toolpath last set them.
    pub rotary: [Option<f64>; 3],
    /// Whether a Tool event has come.
    pub has_tool: bool,
    /// Current feed rate.
    pub feed: f64,
    /// Start of the current move, and its length when it is not straight
    /// (arcs), for the inverse-time feed number.
    pub move_from: [f64; 3],
    pub move_length: Option<f64>,
    pub spindle_speed: f64,
    /// Whether the spindle runs at constant surface speed (the last
    /// SpindleOn's `css`: `spindle_speed` is then m/min or ft/min), and its
    /// highest speed in rpm then; both reset when a tool is loaded.
    pub spindle_css: bool,
    pub spindle_max_rpm: Option<f64>,
    /// Whether the spindle turns counter-clockwise (the last SpindleOn's
    /// `ccw`); a tool is loaded turning clockwise.
    pub spindle_ccw: bool,
    /// Jet power: the jet tool's own, or the last Power event's since the
    /// tool was loaded; `None` while no power is set (a spindle tool prints
    /// nothing, a jet tool 0).
    pub power: Option<f64>,
    /// Dwell time in seconds; [`NO_VALUE`] before any dwell.
    pub dwell: f64,
    /// The drilling cycle between its DrillCycle and DrillEnd events.
    pub drill: Option<DrillCycle>,
    /// Geometry of the arc being printed.
    pub arc: ArcGeometry,
    pub comment: String,
    pub date: String,
    pub time: String,
    /// What `[DATE]` and `[TIME]` print when neither the job nor the
    /// command line gives them.
    pub default_date: String,
    pub default_time: String,
    /// Output file, as printed by `[TP_FILENAME]`, `[TP_DIR]`, `[TP_EXT]`.
    pub file_name: String,
    pub file_dir: String,
    pub file_ext: String,
    /// Cutter compensation register a CutterComp event named.
    pub comp_register: Option<f64>,
    /// The side of the last CutterComp event.
    pub comp_side: CompSide,
    /// The coolant of the last Coolant event.
    pub coolant: Coolant,
    /// `[TOOLS_USED]` and `[TOOLPATHS_OUTPUT]`: the job's lists, joined.
    pub tools_used: String,
    pub toolpaths_output: String,
    pub spindle_range: Option<SpindleSpeedRange>,
    pub wrap: Option<RotaryWrap>,
    /// `[REVISION]`: the post's revision hash (`PostInfo::revision`).
    pub revision: String,
    /// `JOB_OUTLINE`: the job's outline as JSON, for posts that read ahead.
    pub outline: String,
    /// `POST_PROPERTIES`: the post properties the user set, as JSON.
    pub properties: String,
    /// `RECORD_ID` and `NEXT_RECORD_MOTION`: where the event being posted
    /// is in the toolpath, and whether a move follows it (posts that read
    /// ahead).
    pub record_id: f64,
    pub next_record_motion: bool,
}

impl MachineState {
    pub fn new(
        output_units: Option<Units>,
        spindle_range: Option<SpindleSpeedRange>,
        wrap: Option<RotaryWrap>,
    ) -> MachineState {
        let units = output_units.unwrap_or_default();
        MachineState {
            output_units: units,
            job: Job::default(),
            tool: Tool::default(),
            previous_tool: None,
            toolpath: ToolpathStart::default(),
            pos: [0.0; 3],
            pos_known: false,
            rotary: [None; 3],
            has_tool: false,
            feed: 0.0,
            move_from: [0.0; 3],
            move_length: None,
            spindle_speed: 0.0,
            spindle_css: false,
            spindle_ccw: false,
            spindle_max_rpm: None,
            power: None,
            dwell: NO_VALUE,
            drill: None,
            arc: ArcGeometry::default(),
            comment: String::new(),
            date: String::new(),
            time: String::new(),
            default_date: String::new(),
            default_time: String::new(),
            file_name: String::new(),
            file_dir: String::new(),
            file_ext: String::new(),
            comp_register: None,
            comp_side: CompSide::Off,
            coolant: Coolant::Off,
            tools_used: String::new(),
            toolpaths_output: String::new(),
            spindle_range,
            wrap,
            revision: String::new(),
            outline: String::new(),
            properties: "{}".into(),
            record_id: 0.0,
            next_record_motion: false,
        }
    }

    /// Takes the job, already in output units (its units are the output's).
    pub fn set_job(&mut self, job: Job) {
        self.output_units = job.units;
        if let Some(h) = &job.home {
            self.pos = [h.x, h.y, h.z];
            self.pos_known = true;
        }
        if self.file_name.is_empty() {
            self.file_name.clone_from(&job.file.name);
            self.file_dir.clone_from(&job.file.dir);
            self.file_ext.clone_from(&job.file.extension);
        }
        if self.date.is_empty() {
            self.date = job.date.clone().unwrap_or_default();
        }
        if self.time.is_empty() {
            self.time = job.time.clone().unwrap_or_default();
        }
        self.tools_used = job.tools.join(", ");
        self.toolpaths_output = job.toolpaths.join(", ");
        self.job = job;
    }

    /// Takes a tool: converts its feeds and diameter. Until a move sets
    /// another, the current feed (`[F]`) is the tool's cut feed, which is
    /// what a HEADER or TOOLCHANGE that prints `[F]` means ("Feed Rate used
    /// for cutting", the 2012 Vectric post guide) and what a rapid that carries `[F]` should
    /// print before the first cut, rather than 0.
    pub fn set_tool(&mut self, tool: Tool) {
        self.feed = tool.cut_feed;
        // The first tool has no previous one: `[TP]` prints nothing until a
        // second tool comes.
        if self.has_tool && self.tool.number != tool.number {
            self.previous_tool = Some(self.tool.number);
        }
        self.spindle_speed = tool.spindle_speed;
        self.spindle_css = false;
        self.spindle_ccw = false;
        self.spindle_max_rpm = None;
        // Power belongs to jet tools: a spindle tool has none, and a new
        // jet tool has its own or none until a Power event. The same jet
        // tool given again keeps the power it was set to.
        self.power = match tool.power {
            Some(p) => Some(p),
            None if tool.jet && self.has_tool && tool.number == self.tool.number => self.power,
            None => None,
        };
        self.has_tool = true;
        self.tool = tool;
    }

    /// The value of a numeric quantity; [`NO_VALUE`] when nothing gave it one.
    pub fn number(&self, q: Quantity) -> f64 {
        let arc = &self.arc;
        let material = |f: fn(&postc_ir::event::Material) -> f64| self.job.material.as_ref().map_or(NO_VALUE, f);
        let home = |f: fn(&postc_ir::event::Point) -> f64| self.job.home.as_ref().map_or(NO_VALUE, f);
        let origin = self.job.origin.as_ref();
        let tool = |v: f64| if self.has_tool { v } else { NO_VALUE };
        match q {
            Quantity::X => self.position(self.axis_value(0)),
            Quantity::Y => self.position(self.axis_value(1)),
            Quantity::Z => self.position(self.pos[2]),
            Quantity::A => self.a_value(),
            Quantity::B => self.rotary[1].unwrap_or(NO_VALUE),
            Quantity::C => self.rotary[2].unwrap_or(NO_VALUE),
            Quantity::I => arc.centre[0] - arc.start[0],
            Quantity::J => arc.centre[1] - arc.start[1],
            Quantity::K => arc.centre[2] - arc.start[2],
            Quantity::IA => arc.centre[0],
            Quantity::JA => arc.centre[1],
            Quantity::KA => arc.centre[2],
            Quantity::ArcStartX => arc.start[0],
            Quantity::ArcStartY => arc.start[1],
            Quantity::ArcMidX => arc.mid[0],
            Quantity::ArcMidY => arc.mid[1],
            Quantity::ArcMidXI => arc.mid[0] - arc.start[0],
            Quantity::ArcMidYI => arc.mid[1] - arc.start[1],
            Quantity::Radius => arc.radius,
            Quantity::Angle => arc.sweep,
            Quantity::Feed => given(self.feed),
            Quantity::FeedPerRev => f64::from(u8::from(self.toolpath.feed_per_rev)),
            Quantity::CutFeed => given(self.tool.cut_feed),
            Quantity::PlungeFeed => given(self.tool.plunge_feed),
            Quantity::InverseTimeFeed => self.inverse_time(),
            // No tool and no speed given: no value (not S0).
            Quantity::SpindleSpeed if !self.has_tool && self.spindle_speed == 0.0 => NO_VALUE,
            Quantity::SpindleSpeed => self.spindle_output(),
            Quantity::Power => self.jet_power(),
            Quantity::JetTool => f64::from(u8::from(self.has_tool && self.tool.jet)),
            Quantity::TurningTool => f64::from(u8::from(self.has_tool && self.tool.turning)),
            Quantity::SpindleCss => f64::from(u8::from(self.spindle_css)),
            Quantity::SpindleCcw => f64::from(u8::from(self.spindle_ccw)),
            Quantity::SpindleMaxRpm => self.spindle_max_rpm.unwrap_or(NO_VALUE),
            Quantity::ArcPlane => match self.arc.plane {
                Plane::Xy => 0.0,
                Plane::Zx => 1.0,
                Plane::Yz => 2.0,
            },
            Quantity::CompSide => match self.comp_side {
                CompSide::Off => 0.0,
                CompSide::Left => 1.0,
                CompSide::Right => 2.0,
            },
            Quantity::CoolantKind => coolant_kind(self.coolant),
            Quantity::Tool => tool(f64::from(self.tool.number)),
            Quantity::PreviousTool => self.previous_tool.map_or(NO_VALUE, f64::from),
            Quantity::ToolDiameter => tool(self.tool.diameter),
            Quantity::DwellTime => self.dwell,
            Quantity::DrillKind => self.drill.as_ref().map_or(NO_VALUE, |c| drill_kind(c.kind)),
            Quantity::DrillClearance => self.drill.as_ref().map_or(NO_VALUE, |c| c.retract_plane),
            Quantity::DrillReference => self.drill.as_ref().map_or(NO_VALUE, |c| c.reference_plane),
            Quantity::DrillSurface => self.drill.as_ref().map_or(NO_VALUE, |c| c.surface.unwrap_or(c.reference_plane)),
            Quantity::DrillBottom => self.drill.as_ref().map_or(NO_VALUE, |c| c.depth),
            Quantity::DrillFeed => self.drill.as_ref().map_or(NO_VALUE, |c| {
                let tool_feed =
                    if self.tool.plunge_feed > 0.0 { self.tool.plunge_feed } else { given(self.tool.cut_feed) };
                c.feed.filter(|f| *f > 0.0).unwrap_or(tool_feed)
            }),
            Quantity::DrillPeck => self.drill.as_ref().and_then(|c| c.peck).filter(|p| *p > 0.0).unwrap_or(NO_VALUE),
            Quantity::DrillDwell => {
                self.drill.as_ref().map_or(NO_VALUE, |c| c.dwell.filter(|d| *d > 0.0).unwrap_or(0.0))
            }
            Quantity::RecordId => self.record_id,
            Quantity::NextRecordMotion => f64::from(u8::from(self.next_record_motion)),
            Quantity::DrillPitch => self.drill.as_ref().and_then(|c| c.pitch).filter(|p| *p > 0.0).unwrap_or(NO_VALUE),
            Quantity::HomeX => self.wrapped(0, home(|h| h.x)),
            Quantity::HomeY => self.wrapped(1, home(|h| h.y)),
            Quantity::HomeZ => home(|h| h.z),
            Quantity::SafeZ => self.job.safe_z.unwrap_or_else(|| home(|h| h.z)),
            Quantity::WrapDiameter => self.job.wrap_diameter.unwrap_or(NO_VALUE),
            Quantity::XLength => material(|m| m.max.x - m.min.x),
            Quantity::YLength => material(|m| m.max.y - m.min.y),
            Quantity::ZLength => material(|m| m.max.z - m.min.z),
            Quantity::XMin => material(|m| m.min.x),
            Quantity::YMin => material(|m| m.min.y),
            Quantity::ZMin => material(|m| m.min.z),
            Quantity::XMax => material(|m| m.max.x),
            Quantity::YMax => material(|m| m.max.y),
            Quantity::ZMax => material(|m| m.max.z),
            Quantity::XOrigin => origin.map_or(NO_VALUE, |o| o.x),
            Quantity::YOrigin => origin.map_or(NO_VALUE, |o| o.y),
            Quantity::CompRegister => match self.comp_register {
                Some(d) => d,
                None => tool(f64::from(self.tool.diameter_offset.unwrap_or(self.tool.number))),
            },
            Quantity::LengthOffset => tool(f64::from(self.tool.length_offset.unwrap_or(self.tool.number))),
            Quantity::BlockNumber => 0.0,
            // Text quantities have no number.
            _ => 0.0,
        }
    }

    /// Jet power: the power set for the tool; 0 for a jet tool no power has
    /// been set for yet (the jet is off: "M4 S0 laser off", as the corpus's
    /// Snapmaker laser post writes it, while leaving the word out would let
    /// the controller's last S, often a spindle speed, drive the jet); no
    /// value while a spindle tool has no power, so a router's cuts carry no
    /// `S0`.
    #[inline]
    fn jet_power(&self) -> f64 {
        match self.power {
            Some(p) => p,
            None if self.has_tool && self.tool.jet => 0.0,
            None => NO_VALUE,
        }
    }

    /// A position coordinate, or no value before the first move of a job
    /// without a home position.
    #[inline]
    fn position(&self, v: f64) -> f64 {
        if self.pos_known { v } else { NO_VALUE }
    }

    /// The value of a text quantity.
    pub fn text(&self, q: Quantity) -> &str {
        match q {
            Quantity::ZOriginText => match self.job.origin.as_ref().map(|o| o.z) {
                Some(ZOrigin::Table) => "Table Surface",
                _ => "Material Surface",
            },
            Quantity::XyOriginText => self.job.origin.as_ref().map_or("", |o| o.xy.as_str()),
            Quantity::ToolName => &self.tool.name,
            Quantity::ToolNotes => &self.tool.notes,
            Quantity::ToolpathName => &self.toolpath.name,
            Quantity::ToolpathNotes => &self.toolpath.notes,
            Quantity::FileName => &self.file_name,
            Quantity::FileDir | Quantity::PathName => &self.file_dir,
            Quantity::FileExtension => &self.file_ext,
            Quantity::FileNotes => &self.job.notes,
            Quantity::ToolsUsed => &self.tools_used,
            Quantity::ToolpathsOutput => &self.toolpaths_output,
            Quantity::Date if self.date.is_empty() => &self.default_date,
            Quantity::Date => &self.date,
            // A date given (`--set date`, the job's) without a time is the start of that day,
            // so that a fixed date never prints the clock's time (README, "Reproducible output").
            Quantity::Time if self.time.is_empty() && !self.date.is_empty() => "00:00",
            Quantity::Time if self.time.is_empty() => &self.default_time,
            Quantity::Time => &self.time,
            Quantity::Product => self.job.product.as_deref().unwrap_or("postc"),
            Quantity::UnitsText => self.output_units.name(),
            Quantity::CommentText => &self.comment,
            Quantity::Revision => &self.revision,
            Quantity::JobOutline => &self.outline,
            Quantity::PostProperties => &self.properties,
            _ => "",
        }
    }

    /// Feed number of inverse-time mode: one over the move's time in minutes.
    fn inverse_time(&self) -> f64 {
        let length = self.move_length.unwrap_or_else(|| {
            let d = [0, 1, 2].map(|i| self.pos[i] - self.move_from[i]);
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        });
        if length > 0.0 { self.feed / length } else { 0.0 }
    }

    /// X or Y, as an angle when that axis is wrapped.
    #[inline]
    fn axis_value(&self, axis: usize) -> f64 {
        self.wrapped(axis, self.pos[axis])
    }

    /// A value of X (`axis` 0) or Y (1), as an angle when that axis is
    /// wrapped: positions and the home position alike.
    #[inline]
    fn wrapped(&self, axis: usize, v: f64) -> f64 {
        match self.wrap {
            Some(w) if (w.axis == WrappedAxis::X) == (axis == 0) => self.wrap_angle(v, w),
            _ => v,
        }
    }

    /// A: the wrapped axis's angle under ROTARY_WRAP, else the A position
    /// the toolpath last gave (no value before it gives one).
    fn a_value(&self) -> f64 {
        match self.wrap {
            Some(w) => self.position(self.wrap_angle(self.pos[if w.axis == WrappedAxis::X { 0 } else { 1 }], w)),
            None => self.rotary[0].unwrap_or(NO_VALUE),
        }
    }

    /// Degrees of rotation that unroll `distance` on the wrap cylinder.
    fn wrap_angle(&self, distance: f64, wrap: RotaryWrap) -> f64 {
        let d = self.job.wrap_diameter.unwrap_or(0.0);
        if d <= 0.0 {
            return distance;
        }
        let angle = distance / (std::f64::consts::PI * d) * 360.0;
        if wrap.reversed { -angle } else { angle }
    }

    /// The spindle speed, through SPINDLE_SPEED_RANGE. A speed of 0 (a jet
    /// tool, an APT tool before its SPINDL) still prints: a spindle that is
    /// not turning is the true state, and leaving `S` out would let an `M3`
    /// run at whatever speed the controller last had.
    fn spindle_output(&self) -> f64 {
        match self.spindle_range {
            Some(r) if r.rpm_max > r.rpm_min => {
                let t = ((self.spindle_speed - r.rpm_min) / (r.rpm_max - r.rpm_min)).clamp(0.0, 1.0);
                (r.out_min + t * (r.out_max - r.out_min)).round()
            }
            _ => self.spindle_speed,
        }
    }
}
