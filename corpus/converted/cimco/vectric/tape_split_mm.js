// Converted by postc from tape_split_mm.pp (Vectric).
//================================================
//
// postc corpus: G-code ATC with arcs and helices, tape splitting (mm).
//
// Demonstrates:
// - TAPE_SPLITTING = 40 15 "%s_%d.nc" 1 "YES": parts of at most 40
//   blocks (plus the footer), split after a retract to safe Z once a
//   part has 25, every part named name_1.nc, name_2.nc, ...
//   (INDEX_ON_FIRST_FILE); each part starts with HEADER and SPINDLE_ON
//   and ends with FOOTER; a program that fits is not split;
// - all eight helical sections: FIRST_ and plain CW/CCW
//   HELICAL_ARC_MOVE and HELICAL_ARC_PLUNGE_MOVE (the plunge ones at the
//   plunge feed, marked with a comment);
// - FIRST_PLUNGE_MOVE / PLUNGE_MOVE and FIRST_FEED_MOVE / FEED_MOVE;
// - [TOOLPATH_NOTES], [TP_DIR], [TP_EXT], [PATHNAME], [FC], [FP].
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "G-Code ATC Arcs TS40 (mm) (*.nc)",
    fileExtension: "nc",
    units: "MM",
    substitute: [["(", "{"], [")", "}"]],
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
    tapeSplitting: [40, 15, "%s_%d.nc", 1, true],
};

var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F", modal: true}, createFormat({decimals: 1, negativeZero: true}));
var CUT_RATE = createVariable({prefix: "", label: "FC"}, createFormat({decimals: 0, negativeZero: true}));
var PLUNGE_RATE = createVariable({prefix: "", label: "FP"}, createFormat({decimals: 0, negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "I", label: "I"}, createFormat({negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "J", label: "J"}, createFormat({negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "X", label: "XH"}, createFormat({negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "Y", label: "YH"}, createFormat({negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "Z", label: "ZH"}, createFormat({negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "P", label: "DWELL"}, createFormat({decimals: 2, negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_EXTENSION = createVariable({prefix: "", label: "TP_EXT"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_DIR = createVariable({prefix: "", label: "TP_DIR"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_PATHNAME = createVariable({prefix: "", label: "PATHNAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NOTES = createVariable({prefix: "", label: "TOOLPATH_NOTES"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "( " + TOOLPATH_FILENAME + "." + TOOLPATH_EXTENSION + " in " + TOOLPATH_DIR + " )\n" +
        "( path " + TOOLPATH_PATHNAME + " )\n" +
        "G21 G90 G17 G40 G49 G94\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "T" + TOOL_NUMBER + " M6\n" +
        "G43 H" + TOOL_NUMBER + "\n" +
        "( " + TOOLPATH_NAME + ": " + TOOLPATH_NOTES + " )\n" +
        "( cut " + CUT_RATE + " plunge " + PLUNGE_RATE + " mm/min )\n";
}

function FOOTER() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "G0" + X_HOME_POSITION + Y_HOME_POSITION + "\n" +
        "M30\n";
}

function SPINDLE_ON() {
    return SPINDLE_SPEED + " M3\n";
}

function TOOLCHANGE() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "T" + TOOL_NUMBER + " M6\n" +
        "G43 H" + TOOL_NUMBER + "\n";
}

function NEW_SEGMENT() {
    return "( " + TOOLPATH_NAME + ": " + TOOLPATH_NOTES + " )\n" +
        "( cut " + CUT_RATE + " plunge " + PLUNGE_RATE + " mm/min )\n";
}

function RAPID_MOVE() {
    return "G0" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FIRST_FEED_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + FEED_RATE + "\n";
}

function FEED_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FIRST_PLUNGE_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + FEED_RATE + "\n";
}

function PLUNGE_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

function FIRST_CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function FIRST_CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function FIRST_CW_HELICAL_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CW_HELICAL_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function FIRST_CCW_HELICAL_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CCW_HELICAL_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function FIRST_CW_HELICAL_ARC_PLUNGE_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + " ( helical plunge )\n";
}

function CW_HELICAL_ARC_PLUNGE_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + " ( helical plunge )\n";
}

function FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + " ( helical plunge )\n";
}

function CCW_HELICAL_ARC_PLUNGE_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + " ( helical plunge )\n";
}

function DWELL_MOVE() {
    return "G4" + DWELL_TIME + "\n";
}

