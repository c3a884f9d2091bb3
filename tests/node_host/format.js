// Number formats and output variables of the CNC-Calc host, written for
// Node.js from docs/cimco.md (the referee for postc's CIMCO support; it
// shares no code with postc).
//
// createFormat({prefix, width, zeropad, decimals, scale, forceDecimal,
// forceSign}): the value times scale, rounded half away from zero on its
// decimal digits to `decimals` places; without forceDecimal trailing zeros
// (and then the point) are dropped; width pads the integer digits (zeros
// with zeropad, blanks otherwise) after the sign; forceSign writes "+".
// createVariable({prefix, force}, format): format(v) returns "" when the
// text is the one it returned last (unless force); getLast() the last value;
// reset() forgets the text, so the next format(v) returns it.
"use strict";

// The digits of |v| as JavaScript prints it: a digit string and the number
// of digits before the decimal point (which may be <= 0 or past the end).
function decimalDigits(v) {
    var s = Math.abs(v).toString();
    var exp = 0;
    var e = s.indexOf("e");
    if (e >= 0) {
        exp = parseInt(s.substring(e + 1), 10);
        s = s.substring(0, e);
    }
    var dot = s.indexOf(".");
    var digits = dot < 0 ? s : s.substring(0, dot) + s.substring(dot + 1);
    var point = (dot < 0 ? s.length : dot) + exp;
    // Drop leading zeros ("0.05" -> "5" with the point moved).
    var lead = 0;
    while (lead < digits.length - 1 && digits.charAt(lead) === "0") {
        lead++;
    }
    return { digits: digits.substring(lead), point: point - lead };
}

// Rounds |v| half away from zero to d decimals: integer and fraction text.
function roundHalfAway(v, d) {
    var x = decimalDigits(v);
    var digits = x.digits;
    var point = x.point;
    // Pad so there are at least `point + d` digits and a point >= 1.
    if (point < 1) {
        digits = "0".repeat(1 - point) + digits;
        point = 1;
    }
    var keep = point + d;
    if (digits.length < keep) {
        digits = digits + "0".repeat(keep - digits.length);
    }
    var up = digits.length > keep && digits.charCodeAt(keep) >= 53; // '5'
    var kept = digits.substring(0, keep).split("").map(Number);
    if (up) {
        var i = kept.length - 1;
        while (i >= 0 && kept[i] === 9) {
            kept[i] = 0;
            i--;
        }
        if (i < 0) {
            kept.unshift(1);
            point++;
        } else {
            kept[i]++;
        }
    }
    var intPart = kept.slice(0, kept.length - d).join("").replace(/^0+(?=\d)/, "");
    var frac = kept.slice(kept.length - d).join("");
    return { intPart: intPart === "" ? "0" : intPart, frac: frac };
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
    var pow = Math.pow(10, decimals);
    var intPad = zeropad ? "0" : " ";
    // The text of a value rounded to m units of the last decimal.
    function fromUnits(m, negative) {
        var d = decimals;
        if (!forceDecimal) {
            while (d > 0 && m % 10 === 0) {
                m = m / 10;
                d--;
            }
        }
        var digits = String(m);
        if (digits.length <= d) {
            digits = "0".repeat(d + 1 - digits.length) + digits;
        }
        var intPart = digits.substring(0, digits.length - d);
        if (intPart.length < width) {
            intPart = intPad.repeat(width - intPart.length) + intPart;
        }
        var sign = negative && m !== 0 ? "-" : forceSign ? "+" : "";
        var point = d > 0 || forceDecimal ? mark : "";
        return prefix + sign + intPart + point + digits.substring(digits.length - d);
    }
    function format(value) {
        var v = Number(value) * scale;
        if (isNaN(v)) {
            v = 0;
        }
        var scaled = Math.abs(v) * pow;
        if (scaled < 1e14) {
            var floor = Math.floor(scaled);
            var frac = scaled - floor;
            // Near a tie the product's own rounding error could decide:
            // take the exact path.
            if (Math.abs(frac - 0.5) > 1e-9 * Math.max(1, scaled)) {
                return fromUnits(frac > 0.5 ? floor + 1 : floor, v < 0);
            }
        }
        var r = roundHalfAway(v, decimals);
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

module.exports = { createFormat: createFormat, createVariable: createVariable, roundHalfAway: roundHalfAway };
