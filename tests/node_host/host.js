// A CNC-Calc host for Node.js: runs a CIMCO post over a toolpath of
// native events (JSON Lines) the way docs/cimco.md says postc does, as a
// second engine to check postc against. It shares no code with postc.
//
// Call order: the post's top level, onInit(); at the first toolpath
// onOpen(false) and onToolChange(...) for the first tool; later toolpaths
// with another tool onToolChange(...). Output variables keep what they
// printed for the whole program (seed 002: a variable without force "will
// only be written if it has changed since the last time it was used");
// only their reset() makes them forget. Moves call onLinear and
// onCircular (split under useRadius so that no part turns 180 degrees or
// more); cutter compensation onCompensation(0|1|2); milling drill cycles
// onDrillingHeader(drillHeader), onDrillingPoint(x, y), onDrillingFooter();
// turning drill cycles onDrilling(drillHeader); dwells onDwell(seconds);
// comments onComment(text); toolpath ends onToolpathEnd(); the end
// onClose(). Each returned text is cut into lines at "\n" (a "\r" before
// it dropped), and every line that is not empty is written with the
// post's linebreak.
"use strict";

var vm = require("vm");
var fmt = require("./format.js");

var RAPID = 0, CUTTING = 1, PLUNGE = 2;

// `context`, when given, is a fresh `vm` context the post runs in (so that
// several posts can run one after another in one process, each with its
// own globals); without it the post's globals are this process's.
function Host(source, fileName, context) {
    var host = this;
    this.out = [];
    this.bytes = 0;
    this.keepOutput = true;
    var createVariable = fmt.createVariable;
    // A format error of a post before this one is not this post's.
    fmt.takeStop();
    var sandbox = {
        MOVEMENT_RAPID: RAPID, MOVEMENT_CUTTING: CUTTING, MOVEMENT_FEED: CUTTING, MOVEMENT_PLUNGE: PLUNGE, MOVEMENT_RETRACT: 3,
        COMPENSATION_OFF: 0, COMPENSATION_LEFT: 1, COMPENSATION_RIGHT: 2,
        POST_TYPE_MILL: 0, POST_TYPE_TURN: 1,
        DEGRESSION_NONE: 0, DEGRESSION_VALUE: 1, DEGRESSION_FACTOR: 2,
        createFormat: function (props) {
            return fmt.createFormat(props, host.setting("decimalMark"));
        },
        createVariable: createVariable,
        getFeedrate: function (movement) {
            if (movement == RAPID) {
                return "";
            }
            return (host.feedPerRev ? host.feedRevVariable : host.feedVariable).format(host.feed);
        },
    };
    // By default the post runs as an ordinary script in this context, so
    // that its globals are plain globals (a vm sandbox would slow every
    // access).
    var ctx = context || globalThis;
    this.ctx = ctx;
    Object.keys(sandbox).forEach(function (k) {
        ctx[k] = sandbox[k];
    });
    if (context) {
        vm.runInContext(source, context, { filename: fileName });
    } else {
        vm.runInThisContext(source, { filename: fileName });
    }
    this.stopIfFormatFailed();
    // getFeedrate: one decimal per minute, four per revolution (0.15
    // mm/rev prints F0.15).
    this.feedVariable = createVariable({ prefix: "F", force: true }, fmt.createFormat({ decimals: 1 }, this.setting("decimalMark")));
    this.feedRevVariable = createVariable({ prefix: "F", force: true }, fmt.createFormat({ decimals: 4 }, this.setting("decimalMark")));
    this.feedPerRev = false;
    var info = this.ctx.PostInfo;
    var onLinear = this.ctx.onLinear;
    if (info && info.type !== undefined) {
        this.lathe = info.type === 1;
    } else {
        this.lathe = (typeof onLinear === "function" && onLinear.length === 3)
            || (this.ctx.TurnDrillingFields !== undefined && this.ctx.MillDrillingFields === undefined);
    }
    var lb = this.setting("linebreak");
    this.linebreak = typeof lb === "string" && lb !== "" ? lb : "\n";
    this.started = false;
    this.finished = false;
    this.toolChanged = false;
    this.lastTool = null;
    this.tool = { number: 0, name: "", diameter: 0, spindle_speed: 0, cut_feed: 0, plunge_feed: 0 };
    this.spindle = 0;
    this.feed = 0;
    this.pos = [0, 0, 0];
    this.drill = null;
    this.comp = 0;
    if (typeof this.ctx.onInit === "function") {
        this.ctx.onInit();
        this.stopIfFormatFailed();
    }
}

// A format was given a value that is not a finite number and the post's
// `catch` took the error: the post stops there all the same, as it stops
// in postc (RT032 is not catchable).
Host.prototype.stopIfFormatFailed = function () {
    var e = fmt.takeStop();
    if (e !== null) {
        throw e;
    }
};

// A setting in either form: `name` or `globals.name`.
Host.prototype.setting = function (name) {
    var ctx = this.ctx;
    if (ctx[name] !== undefined) {
        return ctx[name];
    }
    if (ctx.globals && typeof ctx.globals === "object") {
        return ctx.globals[name];
    }
    return undefined;
};

Host.prototype.has = function (name) {
    return typeof this.ctx[name] === "function";
};

// Writes what a function returned.
Host.prototype.write = function (value) {
    if (value === undefined || value === null) {
        return;
    }
    var text = String(value);
    var end = text.indexOf("\n");
    // The usual case: one line with its line ending.
    if (end === text.length - 1 && end > 0) {
        var line = text.charCodeAt(end - 1) === 13 ? text.substring(0, end - 1) : text.substring(0, end);
        if (line !== "") {
            this.emit(line);
        }
        return;
    }
    var lines = text.split("\n");
    for (var i = 0; i < lines.length; i++) {
        var l = lines[i];
        if (l.charAt(l.length - 1) === "\r") {
            l = l.substring(0, l.length - 1);
        }
        if (l !== "") {
            this.emit(l);
        }
    }
};

Host.prototype.emit = function (line) {
    this.bytes += line.length + this.linebreak.length;
    if (this.keepOutput) {
        this.out.push(line, this.linebreak);
    }
};

Host.prototype.call = function (name, args) {
    if (this.has(name)) {
        var value = this.ctx[name].apply(null, args);
        this.stopIfFormatFailed();
        this.write(value);
    }
};

Host.prototype.toolChange = function () {
    var t = this.tool;
    this.call("onToolChange", [t.number, t.name, t.diameter, this.spindle]);
};

Host.prototype.beginToolpath = function () {
    if (!this.started) {
        this.started = true;
        this.call("onOpen", [false]);
        this.toolChange();
    } else if (this.toolChanged) {
        this.toolChange();
    }
    this.toolChanged = false;
    this.lastTool = this.tool.number;
};

Host.prototype.ensureStarted = function () {
    if (!this.started || this.toolChanged) {
        this.beginToolpath();
    }
};

Host.prototype.linear = function (p, movement) {
    if (this.lathe) {
        this.call("onLinear", [p[0], p[2], movement]);
    } else {
        this.call("onLinear", [p[0], p[1], p[2], movement]);
    }
};

Host.prototype.rapid = function (m) {
    this.pos = [m.x, m.y, m.z];
    this.linear(this.pos, RAPID);
};

Host.prototype.feedMove = function (m) {
    var from = this.pos;
    var intent = m.intent || "Cut";
    var sameXY = from[0] === m.x && from[1] === m.y;
    if (intent === "Cut" && sameXY && !this.lathe) {
        if (m.z < from[2]) {
            intent = "Plunge";
        } else if (m.z > from[2]) {
            intent = "Retract";
        }
    }
    var slow = intent === "Plunge" || intent === "Retract";
    this.feed = m.feed != null ? m.feed : slow ? this.tool.plunge_feed : this.tool.cut_feed;
    this.pos = [m.x, m.y, m.z];
    this.linear(this.pos, intent === "Plunge" ? PLUNGE : CUTTING);
};

// The plane coordinates (u, v) and the normal w of a point.
function inPlane(p, lathe) {
    return lathe ? { u: p[2], v: p[0], w: p[1] } : { u: p[0], v: p[1], w: p[2] };
}

Host.prototype.arc = function (a) {
    var plane = a.plane || "Xy";
    if (this.lathe ? plane !== "Zx" : plane !== "Xy") {
        throw new Error("the referee host does not linearize arcs outside the machine's plane");
    }
    var start = inPlane(this.pos, this.lathe);
    var end = inPlane([a.x, a.y, a.z], this.lathe);
    var centre = inPlane([a.cx, a.cy, a.cz || 0], this.lathe);
    var r = Math.hypot(start.u - centre.u, start.v - centre.v);
    var a0 = Math.atan2(start.v - centre.v, start.u - centre.u);
    var a1 = Math.atan2(end.v - centre.v, end.u - centre.u);
    var closed = Math.hypot(end.u - start.u, end.v - start.v) <= 1e-9 * Math.max(r, 1);
    var TAU = 2 * Math.PI;
    var cw = a.dir === "Cw";
    var turn = closed ? TAU : ((cw ? a0 - a1 : a1 - a0) % TAU + TAU) % TAU;
    if (turn <= 1e-12) {
        turn = TAU;
    }
    var sweep = cw ? -turn : turn;
    var intent = a.intent || "Cut";
    var slow = intent === "Plunge" || intent === "Retract";
    this.feed = a.feed != null ? a.feed : slow ? this.tool.plunge_feed : this.tool.cut_feed;
    this.pos = [a.x, a.y, a.z];
    var useRadius = !!this.setting("useRadius");
    var parts = useRadius ? Math.floor(Math.abs(sweep) / Math.PI + 1e-9) + 1 : 1;
    for (var i = 1; i <= parts; i++) {
        var p;
        if (i === parts) {
            p = end;
        } else {
            var t = i / parts;
            var ang = a0 + sweep * t;
            p = { u: centre.u + r * Math.cos(ang), v: centre.v + r * Math.sin(ang), w: start.w + (end.w - start.w) * t };
        }
        if (this.lathe) {
            this.call("onCircular", [centre.v, centre.u, p.v, p.u, cw, CUTTING]);
        } else {
            this.call("onCircular", [centre.u, centre.v, start.w, p.u, p.v, p.w, cw, CUTTING]);
        }
    }
};

var KIND_NAMES = { Drill: "Drilling", Deep: "Peck drilling", ChipBreak: "Chip breaking", Tap: "Tapping", Bore: "Boring", Ream: "Reaming" };

Host.prototype.drillName = function (list) {
    var c = this.drill;
    var name = c.name ? c.name : KIND_NAMES[c.kind || "Drill"];
    var longhand = false;
    var fields = this.ctx[list];
    if (fields && fields.length !== undefined) {
        for (var i = 0; i < fields.length; i++) {
            if (fields[i] && fields[i].name === name) {
                longhand = !!fields[i].isLonghand;
                break;
            }
        }
    }
    return { name: name, longhand: longhand };
};

Host.prototype.millHeader = function () {
    var c = this.drill;
    var n = this.drillName("MillDrillingFields");
    var feed = c.feed != null ? c.feed : this.tool.plunge_feed;
    var dwell = c.dwell != null && c.dwell > 0 ? c.dwell : null;
    return {
        name: n.name, isLonghand: n.longhand,
        // referencePlane is the top of the holes (seed 002: safe distance
        // and end depth are relative to it); safeDistance the R plane.
        retractPlane: c.retract_plane || 0, referencePlane: c.surface != null ? c.surface : c.reference_plane || 0,
        safeDistanceIsAbsolute: true, safeDistance: c.reference_plane || 0,
        endDepthIsAbsolute: true, endDepth: c.depth || 0,
        firstDepth: c.peck != null && c.peck > 0 ? c.peck : 0,
        firstFeedrateFactor: 1, degressionType: 0, degression: 0, peckingRetract: 0, minimumDepth: 0,
        usePlungingFeedrate: true, plungingFeedrate: feed, useRetractFeedrate: false, retractFeedrate: feed,
        useTopDwelling: false, topDwelling: 0,
        useBottomDwelling: dwell !== null, bottomDwelling: dwell !== null ? dwell : 0,
        pitch: c.pitch != null ? c.pitch : 0,
        useTappingSpeed: false, tappingSpeed: this.spindle, useRetractSpeed: false, retractSpeed: this.spindle,
    };
};

Host.prototype.turnHeader = function (point) {
    var c = this.drill;
    var n = this.drillName("TurnDrillingFields");
    var feed = c.feed != null ? c.feed : this.tool.plunge_feed;
    var kind = c.kind || "Drill";
    var pecking = (kind === "Deep" || kind === "ChipBreak") && c.peck != null && c.peck > 0;
    var peck = pecking ? c.peck : 0;
    var dwell = c.dwell != null && c.dwell > 0 ? c.dwell : null;
    var pitch = c.pitch != null ? c.pitch : 0;
    return {
        name: n.name, Name: n.name, isLonghand: n.longhand,
        startDepth: point.z || 0, endDepth: c.depth || 0,
        safeDistance: c.reference_plane || 0, retractDistance: c.retract_plane || 0,
        usePlungingFeedrate: true, plungingFeedrate: feed, useRetractFeedrate: false, retractFeedrate: feed,
        pitch: pitch, Pitch: pitch, usePecking: pecking, UsePecking: pecking,
        firstPeckDepth: peck, subsequentPecksDepths: peck, subsequentPeckDepths: peck,
        peckClearance: 0, peckRetract: 0, PeckRetract: 0,
        useUpperDwell: false, upperDwell: 0,
        useLowerDwell: dwell !== null, lowerDwell: dwell !== null ? dwell : 0,
        useDrillTipCompensation: false, drillDiameter: this.tool.diameter, drillTipAngle: 118,
    };
};

Host.prototype.event = function (e) {
    var kind = typeof e === "string" ? e : Object.keys(e)[0];
    var d = typeof e === "string" ? null : e[kind];
    switch (kind) {
        case "Job":
            if (d.home) {
                this.pos = [d.home.x, d.home.y, d.home.z];
            }
            break;
        case "Tool":
            this.toolChanged = this.lastTool !== d.number;
            this.tool = {
                number: d.number || 0, name: d.name || "", diameter: d.diameter || 0,
                spindle_speed: d.spindle_speed || 0, cut_feed: d.cut_feed || 0, plunge_feed: d.plunge_feed || 0,
            };
            this.spindle = this.tool.spindle_speed;
            this.feed = this.tool.cut_feed;
            break;
        case "ToolpathStart":
            this.feedPerRev = !!d.feed_per_rev;
            this.beginToolpath();
            break;
        case "ToolpathEnd":
            this.ensureStarted();
            this.call("onToolpathEnd", []);
            break;
        case "Rapid":
            this.ensureStarted();
            this.rapid(d);
            break;
        case "Feed":
            this.ensureStarted();
            this.feedMove(d);
            break;
        case "Arc":
            this.ensureStarted();
            this.arc(d);
            break;
        case "Dwell":
            this.ensureStarted();
            this.call("onDwell", [d.revolutions && this.spindle > 0 ? d.seconds * 60 / this.spindle : d.seconds]);
            break;
        case "SpindleOn":
            if (d.speed != null) {
                this.spindle = d.speed;
            }
            break;
        case "CutterComp":
            this.comp = d.side === "Left" ? 1 : d.side === "Right" ? 2 : 0;
            if (this.started) {
                this.call("onCompensation", [this.comp]);
            }
            break;
        case "DrillCycle":
            this.ensureStarted();
            this.drill = d;
            if (!this.lathe) {
                this.call("onDrillingHeader", [this.millHeader()]);
            }
            break;
        case "DrillPoint":
            this.ensureStarted();
            if (this.lathe) {
                this.pos = [d.x, d.y, d.z || 0];
                this.call("onDrilling", [this.turnHeader(d)]);
            } else if (this.has("onDrillingPoint")) {
                this.pos = [d.x, d.y, d.z || 0];
                this.call("onDrillingPoint", [d.x, d.y]);
            } else {
                throw new Error("the referee host does not expand holes into moves");
            }
            break;
        case "DrillEnd":
            if (this.started && !this.lathe) {
                this.call("onDrillingFooter", []);
            }
            this.drill = null;
            break;
        case "Comment":
            if (this.started) {
                this.call("onComment", [d.text]);
            }
            break;
        case "Insert":
            this.ensureStarted();
            this.write(d.text);
            break;
        case "End":
            this.finish();
            break;
        default:
            // Spindle off, coolant, jet and pass-through words: CNC-Calc
            // posts have no function for them.
            break;
    }
};

Host.prototype.finish = function () {
    if (this.finished) {
        return;
    }
    this.ensureStarted();
    this.call("onClose", []);
    this.finished = true;
};

module.exports = { Host: Host };
