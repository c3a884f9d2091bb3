//! What the server knows about each dialect's names, for hover and
//! completion: one table per kind of name, each entry a name and one line
//! in our words (from the seeds' tables and `docs/cimco.md`,
//! `docs/vcpost.md`).

use postc_ir::post::Section;

/// Vectric sections (`begin NAME`): when each is written.
pub const VECTRIC_SECTIONS: &[(&str, &str)] = &[
    ("HEADER", "Written once at the start of the program, when the first tool's data is known."),
    ("FOOTER", "Written once at the end of the program."),
    ("SPINDLE_ON", "Written after the header and after each tool change to start the spindle."),
    ("TOOLCHANGE", "Written when a later toolpath needs a different tool."),
    ("NEW_SEGMENT", "Written at the start of each later toolpath (same tool or not)."),
    ("INITIAL_RAPID_MOVE", "The first rapid move after the header or a tool change."),
    ("RAPID_MOVE", "A rapid (non-cutting) move."),
    ("FIRST_FEED_MOVE", "The first feed move after a move of another kind."),
    ("FEED_MOVE", "A straight cutting move at feed rate."),
    ("FIRST_PLUNGE_MOVE", "The first plunge move after a move of another kind."),
    ("PLUNGE_MOVE", "A move down into the material at plunge rate."),
    ("RETRACT_MOVE", "A move up out of the material."),
    ("FIRST_CW_ARC_MOVE", "The first clockwise arc after a move of another kind."),
    ("CW_ARC_MOVE", "A clockwise arc (G2)."),
    ("FIRST_CCW_ARC_MOVE", "The first counter-clockwise arc after a move of another kind."),
    ("CCW_ARC_MOVE", "A counter-clockwise arc (G3)."),
    ("FIRST_CW_HELICAL_ARC_MOVE", "The first clockwise helix after a move of another kind."),
    ("CW_HELICAL_ARC_MOVE", "A clockwise arc that also moves in Z."),
    ("FIRST_CCW_HELICAL_ARC_MOVE", "The first counter-clockwise helix after a move of another kind."),
    ("CCW_HELICAL_ARC_MOVE", "A counter-clockwise arc that also moves in Z."),
    (
        "FIRST_CW_HELICAL_ARC_PLUNGE_MOVE",
        "The first clockwise helical plunge (ramping down) after a move of another kind.",
    ),
    ("CW_HELICAL_ARC_PLUNGE_MOVE", "A clockwise helix used to plunge (ramp) into the material."),
    ("FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE", "The first counter-clockwise helical plunge after a move of another kind."),
    ("CCW_HELICAL_ARC_PLUNGE_MOVE", "A counter-clockwise helix used to plunge (ramp) into the material."),
    ("FEED_RATE_CHANGE", "Written before a move whose feed rate differs from the last one."),
    ("DWELL_MOVE", "A pause of the machine for the dwell time ([DWELL])."),
    ("JET_TOOL_ON", "Switches a laser, plasma or waterjet tool on."),
    ("JET_TOOL_OFF", "Switches a laser, plasma or waterjet tool off."),
    ("JET_TOOL_POWER", "Changes the power of a jet tool ([P])."),
    ("SPINDLE_OFF", "postc extension: the spindle stops."),
    ("COOLANT", "postc extension: the coolant changes."),
    ("CUTTER_COMP", "postc extension: cutter compensation changes."),
    ("DRILL_HEADER", "postc extension: a canned drilling cycle starts."),
    ("DRILL_POINT", "postc extension: one hole of a drilling cycle."),
    ("DRILL_FOOTER", "postc extension: a drilling cycle ends."),
    ("COMMENT", "postc extension: an operator comment."),
    ("INSERT", "postc extension: verbatim text from the toolpath."),
    ("TOOLPATH_END", "postc extension: the end of a toolpath."),
    ("REVISION_COMMENT", "Written first, before the header: the stock post's revision ([REVISION])."),
];

/// Vectric labels (`[LABEL]`): what each prints. The `VAR` name of each is
/// in `postc_front_vectric::names::VAR_NAMES`.
pub const VECTRIC_LABELS: &[(&str, &str)] = &[
    ("F", "The feed rate of the current move."),
    ("FC", "The tool's cutting feed rate."),
    ("FP", "The tool's plunge feed rate."),
    ("S", "The spindle speed (rpm, or its SPINDLE_SPEED_RANGE step)."),
    ("P", "The power of a jet tool."),
    ("T", "The number of the current tool."),
    ("TP", "The number of the tool used before the current one."),
    ("N", "The block (line) number; it advances each time a block prints it."),
    ("TOOLNAME", "The name of the current tool."),
    ("TOOL_NOTES", "The notes written for the current tool."),
    ("TOOLPATH_NAME", "The name of the current toolpath."),
    ("TP_FILENAME", "The name the toolpath file was saved under."),
    ("TP_DIR", "The folder the toolpath file was saved to."),
    ("TP_EXT", "The extension of the saved toolpath file."),
    ("PATHNAME", "The full pathname of the folder the toolpath file was saved to."),
    ("X", "The X position at the end of the current move."),
    ("Y", "The Y position at the end of the current move."),
    ("Z", "The Z position at the end of the current move."),
    ("A", "The A (rotary) position in degrees; the wrapped axis under ROTARY_WRAP."),
    ("B", "The B (rotary) position in degrees."),
    ("C", "The C (rotary) position in degrees."),
    ("I", "The X distance from an arc's start to its centre."),
    ("J", "The Y distance from an arc's start to its centre."),
    ("IA", "The X coordinate of an arc's centre."),
    ("JA", "The Y coordinate of an arc's centre."),
    ("ArcStartX", "The X coordinate where the arc starts."),
    ("ArcStartY", "The Y coordinate where the arc starts."),
    ("ArcMidX", "The X coordinate of the arc's middle point."),
    ("ArcMidY", "The Y coordinate of the arc's middle point."),
    ("ArcMidXI", "The X distance from the arc's start to its middle point."),
    ("ArcMidYI", "The Y distance from the arc's start to its middle point."),
    ("Radius", "The radius of the current arc."),
    ("Angle", "The angle the arc sweeps through, in radians (times 57.2957795 for degrees)."),
    ("XH", "The X home position."),
    ("YH", "The Y home position."),
    ("ZH", "The Z home position."),
    ("SAFEZ", "The safe Z height for rapid moves."),
    ("WRAP_DIA", "The diameter of the cylinder a wrapped (rotary) axis goes around."),
    ("XLENGTH", "The length of the material block in X."),
    ("YLENGTH", "The length of the material block in Y."),
    ("ZLENGTH", "The thickness of the material block."),
    ("XMIN", "The smallest X of the material block."),
    ("YMIN", "The smallest Y of the material block."),
    ("ZMIN", "The smallest Z of the material block."),
    ("XMAX", "The largest X of the material block."),
    ("YMAX", "The largest Y of the material block."),
    ("ZMAX", "The largest Z of the material block."),
    ("X_ORIGIN_POS", "Where the X origin is on the material (left, centre, right)."),
    ("Y_ORIGIN_POS", "Where the Y origin is on the material (bottom, centre, top)."),
    ("Z_ORIGIN", "Whether Z zero is on the material's surface or on the machine bed."),
    ("XY_ORIGIN", "Where the XY origin is on the material, as one value."),
    ("TOOLS_USED", "The list of tools the program uses."),
    ("TOOLPATHS_OUTPUT", "The list of toolpaths written to the program."),
    ("TOOLPATH_NOTES", "The notes written for the current toolpath."),
    ("FILE_NOTES", "The notes written for the job."),
    ("TIME", "The time the program was written."),
    ("DATE", "The date the program was written."),
    ("DWELL", "The dwell time in seconds."),
    ("PRODUCT", "The name and version of the program that wrote the output."),
    ("TDIA", "The diameter of the current tool."),
    ("FI", "The inverse-time feed number (1 / minutes for the move)."),
    ("REVISION", "The post's revision: a 32-digit hash of the post file."),
];

/// Vectric global statements (`NAME = value` outside sections).
pub const VECTRIC_GLOBALS: &[(&str, &str)] = &[
    ("POST_NAME", "The name the post is listed under, with its extension: \"G-Code (mm) (*.tap)\"."),
    ("FILE_EXTENSION", "The extension of the files the post writes."),
    ("UNITS", "\"MM\" or \"INCHES\": the units the post writes."),
    ("DIRECT_OUTPUT", "Sends the program straight to a machine controller."),
    ("PRINT_DIRECT", "Sends the program to a printer-style driver."),
    ("RAPID_PLUNGE_TO_STARTZ", "\"YES\": plunges at rapid speed down to the start height."),
    ("LASER_SUPPORT", "\"YES\": the post drives laser tools (JET_TOOL sections)."),
    ("LINE_ENDING", "The characters that end each line, as codes: \"[13][10]\"."),
    ("LINE_NUMBER_START", "The first block number."),
    ("LINE_NUMBER", "The first block number (the newer spelling of LINE_NUMBER_START)."),
    ("LINE_NUMBER_INCREMENT", "How much the block number grows each time it prints."),
    ("LINE_NUMBER_MAXIMUM", "The block number after which numbering starts again."),
    ("SUBSTITUTE", "Pairs of characters: each first one is written as the second one."),
    ("TAPE_SPLITTING", "Splits long programs into several files."),
    ("SPINDLE_SPEED_RANGE", "Maps spindle speeds onto the steps of a controller: first last min max."),
    ("ROTARY_WRAP_X", "Wraps X moves around a rotary axis."),
    ("ROTARY_WRAP_Y", "Wraps Y moves around a rotary axis."),
    ("INVERSE_TIME_MODE", "\"YES\": feeds are written as inverse time ([FI])."),
    ("MIN_ARC_RADIUS", "Arcs smaller than this are written as straight moves."),
    ("MAX_ARC_RADIUS", "Arcs larger than this are written as straight moves."),
    ("POST_BASE", "Another post this one starts from; its sections are used where this one has none."),
];

/// CIMCO host functions the post defines (called by the host) or calls.
/// (name, signature, description)
pub const CIMCO_FUNCTIONS: &[(&str, &str, &str)] = &[
    (
        "onInit",
        "onInit()",
        "Called first, before anything else: set up formats, output variables and defaults here. It writes nothing.",
    ),
    (
        "onOpen",
        "onOpen(isClipboard)",
        "Called at the start of the program; returns the opening blocks. isClipboard tells a program from a snippet (postc always passes false).",
    ),
    ("onClose", "onClose()", "Called last; returns the closing blocks (M30 and the like)."),
    (
        "onLinear",
        "onLinear(x, y, z, movement) / lathe onLinear(x, z, movement)",
        "Called for every straight move; movement is MOVEMENT_RAPID, MOVEMENT_CUTTING or MOVEMENT_PLUNGE. Returns the block.",
    ),
    (
        "onCircular",
        "onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) / lathe onCircular(cx, cz, ex, ez, isCW, movement)",
        "Called for every arc with its absolute centre and end point; isCW is true for clockwise (G2). Without it arcs come as short onLinear moves.",
    ),
    (
        "onCompensation",
        "onCompensation(comp)",
        "Called when cutter compensation changes: COMPENSATION_OFF, _LEFT or _RIGHT. Keep it for the next move.",
    ),
    (
        "getCompensation",
        "getCompensation()",
        "Written by the post: returns the compensation code kept by onCompensation (the host's returns \"\").",
    ),
    (
        "onDrillingHeader",
        "onDrillingHeader(drillHeader)",
        "Called before the holes of a milling drill cycle with the cycle's parameters; save drillHeader for the points.",
    ),
    ("onDrillingPoint", "onDrillingPoint(x, y)", "Called for each hole of a milling drill cycle."),
    ("onDrillingFooter", "onDrillingFooter()", "Called after the last hole of a milling drill cycle."),
    ("onDrilling", "onDrilling(drillHeader)", "Called for each hole of a turning drill cycle."),
    (
        "onToolChange",
        "onToolChange(tool, name, diameter, spindleSpeed)",
        "postc extension: called when a toolpath uses another tool.",
    ),
    ("onDwell", "onDwell(seconds)", "postc extension: called for a dwell; without it dwells are skipped."),
    ("onComment", "onComment(text)", "postc extension: called for an operator comment."),
    ("onToolpathEnd", "onToolpathEnd()", "postc extension: called at the end of each toolpath."),
    (
        "createFormat",
        "createFormat({prefix, width, zeropad, decimals, scale, forceDecimal, forceSign})",
        "Makes a number format: prefix text, minimum width, zero padding, decimals, a scale factor, a forced decimal point and a forced sign.",
    ),
    (
        "createVariable",
        "createVariable({prefix, force}, format)",
        "Makes a modal output variable from a format: it writes its value only when it changed, unless force is true.",
    ),
    (
        "getFeedrate",
        "getFeedrate(movement)",
        "Returns the feed word of the move being posted (\"F1500\"), or \"\" for MOVEMENT_RAPID. A post may define its own.",
    ),
    (
        "format",
        "variable.format(value)",
        "Formats a value with a format or output variable; an output variable returns \"\" when the value did not change.",
    ),
    ("getLast", "variable.getLast()", "Returns the last value an output variable wrote."),
];

/// CIMCO host constants and globals.
pub const CIMCO_GLOBALS: &[(&str, &str)] = &[
    ("MOVEMENT_RAPID", "Movement 0: a rapid move."),
    ("MOVEMENT_CUTTING", "Movement 1: a cutting move at feed rate."),
    ("MOVEMENT_FEED", "Movement 1: another name for MOVEMENT_CUTTING."),
    ("MOVEMENT_PLUNGE", "Movement 2: a plunge into the material."),
    ("MOVEMENT_RETRACT", "Movement 3: a retract out of the material."),
    ("COMPENSATION_OFF", "Compensation 0: none (G40)."),
    ("COMPENSATION_LEFT", "Compensation 1: tool left of the path (G41)."),
    ("COMPENSATION_RIGHT", "Compensation 2: tool right of the path (G42)."),
    ("POST_TYPE_MILL", "PostInfo.type 0: a milling post."),
    ("POST_TYPE_TURN", "PostInfo.type 1: a lathe post."),
    ("DEGRESSION_NONE", "Peck degression 0: every peck the same."),
    ("DEGRESSION_VALUE", "Peck degression 1: each peck shorter by a value."),
    ("DEGRESSION_FACTOR", "Peck degression 2: each peck shorter by a factor."),
    ("decimalMark", "The decimal mark of the formats made afterwards: '.' or ','."),
    ("linebreak", "The line ending of the program (default \"\\n\")."),
    ("variableDelimeter", "Text the post's writeBlock puts between words."),
    ("tolerance", "The post's tolerance in mm; postc also uses it to cut arcs into lines."),
    ("showSequenceNumbers", "Whether the post's writeBlock numbers blocks."),
    ("sequenceNumberStart", "The first block number writeBlock uses."),
    ("sequenceNumberIncrement", "How much writeBlock's block number grows."),
    ("useRadius", "Arcs are written with R: postc then splits arcs of 180 degrees or more."),
    ("absoluteArcCenter", "Arcs are written with absolute centres."),
    ("xDiameterProg", "X is written as a diameter (lathe)."),
    ("iDiameterProg", "I is written as a diameter (lathe)."),
    ("PostInfo", "The post's description: title, summary, author, version, type."),
    ("globals", "An object whose properties are the post's globals."),
];

/// VcPost registers and variables the runtime sets from each APT record.
pub const VCPOST_REGISTERS: &[(&str, &str)] = &[
    ("N", "The sequence (block) number; it cannot be assigned."),
    ("X", "X of the move's end point (GOTO, RAPID, CIRCLE) or of the hole (CYCLE)."),
    ("Y", "Y of the move's end point or of the hole."),
    ("Z", "Z of the move's end point; the depth in CYCLE, the top of the hole in later GOTOs."),
    ("A", "A rotary position, when the move has one."),
    ("B", "B rotary position, when the move has one."),
    ("C", "C rotary position, when the move has one."),
    ("I", "Tool axis X on GOTO; centre minus start in X on CIRCLE."),
    ("J", "Tool axis Y on GOTO; centre minus start in Y on CIRCLE."),
    ("K", "Tool axis Z on GOTO; centre minus start in Z on CIRCLE."),
    ("G", "The motion: 0 rapid, 1 feed, 2 clockwise arc, 3 counter-clockwise arc."),
    ("F", "The feed rate, set for every feed move and by FEDRAT."),
    ("S", "The spindle speed (SPINDL)."),
    ("T", "The tool number (LOADTL)."),
    ("H", "The tool length offset number (LOADTL; the tool number if none)."),
    ("D", "The diameter offset number (LOADTL, CUTCOM)."),
    ("R", "The arc radius (CIRCLE), the dwell seconds (DELAY) or the reference plane (CYCLE)."),
    ("Q", "The peck depth of a drill cycle."),
    ("P", "The dwell of a drill cycle, in seconds."),
    ("CX", "X of the arc's centre."),
    ("CY", "Y of the arc's centre."),
    ("CZ", "Z of the arc's centre."),
    ("Plane", "The arc's plane: 17 (XY), 18 (ZX) or 19 (YZ)."),
    ("Word", "The record's major word (GOTO, LOADTL, ...)."),
    ("Minor", "The record's first minor word (CLW, OFF, DRILL, ...) or \"\"."),
    ("Text", "The record's text: part name, tool name, comment."),
    ("Metric", "1 when the CL file's lengths are millimetres, 0 for inches."),
    ("Args", "How many arguments the record has."),
    ("Arg1", "The record's first argument (Arg1 ... Arg16)."),
];

/// VcPost register properties (`Register.Property = value`).
pub const VCPOST_PROPERTIES: &[(&str, &str)] = &[
    ("Prefix", "Text written before the number (default: the register's name)."),
    ("Format", "\"[+]I.D\": up to I integer digits and D decimals; + forces the sign."),
    ("Decimals", "The number of decimals (0-9)."),
    ("TrailingZeros", "Keep trailing zeros (default False)."),
    ("LeadingZeros", "Pad the integer part with zeros."),
    ("DecimalPoint", "Write the point even without decimals (\"Always\", \"Auto\")."),
    ("ZeroBeforePoint", "Write 0.5 rather than .5 (default True)."),
    ("Sign", "When a sign prints: \"+\"/\"Always\" or \"-\"/\"Negative\"."),
    ("Width", "Minimum width, padded with blanks."),
    ("Justify", "\"Left\" or \"Right\" inside Width."),
    ("DecimalMark", "\".\" or \",\"."),
    ("Multiplier", "A factor applied before rounding (also Scale)."),
    ("Modal", "Print only when the text changed."),
    ("Previous", "The value the register had before its last assignment."),
];

/// VcPost built-in functions.
pub const VCPOST_BUILTINS: &[(&str, &str)] = &[
    ("Abs", "Abs(x): the absolute value."),
    ("Sqr", "Sqr(x): the square root."),
    ("Sin", "Sin(x): sine of radians."),
    ("Cos", "Cos(x): cosine of radians."),
    ("Tan", "Tan(x): tangent of radians."),
    ("Atn", "Atn(x): arc tangent, in radians."),
    ("Int", "Int(x): rounds down."),
    ("Fix", "Fix(x): drops the fraction."),
    ("Round", "Round(x[, n]): rounds half away from zero."),
    ("Len", "Len(s): the length of a text."),
    ("Left", "Left(s, n): the first n characters."),
    ("Right", "Right(s, n): the last n characters."),
    ("Mid", "Mid(s, start[, n]): characters from start (1-based)."),
    ("UCase", "UCase(s): upper case."),
    ("LCase", "LCase(s): lower case."),
    ("Str", "Str(x): a number as text."),
    ("CStr", "CStr(x): a number as text."),
    ("Val", "Val(s): the number a text starts with."),
    ("Format", "Format(x, \"0.000\"): a number with a picture."),
    ("Chr", "Chr(n): the character with code n."),
    ("IIf", "IIf(c, a, b): a when c is true, else b."),
    ("Sgn", "Sgn(x): -1, 0 or 1."),
];

/// APT major words a VcPost `Sub` handles.
pub const VCPOST_WORDS: &[(&str, &str)] = &[
    ("PARTNO", "Called once, first: Text is the part name, Metric tells the units."),
    ("LOADTL", "A tool change: T, H, D, Text (tool name)."),
    ("TOOLPATH", "A toolpath starts: Text is its name."),
    ("RAPID", "The next GOTO is a rapid."),
    ("GOTO", "A move: X Y Z (A B C, I J K), G 0 or 1, F."),
    ("FEDRAT", "The feed changes: F."),
    ("CIRCLE", "An arc: end X Y Z, G 2 or 3, I J K, CX CY CZ, R, Plane, F."),
    ("DELAY", "A dwell: R seconds."),
    ("SPINDL", "Spindle on or off: S, Minor CLW, CCLW or OFF."),
    ("COOLNT", "Coolant: Minor ON, FLOOD, MIST, AIR or OFF."),
    ("CUTCOM", "Cutter compensation: Minor LEFT, RIGHT or OFF; D."),
    ("CYCLE", "A drill cycle starts (Minor DRILL, DEEP, ...) or ends (Minor OFF)."),
    ("PPRINT", "An operator comment: Text."),
    ("INSERT", "Verbatim text: Text."),
    ("FINI", "Called once, last."),
];

/// VcPost keywords.
pub const VCPOST_KEYWORDS: &[&str] = &[
    "And", "As", "Call", "Case", "Const", "Dim", "Do", "Else", "ElseIf", "End", "Exit", "False", "For", "Function",
    "If", "Is", "Let", "Loop", "Mod", "Next", "Not", "Or", "Out", "Private", "Public", "Rem", "Select", "Step", "Sub",
    "Then", "To", "True", "Until", "Wend", "While", "Xor",
];

/// The description of a table entry, by name (case-insensitive).
pub fn lookup(table: &[(&'static str, &'static str)], name: &str) -> Option<(&'static str, &'static str)> {
    table.iter().copied().find(|(n, _)| n.eq_ignore_ascii_case(name))
}

/// The Vectric section names the frontend knows, in declaration order.
pub fn section_names() -> impl Iterator<Item = &'static str> {
    Section::ALL.iter().map(|s| s.name())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_section_and_label_has_a_description() {
        for name in section_names() {
            assert!(lookup(VECTRIC_SECTIONS, name).is_some(), "section {name} undescribed");
        }
        for (var, label) in postc_front_vectric::names::VAR_NAMES {
            assert!(lookup(VECTRIC_LABELS, label).is_some(), "label {label} of {var} undescribed");
        }
        for (name, _) in VECTRIC_GLOBALS {
            assert!(postc_front_vectric::names::GlobalName::from_name(name).is_some(), "{name}");
        }
    }
}
