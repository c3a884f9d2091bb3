// Converted by postc from shopbot_inch.pp (Vectric).
//================================================
//
// postc corpus: ShopBot OpenSBP with tool changes (inch).
//
// Demonstrates:
// - OpenSBP commands: J2/J3/JZ jogs, M3 moves, CG arcs (1 clockwise,
//   -1 counter-clockwise, centre relative to the start), MS speeds,
//   TR spindle rpm, PAUSE for dwells, C6/C7/C9 custom cuts;
// - speeds in inches per second: [F] [FC] [FP] through a multiplier of
//   1/60;
// - INITIAL_RAPID_MOVE: the first rapid after the header or a tool
//   change jogs XY first, then Z;
// - FEED_RATE_CHANGE setting MS when the feed changes (M3 carries no
//   speed);
// - arc sections without [Z]: helices are linearized;
// - the defaults of undeclared labels: [XMIN] [XMAX] [YMIN] [YMAX]
//   [ZMIN] [ZMAX] print with no prefix and 3 decimals, so the line
//   writes its own blanks, as VCarve's ShopBot posts do
//   ("'Length of material in X = [XLENGTH]");
// - job data: [Z_ORIGIN] [XY_ORIGIN] [X_ORIGIN_POS] [Y_ORIGIN_POS]
//   [SAFEZ] [ZLENGTH] [FILE_NOTES] [TOOLPATHS_OUTPUT] [DATE] [TIME]
//   [PRODUCT];
// - SUBSTITUTE with a [nn] code: commas in names print as ;.
//
//================================================
// Commas separate OpenSBP arguments.
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "ShopBot TC (inch) (*.sbp)",
    fileExtension: "sbp",
    units: "INCH",
    lineEnding: "\r\n",
    substitute: [[",", ";"]],
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
};

var SPINDLE_SPEED = createVariable({prefix: "", label: "S"}, createFormat({decimals: 0, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "", label: "F"}, createFormat({scale: 0.0166667, negativeZero: true}));
var CUT_RATE = createVariable({prefix: "", label: "FC"}, createFormat({scale: 0.0166667, negativeZero: true}));
var PLUNGE_RATE = createVariable({prefix: "", label: "FP"}, createFormat({scale: 0.0166667, negativeZero: true}));
var X_POSITION = createVariable({prefix: "", label: "X"}, createFormat({decimals: 4, negativeZero: true}));
var Y_POSITION = createVariable({prefix: "", label: "Y"}, createFormat({decimals: 4, negativeZero: true}));
var Z_POSITION = createVariable({prefix: "", label: "Z"}, createFormat({decimals: 4, negativeZero: true}));
var ARC_CENTRE_I_INC_POSITION = createVariable({prefix: "", label: "I"}, createFormat({decimals: 4, negativeZero: true}));
var ARC_CENTRE_J_INC_POSITION = createVariable({prefix: "", label: "J"}, createFormat({decimals: 4, negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "", label: "XH"}, createFormat({decimals: 4, negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "", label: "YH"}, createFormat({decimals: 4, negativeZero: true}));
var Z_HOME_POSITION = createVariable({prefix: "", label: "ZH"}, createFormat({decimals: 4, negativeZero: true}));
var SAFE_Z_HEIGHT = createVariable({prefix: "", label: "SAFEZ"}, createFormat({decimals: 4, negativeZero: true}));
var Z_LENGTH = createVariable({prefix: "", label: "ZLENGTH"}, createFormat({decimals: 4, negativeZero: true}));
var X_ORIGIN_POS = createVariable({prefix: "", label: "X_ORIGIN_POS"}, createFormat({decimals: 4, negativeZero: true}));
var Y_ORIGIN_POS = createVariable({prefix: "", label: "Y_ORIGIN_POS"}, createFormat({decimals: 4, negativeZero: true}));
var DWELL_TIME = createVariable({prefix: "", label: "DWELL"}, createFormat({decimals: 2, negativeZero: true}));
var TOOLPATH_FILENAME = createVariable({prefix: "", label: "TP_FILENAME"}, createFormat({decimals: 0, negativeZero: true}));
var PRODUCT = createVariable({prefix: "", label: "PRODUCT"}, createFormat({decimals: 0, negativeZero: true}));
var DATE = createVariable({prefix: "", label: "DATE"}, createFormat({decimals: 0, negativeZero: true}));
var TIME = createVariable({prefix: "", label: "TIME"}, createFormat({decimals: 0, negativeZero: true}));
var X_MIN = createVariable({prefix: "", label: "XMIN"}, createFormat({negativeZero: true}));
var X_MAX = createVariable({prefix: "", label: "XMAX"}, createFormat({negativeZero: true}));
var Y_MIN = createVariable({prefix: "", label: "YMIN"}, createFormat({negativeZero: true}));
var Y_MAX = createVariable({prefix: "", label: "YMAX"}, createFormat({negativeZero: true}));
var Z_MIN = createVariable({prefix: "", label: "ZMIN"}, createFormat({negativeZero: true}));
var Z_MAX = createVariable({prefix: "", label: "ZMAX"}, createFormat({negativeZero: true}));
var XY_ORIGIN = createVariable({prefix: "", label: "XY_ORIGIN"}, createFormat({decimals: 0, negativeZero: true}));
var FILE_NOTES = createVariable({prefix: "", label: "FILE_NOTES"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATHS_OUTPUT = createVariable({prefix: "", label: "TOOLPATHS_OUTPUT"}, createFormat({decimals: 0, negativeZero: true}));
var Z_ORIGIN = createVariable({prefix: "", label: "Z_ORIGIN"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NUMBER = createVariable({prefix: "", label: "T"}, createFormat({decimals: 0, negativeZero: true}));
var TOOL_NAME = createVariable({prefix: "", label: "TOOLNAME"}, createFormat({decimals: 0, negativeZero: true}));
var PREVIOUS_TOOL_NUMBER = createVariable({prefix: "", label: "TP"}, createFormat({decimals: 0, negativeZero: true}));
var TOOLPATH_NAME = createVariable({prefix: "", label: "TOOLPATH_NAME"}, createFormat({decimals: 0, negativeZero: true}));

function HEADER() {
    return "'" + TOOLPATH_FILENAME + "\n" +
        "'Made by " + PRODUCT + " on " + DATE + " at " + TIME + "\n" +
        "'Material X " + X_MIN + " to " + X_MAX + ", Y " + Y_MIN + " to " + Y_MAX + ", Z " + Z_MIN + " to " + Z_MAX + "\n" +
        "'Origin " + XY_ORIGIN + " at " + X_ORIGIN_POS + ", " + Y_ORIGIN_POS + "\n" +
        "'Notes: " + FILE_NOTES + "\n" +
        "'Toolpaths: " + TOOLPATHS_OUTPUT + "\n" +
        "&PWZorigin = " + Z_ORIGIN + "\n" +
        "&PWSafeZ = " + SAFE_Z_HEIGHT + "\n" +
        "&PWMaterial = " + Z_LENGTH + "\n" +
        "SA\n" +
        "'Tool " + TOOL_NUMBER + ": " + TOOL_NAME + "\n" +
        "&Tool = " + TOOL_NUMBER + "\n" +
        "C9\n" +
        "MS," + CUT_RATE + "," + PLUNGE_RATE + "\n" +
        "JZ," + Z_HOME_POSITION + "\n" +
        "J2," + X_HOME_POSITION + "," + Y_HOME_POSITION + "\n";
}

function FOOTER() {
    return "C7\n" +
        "JZ," + Z_HOME_POSITION + "\n" +
        "J2," + X_HOME_POSITION + "," + Y_HOME_POSITION + "\n" +
        "END\n";
}

function SPINDLE_ON() {
    return "TR," + SPINDLE_SPEED + "\n" +
        "C6\n" +
        "PAUSE 2\n";
}

function TOOLCHANGE() {
    return "C7\n" +
        "'Tool " + TOOL_NUMBER + ": " + TOOL_NAME + " replaces tool " + PREVIOUS_TOOL_NUMBER + "\n" +
        "&Tool = " + TOOL_NUMBER + "\n" +
        "C9\n";
}

function NEW_SEGMENT() {
    return "'Toolpath: " + TOOLPATH_NAME + "\n" +
        "MS," + CUT_RATE + "," + PLUNGE_RATE + "\n";
}

function INITIAL_RAPID_MOVE() {
    return "J2," + X_POSITION + "," + Y_POSITION + "\n" +
        "JZ," + Z_POSITION + "\n";
}

function RAPID_MOVE() {
    return "J3," + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + "\n";
}

function FEED_MOVE() {
    return "M3," + X_POSITION + "," + Y_POSITION + "," + Z_POSITION + "\n";
}

function CW_ARC_MOVE() {
    return "CG,," + X_POSITION + "," + Y_POSITION + "," + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ",T,1\n";
}

function CCW_ARC_MOVE() {
    return "CG,," + X_POSITION + "," + Y_POSITION + "," + ARC_CENTRE_I_INC_POSITION + "," + ARC_CENTRE_J_INC_POSITION + ",T,-1\n";
}

function FEED_RATE_CHANGE() {
    return "MS," + FEED_RATE + "," + PLUNGE_RATE + "\n";
}

function DWELL_MOVE() {
    return "PAUSE " + DWELL_TIME + "\n";
}

