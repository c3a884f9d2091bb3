/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one writes through a writer object with methods: `out.block(text)`
 * numbers a block from `this.seq` and `this.step`, `out.comment(text)`
 * cleans a comment and calls `this.block`, `out.words(a, b)` joins two
 * words. Modal words are objects with methods too (`motion.word(1)`,
 * `feed.word(text)`, `reset()`), their memory in `this.last`; the axes are
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

var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);

// Machine settings.
var programNumber = 1001;
var programTitle = "Field style Fanuc mill";
var clearanceHeight = 50;
var peckClearance = 1;

// ------------------------------------------------------------------ Writers

// The program writer: blocks with their numbers, comments, words.
var out = {
    seq: sequenceNumberStart,
    step: sequenceNumberIncrement,
    numbered: showSequenceNumbers,
    block: function (text) {
        if (text == "") {
            return "";
        }
        if (this.numbered) {
            text = "N" + this.seq + " " + text;
            this.seq += this.step;
        }
        return text + linebreak;
    },
    comment: function (text) {
        var clean = "";
        var upper = String(text).toUpperCase();
        for (var i = 0; i < upper.length; i++) {
            var c = upper.charAt(i);
            if (c != "(" && c != ")") {
                clean += c;
            }
        }
        return this.block("(" + clean + ")");
    },
    words: function (text, word) {
        if (word == "") {
            return text;
        }
        if (text == "") {
            return word;
        }
        return text + variableDelimeter + word;
    },
    line: function (text) {
        return text + linebreak;
    }
};

// The motion code in force.
var motion = {
    last: null,
    word: function (code) {
        var text = "G" + code;
        if (text == this.last) {
            return "";
        }
        this.last = text;
        return text;
    },
    reset: function () {
        this.last = null;
    }
};

// The feed in force, as getFeedrate writes it.
var feed = {
    last: null,
    word: function (text) {
        if (text == "" || text == this.last) {
            return "";
        }
        this.last = text;
        return text;
    },
    value: function (f) {
        return this.word("F" + feedFormat.format(f));
    },
    reset: function () {
        this.last = null;
    }
};

// The machine: tool, compensation, drilling cycle.
var machine = {
    clipboard: false,
    toolCount: 0,
    tool: 0,
    compensation: "",
    drill: null,
    cycleActive: false,
    forgetPosition: function () {
        motion.reset();
        feed.reset();
        xOutput.reset();
        yOutput.reset();
        zOutput.reset();
    },
    takeCompensation: function () {
        var code = this.compensation;
        this.compensation = "";
        return code;
    }
};

// -------------------------------------------------------------- Framework
function onInit() {
    machine.clipboard = false;
}

function onOpen(isClipboard) {
    machine.clipboard = isClipboard;
    if (isClipboard) {
        return "";
    }
    return out.line("%") + out.line("O" + programNumber + " (" + programTitle.toUpperCase() + ")")
        + out.block("G17 G21 G40 G49 G80 G90 G94");
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var text = "";
    machine.toolCount++;
    if (machine.toolCount > 1) {
        text += out.block("M9") + out.block("M5") + out.block("G91 G28 Z0.") + out.block("G90");
    }
    machine.tool = tool;
    machine.forgetPosition();
    text += out.comment("T" + tool + " " + name + " D" + xyzFormat.format(diameter));
    text += out.block("T" + tool + " M6");
    text += out.block("S" + rpmFormat.format(spindleSpeed) + " M3");
    text += out.block("M8");
    return text + out.block(out.words(out.words(out.words(motion.word(0), "G43"), zOutput.format(clearanceHeight)),
        "H" + tool));
}

function onComment(text) {
    return out.comment(text);
}

function onDwell(seconds) {
    return out.block("G4 P" + Math.round(seconds * 1000));
}

function onClose() {
    var text = out.block("M9") + out.block("M5") + out.block("G91 G28 Z0.") + out.block("G90");
    if (!machine.clipboard) {
        text += out.block("M30") + out.line("%");
    }
    return text;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    if (comp == COMPENSATION_LEFT) {
        machine.compensation = "G41 D" + machine.tool;
    } else if (comp == COMPENSATION_RIGHT) {
        machine.compensation = "G42 D" + machine.tool;
    } else {
        machine.compensation = "G40";
    }
}

function getCompensation() {
    return machine.takeCompensation();
}

// --------------------------------------------------------------- Movement
function onLinear(vx, vy, vz, movement) {
    var xyz = out.words(out.words(xOutput.format(vx), yOutput.format(vy)), zOutput.format(vz));
    if (xyz == "") {
        return "";
    }
    var text = out.words(motion.word(movement == MOVEMENT_RAPID ? 0 : 1), getCompensation());
    return out.block(out.words(out.words(text, xyz), feed.word(getFeedrate(movement))));
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xOutput.getLast();
    var sy = yOutput.getLast();
    xOutput.reset();
    yOutput.reset();
    var text = out.words(motion.word(isCW ? 2 : 3), xOutput.format(ex));
    text = out.words(out.words(text, yOutput.format(ey)), zOutput.format(ez));
    text = out.words(text, "I" + xyzFormat.format(cx - sx));
    text = out.words(text, "J" + xyzFormat.format(cy - sy));
    return out.block(out.words(text, feed.word(getFeedrate(movement))));
}

// ---------------------------------------------------------------- Drilling

// The drilling cycle being posted, with the heights it needs.
var drilling = {
    header: null,
    code: function () {
        var h = this.header;
        if (h.name == "Drilling" || h.name == "Drilling (G81)") {
            return h.useBottomDwelling ? "G82" : "G81";
        }
        if (h.name == "Peck drilling (G83)") {
            return "G83";
        }
        throw new Error("unsupported drilling cycle: " + h.name);
    },
    bottom: function () {
        var h = this.header;
        return h.endDepthIsAbsolute ? h.endDepth : h.referencePlane - Math.abs(h.endDepth);
    },
    r: function () {
        var h = this.header;
        return h.safeDistanceIsAbsolute ? h.safeDistance : h.referencePlane + h.safeDistance;
    },
    dwell: function () {
        return out.block("G4 P" + Math.round(this.header.bottomDwelling * 1000));
    },
    rapidZ: function (z) {
        var word = zOutput.format(z);
        if (word == "") {
            return "";
        }
        return out.block(out.words(motion.word(0), word));
    },
    feedZ: function (z) {
        var word = zOutput.format(z);
        if (word == "") {
            return "";
        }
        return out.block(out.words(out.words(motion.word(1), word), feed.value(this.header.plungingFeedrate)));
    },
    // A rapid over the hole, then down to the retract plane.
    approach: function (x, y) {
        var xy = out.words(xOutput.format(x), yOutput.format(y));
        var text = "";
        if (xy != "") {
            text = out.block(out.words(motion.word(0), xy));
        }
        return text + this.rapidZ(this.header.retractPlane);
    },
    cycle: function () {
        var h = this.header;
        var code = this.code();
        var text = "G98 " + code + " Z" + xyzFormat.format(this.bottom()) + " R" + xyzFormat.format(this.r());
        if (code == "G83") {
            text += " Q" + xyzFormat.format(h.firstDepth);
        }
        if (h.useBottomDwelling) {
            text += " P" + Math.round(h.bottomDwelling * 1000);
        }
        return out.block(out.words(text, feed.value(h.plungingFeedrate)));
    },
    // A peck-drilled hole written out move by move: feed down one peck,
    // rapid out to the R plane, rapid back to just above the last depth.
    longhand: function (x, y) {
        var top = this.r();
        var bottom = this.bottom();
        var step = this.header.firstDepth > 0 ? this.header.firstDepth : top - bottom;
        var depth = top;
        var text = this.approach(x, y) + this.rapidZ(top);
        do {
            text += this.rapidZ(Math.min(top, depth + peckClearance));
            depth = Math.max(depth - step, bottom);
            text += this.feedZ(depth);
            if (depth <= bottom && this.header.useBottomDwelling) {
                text += this.dwell();
            }
            text += this.rapidZ(top);
        } while (depth > bottom);
        return text + this.rapidZ(this.header.retractPlane);
    }
};

function onDrillingHeader(drillHeader) {
    drilling.header = drillHeader;
    machine.cycleActive = false;
    if (!drillHeader.isLonghand) {
        drilling.code();
    }
    return "";
}

function onDrillingPoint(x, y) {
    if (drilling.header.isLonghand) {
        return drilling.longhand(x, y);
    }
    if (machine.cycleActive) {
        return out.block(out.words(xOutput.format(x), yOutput.format(y)));
    }
    machine.cycleActive = true;
    return drilling.approach(x, y) + drilling.cycle();
}

function onDrillingFooter() {
    var text = "";
    if (machine.cycleActive) {
        text = out.block("G80");
        // G98 leaves the tool at the retract plane and G80 cancels the
        // motion mode: Z and G print again.
        motion.reset();
        zOutput.reset();
    }
    machine.cycleActive = false;
    drilling.header = null;
    return text;
}
