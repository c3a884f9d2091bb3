// Converted by postc from hpgl_arcs.pp (Vectric).
//================================================
//
// postc: a generic HPGL plotter post with arcs, in the style of the
// "Generic HPGL_Arcs.pp" the Vectric guide names. 40 plotter units per mm.
// [Angle] is the arc sweep in radians (counter-clockwise positive); the
// multiplier turns it into the degrees HPGL AA wants.
//
//================================================
// A section post: postc's extension of CNC-Calc (docs/cimco.md); CNC-Calc itself does not run it.

var postcOptions = {
    name: "Generic HPGL Arcs (*.plt)",
    fileExtension: "plt",
    units: "MM",
    lineEnding: "\r\n",
    onChangeByValue: true,
    rapidForgetsFeed: true,
    blockNumbers: [0, 10, 999999],
};

var X_POSITION = createVariable({prefix: "", label: "X"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));
var Y_POSITION = createVariable({prefix: "", label: "Y"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));
var ARC_CENTRE_I_ABS_POSITION = createVariable({prefix: "", label: "IA"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));
var ARC_CENTRE_J_ABS_POSITION = createVariable({prefix: "", label: "JA"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));
var ARC_ANGLE = createVariable({prefix: "", label: "Angle"}, createFormat({scale: 57.2957795, negativeZero: true}));
var X_HOME_POSITION = createVariable({prefix: "", label: "XH"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));
var Y_HOME_POSITION = createVariable({prefix: "", label: "YH"}, createFormat({decimals: 0, scale: 40, negativeZero: true}));

function HEADER() {
    return "IN;PA;\n";
}

function FOOTER() {
    return "PU" + X_HOME_POSITION + "," + Y_HOME_POSITION + ";\n" +
        "SP0;\n";
}

function RAPID_MOVE() {
    return "PU" + X_POSITION + "," + Y_POSITION + ";\n";
}

function FEED_MOVE() {
    return "PD" + X_POSITION + "," + Y_POSITION + ";\n";
}

function CW_ARC_MOVE() {
    return "AA" + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + "," + ARC_ANGLE + "\n";
}

function CCW_ARC_MOVE() {
    return "AA" + ARC_CENTRE_I_ABS_POSITION + "," + ARC_CENTRE_J_ABS_POSITION + "," + ARC_ANGLE + "\n";
}

