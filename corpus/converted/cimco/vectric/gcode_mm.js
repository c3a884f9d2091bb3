// Converted by postc from gcode_mm.pp (Vectric).
//================================================
//
// postc generic G-code post, millimetres.
// The post `postc post TOOLPATH` uses when no post is named (it is
// embedded in the binary). Output reads in LinuxCNC, Mach3/4, grbl and
// most Fanuc-style controls: G21, absolute, XY plane, I/J relative arcs
// with helical Z, G4 dwells, T/M6 tool changes with G43 length offsets.
// Safe retracts go to machine Z zero (G53 G0 Z0), which is safe whether or
// not the toolpath says where home is (APT CL files often do not).
//
//================================================
// Parentheses end a G-code comment: print ( ) in names as { }.
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "postc G-code (mm) (*.ngc)",
    fileExtension: "ngc",
    units: "MM",
    substitute: [["(", "{"], [")", "}"]],
    laserSupport: true,
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [10, 10, 99999],
};

var LINE_NUMBER = createVariable({prefix: "N", label: "N"}, createFormat({decimals: 0, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var POWER = createVariable({prefix: "S", label: "P"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F", modal: true}, createFormat({decimals: 1, negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "I", label: "I"}, createFormat({decimals: 4, negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "J", label: "J"}, createFormat({decimals: 4, negativeZero: true}));
var SAFE_Z_HEIGHT = createVariable({prefix: "Z", label: "SAFEZ"}, createFormat({negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "P", label: "DWELL"}, createFormat({decimals: 2, negativeZero: true}));
var X_LENGTH = createVariable({prefix: "", label: "XLENGTH"}, createFormat({decimals: 1, negativeZero: true}));
var Y_LENGTH = createVariable({prefix: "", label: "YLENGTH"}, createFormat({decimals: 1, negativeZero: true}));
var Z_LENGTH = createVariable({prefix: "", label: "ZLENGTH"}, createFormat({decimals: 1, negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var PRODUCT = createVariable({prefix: "", label: "PRODUCT"}, createFormat({decimals: 0, negativeZero: true}));
var DATE = createVariable({prefix: "", label: "DATE"}, createFormat({decimals: 0, negativeZero: true}));
var TIME = createVariable({prefix: "", label: "TIME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLS_USED = createVariable({prefix: "", label: "TOOLS_USED"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "( " + TOOLPATH_FILENAME + " )\n" +
        "( made by " + PRODUCT + " on " + DATE + " " + TIME + " )\n" +
        "( material " + X_LENGTH + " x " + Y_LENGTH + " x " + Z_LENGTH + " mm )\n" +
        "( tools: " + TOOLS_USED + " )\n" +
        "( toolpath: " + TOOLPATH_NAME + " )\n" +
        "G21 G90 G17 G40 G49 G94\n" +
        "G53 G0 Z0\n" +
        "T" + TOOL_NUMBER + " M6\n" +
        "G43 H" + TOOL_NUMBER + "\n";
}

function FOOTER() {
    return "M5\n" +
        "G53 G0 Z0\n" +
        "M30\n";
}

function SPINDLE_ON() {
    return SPINDLE_SPEED + " M3\n";
}

function TOOLCHANGE() {
    return "M5\n" +
        "G53 G0 Z0\n" +
        "( tool " + TOOL_NUMBER + ": " + TOOL_NAME + " )\n" +
        "T" + TOOL_NUMBER + " M6\n" +
        "G43 H" + TOOL_NUMBER + "\n";
}

function NEW_SEGMENT() {
    return "( toolpath: " + TOOLPATH_NAME + " )\n";
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

function FIRST_CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CW_ARC_MOVE() {
    return "G2" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function FIRST_CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + FEED_RATE + "\n";
}

function CCW_ARC_MOVE() {
    return "G3" + X_POSITION + Y_POSITION + Z_POSITION + ARC_CENTRE_I_INC_POSITION + ARC_CENTRE_J_INC_POSITION + "\n";
}

function DWELL_MOVE() {
    return "G4" + DWELL_TIME + "\n";
}

function JET_TOOL_ON() {
    return "M3" + POWER + "\n";
}

function JET_TOOL_OFF() {
    return "M5\n";
}

function JET_TOOL_POWER() {
    return POWER + "\n";
}

