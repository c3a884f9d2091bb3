//! Quantities: the values the runtime knows at any moment of a toolpath
//! (positions, arc geometry, feeds, tool and job data) that a post prints.
//!
//! A Vectric `[X]` or a VcPost `<X>` register reads a quantity; each has a
//! [`Dimension`] that says how it converts between the toolpath's units and
//! the post's units.

use serde::{Deserialize, Serialize};

/// How a quantity converts between units.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Dimension {
    /// A length: converted between mm and inch.
    Length,
    /// A feed rate (length per minute): converted like a length.
    Feed,
    /// Not converted: angles, speeds, counts, times, power.
    Plain,
    /// Text.
    Text,
}

macro_rules! quantities {
    ($( $(#[$doc:meta])* $name:ident = $label:literal, $dim:ident; )*) => {
        /// A value the runtime provides to posts.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
        pub enum Quantity {
            $( $(#[$doc])* $name, )*
        }

        impl Quantity {
            /// Every quantity, in declaration order.
            pub const ALL: &'static [Quantity] = &[$(Quantity::$name,)*];

            /// The Vectric label that prints this quantity (`X` for `[X]`).
            #[inline]
            pub fn label(self) -> &'static str {
                match self { $(Quantity::$name => $label,)* }
            }

            /// How the quantity converts between units.
            #[inline]
            pub fn dimension(self) -> Dimension {
                match self { $(Quantity::$name => Dimension::$dim,)* }
            }
        }
    };
}

quantities! {
    /// Block (line) number; advances each time a block prints it.
    BlockNumber = "N", Plain;
    /// Current X position (end of the current move).
    X = "X", Length;
    Y = "Y", Length;
    Z = "Z", Length;
    /// Rotary A position in degrees (the wrapped axis under ROTARY_WRAP).
    A = "A", Plain;
    B = "B", Plain;
    C = "C", Plain;
    /// Arc centre relative to the arc's start.
    I = "I", Length;
    J = "J", Length;
    K = "K", Length;
    /// Arc centre, absolute.
    IA = "IA", Length;
    JA = "JA", Length;
    KA = "KA", Length;
    /// Arc start point.
    ArcStartX = "ArcStartX", Length;
    ArcStartY = "ArcStartY", Length;
    /// Arc mid point, absolute.
    ArcMidX = "ArcMidX", Length;
    ArcMidY = "ArcMidY", Length;
    /// Arc mid point relative to the arc's start.
    ArcMidXI = "ArcMidXI", Length;
    ArcMidYI = "ArcMidYI", Length;
    /// Arc radius.
    Radius = "Radius", Length;
    /// Arc sweep in radians, positive counter-clockwise.
    Angle = "Angle", Plain;
    /// Current feed rate.
    Feed = "F", Feed;
    /// 1 while the toolpath's feeds are per spindle revolution
    /// ([`crate::event::ToolpathStart::feed_per_rev`]), else 0.
    FeedPerRev = "FEED_PER_REV", Plain;
    /// The tool's cut feed rate.
    CutFeed = "FC", Feed;
    /// The tool's plunge feed rate.
    PlungeFeed = "FP", Feed;
    /// Inverse-time feed number (1 / minutes for the move).
    InverseTimeFeed = "FI", Plain;
    /// Spindle speed in rpm (or its SPINDLE_SPEED_RANGE step).
    SpindleSpeed = "S", Plain;
    /// Jet power.
    Power = "P", Plain;
    /// 1 when the current tool is a jet tool (laser, plasma, waterjet), else 0
    /// (postc's; Fusion posts read it as the section's type).
    JetTool = "JET_TOOL", Plain;
    /// 1 when the current tool is a lathe's turning tool
    /// ([`crate::event::Tool::turning`]), else 0 (postc's; Fusion posts
    /// read it as the section's type).
    TurningTool = "TURNING_TOOL", Plain;
    /// 1 while the spindle runs at constant surface speed (the last
    /// SpindleOn said `css`: `S` is then metres or feet a minute), else 0.
    SpindleCss = "SPINDLE_CSS", Plain;
    /// 1 while the spindle turns counter-clockwise (the last SpindleOn
    /// said `ccw`), else 0; a tool is loaded turning clockwise.
    SpindleCcw = "SPINDLE_CCW", Plain;
    /// The highest spindle speed (rpm) under constant surface speed; no
    /// value when the SpindleOn gave none.
    SpindleMaxRpm = "SPINDLE_MAX_RPM", Plain;
    /// The cutter compensation side of the last CutterComp event: 0 off,
    /// 1 left, 2 right.
    CompSide = "COMP_SIDE", Plain;
    /// The coolant of the last Coolant event: 0 off, 1 flood, 2 mist,
    /// 3 through the tool, 4 air.
    CoolantKind = "COOLANT_KIND", Plain;
    /// The plane of the arc being printed: 0 XY, 1 ZX, 2 YZ.
    ArcPlane = "ARC_PLANE", Plain;
    /// The drilling cycle being printed (between DrillCycle and DrillEnd;
    /// [`crate::event::DrillCycle`]): its kind, 0 drill, 1 deep (full
    /// retract pecks), 2 chip breaking, 3 tap, 4 bore, 5 ream.
    DrillKind = "DRILL_KIND", Plain;
    /// The cycle's clearance plane, where the tool goes between holes.
    DrillClearance = "DRILL_CLEARANCE", Length;
    /// The cycle's R plane, where feeding starts.
    DrillReference = "DRILL_R", Length;
    /// The top of the cycle's holes (the R plane when the cycle names none).
    DrillSurface = "DRILL_SURFACE", Length;
    /// The bottom of the cycle's holes.
    DrillBottom = "DRILL_BOTTOM", Length;
    /// The cycle's feed: its own, else the tool's plunge feed, else its cut feed.
    DrillFeed = "DRILL_FEED", Feed;
    /// The cycle's peck depth; no value when it does not peck.
    DrillPeck = "DRILL_PECK", Length;
    /// The cycle's dwell at the bottom in seconds; 0 when it has none.
    DrillDwell = "DRILL_DWELL", Plain;
    /// The cycle's thread pitch (tapping); no value when it has none.
    DrillPitch = "DRILL_PITCH", Length;
    /// For posts that read ahead ([`crate::post::OutputOptions::reads_ahead`]):
    /// the index of the event being posted in the toolpath (FeedRate
    /// records not counted), from 0.
    RecordId = "RECORD_ID", Plain;
    /// For posts that read ahead: 1 when the event after the one being
    /// posted is a move (Rapid, Feed, Arc), else 0.
    NextRecordMotion = "NEXT_RECORD_MOTION", Plain;
    /// Tool number.
    Tool = "T", Plain;
    /// Previous tool number.
    PreviousTool = "TP", Plain;
    /// Tool diameter.
    ToolDiameter = "TDIA", Length;
    /// Dwell time in seconds.
    DwellTime = "DWELL", Plain;
    /// Home position.
    HomeX = "XH", Length;
    HomeY = "YH", Length;
    HomeZ = "ZH", Length;
    /// Safe Z height.
    SafeZ = "SAFEZ", Length;
    /// Diameter of the cylinder a wrapped axis goes around.
    WrapDiameter = "WRAP_DIA", Length;
    /// Material block.
    XLength = "XLENGTH", Length;
    YLength = "YLENGTH", Length;
    ZLength = "ZLENGTH", Length;
    XMin = "XMIN", Length;
    YMin = "YMIN", Length;
    ZMin = "ZMIN", Length;
    XMax = "XMAX", Length;
    YMax = "YMAX", Length;
    ZMax = "ZMAX", Length;
    /// Origin position.
    XOrigin = "X_ORIGIN_POS", Length;
    YOrigin = "Y_ORIGIN_POS", Length;
    /// Cutter compensation register (D word).
    CompRegister = "D", Plain;
    /// Tool length offset register (H word).
    LengthOffset = "H", Plain;
    /// Text: where Z zero is ("Material Surface" or "Table Surface").
    ZOriginText = "Z_ORIGIN", Text;
    /// Text: the XY origin ("Bottom Left", ...).
    XyOriginText = "XY_ORIGIN", Text;
    ToolName = "TOOLNAME", Text;
    ToolNotes = "TOOL_NOTES", Text;
    ToolpathName = "TOOLPATH_NAME", Text;
    ToolpathNotes = "TOOLPATH_NOTES", Text;
    /// Output file name (without folder).
    FileName = "TP_FILENAME", Text;
    /// Output folder.
    FileDir = "TP_DIR", Text;
    /// Output extension.
    FileExtension = "TP_EXT", Text;
    /// Output folder path name.
    PathName = "PATHNAME", Text;
    ToolsUsed = "TOOLS_USED", Text;
    ToolpathsOutput = "TOOLPATHS_OUTPUT", Text;
    FileNotes = "FILE_NOTES", Text;
    Date = "DATE", Text;
    Time = "TIME", Text;
    Product = "PRODUCT", Text;
    /// The post's output units ("MM" or "INCHES").
    UnitsText = "UNITS", Text;
    /// Text of the current comment or insert event.
    CommentText = "COMMENT", Text;
    /// Text: the post's revision hash ([`crate::post::PostInfo::revision`]).
    Revision = "REVISION", Text;
    /// Text: the job's outline as JSON, in the post's units, for posts
    /// that read ahead ([`crate::post::OutputOptions::reads_ahead`]); an
    /// empty text when the toolpath source cannot read ahead.
    JobOutline = "JOB_OUTLINE", Text;
    /// Text: the post properties the user set for this run (`--set
    /// property.NAME=VALUE`), as a JSON object of texts by name; `{}` when
    /// none was set. A Fusion post's host applies them before `onOpen`.
    PostProperties = "POST_PROPERTIES", Text;
}

impl Quantity {
    /// The quantity a Vectric label (case-insensitive) stands for.
    pub fn from_label(label: &str) -> Option<Quantity> {
        Quantity::ALL.iter().copied().find(|q| q.label().eq_ignore_ascii_case(label))
    }

    /// Whether the quantity is text rather than a number.
    #[inline]
    pub fn is_text(self) -> bool {
        self.dimension() == Dimension::Text
    }
}
