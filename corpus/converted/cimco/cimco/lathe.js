// Converted by postc from lathe.js (CIMCO CNC-Calc JavaScript).
/*
 * Fanuc-style lathe post for CIMCO CNC-Calc, written for the postc corpus
 * from the CNC-Calc Post Processor Manual (May 2014): the `globals` object
 * with diameter programming, PostInfo of type POST_TYPE_TURN, the turning
 * onLinear(vx, vz, movement) and onCircular(cx, cz, ex, ez, isCW,
 * movement), and TurnDrillingFields with onDrilling.
 *
 * X values arrive as radii; xDiameterProg doubles them through the X
 * format's scale. Arc centres are I (radius, as iDiameterProg is false) and
 * K, relative to the arc's start. Drilling on the spindle axis uses G83
 * (with Q for pecking) or the moves of a longhand cycle.
 */

globals = {
    decimalMark: ".",
    linebreak: "\n",
    variableDelimeter: " ",
    tolerance: 0.01,
    showSequenceNumbers: true,
    sequenceNumberStart: 10,
    sequenceNumberIncrement: 10,
    useRadius: false,
    absoluteArcCenter: false,
    xDiameterProg: true,
    iDiameterProg: false
};

PostInfo = {
    title: "Fanuc lathe",
    summary: "Diameter programming, G83 and longhand drilling on the axis",
    author: "postc corpus",
    version: "1.0",
    type: POST_TYPE_TURN
};

TurnDrillingFields = [
    {name: "Centre drill", isLonghand: false, plungingFeedrate: true, retractFeedrate: false, usePecking: false,
     firstPeckDepth: false, subsequentPeckDepths: false, peckClearance: false, peckRetract: false,
     useUpperDwell: false, uselowerDwell: true, pitch: false},
    {name: "Peck drill (G74)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false, usePecking: true,
     firstPeckDepth: true, subsequentPeckDepths: true, peckClearance: false, peckRetract: false,
     useUpperDwell: false, uselowerDwell: true, pitch: false},
    {name: "Longhand peck", isLonghand: true, plungingFeedrate: true, retractFeedrate: false, usePecking: true,
     firstPeckDepth: true, subsequentPeckDepths: true, peckClearance: true, peckRetract: true,
     useUpperDwell: false, uselowerDwell: true, pitch: false}
];

var xOutput = createVariable({prefix: " X"}, createFormat({decimals: 3, forceDecimal: true, scale: globals.xDiameterProg ? 2 : 1}));
var zOutput = createVariable({prefix: " Z"}, createFormat({decimals: 3, forceDecimal: true}));
var iOutput = createVariable({prefix: " I", force: true}, createFormat({decimals: 3, forceDecimal: true, scale: globals.iDiameterProg ? 2 : 1}));
var kOutput = createVariable({prefix: " K", force: true}, createFormat({decimals: 3, forceDecimal: true}));
var gMotion = createVariable({prefix: " G"}, createFormat({decimals: 0}));
var zFormat = createFormat({decimals: 3, forceDecimal: true});
var toolFormat = createFormat({decimals: 0, width: 2, zeropad: true});

var sequence = globals.sequenceNumberStart;
var compensation = "";

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (globals.showSequenceNumbers) {
        text = "N" + sequence + text;
        sequence += globals.sequenceNumberIncrement;
    }
    return text + globals.linebreak;
}

function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return globals.variableDelimeter + f;
}

function onOpen(isClipboard) {
    return "%" + globals.linebreak + "O2000 (" + PostInfo.title.toUpperCase() + ")" + globals.linebreak
        + writeBlock(" G18 G21 G40 G99");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var t = toolFormat.format(tool);
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    zOutput.reset();
    return writeBlock(" T" + t + t + " (" + name.toUpperCase() + ")") + writeBlock(" G97 S" + spindleSpeed + " M3");
}

function onDwell(seconds) {
    return writeBlock(" G4 U" + zFormat.format(seconds));
}

function onClose() {
    return writeBlock(" G28 U0. W0.") + writeBlock(" M5") + writeBlock(" M30") + "%" + globals.linebreak;
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? " G41" : comp == COMPENSATION_RIGHT ? " G42" : " G40";
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vz, movement) {
    return writeBlock(getCompensation() + gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1)
        + xOutput.format(vx) + zOutput.format(vz) + feedWord(movement));
}

function onCircular(cx, cz, ex, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sz = zOutput.getLast();
    var centre = iOutput.format(cx - sx) + kOutput.format(cz - sz);
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + zOutput.format(ez) + centre + feedWord(movement));
}

// Drilling on the spindle axis; X is zero.
function onDrilling(drillHeader) {
    var d = drillHeader;
    var out = writeBlock(gMotion.format(0) + xOutput.format(0) + zOutput.format(d.safeDistance));
    var feed = " F" + Math.round(d.plungingFeedrate * 100) / 100;
    if (d.isLonghand) {
        var depth = d.safeDistance;
        var first = true;
        while (depth > d.endDepth) {
            depth = Math.max(depth - (first ? d.firstPeckDepth : d.subsequentPecksDepths), d.endDepth);
            first = false;
            out += writeBlock(gMotion.format(1) + zOutput.format(depth) + feed);
            out += writeBlock(gMotion.format(0) + zOutput.format(d.safeDistance));
            if (depth > d.endDepth) {
                out += writeBlock(zOutput.format(depth + 0.5));
            }
        }
    } else {
        var q = d.usePecking ? " Q" + Math.round(d.firstPeckDepth * 1000) : "";
        var p = d.useLowerDwell ? " P" + Math.round(d.lowerDwell * 1000) : "";
        out += writeBlock(" G83" + zOutput.format(d.endDepth) + " R" + zFormat.format(d.safeDistance - d.startDepth) + q + p + feed);
        out += writeBlock(" G80");
        // G80 cancels the motion mode: G prints again.
        gMotion.reset();
        zOutput.format(d.safeDistance);
    }
    return out + writeBlock(gMotion.format(0) + zOutput.format(d.retractDistance));
}
