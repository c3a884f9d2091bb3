//! Values of the IR's statement language: numbers, text, booleans, null
//! and undefined, and JavaScript's arrays, objects and functions.
//!
//! Text is kept in the value itself when it is short ASCII ([`Text`]): the
//! words a post formats (`X12.5`, `G1`, `F1500`) cost no allocation, and a
//! value is 24 bytes either way. Longer text is shared ([`Rc<str>`]).
//! Arrays and objects are shared and mutable, as in JavaScript: a value
//! copied refers to the same array.
//!
//! Objects carry JavaScript's prototype link ([`Proto`]) and functions
//! their own properties, `prototype` among them ([`Closure::props`]); the
//! interpreter's `objects` module walks the chain.

use std::cell::{OnceCell, RefCell};
use std::rc::Rc;

use postc_ir::{FunctionId, OutputRef};

use crate::js::ProtoKind;

/// A value computed by a post's code.
#[derive(Clone, Debug, Default)]
pub enum Value {
    #[default]
    Null,
    /// JavaScript's `undefined`.
    Undefined,
    Num(f64),
    Bool(bool),
    Text(Text),
    /// A JavaScript array.
    Array(Rc<RefCell<Vec<Value>>>),
    /// A JavaScript object: its properties in the order they were made.
    Object(Rc<RefCell<Object>>),
    /// A post function as a value, with the values it closes over.
    Func(Rc<Closure>),
    /// A format or an output variable of the post as a value.
    Output(OutputRef),
    /// A JavaScript regular expression: one evaluation of a literal, with
    /// its own identity, sharing the pattern compiled once
    /// ([`crate::regex`]).
    Regex(Rc<crate::regex::RegExp>),
}

impl PartialEq for Value {
    /// Primitives by value; arrays, objects and functions by identity (as
    /// JavaScript's `===` compares them).
    fn eq(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Null, Value::Null) | (Value::Undefined, Value::Undefined) => true,
            (Value::Num(a), Value::Num(b)) => a == b,
            (Value::Bool(a), Value::Bool(b)) => a == b,
            (Value::Text(a), Value::Text(b)) => a == b,
            (Value::Array(a), Value::Array(b)) => Rc::ptr_eq(a, b),
            (Value::Object(a), Value::Object(b)) => Rc::ptr_eq(a, b),
            (Value::Func(a), Value::Func(b)) => Rc::ptr_eq(a, b),
            (Value::Output(a), Value::Output(b)) => a == b,
            (Value::Regex(a), Value::Regex(b)) => Rc::ptr_eq(a, b),
            _ => false,
        }
    }
}

/// The properties of a JavaScript object, in the order they were made.
/// Post objects are small (a handful of keys): a property is found by a
/// scan of the keys, compared as bytes. A property the object does not
/// have is looked for along its prototype chain ([`Proto`]).
#[derive(Clone, Debug, Default)]
pub struct Object {
    pub keys: Vec<Text>,
    pub values: Vec<Value>,
    /// Where a property the object does not have is looked for next.
    pub proto: Proto,
    /// The built-in prototype this object is (`Array.prototype`, ...):
    /// it answers the built-in methods of values of that kind.
    pub builtin: Option<ProtoKind>,
    /// Its `constructor` is not enumerable: the object is a function's
    /// first `prototype`, made by the engine (`for ... in` skips it, as
    /// JavaScript does).
    pub hidden_constructor: bool,
}

/// The prototype of an object.
#[derive(Clone, Debug, Default)]
pub enum Proto {
    /// `Object.prototype`: what an object literal has. The engine holds
    /// that object (with the methods a post adds to it) and makes it when
    /// it is first needed.
    #[default]
    Object,
    /// None: `Object.create(null)`, and `Object.prototype` itself.
    Null,
    /// Another object: `Object.create(p)`, `new F()` with `F.prototype`.
    Of(Rc<RefCell<Object>>),
}

/// A chain of prototypes is at most this many objects long (JavaScript
/// sets no bound; a post's classes are a few levels deep). The bound
/// keeps every walk along a chain, and dropping one, short.
pub const MAX_PROTO_CHAIN: usize = 1024;

impl Proto {
    /// How many objects the chain from this prototype has, up to and
    /// including `Object.prototype` (0 for none).
    pub fn depth(&self) -> usize {
        match self {
            Proto::Null => 0,
            Proto::Object => 1,
            Proto::Of(p) => {
                let mut n = 1;
                let mut next = p.borrow().proto.clone();
                while let Proto::Of(q) = &next {
                    n += 1;
                    if n > MAX_PROTO_CHAIN {
                        break;
                    }
                    let after = q.borrow().proto.clone();
                    next = after;
                }
                n + usize::from(matches!(next, Proto::Object))
            }
        }
    }
}

impl Object {
    /// The index of a property.
    #[inline]
    pub fn find(&self, key: &[u8]) -> Option<usize> {
        self.keys.iter().position(|k| k.as_bytes() == key)
    }

    /// [`Self::find`], first trying the index `hint` holds (a site's
    /// inline cache, `crate::exec::Text`), which it sets to where the key
    /// is found.
    #[inline]
    pub fn find_hinted(&self, key: &[u8], hint: &std::cell::Cell<u32>) -> Option<usize> {
        let h = hint.get() as usize;
        if self.keys.get(h).is_some_and(|k| k.as_bytes() == key) {
            return Some(h);
        }
        let i = self.find(key)?;
        hint.set(u32::try_from(i).unwrap_or(0));
        Some(i)
    }

    pub fn get(&self, key: &[u8]) -> Option<&Value> {
        self.find(key).map(|i| &self.values[i])
    }

    /// [`Self::set`] through a site's inline cache ([`Self::find_hinted`]);
    /// a property added last leaves its index there.
    #[inline]
    pub fn set_hinted(&mut self, key: &Text, value: Value, hint: &std::cell::Cell<u32>) {
        match self.find_hinted(key.as_bytes(), hint) {
            Some(i) => self.values[i] = value,
            None => {
                hint.set(u32::try_from(self.keys.len()).unwrap_or(0));
                self.keys.push(key.clone());
                self.values.push(value);
            }
        }
    }

    /// Sets a property, adding it last when it is new.
    pub fn set(&mut self, key: Text, value: Value) {
        match self.find(key.as_bytes()) {
            Some(i) => self.values[i] = value,
            None => {
                self.keys.push(key);
                self.values.push(value);
            }
        }
    }
}

/// Arrays in arrays are written as text to this depth.
const MAX_NESTED_TEXT: u32 = 64;

/// A function value: the post function and the values it captured, or
/// a built-in method held as a value (`Array.prototype.slice`).
#[derive(Debug)]
pub struct Closure {
    pub callee: Callee,
    pub captures: Vec<Value>,
    /// The function's own properties (`prototype`, and what the post sets
    /// on it), made when first needed. A post function's first
    /// `prototype` is `{constructor: f}`.
    pub props: OnceCell<Rc<RefCell<Object>>>,
}

/// What a function value runs.
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    /// A function of the post.
    Post(FunctionId),
    /// The built-in method `name` of values of `kind`, run on the `this`
    /// it is called with (`Object.prototype.toString.call(x)`).
    Method(ProtoKind, Text),
}

impl Closure {
    /// A function value of the post with its captures.
    pub fn post(function: FunctionId, captures: Vec<Value>) -> Closure {
        Closure { callee: Callee::Post(function), captures, props: OnceCell::new() }
    }
}

impl Value {
    pub fn array(items: Vec<Value>) -> Value {
        Value::Array(Rc::new(RefCell::new(items)))
    }

    pub fn object(object: Object) -> Value {
        Value::Object(Rc::new(RefCell::new(object)))
    }
}

/// How many bytes of ASCII text a [`Text`] holds in place.
pub const INLINE_TEXT: usize = 22;

/// The text of a value: short ASCII text in place, other text shared.
#[derive(Clone)]
pub struct Text(Repr);

#[derive(Clone)]
#[doc(hidden)]
pub enum Repr {
    /// `len` bytes of ASCII.
    Inline(u8, [u8; INLINE_TEXT]),
    Shared(Rc<str>),
}

impl Text {
    /// How the text is held: in place or shared (for tests).
    #[doc(hidden)]
    pub fn repr(&self) -> &Repr {
        &self.0
    }

    /// The text of `s`, always shared: a name read as `str` at every use
    /// (a method's), which text kept in place would check is UTF-8 each
    /// time.
    pub fn shared(s: &str) -> Text {
        Text(Repr::Shared(Rc::from(s)))
    }

    /// The text of `s`.
    pub fn new(s: &str) -> Text {
        match Text::inline(s.as_bytes()) {
            Some(t) => t,
            None => Text(Repr::Shared(Rc::from(s))),
        }
    }

    /// Bytes as text (replacing what is not UTF-8).
    pub fn from_bytes(b: &[u8]) -> Text {
        match Text::inline(b) {
            Some(t) => t,
            None => match std::str::from_utf8(b) {
                Ok(s) => Text(Repr::Shared(Rc::from(s))),
                Err(_) => Text(Repr::Shared(Rc::from(String::from_utf8_lossy(b).as_ref()))),
            },
        }
    }

    /// The text of the first `len` bytes of `padded`: the whole array is
    /// kept when they are ASCII (what follows them is never read). Its
    /// one caller gives `len <= INLINE_TEXT`; past it, the whole array is
    /// taken.
    #[inline]
    pub fn from_padded(padded: &[u8; INLINE_TEXT], len: usize) -> Text {
        match padded.get(..len) {
            Some(b) if b.is_ascii() => Text(Repr::Inline(len as u8, *padded)),
            Some(b) => Text::from_bytes(b),
            None => Text::from_bytes(padded),
        }
    }

    /// `x` then `y` as one text kept in place, when both are kept in place
    /// and their sum fits: both are ASCII, so their sum is, with no check.
    #[inline]
    pub fn joined_inline(x: &Text, y: &Text) -> Option<Text> {
        let (Repr::Inline(xl, xb), Repr::Inline(yl, yb)) = (&x.0, &y.0) else { return None };
        let (xl, yl) = (*xl as usize, *yl as usize);
        let n = xl + yl;
        if n > INLINE_TEXT {
            return None;
        }
        let mut bytes = *xb;
        bytes[xl..n].copy_from_slice(&yb[..yl]);
        Some(Text(Repr::Inline(n as u8, bytes)))
    }

    fn inline(b: &[u8]) -> Option<Text> {
        if b.len() > INLINE_TEXT || !b.is_ascii() {
            return None;
        }
        let mut bytes = [0u8; INLINE_TEXT];
        bytes[..b.len()].copy_from_slice(b);
        Some(Text(Repr::Inline(b.len() as u8, bytes)))
    }

    pub fn as_bytes(&self) -> &[u8] {
        match &self.0 {
            Repr::Inline(len, bytes) => &bytes[..*len as usize],
            Repr::Shared(s) => s.as_bytes(),
        }
    }

    /// The bytes of ASCII text; `None` for other text. Short text answers
    /// at once (it is kept in place only when ASCII).
    #[inline]
    pub fn ascii_bytes(&self) -> Option<&[u8]> {
        match &self.0 {
            Repr::Inline(len, bytes) => Some(&bytes[..*len as usize]),
            Repr::Shared(s) => s.is_ascii().then_some(s.as_bytes()),
        }
    }

    /// Appends the text to `out`. Text kept in place is ASCII: viewed as
    /// `str` (the check of a few ASCII bytes costs less than pushing them
    /// one character at a time, each with its own room check) and copied.
    #[inline]
    pub fn push_to(&self, out: &mut String) {
        out.push_str(self.as_str());
    }

    /// Appends the text's bytes to `out`. Text kept in place is copied
    /// whole (a fixed-size copy, no `memcpy` call) and the tail cut off:
    /// the words of a block are appended this way.
    #[inline(always)]
    pub fn append_to_bytes(&self, out: &mut Vec<u8>) {
        match &self.0 {
            Repr::Inline(len, bytes) => {
                let end = out.len() + *len as usize;
                out.extend_from_slice(bytes);
                out.truncate(end);
            }
            Repr::Shared(s) => out.extend_from_slice(s.as_bytes()),
        }
    }

    pub fn as_str(&self) -> &str {
        match &self.0 {
            // ASCII: always UTF-8.
            Repr::Inline(len, bytes) => std::str::from_utf8(&bytes[..*len as usize]).unwrap_or_default(),
            Repr::Shared(s) => s,
        }
    }

    pub fn len(&self) -> usize {
        match &self.0 {
            Repr::Inline(len, _) => *len as usize,
            Repr::Shared(s) => s.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl std::ops::Deref for Text {
    type Target = str;
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl PartialEq for Text {
    fn eq(&self, other: &Text) -> bool {
        self.as_bytes() == other.as_bytes()
    }
}

impl Eq for Text {}

impl PartialOrd for Text {
    fn partial_cmp(&self, other: &Text) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Text {
    /// JavaScript's order of texts ([`crate::js::compare_text`]): text kept
    /// in place is ASCII, whose bytes compare as its UTF-16 units do.
    fn cmp(&self, other: &Text) -> std::cmp::Ordering {
        match (&self.0, &other.0) {
            (Repr::Shared(a), Repr::Shared(b)) => crate::js::compare_text(a, b),
            _ => self.as_bytes().cmp(other.as_bytes()),
        }
    }
}

impl std::fmt::Debug for Text {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(self.as_str(), f)
    }
}

impl std::fmt::Display for Text {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl From<&str> for Text {
    fn from(s: &str) -> Text {
        Text::new(s)
    }
}

impl From<String> for Text {
    fn from(s: String) -> Text {
        match Text::inline(s.as_bytes()) {
            Some(t) => t,
            None => Text(Repr::Shared(Rc::from(s))),
        }
    }
}

impl From<Rc<str>> for Text {
    fn from(s: Rc<str>) -> Text {
        Text(Repr::Shared(s))
    }
}

impl Value {
    pub fn text(s: &str) -> Value {
        Value::Text(Text::new(s))
    }

    /// The value as a number: text that reads as a number gives it, other
    /// text and null give 0, true gives 1.
    #[inline]
    pub fn num(&self) -> f64 {
        match self {
            Value::Num(n) => *n,
            other => other.num_other(),
        }
    }

    fn num_other(&self) -> f64 {
        match self {
            Value::Num(n) => *n,
            Value::Bool(b) => f64::from(u8::from(*b)),
            Value::Text(s) => s.as_str().trim().parse().unwrap_or(0.0),
            Value::Null => 0.0,
            Value::Undefined
            | Value::Array(_)
            | Value::Object(_)
            | Value::Func(_)
            | Value::Output(_)
            | Value::Regex(_) => f64::NAN,
        }
    }

    /// The primitive the value is, for [`crate::js`]'s operators; `None`
    /// for an array, object, function or regular expression, which the
    /// operators make primitive first.
    pub fn primitive(&self) -> Option<crate::js::Primitive<'_>> {
        use crate::js::Primitive;
        Some(match self {
            Value::Num(n) => Primitive::Number(*n),
            Value::Text(t) => Primitive::Text(t.as_str()),
            Value::Bool(b) => Primitive::Bool(*b),
            Value::Null => Primitive::Null,
            Value::Undefined => Primitive::Undefined,
            _ => return None,
        })
    }

    /// Lets the value go where it is, with no call to drop it: nothing to
    /// do when it owns nothing (a number, a boolean, null, undefined, a
    /// format, short text kept in place), else the one reference it holds
    /// given up in place. For the interpreter's
    /// hottest places, where most values let go are numbers, short words
    /// and arrays or objects still held elsewhere.
    #[inline(always)]
    pub fn let_go(self) {
        match self {
            Value::Text(Text(Repr::Shared(s))) => drop(s),
            Value::Array(a) => drop(a),
            Value::Object(o) => drop(o),
            Value::Func(f) => drop(f),
            Value::Regex(r) => drop(r),
            Value::Null
            | Value::Undefined
            | Value::Num(_)
            | Value::Bool(_)
            | Value::Output(_)
            | Value::Text(Text(Repr::Inline(..))) => {}
        }
    }

    /// Truthiness: non-zero numbers, non-empty text, true, and every
    /// array, object, function and regular expression.
    pub fn truthy(&self) -> bool {
        match self {
            Value::Num(n) => *n != 0.0 && !n.is_nan(),
            Value::Bool(b) => *b,
            Value::Text(s) => !s.is_empty(),
            Value::Null | Value::Undefined => false,
            Value::Array(_) | Value::Object(_) | Value::Func(_) | Value::Output(_) | Value::Regex(_) => true,
        }
    }

    /// Appends the value as text: numbers in their shortest form without a
    /// trailing `.0`; null as nothing (BASIC's empty value); `undefined`,
    /// arrays (their items joined by commas), objects and functions as
    /// JavaScript's `String()` writes them (a regular expression as
    /// `/source/flags`).
    pub fn append_to(&self, out: &mut String) {
        self.append_nested(out, 0);
    }

    /// [`Value::append_to`] at a depth of arrays in arrays: an array that
    /// holds itself (JavaScript writes nothing for the cycle) stops there.
    fn append_nested(&self, out: &mut String, depth: u32) {
        match self {
            // As JavaScript writes it: `Infinity`, `1e+21`, `1e-7`.
            Value::Num(n) => crate::js::push_number(out, *n),
            Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
            Value::Text(s) => s.push_to(out),
            Value::Null => {}
            Value::Undefined => out.push_str("undefined"),
            Value::Array(_) if depth > MAX_NESTED_TEXT => {}
            Value::Array(items) => {
                for (i, item) in items.borrow().iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    // JavaScript's join writes null and undefined as nothing.
                    if !matches!(item, Value::Null | Value::Undefined) {
                        item.append_nested(out, depth + 1);
                    }
                }
            }
            Value::Object(_) | Value::Output(_) => out.push_str("[object Object]"),
            Value::Func(_) => out.push_str("function () { [native code] }"),
            Value::Regex(r) => out.push_str(&r.0.to_text()),
        }
    }

    /// [`Value::append_to`] as JavaScript's ToString writes a primitive
    /// operand of `+`: null as `null` (an array's items, and null in the
    /// other dialects, write nothing).
    pub fn append_js(&self, out: &mut String) {
        match self {
            Value::Null => out.push_str("null"),
            other => other.append_to(out),
        }
    }

    pub fn to_text(&self) -> Text {
        match self {
            Value::Text(s) => s.clone(),
            other => {
                let mut s = String::new();
                other.append_to(&mut s);
                Text::from(s)
            }
        }
    }
}
