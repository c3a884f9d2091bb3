// Converted by postc from okuma_field.js (CIMCO CNC-Calc JavaScript).
/*
 * Okuma OSP-P milling post (mm) for CIMCO CNC-Calc, written for the postc
 * corpus in the style posts found in the field are written in: every block
 * is built by string concatenation and handed to a one-argument
 * writeBlock(); switch statements pick the motion and coolant codes;
 * implicit globals (assigned without `var`) carry the state; a do ... while
 * loop cuts long comments into the 32-character pieces the OSP screen
 * shows; object literals are the cycle and coolant tables.
 *
 * OSP conventions: the program name O1001; comments in parentheses; G15 H1
 * selects work coordinate system 1; a tool change is T M06 with the tool
 * length offset G56 H on the first Z move (Okuma's G56, not G43), and each
 * tool starts a numbered sequence N1, N2, ... (OSP restarts by sequence
 * name); fixed cycles G81/G82/G83 with R, Q and P (dwell in seconds) return
 * to the level G71 sets; dwell G04 F in seconds; G30 P1 sends the machine
 * to its zero point; M02 ends the program.
 */

var linebreak = "\n";
var tolerance = 0.01;
var useRadius = false;
var absoluteArcCenter = false;

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

var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 0});
var dwellFormat = createFormat({decimals: 2, forceDecimal: true});
var xOutput = createVariable({prefix: " X"}, xyzFormat);
var yOutput = createVariable({prefix: " Y"}, xyzFormat);
var zOutput = createVariable({prefix: " Z"}, xyzFormat);
var fOutput = createVariable({prefix: " F"}, feedFormat);
var gMotion = createVariable({prefix: " G"}, createFormat({decimals: 0, width: 2, zeropad: true}));

var coolants = {flood: " M08", mist: " M07", off: " M09"};
var cycles = {"Drilling (G81)": 81, "Peck drilling (G83)": 83};
var commentWidth = 32;

function writeBlock(text) {
    if (text == "") {
        return "";
    }
    return text.substring(1) + linebreak;
}

// Long comments become several comment blocks of at most commentWidth
// characters, cut at a blank where there is one; parentheses inside a
// comment become brackets.
function writeComment(text) {
    var clean = text.toUpperCase().split("(").join("[").split(")").join("]");
    var out = "";
    var at = 0;
    do {
        var end = at + commentWidth;
        if (end < clean.length) {
            // The last blank at or before `end`.
            var blank = clean.lastIndexOf(" ", end);
            if (blank > at) {
                end = blank;
            }
        }
        out = out + "(" + clean.substring(at, end) + ")" + linebreak;
        at = end;
        while (clean.charAt(at) == " ") {
            at = at + 1;
        }
    } while (at < clean.length);
    return out;
}

function coolant(mode) {
    var code;
    switch (mode) {
    case 1:
        code = coolants.flood;
        break;
    case 2:
        code = coolants.mist;
        break;
    default:
        code = coolants.off;
        break;
    }
    return code;
}

function motionWord(movement) {
    switch (movement) {
    case MOVEMENT_RAPID:
        return gMotion.format(0);
    default:
        return gMotion.format(1);
    }
}

function feedWord(movement) {
    if (movement == MOVEMENT_RAPID) {
        return "";
    }
    return fOutput.format(parseFloat(getFeedrate(movement).substring(1)));
}

// The tool length offset goes on the first Z move after a tool change.
function lengthOffset() {
    if (pendingLength == 0) {
        return "";
    }
    var h = " G56 H" + pendingLength;
    pendingLength = 0;
    return h;
}

function onOpen(isClipboard) {
    sequence = 0;
    pendingLength = 0;
    compensation = "";
    activeTool = 0;
    return writeBlock(" O1001") + writeComment("Okuma OSP-P field-style post for CIMCO CNC-Calc")
        + writeBlock(" G15 H1") + writeBlock(" G17 G21 G40 G80 G90 G94");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    if (activeTool != 0) {
        out = writeBlock(coolant(0) + " M05") + writeBlock(" G30 P1");
    }
    activeTool = tool;
    sequence = sequence + 1;
    pendingLength = tool;
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    fOutput.reset();
    gMotion.reset();
    out = out + writeComment(name + " D" + xyzFormat.format(diameter));
    return out + writeBlock(" N" + sequence + " T" + tool + " M06") + writeBlock(" S" + Math.round(spindleSpeed) + " M03" + coolant(1));
}

function onComment(text) {
    return writeComment(text);
}

function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        compensation = " G41 D" + activeTool;
    } else if (comp == COMPENSATION_RIGHT) {
        compensation = " G42 D" + activeTool;
    } else {
        compensation = " G40";
    }
}

function getCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vy, vz, movement) {
    var x = xOutput.format(vx);
    var y = yOutput.format(vy);
    var z = zOutput.format(vz);
    if (x + y + z == "") {
        return "";
    }
    var h = z != "" ? lengthOffset() : "";
    return writeBlock(getCompensation() + motionWord(movement) + h + x + y + z + feedWord(movement));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    xOutput.reset();
    yOutput.reset();
    return writeBlock(getCompensation() + gMotion.format(isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey)
        + zOutput.format(ez) + " I" + xyzFormat.format(cx - sx) + " J" + xyzFormat.format(cy - sy)
        + feedWord(movement));
}

function onDwell(seconds) {
    return writeBlock(" G04 F" + dwellFormat.format(seconds));
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    holeCount = 0;
    return "";
}

function cycleCode() {
    var code = cycles[drill.name];
    if (code == undefined) {
        code = drill.firstDepth > 0 ? 83 : 81;
    }
    if (code == 81 && drill.useBottomDwelling) {
        code = 82;
    }
    return code;
}

function onDrillingPoint(x, y) {
    holeCount = holeCount + 1;
    if (holeCount > 1) {
        return writeBlock(xOutput.format(x) + yOutput.format(y));
    }
    var code = cycleCode();
    var block = " G" + code + xOutput.format(x) + yOutput.format(y) + " Z" + xyzFormat.format(drill.endDepth)
        + " R" + xyzFormat.format(drill.safeDistance);
    if (code == 83) {
        block = block + " Q" + xyzFormat.format(drill.firstDepth);
    }
    if (drill.useBottomDwelling) {
        block = block + " P" + dwellFormat.format(drill.bottomDwelling);
    }
    var approach = "";
    if (pendingLength != 0) {
        approach = writeBlock(gMotion.format(0) + lengthOffset() + zOutput.format(drill.retractPlane));
    }
    fOutput.reset();
    return approach + writeBlock(" G71 Z" + xyzFormat.format(drill.retractPlane)) + writeBlock(block + fOutput.format(drill.plungingFeedrate));
}

function onDrillingFooter() {
    gMotion.reset();
    zOutput.reset();
    return holeCount > 0 ? writeBlock(" G80") : "";
}

function onClose() {
    return writeBlock(coolant(0) + " M05") + writeBlock(" G30 P1") + writeBlock(" M02");
}
