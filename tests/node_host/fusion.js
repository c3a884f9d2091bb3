// A referee for Fusion posts: Node.js runs postc's Fusion host API
// (frontends/cimco/src/fusion/host.js, JavaScript) and the post in one
// context, and turns a toolpath of native events (JSON Lines) into the
// host's engine calls (`__fusion_*`) in the order docs/fusion.md and the
// runtime's section dispatch give them. The host API is shared with postc
// on purpose (it is JavaScript); what this checks is postc's JavaScript
// engine against V8 on real posts, and the event order against a second
// reading of the documentation.
//
//   node fusion.js POST.cps TOOLPATH.jsonl [--property NAME=VALUE]...
//
// `--property` sets a post property, as Fusion's post dialog and Autodesk's
// `post --property` do (postc: `--set property.NAME=VALUE`).
"use strict";

var fs = require("fs");
var path = require("path");
var vm = require("vm");

var HOST = path.join(__dirname, "..", "..", "frontends", "cimco", "src", "fusion", "host.js");

// `__postc_formatNumber(spec, value)`: the text of `value` under a
// format's specifiers, `undefined` when the scaled value is not finite.
function formatNumber(spec, value) {
  var v = value * spec.scale + spec.offset;
  if (spec.cyclicLimit !== undefined && spec.cyclicLimit > 0) {
    v = v % spec.cyclicLimit;
    if (v < 0 && spec.cyclicSign >= 0) { v += spec.cyclicLimit; }
  }
  if (!(v - v == 0)) {
    return undefined;
  }
  var factor = Math.pow(10, spec.decimals);
  var units = Math.floor(Math.abs(v) * factor + 0.5);
  var negative = v < 0 && units != 0;
  var digits = String(units);
  while (digits.length <= spec.decimals) { digits = "0" + digits; }
  var whole = digits.substring(0, digits.length - spec.decimals);
  var fraction = digits.substring(digits.length - spec.decimals);
  if (spec.trim) {
    var n = fraction.length;
    while (n > 0 && fraction.charAt(n - 1) == "0") { --n; }
    fraction = fraction.substring(0, n);
  }
  if (spec.trimLeadZero && whole == "0" && fraction.length > 0) { whole = ""; }
  var text;
  if (fraction.length > 0) {
    text = whole + spec.decimalSymbol + fraction;
  } else {
    text = spec.forceDecimal ? whole + spec.decimalSymbol : whole;
  }
  if (spec.zeropad && spec.width > 0) {
    var sign = (negative || spec.forceSign) ? 1 : 0;
    var wholeLength = whole.length;
    var pad = spec.width - sign - text.length;
    if (fraction.length > 0 || spec.forceDecimal) {
      pad = spec.width - sign - wholeLength;
    }
    while (pad > 0) { text = "0" + text; --pad; }
  }
  if (negative) {
    text = "-" + text;
  } else if (spec.forceSign) {
    text = "+" + text;
  }
  if (!spec.zeropad && spec.width > 0) {
    while (text.length < spec.width) { text = " " + text; }
  }
  return spec.prefix + text + spec.suffix;
}

// `__postc_words(list, separator, start)`: the words of a block (texts
// and arrays of texts, an `arguments` object too, the empty ones left
// out) from `start`, joined by the separator.
function words(list, separator, start) {
  var into = [];
  function gather(items, from) {
    for (var i = from; i < items.length; ++i) {
      var w = items[i];
      if (w === undefined || w === null) { continue; }
      if (typeof w == "object") {
        gather(w, 0);
      } else {
        var t = String(w);
        if (t != "") { into.push(t); }
      }
    }
  }
  gather(list, start);
  return into.join(separator);
}

function Referee(postSource, postName, mm) {
    var out = [];
    var context = vm.createContext({});
    // The job's unit, known before the post's top level runs.
    context.__postc_jobUnitIsMm = function () { return mm; };
    // A line and the host's line ending (`EOL`, which `setEOL` changes).
    context.__postc_writeln = function (text, eol) {
        out.push(String(text) + String(eol));
    };
    // The host's text primitives, which postc runs natively
    // (runtime/src/interp/host_text.rs), in plain JavaScript.
    context.__postc_formatNumber = formatNumber;
    context.__postc_words = words;
    // postc's native path of an output's `format`: here the host's
    // JavaScript after it always runs.
    context.__postc_formatOutput = function () { return undefined; };
    // A setting the post cannot take stops the run (postc: IO007).
    context.__postc_settingError = function (message) { throw new Error(message); };
    context.__postc_property = function (properties, name, otherwise) {
        var p = properties[name];
        if (p === undefined) { return otherwise; }
        if (p !== null && typeof p == "object" && p.value !== undefined) { return p.value; }
        return p;
    };
    vm.runInContext(fs.readFileSync(HOST, "utf8"), context, { filename: HOST });
    // The post's own file, as postc sets it when it reads the post.
    context.__configurationPath = String(postName);
    // `include("name")`: the file beside the post, run where the call is
    // (postc splices it in at the top level; docs/fusion.md, choice 30).
    var folder = path.dirname(String(postName));
    context.include = function (name) {
        var file = path.join(folder, String(name));
        vm.runInContext(fs.readFileSync(file, "utf8"), context, { filename: file });
    };
    vm.runInContext(postSource, context, { filename: postName });
    // A static method the host writes as `__Class_method` (postc calls it
    // for `Class.method(...)`).
    vm.runInContext(
        "Object.getOwnPropertyNames(this).forEach(function (n) {" +
            "  var m = /^__([A-Za-z]+)_([A-Za-z0-9]+)$/.exec(n);" +
            "  if (m && this[m[1]] !== undefined) { this[m[1]][m[2]] = this[n]; }" +
            "}, this);",
        context
    );
    this.ctx = context;
    this.out = out;
    this.started = false;
    this.finished = false;
    this.spindleOn = false;
    this.pos = [0, 0, 0];
    this.job = {};
    this.tool = null;
    this.toolChanged = false;
    this.lastTool = null;
    this.spindle = 0;
    this.css = false;
    this.ccw = false;
    this.maxRpm = null;
    this.feedPerRev = false;
    this.coolant = 0;
    this.held = [];
}

// The coolant kinds as the host numbers them (COOLANT_OFF ... COOLANT_AIR).
var COOLANT_KINDS = { Off: 0, Flood: 1, Mist: 2, Through: 3, Air: 4 };
var COMP_SIDES = { Off: 0, Left: 1, Right: 2 };

// Each engine function also gets where the event is in the toolpath and
// whether a move follows it (FeedRate records not counted), as postc's
// runtime passes them; a turning job's arguments come after those
// (docs/fusion.md, "Turning").
// The program's bytes: UTF-8, or Windows-1252 once the post has called
// `setCodePage("ansi")` (Fusion's code page; a character Windows-1252 does
// not have is "?").
var CP1252 = {0x20AC: 0x80, 0x81: 0x81, 0x201A: 0x82, 0x0192: 0x83, 0x201E: 0x84, 0x2026: 0x85, 0x2020: 0x86,
    0x2021: 0x87, 0x02C6: 0x88, 0x2030: 0x89, 0x0160: 0x8A, 0x2039: 0x8B, 0x0152: 0x8C, 0x8D: 0x8D, 0x017D: 0x8E,
    0x8F: 0x8F, 0x90: 0x90, 0x2018: 0x91, 0x2019: 0x92, 0x201C: 0x93, 0x201D: 0x94, 0x2022: 0x95, 0x2013: 0x96,
    0x2014: 0x97, 0x02DC: 0x98, 0x2122: 0x99, 0x0161: 0x9A, 0x203A: 0x9B, 0x0153: 0x9C, 0x9D: 0x9D, 0x017E: 0x9E,
    0x0178: 0x9F};
Referee.prototype.bytes = function () {
    var text = this.out.join("");
    if (this.ctx.__codePage !== "ansi") {
        return Buffer.from(text, "utf8");
    }
    var bytes = [];
    for (var ch of text) {
        var c = ch.codePointAt(0);
        bytes.push(c < 0x80 || (c >= 0xA0 && c <= 0xFF) ? c : (CP1252[c] !== undefined ? CP1252[c] : 0x3F));
    }
    return Buffer.from(bytes);
};

Referee.prototype.call = function (name, args, after) {
    this.ctx[name].apply(null, args.concat([this.record, this.nextMotion]).concat(after || []));
};

// The spindle's constant surface speed and its highest rpm (NaN when it
// runs at a fixed rpm or gives no limit).
Referee.prototype.cssArgs = function () {
    return [this.css, this.css && this.maxRpm != null ? this.maxRpm : NaN];
};

// The spindle arguments after its speed: its constant surface speed and
// highest rpm, and whether it turns counter-clockwise.
Referee.prototype.spindleArgs = function () {
    return this.cssArgs().concat([this.ccw]);
};

// A toolpath's turning arguments: a turning tool, feeds per revolution,
// and the spindle's surface speed.
Referee.prototype.turningArgs = function () {
    return [!!this.tool.turning, !!this.feedPerRev].concat(this.cssArgs());
};

Referee.prototype.spindleTool = function () {
    return !this.tool.jet && this.spindle > 0;
};

Referee.prototype.toolpathArgs = function () {
    var t = this.tool;
    // The tool's feeds (0 is none, as the toolpath format writes a value it
    // does not know) and the job's safe Z (its home Z when it has none).
    var given = function (v) { return v ? v : NaN; };
    var home = this.job.home;
    var safeZ = this.job.safe_z != null ? this.job.safe_z : home ? home.z : NaN;
    return [t.number, t.diameter, t.name, this.toolpathName, !!t.jet, this.spindle, t.notes, this.coolant, t.lengthOffset,
        given(t.cut_feed), given(t.plunge_feed), safeZ];
};

Referee.prototype.beginToolpath = function () {
    if (!this.started) {
        this.started = true;
        var j = this.job;
        var file = j.file || {};
        this.call("__fusion_toolpath", this.toolpathArgs(), this.turningArgs().concat([this.toolpathNotes, this.ccw]));
        var m = j.material;
        var stock = m ? [m.min.x, m.min.y, m.min.z, m.max.x, m.max.y, m.max.z] : [NaN, NaN, NaN, NaN, NaN, NaN];
        // The CAM product, Fusion's `generated-by` (host.js `__fusion_job`).
        this.call("__fusion_job", [typeof j.product === "string" ? j.product : "postc"]);
        this.call(
            "__fusion_open",
            [(j.units || "Mm") === "Mm", file.name || "", j.notes || "", j.date || NOW[0], j.time || NOW[1], file.dir || ""]
                .concat(stock)
                .concat([JSON.stringify(this.outline || []), JSON.stringify(this.properties || {})])
        );
        this.spindleOn = this.spindleTool();
        if (this.spindleOn) {
            this.call("__fusion_spindle", [this.spindle], this.spindleArgs());
        }
        for (var h = 0; h < this.held.length; h++) {
            this.call("__fusion_insert", [this.held[h]]);
        }
        this.held = [];
    } else {
        if (this.toolChanged) {
            this.call("__fusion_tool_change", []);
            this.spindleOn = this.spindleTool();
            if (this.spindleOn) {
                this.call("__fusion_spindle", [this.spindle], this.spindleArgs());
            }
        }
        this.call("__fusion_toolpath", this.toolpathArgs(), this.turningArgs().concat([this.toolpathNotes, this.ccw]));
    }
    this.toolChanged = false;
    this.lastTool = this.tool.number;
};

Referee.prototype.ensureStarted = function () {
    if (!this.started) {
        this.beginToolpath();
    }
};

Referee.prototype.feedOf = function (m, slow) {
    return m.feed != null ? m.feed : slow ? this.tool.plunge_feed : this.tool.cut_feed;
};

Referee.prototype.feedMove = function (m) {
    var from = this.pos;
    var intent = m.intent || "Cut";
    // A move straight along Z is a milling tool's plunge or retract; a
    // turning tool's Z runs along the spindle, where it cuts.
    if (intent === "Cut" && !this.tool.turning && from[0] === m.x && from[1] === m.y) {
        if (m.z < from[2]) {
            intent = "Plunge";
        } else if (m.z > from[2]) {
            intent = "Retract";
        }
    }
    var slow = intent === "Plunge" || intent === "Retract";
    this.pos = [m.x, m.y, m.z];
    this.call("__fusion_linear", [m.x, m.y, m.z, this.feedOf(m, slow), intent === "Plunge"]);
};

// The date and time of a job that gives none: now, as the caller's clock
// says (docs/vectric.md: the long date VCarve writes and HH:MM, in UTC).
// The tests post with no clock, which is the Unix epoch.
var NOW = (function (seconds) {
    var d = new Date(seconds * 1000);
    var days = ["Sunday", "Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday"];
    var months = ["January", "February", "March", "April", "May", "June", "July", "August", "September",
        "October", "November", "December"];
    var two = function (n) { return (n < 10 ? "0" : "") + n; };
    return [days[d.getUTCDay()] + ", " + months[d.getUTCMonth()] + " " + d.getUTCDate() + ", " + d.getUTCFullYear(),
        two(d.getUTCHours()) + ":" + two(d.getUTCMinutes())];
})(0);

// An arc's plane: its number in Fusion's API (PLANE_XY 0, PLANE_ZX 1,
// PLANE_YZ 2) and its axes (u, v, normal w) as G17, G18 and G19 take
// them, right-handed: XY (x, y, z), ZX (z, x, y), YZ (y, z, x).
var PLANES = {Xy: [0, [0, 1, 2]], Zx: [1, [2, 0, 1]], Yz: [2, [1, 2, 0]]};

Referee.prototype.arc = function (a) {
    var plane = PLANES[a.plane || "Xy"];
    if (!plane) {
        throw new Error("the referee does not know the arc plane " + a.plane);
    }
    var u = plane[1][0], v = plane[1][1], w = plane[1][2];
    var s = this.pos;
    var e = [a.x, a.y, a.z];
    // The centre lies at the start along the plane's normal (a helix's axis).
    var c = [a.cx, a.cy, a.cz];
    c[w] = s[w];
    var r = Math.hypot(s[u] - c[u], s[v] - c[v]);
    var a0 = Math.atan2(s[v] - c[v], s[u] - c[u]);
    var a1 = Math.atan2(e[v] - c[v], e[u] - c[u]);
    var closed = Math.hypot(e[u] - s[u], e[v] - s[v]) <= 1e-9 * Math.max(r, 1);
    var TAU = 2 * Math.PI;
    var cw = a.dir === "Cw";
    var turn = closed ? TAU : (((cw ? a0 - a1 : a1 - a0) % TAU) + TAU) % TAU;
    if (turn <= 1e-12) {
        turn = TAU;
    }
    var intent = a.intent || "Cut";
    var slow = intent === "Plunge" || intent === "Retract";
    this.pos = e;
    // A helix marked as plunging is Fusion's helical ramp.
    var ramp = intent === "Plunge" && Math.abs(e[w] - s[w]) > 1e-9;
    this.call("__fusion_circular", [cw, c[0], c[1], c[2], a.x, a.y, a.z, this.feedOf(a, slow), cw ? -turn : turn, r, plane[0]], [ramp]);
};

Referee.prototype.event = function (e) {
    var kind = typeof e === "string" ? e : Object.keys(e)[0];
    var d = typeof e === "string" ? null : e[kind];
    switch (kind) {
        case "Job":
            this.job = d;
            if (d.home) {
                this.pos = [d.home.x, d.home.y, d.home.z];
            }
            break;
        case "Tool":
            this.toolChanged = this.lastTool !== d.number;
            this.tool = {
                number: d.number || 0, name: d.name || "", diameter: d.diameter || 0, jet: !!d.jet,
                cut_feed: d.cut_feed || 0, plunge_feed: d.plunge_feed || 0, notes: d.notes || "",
                lengthOffset: d.length_offset != null ? d.length_offset : d.number || 0,
                turning: !!d.turning,
            };
            this.spindle = d.spindle_speed || 0;
            // A new tool's spindle runs at its rpm, clockwise, until a
            // SpindleOn says otherwise.
            this.css = false;
            this.ccw = false;
            this.maxRpm = null;
            break;
        case "ToolpathStart":
            this.toolpathName = d.name || "";
            this.toolpathNotes = d.notes || "";
            this.feedPerRev = !!d.feed_per_rev;
            this.beginToolpath();
            break;
        case "Rapid":
            this.ensureStarted();
            this.pos = [d.x, d.y, d.z];
            this.call("__fusion_rapid", [d.x, d.y, d.z]);
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
            this.call("__fusion_dwell", [d.revolutions && this.spindle > 0 ? d.seconds * 60 / this.spindle : d.seconds]);
            break;
        case "SpindleOn": {
            var speed = d.speed != null ? d.speed : this.spindle;
            var css = !!d.css;
            var ccw = !!d.ccw;
            // A direction of its own starts the spindle again: the Fusion
            // host reads it (postc's SPINDLE_CCW).
            var changed = speed !== this.spindle || css !== this.css || ccw !== this.ccw;
            this.spindle = speed;
            this.css = css;
            this.ccw = ccw;
            this.maxRpm = css && d.max_rpm != null ? d.max_rpm : null;
            if (this.started && (!this.spindleOn || changed) && !this.tool.jet) {
                this.spindleOn = true;
                this.call("__fusion_spindle", [speed], this.spindleArgs());
            }
            break;
        }
        case "SpindleOff":
            this.spindleOn = false;
            break;
        case "JetOn":
            this.ensureStarted();
            this.call("__fusion_power", [true]);
            break;
        case "JetOff":
            this.ensureStarted();
            this.call("__fusion_power", [false]);
            break;
        case "Coolant": {
            var c = typeof d === "string" ? d : d.coolant;
            this.coolant = COOLANT_KINDS[c] || 0;
            if (this.started) {
                this.call("__fusion_coolant", [this.coolant]);
            }
            break;
        }
        case "CutterComp":
            if (this.started) {
                this.call("__fusion_compensation", [COMP_SIDES[d.side || "Off"]]);
            }
            break;
        case "Comment":
            if (this.started) {
                this.call("__fusion_comment", [d.text]);
            }
            break;
        case "Insert":
            // Text inserted before the program starts waits for its head.
            if (this.started) {
                this.call("__fusion_insert", [d.text]);
            } else {
                this.held.push(d.text);
            }
            break;
        case "DrillCycle": {
            // The cycle's data as docs/fusion.md gives it (`__fusion_cycle`):
            // kind number, clearance, R plane, top (the R plane when the
            // cycle names none), bottom, feed (the cycle's, else the tool's
            // plunge feed, else its cut feed), peck, dwell (0 when none),
            // pitch.
            this.ensureStarted();
            var kinds = { Drill: 0, Deep: 1, ChipBreak: 2, Tap: 3, Bore: 4, Ream: 5 };
            var toolFeed = this.tool.plunge_feed > 0 ? this.tool.plunge_feed : this.tool.cut_feed > 0 ? this.tool.cut_feed : NaN;
            var feed = d.feed > 0 ? d.feed : toolFeed;
            this.call("__fusion_cycle", [
                kinds[d.kind || "Drill"], d.retract_plane || 0, d.reference_plane || 0,
                d.surface != null ? d.surface : d.reference_plane || 0, d.depth || 0, feed,
                d.peck > 0 ? d.peck : NaN, d.dwell > 0 ? d.dwell : 0, d.pitch > 0 ? d.pitch : NaN,
            ]);
            break;
        }
        case "DrillPoint":
            this.ensureStarted();
            this.pos = [d.x, d.y, d.z || 0];
            this.call("__fusion_cycle_point", [d.x, d.y]);
            break;
        case "DrillEnd":
            if (this.started) {
                this.call("__fusion_cycle_end", []);
            }
            break;
        case "End":
            this.finish();
            break;
        default:
            break;
    }
};

Referee.prototype.finish = function () {
    if (this.finished) {
        return;
    }
    this.ensureStarted();
    this.call("__fusion_close", []);
    this.finished = true;
};

// The job's outline as docs/fusion.md describes `JOB_OUTLINE`: one entry
// per section (a toolpath, or its part after a tool change, that moves),
// with its tool, where its first move goes (over the first hole at the
// clearance plane for a cycle), the Z it spans, and its cycles.
function outlineOf(events) {
    var KINDS = { Drill: 0, Deep: 1, ChipBreak: 2, Tap: 3, Bore: 4, Ream: 5 };
    var sections = [];
    var tool = {};
    var speed = 0;
    var toolpath = "";
    var toolpathNotes = "";
    var coolant = 0;
    var cycle = null;
    var open = null;
    var fresh = true;
    function close() {
        if (open) {
            sections.push(open);
            open = null;
        }
    }
    events.forEach(function (e) {
        var kind = typeof e === "string" ? e : Object.keys(e)[0];
        var d = typeof e === "string" ? null : e[kind];
        var reached = null;
        switch (kind) {
            case "Tool":
                if ((d.number || 0) !== tool.number) {
                    close();
                    fresh = true;
                }
                tool = { number: d.number || 0, name: d.name || "", notes: d.notes || "", diameter: d.diameter || 0,
                    jet: !!d.jet, turning: !!d.turning,
                    lengthOffset: d.length_offset != null ? d.length_offset : d.number || 0 };
                speed = d.spindle_speed || 0;
                break;
            case "ToolpathStart":
                close();
                fresh = true;
                toolpath = d.name || "";
                toolpathNotes = d.notes || "";
                break;
            case "SpindleOn":
                // A constant surface speed is no rpm of the tool's.
                if (fresh && d.speed != null && !d.css) {
                    speed = d.speed;
                }
                break;
            case "Coolant": {
                var c = typeof d === "string" ? d : d.coolant;
                coolant = COOLANT_KINDS[c] || 0;
                break;
            }
            case "Rapid":
            case "Feed":
            case "Arc":
                reached = [d.x, d.y, d.z, d.z, d.z];
                break;
            case "DrillCycle":
                cycle = d;
                if (open) {
                    open.cycles += 1;
                }
                break;
            case "DrillPoint":
                if (cycle) {
                    var clear = cycle.retract_plane || 0, bottom = cycle.depth || 0;
                    reached = [d.x, d.y, clear, Math.min(bottom, clear), Math.max(bottom, clear)];
                }
                break;
            case "DrillEnd":
                cycle = null;
                break;
        }
        if (!reached) {
            return;
        }
        if (fresh) {
            fresh = false;
            var starts = kind === "DrillPoint";
            open = {
                tool: tool.number || 0, diameter: tool.diameter || 0, name: tool.name || "", notes: tool.notes || "",
                lengthOffset: tool.lengthOffset || 0, speed: speed, jet: !!tool.jet, turning: !!tool.turning,
                coolant: coolant,
                toolpath: toolpath, toolpathNotes: toolpathNotes, x: reached[0], y: reached[1], z: reached[2], zMin: reached[3], zMax: reached[4],
                cycle: starts ? KINDS[cycle.kind || "Drill"] : -1, dwell: starts && cycle.dwell > 0,
                cycles: starts ? 1 : 0, points: 0,
            };
        }
        open.zMin = Math.min(open.zMin, reached[3]);
        open.zMax = Math.max(open.zMax, reached[4]);
        if (kind === "DrillPoint") {
            open.points += 1;
        }
    });
    close();
    return sections;
}

function main(argv) {
    var post = argv[2];
    var toolpath = argv[3];
    if (!post || !toolpath) {
        process.stderr.write("usage: node fusion.js POST.cps TOOLPATH.jsonl [--property NAME=VALUE]...\n");
        return 2;
    }
    var properties = {};
    for (var a = 4; a < argv.length; a++) {
        var set = a + 1 < argv.length ? argv[a + 1] : "";
        var eq = set.indexOf("=");
        if (argv[a] !== "--property" || eq <= 0) {
            process.stderr.write("usage: node fusion.js POST.cps TOOLPATH.jsonl [--property NAME=VALUE]...\n");
            return 2;
        }
        properties[set.substring(0, eq)] = set.substring(eq + 1);
        a++;
    }
    var events = fs
        .readFileSync(toolpath, "utf8")
        .split("\n")
        .map(function (line) { return line.trim(); })
        .filter(function (line) { return line !== ""; })
        .map(function (line) { return JSON.parse(line); });
    var job = events.length > 0 && events[0].Job ? events[0].Job : {};
    var referee = new Referee(fs.readFileSync(post, "utf8"), post, (job.units || "Mm") === "Mm");
    referee.properties = properties;
    referee.outline = outlineOf(events);
    var posted = events.filter(function (e) { return Object.keys(e)[0] !== "FeedRate"; });
    var isMove = function (e) {
        var kind = typeof e === "string" ? e : Object.keys(e)[0];
        return kind === "Rapid" || kind === "Feed" || kind === "Arc";
    };
    referee.record = 0;
    referee.nextMotion = 0;
    try {
        for (var i = 0; i < posted.length; i++) {
            referee.record = i;
            referee.nextMotion = i + 1 < posted.length && isMove(posted[i + 1]) ? 1 : 0;
            referee.event(posted[i]);
        }
        referee.nextMotion = 0;
        referee.finish();
    } catch (e) {
        process.stdout.write(referee.bytes());
        process.stderr.write("error: " + (e && e.message ? e.message : String(e)) + "\n");
        return 1;
    }
    process.stdout.write(referee.bytes());
    return 0;
}

process.exitCode = main(process.argv);
