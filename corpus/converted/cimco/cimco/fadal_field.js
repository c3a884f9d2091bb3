// Converted by postc from fadal_field.js (CIMCO CNC-Calc JavaScript).
/*
 * Fadal VMC milling post (Format 2, mm) for CIMCO CNC-Calc, written for the
 * postc corpus in the style posts found in the field are written in: a
 * variadic writeBlock() that reads `arguments` and numbers the blocks N1,
 * N2, ...; radius arcs (useRadius) broken at every quadrant boundary, as
 * posts for older controls do, by a helper that collects the pieces in an
 * array of objects and a for loop that writes them; object-literal tables
 * for the cycle and coolant codes; a do ... while loop that pads the
 * program number.
 *
 * Fadal conventions: the program number on the first block (N1 O0042);
 * E1 selects fixture offset 1; the tool length offset H goes with the
 * first Z move after the tool change (Fadal applies H with a Z word);
 * G2/G3 with R (the host never passes an arc of 180 degrees or more, and
 * the post breaks each at 0, 90, 180 and 270 degrees); canned cycles
 * G81/G82/G83/G73 with G98, R absolute, Q the peck, P the dwell in
 * seconds; G4 P seconds; the end cancels H and E and returns home; M2.
 */

var linebreak = "\n";
var tolerance = 0.01;
var useRadius = true;
var absoluteArcCenter = false;
var showSequenceNumbers = true;
var sequenceNumberStart = 1;
var sequenceNumberIncrement = 1;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
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
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 1, forceDecimal: true});
var secondsFormat = createFormat({decimals: 3});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var fOutput = createVariable({prefix: "F"}, feedFormat);
var gMotion = createVariable({prefix: "G"}, createFormat({decimals: 0}));

var programNumber = 42;
var coolantCodes = {flood: "M8", mist: "M7", off: "M9"};
var cycleCodes = {"Drilling (G81)": "G81", "Peck drilling (G83)": "G83", "Chip breaking (G73)": "G73",
    "Peck drilling": "G83", "Chip breaking": "G73"};
// Unit vectors at 0, 90, 180 and 270 degrees: the quadrant points are
// exact, with no sine or cosine.
var quadrants = [{c: 1, s: 0}, {c: 0, s: 1}, {c: -1, s: 0}, {c: 0, s: -1}];

var sequenceNumber = sequenceNumberStart;
var lengthOffset = "";
var compensation = "";
var drill;
var cycleStarted = false;
var toolCount = 0;
var currentTool = 0;

function writeBlock() {
    var words = [];
    for (var i = 0; i < arguments.length; ++i) {
        if (arguments[i] != "") {
            words.push(arguments[i]);
        }
    }
    if (words.length == 0) {
        return "";
    }
    if (showSequenceNumbers) {
        words.unshift("N" + sequenceNumber);
        sequenceNumber += sequenceNumberIncrement;
    }
    return words.join(" ") + linebreak;
}

// Fadal comments cannot hold parentheses: they become brackets.
function writeComment(text) {
    return writeBlock("(" + text.toUpperCase().split("(").join("[").split(")").join("]") + ")");
}

function programName() {
    var s = String(programNumber);
    do {
        s = "0" + s;
    } while (s.length < 4);
    return "O" + s;
}

function feed() {
    return fOutput.format(parseFloat(getFeedrate(MOVEMENT_CUTTING).substring(1)));
}

function takeLengthOffset(z) {
    if (z == "" || lengthOffset == "") {
        return "";
    }
    var h = lengthOffset;
    lengthOffset = "";
    return h;
}

function takeCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onOpen(isClipboard) {
    return "%" + linebreak + writeBlock(programName(), "(FADAL FIELD-STYLE POST, CIMCO CNC-CALC)")
        + writeBlock("G0", "G17", "G21", "G40", "G49", "G80", "G90");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    if (toolCount > 0) {
        out = writeBlock(coolantCodes.off, "M5") + writeBlock("G0", "G90", "H0", "Z0.");
    }
    toolCount++;
    currentTool = tool;
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    fOutput.reset();
    gMotion.reset();
    lengthOffset = "H" + tool;
    return out + writeBlock("T" + tool, "M6") + writeComment(name)
        + writeBlock("G90", "E1", "S" + Math.round(spindleSpeed), "M3") + writeBlock(coolantCodes.flood);
}

function onComment(text) {
    return writeComment(text);
}

function onCompensation(comp) {
    compensation = comp == COMPENSATION_LEFT ? "G41" : comp == COMPENSATION_RIGHT ? "G42" : "G40";
    if (comp != COMPENSATION_OFF) {
        compensation += " D" + currentTool;
    }
}

function onLinear(vx, vy, vz, movement) {
    var x = xOutput.format(vx);
    var y = yOutput.format(vy);
    var z = zOutput.format(vz);
    if (x == "" && y == "" && z == "") {
        return "";
    }
    if (movement == MOVEMENT_RAPID) {
        return writeBlock(takeCompensation(), gMotion.format(0), x, y, takeLengthOffset(z), z);
    }
    return writeBlock(takeCompensation(), gMotion.format(1), x, y, takeLengthOffset(z), z, feed());
}

// The quadrant index, 0 to 3, of a quarter turn counted from 0 degrees.
function quadrantIndex(k) {
    return ((k % 4) + 4) % 4;
}

// The pieces of an arc: its end, and before it every quadrant point the
// arc passes, each {x, y, z}; Z moves with the angle (a helix).
function arcPieces(cx, cy, sx, sy, sz, ex, ey, ez, isCW) {
    var r = Math.sqrt((sx - cx) * (sx - cx) + (sy - cy) * (sy - cy));
    var a0 = Math.atan2(sy - cy, sx - cx);
    var a1 = Math.atan2(ey - cy, ex - cx);
    var sweep = isCW ? a0 - a1 : a1 - a0;
    while (sweep <= 1e-9) {
        sweep += 2 * Math.PI;
    }
    var quarter = Math.PI / 2;
    var pieces = [];
    var k = isCW ? Math.ceil(a0 / quarter - 1e-9) - 1 : Math.floor(a0 / quarter + 1e-9) + 1;
    for (var n = 0; n < 4; n++) {
        var turned = isCW ? a0 - k * quarter : k * quarter - a0;
        if (turned >= sweep - 1e-6) {
            break;
        }
        var q = quadrants[quadrantIndex(k)];
        pieces.push({x: cx + r * q.c, y: cy + r * q.s, z: sz + (ez - sz) * (turned / sweep)});
        k += isCW ? -1 : 1;
    }
    pieces.push({x: ex, y: ey, z: ez});
    return {radius: r, pieces: pieces};
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var arc = arcPieces(cx, cy, xOutput.getLast(), yOutput.getLast(), zOutput.getLast(), ex, ey, ez, isCW);
    var out = "";
    for (var i = 0; i < arc.pieces.length; i++) {
        var p = arc.pieces[i];
        xOutput.reset();
        yOutput.reset();
        out += writeBlock(i == 0 ? takeCompensation() : "", gMotion.format(isCW ? 2 : 3), xOutput.format(p.x),
            yOutput.format(p.y), zOutput.format(p.z), "R" + xyzFormat.format(arc.radius), feed());
    }
    return out;
}

function onDwell(seconds) {
    return writeBlock("G4", "P" + secondsFormat.format(seconds));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleStarted = false;
    return "";
}

function onDrillingPoint(x, y) {
    if (cycleStarted) {
        return writeBlock(xOutput.format(x), yOutput.format(y));
    }
    cycleStarted = true;
    var code = cycleCodes[drill.name] || (drill.firstDepth > 0 ? "G83" : drill.useBottomDwelling ? "G82" : "G81");
    var out = "";
    var z = zOutput.format(drill.retractPlane);
    if (z != "") {
        out = writeBlock(gMotion.format(0), takeLengthOffset(z), z);
    }
    var words = ["G98", code, xOutput.format(x), yOutput.format(y), "Z" + xyzFormat.format(drill.endDepth),
        "R" + xyzFormat.format(drill.safeDistance)];
    if (code == "G83" || code == "G73") {
        words[words.length] = "Q" + xyzFormat.format(drill.firstDepth);
    }
    if (code == "G82") {
        words[words.length] = "P" + secondsFormat.format(drill.bottomDwelling);
    }
    fOutput.reset();
    words.push(fOutput.format(drill.plungingFeedrate));
    return out + writeBlock.apply(null, words);
}

function onDrillingFooter() {
    var out = cycleStarted ? writeBlock("G80") : "";
    cycleStarted = false;
    gMotion.reset();
    zOutput.reset();
    return out;
}

function onClose() {
    return writeBlock(coolantCodes.off, "M5") + writeBlock("G0", "G90", "H0", "Z0.") + writeBlock("E0", "X0.", "Y0.")
        + writeBlock("M2") + "%" + linebreak;
}
