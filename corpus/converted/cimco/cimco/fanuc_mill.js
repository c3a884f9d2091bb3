// Converted by postc from fanuc_mill.js (CIMCO CNC-Calc JavaScript).
// Fanuc 0i-MF milling post for CIMCO CNC-Calc, written for the postc corpus
// from the CNC-Calc Post Processor Manual (May 2014): the Globals,
// createFormat and createVariable, the framework and movement functions,
// getFeedrate, onCompensation/getCompensation, and the milling drill cycles
// (G81 and G83 canned, and a peck cycle written out move by move).
//
// Every word carries the variable delimiter in front of it, so a word that
// is not output (a modal variable returning "") leaves no gap, and
// writeBlock only puts the block number in front.

// ------------------------------------------------------------------ Globals
var decimalMark = ".";
var linebreak = "\n";
var variableDelimeter = " ";
var tolerance = 0.01;
var showSequenceNumbers = true;
var sequenceNumberStart = 10;
var sequenceNumberIncrement = 10;
var useRadius = false;
var absoluteArcCenter = false;

// -------------------------------------------------------- Drilling UI fields
var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Longhand peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: true,
     firstDepth: true, degressionType: true, degression: true, peckingRetract: true,
     minimumDepth: true, firstFeedrateFactor: true, upperDwell: true, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

// ------------------------------------------------------ Formats and outputs
var xyzFormat = createFormat({prefix: "", width: 0, zeropad: false, decimals: 3, scale: 1.0, forceDecimal: true, forceSign: false});
var feedFormat = createFormat({decimals: 0});
var toolFormat = createFormat({width: 2, zeropad: true, decimals: 0});
var rpmFormat = createFormat({decimals: 0});
var dwellFormat = createFormat({decimals: 3});

var gMotion = createVariable({prefix: variableDelimeter + "G"}, createFormat({decimals: 0}));
var xOutput = createVariable({prefix: variableDelimeter + "X", force: false}, xyzFormat);
var yOutput = createVariable({prefix: variableDelimeter + "Y", force: false}, xyzFormat);
var zOutput = createVariable({prefix: variableDelimeter + "Z", force: false}, xyzFormat);
var iOutput = createVariable({prefix: variableDelimeter + "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: variableDelimeter + "J", force: true}, xyzFormat);

// -------------------------------------------------------------------- State
var sequenceNumber = sequenceNumberStart;
var clipboard = false;
var toolNumber = 0;
var pendingCompensation = "";
var drill = null;
var cycleStarted = false;

// ------------------------------------------------------------------ Helpers

// One NC line: the block number, then the words (each with its delimiter).
function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = "N" + sequenceNumber + text;
        sequenceNumber += sequenceNumberIncrement;
    }
    return text + linebreak;
}

// The feed word of a movement, with its delimiter; nothing for rapids.
function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return variableDelimeter + f;
}

// An operator comment; brackets inside would end it early.
function comment(text) {
    return writeBlock(variableDelimeter + "(" + String(text).replace(/[()]/g, "").toUpperCase() + ")");
}

// -------------------------------------------------------------- Framework
function onInit() {
    clipboard = false;
}

function onOpen(isClipboard) {
    clipboard = isClipboard;
    if (isClipboard) {
        return "";
    }
    return "%" + linebreak
        + "O1000 (FANUC 0I-MF MILL)" + linebreak
        + writeBlock(" G90 G94 G17 G21 G40 G80");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    toolNumber = tool;
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return comment("T" + tool + " " + name + " D" + xyzFormat.format(diameter))
        + writeBlock(" T" + toolFormat.format(tool) + " M6")
        + writeBlock(" S" + rpmFormat.format(spindleSpeed) + " M3");
}

function onComment(text) {
    return comment(text);
}

function onDwell(seconds) {
    return writeBlock(" G4 X" + dwellFormat.format(seconds));
}

function onClose() {
    var out = writeBlock(" G80 G40") + writeBlock(" M5") + writeBlock(" G91 G28 Z0.");
    if (!clipboard) {
        out += writeBlock(" M30") + "%" + linebreak;
    }
    return out;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        pendingCompensation = " G41 D" + toolNumber;
    } else if (comp == COMPENSATION_RIGHT) {
        pendingCompensation = " G42 D" + toolNumber;
    } else {
        pendingCompensation = " G40";
    }
}

function getCompensation() {
    var code = pendingCompensation;
    pendingCompensation = "";
    return code;
}

// --------------------------------------------------------------- Movement
function onLinear(vx, vy, vz, movement) {
    var xyz = xOutput.format(vx) + yOutput.format(vy) + zOutput.format(vz);
    if (xyz == "") {
        return "";
    }
    return writeBlock(getCompensation() + gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1) + xyz + feedWord(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    // The arc starts where the last move ended.
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    var centre = iOutput.format(cx - sx) + jOutput.format(cy - sy);
    return writeBlock(gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + zOutput.format(ez) + centre + feedWord(movement));
}

// ---------------------------------------------------------------- Drilling
function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleStarted = false;
    return "";
}

// The absolute Z of the bottom of the hole and of the R plane.
function holeBottom() {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhandHole(x, y);
    }
    if (cycleStarted) {
        return writeBlock(xOutput.format(x) + yOutput.format(y));
    }
    cycleStarted = true;
    var peck = drill.name == "Peck drilling (G83)";
    var block = " G98" + (peck ? " G83" : (drill.useBottomDwelling ? " G82" : " G81"))
        + xOutput.format(x) + yOutput.format(y)
        + " Z" + xyzFormat.format(holeBottom()) + " R" + xyzFormat.format(rPlane());
    if (peck) {
        block += " Q" + xyzFormat.format(drill.firstDepth);
    }
    if (drill.useBottomDwelling) {
        block += " P" + Math.round(drill.bottomDwelling * 1000);
    }
    block += " F" + feedFormat.format(drill.plungingFeedrate);
    return writeBlock(block);
}

// A peck-drilled hole written out move by move.
function longhandHole(x, y) {
    var top = rPlane();
    var bottom = holeBottom();
    var step = drill.firstDepth > 0 ? drill.firstDepth : top - bottom;
    var depth = top;
    var pecks = 0;
    var out = writeBlock(gMotion.format(0) + xOutput.format(x) + yOutput.format(y));
    out += writeBlock(zOutput.format(top));
    do {
        depth = Math.max(depth - step, bottom);
        pecks++;
        var feed = drill.plungingFeedrate;
        if (pecks == 1 && drill.firstFeedrateFactor > 0) {
            feed *= drill.firstFeedrateFactor;
        }
        out += writeBlock(gMotion.format(1) + zOutput.format(depth) + " F" + feedFormat.format(feed));
        if (drill.useBottomDwelling && depth <= bottom) {
            out += writeBlock(" G4 X" + dwellFormat.format(drill.bottomDwelling));
        }
        out += writeBlock(gMotion.format(0) + zOutput.format(depth < bottom + tolerance ? top : Math.min(top, depth + 1)));
    } while (depth > bottom + tolerance);
    out += writeBlock(gMotion.format(0) + zOutput.format(drill.retractPlane));
    return out;
}

function onDrillingFooter() {
    var out = "";
    if (cycleStarted && !drill.isLonghand) {
        out = writeBlock(" G80");
        // G98 leaves the tool at the level it started the cycle from, and
        // G80 cancels the motion mode: Z and G print again.
        gMotion.reset();
        zOutput.reset();
    }
    cycleStarted = false;
    drill = null;
    return out;
}
