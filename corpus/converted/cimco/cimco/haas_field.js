// Converted by postc from haas_field.js (CIMCO CNC-Calc JavaScript).
/*
 * Haas VF milling post (mm) for CIMCO CNC-Calc, written for the postc corpus in
 * the style posts found in the field are written in: a variadic
 * writeBlock() that reads `arguments`, words gathered in an array and
 * joined with blanks, object literals as look-up tables (coolant codes,
 * cycle codes), a do ... while loop, and helpers that call helpers. Block
 * numbers N10, N20, ...; the program number is padded to four digits.
 */

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var linebreak = "\n";
var showSequenceNumbers = true;
var sequenceNumber = 10;
var sequenceNumberIncrement = 10;
var programNumber = 42;

var xyzFormat = createFormat({decimals: 4, forceDecimal: true});
var feedFormat = createFormat({decimals: 1, forceDecimal: true});
var rpmFormat = createFormat({decimals: 0});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var fOutput = createVariable({prefix: "F"}, feedFormat);
var gMotion = createVariable({prefix: "G"}, createFormat({decimals: 0}));

// Look-up tables, as object literals.
var coolantCodes = {off: "M09", flood: "M08", mist: "M07"};
var arcCodes = {1: "G02", 0: "G03"};
var cycleCodes = {"Drilling (G81)": "G81", "Peck drilling (G83)": "G83"};
var drill;
var cycleStarted = false;

// Every argument that is not empty, joined by blanks, after a block number.
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
    var text = words.join(" ");
    if (showSequenceNumbers) {
        text = "N" + sequenceNumber + " " + text;
        sequenceNumber += sequenceNumberIncrement;
    }
    return text + linebreak;
}

function writeComment(text) {
    return "(" + text.toUpperCase() + ")" + linebreak;
}

// The program number, padded with zeros to four digits.
function programName(n) {
    var s = "" + n;
    do {
        s = "0" + s;
    } while (s.length < 5);
    return "O" + s.substring(1);
}

function coolant(kind) {
    return coolantCodes[kind];
}

function onOpen(isClipboard) {
    return "%" + linebreak + programName(programNumber) + linebreak + writeComment("Haas field-style post")
        + writeBlock("G90", "G17", "G21", "G40", "G80");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    gMotion.reset();
    fOutput.reset();
    return writeBlock("T" + tool, "M06") + writeComment(name)
        + writeBlock("S" + rpmFormat.format(spindleSpeed), "M03") + writeBlock(coolant("flood"));
}

function onLinear(vx, vy, vz, movement) {
    var x = xOutput.format(vx);
    var y = yOutput.format(vy);
    var z = zOutput.format(vz);
    if (x == "" && y == "" && z == "") {
        return "";
    }
    if (movement == MOVEMENT_RAPID) {
        return writeBlock(gMotion.format(0), x, y, z);
    }
    return writeBlock(gMotion.format(1), x, y, z, fOutput.format(getFeedrateValue()));
}

function getFeedrateValue() {
    var f = getFeedrate(MOVEMENT_CUTTING);
    return parseFloat(f.substring(1));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    gMotion.reset();
    return writeBlock(arcCodes[isCW ? 1 : 0], xOutput.format(ex), yOutput.format(ey), zOutput.format(ez),
        "I" + xyzFormat.format(cx - sx), "J" + xyzFormat.format(cy - sy), fOutput.format(getFeedrateValue()));
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
    var code = cycleCodes[drill.name] || (drill.firstDepth > 0 ? "G83" : "G81");
    if (drill.useBottomDwelling && code == "G81") {
        code = "G82";
    }
    var words = ["G98", code, xOutput.format(x), yOutput.format(y)];
    var bottom = drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
    var r = drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
    words.push("Z" + xyzFormat.format(bottom), "R" + xyzFormat.format(r));
    if (code == "G83") {
        words.push("Q" + xyzFormat.format(drill.firstDepth));
    }
    if (drill.useBottomDwelling) {
        words.push("P" + Math.round(drill.bottomDwelling * 1000));
    }
    words.push("F" + feedFormat.format(drill.plungingFeedrate));
    return writeBlock.apply(null, words);
}

function onDrillingFooter() {
    var out = "";
    if (cycleStarted) {
        out = writeBlock("G80");
        gMotion.reset();
        zOutput.reset();
    }
    cycleStarted = false;
    return out;
}

function onDwell(seconds) {
    return writeBlock("G04", "P" + xyzFormat.format(seconds));
}

function onClose() {
    return writeBlock(coolant("off")) + writeBlock("M05") + writeBlock("G91", "G28", "Z0.") + writeBlock("M30")
        + "%" + linebreak;
}
