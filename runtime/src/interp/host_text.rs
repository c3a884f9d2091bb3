//! Native primitives of a host written in JavaScript (Fusion's `host.js`):
//! the text of a number under a format's specifiers
//! ([`postc_ir::Builtin::FormatNumber`]) and the words of a block joined
//! ([`postc_ir::Builtin::Words`]). They do what the host's JavaScript of
//! the same name (`__postc_formatNumber`, `__postc_words`, which the
//! Node.js referee `tests/node_host/fusion.js` defines) does, with
//! JavaScript's arithmetic and number text, and build their text in the
//! interpreter's scratch buffer: a result of up to 22 ASCII bytes (a
//! word) allocates nothing.

use postc_ir::Diagnostic;

use super::objects;
use super::protos::Protos;
use crate::value::{Text, Value};

type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// JavaScript's `ToNumber` of a primitive (an object reads as NaN: its
/// `valueOf` is not called).
fn number(v: Option<&Value>) -> f64 {
    match v {
        Some(Value::Num(n)) => *n,
        Some(Value::Text(t)) => crate::js::text_to_number(t.as_str()),
        Some(Value::Bool(b)) => f64::from(u8::from(*b)),
        Some(Value::Null) => 0.0,
        _ => f64::NAN,
    }
}

fn truthy(v: Option<&Value>) -> bool {
    v.is_some_and(Value::truthy)
}

/// Appends JavaScript's `String(v)`.
fn push_string(out: &mut String, v: Option<&Value>) {
    match v {
        None | Some(Value::Undefined) => out.push_str("undefined"),
        Some(Value::Null) => out.push_str("null"),
        Some(other) => other.append_to(out),
    }
}

/// JavaScript's `ToIntegerOrInfinity` of a `substring` index, clamped to
/// a text of `len` characters.
fn clamp_index(x: f64, len: usize) -> usize {
    if x.is_nan() || x <= 0.0 {
        0
    } else if x >= len as f64 {
        len
    } else {
        x as usize
    }
}

/// How many times `while (n > 0) { ...; --n; }` runs, bounded (a width or
/// a number of decimals past it is no post's).
fn repeats(n: f64) -> usize {
    const MOST: f64 = 4096.0;
    if n > 0.0 { n.ceil().min(MOST) as usize } else { 0 }
}

/// The length JavaScript gives text (UTF-16 units).
fn js_len(s: &str) -> usize {
    if s.is_ascii() { s.len() } else { s.encode_utf16().count() }
}

/// The specifiers a format reads, by name ([`field`] numbers them).
const FIELDS: [&[u8]; 14] = [
    b"scale",
    b"offset",
    b"cyclicLimit",
    b"cyclicSign",
    b"decimals",
    b"trim",
    b"trimLeadZero",
    b"forceDecimal",
    b"zeropad",
    b"width",
    b"forceSign",
    b"decimalSymbol",
    b"prefix",
    b"suffix",
];
const SCALE: usize = 0;
const OFFSET: usize = 1;
const CYCLIC_LIMIT: usize = 2;
const CYCLIC_SIGN: usize = 3;
const DECIMALS: usize = 4;
const TRIM: usize = 5;
const TRIM_LEAD_ZERO: usize = 6;
const FORCE_DECIMAL: usize = 7;
const ZEROPAD: usize = 8;
const WIDTH: usize = 9;
const FORCE_SIGN: usize = 10;
const DECIMAL_SYMBOL: usize = 11;
const PREFIX: usize = 12;
const SUFFIX: usize = 13;

/// `__postc_formatNumber(spec, value)`: the text of `value` under the
/// specifiers of `spec` (the host's own object, its specifiers its own
/// properties), as the host's JavaScript computes it:
///
/// ```js
/// var v = value * spec.scale + spec.offset;
/// if (spec.cyclicLimit !== undefined && spec.cyclicLimit > 0) {
///   v = v % spec.cyclicLimit;
///   if (v < 0 && spec.cyclicSign >= 0) { v += spec.cyclicLimit; }
/// }
/// if (!(v - v == 0)) { return undefined; }
/// var factor = Math.pow(10, spec.decimals);
/// var units = Math.floor(Math.abs(v) * factor + 0.5);
/// var negative = v < 0 && units != 0;
/// var digits = String(units);  // then "0"s before it up to decimals + 1
/// ```
///
/// then the whole and fractional digits split at `decimals`, trailing
/// zeros trimmed (`trim`), the lead zero dropped (`trimLeadZero`), the
/// decimal symbol when a fraction follows or `forceDecimal`, zeros to
/// `width` (`zeropad`), the sign, spaces to `width` (no `zeropad`),
/// `prefix` and `suffix`. The offset and the cyclic limit are read as
/// numbers (JavaScript would join a text offset as text). `undefined` when
/// the scaled value is not a finite number.
pub(crate) fn format_number(spec: &Value, value: &Value, out: &mut String) -> Result<Value> {
    let Value::Object(o) = spec else {
        return Err(objects::type_error(format!(
            "cannot read property 'scale' of {}",
            if matches!(spec, Value::Null) { "null" } else { "undefined" }
        )));
    };
    let o = o.borrow();
    let mut f: [Option<&Value>; FIELDS.len()] = [None; FIELDS.len()];
    for (k, v) in o.keys.iter().zip(&o.values) {
        if let Some(i) = field(k.as_bytes()) {
            f[i] = Some(v);
        }
    }
    format_spec(&f, value, out)
}

/// The index in [`FIELDS`] of a specifier's name: the one candidate its
/// length and first byte leave, compared with that name's literal (every
/// key of every format is looked up on every call; a comparison with a
/// literal is a few word compares, with a name of [`FIELDS`] a call).
fn field(name: &[u8]) -> Option<usize> {
    Some(match (name.len(), *name.first()?) {
        (5, b's') if name == b"scale" => SCALE,
        (6, b'o') if name == b"offset" => OFFSET,
        (11, b'c') if name == b"cyclicLimit" => CYCLIC_LIMIT,
        (10, b'c') if name == b"cyclicSign" => CYCLIC_SIGN,
        (8, b'd') if name == b"decimals" => DECIMALS,
        (4, b't') if name == b"trim" => TRIM,
        (12, b't') if name == b"trimLeadZero" => TRIM_LEAD_ZERO,
        (12, b'f') if name == b"forceDecimal" => FORCE_DECIMAL,
        (7, b'z') if name == b"zeropad" => ZEROPAD,
        (5, b'w') if name == b"width" => WIDTH,
        (9, b'f') if name == b"forceSign" => FORCE_SIGN,
        (13, b'd') if name == b"decimalSymbol" => DECIMAL_SYMBOL,
        (6, b'p') if name == b"prefix" => PREFIX,
        (6, b's') if name == b"suffix" => SUFFIX,
        _ => return None,
    })
}

/// `Math.pow(10, decimals)`: exact for the whole numbers of decimals a
/// format has (every power of ten to 10^22 is a double).
fn power_of_ten(decimals: f64) -> f64 {
    const EXACT: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19,
        1e20, 1e21, 1e22,
    ];
    if (0.0..=22.0).contains(&decimals) && decimals == decimals.trunc() {
        EXACT[decimals as usize]
    } else {
        crate::js::math_pow(10.0, decimals)
    }
}

/// [`format_number`] of the specifiers read.
fn format_spec(f: &[Option<&Value>; FIELDS.len()], value: &Value, out: &mut String) -> Result<Value> {
    let mut v = number(Some(value)) * number(f[SCALE]) + number(f[OFFSET]);
    if f[CYCLIC_LIMIT].is_some_and(|l| !matches!(l, Value::Undefined)) {
        let limit = number(f[CYCLIC_LIMIT]);
        if limit > 0.0 {
            v %= limit;
            if v < 0.0 && number(f[CYCLIC_SIGN]) >= 0.0 {
                v += limit;
            }
        }
    }
    if !v.is_finite() {
        return Ok(Value::Undefined);
    }
    let decimals = number(f[DECIMALS]);
    let units = (v.abs() * power_of_ten(decimals) + 0.5).floor();
    let negative = v < 0.0 && units != 0.0;
    // `String(units)`, as `js::push_number` writes a number.
    let (mut whole_digits, mut ryu) = (itoa::Buffer::new(), ryu_js::Buffer::new());
    let digits: &str = if units == units.trunc() && units.abs() < 9_007_199_254_740_992.0 {
        whole_digits.format(units as i64)
    } else {
        ryu.format(units)
    };
    // `while (digits.length <= decimals) digits = "0" + digits`: `zeros`
    // zeros, then the digits.
    let zeros =
        if (digits.len() as f64) <= decimals { repeats(decimals.floor() - digits.len() as f64 + 1.0) } else { 0 };
    let len = zeros + digits.len();
    let at = |i: usize| if i < zeros { b'0' } else { digits.as_bytes()[i - zeros] };
    // Characters `from..to` of the zeros then the digits, appended whole
    // (the digits are ASCII: any index is a character's).
    let push = |out: &mut String, from: usize, to: usize| {
        for _ in from..to.min(zeros) {
            out.push('0');
        }
        if to > zeros {
            out.push_str(&digits[from.max(zeros) - zeros..to - zeros]);
        }
    };
    // `whole = digits.substring(0, len - decimals)`, `fraction` the rest.
    let split = clamp_index(len as f64 - decimals, len);
    let mut end = len;
    if truthy(f[TRIM]) {
        while end > split && at(end - 1) == b'0' {
            end -= 1;
        }
    }
    let has_fraction = end > split;
    let whole = if truthy(f[TRIM_LEAD_ZERO]) && split == 1 && at(0) == b'0' && has_fraction { 0 } else { split };
    let whole_start = split - whole;

    out.clear();
    push_string(out, f[PREFIX]);
    let start = out.len();
    push(out, whole_start, split);
    if has_fraction || truthy(f[FORCE_DECIMAL]) {
        push_string(out, f[DECIMAL_SYMBOL]);
    }
    if has_fraction {
        push(out, split, end);
    }
    let width = number(f[WIDTH]);
    let forced_sign = truthy(f[FORCE_SIGN]);
    let zeropad = truthy(f[ZEROPAD]);
    if zeropad && width > 0.0 {
        let sign = if negative || forced_sign { 1.0 } else { 0.0 };
        let pad = if has_fraction || truthy(f[FORCE_DECIMAL]) {
            width - sign - whole as f64
        } else {
            width - sign - js_len(&out[start..]) as f64
        };
        for _ in 0..repeats(pad) {
            out.insert(start, '0');
        }
    }
    if negative {
        out.insert(start, '-');
    } else if forced_sign {
        out.insert(start, '+');
    }
    if !zeropad && width > 0.0 {
        for _ in 0..repeats(width - js_len(&out[start..]) as f64) {
            out.insert(start, ' ');
        }
    }
    push_string(out, f[SUFFIX]);
    Ok(Value::Text(Text::new(out)))
}

/// How deep arrays in the words of a block nest (JavaScript's recursion
/// would overflow its stack on an array that holds itself).
const MAX_WORDS_DEPTH: u32 = 64;

/// `__postc_words(list, separator, start)`: the words of `list` from
/// `start` joined by `separator` (JavaScript's `join`: `undefined` joins
/// with `,`), as the host's JavaScript gathers them:
///
/// ```js
/// for (var i = start; i < list.length; ++i) {
///   var w = list[i];
///   if (w === undefined || w === null) { continue; }
///   if (typeof w == "object") { /* its items, the same way */ }
///   else { var t = String(w); if (t != "") { words.push(t); } }
/// }
/// ```
pub(crate) fn words(args: &[Value], protos: &Protos, out: &mut String) -> Result<Value> {
    let arg = |i: usize| args.get(i).unwrap_or(&Value::Undefined);
    let sep_start = {
        out.clear();
        match arg(1) {
            Value::Undefined => out.push(','),
            sep => push_string(out, Some(sep)),
        }
        out.len()
    };
    let start = number(Some(arg(2)));
    let start = if start.is_nan() { 0.0 } else { start };
    let mut first = true;
    walk(arg(0), start, sep_start, &mut first, 0, protos, out)?;
    let joined = &out[sep_start..];
    Ok(Value::Text(Text::new(joined)))
}

/// Appends the words of one list from index `from`; the separator is
/// `out[..sep]`.
fn walk(
    list: &Value,
    from: f64,
    sep: usize,
    first: &mut bool,
    depth: u32,
    protos: &Protos,
    out: &mut String,
) -> Result<()> {
    if depth > MAX_WORDS_DEPTH {
        return Err(Box::new(Diagnostic::error(
            "RT004",
            format!("the words of a block nest deeper than {MAX_WORDS_DEPTH} lists (a list that holds itself?)"),
        )));
    }
    match list {
        Value::Array(items) => {
            let items = items.borrow();
            let skip = clamp_index(from.ceil(), items.len());
            for w in &items[skip..] {
                word(w, sep, first, depth, protos, out)?;
            }
        }
        _ => {
            // `list.length` and `list[i]`, read along the prototype chain.
            let mut i = if from > 0.0 { from.ceil() } else { 0.0 };
            while i < number(Some(&objects::member(list, &Value::text("length"), protos)?)) {
                let w = objects::member(list, &Value::Num(i), protos)?;
                word(&w, sep, first, depth, protos, out)?;
                i += 1.0;
            }
        }
    }
    Ok(())
}

/// One item of a block's list: skipped, walked into, or a word.
fn word(w: &Value, sep: usize, first: &mut bool, depth: u32, protos: &Protos, out: &mut String) -> Result<()> {
    match w {
        Value::Undefined | Value::Null => Ok(()),
        // `typeof w == "object"`.
        Value::Array(_) | Value::Object(_) | Value::Regex(_) | Value::Output(_) => {
            walk(w, 0.0, sep, first, depth + 1, protos, out)
        }
        Value::Text(t) if t.is_empty() => Ok(()),
        _ => {
            let at = out.len();
            if !*first {
                out.extend_from_within(..sep);
            }
            let text_at = out.len();
            w.append_to(out);
            if out.len() == text_at {
                out.truncate(at);
            } else {
                *first = false;
            }
            Ok(())
        }
    }
}

/// `__postc_formatOutput(output, value, hostFormat, modal)`: what the
/// `format(value)` method of the host's output variable (`modal` false:
/// `createVariable`, `createOutputVariable`) or modal (`modal` true:
/// `createModal`) prints, when its format is one of the host's (its
/// `format` method is the function `hostFormat` is, and its specifiers its
/// `spec`):
///
/// ```js
/// if (!this.enabled) { return ""; }                  // a variable only
/// var text = this.formatter.format(value);           // a modal: a text value as it is
/// var changed = text !== this.last;
/// if (!changed && !this.force) { return ""; }
/// this.last = text;
/// this.current = value;
/// return this.prefix + text;                          // a modal: + this.suffix
/// ```
///
/// `undefined` (before changing anything) where the host's JavaScript
/// does more than this: another format, a value the format cannot write,
/// an `onchange` to call, `CONTROL_NONZERO`, a property the output lacks.
pub(crate) fn format_output(args: &[Value], hints: &OutputHints, out: &mut String) -> Result<Value> {
    let arg = |i: usize| args.get(i).unwrap_or(&Value::Undefined);
    let (Value::Object(output), Value::Func(reference)) = (arg(0), arg(2)) else { return Ok(Value::Undefined) };
    let modal = arg(3).truthy();
    let value = arg(1);
    let text = {
        let o = output.borrow();
        if !modal {
            match hints.get(&o, Out::Enabled) {
                Some(enabled) if !enabled.truthy() => return Ok(Value::text("")),
                Some(_) => {}
                None => return Ok(Value::Undefined),
            }
            if hints.get(&o, Out::Nonzero).is_none_or(Value::truthy) {
                return Ok(Value::Undefined);
            }
        }
        match (value, hints.get(&o, Out::Formatter)) {
            (Value::Text(t), _) if modal => Value::Text(t.clone()),
            (Value::Num(_), Some(Value::Object(format))) => {
                let format = format.borrow();
                let host =
                    matches!(hints.get(&format, Out::Format), Some(Value::Func(f)) if f.callee == reference.callee);
                match hints.get(&format, Out::Spec) {
                    Some(spec) if host => format_number(spec, value, out)?,
                    _ => return Ok(Value::Undefined),
                }
            }
            _ => return Ok(Value::Undefined),
        }
    };
    let Value::Text(text) = text else { return Ok(Value::Undefined) };
    let mut o = output.borrow_mut();
    let changed = !matches!(hints.get(&o, Out::Last), Some(Value::Text(last)) if *last == text);
    if !changed && !hints.get(&o, Out::Force).is_some_and(Value::truthy) {
        return Ok(Value::text(""));
    }
    if changed && !matches!(hints.get(&o, Out::Onchange), Some(Value::Undefined)) {
        return Ok(Value::Undefined);
    }
    let (Some(_), Some(_), Some(prefix)) =
        (hints.get(&o, Out::Last), hints.get(&o, Out::Current), hints.get(&o, Out::Prefix))
    else {
        return Ok(Value::Undefined);
    };
    out.clear();
    push_string(out, Some(prefix));
    text.push_to(out);
    if modal {
        match hints.get(&o, Out::Suffix) {
            Some(suffix) => push_string(out, Some(suffix)),
            None => return Ok(Value::Undefined),
        }
    }
    let printed = Value::Text(Text::new(out));
    hints.set(&mut o, Out::Last, Value::Text(text));
    hints.set(&mut o, Out::Current, value.clone());
    Ok(printed)
}

/// The inline caches of [`format_output`]: for each property it reads,
/// the index where it was found last ([`crate::value::Object::find_hinted`]).
#[derive(Default)]
pub(crate) struct OutputHints([std::cell::Cell<u32>; Out::COUNT]);

/// The properties [`format_output`] reads, of output variables and
/// formats, each with its inline cache in [`OutputHints`].
#[derive(Clone, Copy)]
enum Out {
    Enabled,
    Nonzero,
    Formatter,
    Format,
    Spec,
    Last,
    Force,
    Onchange,
    Current,
    Prefix,
    Suffix,
}

impl Out {
    const COUNT: usize = 11;

    /// The property's name, by its place in [`Out`].
    const NAMES: [&'static str; Out::COUNT] = [
        "enabled",
        "nonzero",
        "formatter",
        "format",
        "spec",
        "last",
        "force",
        "onchange",
        "current",
        "prefix",
        "suffix",
    ];

    #[inline(always)]
    fn name(self) -> &'static str {
        Out::NAMES[self as usize]
    }
}

impl OutputHints {
    /// The own property `p` of `o`.
    #[inline(always)]
    fn get<'o>(&self, o: &'o crate::value::Object, p: Out) -> Option<&'o Value> {
        o.find_hinted(p.name().as_bytes(), &self.0[p as usize]).map(|i| &o.values[i])
    }

    /// Sets the own property `p` of `o`.
    fn set(&self, o: &mut crate::value::Object, p: Out, v: Value) {
        match o.find_hinted(p.name().as_bytes(), &self.0[p as usize]) {
            Some(i) => o.values[i] = v,
            None => o.set(Text::new(p.name()), v),
        }
    }
}

/// `__postc_property(properties, name, otherwise)`, as the host's
/// JavaScript reads a property by name:
///
/// ```js
/// var p = properties[name];
/// if (p === undefined) { return otherwise; }
/// if (p !== null && typeof p == "object" && p.value !== undefined) { return p.value; }
/// return p;
/// ```
pub(crate) fn property(args: &[Value], protos: &Protos) -> Result<Value> {
    let arg = |i: usize| args.get(i).unwrap_or(&Value::Undefined);
    let p = objects::member(arg(0), arg(1), protos)?;
    match &p {
        Value::Undefined => Ok(arg(2).clone()),
        Value::Object(_) | Value::Array(_) | Value::Regex(_) | Value::Output(_) => {
            match objects::member(&p, &Value::text("value"), protos)? {
                Value::Undefined => Ok(p),
                value => Ok(value),
            }
        }
        _ => Ok(p),
    }
}
