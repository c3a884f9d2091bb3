/*
 * Fanuc 0i-MF milling post (mm) for CIMCO CNC-Calc, one of six posts of
 * postc's field-style set: the six print the same program for the same
 * toolpath, each written in one way posts found in the field are written.
 *
 * This one is built from small helpers that call helpers and take
 * functions as values: `modal(format, prefix)` makes a modal word (a
 * closure over its last text), `each(list, fn)` and the ES5 array methods
 * `forEach`, `map`, `filter` and `sort` with callbacks (the safe-start
 * codes sorted numerically, every modal word reset by `forEach`), a
 * callback that writes each peck of the longhand cycle, a `do ... while`
 * for the pecks, and `try { } catch (e) { }` that names the drilling cycle
 * in the error of one the post cannot write before throwing it again.
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

// ------------------------------------------------------------------ Formats
var xyzFormat = createFormat({decimals: 3, forceDecimal: true});
var feedFormat = createFormat({decimals: 1});
var rpmFormat = createFormat({decimals: 0});
var codeFormat = createFormat({decimals: 0});

// Machine settings.
var programNumber = 1001;
var programTitle = "Field style Fanuc mill";
var clearanceHeight = 50;
var peckClearance = 1;
var safeStartCodes = [90, 94, 17, 21, 40, 49, 80];

// ------------------------------------------------------------ Modal words

// A modal word: `word(value)` is its text, or "" when that is the text it
// gave last; `reset()` forgets; `last()` is the last value.
function modal(prefix, format) {
    var lastText = null;
    var lastValue = 0;
    return {
        word: function (value) {
            var text = prefix + format.format(value);
            lastValue = value;
            if (text == lastText) {
                return "";
            }
            lastText = text;
            return text;
        },
        reset: function () {
            lastText = null;
        },
        last: function () {
            return lastValue;
        }
    };
}

var gMotion = modal("G", codeFormat);
var xWord = modal("X", xyzFormat);
var yWord = modal("Y", xyzFormat);
var zWord = modal("Z", xyzFormat);
var fWord = modal("F", feedFormat);
var everyModal = [gMotion, xWord, yWord, zWord, fWord];

// -------------------------------------------------------------------- State
var sequenceNumber = sequenceNumberStart;
var clipboard = false;
var toolCount = 0;
var toolNumber = 0;
var pendingCompensation = "";
var drill = null;
var cycleActive = false;

// ------------------------------------------------------------------ Helpers

// Calls fn with each element of a list and its index.
function each(list, fn) {
    for (var i = 0; i < list.length; i++) {
        fn(list[i], i);
    }
}

function isWord(word) {
    return word !== "";
}

// A block of the words that are not empty, after its number.
function block(words) {
    var kept = words.filter(isWord);
    if (kept.length == 0) {
        return "";
    }
    var text = kept.join(variableDelimeter);
    if (showSequenceNumbers) {
        text = "N" + sequenceNumber + variableDelimeter + text;
        sequenceNumber += sequenceNumberIncrement;
    }
    return text + linebreak;
}

// The blocks of a list of word lists.
function blocks(lists) {
    var out = "";
    each(lists, function (words) {
        out += block(words);
    });
    return out;
}

// What a comment cannot hold, dropped.
function commentText(text) {
    var kept = [];
    each(String(text).toUpperCase().split(""), function (c) {
        if (c != "(" && c != ")") {
            kept.push(c);
        }
    });
    return kept.join("");
}

function comment(text) {
    return block(["(" + commentText(text) + ")"]);
}

// The feed word of a movement, as its number: getFeedrate's text read back.
function feedOf(movement, then) {
    var f = getFeedrate(movement);
    return f == "" ? "" : then(parseFloat(f.substring(1)));
}

function forgetPosition() {
    everyModal.forEach(function (m) {
        m.reset();
    });
}

// -------------------------------------------------------------- Framework
function onInit() {
    clipboard = false;
}

function onOpen(isClipboard) {
    clipboard = isClipboard;
    if (isClipboard) {
        return "";
    }
    var codes = safeStartCodes.slice(0).sort(function (a, b) {
        return a - b;
    });
    return "%" + linebreak
        + "O" + programNumber + " (" + programTitle.toUpperCase() + ")" + linebreak
        + block(codes.map(function (c) {
            return "G" + c;
        }));
}

function onToolChange(tool, name, diameter, spindleSpeed) {
    var out = "";
    toolCount++;
    if (toolCount > 1) {
        out += blocks([["M9"], ["M5"], ["G91", "G28", "Z0."], ["G90"]]);
    }
    toolNumber = tool;
    forgetPosition();
    out += comment("T" + tool + " " + name + " D" + xyzFormat.format(diameter));
    return out + blocks([
        ["T" + tool, "M6"],
        ["S" + rpmFormat.format(spindleSpeed), "M3"],
        ["M8"],
        [gMotion.word(0), "G43", zWord.word(clearanceHeight), "H" + tool]
    ]);
}

function onComment(text) {
    return comment(text);
}

function onDwell(seconds) {
    return block(["G4", "P" + Math.round(seconds * 1000)]);
}

function onClose() {
    var out = blocks([["M9"], ["M5"], ["G91", "G28", "Z0."], ["G90"]]);
    if (!clipboard) {
        out += block(["M30"]) + "%" + linebreak;
    }
    return out;
}

// ------------------------------------------------------------ Compensation
function onCompensation(comp) {
    var side = comp == COMPENSATION_LEFT ? "G41" : comp == COMPENSATION_RIGHT ? "G42" : "";
    pendingCompensation = side == "" ? "G40" : side + variableDelimeter + "D" + toolNumber;
}

function getCompensation() {
    var code = pendingCompensation;
    pendingCompensation = "";
    return code;
}

// --------------------------------------------------------------- Movement

// A block of a motion code and axis words, when an axis word is printed;
// `before` gives the words between the code and the axes, `after` those
// after the axes (either may be null).
function motionBlock(code, axes, before, after) {
    if (axes.filter(isWord).length == 0) {
        return "";
    }
    var words = [gMotion.word(code)];
    words = words.concat(before ? before() : [], axes);
    return block(after ? words.concat(after()) : words);
}

function onLinear(vx, vy, vz, movement) {
    var axes = [xWord.word(vx), yWord.word(vy), zWord.word(vz)];
    return motionBlock(movement == MOVEMENT_RAPID ? 0 : 1, axes, function () {
        return [getCompensation()];
    }, function () {
        return [feedOf(movement, fWord.word)];
    });
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    var sx = xWord.last();
    var sy = yWord.last();
    xWord.reset();
    yWord.reset();
    var words = [gMotion.word(isCW ? 2 : 3), xWord.word(ex), yWord.word(ey), zWord.word(ez),
        "I" + xyzFormat.format(cx - sx), "J" + xyzFormat.format(cy - sy)];
    return block(words.concat([feedOf(movement, fWord.word)]));
}

// ---------------------------------------------------------------- Drilling
function holeBottom() {
    return drill.endDepthIsAbsolute ? drill.endDepth : drill.referencePlane - Math.abs(drill.endDepth);
}

function rPlane() {
    return drill.safeDistanceIsAbsolute ? drill.safeDistance : drill.referencePlane + drill.safeDistance;
}

function dwellWord() {
    return "P" + Math.round(drill.bottomDwelling * 1000);
}

// The canned cycle's G code; an error for a cycle the post has none for.
function cycleCode(name) {
    if (name == "Drilling" || name == "Drilling (G81)") {
        return drill.useBottomDwelling ? "G82" : "G81";
    }
    if (name == "Peck drilling (G83)") {
        return "G83";
    }
    throw new Error("no canned cycle");
}

function rapidZ(z) {
    return motionBlock(0, [zWord.word(z)], null, null);
}

function feedZ(z) {
    return motionBlock(1, [zWord.word(z)], null, function () {
        return [fWord.word(drill.plungingFeedrate)];
    });
}

// A rapid over the hole, then down to the retract plane.
function approach(x, y) {
    return motionBlock(0, [xWord.word(x), yWord.word(y)], null, null) + rapidZ(drill.retractPlane);
}

// The depths of the pecks of a hole, each given to `peck` with whether it
// is the last.
function eachPeck(top, bottom, step, peck) {
    var depth = top;
    do {
        var from = depth;
        depth = Math.max(depth - step, bottom);
        peck(from, depth, depth <= bottom);
    } while (depth > bottom);
}

// A peck-drilled hole written out move by move: feed down one peck,
// rapid out to the R plane, rapid back to just above the last depth.
function longhandHole(x, y) {
    var top = rPlane();
    var bottom = holeBottom();
    var out = approach(x, y) + rapidZ(top);
    eachPeck(top, bottom, drill.firstDepth > 0 ? drill.firstDepth : top - bottom, function (from, depth, last) {
        out += rapidZ(Math.min(top, from + peckClearance)) + feedZ(depth);
        if (last && drill.useBottomDwelling) {
            out += block(["G4", dwellWord()]);
        }
        out += rapidZ(top);
    });
    return out + rapidZ(drill.retractPlane);
}

function cycleBlock(code) {
    var words = ["G98", code, "Z" + xyzFormat.format(holeBottom()), "R" + xyzFormat.format(rPlane())];
    if (code == "G83") {
        words.push("Q" + xyzFormat.format(drill.firstDepth));
    }
    if (drill.useBottomDwelling) {
        words.push(dwellWord());
    }
    words.push(fWord.word(drill.plungingFeedrate));
    return block(words);
}

function onDrillingHeader(drillHeader) {
    drill = drillHeader;
    cycleActive = false;
    if (!drill.isLonghand) {
        try {
            cycleCode(drill.name);
        } catch (e) {
            throw new Error("unsupported drilling cycle: " + drill.name);
        }
    }
    return "";
}

function onDrillingPoint(x, y) {
    if (drill.isLonghand) {
        return longhandHole(x, y);
    }
    if (cycleActive) {
        return block([xWord.word(x), yWord.word(y)]);
    }
    cycleActive = true;
    return approach(x, y) + cycleBlock(cycleCode(drill.name));
}

function onDrillingFooter() {
    var out = "";
    if (cycleActive) {
        out = block(["G80"]);
        // G98 leaves the tool at the retract plane and G80 cancels the
        // motion mode: Z and G print again.
        [gMotion, zWord].forEach(function (m) {
            m.reset();
        });
    }
    cycleActive = false;
    drill = null;
    return out;
}
