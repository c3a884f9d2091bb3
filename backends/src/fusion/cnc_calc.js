// An Autodesk Fusion post made from a CIMCO CNC-Calc post: the CNC-Calc
// post runs as written inside `cncCalc` below, beside the CNC-Calc host
// names it calls (createFormat, createVariable, getFeedrate and the
// MOVEMENT_, COMPENSATION_, DEGRESSION_ and POST_TYPE_ constants, as
// docs/cimco.md defines them), and Fusion's entry points at the end call
// it in CNC-Calc's order: onInit and onOpen(false) at the first section,
// onToolChange at each new tool, onLinear and onCircular for the moves,
// the drilling functions for each cycle, onCompensation, onDwell,
// onComment, onToolpathEnd and onClose (docs/convert.md, "CIMCO posts as
// Fusion posts").

// Fusion hands every arc whole: the post gets an arc in XY (split only
// as useRadius asks, below) and one in another plane as chords, as
// CNC-Calc does.
{{SETTINGS}}
// The CNC-Calc post and its host.
var cncCalc = (function () {
    // The settings a CNC-Calc post may give without `var`: the post's own
    // here, not Fusion's (Fusion has a `tolerance` of its own).
    var linebreak, decimalMark, variableDelimeter, tolerance, useRadius, absoluteArcCenter;
    var showSequenceNumbers, sequenceNumberStart, sequenceNumberIncrement, xDiameterProg, iDiameterProg;
    var globals, PostInfo, MillDrillingFields, TurnDrillingFields;
{{UNDEFINED}}
    var MOVEMENT_RAPID = 0, MOVEMENT_CUTTING = 1, MOVEMENT_FEED = 1, MOVEMENT_PLUNGE = 2, MOVEMENT_RETRACT = 3;
    var COMPENSATION_OFF = 0, COMPENSATION_LEFT = 1, COMPENSATION_RIGHT = 2;
    var POST_TYPE_MILL = 0, POST_TYPE_TURN = 1;
    var DEGRESSION_NONE = 0, DEGRESSION_VALUE = 1, DEGRESSION_FACTOR = 2;

    // A setting in either form: `name` or `globals.name`.
    function __cncSetting(name, own) {
        if (own !== undefined) {
            return own;
        }
        return globals !== null && typeof globals == "object" ? globals[name] : undefined;
    }

    // The first format given a value that is not a finite number since
    // the last call: the post stops there even when its `catch` took the
    // error, as it stops in postc.
    var __cncStopped = null;

    // createFormat({prefix, width, zeropad, decimals, scale, forceDecimal,
    // forceSign}): the value times scale, rounded to `decimals` places as
    // JavaScript's toFixed rounds it; without forceDecimal trailing zeros
    // (and then the point) dropped; width pads the integer digits after
    // the sign (zeros with zeropad, blanks otherwise); forceSign writes
    // "+"; the decimal mark is `decimalMark` when the format is made.
    function createFormat(props) {
        props = props || {};
        var decimals = props.decimals === undefined ? 0 : Number(props.decimals);
        decimals = isFinite(decimals) ? Math.min(15, Math.max(0, Math.floor(decimals))) : 0;
        var width = props.width === undefined ? 0 : Number(props.width);
        width = isFinite(width) ? Math.min(64, Math.max(0, Math.floor(width))) : 0;
        var zeropad = !!props.zeropad;
        var forceDecimal = !!props.forceDecimal;
        var forceSign = !!props.forceSign;
        var scale = props.scale === undefined ? 1 : Number(props.scale);
        if (!isFinite(scale)) {
            scale = 1;
        }
        var prefix = props.prefix === undefined ? "" : String(props.prefix);
        var mark = __cncSetting("decimalMark", decimalMark) === "," ? "," : ".";
        var pad = zeropad ? "0" : " ";
        function format(value) {
            var v = Number(value) * scale;
            if (!isFinite(v)) {
                var e = new Error("format() was given " + value + ", which is not a finite number");
                if (__cncStopped === null) {
                    __cncStopped = e;
                }
                throw e;
            }
            var text = Math.abs(v).toFixed(decimals);
            var dot = text.indexOf(".");
            var intPart = dot < 0 ? text : text.substring(0, dot);
            var fracText = dot < 0 ? "" : text.substring(dot + 1);
            if (!forceDecimal) {
                fracText = fracText.replace(/0+$/, "");
            }
            var zero = /^0*$/.test(intPart + fracText);
            var sign = v < 0 && !zero ? "-" : forceSign ? "+" : "";
            while (intPart.length < width) {
                intPart = pad + intPart;
            }
            var point = fracText.length > 0 || forceDecimal ? mark : "";
            return prefix + sign + intPart + point + fracText;
        }
        return {format: format};
    }

    // createVariable({prefix, force}, format): format(v) is "" when the
    // text is the one it gave last (unless force), for the whole program;
    // getLast() the last value; reset() forgets the text.
    function createVariable(props, format) {
        props = props || {};
        var prefix = props.prefix === undefined ? "" : String(props.prefix);
        var force = !!props.force;
        var fmt = format || createFormat({});
        var lastText = null;
        var lastValue = 0;
        return {
            format: function (value) {
                var v = Number(value);
                var text = prefix + fmt.format(v);
                lastValue = v;
                var same = !force && lastText === text;
                lastText = text;
                return same ? "" : text;
            },
            getLast: function () {
                return lastValue;
            },
            reset: function () {
                lastText = null;
            }
        };
    }

    // getFeedrate(movement): "" for a rapid, else the move's feed as `F`
    // with one decimal at most.
    var __cncFeed = 0;
    var __cncFeedVariable = null;
    function getFeedrate(movement) {
        if (movement == MOVEMENT_RAPID) {
            return "";
        }
        return __cncFeedVariable.format(__cncFeed);
    }

{{SOURCE}}

    return {
        // The post's setting `name`, in either form.
        setting: function (name) {
            switch (name) {
            case "linebreak":
                return __cncSetting(name, linebreak);
            case "useRadius":
                return __cncSetting(name, useRadius);
            case "MillDrillingFields":
                return __cncSetting(name, MillDrillingFields);
            }
            return undefined;
        },
        // The post's entry point `name`, if it defines it.
        entry: function (name) {
            switch (name) {
            case "onInit":
                return typeof onInit == "function" ? onInit : undefined;
            case "onOpen":
                return typeof onOpen == "function" ? onOpen : undefined;
            case "onToolChange":
                return typeof onToolChange == "function" ? onToolChange : undefined;
            case "onLinear":
                return typeof onLinear == "function" ? onLinear : undefined;
            case "onCircular":
                return typeof onCircular == "function" ? onCircular : undefined;
            case "onCompensation":
                return typeof onCompensation == "function" ? onCompensation : undefined;
            case "onDwell":
                return typeof onDwell == "function" ? onDwell : undefined;
            case "onComment":
                return typeof onComment == "function" ? onComment : undefined;
            case "onToolpathEnd":
                return typeof onToolpathEnd == "function" ? onToolpathEnd : undefined;
            case "onDrillingHeader":
                return typeof onDrillingHeader == "function" ? onDrillingHeader : undefined;
            case "onDrillingPoint":
                return typeof onDrillingPoint == "function" ? onDrillingPoint : undefined;
            case "onDrillingFooter":
                return typeof onDrillingFooter == "function" ? onDrillingFooter : undefined;
            case "onClose":
                return typeof onClose == "function" ? onClose : undefined;
            }
            return undefined;
        },
        // After the post's top level: getFeedrate's variable.
        start: function () {
            __cncFeedVariable = createVariable({prefix: "F", force: true}, createFormat({decimals: 1}));
        },
        setFeed: function (feed) {
            __cncFeed = feed;
        },
        // The error of a format given no finite number, which stops the
        // post even when its `catch` took it.
        takeStop: function () {
            var e = __cncStopped;
            __cncStopped = null;
            return e;
        }
    };
})();

// Each line the post returns ends with its `linebreak`; inserted text too.
var cncLinebreak = cncCalc.setting("linebreak");
setEOL(typeof cncLinebreak == "string" && cncLinebreak !== "" ? cncLinebreak : "\n");

var cncStarted = false;
// Between a section's end and the next one's first move (where Fusion
// calls onSection), comments and dwells wait for the tool change CNC-Calc
// makes at the toolpath's start; before onOpen there is no program yet.
var cncOpened = false;
var cncInSection = false;
var cncWaiting = [];
var cncLastTool = NaN;
var cncSpindle = 0;
var cncPosition = [0, 0, 0];
// Fusion hands lengths and feeds in the document's units; the post
// prints them in {{UNITS}}, each multiplied by `cncScale`.
var cncScale = 1;

// Calls the post's entry point with `args` and writes what it returns:
// each line that is not empty (a "\r" before its "\n" dropped).
function cncCall(name, args) {
    var f = cncCalc.entry(name);
    if (typeof f != "function") {
        return;
    }
    var value = f.apply(null, args);
    var stop = cncCalc.takeStop();
    if (stop !== null) {
        throw stop;
    }
    if (value === undefined || value === null) {
        return;
    }
    var lines = String(value).split("\n");
    for (var i = 0; i < lines.length; i++) {
        var line = lines[i];
        if (line.charAt(line.length - 1) == "\r") {
            line = line.substring(0, line.length - 1);
        }
        if (line !== "") {
            writeln(line);
        }
    }
}

function cncToolChange() {
    cncCall("onToolChange", [tool.number, tool.description, tool.diameter * cncScale, cncSpindle]);
}

function onOpen() {
    {{SCALE}}
    cncCalc.start();
    cncCall("onInit", []);
    cncOpened = true;
}

// A call Fusion makes between sections: after the next section's tool
// change.
function cncInOrder(name, args) {
    if (!cncOpened) {
        return;
    }
    if (cncInSection) {
        cncCall(name, args);
    } else {
        cncWaiting.push([name, args]);
    }
}

// A toolpath: the first opens the program and loads its tool, a later
// one with another tool changes it.
function onSection() {
    cncSpindle = spindleSpeed;
    if (!cncStarted) {
        cncStarted = true;
        cncCall("onOpen", [false]);
        cncToolChange();
    } else if (tool.number !== cncLastTool) {
        cncToolChange();
    }
    cncLastTool = tool.number;
    cncInSection = true;
    var waiting = cncWaiting;
    cncWaiting = [];
    for (var i = 0; i < waiting.length; i++) {
        cncCall(waiting[i][0], waiting[i][1]);
    }
}

function onSpindleSpeed(speed) {
    cncSpindle = speed;
}

function onSectionEnd() {
    cncInSection = false;
    cncCall("onToolpathEnd", []);
}

function onRapid(x, y, z) {
    cncPosition = [x * cncScale, y * cncScale, z * cncScale];
    cncCall("onLinear", [cncPosition[0], cncPosition[1], cncPosition[2], 0]);
}

// A feed move; one straight down, or one Fusion says plunges, is a
// plunge (MOVEMENT_PLUNGE).
function onLinear(x, y, z, feed) {
    cncFeedTo(x * cncScale, y * cncScale, z * cncScale, feed * cncScale);
}

// A feed move in the post's units.
function cncFeedTo(x, y, z, feed) {
    var down = x === cncPosition[0] && y === cncPosition[1] && z < cncPosition[2];
    var plunge = movement == MOVEMENT_PLUNGE || down;
    cncCalc.setFeed(feed);
    cncPosition = [x, y, z];
    cncCall("onLinear", [x, y, z, plunge ? 2 : 1]);
}

// An arc in the plane of the axes (u, v) about w, from the last position
// to e around c, as postc's runtime cuts it (runtime/src/geometry.rs):
// equal-angle chords within `tolerance` ({{TOLERANCE}} in the post's
// units), at most 10,000.
function cncChords(axes, c, e, clockwise, feed) {
    var u = axes[0], v = axes[1], w = axes[2];
    var s = cncPosition;
    var su = s[u] - c[u], sv = s[v] - c[v];
    var r = Math.sqrt(su * su + sv * sv);
    var a0 = Math.atan2(sv, su);
    var a1 = Math.atan2(e[v] - c[v], e[u] - c[u]);
    var TAU = 2 * Math.PI;
    var du = e[u] - s[u], dv = e[v] - s[v];
    var closed = Math.sqrt(du * du + dv * dv) <= 1e-9 * Math.max(r, 1);
    var turn = closed ? TAU : ((clockwise ? a0 - a1 : a1 - a0) % TAU + TAU) % TAU;
    if (turn <= 1e-12) {
        turn = TAU;
    }
    var sweep = clockwise ? -turn : turn;
    var n = 1;
    if (r > 0 && r < Infinity) {
        var step = 2 * Math.acos(1 - Math.min(Math.max({{TOLERANCE}} / r, 0), 1));
        n = step <= 0 ? 1000000 : Math.min(Math.max(Math.ceil(Math.abs(sweep) / step), 1), 1000000);
    }
    n = Math.min(n, 10000);
    for (var i = 1; i <= n; i++) {
        var t = i / n;
        if (t >= 1) {
            cncFeedTo(e[0], e[1], e[2], feed);
        } else {
            var a = a0 + sweep * t;
            var p = [0, 0, 0];
            p[u] = c[u] + r * Math.cos(a);
            p[v] = c[v] + r * Math.sin(a);
            p[w] = s[w] + (e[w] - s[w]) * t;
            cncFeedTo(p[0], p[1], p[2], feed);
        }
    }
}

// An arc in XY: whole, or under `useRadius` in n = floor(|sweep| / pi +
// 1e-9) + 1 equal parts, so that no part turns 180 degrees or more; the
// centre's Z is the arc's start Z.
function onCircular(clockwise, cx, cy, cz, x, y, z, feed) {
    cx *= cncScale;
    cy *= cncScale;
    cz *= cncScale;
    x *= cncScale;
    y *= cncScale;
    z *= cncScale;
    feed *= cncScale;
    if (getCircularPlane() != PLANE_XY) {
        cncChords(getCircularPlane() == PLANE_ZX ? [2, 0, 1] : [1, 2, 0], [cx, cy, cz], [x, y, z], clockwise, feed);
        return;
    }
    cncCalc.setFeed(feed);
    var s = cncPosition;
    var r = Math.sqrt((s[0] - cx) * (s[0] - cx) + (s[1] - cy) * (s[1] - cy));
    var a0 = Math.atan2(s[1] - cy, s[0] - cx);
    var a1 = Math.atan2(y - cy, x - cx);
    var closed = Math.sqrt((x - s[0]) * (x - s[0]) + (y - s[1]) * (y - s[1])) <= 1e-9 * Math.max(r, 1);
    var TAU = 2 * Math.PI;
    var turn = closed ? TAU : ((clockwise ? a0 - a1 : a1 - a0) % TAU + TAU) % TAU;
    if (turn <= 1e-12) {
        turn = TAU;
    }
    var sweep = clockwise ? -turn : turn;
    var parts = cncCalc.setting("useRadius") ? Math.floor(Math.abs(sweep) / Math.PI + 1e-9) + 1 : 1;
    for (var i = 1; i <= parts; i++) {
        var px = x, py = y, pz = z;
        if (i < parts) {
            var t = i / parts;
            var a = a0 + sweep * t;
            px = cx + r * Math.cos(a);
            py = cy + r * Math.sin(a);
            pz = s[2] + (z - s[2]) * t;
        }
        cncCall("onCircular", [cx, cy, s[2], px, py, pz, clockwise, 1]);
    }
    cncPosition = [x, y, z];
}

function onDwell(seconds) {
    cncInOrder("onDwell", [seconds]);
}

function onComment(text) {
    cncInOrder("onComment", [text]);
}

function onRadiusCompensation() {
    var comp = radiusCompensation == RADIUS_COMPENSATION_LEFT ? 1 : radiusCompensation == RADIUS_COMPENSATION_RIGHT ? 2 : 0;
    if (cncStarted) {
        cncCall("onCompensation", [comp]);
    }
}

// The drilling cycle as CNC-Calc's drill header (docs/cimco.md): its
// name is the kind's, since Fusion hands a cycle's type and no name.
var cncCycleNames = {
    "drilling": "Drilling",
    "counter-boring": "Drilling",
    "deep-drilling": "Peck drilling",
    "chip-breaking": "Chip breaking",
    "tapping": "Tapping",
    "left-tapping": "Tapping",
    "right-tapping": "Tapping",
    "boring": "Boring",
    "reaming": "Reaming"
};

function onCycle() {
    var name = cncCycleNames[cycleType] !== undefined ? cncCycleNames[cycleType] : "Drilling";
    var longhand = false;
    var fields = cncCalc.setting("MillDrillingFields");
    if (fields && fields.length !== undefined) {
        for (var i = 0; i < fields.length; i++) {
            if (fields[i] && fields[i].name === name) {
                longhand = !!fields[i].isLonghand;
                break;
            }
        }
    }
    var k = cncScale;
    var dwell = cycle.dwell > 0 ? cycle.dwell : null;
    cncCall("onDrillingHeader", [{
        name: name, isLonghand: longhand,
        retractPlane: cycle.clearance * k, referencePlane: cycle.stock * k,
        safeDistanceIsAbsolute: true, safeDistance: cycle.retract * k,
        endDepthIsAbsolute: true, endDepth: cycle.bottom * k,
        firstDepth: cycle.incrementalDepth < cycle.depth ? cycle.incrementalDepth * k : 0,
        firstFeedrateFactor: 1, degressionType: 0, degression: 0, peckingRetract: 0, minimumDepth: 0,
        usePlungingFeedrate: true, plungingFeedrate: cycle.feedrate * k, useRetractFeedrate: false, retractFeedrate: cycle.feedrate * k,
        useTopDwelling: false, topDwelling: 0,
        useBottomDwelling: dwell !== null, bottomDwelling: dwell !== null ? dwell : 0,
        pitch: cycle.pitch !== undefined ? cycle.pitch * k : 0,
        useTappingSpeed: false, tappingSpeed: cncSpindle, useRetractSpeed: false, retractSpeed: cncSpindle
    }]);
}

// Each hole: onDrillingPoint, or the hole as moves when the post has none.
function onCyclePoint(x, y, z) {
    if (typeof cncCalc.entry("onDrillingPoint") == "function") {
        cncPosition = [x * cncScale, y * cncScale, 0];
        cncCall("onDrillingPoint", [x * cncScale, y * cncScale]);
    } else {
        expandCyclePoint(x, y, z);
    }
}

function onCycleEnd() {
    cncCall("onDrillingFooter", []);
}

function onClose() {
    if (!cncStarted) {
        cncStarted = true;
        cncCall("onOpen", [false]);
        cncToolChange();
    }
    cncCall("onClose", []);
}
