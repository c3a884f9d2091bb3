// Converted by postc from iso_mill.js (CIMCO CNC-Calc JavaScript).
/*
 * Generic ISO milling post for CIMCO CNC-Calc, written for the postc corpus
 * from the CNC-Calc Post Processor Manual (May 2014), in the newer style:
 * a `globals` object and `PostInfo`. Words are packed without blanks, block
 * numbers are off, and coordinates print at most three decimals with
 * trailing zeros dropped (X12.5, X40). Every drilling cycle is written out
 * as moves.
 */

globals = {
    decimalMark: ".",
    linebreak: "\n",
    variableDelimeter: "",
    tolerance: 0.01,
    showSequenceNumbers: false,
    sequenceNumberStart: 1,
    sequenceNumberIncrement: 1,
    useRadius: false,
    absoluteArcCenter: false
};

PostInfo = {
    title: "Generic ISO mill",
    summary: "G-code without blanks or block numbers; drilling as moves",
    author: "postc corpus",
    version: "1.0",
    type: POST_TYPE_MILL
};

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3});
var gFormat = createFormat({width: 2, zeropad: true, decimals: 0});
var gMotion = createVariable({prefix: "G"}, gFormat);
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var iOutput = createVariable({prefix: "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: "J", force: true}, xyzFormat);
var drill;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    return text + globals.linebreak;
}

function onOpen(isClipboard) {
    if (isClipboard) {
        return "";
    }
    return writeBlock("%") + writeBlock("(" + PostInfo.title.toUpperCase() + ")") + writeBlock("G90G17G21G40G49G80");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return writeBlock("T" + tool + "M06") + writeBlock("S" + Math.round(spindleSpeed) + "M03");
}

function onDwell(seconds) {
    return writeBlock("G04P" + xyzFormat.format(seconds));
}

function onClose() {
    return writeBlock("M05") + writeBlock("M30") + writeBlock("%");
}

var compensation = "";

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
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + zOutput.format(ez)
        + iOutput.format(cx - sx) + jOutput.format(cy - sy) + getFeedrate(movement));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    return "";
}

// Every hole as moves: over it, down to the R plane, pecks (or one feed
// down), a dwell at the bottom, and back up to the retract plane.
function onDrillingPoint(x, y) {
    var top = drill.safeDistance;
    var bottom = drill.endDepth;
    var peck = drill.firstDepth > 0 ? drill.firstDepth : top - bottom;
    var feed = "F" + Math.round(drill.plungingFeedrate);
    var out = writeBlock(gMotion.format(0) + xOutput.format(x) + yOutput.format(y));
    out += writeBlock(zOutput.format(top));
    var depth = top;
    while (depth > bottom) {
        depth = Math.max(depth - peck, bottom);
        out += writeBlock(gMotion.format(1) + zOutput.format(depth) + feed);
        if (depth > bottom) {
            out += writeBlock(gMotion.format(0) + zOutput.format(top));
            out += writeBlock(zOutput.format(depth + 0.5));
        }
    }
    if (drill.useBottomDwelling) {
        out += writeBlock("G04P" + xyzFormat.format(drill.bottomDwelling));
    }
    return out + writeBlock(gMotion.format(0) + zOutput.format(drill.retractPlane));
}

function onDrillingFooter() {
    drill = null;
    return "";
}
