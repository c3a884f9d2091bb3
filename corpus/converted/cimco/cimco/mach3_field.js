// Converted by postc from mach3_field.js (CIMCO CNC-Calc JavaScript).
/*
 * Mach3 Mill post (mm, .tap style) for CIMCO CNC-Calc, written for the postc
 * corpus in the style posts found in the field are written in: a variadic
 * writeBlock() that reads `arguments` and numbers the block, a header built
 * by a for ... in loop over an object literal of modal groups, switch
 * statements for the movement and the coolant, implicit globals (assigned
 * without `var`, as hobby-shop posts often do), and helpers calling helpers.
 *
 * The program is what Mach3 reads with its default settings: block numbers
 * N10, N20, ...; comments in parentheses; G91.1 (I and J relative to the
 * arc start, whatever the Mach3 "IJ mode" setting says); T M6 then G43 H;
 * G98 canned cycles G81/G82/G83 with G80; G4 P in seconds (Mach3's
 * default; machines set to milliseconds need P scaled by 1000); M30.
 */

var linebreak = "\n";
var tolerance = 0.01;
var useRadius = false;
var absoluteArcCenter = false;
var showSequenceNumbers = true;
var sequenceNumberStart = 10;
var sequenceNumberIncrement = 10;

var MillDrillingFields = [
    {name: "Drilling (G81)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: false, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: true,
     pitch: false, tappingSpeed: false, retractSpeed: false},
    {name: "Peck drilling (G83)", isLonghand: false, plungingFeedrate: true, retractFeedrate: false,
     firstDepth: true, degressionType: false, degression: false, peckingRetract: false,
     minimumDepth: false, firstFeedrateFactor: false, upperDwell: false, lowerDwell: false,
     pitch: false, tappingSpeed: false, retractSpeed: false}
];

var xyzFormat = createFormat({decimals: 4});
var feedFormat = createFormat({decimals: 1});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var fOutput = createVariable({prefix: "F"}, feedFormat);

// The safe-start block, one word per modal group, in this order.
var modalGroups = {plane: "G17", units: "G21", distance: "G90", arcDistance: "G91.1", feedMode: "G94",
    compensation: "G40", lengthOffset: "G49", cycle: "G80"};

function writeBlock() {
    var text = "";
    for (var i = 0; i < arguments.length; i++) {
        if (arguments[i] != "") {
            text = text == "" ? arguments[i] : text + " " + arguments[i];
        }
    }
    if (text == "") {
        return "";
    }
    if (showSequenceNumbers) {
        text = "N" + blockNumber + " " + text;
        blockNumber = blockNumber + sequenceNumberIncrement;
    }
    return text + linebreak;
}

// Mach3 ends a comment at the first ")": parentheses inside are dropped.
function writeComment(text) {
    return "(" + text.replace(/[()]/g, "") + ")" + linebreak;
}

// A rapid up to the safe height, unless the tool is there.
function retract() {
    var z = zOutput.format(safeZ());
    return z == "" ? "" : writeBlock(motion("G0"), z);
}

function coolantCode(mode) {
    switch (mode) {
    case "flood":
        return "M8";
    case "mist":
        return "M7";
    default:
        return "M9";
    }
}

function motionCode(movement) {
    switch (movement) {
    case MOVEMENT_RAPID:
        return "G0";
    case MOVEMENT_PLUNGE:
    case MOVEMENT_CUTTING:
        return "G1";
    }
    return "G1";
}

function feedValue(movement) {
    return parseFloat(getFeedrate(movement).substring(1));
}

function motion(code) {
    if (code == lastMotion) {
        return "";
    }
    lastMotion = code;
    return code;
}

function resetModals() {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    fOutput.reset();
    lastMotion = "";
}

function onOpen(isClipboard) {
    blockNumber = sequenceNumberStart;
    lastMotion = "";
    compensation = "";
    toolCount = 0;
    var header = [];
    for (var group in modalGroups) {
        header.push(modalGroups[group]);
    }
    return "%" + linebreak + writeComment("MACH3 FIELD-STYLE POST, CIMCO CNC-CALC")
        + writeBlock.apply(null, header);
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    if (toolCount > 0) {
        out = writeBlock("M5", coolantCode("off")) + retract();
    }
    toolCount = toolCount + 1;
    resetModals();
    return out + writeComment("T" + tool + " - " + name.toUpperCase()) + writeBlock("T" + tool, "M6")
        + writeBlock("G43", "H" + tool) + writeBlock("S" + spindleSpeed, "M3") + writeBlock(coolantCode("flood"));
}

function safeZ() {
    return 25;
}

function onComment(text) {
    return writeComment(text);
}

function onCompensation(comp) {
    switch (comp) {
    case COMPENSATION_LEFT:
        compensation = "G41";
        break;
    case COMPENSATION_RIGHT:
        compensation = "G42";
        break;
    default:
        compensation = "G40";
    }
}

function takeCompensation() {
    var c = compensation;
    compensation = "";
    return c;
}

function onLinear(vx, vy, vz, movement) {
    var x = xOutput.format(vx);
    var y = yOutput.format(vy);
    var z = zOutput.format(vz);
    if (x == "" && y == "" && z == "") {
        return "";
    }
    var f = movement == MOVEMENT_RAPID ? "" : fOutput.format(feedValue(movement));
    return writeBlock(takeCompensation(), motion(motionCode(movement)), x, y, z, f);
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    xOutput.reset();
    yOutput.reset();
    return writeBlock(takeCompensation(), motion(isCW ? "G2" : "G3"), xOutput.format(ex), yOutput.format(ey),
        zOutput.format(ez), "I" + xyzFormat.format(cx - sx), "J" + xyzFormat.format(cy - sy),
        fOutput.format(feedValue(movement)));
}

function onDwell(seconds) {
    return writeBlock("G4", "P" + seconds);
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    holes = 0;
    return "";
}

function onDrillingPoint(x, y) {
    holes = holes + 1;
    if (holes > 1) {
        return writeBlock(xOutput.format(x), yOutput.format(y));
    }
    var code = drill.firstDepth > 0 ? "G83" : drill.useBottomDwelling ? "G82" : "G81";
    var z = zOutput.format(drill.retractPlane);
    var out = z == "" ? "" : writeBlock(motion("G0"), z);
    xOutput.reset();
    yOutput.reset();
    fOutput.reset();
    return out + writeBlock("G98", code, xOutput.format(x), yOutput.format(y), "Z" + xyzFormat.format(drill.endDepth),
        "R" + xyzFormat.format(drill.safeDistance), code == "G83" ? "Q" + xyzFormat.format(drill.firstDepth) : "",
        code == "G82" ? "P" + drill.bottomDwelling : "", fOutput.format(drill.plungingFeedrate));
}

function onDrillingFooter() {
    lastMotion = "";
    zOutput.reset();
    return holes > 0 ? writeBlock("G80") : "";
}

function onClose() {
    return writeBlock("M5", coolantCode("off")) + retract() + writeBlock(motion("G0"), "X0", "Y0") + writeBlock("M30") + "%" + linebreak;
}
