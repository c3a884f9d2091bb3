// Converted by postc from text_output_mm.pp (Vectric).
//================================================
//
// postc corpus: a readable listing of every section (mm), in the manner
// of Vectric's TextOutput_Arcs_mm.pp.
//
// Every section of both Vectric guides is here and names itself, so the
// goldens of this post show which section the runtime chose for each
// event (FIRST_ or plain, plunge, retract, helical, helical plunge, jet,
// dwell, feed-rate change, ...). It prints every variable of both
// guides' tables: the arc words [I] [J] [IA] [JA] [ArcStartX]
// [ArcStartY] [ArcMidX] [ArcMidY] [ArcMidXI] [ArcMidYI] [Radius] and
// [Angle] (in degrees through a multiplier), job and file data, [FI],
// [P], [DWELL], [TDIA], [PRODUCT].
//
// Block numbers are zero padded to four digits (0 flag, width 4),
// start at 1 and wrap after 9999.
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "Text listing (mm) (*.txt)",
    fileExtension: "txt",
    units: "MM",
    laserSupport: true,
    onChangeByValue: true,
    rapidForgetsFeed: true,
    directOutput: "Listing|Notepad.Document",
    blockNumbers: [1, 1, 9999],
};

var LINE_NUMBER = createVariable({prefix: "", label: "N"}, createFormat({decimals: 0, width: 4, zeropad: true, negativeZero: true}));
var SPINDLE_SPEED = createVariable({prefix: "", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var POWER = createVariable({prefix: "", label: "P"}, createFormat({decimals: 1, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "", label: "F"}, createFormat({decimals: 1, negativeZero: true}));
var CUT_RATE = createVariable({prefix: "", label: "FC"}, createFormat({decimals: 1, negativeZero: true}));
var PLUNGE_RATE = createVariable({prefix: "", label: "FP"}, createFormat({decimals: 1, negativeZero: true}));
var INVERSE_TIME = createVariable({prefix: "", label: "FI"}, createFormat({decimals: 4, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var PREVIOUS_TOOL_NUMBER = createVariable({prefix: "", label: "TP"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_DIAMETER = createVariable({prefix: "", label: "TDIA"}, createFormat({negativeZero: true}));
var X_POSITION = createVariable({prefix: "", label: "X"}, createFormat({negativeZero: true}));
var Y_POSITION = createVariable({prefix: "", label: "Y"}, createFormat({negativeZero: true}));
var Z_POSITION = createVariable({prefix: "", label: "Z"}, createFormat({negativeZero: true}));
var A_POSITION = createVariable({prefix: "", label: "A"}, createFormat({negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "", label: "I"}, createFormat({negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "", label: "J"}, createFormat({negativeZero: true}));
var ARC_CENTRE_I_ABS_POSITION = createVariable({prefix: "", label: "IA"}, createFormat({negativeZero: true}));
var ARC_CENTRE_J_ABS_POSITION = createVariable({prefix: "", label: "JA"}, createFormat({negativeZero: true}));
var ARC_START_X_POSITION = createVariable({prefix: "", label: "ArcStartX"}, createFormat({negativeZero: true}));
var ARC_START_Y_POSITION = createVariable({prefix: "", label: "ArcStartY"}, createFormat({negativeZero: true}));
var ARC_MID_X_POSITION = createVariable({prefix: "", label: "ArcMidX"}, createFormat({negativeZero: true}));
var ARC_MID_Y_POSITION = createVariable({prefix: "", label: "ArcMidY"}, createFormat({negativeZero: true}));
var ARC_MID_X_INC_POSITION = createVariable({prefix: "", label: "ArcMidXI"}, createFormat({negativeZero: true}));
var ARC_MID_Y_INC_POSITION = createVariable({prefix: "", label: "ArcMidYI"}, createFormat({negativeZero: true}));
var ARC_RADIUS = createVariable({prefix: "", label: "Radius"}, createFormat({negativeZero: true}));
var ARC_ANGLE = createVariable({prefix: "", label: "Angle"}, createFormat({scale: 57.2957795, negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "", label: "XH"}, createFormat({negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "", label: "YH"}, createFormat({negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "", label: "ZH"}, createFormat({negativeZero: true}));
var SAFE_Z_HEIGHT = createVariable({prefix: "", label: "SAFEZ"}, createFormat({negativeZero: true}));
var WRAP_DIAMETER = createVariable({prefix: "", label: "WRAP_DIA"}, createFormat({negativeZero: true}));
var X_LENGTH = createVariable({prefix: "", label: "XLENGTH"}, createFormat({negativeZero: true}));
var Y_LENGTH = createVariable({prefix: "", label: "YLENGTH"}, createFormat({negativeZero: true}));
var Z_LENGTH = createVariable({prefix: "", label: "ZLENGTH"}, createFormat({negativeZero: true}));
var X_MIN = createVariable({prefix: "", label: "XMIN"}, createFormat({negativeZero: true}));
var Y_MIN = createVariable({prefix: "", label: "YMIN"}, createFormat({negativeZero: true}));
var Z_MIN = createVariable({prefix: "", label: "ZMIN"}, createFormat({negativeZero: true}));
var X_MAX = createVariable({prefix: "", label: "XMAX"}, createFormat({negativeZero: true}));
var Y_MAX = createVariable({prefix: "", label: "YMAX"}, createFormat({negativeZero: true}));
var Z_MAX = createVariable({prefix: "", label: "ZMAX"}, createFormat({negativeZero: true}));
var X_ORIGIN_POS = createVariable({prefix: "", label: "X_ORIGIN_POS"}, createFormat({negativeZero: true}));
var Y_ORIGIN_POS = createVariable({prefix: "", label: "Y_ORIGIN_POS"}, createFormat({negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "", label: "DWELL"}, createFormat({decimals: 2, negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_EXTENSION = createVariable({prefix: "", label: "TP_EXT"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_DIR = createVariable({prefix: "", label: "TP_DIR"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_PATHNAME = createVariable({prefix: "", label: "PATHNAME"}, createFormat({decimals: 0, negativeZero: true}));
var PRODUCT = createVariable({prefix: "", label: "PRODUCT"}, createFormat({decimals: 0, negativeZero: true}));
var DATE = createVariable({prefix: "", label: "DATE"}, createFormat({decimals: 0, negativeZero: true}));
var TIME = createVariable({prefix: "", label: "TIME"}, createFormat({decimals: 0, negativeZero: true}));
var FILE_NOTES = createVariable({prefix: "", label: "FILE_NOTES"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLS_USED = createVariable({prefix: "", label: "TOOLS_USED"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATHS_OUTPUT = createVariable({prefix: "", label: "TOOLPATHS_OUTPUT"}, createFormat({decimals: 0, negativeZero: true}));
var XY_ORIGIN = createVariable({prefix: "", label: "XY_ORIGIN"}, createFormat({decimals: 0, negativeZero: true}));
var Z_ORIGIN = createVariable({prefix: "", label: "Z_ORIGIN"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NOTES = createVariable({prefix: "", label: "TOOL_NOTES"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NOTES = createVariable({prefix: "", label: "TOOLPATH_NOTES"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return LINE_NUMBER + " HEADER\n" +
        LINE_NUMBER + "   file " + TOOLPATH_FILENAME + " ext " + TOOLPATH_EXTENSION + " dir " + TOOLPATH_DIR + " path " + TOOLPATH_PATHNAME + "\n" +
        LINE_NUMBER + "   made by " + PRODUCT + " on " + DATE + " at " + TIME + "\n" +
        LINE_NUMBER + "   notes " + FILE_NOTES + "\n" +
        LINE_NUMBER + "   tools used " + TOOLS_USED + "\n" +
        LINE_NUMBER + "   toolpaths " + TOOLPATHS_OUTPUT + "\n" +
        LINE_NUMBER + "   block " + X_LENGTH + " x " + Y_LENGTH + " x " + Z_LENGTH + ", from " + X_MIN + "," + Y_MIN + "," + Z_MIN + " to " + X_MAX + "," + Y_MAX + "," + Z_MAX + "\n" +
        LINE_NUMBER + "   origin " + XY_ORIGIN + " at " + X_ORIGIN_POS + "," + Y_ORIGIN_POS + ", Z zero on " + Z_ORIGIN + "\n" +
        LINE_NUMBER + "   home " + X_HOME_POSITION + "," + Y_HOME_POSITION + "," + Z_HOME_POSITION + " safe Z " + SAFE_Z_HEIGHT + " wrap diameter " + WRAP_DIAMETER + "\n" +
        LINE_NUMBER + "   tool " + TOOL_NUMBER + " after " + PREVIOUS_TOOL_NUMBER + ": " + TOOL_NAME + " (" + TOOL_NOTES + ") dia " + TOOL_DIAMETER + " speed " + SPINDLE_SPEED + " cut " + CUT_RATE + " plunge " + PLUNGE_RATE + " power " + POWER + "\n" +
        LINE_NUMBER + "   toolpath " + TOOLPATH_NAME + " (" + TOOLPATH_NOTES + ")\n";
}

function FOOTER() {
    return LINE_NUMBER + " FOOTER home " + X_HOME_POSITION + "," + Y_HOME_POSITION + "," + Z_HOME_POSITION + "\n";
}

function SPINDLE_ON() {
    return LINE_NUMBER + " SPINDLE_ON speed " + SPINDLE_SPEED + "\n";
}

function TOOLCHANGE() {
    return LINE_NUMBER + " TOOLCHANGE tool " + TOOL_NUMBER + " after " + PREVIOUS_TOOL_NUMBER + ": " + TOOL_NAME + " (" + TOOL_NOTES + ") dia " + TOOL_DIAMETER + " speed " + SPINDLE_SPEED + " cut " + CUT_RATE + " plunge " + PLUNGE_RATE + "\n";
}

function NEW_SEGMENT() {
    return LINE_NUMBER + " NEW_SEGMENT " + TOOLPATH_NAME + " (" + TOOLPATH_NOTES + ") tool " + TOOL_NUMBER + "\n";
}

function INITIAL_RAPID_MOVE() {
    return LINE_NUMBER + " INITIAL_RAPID_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " A " + A_POSITION + "\n";
}

function RAPID_MOVE() {
    return LINE_NUMBER + " RAPID_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " A " + A_POSITION + "\n";
}

function FIRST_FEED_MOVE() {
    return LINE_NUMBER + " FIRST_FEED_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n";
}

function FEED_MOVE() {
    return LINE_NUMBER + " FEED_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n";
}

function FIRST_PLUNGE_MOVE() {
    return LINE_NUMBER + " FIRST_PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + "\n";
}

function PLUNGE_MOVE() {
    return LINE_NUMBER + " PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + "\n";
}

function RETRACT_MOVE() {
    return LINE_NUMBER + " RETRACT_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + "\n";
}

function FIRST_CW_ARC_MOVE() {
    return LINE_NUMBER + " FIRST_CW_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n" +
        LINE_NUMBER + "   from " + ARC_START_X_POSITION + "," + ARC_START_Y_POSITION + " via " + ARC_MID_X_POSITION + "," + ARC_MID_Y_POSITION + " (rel " + ARC_MID_X_INC_POSITION + "," + ARC_MID_Y_INC_POSITION + ") centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " (rel " + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ") r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CW_ARC_MOVE() {
    return LINE_NUMBER + " CW_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n" +
        LINE_NUMBER + "   from " + ARC_START_X_POSITION + "," + ARC_START_Y_POSITION + " via " + ARC_MID_X_POSITION + "," + ARC_MID_Y_POSITION + " (rel " + ARC_MID_X_INC_POSITION + "," + ARC_MID_Y_INC_POSITION + ") centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " (rel " + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ") r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FIRST_CCW_ARC_MOVE() {
    return LINE_NUMBER + " FIRST_CCW_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n" +
        LINE_NUMBER + "   from " + ARC_START_X_POSITION + "," + ARC_START_Y_POSITION + " via " + ARC_MID_X_POSITION + "," + ARC_MID_Y_POSITION + " (rel " + ARC_MID_X_INC_POSITION + "," + ARC_MID_Y_INC_POSITION + ") centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " (rel " + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ") r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CCW_ARC_MOVE() {
    return LINE_NUMBER + " CCW_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " FI " + INVERSE_TIME + "\n" +
        LINE_NUMBER + "   from " + ARC_START_X_POSITION + "," + ARC_START_Y_POSITION + " via " + ARC_MID_X_POSITION + "," + ARC_MID_Y_POSITION + " (rel " + ARC_MID_X_INC_POSITION + "," + ARC_MID_Y_INC_POSITION + ") centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " (rel " + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ") r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FIRST_CW_HELICAL_ARC_MOVE() {
    return LINE_NUMBER + " FIRST_CW_HELICAL_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CW_HELICAL_ARC_MOVE() {
    return LINE_NUMBER + " CW_HELICAL_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FIRST_CCW_HELICAL_ARC_MOVE() {
    return LINE_NUMBER + " FIRST_CCW_HELICAL_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CCW_HELICAL_ARC_MOVE() {
    return LINE_NUMBER + " CCW_HELICAL_ARC_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FIRST_CW_HELICAL_ARC_PLUNGE_MOVE() {
    return LINE_NUMBER + " FIRST_CW_HELICAL_ARC_PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CW_HELICAL_ARC_PLUNGE_MOVE() {
    return LINE_NUMBER + " CW_HELICAL_ARC_PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE() {
    return LINE_NUMBER + " FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function CCW_HELICAL_ARC_PLUNGE_MOVE() {
    return LINE_NUMBER + " CCW_HELICAL_ARC_PLUNGE_MOVE " + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + " F " + FEED_RATE + " centre " + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + " r " + ARC_RADIUS + " angle " + ARC_ANGLE + "\n";
}

function FEED_RATE_CHANGE() {
    return LINE_NUMBER + " FEED_RATE_CHANGE " + FEED_RATE + "\n";
}

function DWELL_MOVE() {
    return LINE_NUMBER + " DWELL_MOVE " + DWELL_TIME + " s\n";
}

function JET_TOOL_ON() {
    return LINE_NUMBER + " JET_TOOL_ON power " + POWER + "\n";
}

function JET_TOOL_OFF() {
    return LINE_NUMBER + " JET_TOOL_OFF\n";
}

function JET_TOOL_POWER() {
    return LINE_NUMBER + " JET_TOOL_POWER " + POWER + "\n";
}

