//! Toolpath events: the one vocabulary every toolpath reader produces and
//! every post consumes.
//!
//! A toolpath is a stream of [`Event`]s. Positions are absolute, in the units
//! the [`Job`] names (millimetres unless it says otherwise); feeds are in
//! those units per minute (per spindle revolution in a toolpath whose
//! [`ToolpathStart::feed_per_rev`] is set), spindle speeds in revolutions per minute, dwell
//! times in seconds. The same serde types are read from RON (one event per
//! line) and from JSON Lines; `docs/toolpath-format.md` documents every field
//! with a complete example.
//!
//! The stream is expected in this order: one `Job`, then for each toolpath a
//! `Tool` (when the tool changes or for the first toolpath), a
//! `ToolpathStart`, its moves and other events, and an optional
//! `ToolpathEnd`; finally `End` (a stream without it ends the program too,
//! with a warning that it may be cut short). Readers of foreign formats
//! (APT CL) produce the same order. The ranges a reader accepts are in
//! [`crate::limits`].

use serde::{Deserialize, Serialize};

use crate::units::Units;

/// One toolpath event.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Event {
    /// Job data, once, before anything else.
    Job(Box<Job>),
    /// The tool for the toolpaths that follow.
    Tool(Tool),
    /// A toolpath begins.
    ToolpathStart(ToolpathStart),
    /// A toolpath ends.
    ToolpathEnd,
    /// A move at rapid traverse.
    Rapid(Move),
    /// A straight move at feed.
    Feed(FeedMove),
    /// A circular (or helical) move at feed.
    Arc(ArcMove),
    /// The axes stop for a while.
    Dwell(Dwell),
    /// The spindle starts (or changes speed).
    SpindleOn(Spindle),
    /// The spindle stops.
    SpindleOff,
    /// A jet tool (laser, plasma, waterjet) switches on.
    JetOn,
    /// A jet tool switches off.
    JetOff,
    /// The jet power changes (percent, or the post's power scale).
    Power(Power),
    /// Coolant changes.
    Coolant(CoolantChange),
    /// Cutter radius compensation changes.
    CutterComp(CutterComp),
    /// A canned drilling cycle starts; `DrillPoint`s follow, then `DrillEnd`.
    DrillCycle(DrillCycle),
    /// One hole of the current drilling cycle.
    DrillPoint(DrillPoint),
    /// The current drilling cycle ends.
    DrillEnd,
    /// An operator comment (printed the way the post prints comments).
    Comment(Text),
    /// Text a post writes verbatim as a block.
    Insert(Text),
    /// A post-processor command with no dedicated event (APT words such as
    /// `AUXFUN/8`, `OPSTOP`, `ORIGIN/54`), passed through for posts that
    /// handle it; posts that do not know the word ignore it.
    Command(Command),
    /// The program ends (the footer follows). The end of the stream ends
    /// the program too, but a reader warns that a stream without `End`
    /// may be cut short.
    End,
    /// A feed rate as the toolpath wrote it (an APT `FEDRAT` record). Moves
    /// carry their feed already; posts never see this event.
    FeedRate(FeedRate),
}

impl Event {
    /// A move of the tool: Rapid, Feed or Arc.
    pub fn is_move(&self) -> bool {
        matches!(self, Event::Rapid(_) | Event::Feed(_) | Event::Arc(_))
    }

    /// The event's name as written in the native formats (`Rapid`, `Feed`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            Event::Job(_) => "Job",
            Event::Tool(_) => "Tool",
            Event::ToolpathStart(_) => "ToolpathStart",
            Event::ToolpathEnd => "ToolpathEnd",
            Event::Rapid(_) => "Rapid",
            Event::Feed(_) => "Feed",
            Event::Arc(_) => "Arc",
            Event::Dwell(_) => "Dwell",
            Event::SpindleOn(_) => "SpindleOn",
            Event::SpindleOff => "SpindleOff",
            Event::JetOn => "JetOn",
            Event::JetOff => "JetOff",
            Event::Power(_) => "Power",
            Event::Coolant(_) => "Coolant",
            Event::CutterComp(_) => "CutterComp",
            Event::DrillCycle(_) => "DrillCycle",
            Event::DrillPoint(_) => "DrillPoint",
            Event::DrillEnd => "DrillEnd",
            Event::Comment(_) => "Comment",
            Event::Insert(_) => "Insert",
            Event::Command(_) => "Command",
            Event::End => "End",
            Event::FeedRate(_) => "FeedRate",
        }
    }
}

/// A point in space.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// Job data: what the CAM system knows about the whole program.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct Job {
    /// Units of every length and feed in the stream.
    pub units: Units,
    /// The material block.
    pub material: Option<Material>,
    /// Where the job's origin sits.
    pub origin: Option<Origin>,
    /// The home position.
    pub home: Option<Point>,
    /// Safe Z (rapid clearance height).
    pub safe_z: Option<f64>,
    /// Diameter of the cylinder a rotary job is wrapped around.
    pub wrap_diameter: Option<f64>,
    /// The output file: name without extension, folder, extension.
    pub file: FileInfo,
    /// File notes.
    pub notes: String,
    /// Date the program is made, as printed (`[DATE]`); the current date when absent.
    pub date: Option<String>,
    /// Time the program is made, as printed (`[TIME]`); the current time when absent.
    pub time: Option<String>,
    /// Tools used, in order of use, as printed by `[TOOLS_USED]`.
    pub tools: Vec<String>,
    /// Toolpaths output, in order, as printed by `[TOOLPATHS_OUTPUT]`.
    pub toolpaths: Vec<String>,
    /// The CAM product and version (`[PRODUCT]`).
    pub product: Option<String>,
    /// Part name or program title (APT `PARTNO`).
    pub part: Option<String>,
}

/// The material block.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    pub min: Point,
    pub max: Point,
}

/// Where the origin of the job sits on the material.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct Origin {
    /// X and Y of the origin.
    pub x: f64,
    pub y: f64,
    /// Where Z zero is: the machine table or the material surface.
    pub z: ZOrigin,
    /// Which corner (or the centre) of the material the XY origin is, as
    /// printed: "Bottom Left", "Centre", ...
    pub xy: String,
}

/// Where Z zero is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ZOrigin {
    #[default]
    MaterialSurface,
    Table,
}

/// The output file the job is posted to.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct FileInfo {
    /// File name without folder and extension.
    pub name: String,
    /// Folder.
    pub dir: String,
    /// Extension without the dot.
    pub extension: String,
}

/// A cutting tool.
#[derive(Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    pub number: u32,
    pub name: String,
    pub notes: String,
    pub diameter: f64,
    /// Spindle speed in rpm.
    pub spindle_speed: f64,
    /// Feed for cutting moves.
    pub cut_feed: f64,
    /// Feed for plunge moves.
    pub plunge_feed: f64,
    /// A jet tool (laser, plasma, waterjet): it has no spindle.
    pub jet: bool,
    /// Jet power, when `jet`.
    pub power: Option<f64>,
    /// A lathe's turning tool (an insert in a holder: the part turns on
    /// the spindle, the tool holds still). Its toolpaths are turning
    /// toolpaths: X is the radius, Z runs along the spindle, Y is zero and
    /// arcs lie in the ZX plane; `diameter` is twice the insert's nose
    /// radius. Left out when false.
    #[serde(skip_serializing_if = "is_default")]
    pub turning: bool,
    /// Length (height) offset register, when it is not the tool number.
    pub length_offset: Option<u32>,
    /// Diameter offset register, when it is not the tool number.
    pub diameter_offset: Option<u32>,
    /// The tool load (APT `LOADTL`, `LOAD/TOOL`) this tool came from, with
    /// its offset registers as written; absent for a tool described only
    /// (APT `CUTTER`, `TLDATA`) and in native toolpaths that do not say.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load: Option<Box<ToolLoad>>,
}

/// Printed as it is written: `turning` only when the tool is a turning
/// tool, so a milling tool prints as it did before the field.
impl std::fmt::Debug for Tool {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut d = f.debug_struct("Tool");
        d.field("number", &self.number)
            .field("name", &self.name)
            .field("notes", &self.notes)
            .field("diameter", &self.diameter)
            .field("spindle_speed", &self.spindle_speed)
            .field("cut_feed", &self.cut_feed)
            .field("plunge_feed", &self.plunge_feed)
            .field("jet", &self.jet)
            .field("power", &self.power);
        if self.turning {
            d.field("turning", &self.turning);
        }
        d.field("length_offset", &self.length_offset)
            .field("diameter_offset", &self.diameter_offset)
            .field("load", &self.load)
            .finish()
    }
}

/// A tool load as written: the offset registers it names, equal to the
/// tool number or not.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct ToolLoad {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_offset: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diameter_offset: Option<u32>,
}

/// A toolpath begins.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct ToolpathStart {
    pub name: String,
    pub notes: String,
    /// The toolpath's feeds are per spindle revolution (mm/rev or in/rev,
    /// G95/G99 on a lathe) instead of per minute.
    #[serde(skip_serializing_if = "is_default")]
    pub feed_per_rev: bool,
}

/// A rapid move to an absolute position.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Move {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Rotary axis positions in degrees, for machines that have them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub c: Option<f64>,
    /// Tool axis unit vector (i, j, k) of a multi-axis move.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_axis: Option<[f64; 3]>,
}

/// Why a feed move is made; posts print plunges and retracts differently.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Intent {
    /// Cutting (the default).
    #[default]
    Cut,
    /// Plunging down into the material (plunge feed).
    Plunge,
    /// Retracting out of the material.
    Retract,
    /// Entering the cut.
    LeadIn,
    /// Leaving the cut.
    LeadOut,
}

/// A straight move at feed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FeedMove {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Why the move is made; a move straight down is a plunge when this is
    /// left out.
    #[serde(default, skip_serializing_if = "is_default")]
    pub intent: Intent,
    /// Feed rate; when absent the tool's cut feed (or plunge feed for
    /// plunges) applies.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub feed: Option<f64>,
    /// Rotary axis positions in degrees, for machines that have them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub c: Option<f64>,
    /// Tool axis unit vector (i, j, k) of a multi-axis move.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_axis: Option<[f64; 3]>,
}

/// Turning direction of an arc, looking down the plane's normal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ArcDir {
    /// Clockwise (G2).
    #[default]
    Cw,
    /// Counter-clockwise (G3).
    Ccw,
}

/// The plane an arc lies in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Plane {
    /// XY plane (G17); helical arcs move in Z.
    #[default]
    Xy,
    /// ZX plane (G18).
    Zx,
    /// YZ plane (G19).
    Yz,
}

/// A circular move: from the current position to the end point, around an
/// absolute centre. An arc whose end equals its start is a full circle. When
/// the end differs from the start along the plane's normal the arc is
/// helical.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcMove {
    pub dir: ArcDir,
    /// End point.
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Absolute centre; the coordinate along the plane's normal is ignored.
    pub cx: f64,
    pub cy: f64,
    #[serde(default)]
    pub cz: f64,
    #[serde(default, skip_serializing_if = "is_default")]
    pub plane: Plane,
    /// `Plunge` for a helical ramp down into the material.
    #[serde(default, skip_serializing_if = "is_default")]
    pub intent: Intent,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub feed: Option<f64>,
}

/// A dwell.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Dwell {
    /// Seconds, or spindle revolutions when `revolutions` is set.
    pub seconds: f64,
    #[serde(default, skip_serializing_if = "is_default")]
    pub revolutions: bool,
}

/// Spindle start.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct Spindle {
    /// Speed in rpm (or surface speed with `css`); the tool's speed when absent.
    pub speed: Option<f64>,
    /// Counter-clockwise (M4) instead of clockwise (M3).
    pub ccw: bool,
    /// Constant surface speed (lathes): `speed` is m/min or ft/min.
    pub css: bool,
    /// Maximum rpm under constant surface speed.
    pub max_rpm: Option<f64>,
}

/// Jet power.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Power {
    pub value: f64,
}

/// A coolant change: the coolant, and when it takes effect if the toolpath
/// says (APT `COOLNT/FLOOD,NOW`). Without a placement it is written as the
/// bare coolant, `Coolant(Flood)` (`{"Coolant":"Flood"}`), as it always was;
/// with one, `Coolant(coolant: Flood, at: Now)`
/// (`{"Coolant":{"coolant":"Flood","at":"Now"}}`).
#[derive(Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(from = "CoolantRepr", into = "CoolantRepr")]
pub struct CoolantChange {
    pub coolant: Coolant,
    pub at: Option<CoolantAt>,
}

impl From<Coolant> for CoolantChange {
    fn from(coolant: Coolant) -> CoolantChange {
        CoolantChange { coolant, at: None }
    }
}

/// Printed as it is written: the bare coolant when there is no placement.
impl std::fmt::Debug for CoolantChange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.at {
            None => std::fmt::Debug::fmt(&self.coolant, f),
            Some(at) => f.debug_struct("CoolantChange").field("coolant", &self.coolant).field("at", &at).finish(),
        }
    }
}

/// The two written forms of a [`CoolantChange`].
#[derive(Clone, Copy, Serialize, Deserialize)]
#[serde(untagged)]
enum CoolantRepr {
    Bare(Coolant),
    Placed {
        coolant: Coolant,
        #[serde(default)]
        at: Option<CoolantAt>,
    },
}

impl From<CoolantRepr> for CoolantChange {
    fn from(r: CoolantRepr) -> CoolantChange {
        match r {
            CoolantRepr::Bare(coolant) => CoolantChange { coolant, at: None },
            CoolantRepr::Placed { coolant, at } => CoolantChange { coolant, at },
        }
    }
}

impl From<CoolantChange> for CoolantRepr {
    fn from(c: CoolantChange) -> CoolantRepr {
        match c.at {
            None => CoolantRepr::Bare(c.coolant),
            Some(at) => CoolantRepr::Placed { coolant: c.coolant, at: Some(at) },
        }
    }
}

/// When a coolant change takes effect.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CoolantAt {
    /// At once, where the tool is (`NOW`).
    Now,
    /// With the next motion (`NEXT`).
    Next,
}

/// Coolant state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Coolant {
    #[default]
    Off,
    Flood,
    Mist,
    Through,
    Air,
}

/// Cutter radius compensation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct CutterComp {
    pub side: CompSide,
    /// Offset register (D word on mills).
    pub register: Option<u32>,
}

/// Side of cutter compensation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum CompSide {
    #[default]
    Off,
    Left,
    Right,
}

/// Kind of canned drilling cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum DrillKind {
    /// Straight drilling (G81), with bottom dwell (G82) when `dwell` is set.
    #[default]
    Drill,
    /// Full-retract peck drilling (G83).
    Deep,
    /// Chip-breaking peck drilling (G73).
    ChipBreak,
    /// Tapping (G84).
    Tap,
    /// Boring, feed out (G85).
    Bore,
    /// Reaming (G85 on most controllers).
    Ream,
}

/// A canned drilling cycle; every height is absolute.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[serde(deny_unknown_fields)]
pub struct DrillCycle {
    pub kind: DrillKind,
    /// A name the CAM system gave the cycle (CIMCO drilling operation names).
    pub name: String,
    /// Clearance plane the drill returns to between holes.
    pub retract_plane: f64,
    /// Plane where feeding starts (R plane).
    pub reference_plane: f64,
    /// Top of the holes: the material surface the cycle starts from (APT
    /// CYCLE's clearance is measured from it; Heidenhain Q203, Siemens RFP,
    /// CIMCO `referencePlane`). When absent the R plane stands for it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<f64>,
    /// Bottom of the hole.
    pub depth: f64,
    /// Feed rate; the tool's plunge feed when absent.
    pub feed: Option<f64>,
    /// Peck depth for pecking cycles.
    pub peck: Option<f64>,
    /// Bottom dwell in seconds.
    pub dwell: Option<f64>,
    /// Thread pitch for tapping.
    pub pitch: Option<f64>,
}

/// One hole of a drilling cycle: its position at the top of the hole.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DrillPoint {
    pub x: f64,
    pub y: f64,
    #[serde(default)]
    pub z: f64,
}

/// Free text.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Text {
    pub text: String,
}

/// A post-processor word and its arguments, APT style (`AUXFUN/8,NEXT` is
/// `word: "AUXFUN", args: [Number(8), Word("NEXT")]`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Command {
    pub word: String,
    #[serde(default)]
    pub args: Vec<Arg>,
}

/// One argument of a [`Command`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Arg {
    Number(f64),
    Word(String),
    Text(String),
}

/// A feed rate as the toolpath wrote it: an APT `FEDRAT` record's value
/// and the unit it named. Moves already carry their feed (per minute in
/// the job's units, or per revolution in a `feed_per_rev` toolpath); this
/// event keeps what the record said for readers that need it (the APT
/// post processor, `postp`, tells the machine per-revolution feeds as
/// written). Posts ignore it: the runtime never hands it to a handler.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FeedRate {
    pub value: f64,
    /// The unit the record named; none when it named none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<FeedUnit>,
}

/// The unit of a written feed rate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FeedUnit {
    /// Per minute, in the job's length unit (`PERMIN`, `UPM`).
    PerMinute,
    /// Per spindle revolution, in the job's length unit (`PERREV`, `UPR`).
    PerRev,
    /// Millimetres per minute (`MMPM`).
    Mmpm,
    /// Inches per minute (`IPM`).
    Ipm,
    /// Millimetres per revolution (`MMPR`).
    Mmpr,
    /// Inches per revolution (`IPR`).
    Ipr,
}

impl FeedUnit {
    /// Whether the feed is per spindle revolution.
    pub fn per_rev(self) -> bool {
        matches!(self, FeedUnit::PerRev | FeedUnit::Mmpr | FeedUnit::Ipr)
    }

    /// The length unit it names, if any.
    pub fn units(self) -> Option<Units> {
        match self {
            FeedUnit::Mmpm | FeedUnit::Mmpr => Some(Units::Mm),
            FeedUnit::Ipm | FeedUnit::Ipr => Some(Units::Inch),
            FeedUnit::PerMinute | FeedUnit::PerRev => None,
        }
    }
}

fn is_default<T: Default + PartialEq>(value: &T) -> bool {
    *value == T::default()
}

/// A source of toolpath events: the native stream reader, the APT CL reader,
/// the synthetic generator of `postc toolpath gen` and `postc bench`.
pub trait EventSource {
    /// The next event and the span of the record it came from; `None` at the
    /// end of the stream. Problems go into `diagnostics`; after an error a
    /// source resynchronises at the next record, so a checker sees them all.
    fn next_event(
        &mut self,
        diagnostics: &mut Vec<crate::diagnostic::Diagnostic>,
    ) -> Option<(Event, crate::diagnostic::Span)>;

    /// The whole job's outline, read ahead of the stream (a file read once
    /// more), for posts that ask for later toolpaths before they come;
    /// `None` when the source cannot read ahead (a stream that is read
    /// once).
    fn outline(&mut self) -> Option<crate::outline::JobOutline> {
        None
    }
}

impl<S: EventSource + ?Sized> EventSource for Box<S> {
    fn next_event(
        &mut self,
        diagnostics: &mut Vec<crate::diagnostic::Diagnostic>,
    ) -> Option<(Event, crate::diagnostic::Span)> {
        (**self).next_event(diagnostics)
    }

    fn outline(&mut self) -> Option<crate::outline::JobOutline> {
        (**self).outline()
    }
}

/// Events already in memory (tests, converters).
pub struct VecSource {
    events: std::vec::IntoIter<Event>,
    file: crate::diagnostic::FileId,
}

impl VecSource {
    pub fn new(events: Vec<Event>, file: crate::diagnostic::FileId) -> VecSource {
        VecSource { events: events.into_iter(), file }
    }
}

impl EventSource for VecSource {
    fn next_event(&mut self, _: &mut Vec<crate::diagnostic::Diagnostic>) -> Option<(Event, crate::diagnostic::Span)> {
        self.events.next().map(|e| (e, crate::diagnostic::Span::new(self.file, 0, 0)))
    }
}
