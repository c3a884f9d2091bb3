// Converted by postc from rotary_wrap_mm.pp (Vectric).
//================================================
//
// postc corpus: G-code with Y wrapped onto a rotary A axis, inverse-time
// feeds (mm).
//
// Demonstrates:
// - ROTARY_WRAP_Y = "-A": Y values print as degrees of A around a
//   cylinder of the job's wrap diameter ([WRAP_DIA]), turning the other
//   way ("-"); the Y prefix of [Y] becomes A;
// - INVERSE_TIME_MODE with G93 and [FI]: every feed block carries
//   F = 1 / minutes for that move;
// - no arc sections (rotary machines rarely take arcs around A): arcs
//   are linearized in the unrolled plane, then wrapped;
// - [A] (the wrapped angle) in a comment.
//
//================================================
// Names print in ( ) comments: parentheses in them print as braces.
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "G-Code WrapY2A G93 (mm) (*.ngc)",
    fileExtension: "ngc",
    units: "MM",
    substitute: [["(", "{"], [")", "}"]],
    rotaryWrap: ["Y", "A", true],
    inverseTimeFeed: true,
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
};

var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var INVERSE_TIME = createVariable({prefix: "F", label: "FI"}, createFormat({negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({negativeZero: true}));
var A_POSITION = createVariable({prefix: "A", label: "A"}, createFormat({negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "X", label: "XH"}, createFormat({negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "Z", label: "ZH"}, createFormat({negativeZero: true}));
var WRAP_DIAMETER = createVariable({prefix: "", label: "WRAP_DIA"}, createFormat({negativeZero: true}));
var X_LENGTH = createVariable({prefix: "", label: "XLENGTH"}, createFormat({decimals: 1, negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "( " + TOOLPATH_FILENAME + " )\n" +
        "( stock length " + X_LENGTH + " mm, diameter " + WRAP_DIAMETER + " mm )\n" +
        "( Y values wrapped around X, output as -A degrees )\n" +
        "G21 G90 G17 G40 G49\n" +
        "G93\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "T" + TOOL_NUMBER + " M6\n";
}

function FOOTER() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "( last rotary position " + A_POSITION + " )\n" +
        "G0" + X_HOME_POSITION + " A0\n" +
        "G94\n" +
        "M30\n";
}

function SPINDLE_ON() {
    return SPINDLE_SPEED + " M3\n";
}

function TOOLCHANGE() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "T" + TOOL_NUMBER + " M6\n";
}

function NEW_SEGMENT() {
    return "( " + TOOLPATH_NAME + " )\n";
}

function RAPID_MOVE() {
    return "G0" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FEED_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + INVERSE_TIME + "\n";
}

