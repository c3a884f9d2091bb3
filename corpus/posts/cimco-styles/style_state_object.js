/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one keeps all modal state in one global object literal: the words
 * last printed (`state.x`, `state.feed`, `state.motion`), the last
 * positions, the block number, the tool, the pending compensation and the
 * drilling cycle. A modal word is printed when its text differs from the
 * one in `state`, and `state.x = null` forgets it. Headers are passed to
 * helpers as objects (`programHeader({number: ..., title: ...})`,
 * `toolHeader({number: ..., name: ..., ...})`, the drill header itself).
 * No createVariable: the formats only format.
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

// ------------------------------------------------------------------ Formats
var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 1});
var rpmFormat = createFormat({decimals: 0});

// Machine settings.
var programNumber = 1001;
var programTitle = "Field style Fanuc mill";
var clearanceHeight = 50;
var peckClearance = 1;

// -------------------------------------------------------------------- State
var state = {
    sequence: sequenceNumberStart,
    clipboard: false,
    toolCount: 0,
    tool: 0,
    motion: null,
    x: null,
    y: null,
    z: null,
    feed: null,
    lastX: 0,
    lastY: 0,
    compensation: "",
    drill: null,
    cycleActive: false
};

// ------------------------------------------------------------------ Helpers

// One block: the block number, then the words.
function writeBlock(text) {
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = "N" + state.sequence + " " + text;
        state.sequence += sequenceNumberIncrement;
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

// The motion code, when it differs from the one in force.
function motionWord(code) {
    var text = "G" + code;
    if (text == state.motion) {
        return "";
    }
    state.motion = text;
    return text;
}

function xWord(x) {
    var text = "X" + xyzFormat.format(x);
    state.lastX = x;
    if (text == state.x) {
        return "";
    }
    state.x = text;
    return text;
}

function yWord(y) {
    var text = "Y" + xyzFormat.format(y);
    state.lastY = y;
    if (text == state.y) {
        return "";
    }
    state.y = text;
    return text;
}

function zWord(z) {
    var text = "Z" + xyzFormat.format(z);
    if (text == state.z) {
        return "";
    }
    state.z = text;
    return text;
}

// The feed word (text like getFeedrate's), when it changed.
function feedWord(text) {
    if (text == "" || text == state.feed) {
        return "";
    }
    state.feed = text;
    return text;
}

// After a tool change nothing is known of the machine's position.
function forgetPosition() {
    state.motion = null;
    state.x = null;
    state.y = null;
    state.z = null;
    state.feed = null;
}

function programHeader(header) {
    return "%" + linebreak
        + "O" + header.number + " (" + header.title.toUpperCase() + ")" + linebreak
        + writeBlock(header.safeStart);
}

function toolHeader(header) {
    var out = "";
    if (header.count > 1) {
        out += writeBlock("M9") + writeBlock("M5") + writeBlock("G91 G28 Z0.") + writeBlock("G90");
    }
    out += writeComment("T" + header.number + " " + header.name + " D" + xyzFormat.format(header.diameter));
    out += writeBlock("T" + header.number + " M6");
    out += writeBlock("S" + rpmFormat.format(header.speed) + " M3");
    out += writeBlock("M8");
    out += writeBlock(join(join(join(motionWord(0), "G43"), zWord(header.clearance)), "H" + header.number));
    return out;
}

// -------------------------------------------------------------- Framework
function onInit() {
    state.clipboard = false;
}

function onOpen(isClipboard) {
    state.clipboard = isClipboard;
    if (isClipboard) {
        return "";
    }
    return programHeader({number: programNumber, title: programTitle, safeStart: "G17 G21 G40 G49 G80 G90 G94"});
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    state.toolCount++;
    state.tool = tool;
    forgetPosition();
    return toolHeader({count: state.toolCount, number: tool, name: name, diameter: diameter, speed: spindleSpeed,
        clearance: clearanceHeight});
}

function onComment(text) {
    return writeComment(text);
}

function onDwell(seconds) {
    return writeBlock("G4 P" + Math.round(seconds * 1000));
}

function onClose() {
    var out = writeBlock("M9") + writeBlock("M5") + writeBlock("G91 G28 Z0.") + writeBlock("G90");
    if (!state.clipboard) {
        out += writeBlock("M30") + "%" + linebreak;
    }
    return out;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        state.compensation = "G41 D" + state.tool;
    } else if (comp == COMPENSATION_RIGHT) {
        state.compensation = "G42 D" + state.tool;
    } else {
        state.compensation = "G40";
    }
}

function getCompensation() {
    var code = state.compensation;
    state.compensation = "";
    return code;
}

// --------------------------------------------------------------- Movement
function onLinear(vx, vy, vz, movement) {
    var xyz = join(join(xWord(vx), yWord(vy)), zWord(vz));
    if (xyz == "") {
        return "";
    }
    var text = motionWord(movement == MOVEMENT_RAPID ? 0 : 1);
    text = join(text, getCompensation());
    text = join(text, xyz);
    return writeBlock(join(text, feedWord(getFeedrate(movement))));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = state.lastX;
    var sy = state.lastY;
    // Both end coordinates on every arc.
    state.x = null;
    state.y = null;
    var text = join(motionWord(isCW ? 2 : 3), xWord(ex));
    text = join(join(text, yWord(ey)), zWord(ez));
    text = join(text, "I" + xyzFormat.format(cx - sx));
    text = join(text, "J" + xyzFormat.format(cy - sy));
    return writeBlock(join(text, feedWord(getFeedrate(movement))));
}

// ---------------------------------------------------------------- Drilling
function onDrillingHeader(drillHeader) {
    state.drill = drillHeader;
    state.cycleActive = false;
    if (!drillHeader.isLonghand && cycleCode(drillHeader) == "") {
        throw new Error("unsupported drilling cycle: " + drillHeader.name);
    }
    return "";
}

// The canned cycle's G code of a drill header, "" for a name it has none for.
function cycleCode(drill) {
    if (drill.name == "Drilling" || drill.name == "Drilling (G81)") {
        return drill.useBottomDwelling ? "G82" : "G81";
    }
    if (drill.name == "Peck drilling (G83)") {
        return "G83";
    }
    return "";
}

function holeBottom(drill) {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

function rPlane(drill) {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

// A rapid block to a height, when the tool is not there.
function rapidZ(z) {
    var word = zWord(z);
    if (word == "") {
        return "";
    }
    return writeBlock(join(motionWord(0), word));
}

// A feed block to a depth.
function feedZ(z, feed) {
    var word = zWord(z);
    if (word == "") {
        return "";
    }
    return writeBlock(join(join(motionWord(1), word), feedWord(feed)));
}

// A rapid over the hole, then down to the retract plane.
function approach(drill, x, y) {
    var xy = join(xWord(x), yWord(y));
    var out = "";
    if (xy != "") {
        out = writeBlock(join(motionWord(0), xy));
    }
    return out + rapidZ(drill.retractPlane);
}

function onDrillingPoint(x, y) {
    var drill = state.drill;
    if (drill.isLonghand) {
        return longhandHole(drill, x, y);
    }
    if (state.cycleActive) {
        return writeBlock(join(xWord(x), yWord(y)));
    }
    state.cycleActive = true;
    return approach(drill, x, y) + writeBlock(cycleBlock(drill));
}

function cycleBlock(drill) {
    var code = cycleCode(drill);
    var text = "G98 " + code + " Z" + xyzFormat.format(holeBottom(drill)) + " R" + xyzFormat.format(rPlane(drill));
    if (code == "G83") {
        text += " Q" + xyzFormat.format(drill.firstDepth);
    }
    if (drill.useBottomDwelling) {
        text += " P" + Math.round(drill.bottomDwelling * 1000);
    }
    state.motion = code;
    return join(text, feedWord("F" + feedFormat.format(drill.plungingFeedrate)));
}

// A peck-drilled hole written out move by move: feed down one peck,
// rapid out to the R plane, rapid back to just above the last depth.
function longhandHole(drill, x, y) {
    var top = rPlane(drill);
    var bottom = holeBottom(drill);
    var step = drill.firstDepth > 0 ? drill.firstDepth : top - bottom;
    var feed = "F" + feedFormat.format(drill.plungingFeedrate);
    var depth = top;
    var out = approach(drill, x, y) + rapidZ(top);
    do {
        out += rapidZ(Math.min(top, depth + peckClearance));
        depth = Math.max(depth - step, bottom);
        out += feedZ(depth, feed);
        if (depth <= bottom && drill.useBottomDwelling) {
            out += writeBlock("G4 P" + Math.round(drill.bottomDwelling * 1000));
        }
        out += rapidZ(top);
    } while (depth > bottom);
    return out + rapidZ(drill.retractPlane);
}

function onDrillingFooter() {
    var out = "";
    if (state.cycleActive) {
        out = writeBlock("G80");
        // G98 leaves the tool at the retract plane and G80 cancels the
        // motion mode: Z and G print again.
        state.motion = null;
        state.z = null;
    }
    state.cycleActive = false;
    state.drill = null;
    return out;
}
