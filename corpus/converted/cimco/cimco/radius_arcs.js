// Converted by postc from radius_arcs.js (CIMCO CNC-Calc JavaScript).
// ISO milling post with radius arcs (useRadius) for CIMCO CNC-Calc,
// written for the postc corpus from the CNC-Calc Post Processor Manual.
//
// With useRadius true the host never passes an arc of 180 degrees or more:
// postc (and any CNC-Calc host following docs/cimco.md) splits such arcs,
// full circles included, into equal parts, so R is always the positive
// radius. The radius is the distance from the centre to the arc's start,
// the last point written.

var decimalMark = ".";
var linebreak = "\n";
var variableDelimeter = " ";
var tolerance = 0.01;
var showSequenceNumbers = true;
var sequenceNumberStart = 1;
var sequenceNumberIncrement = 1;
var useRadius = true;
var absoluteArcCenter = false;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 4, forceDecimal: true});
var xOutput = createVariable({prefix: " X"}, xyzFormat);
var yOutput = createVariable({prefix: " Y"}, xyzFormat);
var zOutput = createVariable({prefix: " Z"}, xyzFormat);
var rOutput = createVariable({prefix: " R", force: true}, xyzFormat);
var gMotion = createVariable({prefix: " G"}, createFormat({decimals: 0}));

var n = sequenceNumberStart;
var compensation = "";
var drill = null;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = "N" + n + text;
        n += sequenceNumberIncrement;
    }
    return text + linebreak;
}

function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return variableDelimeter + f;
}

function onOpen(isClipboard) {
    return writeBlock(" G90 G17 G21") + writeBlock(" G40 G49 G80");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return writeBlock(" T" + tool + " M6") + writeBlock(" S" + spindleSpeed + " M3");
}

function onDwell(seconds) {
    return writeBlock(" G4 P" + Math.round(seconds * 1000));
}

function onClose() {
    return writeBlock(" M5") + writeBlock(" M30");
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? " G41" : comp == COMPENSATION_RIGHT ? " G42" : " G40";
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vy, vz, movement) {
    return writeBlock(getCompensation() + gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1)
        + xOutput.format(vx) + yOutput.format(vy) + zOutput.format(vz) + feedWord(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    var radius = Math.sqrt((sx - cx) * (sx - cx) + (sy - cy) * (sy - cy));
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + zOutput.format(ez)
        + rOutput.format(radius) + feedWord(movement));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    return "";
}

function onDrillingPoint(x, y) {
    return writeBlock(" G81" + xOutput.format(x) + yOutput.format(y) + " Z" + xyzFormat.format(drill.endDepth)
        + " R" + xyzFormat.format(drill.safeDistance) + " F" + Math.round(drill.plungingFeedrate));
}

function onDrillingFooter() {
    // G81 leaves the tool at the level it started the cycle from, and G80
    // cancels the motion mode: Z and G print again.
    gMotion.reset();
    zOutput.reset();
    drill = null;
    return writeBlock(" G80");
}
