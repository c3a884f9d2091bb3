//! JavaScript's prototypes in the interpreter: the built-in prototypes of
//! a run (`Object.prototype`, `Array.prototype`, `String.prototype`, ...),
//! a function's `prototype`, and the walk along an object's chain.
//!
//! A property read that misses an object's own properties follows its
//! [`Proto`] link: objects made by `Object.create(p)` or `new F()` (with
//! `F.prototype`) to that object, and so on, until `Object.prototype`. A
//! value that is not an object starts at the built-in prototype of its
//! kind. At a built-in prototype, the built-in methods postc runs come
//! first ([`has_method`]), then what the post added to that prototype
//! (`String.prototype.f = ...`), then `Object.prototype`'s. Writes go to
//! the object itself. Chains are made only when an object is made, never
//! changed after, so they hold no cycle; their length is bounded
//! ([`MAX_PROTO_CHAIN`]) all the same, and every walk stops there.
//!
//! The built-in prototypes are made when a post first reaches one, so a
//! post that never names a prototype costs a look at an empty cell on a
//! missed property, nothing more.

use std::cell::{OnceCell, RefCell};
use std::rc::Rc;

use postc_ir::Diagnostic;

use super::Result;
use super::objects::type_error;
use crate::js::{self, ProtoKind};
use crate::value::{Callee, Closure, MAX_PROTO_CHAIN, Object, Proto, Text, Value};

/// The built-in prototypes of one run, each made when first needed.
#[derive(Default)]
pub(crate) struct Protos([OnceCell<Rc<RefCell<Object>>>; ProtoKind::ALL.len()]);

impl Protos {
    /// The built-in prototype of `kind`, made now if it is not yet: its
    /// prototype is `Object.prototype` (which has none).
    pub(crate) fn get(&self, kind: ProtoKind) -> &Rc<RefCell<Object>> {
        self.0[kind as usize].get_or_init(|| {
            let proto = if kind == ProtoKind::Object { Proto::Null } else { Proto::Object };
            Rc::new(RefCell::new(Object { proto, builtin: Some(kind), ..Object::default() }))
        })
    }

    /// The built-in prototype of `kind`, if the post has reached it.
    fn made(&self, kind: ProtoKind) -> Option<&Rc<RefCell<Object>>> {
        self.0[kind as usize].get()
    }
}

/// Where a property was found along a chain.
pub(crate) enum Found {
    /// A property's value.
    Value(Value),
    /// A built-in method of values of this kind.
    Method(ProtoKind),
}

impl Found {
    /// The property as a value: a built-in method as a function value.
    pub(crate) fn into_value(self, name: &Text) -> Value {
        match self {
            Found::Value(v) => v,
            Found::Method(kind) => Value::Func(Rc::new(Closure {
                callee: Callee::Method(kind, name.clone()),
                captures: Vec::new(),
                props: OnceCell::new(),
            })),
        }
    }
}

/// The built-in methods postc runs on values of each kind (the
/// interpreter's `invoke` dispatches on the same names).
pub(crate) fn has_method(kind: ProtoKind, name: &[u8]) -> bool {
    match kind {
        ProtoKind::Object => matches!(name, b"hasOwnProperty" | b"isPrototypeOf" | b"toString" | b"valueOf"),
        ProtoKind::Array => super::objects::ArrayMethod::of(name).is_some(),
        ProtoKind::String => matches!(
            name,
            b"substring"
                | b"substr"
                | b"slice"
                | b"charAt"
                | b"charCodeAt"
                | b"indexOf"
                | b"lastIndexOf"
                | b"toUpperCase"
                | b"toLocaleUpperCase"
                | b"toLowerCase"
                | b"toLocaleLowerCase"
                | b"trim"
                | b"trimStart"
                | b"trimLeft"
                | b"trimEnd"
                | b"trimRight"
                | b"startsWith"
                | b"endsWith"
                | b"includes"
                | b"repeat"
                | b"padStart"
                | b"padEnd"
                | b"split"
                | b"replace"
                | b"search"
                | b"match"
                | b"concat"
                | b"toString"
                | b"valueOf"
        ),
        ProtoKind::Number => matches!(name, b"toFixed" | b"toPrecision" | b"toString" | b"valueOf"),
        ProtoKind::Boolean => matches!(name, b"toString" | b"valueOf"),
        ProtoKind::Function => matches!(name, b"call" | b"apply" | b"toString"),
        ProtoKind::RegExp => matches!(name, b"test" | b"toString"),
    }
}

/// The built-in prototype a value that is not an object starts its chain
/// at (`None` for null and undefined, which have none, and for formats
/// and output variables, which answer their own methods).
pub(crate) fn kind_of(value: &Value) -> Option<ProtoKind> {
    Some(match value {
        Value::Object(_) => ProtoKind::Object,
        Value::Array(_) => ProtoKind::Array,
        Value::Text(_) => ProtoKind::String,
        Value::Num(_) => ProtoKind::Number,
        Value::Bool(_) => ProtoKind::Boolean,
        Value::Func(_) => ProtoKind::Function,
        Value::Regex(_) => ProtoKind::RegExp,
        Value::Null | Value::Undefined | Value::Output(_) => return None,
    })
}

/// `name` from the built-in prototype of `kind` on: its built-in methods
/// postc runs, then what the post added to it, then `Object.prototype`'s.
/// With `node`, a method Node.js has and postc does not run is found too
/// (for `in`).
pub(crate) fn find_builtin(kind: ProtoKind, name: &[u8], protos: &Protos, node: bool) -> Option<Found> {
    if has_method(kind, name) || (node && std::str::from_utf8(name).is_ok_and(|n| js::prototype_has(kind, n))) {
        return Some(Found::Method(kind));
    }
    if let Some(p) = protos.made(kind)
        && let Some(v) = p.borrow().get(name)
    {
        return Some(Found::Value(v.clone()));
    }
    if kind == ProtoKind::Object { None } else { find_builtin(ProtoKind::Object, name, protos, node) }
}

/// `name` on an object: its own property, or one along its chain (a
/// built-in prototype answers its built-in methods first).
pub(crate) fn find_in(o: &Object, name: &[u8], protos: &Protos, node: bool) -> Option<Found> {
    if let Some(kind) = o.builtin {
        return find_builtin(kind, name, protos, node);
    }
    if let Some(v) = o.get(name) {
        return Some(Found::Value(v.clone()));
    }
    find_from(&o.proto, name, protos, node)
}

/// `name` along the chain that starts at `proto` (what an object misses
/// of its own properties).
pub(crate) fn find_from(proto: &Proto, name: &[u8], protos: &Protos, node: bool) -> Option<Found> {
    let mut at = match proto {
        Proto::Null => return None,
        Proto::Object => return find_builtin(ProtoKind::Object, name, protos, node),
        Proto::Of(p) => p.clone(),
    };
    for _ in 0..MAX_PROTO_CHAIN {
        let next = {
            let o = at.borrow();
            if o.builtin.is_some() {
                return find_in(&o, name, protos, node);
            }
            if let Some(v) = o.get(name) {
                return Some(Found::Value(v.clone()));
            }
            match &o.proto {
                Proto::Null => return None,
                Proto::Object => {
                    drop(o);
                    return find_builtin(ProtoKind::Object, name, protos, node);
                }
                Proto::Of(p) => p.clone(),
            }
        };
        at = next;
    }
    None
}

/// The own properties of a function value, made on first need: a post
/// function's first `prototype` is `{constructor: f}` (its `constructor`
/// not enumerable, as JavaScript makes it). The function and its
/// prototype refer to each other, so they live as long as the run.
pub(crate) fn props_of(f: &Rc<Closure>) -> &Rc<RefCell<Object>> {
    f.props.get_or_init(|| {
        let mut props = Object::default();
        if let Callee::Post(_) = f.callee {
            let mut proto = Object { hidden_constructor: true, ..Object::default() };
            proto.set(Text::new("constructor"), Value::Func(f.clone()));
            props.set(Text::new("prototype"), Value::object(proto));
        }
        Rc::new(RefCell::new(props))
    })
}

/// The own property `name` of a function value, if it has it (without
/// making its properties when it has none yet and `name` is not
/// `prototype`).
pub(crate) fn function_own(f: &Rc<Closure>, name: &[u8]) -> Option<Value> {
    let props = match f.props.get() {
        Some(p) => p,
        None if name == b"prototype" && matches!(f.callee, Callee::Post(_)) => props_of(f),
        None => return None,
    };
    props.borrow().get(name).cloned()
}

/// The error of a chain longer than [`MAX_PROTO_CHAIN`]: a budget, like a
/// text too long, which `try` does not catch.
fn chain_too_long() -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(
            super::TEXT_BUDGET,
            format!("the post built a chain of more than {MAX_PROTO_CHAIN} prototypes and was stopped"),
        )
        .note("no output is written"),
    )
}

/// The prototype of an object made from `proto` (`Object.create(proto)`):
/// an object, or null for none; a TypeError for any other value.
pub(crate) fn proto_of_new(proto: &Value) -> Result<Proto> {
    match proto {
        Value::Object(p) => {
            let link = Proto::Of(p.clone());
            if link.depth() >= MAX_PROTO_CHAIN {
                return Err(chain_too_long());
            }
            Ok(link)
        }
        Value::Null => Ok(Proto::Null),
        other => Err(type_error(format!(
            "Object prototype may only be an Object or null: {}",
            crate::interp::objects::describe(other)
        ))),
    }
}

/// The prototype of an object `new F()` makes: `F.prototype` when it is
/// an object, else `Object.prototype`. A TypeError when `F` is not a
/// function of the post.
pub(crate) fn proto_for_new(callee: &Value) -> Result<Proto> {
    let Value::Func(f) = callee else {
        return Err(type_error(format!("{} is not a constructor", crate::interp::objects::describe(callee))));
    };
    if let Callee::Method(kind, name) = &f.callee {
        return Err(type_error(format!("{}.prototype.{name} is not a constructor", kind.constructor())));
    }
    match function_own(f, b"prototype") {
        Some(p @ Value::Object(_)) => proto_of_new(&p),
        _ => Ok(Proto::Object),
    }
}

/// Whether the object `target` is on the prototype chain of `value`
/// (`target.isPrototypeOf(value)`, `value instanceof F` with
/// `F.prototype`).
pub(crate) fn chain_has(value: &Value, target: &Rc<RefCell<Object>>, protos: &Protos) -> bool {
    let mut link = match value {
        Value::Object(o) => o.borrow().proto.clone(),
        other => match kind_of(other) {
            Some(kind) if !matches!(other, Value::Text(_) | Value::Num(_) | Value::Bool(_)) => {
                Proto::Of(protos.get(kind).clone())
            }
            _ => return false,
        },
    };
    for _ in 0..=MAX_PROTO_CHAIN {
        let at = match link {
            Proto::Null => return false,
            Proto::Object => protos.get(ProtoKind::Object).clone(),
            Proto::Of(p) => p,
        };
        if Rc::ptr_eq(&at, target) {
            return true;
        }
        link = at.borrow().proto.clone();
    }
    false
}

/// The enumerable properties of a value's prototype chain, for `for ...
/// in`: each level's in the order they were made, a name once (a name a
/// nearer level has is not listed again, nor a function's first
/// `prototype.constructor`). Nothing is made or copied for a chain that
/// holds none (an object literal's, while the post adds nothing to
/// `Object.prototype`).
pub(crate) fn chain_keys(value: &Value, protos: &Protos) -> Vec<Text> {
    let mut link = match value {
        Value::Object(o) => o.borrow().proto.clone(),
        other => match kind_of(other) {
            Some(kind) => match protos.made(kind) {
                Some(p) => Proto::Of(p.clone()),
                None => Proto::Object,
            },
            None => Proto::Null,
        },
    };
    let (mut names, mut seen) = (Vec::new(), Vec::new());
    for _ in 0..=MAX_PROTO_CHAIN {
        let at = match link {
            Proto::Null => break,
            Proto::Object => match protos.made(ProtoKind::Object) {
                Some(p) => p.clone(),
                None => break,
            },
            Proto::Of(p) => p,
        };
        let o = at.borrow();
        for k in &o.keys {
            if seen.contains(k) {
                continue;
            }
            seen.push(k.clone());
            if !(o.hidden_constructor && k.as_bytes() == b"constructor") {
                names.push(k.clone());
            }
        }
        link = o.proto.clone();
    }
    names
}

/// The tag `Object.prototype.toString` gives a value (`[object Array]`).
pub(crate) fn tag(value: &Value) -> Value {
    let name = match value {
        Value::Null => "Null",
        Value::Undefined => "Undefined",
        Value::Array(_) => "Array",
        Value::Text(_) => "String",
        Value::Num(_) => "Number",
        Value::Bool(_) => "Boolean",
        Value::Func(_) => "Function",
        Value::Regex(_) => "RegExp",
        Value::Object(_) | Value::Output(_) => "Object",
    };
    Value::text(&format!("[object {name}]"))
}
