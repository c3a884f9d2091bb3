//! The names the runtime calls and sets: APT major words and composites
//! routines (a Sub with one of these names also becomes a handler), the
//! variables the composites application and the milling records set before
//! calling a Sub, and the composites functions the runtime provides.

/// APT major words a milling post may have a Sub for (the APT post-processor guide's list, the
/// motion words and the usual CL words).
pub const APT_WORDS: &[&str] = &[
    "AIR", "ARC", "AUXFUN", "CALSUB", "CIRCLE", "CLEARP", "CLRSRF", "COOLNT", "CUTCOM", "CUTTER", "CYCLE", "DELAY",
    "DELETE", "DISPLY", "DWELL", "END", "FEDRAT", "FINI", "FROM", "GODLTA", "GOHOME", "GOTO", "INDIRV", "INSERT",
    "INTOL", "LETTER", "LINTOL", "LOADTL", "MACHIN", "MODE", "MULTAX", "OPSKIP", "OPSTOP", "ORIGIN", "OUTTOL",
    "PARTNO", "PITCH", "PLANE", "PPRINT", "PREFUN", "RAPID", "RESET", "RETRCT", "REWIND", "ROTABL", "ROTATE", "ROTHED",
    "SELCTL", "SELECT", "SEQNO", "SET", "SPINDL", "STOP", "THREAD", "TLAXIS", "TMARK", "TOOLNO", "TOOLPATH", "TRANS",
    "TURRET", "UNITS",
];

/// Routines the composites application calls, material laying and probing.
pub const COMPOSITES_ROUTINES: &[&str] = &[
    "Modals",
    "Extent",
    "Length",
    "CamHeader",
    "CamPoint",
    "CamTrailer",
    "PlyHeader",
    "LinkHeader",
    "PulloutHeader",
    "PulloutTrailer",
    "MoveTo",
    "OffForm",
    "OnForm",
    "TraverseHeader",
    "TraverseTo",
    "TraverseTrailer",
    "LinkTrailer",
    "PacketHeader",
    "RestartHeader",
    "RestartBuffer",
    "RestartTrailer",
    "GoTo",
    "PacketTrailer",
    "PlyTrailer",
    "ProgramHeader",
    "SetAngle",
    "ProgramTrailer",
];

/// The handler key of a Sub: its name in upper case when it is an APT
/// major word or a composites routine, otherwise none.
pub fn handler_word(name: &str) -> Option<String> {
    let listed = APT_WORDS.iter().any(|w| w.eq_ignore_ascii_case(name))
        || COMPOSITES_ROUTINES.iter().any(|w| w.eq_ignore_ascii_case(name));
    listed.then(|| name.to_uppercase())
}

/// Whether a variable holds text or a number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarType {
    Number,
    Text,
}

/// Variables the composites application sets (Vericut's post-processor notes' tables; `X`, `Y`,
/// `Z`, `TowArea`, `TowLen`, `TowNum` are registers there) and
/// `NeedThickness`, the flag a post sets to ask for `SumThick`.
pub const COMPOSITES_VARIABLES: &[(&str, VarType)] = {
    use VarType::{Number as N, Text as T};
    &[
        ("AccDecDist", N),
        ("AddAdjustMax", N),
        ("AddAdjustMin", N),
        ("AngleSpacing", N),
        ("AngleTol", N),
        ("Compression", N),
        ("CourseSpread", N),
        ("CutAdjustMax", N),
        ("CutAdjustMin", N),
        ("Directions", N),
        ("EgressLength", N),
        ("FileName", T),
        ("FOff", N),
        ("FOn", N),
        ("Header", T),
        ("HeadReverse", N),
        ("IngressLength", N),
        ("LandOnShelf", N),
        ("LeadInLen", N),
        ("LimitedEntry", N),
        ("MandrelRPM", N),
        ("MatDense", N),
        ("MatThick", N),
        ("MaxGrader", N),
        ("MaxTraverse", N),
        ("MinGapLen", N),
        ("MinGrader", N),
        ("MinSteering", N),
        ("MinTowLen", N),
        ("Natural", N),
        ("NominalPress", N),
        ("Numbering", N),
        ("OffSpacing", N),
        ("OnSpacing", N),
        ("Part", T),
        ("PlyAngle", N),
        ("PlyIdent", T),
        ("PlyNumber", N),
        ("Post", T),
        ("Product", T),
        ("RetractDist", N),
        ("RollerAction", N),
        ("RollerClear", N),
        ("RollOffset", N),
        ("Rotisserie", N),
        ("RunOutLen", N),
        ("ScrewHand", N),
        ("SeqIdent", T),
        ("SeqNumber", N),
        ("ShelfAngle", N),
        ("ShelfInset", N),
        ("SpinAxis", N),
        ("SpiralAngle", N),
        ("SpliceLen", N),
        ("SpliceSpace", N),
        ("Stamp", T),
        ("StartX", N),
        ("StartY", N),
        ("StartZ", N),
        ("Thumb", T),
        ("TowCount", N),
        ("TowEdgeLap", N),
        ("TowReduction", N),
        ("TowTowLap", N),
        ("TowWidth", N),
        ("TraverseSpeed", N),
        ("UnitPerMm", N),
        ("User", T),
        ("Version", T),
        ("VirtualAxis", N),
        ("AMax", N),
        ("AMin", N),
        ("RMax", N),
        ("Rotation", N),
        ("XMax", N),
        ("XMin", N),
        ("YMax", N),
        ("YMin", N),
        ("ZMax", N),
        ("ZMin", N),
        ("TowArea", N),
        ("TowLen", N),
        ("TowNum", N),
        ("LinkType", N),
        ("DTwist", N),
        ("DX", N),
        ("DY", N),
        ("DZ", N),
        ("ETwist", N),
        ("EX", N),
        ("EY", N),
        ("EZ", N),
        ("ToLeadIn", N),
        ("VirtDX", N),
        ("VirtDY", N),
        ("VirtDZ", N),
        ("AddCutA", T),
        ("AddCutB", T),
        ("AddCutI", N),
        ("AddCutJ", N),
        ("LParam", N),
        ("SumThick", N),
        ("Cached", N),
        ("ToLastCut", N),
        ("ToNextAdd", N),
        ("ToNextCut", N),
        ("ToRunOut", N),
        ("TowsInPacket", N),
        ("OptNumber1", N),
        ("OptNumber2", N),
        ("OptNumber3", N),
        ("OptNumber4", N),
        ("OptString1", T),
        ("OptString2", T),
        ("OptSwitch1", N),
        ("OptSwitch2", N),
        ("NeedThickness", N),
    ]
};

/// Variables the milling runtime sets from an APT record besides the
/// single-letter registers: the record's major word, its first minor word
/// (`CLW`, `FLOOD`, `LEFT`, `OFF`, ...), its text (`PARTNO`, `PPRINT`,
/// `INSERT`), whether lengths are millimetres, the arc's plane (17, 18, 19) and absolute centre, and the
/// arguments of a pass-through record (`Args`, `Arg1` to `Arg16`). The
/// runtime's module `apt_words` has the whole record-to-register table.
pub const MILLING_VARIABLES: &[(&str, VarType)] = &[
    ("Word", VarType::Text),
    ("Minor", VarType::Text),
    ("Text", VarType::Text),
    ("Metric", VarType::Number),
    ("Plane", VarType::Number),
    ("CX", VarType::Number),
    ("CY", VarType::Number),
    ("CZ", VarType::Number),
    ("Args", VarType::Number),
];

/// Whether a name is `Arg1` ... `Arg16`, an argument of a pass-through
/// record (a number or a word).
fn is_record_argument(name: &str) -> bool {
    let Some(digits) = name.get(3..).filter(|_| name.get(..3).is_some_and(|p| p.eq_ignore_ascii_case("arg"))) else {
        return false;
    };
    matches!(digits.parse::<u8>(), Ok(1..=16)) && !digits.starts_with('0')
}

/// Functions the composites runtime provides (Vericut's post-processor notes, GoTo and
/// RestartBuffer): name and parameter names.
pub const HOST_FUNCTIONS: &[(&str, &[&str])] = &[
    ("getNthLength1", &["TowNumber"]),
    ("getNthLength2", &["TowNumber"]),
    ("getNthLength3", &["TowNumber"]),
    ("getNthAddCut", &["Index"]),
];

/// The type of a variable the runtime sets, if it is one. Single-letter
/// names are the APT record registers of milling posts (`X`, `G`, `F`, ...).
pub fn runtime_variable(name: &str) -> Option<VarType> {
    let mut known = COMPOSITES_VARIABLES.iter().chain(MILLING_VARIABLES);
    if let Some((_, t)) = known.find(|(n, _)| n.eq_ignore_ascii_case(name)) {
        return Some(*t);
    }
    if is_record_argument(name) {
        return Some(VarType::Number);
    }
    (name.chars().count() == 1).then_some(VarType::Number)
}

/// The host function a name stands for.
pub fn host_function(name: &str) -> Option<(&'static str, &'static [&'static str])> {
    HOST_FUNCTIONS.iter().copied().find(|(n, _)| n.eq_ignore_ascii_case(name))
}
