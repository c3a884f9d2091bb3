// Converted by postc from laser_mm.pp (Vectric).
//================================================
//
// postc corpus: grbl router with a laser (mm).
//
// Demonstrates:
// - LASER_SUPPORT: JET_TOOL_ON (M4 with the power), JET_TOOL_POWER (a
//   new S word when the power changes) and JET_TOOL_OFF (M5);
// - [P] as S0..S1000 from a percentage through a multiplier of 10,
//   printed only when it changes;
// - SPINDLE_ON (M3 with [S]) after the header and each tool change,
//   never for a jet tool;
// - arc sections that print [Z]: helices print through them (G2/G3 with
//   Z), there are no helical sections;
// - FIRST_FEED_MOVE and FIRST_ arc sections carrying [F];
// - no DWELL_MOVE section: dwells are left out (seed 001), with a
//   warning when posting.
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "grbl Laser and Spindle (mm) (*.gcode)",
    fileExtension: "gcode",
    units: "MM",
    laserSupport: true,
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
};

var POWER = createVariable({prefix: "S", label: "P", modal: true}, createFormat({decimals: 0, scale: 10, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: "S", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F", modal: true}, createFormat({decimals: 0, negativeZero: true}));
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "Z", label: "Z", modal: true}, createFormat({negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "I", label: "I"}, createFormat({negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "J", label: "J"}, createFormat({negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "X", label: "XH"}, createFormat({negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "Y", label: "YH"}, createFormat({negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "Z", label: "ZH"}, createFormat({negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLS_USED = createVariable({prefix: "", label: "TOOLS_USED"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "; " + TOOLPATH_FILENAME + " - " + TOOLS_USED + "\n" +
        "G21 G90 G17\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "G0" + X_HOME_POSITION + Y_HOME_POSITION + "\n";
}

function FOOTER() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "G0" + X_HOME_POSITION + Y_HOME_POSITION + "\n" +
        "M2\n";
}

function SPINDLE_ON() {
    return "M3" + SPINDLE_SPEED + "\n";
}

function TOOLCHANGE() {
    return "M5\n" +
        "G0" + Z_HOME_POSITION + "\n" +
        "; change to tool " + TOOL_NUMBER + " " + TOOL_NAME + ", then resume\n" +
        "M0\n";
}

function NEW_SEGMENT() {
    return "; " + TOOLPATH_NAME + "\n";
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

function JET_TOOL_ON() {
    return "M4" + POWER + "\n";
}

function JET_TOOL_OFF() {
    return "M5\n";
}

function JET_TOOL_POWER() {
    return POWER + "\n";
}

