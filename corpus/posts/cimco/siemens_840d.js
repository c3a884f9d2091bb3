// Siemens Sinumerik 840D milling post for CIMCO CNC-Calc, written for the
// postc corpus from the CNC-Calc Post Processor Manual (May 2014).
//
// ISO moves with 840D conventions: comments after ';', tools as T and D,
// and the canned drilling cycles CYCLE81 (drilling) and CYCLE83 (deep hole
// drilling) switched on modally with MCALL, which every hole position then
// calls; a plain MCALL switches the cycle off. Longhand cycles move the tool.

var decimalMark = ".";
var linebreak = "\r\n";
var variableDelimeter = " ";
var tolerance = 0.01;
var showSequenceNumbers = true;
var sequenceNumberStart = 10;
var sequenceNumberIncrement = 10;
var useRadius = false;
var absoluteArcCenter = false;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: true, degression: true, peckingRetract: false,
     minimumDepth: true, firstFeedrateFactor: false, upperDwell: true, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Longhand peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var paramFormat = createFormat({decimals: 3});
var gMotion = createVariable({prefix: " G"}, createFormat({decimals: 0}));
var xOutput = createVariable({prefix: " X"}, xyzFormat);
var yOutput = createVariable({prefix: " Y"}, xyzFormat);
var zOutput = createVariable({prefix: " Z"}, xyzFormat);
var iOutput = createVariable({prefix: " I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: " J", force: true}, xyzFormat);
var fOutput = createVariable({prefix: " F"}, createFormat({decimals: 1}));

var sequence = sequenceNumberStart;
var compensation = "";
var drill = null;
var cycleOn = false;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    text = "N" + sequence + text;
    sequence += sequenceNumberIncrement;
    return text + linebreak;
}

function onOpen(isClipboard) {
    return "; CNC-CALC SIEMENS 840D" + linebreak + writeBlock(" G17 G90 G94 G71 G40");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return writeBlock(" ; " + name) + writeBlock(" T" + tool + " D1") + writeBlock(" M6")
        + writeBlock(" S" + Math.round(spindleSpeed) + " M3");
}

function onComment(text) {
    return writeBlock(" ; " + text);
}

function onDwell(seconds) {
    return writeBlock(" G4 F" + paramFormat.format(seconds));
}

function onClose() {
    return writeBlock(" G40 M5") + writeBlock(" G0 SUPA Z0") + writeBlock(" M30");
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? " G41" : comp == COMPENSATION_RIGHT ? " G42" : " G40";
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

// The feed word when the feed changed (the 840D keeps F modal).
function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return fOutput.format(parseFloat(f.substring(1)));
}

function onLinear(vx, vy, vz, movement) {
    var xyz = xOutput.format(vx) + yOutput.format(vy) + zOutput.format(vz);
    if (xyz == "") {
        return "";
    }
    return writeBlock(getCompensation() + gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1) + xyz + feedWord(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    var centre = iOutput.format(cx - sx) + jOutput.format(cy - sy);
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + zOutput.format(ez) + centre + feedWord(movement));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleOn = false;
    return "";
}

// CYCLE81(RTP, RFP, SDIS, DP, DPR) and CYCLE83(RTP, RFP, SDIS, DP, DPR,
// FDEP, FDPR, DAM, DTB, DTS, FRF, VARI): the reference plane RFP is the
// top of the hole (the seed's referencePlane) and the safety clearance SDIS
// the R plane above it (the seed's safe distance).
function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

function cycleCall() {
    var p = function (v) { return paramFormat.format(v); };
    var common = p(drill.retractPlane) + ", " + p(drill.referencePlane) + ", " + p(rPlane() - drill.referencePlane) + ", " + p(drill.endDepth) + ", ";
    if (drill.name == "Peck drilling (G83)") {
        var first = drill.referencePlane - drill.firstDepth;
        var dwell = drill.useBottomDwelling ? p(drill.bottomDwelling) : "0";
        return " MCALL CYCLE83(" + common + ", " + p(first) + ", , " + p(drill.firstDepth) + ", " + dwell + ", 0, 1, 1)";
    }
    var dtb = drill.useBottomDwelling ? ", " + p(drill.bottomDwelling) : "";
    return " MCALL CYCLE8" + (drill.useBottomDwelling ? "2" : "1") + "(" + common + dtb + ")";
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhand(x, y);
    }
    var out = "";
    if (!cycleOn) {
        cycleOn = true;
        out += writeBlock(gMotion.format(0) + zOutput.format(drill.retractPlane));
        out += writeBlock(fOutput.format(drill.plungingFeedrate));
        out += writeBlock(cycleCall());
        // MCALL drills after each block that moves, not where the tool is:
        // the first hole's X and Y print even when the tool is over it.
        xOutput.reset();
        yOutput.reset();
    }
    return out + writeBlock(xOutput.format(x) + yOutput.format(y));
}

function longhand(x, y) {
    var out = writeBlock(gMotion.format(0) + xOutput.format(x) + yOutput.format(y));
    out += writeBlock(zOutput.format(rPlane()));
    var depth = rPlane();
    var step = drill.firstDepth > 0 ? drill.firstDepth : depth - drill.endDepth;
    for (var n = 0; depth > drill.endDepth && n < 100; n++) {
        depth = Math.max(depth - step, drill.endDepth);
        out += writeBlock(gMotion.format(1) + zOutput.format(depth) + fOutput.format(drill.plungingFeedrate));
        out += writeBlock(gMotion.format(0) + zOutput.format(rPlane()));
    }
    if (drill.useBottomDwelling) {
        out += writeBlock(" G4 F" + paramFormat.format(drill.bottomDwelling));
    }
    return out + writeBlock(zOutput.format(drill.retractPlane));
}

function onDrillingFooter() {
    var out = "";
    if (cycleOn) {
        out = writeBlock(" MCALL");
        // The cycle's own moves leave G and Z to the controller: print them again.
        gMotion.reset();
        zOutput.reset();
    }
    cycleOn = false;
    drill = null;
    return out;
}
