// Converted by postc from heidenhain_mm.pp (Vectric).
//================================================
//
// postc corpus: Heidenhain conversational (plain language), mm.
//
// Demonstrates:
// - a comma decimal separator and a forced sign: X+10,000 Y-5,000;
// - conversational blocks: L X+10,000 Y+5,000 Z+5,000 R0 FMAX, arcs as
//   CC (absolute centre, [IA] [JA]) then C ... DR- / DR+;
// - the - flag (the tool diameter left justified in a width of 8) and
//   the 0 flag (the previous tool zero padded to three digits);
// - block numbers from 0 in steps of 1 on every block;
// - MIN_ARC_RADIUS (arcs under 0.5 mm print as one L block) and
//   MAX_ARC_RADIUS (arcs over 500 mm are linearized);
// - arc sections without [Z], so helices are linearized;
// - RETRACT_MOVE printing straight retracts at FMAX;
// - DWELL_MOVE as cycle 9 with a comma decimal;
// - F is modal, FMAX applies to its own block only.
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "Heidenhain conversational (mm) (*.h)",
    fileExtension: "h",
    units: "MM",
    lineEnding: "\r\n",
    minArcRadius: 0.5,
    maxArcRadius: 500,
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 1, 99999],
};

var LINE_NUMBER = createVariable({prefix: "", label: "N"}, createFormat({decimals: 0, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: " S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: " F", label: "F", modal: true}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var PREVIOUS_TOOL_NUMBER = createVariable({prefix: "T", label: "TP"}, createFormat({decimals: 0, width: 3, zeropad: true, negativeZero: true}));
var TOOL_DIAMETER = createVariable({prefix: "", label: "TDIA"}, createFormat({width: 8, justifyLeft: true, decimalMark: ",", negativeZero: true}));
var X_POSITION = createVariable({prefix: " X", label: "X"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Y_POSITION = createVariable({prefix: " Y", label: "Y"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Z_POSITION = createVariable({prefix: " Z", label: "Z"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var ARC_CENTRE_I_ABS_POSITION = createVariable({prefix: " X", label: "IA"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var ARC_CENTRE_J_ABS_POSITION = createVariable({prefix: " Y", label: "JA"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: " X", label: "XH"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: " Y", label: "YH"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: " Z", label: "ZH"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var X_MIN = createVariable({prefix: " X", label: "XMIN"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Y_MIN = createVariable({prefix: " Y", label: "YMIN"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Z_MIN = createVariable({prefix: " Z", label: "ZMIN"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var X_MAX = createVariable({prefix: " X", label: "XMAX"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Y_MAX = createVariable({prefix: " Y", label: "YMAX"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var Z_MAX = createVariable({prefix: " Z", label: "ZMAX"}, createFormat({forceSign: true, decimalMark: ",", negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "", label: "DWELL"}, createFormat({decimals: 2, decimalMark: ",", negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var FILE_NOTES = createVariable({prefix: "", label: "FILE_NOTES"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return LINE_NUMBER + " BEGIN PGM " + TOOLPATH_FILENAME + " MM\n" +
        LINE_NUMBER + " ; " + FILE_NOTES + "\n" +
        LINE_NUMBER + " BLK FORM 0.1 Z" + X_MIN + Y_MIN + Z_MIN + "\n" +
        LINE_NUMBER + " BLK FORM 0.2" + X_MAX + Y_MAX + Z_MAX + "\n" +
        LINE_NUMBER + " ; T" + TOOL_NUMBER + " DIA " + TOOL_DIAMETER + " " + TOOL_NAME + "\n" +
        LINE_NUMBER + " TOOL CALL " + TOOL_NUMBER + " Z" + SPINDLE_SPEED + "\n";
}

function FOOTER() {
    return LINE_NUMBER + " L" + Z_HOME_POSITION + " R0 FMAX M5\n" +
        LINE_NUMBER + " L" + X_HOME_POSITION + Y_HOME_POSITION + " R0 FMAX M30\n" +
        LINE_NUMBER + " END PGM " + TOOLPATH_FILENAME + " MM\n";
}

function SPINDLE_ON() {
    return LINE_NUMBER + " L" + Z_HOME_POSITION + " R0 FMAX M3\n";
}

function TOOLCHANGE() {
    return LINE_NUMBER + " L" + Z_HOME_POSITION + " R0 FMAX M5\n" +
        LINE_NUMBER + " ; T" + TOOL_NUMBER + " DIA " + TOOL_DIAMETER + " " + TOOL_NAME + " REPLACES " + PREVIOUS_TOOL_NUMBER + "\n" +
        LINE_NUMBER + " TOOL CALL " + TOOL_NUMBER + " Z" + SPINDLE_SPEED + "\n";
}

function NEW_SEGMENT() {
    return LINE_NUMBER + " ; " + TOOLPATH_NAME + "\n";
}

function RAPID_MOVE() {
    return LINE_NUMBER + " L" + X_POSITION + Y_POSITION + Z_POSITION + " R0 FMAX\n";
}

function FEED_MOVE() {
    return LINE_NUMBER + " L" + X_POSITION + Y_POSITION + Z_POSITION + FEED_RATE + "\n";
}

function RETRACT_MOVE() {
    return LINE_NUMBER + " L" + Z_POSITION + " R0 FMAX\n";
}

function CW_ARC_MOVE() {
    return LINE_NUMBER + " CC" + ARC_CENTRE_I_ABS_POSITION + ARC_CENTRE_J_ABS_POSITION + "\n" +
        LINE_NUMBER + " C" + X_POSITION + Y_POSITION + " DR-" + FEED_RATE + "\n";
}

function CCW_ARC_MOVE() {
    return LINE_NUMBER + " CC" + ARC_CENTRE_I_ABS_POSITION + ARC_CENTRE_J_ABS_POSITION + "\n" +
        LINE_NUMBER + " C" + X_POSITION + Y_POSITION + " DR+" + FEED_RATE + "\n";
}

function DWELL_MOVE() {
    return LINE_NUMBER + " CYCL DEF 9.0 DWELL TIME\n" +
        LINE_NUMBER + " CYCL DEF 9.1 DWELL " + DWELL_TIME + "\n";
}

