//! The names a Vectric post may use: variable names after `VAR` (with the
//! label each stands for) and global statement names.
//!
//! Variable names come from the variable tables of both seeds (the newer Vectric post guide
//! adds `A_POSITION`); `B_POSITION` and `C_POSITION` complete the rotary
//! axes the IR knows.

/// Every `VAR` name of the seeds, with the label that prints it.
pub const VAR_NAMES: &[(&str, &str)] = &[
    ("FEED_RATE", "F"),
    ("CUT_RATE", "FC"),
    ("PLUNGE_RATE", "FP"),
    ("SPINDLE_SPEED", "S"),
    ("POWER", "P"),
    ("TOOL_NUMBER", "T"),
    ("PREVIOUS_TOOL_NUMBER", "TP"),
    ("LINE_NUMBER", "N"),
    ("TOOL_NAME", "TOOLNAME"),
    ("TOOL_NOTES", "TOOL_NOTES"),
    ("TOOLPATH_NAME", "TOOLPATH_NAME"),
    ("TOOLPATH_FILENAME", "TP_FILENAME"),
    ("TOOLPATH_DIR", "TP_DIR"),
    ("TOOLPATH_EXTENSION", "TP_EXT"),
    ("TOOLPATH_PATHNAME", "PATHNAME"),
    ("X_POSITION", "X"),
    ("Y_POSITION", "Y"),
    ("Z_POSITION", "Z"),
    ("A_POSITION", "A"),
    ("B_POSITION", "B"),
    ("C_POSITION", "C"),
    ("ARC_CENTRE_I_INC_POSITION", "I"),
    ("ARC_CENTRE_J_INC_POSITION", "J"),
    ("ARC_CENTRE_I_ABS_POSITION", "IA"),
    ("ARC_CENTRE_J_ABS_POSITION", "JA"),
    ("ARC_START_X_POSITION", "ArcStartX"),
    ("ARC_START_Y_POSITION", "ArcStartY"),
    ("ARC_MID_X_POSITION", "ArcMidX"),
    ("ARC_MID_Y_POSITION", "ArcMidY"),
    ("ARC_MID_X_INC_POSITION", "ArcMidXI"),
    ("ARC_MID_Y_INC_POSITION", "ArcMidYI"),
    ("ARC_RADIUS", "Radius"),
    ("ARC_ANGLE", "Angle"),
    ("X_HOME_POSITION", "XH"),
    ("Y_HOME_POSITION", "YH"),
    ("Z_HOME_POSITION", "ZH"),
    ("SAFE_Z_HEIGHT", "SAFEZ"),
    ("WRAP_DIAMETER", "WRAP_DIA"),
    ("X_LENGTH", "XLENGTH"),
    ("Y_LENGTH", "YLENGTH"),
    ("Z_LENGTH", "ZLENGTH"),
    ("X_MIN", "XMIN"),
    ("Y_MIN", "YMIN"),
    ("Z_MIN", "ZMIN"),
    ("X_MAX", "XMAX"),
    ("Y_MAX", "YMAX"),
    ("Z_MAX", "ZMAX"),
    ("X_ORIGIN_POS", "X_ORIGIN_POS"),
    ("Y_ORIGIN_POS", "Y_ORIGIN_POS"),
    ("Z_ORIGIN", "Z_ORIGIN"),
    ("XY_ORIGIN", "XY_ORIGIN"),
    ("TOOLS_USED", "TOOLS_USED"),
    ("TOOLPATHS_OUTPUT", "TOOLPATHS_OUTPUT"),
    ("TOOLPATH_NOTES", "TOOLPATH_NOTES"),
    ("FILE_NOTES", "FILE_NOTES"),
    ("TIME", "TIME"),
    ("DATE", "DATE"),
    ("DWELL_TIME", "DWELL"),
    ("PRODUCT", "PRODUCT"),
    ("TOOL_DIAMETER", "TDIA"),
    ("INVERSE_TIME", "FI"),
];

/// The label a `VAR` name (case-insensitive) stands for.
pub fn label_of_var_name(name: &str) -> Option<&'static str> {
    VAR_NAMES.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|&(_, l)| l)
}

/// The `VAR` name whose label is `label` (case-insensitive).
pub fn var_name_of_label(label: &str) -> Option<&'static str> {
    VAR_NAMES.iter().find(|(_, l)| l.eq_ignore_ascii_case(label)).map(|&(n, _)| n)
}

/// Global statements: what may stand before `=` outside any section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlobalName {
    PostName,
    FileExtension,
    Units,
    DirectOutput,
    PrintDirect,
    RapidPlungeToStartZ,
    LaserSupport,
    LineEnding,
    LineNumberStart,
    LineNumberIncrement,
    LineNumberMaximum,
    Substitute,
    TapeSplitting,
    SpindleSpeedRange,
    RotaryWrapX,
    RotaryWrapY,
    InverseTimeMode,
    MinArcRadius,
    MaxArcRadius,
    PostBase,
}

/// Spellings of the global statements (`LINE_NUMBER` is the newer seed's
/// name for `LINE_NUMBER_START`).
const GLOBAL_NAMES: &[(&str, GlobalName)] = &[
    ("POST_NAME", GlobalName::PostName),
    ("FILE_EXTENSION", GlobalName::FileExtension),
    ("UNITS", GlobalName::Units),
    ("DIRECT_OUTPUT", GlobalName::DirectOutput),
    ("PRINT_DIRECT", GlobalName::PrintDirect),
    ("RAPID_PLUNGE_TO_STARTZ", GlobalName::RapidPlungeToStartZ),
    ("LASER_SUPPORT", GlobalName::LaserSupport),
    ("LINE_ENDING", GlobalName::LineEnding),
    ("LINE_NUMBER_START", GlobalName::LineNumberStart),
    ("LINE_NUMBER", GlobalName::LineNumberStart),
    ("LINE_NUMBER_INCREMENT", GlobalName::LineNumberIncrement),
    ("LINE_NUMBER_MAXIMUM", GlobalName::LineNumberMaximum),
    ("SUBSTITUTE", GlobalName::Substitute),
    ("TAPE_SPLITTING", GlobalName::TapeSplitting),
    ("SPINDLE_SPEED_RANGE", GlobalName::SpindleSpeedRange),
    ("ROTARY_WRAP_X", GlobalName::RotaryWrapX),
    ("ROTARY_WRAP_Y", GlobalName::RotaryWrapY),
    ("INVERSE_TIME_MODE", GlobalName::InverseTimeMode),
    ("MIN_ARC_RADIUS", GlobalName::MinArcRadius),
    ("MAX_ARC_RADIUS", GlobalName::MaxArcRadius),
    ("POST_BASE", GlobalName::PostBase),
];

impl GlobalName {
    /// The statement a name (case-insensitive) stands for.
    pub fn from_name(name: &str) -> Option<GlobalName> {
        GLOBAL_NAMES.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|&(_, g)| g)
    }

    /// The usual spelling.
    pub fn name(self) -> &'static str {
        GLOBAL_NAMES.iter().find(|(_, g)| *g == self).map_or("?", |&(n, _)| n)
    }

    /// An example of the statement, for help lines.
    pub fn example(self) -> &'static str {
        match self {
            GlobalName::PostName => "POST_NAME = \"G-Code Arcs (mm) (*.tap)\"",
            GlobalName::FileExtension => "FILE_EXTENSION = \"tap\"",
            GlobalName::Units => "UNITS = \"MM\" (or \"INCHES\")",
            GlobalName::DirectOutput => "DIRECT_OUTPUT = \"Mach|Mach4.Document\"",
            GlobalName::PrintDirect => "PRINT_DIRECT = \"YES\"",
            GlobalName::RapidPlungeToStartZ => "RAPID_PLUNGE_TO_STARTZ = \"YES\"",
            GlobalName::LaserSupport => "LASER_SUPPORT = \"YES\"",
            GlobalName::LineEnding => "LINE_ENDING = \"[13][10]\"",
            GlobalName::LineNumberStart => "LINE_NUMBER_START = 0",
            GlobalName::LineNumberIncrement => "LINE_NUMBER_INCREMENT = 10",
            GlobalName::LineNumberMaximum => "LINE_NUMBER_MAXIMUM = 999999",
            GlobalName::Substitute => "SUBSTITUTE = \"({)}\"",
            GlobalName::TapeSplitting => "TAPE_SPLITTING = 1000 100 \"%s_%d.tap\" 1 \"YES\"",
            GlobalName::SpindleSpeedRange => "SPINDLE_SPEED_RANGE = 1 15 4500 15000",
            GlobalName::RotaryWrapX => "ROTARY_WRAP_X = B",
            GlobalName::RotaryWrapY => "ROTARY_WRAP_Y = A",
            GlobalName::InverseTimeMode => "INVERSE_TIME_MODE = \"YES\"",
            GlobalName::MinArcRadius => "MIN_ARC_RADIUS = 0.01",
            GlobalName::MaxArcRadius => "MAX_ARC_RADIUS = 1000.0",
            GlobalName::PostBase => "POST_BASE = \"GCode_arc_mm.pp\"",
        }
    }
}
