//! JavaScript value semantics, defined once for every part of postc that
//! evaluates JavaScript: the frontend's compile-time constants
//! (`postc-front-cimco`'s `lower/consts.rs`), the runtime's interpreter
//! and constant folder, and the Rhai script host. Number to text, text to
//! number, the order of texts, `parseInt`, `parseFloat`, `toFixed`,
//! `Math.round` and 32-bit integer conversions.
//!
//! These follow ECMAScript 5 closely enough for post processors: numbers
//! print with the shortest digits that read back as the same double,
//! switching to exponent form at 1e21 and below 1e-6 as JavaScript does.

/// Powers of ten a double holds exactly (the runtime's number writer
/// scales by them too).
pub const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
    1e21, 1e22,
];

/// The order JavaScript gives two texts (`<`, `>`, `sort()` without a
/// comparator): by UTF-16 code units. UTF-8's byte order is the same for
/// every character up to U+FFFF, but puts U+E000..U+FFFF before the
/// characters past U+FFFF, which UTF-16 writes as surrogates (U+D800..):
/// texts that hold both are compared unit by unit.
pub fn compare_text(a: &str, b: &str) -> std::cmp::Ordering {
    if a.is_ascii() || b.is_ascii() {
        return a.as_bytes().cmp(b.as_bytes());
    }
    a.encode_utf16().cmp(b.encode_utf16())
}

/// The text JavaScript gives a number (`String(n)`, `"" + n`).
pub fn number_to_string(n: f64) -> String {
    let mut s = String::new();
    push_number(&mut s, n);
    s
}

/// Appends the text JavaScript gives a number: `ryu-js` implements
/// ECMAScript's Number::toString (shortest round-trip digits, exponent
/// form from 1e21 and below 1e-6, `NaN`, `Infinity`, `-0` as `0`);
/// whole numbers go through `itoa`.
pub fn push_number(out: &mut String, n: f64) {
    if n == n.trunc() && n.abs() < 9_007_199_254_740_992.0 {
        // Exact: every such double is an integer that fits an i64 (and
        // -0 prints `0`, as JavaScript prints it).
        out.push_str(itoa::Buffer::new().format(n as i64));
        return;
    }
    out.push_str(ryu_js::Buffer::new().format(n));
}

/// JavaScript's `Number(text)`: blanks around are ignored, empty text is
/// 0, decimal and hexadecimal numbers and `Infinity` read, anything else
/// is NaN.
pub fn text_to_number(text: &str) -> f64 {
    let t = text.trim_matches(|c: char| c.is_whitespace() || c == '\u{feff}');
    if t.is_empty() {
        return 0.0;
    }
    if let Some(hex) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        return if !hex.is_empty() && hex.chars().all(|c| c.is_ascii_hexdigit()) {
            hex.chars().fold(0.0, |acc, c| acc * 16.0 + f64::from(c.to_digit(16).unwrap_or(0)))
        } else {
            f64::NAN
        };
    }
    let (sign, body) = match t.as_bytes()[0] {
        b'-' => (-1.0, &t[1..]),
        b'+' => (1.0, &t[1..]),
        _ => (1.0, t),
    };
    if body == "Infinity" {
        return sign * f64::INFINITY;
    }
    match decimal_prefix(body) {
        Some(len) if len == body.len() => sign * body.parse::<f64>().unwrap_or(f64::NAN),
        _ => f64::NAN,
    }
}

/// The length of the longest prefix of `s` that is a decimal literal
/// (digits, a point, digits, an exponent), if any digit is in it.
fn decimal_prefix(s: &str) -> Option<usize> {
    let b = s.as_bytes();
    let mut i = 0;
    let digits = |i: &mut usize| {
        let start = *i;
        while *i < b.len() && b[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - start
    };
    let mut seen = digits(&mut i);
    if i < b.len() && b[i] == b'.' {
        let mut j = i + 1;
        let frac = digits(&mut j);
        if seen > 0 || frac > 0 {
            i = j;
            seen += frac;
        }
    }
    if seen == 0 {
        return None;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if digits(&mut j) > 0 {
            i = j;
        }
    }
    Some(i)
}

/// JavaScript's `parseFloat(text)`.
pub fn parse_float(text: &str) -> f64 {
    let t = text.trim_start();
    let (sign, body) = match t.as_bytes().first() {
        Some(b'-') => (-1.0, &t[1..]),
        Some(b'+') => (1.0, &t[1..]),
        _ => (1.0, t),
    };
    if body.starts_with("Infinity") {
        return sign * f64::INFINITY;
    }
    match decimal_prefix(body) {
        Some(len) => {
            sign * short_decimal(&body.as_bytes()[..len]).unwrap_or_else(|| body[..len].parse().unwrap_or(f64::NAN))
        }
        None => f64::NAN,
    }
}

/// `parseFloat` of text that is all one short decimal (`-12.5`, `1000.`):
/// a sign, then what [`short_decimal`] reads, and nothing else. `None` for
/// any other text, which [`parse_float`] reads.
#[doc(hidden)]
pub fn parse_short_decimal(b: &[u8]) -> Option<f64> {
    let (sign, body) = match b.first() {
        Some(b'-') => (-1.0, &b[1..]),
        Some(b'+') => (1.0, &b[1..]),
        _ => (1.0, b),
    };
    short_decimal(body).map(|n| sign * n)
}

/// The value of decimal text of at most 15 digits with no exponent
/// (`123.45`, `.5`, `7.`), the number a post reads back from a word it
/// formatted: its digits as an integer below 2^53 and a power of ten are
/// both exact doubles, so one division gives the correctly rounded value,
/// as the full parse would (Clinger's fast path). `None` for anything else.
fn short_decimal(b: &[u8]) -> Option<f64> {
    let (mut m, mut digits, mut fraction, mut point) = (0u64, 0usize, 0usize, false);
    for &c in b {
        match c {
            b'0'..=b'9' => {
                m = m * 10 + u64::from(c - b'0');
                digits += 1;
                fraction += usize::from(point);
                if digits > 15 {
                    return None;
                }
            }
            b'.' if !point => point = true,
            _ => return None,
        }
    }
    (digits > 0).then(|| m as f64 / POW10[fraction])
}

/// JavaScript's `parseInt(text, radix)`; a radix of 0 means 10, or 16
/// after `0x`.
pub fn parse_int(text: &str, radix: f64) -> f64 {
    let t = text.trim_start();
    let (sign, mut body) = match t.as_bytes().first() {
        Some(b'-') => (-1.0, &t[1..]),
        Some(b'+') => (1.0, &t[1..]),
        _ => (1.0, t),
    };
    let mut radix = if radix.is_finite() { radix.trunc() as i64 } else { 0 };
    if radix != 0 && !(2..=36).contains(&radix) {
        return f64::NAN;
    }
    if (radix == 0 || radix == 16) && (body.starts_with("0x") || body.starts_with("0X")) {
        body = &body[2..];
        radix = 16;
    }
    if radix == 0 {
        radix = 10;
    }
    let mut value = 0.0;
    let mut any = false;
    for c in body.chars() {
        match c.to_digit(radix as u32) {
            Some(d) => {
                value = value * radix as f64 + f64::from(d);
                any = true;
            }
            None => break,
        }
    }
    if any { sign * value } else { f64::NAN }
}

/// JavaScript's `n.toString(radix)`; `Err` with the message of the
/// `RangeError` for a radix outside 2..36, and for what postc does not
/// write in another radix (a fraction, past 2^53).
pub fn radix_string(n: f64, radix: f64) -> Result<String, String> {
    if !(2.0..=36.0).contains(&radix) || radix.fract() != 0.0 {
        return Err("RangeError: toString() radix must be between 2 and 36".into());
    }
    let radix = radix as u32;
    if radix == 10 || !n.is_finite() {
        return Ok(number_to_string(n));
    }
    if n.fract() != 0.0 || n.abs() >= 9_007_199_254_740_992.0 {
        return Err("postc writes a number in another radix only when it is a whole number below 2^53".into());
    }
    let mut m = n.abs() as u64;
    let mut digits = Vec::new();
    loop {
        digits.push(std::char::from_digit((m % u64::from(radix)) as u32, radix).unwrap_or('0'));
        m /= u64::from(radix);
        if m == 0 {
            break;
        }
    }
    if n < 0.0 {
        digits.push('-');
    }
    Ok(digits.iter().rev().collect())
}

/// The `name` and `message` of the error object JavaScript's `catch`
/// receives for an error postc words as `"TypeError: message"`
/// (`ReferenceError`, `RangeError`, `SyntaxError` likewise); `None` for
/// text that names no error.
pub fn error_parts(text: &str) -> Option<(&'static str, &str)> {
    ["TypeError", "ReferenceError", "RangeError", "SyntaxError"]
        .into_iter()
        .find_map(|name| text.strip_prefix(name).and_then(|r| r.strip_prefix(": ")).map(|m| (name, m)))
}

/// A property key, for [`array_index`]: a number, a text, or any other
/// value (a boolean, `null`, `undefined`, an object).
#[derive(Clone, Copy, Debug)]
pub enum Key<'a> {
    Number(f64),
    Text(&'a str),
    Other,
}

/// The element of an array (or character of a text) a property key names:
/// a key names element `i` when its text is `i` as JavaScript writes it,
/// below 2^32 - 1. So `a[1]`, `a["1"]` and `a[-0]` read element 1 (0),
/// while `a["01"]`, `a[" 1"]`, `a[1.5]`, `a[true]` and `a[null]` name
/// properties the array does not have.
pub fn array_index(key: Key<'_>) -> Option<u32> {
    match key {
        // Whole when it survives the cast (checked with no call to `trunc`).
        Key::Number(n) => ((0.0..4_294_967_295.0).contains(&n) && f64::from(n as u32) == n).then_some(n as u32),
        Key::Text(t) => {
            let b = t.as_bytes();
            let canonical = !b.is_empty() && b.iter().all(u8::is_ascii_digit) && (b.len() == 1 || b[0] != b'0');
            canonical.then(|| t.parse::<u32>().ok()).flatten().filter(|&i| i != u32::MAX)
        }
        Key::Other => None,
    }
}

/// JavaScript's `Math.min`: NaN when any value is NaN (Rust's `f64::min`
/// skips it), -0 below +0, `Infinity` of none.
pub fn math_min(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(f64::INFINITY, |a, b| {
        if a.is_nan() || b.is_nan() {
            f64::NAN
        } else if a < b || (a == b && a.is_sign_negative()) {
            a
        } else {
            b
        }
    })
}

/// JavaScript's `Math.max`: NaN when any value is NaN, +0 above -0,
/// `-Infinity` of none.
pub fn math_max(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(f64::NEG_INFINITY, |a, b| {
        if a.is_nan() || b.is_nan() {
            f64::NAN
        } else if a > b || (a == b && a.is_sign_positive()) {
            a
        } else {
            b
        }
    })
}

/// JavaScript's `Math.pow` (and `**`): as `powf`, but NaN for a NaN
/// exponent and for ±1 to an infinite power, where `powf` gives 1.
pub fn math_pow(x: f64, y: f64) -> f64 {
    if y.is_nan() || (x.abs() == 1.0 && y.is_infinite()) { f64::NAN } else { x.powf(y) }
}

/// JavaScript's `Math.round`: the nearest integer, halves toward positive
/// infinity.
pub fn math_round(x: f64) -> f64 {
    if !x.is_finite() {
        return x;
    }
    let f = x.floor();
    if x - f >= 0.5 { f + 1.0 } else { f }
}

/// ToInt32 of ECMAScript: modulo 2^32, as a signed integer.
pub fn to_int32(x: f64) -> i32 {
    to_uint32(x) as i32
}

/// ToUint32 of ECMAScript.
pub fn to_uint32(x: f64) -> u32 {
    if !x.is_finite() {
        return 0;
    }
    let t = x.trunc().rem_euclid(4_294_967_296.0);
    t as u32
}

/// JavaScript's `x.toFixed(digits)`: rounds the exact binary value, exact
/// halves away from zero, a sign for every number below zero; 1e21 and
/// above print as `String(x)`.
/// JavaScript's `x.toPrecision(p)`: `p` significant digits (1 to 100,
/// else `Err` with JavaScript's RangeError), rounded from the exact value
/// of the double, a tie to the larger; exponential notation (`2.0e+2`)
/// when the exponent is under -6 or not under `p`, else fixed.
pub fn to_precision(x: f64, p: f64) -> Result<String, String> {
    if !x.is_finite() {
        return Ok(number_to_string(x));
    }
    if !(1.0..=100.0).contains(&p.trunc()) {
        return Err("RangeError: toPrecision() argument must be between 1 and 100".into());
    }
    let p = p.trunc() as usize;
    let sign = if x < 0.0 { "-" } else { "" };
    if x == 0.0 {
        return Ok(if p > 1 { format!("0.{}", "0".repeat(p - 1)) } else { "0".into() });
    }
    let exact = format!("{:.1100}", x.abs());
    let (int_part, frac) = exact.split_once('.').unwrap_or((&exact, ""));
    let all: Vec<u8> = int_part.bytes().chain(frac.bytes()).collect();
    let first = all.iter().position(|&c| c != b'0').unwrap_or(0);
    let mut e = int_part.len() as i64 - first as i64 - 1;
    let mut sig: Vec<u8> = all[first..].iter().copied().chain(std::iter::repeat(b'0')).take(p).collect();
    if all.get(first + p).is_some_and(|&c| c >= b'5') && round_up(&mut sig) {
        sig.truncate(p);
        e += 1;
    }
    let sig = String::from_utf8(sig).unwrap_or_default();
    Ok(if e < -6 || e >= p as i64 {
        let mantissa = if p > 1 { format!("{}.{}", &sig[..1], &sig[1..]) } else { sig };
        format!("{sign}{mantissa}e{}{}", if e >= 0 { "+" } else { "-" }, e.abs())
    } else if e >= 0 {
        let point = e as usize + 1;
        if p > point { format!("{sign}{}.{}", &sig[..point], &sig[point..]) } else { format!("{sign}{sig}") }
    } else {
        format!("{sign}0.{}{sig}", "0".repeat((-e - 1) as usize))
    })
}

/// Adds one to the last of the decimal `digits`, carrying: whether the
/// carry ran past the first digit and a `1` now leads (`999` -> `1000`).
fn round_up(digits: &mut Vec<u8>) -> bool {
    for d in digits.iter_mut().rev() {
        if *d == b'9' {
            *d = b'0';
        } else {
            *d += 1;
            return false;
        }
    }
    digits.insert(0, b'1');
    true
}

pub fn to_fixed(x: f64, digits: f64) -> String {
    let d = if digits.is_finite() { digits.trunc().clamp(0.0, 100.0) as usize } else { 0 };
    if x.is_nan() {
        return "NaN".into();
    }
    if x.abs() >= 1e21 || x.is_infinite() {
        return number_to_string(x);
    }
    // The exact decimal expansion of the double (at most 1074 fraction digits).
    let exact = format!("{:.1100}", x.abs());
    let (int_part, frac) = exact.split_once('.').unwrap_or((&exact, ""));
    let mut digits: Vec<u8> = int_part.bytes().chain(frac.bytes().take(d)).collect();
    let rest = &frac.as_bytes()[d.min(frac.len())..];
    if rest.first().is_some_and(|&c| c >= b'5') {
        round_up(&mut digits);
    }
    let int_len = digits.len() - d;
    let mut s = String::new();
    // A negative number keeps its sign when it rounds to zero
    // (`(-0.001).toFixed(2)` is "-0.00"); -0 is not below zero.
    if x < 0.0 {
        s.push('-');
    }
    s.push_str(std::str::from_utf8(&digits[..int_len]).unwrap_or("0"));
    if d > 0 {
        s.push('.');
        s.push_str(std::str::from_utf8(&digits[int_len..]).unwrap_or(""));
    }
    s
}

/// What a JavaScript value is, for the properties its prototype gives it:
/// each kind is a built-in prototype (`Array.prototype`, ...), whose own
/// prototype is `Object.prototype`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ProtoKind {
    Object,
    Array,
    Function,
    RegExp,
    String,
    Number,
    Boolean,
}

impl ProtoKind {
    pub const ALL: [ProtoKind; 7] = [
        ProtoKind::Object,
        ProtoKind::Array,
        ProtoKind::Function,
        ProtoKind::RegExp,
        ProtoKind::String,
        ProtoKind::Number,
        ProtoKind::Boolean,
    ];

    /// The kind of the built-in constructor `name` (`"Array"` for
    /// `Array.prototype`).
    pub fn of_constructor(name: &str) -> Option<ProtoKind> {
        ProtoKind::ALL.into_iter().find(|k| k.constructor() == name)
    }

    /// The name of the kind's constructor.
    pub fn constructor(self) -> &'static str {
        match self {
            ProtoKind::Object => "Object",
            ProtoKind::Array => "Array",
            ProtoKind::Function => "Function",
            ProtoKind::RegExp => "RegExp",
            ProtoKind::String => "String",
            ProtoKind::Number => "Number",
            ProtoKind::Boolean => "Boolean",
        }
    }
}

/// Whether a value of this kind has `name` from its prototype chain in
/// Node.js 20 (`"toString" in {}`, `"push" in []`, `"call" in f`): what
/// `key in value` finds besides the value's own properties and what the
/// post added to the prototypes.
pub fn prototype_has(kind: ProtoKind, name: &str) -> bool {
    const OBJECT: &[&str] = &[
        "constructor",
        "hasOwnProperty",
        "isPrototypeOf",
        "propertyIsEnumerable",
        "toLocaleString",
        "toString",
        "valueOf",
        "__proto__",
        "__defineGetter__",
        "__defineSetter__",
        "__lookupGetter__",
        "__lookupSetter__",
    ];
    const ARRAY: &[&str] = &[
        "length",
        "at",
        "concat",
        "copyWithin",
        "entries",
        "every",
        "fill",
        "filter",
        "find",
        "findIndex",
        "findLast",
        "findLastIndex",
        "flat",
        "flatMap",
        "forEach",
        "includes",
        "indexOf",
        "join",
        "keys",
        "lastIndexOf",
        "map",
        "pop",
        "push",
        "reduce",
        "reduceRight",
        "reverse",
        "shift",
        "slice",
        "some",
        "sort",
        "splice",
        "unshift",
        "values",
        "toReversed",
        "toSorted",
        "toSpliced",
        "with",
    ];
    const FUNCTION: &[&str] =
        &["length", "name", "prototype", "arguments", "caller", "apply", "bind", "call", "toString"];
    const REGEXP: &[&str] = &[
        "lastIndex",
        "source",
        "flags",
        "global",
        "ignoreCase",
        "multiline",
        "dotAll",
        "sticky",
        "unicode",
        "unicodeSets",
        "hasIndices",
        "exec",
        "test",
        "toString",
        "compile",
    ];
    const STRING: &[&str] = &[
        "length",
        "anchor",
        "at",
        "big",
        "blink",
        "bold",
        "charAt",
        "charCodeAt",
        "codePointAt",
        "concat",
        "endsWith",
        "fontcolor",
        "fontsize",
        "fixed",
        "includes",
        "indexOf",
        "isWellFormed",
        "italics",
        "lastIndexOf",
        "link",
        "localeCompare",
        "match",
        "matchAll",
        "normalize",
        "padEnd",
        "padStart",
        "repeat",
        "replace",
        "replaceAll",
        "search",
        "slice",
        "small",
        "split",
        "strike",
        "sub",
        "substr",
        "substring",
        "sup",
        "startsWith",
        "toString",
        "toWellFormed",
        "trim",
        "trimStart",
        "trimLeft",
        "trimEnd",
        "trimRight",
        "toLocaleLowerCase",
        "toLocaleUpperCase",
        "toLowerCase",
        "toUpperCase",
        "valueOf",
    ];
    const NUMBER: &[&str] = &["toExponential", "toFixed", "toPrecision", "toString", "valueOf", "toLocaleString"];
    const BOOLEAN: &[&str] = &["toString", "valueOf"];
    let own = match kind {
        ProtoKind::Object => &[][..],
        ProtoKind::Array => ARRAY,
        ProtoKind::Function => FUNCTION,
        ProtoKind::RegExp => REGEXP,
        ProtoKind::String => STRING,
        ProtoKind::Number => NUMBER,
        ProtoKind::Boolean => BOOLEAN,
    };
    own.contains(&name) || OBJECT.contains(&name)
}

/// A JavaScript primitive value, borrowed from the value it stands for:
/// what the operators below read. Each engine's values (the frontend's
/// compile-time constants, the runtime's values once objects are made
/// primitives) give theirs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive<'a> {
    Number(f64),
    Text(&'a str),
    Bool(bool),
    Null,
    Undefined,
}

impl Primitive<'_> {
    /// ToNumber (`Number(v)`).
    pub fn to_number(self) -> f64 {
        match self {
            Primitive::Number(n) => n,
            Primitive::Text(t) => text_to_number(t),
            Primitive::Bool(b) => f64::from(u8::from(b)),
            Primitive::Null => 0.0,
            Primitive::Undefined => f64::NAN,
        }
    }

    /// ToBoolean (`!!v`).
    pub fn truthy(self) -> bool {
        match self {
            Primitive::Number(n) => n != 0.0 && !n.is_nan(),
            Primitive::Text(t) => !t.is_empty(),
            Primitive::Bool(b) => b,
            Primitive::Null | Primitive::Undefined => false,
        }
    }

    /// Appends ToString (`String(v)`).
    pub fn push_text(self, out: &mut String) {
        match self {
            Primitive::Number(n) => push_number(out, n),
            Primitive::Text(t) => out.push_str(t),
            Primitive::Bool(b) => out.push_str(if b { "true" } else { "false" }),
            Primitive::Null => out.push_str("null"),
            Primitive::Undefined => out.push_str("undefined"),
        }
    }
}

/// `a === b` (IsStrictlyEqual) of two primitives.
pub fn strict_equals(a: Primitive<'_>, b: Primitive<'_>) -> bool {
    use Primitive::*;
    match (a, b) {
        (Number(x), Number(y)) => x == y,
        (Text(x), Text(y)) => x == y,
        (Bool(x), Bool(y)) => x == y,
        (Null, Null) | (Undefined, Undefined) => true,
        _ => false,
    }
}

/// `a == b` (IsLooselyEqual) of two primitives: null and undefined equal
/// each other only, two texts compare as texts, anything else as numbers.
pub fn loose_equals(a: Primitive<'_>, b: Primitive<'_>) -> bool {
    use Primitive::*;
    match (a, b) {
        (Null | Undefined, Null | Undefined) => true,
        (Null | Undefined, _) | (_, Null | Undefined) => false,
        (Text(x), Text(y)) => x == y,
        _ => a.to_number() == b.to_number(),
    }
}

/// The order of two primitives for `<`, `<=`, `>`, `>=` (IsLessThan):
/// two texts by their UTF-16 units ([`compare_text`]), anything else as
/// numbers; `None` when a number is NaN, which makes every one of the
/// four false.
pub fn order(a: Primitive<'_>, b: Primitive<'_>) -> Option<std::cmp::Ordering> {
    match (a, b) {
        (Primitive::Text(x), Primitive::Text(y)) => Some(compare_text(x, y)),
        _ => a.to_number().partial_cmp(&b.to_number()),
    }
}
