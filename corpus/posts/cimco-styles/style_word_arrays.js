/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one gathers every block's words in an array: `var words = [];
 * words.push(...)`, and `writeWords(words)` drops the empty words (a
 * modal output that printed nothing) with `filter` and joins the rest
 * with blanks. The variadic `writeBlock("T" + tool, "M6")` reads
 * `arguments` into such an array; `writeBlock.apply(null, words)` passes
 * one on. Modal words are createVariable outputs.
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
var pendingCompensation = [];
var drill = null;
var cycleActive = false;

// ------------------------------------------------------------------ Helpers

// The words of an array that are not empty, joined by blanks, after a
// block number; nothing when no word is left.
function writeWords(words) {
    var kept = words.filter(function (word) {
        return word !== "";
    });
    if (kept.length == 0) {
        return "";
    }
    if (showSequenceNumbers) {
        kept.unshift("N" + sequenceNumber);
        sequenceNumber += sequenceNumberIncrement;
    }
    return kept.join(variableDelimeter) + linebreak;
}

// Every argument is a word.
function writeBlock() {
    var words = [];
    for (var i = 0; i < arguments.length; i++) {
        words.push(arguments[i]);
    }
    return writeWords(words);
}

// A comment block: upper case, without brackets that would end it early.
function writeComment(text) {
    var kept = [];
    var upper = String(text).toUpperCase();
    for (var i = 0; i < upper.length; i++) {
        var c = upper.charAt(i);
        if (c != "(" && c != ")") {
            kept.push(c);
        }
    }
    return writeBlock("(" + kept.join("") + ")");
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
    var header = ["%", "O" + programNumber + " (" + programTitle.toUpperCase() + ")"];
    return header.join(linebreak) + linebreak
        + writeBlock.apply(null, ["G17", "G21", "G40", "G49", "G80", "G90", "G94"]);
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var blocks = [];
    toolCount++;
    if (toolCount > 1) {
        blocks.push(writeBlock("M9"), writeBlock("M5"), writeBlock("G91", "G28", "Z0."), writeBlock("G90"));
    }
    toolNumber = tool;
    forgetPosition();
    blocks.push(writeComment("T" + tool + " " + name + " D" + xyzFormat.format(diameter)));
    blocks.push(writeBlock("T" + tool, "M6"));
    blocks.push(writeBlock("S" + rpmFormat.format(spindleSpeed), "M3"));
    blocks.push(writeBlock("M8"));
    blocks.push(writeBlock(gMotion.format(0), "G43", zOutput.format(clearanceHeight), "H" + tool));
    return blocks.join("");
}

function onComment(text) {
    return writeComment(text);
}

function onDwell(seconds) {
    return writeBlock("G4", "P" + Math.round(seconds * 1000));
}

function onClose() {
    var blocks = [writeBlock("M9"), writeBlock("M5"), writeBlock("G91", "G28", "Z0."), writeBlock("G90")];
    if (!clipboard) {
        blocks.push(writeBlock("M30"), "%" + linebreak);
    }
    return blocks.join("");
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        pendingCompensation = ["G41", "D" + toolNumber];
    } else if (comp == COMPENSATION_RIGHT) {
        pendingCompensation = ["G42", "D" + toolNumber];
    } else {
        pendingCompensation = ["G40"];
    }
}

function getCompensation() {
    var words = pendingCompensation;
    pendingCompensation = [];
    return words;
}

// --------------------------------------------------------------- Movement
function onLinear(vx, vy, vz, movement) {
    var axes = [xOutput.format(vx), yOutput.format(vy), zOutput.format(vz)];
    if (axes.join("") == "") {
        return "";
    }
    var words = [gMotion.format(movement == MOVEMENT_RAPID ? 0 : 1)];
    var comp = getCompensation();
    for (var i = 0; i < comp.length; i++) {
        words.push(comp[i]);
    }
    for (var k = 0; k < axes.length; k++) {
        words.push(axes[k]);
    }
    words.push(feedWord(movement));
    return writeWords(words);
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var start = [xOutput.getLast(), yOutput.getLast()];
    xOutput.reset();
    yOutput.reset();
    var words = [];
    words.push(gMotion.format(isCW ? 2 : 3));
    words.push(xOutput.format(ex), yOutput.format(ey), zOutput.format(ez));
    words.push("I" + xyzFormat.format(cx - start[0]), "J" + xyzFormat.format(cy - start[1]));
    words.push(feedWord(movement));
    return writeWords(words);
}

// ---------------------------------------------------------------- Drilling

// The canned cycle's G code of the drill header, "" for a name it has none for.
function cycleCode() {
    if (drill.name == "Drilling" || drill.name == "Drilling (G81)") {
        return drill.useBottomDwelling ? "G82" : "G81";
    }
    if (drill.name == "Peck drilling (G83)") {
        return "G83";
    }
    return "";
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleActive = false;
    if (!drill.isLonghand && cycleCode() == "") {
        throw new Error("unsupported drilling cycle: " + drill.name);
    }
    return "";
}

function holeBottom() {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

function rapidZ(z) {
    var word = zOutput.format(z);
    if (word == "") {
        return "";
    }
    return writeBlock(gMotion.format(0), word);
}

function feedZ(z) {
    var word = zOutput.format(z);
    if (word == "") {
        return "";
    }
    return writeBlock(gMotion.format(1), word, fOutput.format(drill.plungingFeedrate));
}

// A rapid over the hole, then down to the retract plane.
function approach(x, y) {
    var xy = [xOutput.format(x), yOutput.format(y)];
    var out = "";
    if (xy.join("") != "") {
        xy.unshift(gMotion.format(0));
        out = writeWords(xy);
    }
    return out + rapidZ(drill.retractPlane);
}

function cycleBlock() {
    var code = cycleCode();
    var words = ["G98", code, "Z" + xyzFormat.format(holeBottom()), "R" + xyzFormat.format(rPlane())];
    if (code == "G83") {
        words.push("Q" + xyzFormat.format(drill.firstDepth));
    }
    if (drill.useBottomDwelling) {
        words.push("P" + Math.round(drill.bottomDwelling * 1000));
    }
    words.push(fOutput.format(drill.plungingFeedrate));
    return writeBlock.apply(null, words);
}

// A peck-drilled hole written out move by move: feed down one peck,
// rapid out to the R plane, rapid back to just above the last depth.
function longhandHole(x, y) {
    var top = rPlane();
    var bottom = holeBottom();
    var step = drill.firstDepth > 0 ? drill.firstDepth : top - bottom;
    var depth = top;
    var blocks = [approach(x, y), rapidZ(top)];
    do {
        blocks.push(rapidZ(Math.min(top, depth + peckClearance)));
        depth = Math.max(depth - step, bottom);
        blocks.push(feedZ(depth));
        if (depth <= bottom && drill.useBottomDwelling) {
            blocks.push(writeBlock("G4", "P" + Math.round(drill.bottomDwelling * 1000)));
        }
        blocks.push(rapidZ(top));
    } while (depth > bottom);
    blocks.push(rapidZ(drill.retractPlane));
    return blocks.join("");
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhandHole(x, y);
    }
    if (cycleActive) {
        return writeBlock(xOutput.format(x), yOutput.format(y));
    }
    cycleActive = true;
    return approach(x, y) + cycleBlock();
}

function onDrillingFooter() {
    var blocks = [];
    if (cycleActive) {
        blocks.push(writeBlock("G80"));
        // G98 leaves the tool at the retract plane and G80 cancels the
        // motion mode: Z and G print again.
        gMotion.reset();
        zOutput.reset();
    }
    cycleActive = false;
    drill = null;
    return blocks.join("");
}
