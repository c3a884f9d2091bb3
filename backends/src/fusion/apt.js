// An Autodesk Fusion post made from a VcPost milling post (one Sub per
// APT major word): the Subs run as written inside `vcPost` below, with
// BASIC's values as the source's engine computes them, and Fusion's entry
// points at the end make the APT records that engine makes of the same
// toolpath: PARTNO at onOpen; LOADTL when a section's tool is not the
// last one, TOOLPATH at each section, SPINDL where a tool is loaded or the
// speed changes, COOLNT where the coolant changes; RAPID and GOTO, FEDRAT
// and GOTO, CIRCLE for the moves; DELAY, PPRINT, CUTCOM; CYCLE, GOTO for
// each later hole and CYCLE OFF for a drilling cycle; FINI at onClose
// (docs/convert.md, "VcPost posts as Fusion posts").
{{SETTINGS}}
// Each line the Subs write ends with the source's line ending.
setEOL({{LINEBREAK}});

// The source post, and the adapter that calls its Subs.
var vcPost = (function () {
{{SOURCE}}
})();

// Fusion hands lengths and feeds in the document's units; the post
// prints them in {{UNITS}}, each multiplied by `aptScale`.
var aptScale = 1;
var aptInSection = false;
var aptWaiting = [];
var aptLastTool = NaN;
var aptSpindle = null;
var aptCoolant = "OFF";
var aptCycle = null;
var aptHoles = 0;

// Writes the lines one record's Subs wrote, each ended with EOL.
function aptWrite(text) {
    var lines = String(text).split("\n");
    for (var i = 0; i + 1 < lines.length; i++) {
        writeln(lines[i]);
    }
}

// A record Fusion hands between sections (a comment, a dwell) comes after
// the next section's tool and toolpath records, as in the toolpath.
function aptInOrder(record) {
    if (aptInSection) {
        aptWrite(record());
    } else {
        aptWaiting.push(record);
    }
}

// The name of the program's file, without its folder and extension: the
// part name the source's engine hands PARTNO when the job names no part.
function aptProgramName() {
    var name = FileSystem.getFilename(getOutputPath());
    var dot = name.lastIndexOf(".");
    return dot > 0 ? name.substring(0, dot) : name;
}

function onOpen() {
    {{SCALE}}
    aptWrite(vcPost.open(aptProgramName(), {{METRIC}}));
}

// SPINDL where the tool was just loaded, or the speed or direction
// changed; a speed of 0 switches nothing on.
function aptSpindleTo(speed, loaded) {
    var ccw = !tool.clockwise;
    if (!(speed > 0)) {
        return;
    }
    if (loaded || aptSpindle === null || aptSpindle.speed !== speed || aptSpindle.ccw !== ccw) {
        aptSpindle = {speed: speed, ccw: ccw};
        aptWrite(vcPost.spindleOn(speed, ccw));
    }
}

// COOLNT's minor word of a Fusion coolant.
function aptCoolantWord(coolant) {
    switch (coolant) {
    case COOLANT_OFF:
        return "OFF";
    case COOLANT_FLOOD:
        return "FLOOD";
    case COOLANT_MIST:
        return "MIST";
    case COOLANT_AIR:
        return "AIR";
    default:
        return "ON";
    }
}

function aptCoolantTo(word) {
    if (word !== aptCoolant) {
        aptCoolant = word;
        aptWrite(vcPost.coolant(word));
    }
}

function onSection() {
    var loaded = tool.number !== aptLastTool;
    if (loaded) {
        aptLastTool = tool.number;
        aptSpindle = null;
        aptWrite(vcPost.loadtl(tool.number, tool.lengthOffset, tool.diameterOffset, tool.description));
    }
    aptWrite(vcPost.toolpath(getParameter("operation-comment", "")));
    aptSpindleTo(spindleSpeed, loaded);
    aptCoolantTo(aptCoolantWord(tool.coolant));
    aptInSection = true;
    var waiting = aptWaiting;
    aptWaiting = [];
    for (var i = 0; i < waiting.length; i++) {
        aptWrite(waiting[i]());
    }
}

function onSectionEnd() {
    aptInSection = false;
}

function onSpindleSpeed(speed) {
    aptSpindleTo(speed, false);
}

function onCommand(command) {
    switch (command) {
    case COMMAND_COOLANT_ON:
        aptCoolantTo(aptCoolantWord(tool.coolant));
        break;
    case COMMAND_COOLANT_OFF:
        aptCoolantTo("OFF");
        break;
    case COMMAND_STOP_SPINDLE:
        aptSpindle = null;
        aptWrite(vcPost.spindleOff());
        break;
    case COMMAND_START_SPINDLE:
    case COMMAND_SPINDLE_CLOCKWISE:
    case COMMAND_SPINDLE_COUNTERCLOCKWISE:
        aptSpindleTo(spindleSpeed, true);
        break;
    default:
        break;
    }
}

function onRadiusCompensation() {
    var side = radiusCompensation == RADIUS_COMPENSATION_LEFT ? "LEFT" : radiusCompensation == RADIUS_COMPENSATION_RIGHT ? "RIGHT" : "OFF";
    aptWrite(vcPost.cutcom(side, tool.diameterOffset));
}

function onRapid(x, y, z) {
    var k = aptScale;
    aptWrite(vcPost.rapid(x * k, y * k, z * k));
}

function onLinear(x, y, z, feed) {
    var k = aptScale;
    aptWrite(vcPost.linear(x * k, y * k, z * k, feed * k));
}

// An arc, whole: G 2 clockwise, 3 counterclockwise, seen from the plane's
// positive normal; Plane 17, 18 or 19.
function onCircular(clockwise, cx, cy, cz, x, y, z, feed) {
    var k = aptScale;
    var plane = getCircularPlane() == PLANE_ZX ? 18 : getCircularPlane() == PLANE_YZ ? 19 : 17;
    aptWrite(vcPost.circle(x * k, y * k, z * k, cx * k, cy * k, cz * k, clockwise ? 2 : 3, plane, getCircularRadius() * k, feed * k));
}

function onDwell(seconds) {
    aptInOrder(function () {
        return vcPost.delay(seconds);
    });
}

function onComment(text) {
    aptInOrder(function () {
        return vcPost.pprint(text);
    });
}

// CYCLE's minor word of a Fusion cycle type.
var aptCycleWords = {
    "drilling": "DRILL",
    "counter-boring": "DRILL",
    "deep-drilling": "DEEP",
    "chip-breaking": "BRKCHP",
    "tapping": "TAP",
    "left-tapping": "TAP",
    "right-tapping": "TAP",
    "boring": "BORE",
    "reaming": "REAM"
};

function onCycle() {
    aptCycle = aptCycleWords[cycleType] !== undefined ? aptCycleWords[cycleType] : "DRILL";
    aptHoles = 0;
}

// The first hole is the CYCLE record (its bottom, R plane, peck, dwell
// and feed), each later one a GOTO to the top of the hole.
function onCyclePoint(x, y, z) {
    var k = aptScale;
    aptHoles++;
    if (aptHoles > 1) {
        aptWrite(vcPost.hole(x * k, y * k, cycle.stock * k));
        return;
    }
    var pecking = aptCycle == "DEEP" || aptCycle == "BRKCHP";
    var dwell = cycle.dwell > 0 ? cycle.dwell : 0;
    aptWrite(vcPost.cycle(aptCycle, x * k, y * k, cycle.stock * k, z * k, cycle.retract * k,
        pecking ? cycle.incrementalDepth * k : 0, dwell, cycle.feedrate * k));
}

function onCycleEnd() {
    if (aptHoles > 0) {
        aptWrite(vcPost.cycleOff());
    }
    aptCycle = null;
    aptHoles = 0;
}

function onClose() {
    aptWrite(vcPost.fini());
}
