// Converted by postc from heidenhain.js (CIMCO CNC-Calc JavaScript).
// Heidenhain TNC conversational post for CIMCO CNC-Calc, written for the
// postc corpus from the CNC-Calc Post Processor Manual (May 2014).
//
// Straight moves are L blocks, arcs a CC block (the centre, absolute) and a
// C block (the end point, DR+ counter-clockwise, DR- clockwise); a helix is
// CC and CP with the angle turned (IPA) and the depth (IZ). Radius
// compensation is RL, RR or R0 on the next L block. Every block carries its
// number, starting at 0. Drilling uses CYCL DEF 200 (with the pecking depth
// Q202 for peck drilling) and calls it with M99 at each hole; the longhand
// cycle moves the tool.

var decimalMark = ".";
var linebreak = "\n";
var variableDelimeter = " ";
var tolerance = 0.01;
var showSequenceNumbers = true;
var sequenceNumberStart = 0;
var sequenceNumberIncrement = 1;
var useRadius = false;
var absoluteArcCenter = true;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: true, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: true, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Longhand peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3, forceDecimal: true, forceSign: true});
var angleFormat = createFormat({decimals: 3, forceDecimal: true, forceSign: true});
var qFormat = createFormat({decimals: 3, forceDecimal: true, forceSign: true});
var xOutput = createVariable({prefix: " X"}, xyzFormat);
var yOutput = createVariable({prefix: " Y"}, xyzFormat);
var zOutput = createVariable({prefix: " Z"}, xyzFormat);
var ccX = createVariable({prefix: " X", force: true}, xyzFormat);
var ccY = createVariable({prefix: " Y", force: true}, xyzFormat);

var block = sequenceNumberStart;
var program = "CNCCALC";
var compensation = "";
var drill = null;
var cycleDefined = false;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    text = block + text;
    block += sequenceNumberIncrement;
    return text + linebreak;
}

// The feed of a movement: FMAX for rapids.
function feed(movement) {
    if (movement == MOVEMENT_RAPID) {
        return " FMAX";
    }
    return variableDelimeter + getFeedrate(movement);
}

function onOpen(isClipboard) {
    return writeBlock(" BEGIN PGM " + program + " MM");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    // The tool change moves the axes: every word prints again after it
    // (output variables keep their memory across toolpaths, seed 002).
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    return writeBlock(" ; " + name.toUpperCase())
        + writeBlock(" TOOL CALL " + tool + " Z S" + Math.round(spindleSpeed))
        + writeBlock(" L Z+100.000 R0 FMAX M3");
}

function onComment(text) {
    return writeBlock(" ; " + text);
}

function onDwell(seconds) {
    return writeBlock(" CYCL DEF 9.0 DWELL TIME") + writeBlock(" CYCL DEF 9.1 DWELL " + seconds);
}

function onClose() {
    return writeBlock(" L Z+100.000 R0 FMAX M5") + writeBlock(" L M30") + writeBlock(" END PGM " + program + " MM");
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? " RL" : comp == COMPENSATION_RIGHT ? " RR" : " R0";
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vy, vz, movement) {
    var xyz = xOutput.format(vx) + yOutput.format(vy) + zOutput.format(vz);
    if (xyz == "") {
        return "";
    }
    var radius = getCompensation();
    if (radius == "" && movement == MOVEMENT_RAPID) {
        radius = " R0";
    }
    return writeBlock(" L" + xyz + radius + feed(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    var sz = zOutput.getLast();
    var direction = isCW ? " DR-" : " DR+";
    var out = writeBlock(" CC" + ccX.format(cx) + ccY.format(cy));
    if (ez == sz) {
        // A C block always gives its end point (a full circle ends where it starts).
        xOutput.format(ex);
        yOutput.format(ey);
        return out + writeBlock(" C" + ccX.format(ex) + ccY.format(ey) + direction + feed(movement));
    }
    // A helix: the angle turned, the same sign as the direction.
    var a0 = Math.atan2(sy - cy, sx - cx);
    var a1 = Math.atan2(ey - cy, ex - cx);
    var turn = isCW ? a0 - a1 : a1 - a0;
    while (turn <= 0.000001) {
        turn += 2 * Math.PI;
    }
    var degrees = turn * 180 / Math.PI;
    xOutput.format(ex);
    yOutput.format(ey);
    var dz = ez - sz;
    zOutput.format(ez);
    return out + writeBlock(" CP IPA" + angleFormat.format(isCW ? -degrees : degrees) + " IZ" + xyzFormat.format(dz) + direction + feed(movement));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleDefined = false;
    return "";
}

// The drill header's heights as absolute Z (seed 002): the surface
// (referencePlane), the R plane (safe distance) and the bottom of the hole.
function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

function holeBottom() {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

// Cycle 200 measures from the surface coordinate Q203: Q200 the set-up
// clearance above it (the seed's safe distance), Q201 the depth below it,
// Q204 the 2nd set-up clearance (the retract plane) above it.
function cycleDefinition() {
    var surface = drill.referencePlane;
    var depth = holeBottom() - surface;
    var peck = drill.firstDepth > 0 ? drill.firstDepth : -depth;
    return writeBlock(" CYCL DEF 200 DRILLING ~")
        + "  Q200=" + qFormat.format(rPlane() - surface) + " ;SET-UP CLEARANCE ~" + linebreak
        + "  Q201=" + qFormat.format(depth) + " ;DEPTH ~" + linebreak
        + "  Q206=" + qFormat.format(drill.plungingFeedrate) + " ;FEED RATE FOR PLNGNG ~" + linebreak
        + "  Q202=" + qFormat.format(peck) + " ;PLUNGING DEPTH ~" + linebreak
        + "  Q210=" + qFormat.format(drill.useTopDwelling ? drill.topDwelling : 0) + " ;DWELL TIME AT TOP ~" + linebreak
        + "  Q203=" + qFormat.format(surface) + " ;SURFACE COORDINATE ~" + linebreak
        + "  Q204=" + qFormat.format(drill.retractPlane - surface) + " ;2ND SET-UP CLEARANCE ~" + linebreak
        + "  Q211=" + qFormat.format(drill.useBottomDwelling ? drill.bottomDwelling : 0) + " ;DWELL TIME AT DEPTH" + linebreak;
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhand(x, y);
    }
    var out = "";
    if (!cycleDefined) {
        cycleDefined = true;
        out = cycleDefinition();
        // The cycle starts from the clearance height: always say it.
        zOutput.reset();
        out += writeBlock(" L" + zOutput.format(drill.retractPlane) + " R0 FMAX");
    }
    return out + writeBlock(" L" + xOutput.format(x) + yOutput.format(y) + " R0 FMAX M99");
}

function longhand(x, y) {
    var out = writeBlock(" L" + xOutput.format(x) + yOutput.format(y) + " R0 FMAX");
    var depth = drill.safeDistance;
    out += writeBlock(" L" + zOutput.format(depth) + " R0 FMAX");
    var step = drill.firstDepth > 0 ? drill.firstDepth : drill.safeDistance - drill.endDepth;
    while (depth > drill.endDepth) {
        depth = Math.max(depth - step, drill.endDepth);
        out += writeBlock(" L" + zOutput.format(depth) + " R0 F" + Math.round(drill.plungingFeedrate));
        out += writeBlock(" L" + zOutput.format(drill.safeDistance) + " R0 FMAX");
    }
    return out + writeBlock(" L" + zOutput.format(drill.retractPlane) + " R0 FMAX");
}

function onDrillingFooter() {
    drill = null;
    return "";
}
