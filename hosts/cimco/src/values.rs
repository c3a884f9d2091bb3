//! JavaScript values inside Rhai: numbers are Rhai floats, text Rhai
//! strings, `undefined` Rhai's `()`, and the rest host types with
//! JavaScript's reference semantics: [`JsObj`] (objects and functions),
//! [`JsArr`], [`JsNull`], and references to the post's output variables
//! and formats. Conversions follow ECMAScript 5: `ToString`, `ToNumber`,
//! truthiness, `==`, `===`, `+` and the relational operators.

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Dynamic, FnPtr, ImmutableString};

use postc_runtime::js;
use postc_runtime::number::NumberWriter;
use postc_runtime::value::Value;

/// `null`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JsNull;

/// An object (or a function: objects with a callable body).
#[derive(Clone, Debug)]
pub struct JsObj(pub Rc<RefCell<ObjData>>);

#[derive(Debug, Default)]
pub struct ObjData {
    /// Properties in the order they were added.
    pub props: Vec<(ImmutableString, Dynamic)>,
    pub proto: Option<JsObj>,
    pub kind: ObjKind,
}

/// What kind of object it is.
#[derive(Debug, Default)]
pub enum ObjKind {
    #[default]
    Plain,
    /// A function: a Rhai function pointer (a script function or a closure).
    Function(FnPtr),
    /// A host function by name (`parseInt` used as a value).
    Host(String),
    /// `Math`.
    Math,
}

impl JsObj {
    pub fn new(kind: ObjKind) -> JsObj {
        JsObj(Rc::new(RefCell::new(ObjData { props: Vec::new(), proto: None, kind })))
    }

    /// Own or inherited property.
    pub fn get(&self, key: &str) -> Option<Dynamic> {
        let mut cur = Some(self.clone());
        let mut depth = 0;
        while let Some(o) = cur {
            let data = o.0.borrow();
            if let Some((_, v)) = data.props.iter().find(|(k, _)| k.as_str() == key) {
                return Some(v.clone());
            }
            cur = data.proto.clone();
            depth += 1;
            if depth > 64 {
                break;
            }
        }
        None
    }

    pub fn set(&self, key: &str, value: Dynamic) {
        let mut data = self.0.borrow_mut();
        match data.props.iter_mut().find(|(k, _)| k.as_str() == key) {
            Some((_, v)) => *v = value,
            None => data.props.push((key.into(), value)),
        }
    }

    pub fn function(&self) -> Option<FnPtr> {
        match &self.0.borrow().kind {
            ObjKind::Function(f) => Some(f.clone()),
            _ => None,
        }
    }
}

/// An array.
#[derive(Clone, Debug, Default)]
pub struct JsArr(pub Rc<RefCell<Vec<Dynamic>>>);

impl JsArr {
    pub fn new(items: Vec<Dynamic>) -> JsArr {
        JsArr(Rc::new(RefCell::new(items)))
    }
}

/// An output variable bound at compile time (`xOutput`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VarRef(pub u16);

/// A format bound at compile time (`xyzFormat`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FmtRef(pub u16);

/// A format made while the post runs.
#[derive(Clone, Debug)]
pub struct DynFormat(pub Rc<NumberWriter>);

/// An output variable made while the post runs.
#[derive(Clone, Debug)]
pub struct DynVar(pub Rc<RefCell<DynVarState>>);

#[derive(Debug)]
pub struct DynVarState {
    pub writer: Rc<NumberWriter>,
    pub prefix: String,
    pub force: bool,
    /// The text printed last, and the modal epoch it was printed in.
    pub last_text: Option<(String, u64)>,
    pub last_value: f64,
}

/// A regular expression literal.
#[derive(Clone, Debug)]
pub struct JsRegex(pub Rc<postc_runtime::regex::RegExp>);

pub fn is_null(v: &Dynamic) -> bool {
    v.is::<JsNull>()
}

/// A Rhai value from an interpreter value.
pub fn from_value(v: &Value) -> Dynamic {
    match v {
        Value::Null | Value::Undefined => Dynamic::UNIT,
        // Native arrays, objects and functions stay in native code: no
        // function that holds one runs as a script.
        Value::Array(_) | Value::Object(_) | Value::Func(_) | Value::Output(_) => Dynamic::UNIT,
        Value::Regex(r) => Dynamic::from(JsRegex(r.clone())),
        Value::Num(n) => Dynamic::from_float(*n),
        Value::Bool(b) => Dynamic::from_bool(*b),
        Value::Text(s) => Dynamic::from(ImmutableString::from(&**s)),
    }
}

/// An interpreter value from a Rhai value: `()` is JavaScript's
/// `undefined`, as native code holds it; objects become nothing, as the
/// native side never reads them.
pub fn to_value(v: &Dynamic) -> Option<Value> {
    if v.is_unit() {
        return Some(Value::Undefined);
    }
    if is_null(v) {
        return Some(Value::Null);
    }
    if let Some(n) = v.clone().try_cast::<f64>() {
        return Some(Value::Num(n));
    }
    if let Some(i) = v.clone().try_cast::<i64>() {
        return Some(Value::Num(i as f64));
    }
    if let Some(b) = v.clone().try_cast::<bool>() {
        return Some(Value::Bool(b));
    }
    if let Some(s) = v.clone().try_cast::<ImmutableString>() {
        return Some(Value::text(&s));
    }
    if let Some(r) = v.clone().try_cast::<JsRegex>() {
        return Some(Value::Regex(r.0));
    }
    None
}

/// ToNumber.
pub fn to_number(v: &Dynamic) -> f64 {
    if v.is::<JsArr>() {
        return js::text_to_number(&to_string(v));
    }
    with_primitive(v, |p| p.map_or(f64::NAN, js::Primitive::to_number))
}

/// ToString.
pub fn to_string(v: &Dynamic) -> String {
    let mut s = String::new();
    push_string(&mut s, v, 0);
    s
}

fn push_string(out: &mut String, v: &Dynamic, depth: usize) {
    if let Some(s) = v.clone().try_cast::<ImmutableString>() {
        out.push_str(&s);
    } else if let Some(crate::ops::HostError(s)) = v.clone().try_cast::<crate::ops::HostError>() {
        out.push_str(&s);
    } else if let Some(n) = v.clone().try_cast::<f64>() {
        js::push_number(out, n);
    } else if let Some(i) = v.clone().try_cast::<i64>() {
        js::push_number(out, i as f64);
    } else if let Some(b) = v.clone().try_cast::<bool>() {
        out.push_str(if b { "true" } else { "false" });
    } else if v.is_unit() {
        out.push_str("undefined");
    } else if is_null(v) {
        out.push_str("null");
    } else if let Some(a) = v.clone().try_cast::<JsArr>() {
        if depth > 16 {
            return;
        }
        for (i, item) in a.0.borrow().iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            if !item.is_unit() && !is_null(item) {
                push_string(out, item, depth + 1);
            }
        }
    } else if let Some(o) = v.clone().try_cast::<JsObj>() {
        let text = match &o.0.borrow().kind {
            ObjKind::Plain => "[object Object]",
            ObjKind::Math => "[object Math]",
            ObjKind::Function(_) | ObjKind::Host(_) => "function () { [native code] }",
        };
        out.push_str(text);
    } else if let Some(r) = v.clone().try_cast::<JsRegex>() {
        out.push_str(&r.0.0.to_text());
    } else {
        out.push_str("[object Object]");
    }
}

/// Truthiness.
pub fn truthy(v: &Dynamic) -> bool {
    // Every object is true.
    with_primitive(v, |p| p.is_none_or(js::Primitive::truthy))
}

/// `typeof`.
pub fn type_of(v: &Dynamic) -> &'static str {
    if v.is::<f64>() || v.is::<i64>() {
        "number"
    } else if v.is::<ImmutableString>() {
        "string"
    } else if v.is::<bool>() {
        "boolean"
    } else if v.is_unit() {
        "undefined"
    } else if let Some(o) = v.clone().try_cast::<JsObj>() {
        match &o.0.borrow().kind {
            ObjKind::Function(_) | ObjKind::Host(_) => "function",
            _ => "object",
        }
    } else if v.is::<FnPtr>() {
        "function"
    } else {
        "object"
    }
}

fn is_primitive(v: &Dynamic) -> bool {
    v.is::<f64>() || v.is::<i64>() || v.is::<ImmutableString>() || v.is::<bool>() || v.is_unit() || is_null(v)
}

/// Whether two values are the same object.
fn same_object(a: &Dynamic, b: &Dynamic) -> bool {
    if let (Some(x), Some(y)) = (a.clone().try_cast::<JsObj>(), b.clone().try_cast::<JsObj>()) {
        return Rc::ptr_eq(&x.0, &y.0);
    }
    if let (Some(x), Some(y)) = (a.clone().try_cast::<JsArr>(), b.clone().try_cast::<JsArr>()) {
        return Rc::ptr_eq(&x.0, &y.0);
    }
    if let (Some(x), Some(y)) = (a.clone().try_cast::<JsRegex>(), b.clone().try_cast::<JsRegex>()) {
        return Rc::ptr_eq(&x.0, &y.0);
    }
    if let (Some(x), Some(y)) = (a.clone().try_cast::<VarRef>(), b.clone().try_cast::<VarRef>()) {
        return x == y;
    }
    if let (Some(x), Some(y)) = (a.clone().try_cast::<FmtRef>(), b.clone().try_cast::<FmtRef>()) {
        return x == y;
    }
    false
}

/// `===`: two primitives as [`js::strict_equals`] says, two objects by
/// identity.
pub fn strict_eq(a: &Dynamic, b: &Dynamic) -> bool {
    let primitives = with_primitive(a, |x| {
        with_primitive(b, |y| match (x, y) {
            (Some(x), Some(y)) => Some(js::strict_equals(x, y)),
            (None, None) => None,
            _ => Some(false),
        })
    });
    primitives.unwrap_or_else(|| same_object(a, b))
}

/// The primitive a value is, for [`js`]'s operators, handed to `f`;
/// `None` for an object, an array, a function or a regular expression.
fn with_primitive<R>(v: &Dynamic, f: impl FnOnce(Option<js::Primitive<'_>>) -> R) -> R {
    use js::Primitive;
    if let Some(s) = v.clone().try_cast::<ImmutableString>() {
        return f(Some(Primitive::Text(s.as_str())));
    }
    let p = if let Some(n) = v.clone().try_cast::<f64>() {
        Some(Primitive::Number(n))
    } else if let Some(i) = v.clone().try_cast::<i64>() {
        Some(Primitive::Number(i as f64))
    } else if let Some(b) = v.clone().try_cast::<bool>() {
        Some(Primitive::Bool(b))
    } else if v.is_unit() {
        Some(Primitive::Undefined)
    } else if is_null(v) {
        Some(Primitive::Null)
    } else {
        None
    };
    f(p)
}

/// `==`: two primitives as [`js::loose_equals`] says, two objects by
/// identity, an object against a primitive by its text.
pub fn loose_eq(a: &Dynamic, b: &Dynamic) -> bool {
    let primitives = with_primitive(a, |x| with_primitive(b, |y| x.zip(y).map(|(x, y)| js::loose_equals(x, y))));
    if let Some(equal) = primitives {
        return equal;
    }
    if !is_primitive(a) && !is_primitive(b) {
        return same_object(a, b);
    }
    // An object against null or undefined is unequal; against another
    // primitive it compares its text.
    let (obj, prim) = if is_primitive(a) { (b, a) } else { (a, b) };
    if prim.is_unit() || is_null(prim) {
        return false;
    }
    let text = Dynamic::from(ImmutableString::from(to_string(obj)));
    loose_eq(&text, prim)
}

/// `+`.
pub fn add(a: &Dynamic, b: &Dynamic) -> Dynamic {
    if let (Some(x), Some(y)) = (a.clone().try_cast::<f64>(), b.clone().try_cast::<f64>()) {
        return Dynamic::from_float(x + y);
    }
    let texty = |v: &Dynamic| !is_primitive(v) || v.is::<ImmutableString>();
    if texty(a) || texty(b) {
        let mut s = to_string(a);
        s.push_str(&to_string(b));
        return Dynamic::from(ImmutableString::from(s));
    }
    Dynamic::from_float(to_number(a) + to_number(b))
}

/// `<` and friends: `Some(ordering)` or `None` when NaN is involved.
pub fn compare(a: &Dynamic, b: &Dynamic) -> Option<std::cmp::Ordering> {
    let prim = |v: &Dynamic| {
        if is_primitive(v) { v.clone() } else { Dynamic::from(ImmutableString::from(to_string(v))) }
    };
    let (a, b) = (prim(a), prim(b));
    if let (Some(x), Some(y)) = (a.clone().try_cast::<ImmutableString>(), b.clone().try_cast::<ImmutableString>()) {
        return Some(js::compare_text(x.as_str(), y.as_str()));
    }
    to_number(&a).partial_cmp(&to_number(&b))
}

/// A number as a Rhai value.
pub fn num(n: f64) -> Dynamic {
    Dynamic::from_float(n)
}

/// Text as a Rhai value.
pub fn text(s: impl Into<ImmutableString>) -> Dynamic {
    Dynamic::from(s.into())
}
