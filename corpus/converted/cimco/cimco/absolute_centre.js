// Converted by postc from absolute_centre.js (CIMCO CNC-Calc JavaScript).
// ISO milling post with absolute arc centres (absoluteArcCenter) for CIMCO
// CNC-Calc, written for the postc corpus from the CNC-Calc Post Processor
// Manual: I and J are the centre's coordinates, not its offset from the
// arc's start (controls such as the old Fagor and Heidenhain ISO modes, or
// G90.1 on others). Blocks have no numbers and words no blanks.

var decimalMark = ",";
var linebreak = "\r\n";
var variableDelimeter = "";
var tolerance = 0.01;
var showSequenceNumbers = false;
var sequenceNumberStart = 10;
var sequenceNumberIncrement = 10;
var useRadius = false;
var absoluteArcCenter = true;

var MillDrillingFields = [
    {name: "Longhand drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var iOutput = createVariable({prefix: "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: "J", force: true}, xyzFormat);
var gMotion = createVariable({prefix: "G"}, createFormat({decimals: 0, width: 2, zeropad: true}));

var compensation = "";
var drill = null;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    return text + linebreak;
}

function onOpen(isClipboard) {
    return writeBlock("%") + writeBlock("G90G17G71G90.1");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return writeBlock("T" + tool + "M06") + writeBlock("S" + spindleSpeed + "M03");
}

function onDwell(seconds) {
    return writeBlock("G04K" + xyzFormat.format(seconds));
}

function onClose() {
    return writeBlock("M05") + writeBlock("M30") + writeBlock("%");
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? "G41" : comp == COMPENSATION_RIGHT ? "G42" : "G40";
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vy, vz, movement) {
    return writeBlock(getCompensation() + gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1)
        + xOutput.format(vx) + yOutput.format(vy) + zOutput.format(vz) + getFeedrate(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var centre = absoluteArcCenter ? iOutput.format(cx) + jOutput.format(cy)
        : iOutput.format(cx - xOutput.getLast()) + jOutput.format(cy - yOutput.getLast());
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + zOutput.format(ez)
        + centre + getFeedrate(movement));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    return "";
}

function onDrillingPoint(x, y) {
    var out = writeBlock(gMotion.format(0) + xOutput.format(x) + yOutput.format(y));
    out += writeBlock(zOutput.format(drill.safeDistance));
    out += writeBlock(gMotion.format(1) + zOutput.format(drill.endDepth) + "F" + Math.round(drill.plungingFeedrate));
    if (drill.useBottomDwelling) {
        out += writeBlock("G04K" + xyzFormat.format(drill.bottomDwelling));
    }
    return out + writeBlock(gMotion.format(0) + zOutput.format(drill.retractPlane));
}

function onDrillingFooter() {
    drill = null;
    return "";
}
