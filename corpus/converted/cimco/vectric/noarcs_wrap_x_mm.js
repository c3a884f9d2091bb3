// Converted by postc from noarcs_wrap_x_mm.pp (Vectric).
//================================================
//
// postc corpus: G-code WITHOUT arcs, Fanuc style (mm).
//
// Demonstrates:
// - a post without arc sections: every arc and helix is linearized into
//   FEED_MOVE segments (equal angles, chord error 0.01 mm);
// - FEED_RATE_CHANGE printing the feed on a block of its own, so the
//   move sections carry no [F];
// - the # flag: feeds print with a decimal point (F1200.);
// - block numbers N10, N20, ... that wrap past LINE_NUMBER_MAXIMUM
//   (990) back to LINE_NUMBER_START;
// - SPINDLE_SPEED_RANGE: a spindle dial of steps 1..15 for 4500..18000 rpm;
// - DWELL_MOVE in milliseconds through a multiplier of 1000;
// - [TP], [TOOL_NOTES] and [TDIA] in the tool-change comments.
//
//================================================
// Parentheses end a Fanuc comment: print ( ) in names as [ ].
//================================================
//
// postc corpus: gcode_noarcs_mm.pp with X wrapped onto a rotary B axis.
//
// Demonstrates:
// - POST_BASE: every statement, VAR and section of gcode_noarcs_mm.pp
//   (read from this folder), with the statements, VARs and sections
//   below overriding them one by one;
// - ROTARY_WRAP_X = "B": X values print as degrees of B around a
//   cylinder of the job's wrap diameter (the X in [X]'s prefix becomes
//   B), Y prints as a length; arcs are linearized in the unrolled plane
//   first (the base has no arc sections);
// - [WRAP_DIA] and [A] (the wrapped angle) in comments.
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "G-Code no arcs, WrapX2B (mm) (*.nc)",
    fileExtension: "nc",
    units: "MM",
    lineEnding: "\r\n",
    substitute: [["(", "["], [")", "]"]],
    spindleSpeedRange: [1, 15, 4500, 18000],
    rotaryWrap: ["X", "B", false],
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [10, 10, 990],
};

var LINE_NUMBER = createVariable({prefix: "N", label: "N"}, createFormat({decimals: 0, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F"}, createFormat({decimals: 0, forceDecimal: true, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var PREVIOUS_TOOL_NUMBER = createVariable({prefix: "T", label: "TP"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_DIAMETER = createVariable({prefix: "", label: "TDIA"}, createFormat({decimals: 2, negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "X", label: "XH"}, createFormat({negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "Y", label: "YH"}, createFormat({negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "Z", label: "ZH"}, createFormat({negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "P", label: "DWELL"}, createFormat({decimals: 0, scale: 1000, negativeZero: true}));
var WRAP_DIAMETER = createVariable({prefix: "", label: "WRAP_DIA"}, createFormat({negativeZero: true}));
var A_POSITION = createVariable({prefix: "", label: "A"}, createFormat({negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NOTES = createVariable({prefix: "", label: "TOOL_NOTES"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "%\n" +
        "O0200 (" + TOOLPATH_FILENAME + " WRAPPED ON D" + WRAP_DIAMETER + ")\n" +
        LINE_NUMBER + " G21 G90 G17 G40 G80\n" +
        LINE_NUMBER + " (TOOL T" + TOOL_NUMBER + " DIA " + TOOL_DIAMETER + " " + TOOL_NAME + " - " + TOOL_NOTES + ")\n" +
        LINE_NUMBER + " G91 G28 Z0\n" +
        LINE_NUMBER + " G90 T" + TOOL_NUMBER + " M6\n" +
        LINE_NUMBER + " G43 H" + TOOL_NUMBER + "\n" +
        LINE_NUMBER + " G0" + Z_HOME_POSITION + "\n";
}

function FOOTER() {
    return LINE_NUMBER + " M5\n" +
        LINE_NUMBER + " G91 G28 Z0\n" +
        LINE_NUMBER + " (B AT " + A_POSITION + " DEG)\n" +
        LINE_NUMBER + " G90 G0 B0" + Y_HOME_POSITION + "\n" +
        LINE_NUMBER + " M30\n" +
        "%\n";
}

function SPINDLE_ON() {
    return LINE_NUMBER + " " + SPINDLE_SPEED + " M3\n";
}

function TOOLCHANGE() {
    return LINE_NUMBER + " M5\n" +
        LINE_NUMBER + " (TOOL T" + TOOL_NUMBER + " DIA " + TOOL_DIAMETER + " " + TOOL_NAME + " - " + TOOL_NOTES + " AFTER " + PREVIOUS_TOOL_NUMBER + ")\n" +
        LINE_NUMBER + " G91 G28 Z0\n" +
        LINE_NUMBER + " G90 T" + TOOL_NUMBER + " M6\n" +
        LINE_NUMBER + " G43 H" + TOOL_NUMBER + "\n" +
        LINE_NUMBER + " G0" + Z_HOME_POSITION + "\n";
}

function NEW_SEGMENT() {
    return LINE_NUMBER + " (" + TOOLPATH_NAME + ")\n";
}

function RAPID_MOVE() {
    return LINE_NUMBER + " G0" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FEED_MOVE() {
    return LINE_NUMBER + " G1" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FEED_RATE_CHANGE() {
    return LINE_NUMBER + " " + FEED_RATE + "\n";
}

function DWELL_MOVE() {
    return LINE_NUMBER + " G4 " + DWELL_TIME + "\n";
}

