// Converted by postc from linuxcnc_field.js (CIMCO CNC-Calc JavaScript).
/*
 * LinuxCNC milling post (mm, .ngc style) for CIMCO CNC-Calc, written for the
 * postc corpus in the style posts found in the field are written in: every
 * block is an array of words (push, length, indexing) handed to a variadic
 * writeBlock() with writeBlock.apply(null, words); writeBlock reads
 * `arguments`, drops empty words and joins the rest with blanks. Look-up
 * tables are object literals and arrays; comments are sanitised character
 * by character (LinuxCNC comments cannot nest parentheses); the longhand
 * peck cycle is a do ... while loop of G0/G1 pecks.
 *
 * The program is what LinuxCNC 2.x reads: % ... %, a safe-start block,
 * T M6 with G43 H, G64 path blending, G2/G3 with incremental I J (G91.1),
 * G98 canned cycles G81/G82/G83/G73 (P in seconds, Q the peck) with G80,
 * G4 P seconds, G41/G42/G40 taking the diameter from the tool table,
 * M2 at the end. No block numbers: LinuxCNC does not need them.
 */

var linebreak = "\n";
var tolerance = 0.01;
var useRadius = false;
var absoluteArcCenter = false;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Spot drilling (G82)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Chip breaking (G73)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Longhand peck drilling", isLonghand: true, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 4, forceDecimal: true});
var feedFormat = createFormat({decimals: 1});
var secondsFormat = createFormat({decimals: 3});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var gMotionModal = createVariable({prefix: "G"}, createFormat({decimals: 0}));

// Look-up tables.
var safeStart = ["G17", "G21", "G40", "G49", "G54", "G80", "G90", "G91.1", "G94"];
var compensationCodes = ["G40", "G41", "G42"];
var coolantCodes = {flood: "M8", mist: "M7", off: "M9"};
var cycleCodes = {"Drilling (G81)": "G81", "Spot drilling (G82)": "G82", "Peck drilling (G83)": "G83",
    "Chip breaking (G73)": "G73", "Drilling": "G81", "Peck drilling": "G83", "Chip breaking": "G73"};
var commentCharacters = {"(": "[", ")": "]"};
var peckClearance = 0.5;

var pendingCompensation = "";
var lastFeed = "";
var currentTool = 0;
var drill = null;
var cycleActive = false;

// The words that are not empty, joined by blanks; nothing without words.
function writeBlock() {
    var words = [];
    for (var i = 0; i < arguments.length; i++) {
        if (arguments[i]) {
            words.push(arguments[i]);
        }
    }
    if (words.length == 0) {
        return "";
    }
    return words.join(" ") + linebreak;
}

function sanitize(text) {
    var out = "";
    for (var i = 0; i < text.length; i++) {
        var c = text.charAt(i);
        out += commentCharacters[c] ? commentCharacters[c] : c;
    }
    return out;
}

function writeComment(text) {
    return "(" + sanitize(text) + ")" + linebreak;
}

// The feed word, only when it changed since the last one written.
function feedWord(movement) {
    var f = getFeedrate(movement);
    if (f == "" || f == lastFeed) {
        return "";
    }
    lastFeed = f;
    return f;
}

function takeCompensation() {
    var code = pendingCompensation;
    pendingCompensation = "";
    return code;
}

function forgetPosition() {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    gMotionModal.reset();
}

function onOpen(isClipboard) {
    return "%" + linebreak + writeComment("LinuxCNC field-style post for CIMCO CNC-Calc")
        + writeBlock.apply(null, safeStart) + writeBlock("G64", "P0.01");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    if (currentTool != 0) {
        out += writeBlock(coolantCodes.off) + writeBlock("M5") + writeBlock("G53", "G0", "Z0");
    }
    currentTool = tool;
    forgetPosition();
    out += writeComment("T" + tool + " " + name + " D=" + xyzFormat.format(diameter));
    out += writeBlock("T" + tool, "M6") + writeBlock("G43", "H" + tool);
    out += writeBlock("S" + Math.round(spindleSpeed), "M3") + writeBlock(coolantCodes.flood);
    return out;
}

function onComment(text) {
    return writeComment(text);
}

function onCompensation(comp) {
    pendingCompensation = compensationCodes[comp];
}

function onLinear(vx, vy, vz, movement) {
    var axes = [xOutput.format(vx), yOutput.format(vy), zOutput.format(vz)];
    var comp = takeCompensation();
    if (axes[0] == "" && axes[1] == "" && axes[2] == "" && comp == "") {
        return "";
    }
    var words = [];
    if (comp != "") {
        words.push(comp);
    }
    words.push(gMotionModal.format(movement == MOVEMENT_RAPID ? 0 : 1));
    for (var i = 0; i < axes.length; i++) {
        words.push(axes[i]);
    }
    words.push(feedWord(movement));
    return writeBlock.apply(null, words);
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var start = [xOutput.getLast(), yOutput.getLast()];
    var words = [takeCompensation(), gMotionModal.format(isCW ? 2 : 3)];
    xOutput.reset();
    yOutput.reset();
    words.push(xOutput.format(ex), yOutput.format(ey), zOutput.format(ez));
    words.push("I" + xyzFormat.format(cx - start[0]), "J" + xyzFormat.format(cy - start[1]));
    words.push(feedWord(movement));
    return writeBlock.apply(null, words);
}

function onDwell(seconds) {
    return writeBlock("G4", "P" + secondsFormat.format(seconds));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleActive = false;
    return "";
}

function holeBottom() {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

// A rapid to the retract plane, when the tool is not there.
function retractBlock() {
    var z = zOutput.format(drill.retractPlane);
    if (z == "") {
        return "";
    }
    return writeBlock(gMotionModal.format(0), z);
}

// A longhand peck cycle: feed down a peck at a time, rapid out to the R
// plane and back down to just above the last depth.
function longhandHole(x, y) {
    var bottom = holeBottom();
    var r = rPlane();
    var peck = drill.firstDepth > 0 ? drill.firstDepth : r - bottom;
    var out = retractBlock();
    out += writeBlock(gMotionModal.format(0), xOutput.format(x), yOutput.format(y));
    out += writeBlock(zOutput.format(r));
    var depth = drill.referencePlane;
    do {
        if (depth < drill.referencePlane) {
            out += writeBlock(gMotionModal.format(0), zOutput.format(depth + peckClearance));
        }
        depth = Math.max(depth - peck, bottom);
        out += writeBlock(gMotionModal.format(1), zOutput.format(depth), "F" + feedFormat.format(drill.plungingFeedrate));
        if (depth > bottom) {
            out += writeBlock(gMotionModal.format(0), zOutput.format(r));
        }
    } while (depth > bottom);
    lastFeed = "";
    if (drill.useBottomDwelling) {
        out += onDwell(drill.bottomDwelling);
    }
    return out + writeBlock(gMotionModal.format(0), zOutput.format(drill.retractPlane));
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhandHole(x, y);
    }
    if (cycleActive) {
        return writeBlock(xOutput.format(x), yOutput.format(y));
    }
    cycleActive = true;
    var code = cycleCodes[drill.name] || (drill.firstDepth > 0 ? "G83" : "G81");
    if (code == "G81" && drill.useBottomDwelling) {
        code = "G82";
    }
    var out = retractBlock();
    xOutput.reset();
    yOutput.reset();
    var words = ["G98", code, xOutput.format(x), yOutput.format(y)];
    words.push("Z" + xyzFormat.format(holeBottom()), "R" + xyzFormat.format(rPlane()));
    if (code == "G83" || code == "G73") {
        words.push("Q" + xyzFormat.format(drill.firstDepth));
    }
    if (code == "G82") {
        words.push("P" + secondsFormat.format(drill.bottomDwelling));
    }
    words.push("F" + feedFormat.format(drill.plungingFeedrate));
    lastFeed = "";
    return out + writeBlock.apply(null, words);
}

function onDrillingFooter() {
    var out = "";
    if (cycleActive) {
        out = writeBlock("G80");
    }
    cycleActive = false;
    gMotionModal.reset();
    zOutput.reset();
    return out;
}

function onClose() {
    return writeBlock(coolantCodes.off) + writeBlock("M5") + writeBlock("G53", "G0", "Z0") + writeBlock("M2")
        + "%" + linebreak;
}
