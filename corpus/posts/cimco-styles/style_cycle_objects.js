/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one hands cycle data to helpers as objects: onDrillingHeader turns
 * the drill header into a cycle object (`{name: ..., code: ..., retract:
 * ..., r: ..., bottom: ..., peck: ..., feed: ...}`), chosen by a `switch`
 * on the cycle's name whose `default` throws; onDrillingPoint makes a hole
 * object `{x: ..., y: ...}` and passes both to `cycleBlock(c, hole)`,
 * `approach(c, hole)` and `longhandHole(c, hole)`, which read `c.bottom`,
 * `c.r`, `hole.x`. Modal words are createVariable outputs.
 *
 * The machine: % ... %, O1001, block numbers N10 N20 ..., a safe-start
 * block, T M6 then S M3, flood coolant M8 with every tool (CNC-Calc has no
 * coolant call, so the post turns it on with the spindle and off at the
 * next tool change and at the end), G0 G43 Z50. H to the clearance height,
 * G41/G42 D with the tool number and G40, G2/G3 with incremental I J,
 * canned cycles G81 (G82 with a dwell) and G83 with G98 and G80, a
 * longhand peck cycle, G4 P in milliseconds, G91 G28 Z0. before a tool
 * change and at the end, M30. A drilling cycle the post does not know
 * stops the post with an error naming it.
 */

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

var MillDrillingFields = [
    {name: "Drilling", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Longhand peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

// ------------------------------------------------------ Formats and outputs
var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 1});
var rpmFormat = createFormat({decimals: 0});

var gMotion = createVariable({prefix: "G"}, createFormat({decimals: 0}));
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var fOutput = createVariable({prefix: "F"}, feedFormat);
var iOutput = createVariable({prefix: "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: "J", force: true}, xyzFormat);

// Machine settings.
var programNumber = 1001;
var programTitle = "Field style Fanuc mill";
var clearanceHeight = 50;
var peckClearance = 1;

// -------------------------------------------------------------------- State
var sequenceNumber = sequenceNumberStart;
var clipboard = false;
var toolCount = 0;
var toolNumber = 0;
var pendingCompensation = "";
var cycle = null;
var cycleActive = false;

// ------------------------------------------------------------------ Helpers
function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = "N" + sequenceNumber + " " + text;
        sequenceNumber += sequenceNumberIncrement;
    }
    return text + linebreak;
}

// A comment block: upper case, without brackets that would end it early.
function writeComment(text) {
    var clean = "";
    var upper = String(text).toUpperCase();
    for (var i = 0; i < upper.length; i++) {
        var c = upper.charAt(i);
        if (c != "(" && c != ")") {
            clean += c;
        }
    }
    return writeBlock("(" + clean + ")");
}

// Joins a word to a block's text with the delimiter.
function join(text, word) {
    if (word == "") {
        return text;
    }
    if (text == "") {
        return word;
    }
    return text + variableDelimeter + word;
}

// The modal feed word of a movement; nothing for rapids.
function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "") {
        return "";
    }
    return fOutput.format(parseFloat(f.substring(1)));
}

function forgetPosition() {
    gMotion.reset();
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    fOutput.reset();
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
        + "O" + programNumber + " (" + programTitle.toUpperCase() + ")" + linebreak
        + writeBlock("G17 G21 G40 G49 G80 G90 G94");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    toolCount++;
    if (toolCount > 1) {
        out += writeBlock("M9") + writeBlock("M5") + writeBlock("G91 G28 Z0.") + writeBlock("G90");
    }
    toolNumber = tool;
    forgetPosition();
    out += writeComment("T" + tool + " " + name + " D" + xyzFormat.format(diameter));
    out += writeBlock("T" + tool + " M6");
    out += writeBlock("S" + rpmFormat.format(spindleSpeed) + " M3");
    out += writeBlock("M8");
    return out + writeBlock(join(join(join(gMotion.format(0), "G43"), zOutput.format(clearanceHeight)), "H" + tool));
}

function onComment(text) {
    return writeComment(text);
}

function onDwell(seconds) {
    return writeBlock("G4 P" + Math.round(seconds * 1000));
}

function onClose() {
    var out = writeBlock("M9") + writeBlock("M5") + writeBlock("G91 G28 Z0.") + writeBlock("G90");
    if (!clipboard) {
        out += writeBlock("M30") + "%" + linebreak;
    }
    return out;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        pendingCompensation = "G41 D" + toolNumber;
    } else if (comp == COMPENSATION_RIGHT) {
        pendingCompensation = "G42 D" + toolNumber;
    } else {
        pendingCompensation = "G40";
    }
}

function getCompensation() {
    var code = pendingCompensation;
    pendingCompensation = "";
    return code;
}

// --------------------------------------------------------------- Movement
function onLinear(vx, vy, vz, movement) {
    var xyz = join(join(xOutput.format(vx), yOutput.format(vy)), zOutput.format(vz));
    if (xyz == "") {
        return "";
    }
    var text = join(gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1), getCompensation());
    return writeBlock(join(join(text, xyz), feedWord(movement)));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    xOutput.reset();
    yOutput.reset();
    var text = join(gMotion.format(isCW ? 2 : 3), xOutput.format(ex));
    text = join(join(text, yOutput.format(ey)), zOutput.format(ez));
    text = join(join(text, iOutput.format(cx - sx)), jOutput.format(cy - sy));
    return writeBlock(join(text, feedWord(movement)));
}

// ---------------------------------------------------------------- Drilling

// The cycle object of a drill header: every height absolute.
function makeCycle(drillHeader) {
    var c = {
        name: drillHeader.name,
        longhand: drillHeader.isLonghand,
        code: "",
        retract: drillHeader.retractPlane,
        r: drillHeader.safeDistanceIsAbsolute ? drillHeader.safeDistance
            : drillHeader.referencePlane + drillHeader.safeDistance,
        bottom: drillHeader.endDepthIsAbsolute ? drillHeader.endDepth
            : drillHeader.referencePlane - Math.abs(drillHeader.endDepth),
        peck: drillHeader.firstDepth,
        useDwell: drillHeader.useBottomDwelling,
        dwell: Math.round(drillHeader.bottomDwelling * 1000),
        feed: drillHeader.plungingFeedrate
    };
    if (c.longhand) {
        return c;
    }
    switch (c.name) {
        case "Drilling":
        case "Drilling (G81)":
            c.code = c.useDwell ? "G82" : "G81";
            break;
        case "Peck drilling (G83)":
            c.code = "G83";
            break;
        default:
            throw new Error("unsupported drilling cycle: " + c.name);
    }
    return c;
}

function onDrillingHeader(drillHeader) {
    cycle = makeCycle(drillHeader);
    cycleActive = false;
    return "";
}

function rapidZ(z) {
    var word = zOutput.format(z);
    if (word == "") {
        return "";
    }
    return writeBlock(join(gMotion.format(0), word));
}

function feedZ(z, c) {
    var word = zOutput.format(z);
    if (word == "") {
        return "";
    }
    return writeBlock(join(join(gMotion.format(1), word), fOutput.format(c.feed)));
}

// A rapid over the hole, then down to the retract plane.
function approach(c, hole) {
    var xy = join(xOutput.format(hole.x), yOutput.format(hole.y));
    var out = "";
    if (xy != "") {
        out = writeBlock(join(gMotion.format(0), xy));
    }
    return out + rapidZ(c.retract);
}

function cycleBlock(c) {
    var text = "G98 " + c.code + " Z" + xyzFormat.format(c.bottom) + " R" + xyzFormat.format(c.r);
    switch (c.code) {
        case "G83":
            text += " Q" + xyzFormat.format(c.peck);
            break;
        default:
            break;
    }
    if (c.useDwell) {
        text += " P" + c.dwell;
    }
    return writeBlock(join(text, fOutput.format(c.feed)));
}

// A peck-drilled hole written out move by move: feed down one peck,
// rapid out to the R plane, rapid back to just above the last depth.
function longhandHole(c, hole) {
    var step = c.peck > 0 ? c.peck : c.r - c.bottom;
    var depth = c.r;
    var out = approach(c, hole) + rapidZ(c.r);
    do {
        out += rapidZ(Math.min(c.r, depth + peckClearance));
        depth = Math.max(depth - step, c.bottom);
        out += feedZ(depth, c);
        if (depth <= c.bottom && c.useDwell) {
            out += writeBlock("G4 P" + c.dwell);
        }
        out += rapidZ(c.r);
    } while (depth > c.bottom);
    return out + rapidZ(c.retract);
}

function onDrillingPoint(x, y) {
    var hole = {x: x, y: y};
    if (cycle.longhand) {
        return longhandHole(cycle, hole);
    }
    if (cycleActive) {
        return writeBlock(join(xOutput.format(hole.x), yOutput.format(hole.y)));
    }
    cycleActive = true;
    return approach(cycle, hole) + cycleBlock(cycle);
}

function onDrillingFooter() {
    var out = "";
    if (cycleActive) {
        out = writeBlock("G80");
        // G98 leaves the tool at the retract plane and G80 cancels the
        // motion mode: Z and G print again.
        gMotion.reset();
        zOutput.reset();
    }
    cycleActive = false;
    cycle = null;
    return out;
}
