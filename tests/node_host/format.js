// Number formats and output variables of the CNC-Calc host, written for
// Node.js from docs/cimco.md (the referee for postc's CIMCO support; it
// shares no code with postc).
//
// createFormat({prefix, width, zeropad, decimals, scale, forceDecimal,
// forceSign}): the value times scale, rounded to `decimals` places as
// JavaScript's toFixed rounds (the binary double; an exact tie away from
// zero: 1.005 gives 1.00, 0.125 gives 0.13); without forceDecimal trailing zeros
// (and then the point) are dropped; width pads the integer digits (zeros
// with zeropad, blanks otherwise) after the sign; forceSign writes "+".
// createVariable({prefix, force}, format): format(v) returns "" when the
// text is the one it returned last (unless force); getLast() the last value;
// reset() forgets the text, so the next format(v) returns it.
"use strict";

// A value that is not a finite number stops the post (docs/cimco.md,
// formats, 8): postc stops with RT032, which a post's `try` does not
// catch. The RangeError thrown here is also kept, so that the host stops
// the post when a `catch` took it and the post went on (`takeStop`).
var stopped = null;

// The RangeError of the first format since the last call that was given
// a value that is not a finite number, or null; forgets it.
function takeStop() {
    var e = stopped;
    stopped = null;
    return e;
}

function createFormat(props, decimalMark) {
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
    var mark = decimalMark === "," ? "," : ".";
    var intPad = zeropad ? "0" : " ";
    // The value rounded to `decimals` places as JavaScript rounds it
    // (toFixed: the binary double, an exact tie away from zero), as
    // integer and fraction digit strings.
    function digits(magnitude) {
        var text;
        if (magnitude < 1e21) {
            text = magnitude.toFixed(decimals);
        } else {
            // toFixed writes an exponent here; the double is an integer.
            text = BigInt(magnitude).toString() + (decimals > 0 ? "." + "0".repeat(decimals) : "");
        }
        var dot = text.indexOf(".");
        return dot < 0 ? { intPart: text, frac: "" } : { intPart: text.substring(0, dot), frac: text.substring(dot + 1) };
    }
    function format(value) {
        var v = Number(value) * scale;
        if (!isFinite(v)) {
            // No controller reads NaN or Infinity: the post stops here.
            var e = new RangeError("format() was given " + value + ", which is not a finite number");
            if (stopped === null) {
                stopped = e;
            }
            throw e;
        }
        var r = digits(Math.abs(v));
        var fracText = r.frac;
        if (!forceDecimal) {
            fracText = fracText.replace(/0+$/, "");
        }
        var zero = /^0*$/.test(r.intPart + fracText);
        var sign = v < 0 && !zero ? "-" : forceSign ? "+" : "";
        var intPart = r.intPart;
        if (intPart.length < width) {
            intPart = intPad.repeat(width - intPart.length) + intPart;
        }
        var point = fracText.length > 0 || forceDecimal ? mark : "";
        return prefix + sign + intPart + point + fracText;
    }
    return { format: format };
}

// Output variables: modal for the whole program; reset() forgets.
function createVariable(props, format) {
    props = props || {};
    var prefix = props.prefix === undefined ? "" : String(props.prefix);
    var force = !!props.force;
    var fmt = format || createFormat({}, ".");
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
        },
    };
}

module.exports = { createFormat: createFormat, createVariable: createVariable, takeStop: takeStop };
