/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one keeps the machine's words in tables, object literals looked up
 * by string keys: the safe-start block walked with `for ... in`, motion,
 * compensation and coolant codes, the tool-change and end-of-program
 * sequences (walked with `for ... in`), the drilling cycles by name
 * (`cycles[drill.name]`, an unknown name an error), and a table of
 * functions: the block writer of each kind of cycle (`cycleWriters[kind]`),
 * and the codes each cycle's words come from. Modal words are
 * createVariable outputs.
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

// ------------------------------------------------------------------- Tables
var settings = {
    programNumber: 1001,
    programTitle: "Field style Fanuc mill",
    clearanceHeight: 50,
    peckClearance: 1
};

// The safe-start block, in the order written.
var safeStart = {plane: "G17", units: "G21", compensation: "G40", toolLength: "G49", cycle: "G80",
    distance: "G90", feedMode: "G94"};

var motionCodes = {rapid: 0, linear: 1, cw: 2, ccw: 3};
var compensationCodes = {0: "G40", 1: "G41", 2: "G42"};
var coolantCodes = {flood: "M8", mist: "M7", off: "M9"};

// The blocks that end a tool's work, and the program.
var toolEnd = {coolant: "M9", spindle: "M5", home: "G91 G28 Z0.", absolute: "G90"};
var programEnd = {end: "M30"};

// The drilling cycles by name: the kind of block and its G code.
var cycles = {
    "Drilling": {kind: "canned", code: "G81", dwellCode: "G82", peck: false},
    "Drilling (G81)": {kind: "canned", code: "G81", dwellCode: "G82", peck: false},
    "Peck drilling (G83)": {kind: "canned", code: "G83", dwellCode: "G83", peck: true},
    "Longhand peck drilling": {kind: "longhand", code: "", dwellCode: "", peck: true}
};

// -------------------------------------------------------------------- State
var sequenceNumber = sequenceNumberStart;
var clipboard = false;
var toolCount = 0;
var toolNumber = 0;
var pendingCompensation = "";
var drill = null;
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

// The characters a comment cannot hold, and what they become.
var commentCharacters = {"(": "", ")": ""};

function writeComment(text) {
    var clean = "";
    var upper = String(text).toUpperCase();
    for (var i = 0; i < upper.length; i++) {
        var c = upper.charAt(i);
        clean += c in commentCharacters ? commentCharacters[c] : c;
    }
    return writeBlock("(" + clean + ")");
}

function join(text, word) {
    if (word == "") {
        return text;
    }
    if (text == "") {
        return word;
    }
    return text + variableDelimeter + word;
}

// Every entry of a table, in order, as blocks.
function tableBlocks(table) {
    var out = "";
    for (var key in table) {
        out += writeBlock(table[key]);
    }
    return out;
}

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
    var start = "";
    for (var key in safeStart) {
        start = join(start, safeStart[key]);
    }
    return "%" + linebreak
        + "O" + settings["programNumber"] + " (" + settings["programTitle"].toUpperCase() + ")" + linebreak
        + writeBlock(start);
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    toolCount++;
    if (toolCount > 1) {
        out += tableBlocks(toolEnd);
    }
    toolNumber = tool;
    forgetPosition();
    out += writeComment("T" + tool + " " + name + " D" + xyzFormat.format(diameter));
    out += writeBlock("T" + tool + " M6");
    out += writeBlock("S" + rpmFormat.format(spindleSpeed) + " M3");
    out += writeBlock(coolantCodes["flood"]);
    return out + writeBlock(join(join(join(gMotion.format(motionCodes["rapid"]), "G43"),
        zOutput.format(settings["clearanceHeight"])), "H" + tool));
}

function onComment(text) {
    return writeComment(text);
}

function onDwell(seconds) {
    return writeBlock("G4 P" + Math.round(seconds * 1000));
}

function onClose() {
    var out = tableBlocks(toolEnd);
    if (!clipboard) {
        out += tableBlocks(programEnd) + "%" + linebreak;
    }
    return out;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    pendingCompensation = compensationCodes[comp];
    if (comp != COMPENSATION_OFF) {
        pendingCompensation += " D" + toolNumber;
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
    var code = movement == MOVEMENT_RAPID ? motionCodes["rapid"] : motionCodes["linear"];
    var text = join(gMotion.format(code), getCompensation());
    return writeBlock(join(join(text, xyz), feedWord(movement)));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    xOutput.reset();
    yOutput.reset();
    var text = join(gMotion.format(motionCodes[isCW ? "cw" : "ccw"]), xOutput.format(ex));
    text = join(join(text, yOutput.format(ey)), zOutput.format(ez));
    text = join(text, "I" + xyzFormat.format(cx - sx));
    text = join(text, "J" + xyzFormat.format(cy - sy));
    return writeBlock(join(text, feedWord(movement)));
}

// ---------------------------------------------------------------- Drilling
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
    return writeBlock(join(gMotion.format(motionCodes["rapid"]), word));
}

function feedZ(z) {
    var word = zOutput.format(z);
    if (word == "") {
        return "";
    }
    return writeBlock(join(join(gMotion.format(motionCodes["linear"]), word), fOutput.format(drill.plungingFeedrate)));
}

function dwellBlock() {
    return writeBlock("G4 P" + Math.round(drill.bottomDwelling * 1000));
}

// A rapid over the hole, then down to the retract plane.
function approach(x, y) {
    var xy = join(xOutput.format(x), yOutput.format(y));
    var out = "";
    if (xy != "") {
        out = writeBlock(join(gMotion.format(motionCodes["rapid"]), xy));
    }
    return out + rapidZ(drill.retractPlane);
}

// The block writers of each kind of cycle, for its first hole.
var cycleWriters = {
    canned: function (cycle, x, y) {
        var code = drill.useBottomDwelling ? cycle.dwellCode : cycle.code;
        var text = "G98 " + code + " Z" + xyzFormat.format(holeBottom()) + " R" + xyzFormat.format(rPlane());
        if (cycle.peck) {
            text += " Q" + xyzFormat.format(drill.firstDepth);
        }
        if (drill.useBottomDwelling) {
            text += " P" + Math.round(drill.bottomDwelling * 1000);
        }
        cycleActive = true;
        return approach(x, y) + writeBlock(join(text, fOutput.format(drill.plungingFeedrate)));
    },
    // A peck-drilled hole written out move by move: feed down one peck,
    // rapid out to the R plane, rapid back to just above the last depth.
    longhand: function (cycle, x, y) {
        var top = rPlane();
        var bottom = holeBottom();
        var step = drill.firstDepth > 0 ? drill.firstDepth : top - bottom;
        var depth = top;
        var out = approach(x, y) + rapidZ(top);
        do {
            out += rapidZ(Math.min(top, depth + settings["peckClearance"]));
            depth = Math.max(depth - step, bottom);
            out += feedZ(depth);
            if (depth <= bottom && drill.useBottomDwelling) {
                out += dwellBlock();
            }
            out += rapidZ(top);
        } while (depth > bottom);
        return out + rapidZ(drill.retractPlane);
    }
};

function onDrillingHeader(drillHeader) {
    if (!(drillHeader.name in cycles)) {
        throw new Error("unsupported drilling cycle: " + drillHeader.name);
    }
    drill = drillHeader;
    cycleActive = false;
    return "";
}

function onDrillingPoint(x, y) {
    var cycle = cycles[drill.name];
    if (cycleActive) {
        return writeBlock(join(xOutput.format(x), yOutput.format(y)));
    }
    return cycleWriters[cycle.kind](cycle, x, y);
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
    drill = null;
    return out;
}
