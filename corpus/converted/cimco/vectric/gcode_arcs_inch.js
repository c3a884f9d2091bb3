// Converted by postc from gcode_arcs_inch.pp (Vectric).
//================================================
//
// postc reconstruction of the "G-Code Arcs (inch)" post whose output is
// the 25-line listing of the Vectric post-processor guide (2012).
// Written for postc; not a copy of the vendor file.
//
//================================================
//------------------------------------------------
//    Line terminating characters
//------------------------------------------------
//------------------------------------------------
//    Block numbering
//------------------------------------------------
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "G-Code Arcs (inch) (*.tap)",
    fileExtension: "tap",
    units: "INCH",
    lineEnding: "\r\n",
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
};

//================================================
//    Formatting for variables
//================================================
var LINE_NUMBER = createVariable({prefix: "N", label: "N"}, createFormat({decimals: 0, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F", modal: true}, createFormat({decimals: 1, negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({decimals: 4, negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({decimals: 4, negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({decimals: 4, negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "I", label: "I"}, createFormat({decimals: 4, negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "J", label: "J"}, createFormat({decimals: 4, negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "X", label: "XH"}, createFormat({decimals: 4, negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "Y", label: "YH"}, createFormat({decimals: 4, negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "Z", label: "ZH"}, createFormat({decimals: 4, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));

//================================================
//    Block definitions for toolpath output
//================================================
//---------------------------------------------------
//  Commands output at the start of the file
//---------------------------------------------------
function HEADER() {
    return "T" + TOOL_NUMBER + "M6\n" +
        "G17\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "G0" + X_HOME_POSITION + Y_HOME_POSITION + SPINDLE_SPEED + "M3\n";
}

//---------------------------------------------------
//  Commands output at the end of the file
//---------------------------------------------------
function FOOTER() {
    return "G0" + Z_HOME_POSITION + "\n" +
        "G0" + X_HOME_POSITION + Y_HOME_POSITION + "\n" +
        "M30\n";
}

//---------------------------------------------------
//  Commands output for rapid moves
//---------------------------------------------------
function RAPID_MOVE() {
    return "G0" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

//---------------------------------------------------
//  Commands output for the first feed rate move
//---------------------------------------------------
function FIRST_FEED_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + FEED_RATE + "\n";
}

//---------------------------------------------------
//  Commands output for feed rate moves
//---------------------------------------------------
function FEED_MOVE() {
    return "G1" + X_POSITION + Y_POSITION + Z_POSITION + "\n";
}

//---------------------------------------------------
//  Commands output for the first clockwise arc move
//---------------------------------------------------
function FIRST_CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

//---------------------------------------------------
//  Commands output for clockwise arc moves
//---------------------------------------------------
function CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

//---------------------------------------------------
//  Commands output for the first counterclockwise arc move
//---------------------------------------------------
function FIRST_CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

//---------------------------------------------------
//  Commands output for counterclockwise arc moves
//---------------------------------------------------
function CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

