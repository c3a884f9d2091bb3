// postc library: Haas VF-series (NGC and classic control) 3-axis mill, mm.
//
// Written for postc from Haas's mill programming conventions and the
// CNC-Calc Post Processor Manual (May 2014): a % tape start and end, an O
// program number of five digits, block numbers on tool changes (N1, N2, ...); G21 (metric)
// with G17 G40 G49 G80 G90 G94 and the G54 work offset; T/M06 tool changes
// with G43 H length offsets; G02/G03 with incremental I J (helical when Z
// changes); G04 P dwells in seconds (a P with a decimal point is seconds
// on a Haas); Z retracts through machine zero (G28 G91 Z0.); canned
// drilling cycles G81, G82 (dwell P in milliseconds: no decimal point) and
// G83 with G98 and G80.

var decimalMark = ".";
var linebreak = "\n";
var variableDelimeter = " ";
var tolerance = 0.01;
var showSequenceNumbers = false;
var sequenceNumberStart = 1;
var sequenceNumberIncrement = 1;
var useRadius = false;
var absoluteArcCenter = false;

PostInfo = {
    title: "Haas VF mill (mm)",
    summary: "Haas mill G-code: G81/G82/G83 canned cycles, G43 length offsets, G54",
    author: "postc",
    version: "1.0"
};

var MillDrillingFields = [
    {name: "Drilling", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 1, forceDecimal: true});
var toolFormat = createFormat({width: 2, zeropad: true, decimals: 0});
var rpmFormat = createFormat({decimals: 0});
var dwellFormat = createFormat({decimals: 3, forceDecimal: true});

var gMotion = createVariable({prefix: variableDelimeter + "G"}, createFormat({width: 2, zeropad: true, decimals: 0}));
var xOutput = createVariable({prefix: variableDelimeter + "X"}, xyzFormat);
var yOutput = createVariable({prefix: variableDelimeter + "Y"}, xyzFormat);
var zOutput = createVariable({prefix: variableDelimeter + "Z"}, xyzFormat);
var iOutput = createVariable({prefix: variableDelimeter + "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: variableDelimeter + "J", force: true}, xyzFormat);
var fOutput = createVariable({prefix: variableDelimeter + "F"}, feedFormat);

var sequenceNumber = sequenceNumberStart;
var clipboard = false;
var toolNumber = 0;
var pendingCompensation = "";
var drill = null;
var cycleStarted = false;

// One NC line: the words (each with its delimiter). Block numbers are
// printed on tool changes only (N1, N2, ...), where an operator restarts a
// program, unless showSequenceNumbers numbers every block; either way they
// stay within the five digits of the control.
function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = numbered(text);
    } else if (text.charAt(0) == variableDelimeter) {
        text = text.substring(1);
    }
    return text + linebreak;
}

function numbered(text) {
    if (sequenceNumber > 99999) {
        sequenceNumber = sequenceNumberStart;
    }
    text = "N" + sequenceNumber + text;
    sequenceNumber += sequenceNumberIncrement;
    return text;
}

// The feed word of a move when the feed changed; nothing for rapids.
function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return fOutput.format(parseFloat(f.substring(1)));
}

// An operator comment: upper case, without brackets.
function comment(text) {
    return writeBlock(variableDelimeter + "(" + String(text).replace(/[()]/g, "").toUpperCase() + ")");
}

// Up to machine Z zero (G28 through the point given, incremental 0), back to absolute.
function retractZ() {
    return writeBlock(" G28 G91 Z0.") + writeBlock(" G90");
}

function onInit() {
    clipboard = false;
}

function onOpen(isClipboard) {
    clipboard = isClipboard;
    if (isClipboard) {
        return "";
    }
    return "%" + linebreak
        + "O01000 (HAAS MILL)" + linebreak
        + writeBlock(" G21 G17 G40 G49 G80 G90 G94") + writeBlock(" G54");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    if (toolNumber != 0) {
        out += writeBlock(" M05") + retractZ();
    } else {
        out += retractZ();
    }
    toolNumber = tool;
    // The tool change block is numbered even without showSequenceNumbers.
    var change = " T" + toolFormat.format(tool) + " M06";
    // The tool change moves the axes: every word prints again after it.
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    fOutput.reset();
    return out + comment("T" + tool + " " + name + " D" + xyzFormat.format(diameter))
        + (showSequenceNumbers ? writeBlock(change) : numbered(change) + linebreak)
        + writeBlock(" G43 H" + toolFormat.format(tool))
        + writeBlock(" S" + rpmFormat.format(spindleSpeed) + " M03");
}

function onComment(text) {
    return comment(text);
}

function onDwell(seconds) {
    return writeBlock(" G04 P" + dwellFormat.format(seconds));
}

function onClose() {
    var out = writeBlock(" M05") + retractZ();
    if (!clipboard) {
        out += writeBlock(" M30") + "%" + linebreak;
    }
    return out;
}

function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        pendingCompensation = " G41 D" + toolFormat.format(toolNumber);
    } else if (comp == COMPENSATION_RIGHT) {
        pendingCompensation = " G42 D" + toolFormat.format(toolNumber);
    } else {
        pendingCompensation = " G40";
    }
}

function getCompensation() {
    var code = pendingCompensation;
    pendingCompensation = "";
    return code;
}

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

// The first hole starts the cycle; the others give only their position.
function onDrillingPoint(x, y) {
    if (cycleStarted) {
        return writeBlock(xOutput.format(x) + yOutput.format(y));
    }
    cycleStarted = true;
    var code = drill.firstDepth > 0 ? " G83" : (drill.useBottomDwelling ? " G82" : " G81");
    var block = " G98" + code + xOutput.format(x) + yOutput.format(y)
        + " Z" + xyzFormat.format(holeBottom()) + " R" + xyzFormat.format(rPlane());
    if (drill.firstDepth > 0) {
        block += " Q" + xyzFormat.format(drill.firstDepth);
    }
    if (drill.useBottomDwelling) {
        block += " P" + Math.round(drill.bottomDwelling * 1000);
    }
    return writeBlock(block + " F" + feedFormat.format(drill.plungingFeedrate));
}

function onDrillingFooter() {
    var out = "";
    if (cycleStarted) {
        out = writeBlock(" G80");
        // G80 cancels the motion mode and the cycle left Z at its start: G, Z and F print again.
        gMotion.reset();
        zOutput.reset();
        fOutput.reset();
    }
    cycleStarted = false;
    drill = null;
    return out;
}
