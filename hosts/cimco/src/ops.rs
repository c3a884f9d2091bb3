//! The operators of translated scripts: JavaScript's `+ - * / %`, the
//! bitwise operators, comparisons, equality, truthiness and `typeof`, and
//! literals Rhai has no syntax for (`null`, `NaN`, `Infinity`).

use std::cmp::Ordering;

use postc_front_cimco::host_names as names;
use rhai::{Array, Dynamic, Engine, EvalAltResult, ImmutableString, Position};

use crate::compiled::Shared;
use crate::values::{self, JsNull, num, to_number};
use postc_runtime::js;

type R = Result<Dynamic, Box<EvalAltResult>>;

/// An error that stops the script, reported at the calling line.
/// JavaScript `key in value`: own properties along the prototype chain,
/// then what the value's built-in prototype has.
fn has_property(key: Dynamic, value: Dynamic) -> Result<bool, Box<EvalAltResult>> {
    use js::ProtoKind;
    let k = values::to_string(&key);
    if let Some(a) = value.clone().try_cast::<values::JsArr>() {
        let n = to_number(&key);
        let index = n >= 0.0 && n.fract() == 0.0 && js::number_to_string(n) == k;
        return Ok((index && (n as usize) < a.0.borrow().len()) || js::prototype_has(ProtoKind::Array, &k));
    }
    if value.is::<values::JsRegex>() {
        return Ok(js::prototype_has(ProtoKind::RegExp, &k));
    }
    let Some(o) = value.clone().try_cast::<values::JsObj>() else {
        return Err(fail(format!("TypeError: cannot use 'in' to search for '{k}' in {}", values::to_string(&value))));
    };
    let mut at = Some(o);
    let mut kind = ProtoKind::Object;
    while let Some(obj) = at {
        let data = obj.0.borrow();
        if data.props.iter().any(|(name, _)| name.as_str() == k) {
            return Ok(true);
        }
        if matches!(data.kind, values::ObjKind::Function(_) | values::ObjKind::Host(_)) {
            kind = ProtoKind::Function;
        }
        at = data.proto.clone();
    }
    Ok(js::prototype_has(kind, &k))
}

/// An error of JavaScript's the host raises (`"TypeError: message"`): the
/// post's `catch` receives it as an error object with its `name` and
/// `message` ([`postc_runtime::js::error_parts`]), as a JavaScript engine
/// gives it; uncaught, the run stops with its text.
#[derive(Clone, Debug)]
pub struct HostError(pub ImmutableString);

pub fn fail(message: impl Into<String>) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorRuntime(Dynamic::from(HostError(message.into().into())), Position::NONE))
}

/// A use of JavaScript postc does not run (a regular expression's
/// `lastIndex`: [`postc_runtime::regex::UNSUPPORTED`]), at the call that
/// asked. It is a system error, so the post's `try` does not catch it and
/// no script function wraps it: the run stops there, as native code does.
#[derive(Debug)]
pub struct Unsupported {
    pub message: String,
    pub at: Position,
}

impl std::fmt::Display for Unsupported {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Unsupported {}

pub fn unsupported(message: String, at: Position) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorSystem(String::new(), Box::new(Unsupported { message, at })))
}

pub fn register(engine: &mut Engine, state: &Shared) {
    engine.register_type_with_name::<JsNull>("null");
    engine.register_fn(names::NULL, || JsNull);
    engine.register_fn(names::NAN, || f64::NAN);
    engine.register_fn(names::INF, || f64::INFINITY);
    engine.register_fn(names::ADD, |a: Dynamic, b: Dynamic| values::add(&a, &b));
    engine.register_fn(names::ADDS, |items: Array| {
        let mut it = items.into_iter();
        let first = it.next().unwrap_or(Dynamic::UNIT);
        it.fold(first, |acc, x| values::add(&acc, &x))
    });
    engine.register_fn(names::SUB, |a: Dynamic, b: Dynamic| to_number(&a) - to_number(&b));
    engine.register_fn(names::MUL, |a: Dynamic, b: Dynamic| to_number(&a) * to_number(&b));
    engine.register_fn(names::DIV, |a: Dynamic, b: Dynamic| to_number(&a) / to_number(&b));
    engine.register_fn(names::REM, |a: Dynamic, b: Dynamic| to_number(&a) % to_number(&b));
    engine.register_fn(names::NEG, |a: Dynamic| -to_number(&a));
    engine.register_fn(names::POS, |a: Dynamic| to_number(&a));
    engine.register_fn(names::BNOT, |a: Dynamic| f64::from(!js::to_int32(to_number(&a))));
    let int = |a: &Dynamic| js::to_int32(to_number(a));
    engine.register_fn(names::BAND, move |a: Dynamic, b: Dynamic| f64::from(int(&a) & int(&b)));
    engine.register_fn(names::BOR, move |a: Dynamic, b: Dynamic| f64::from(int(&a) | int(&b)));
    engine.register_fn(names::BXOR, move |a: Dynamic, b: Dynamic| f64::from(int(&a) ^ int(&b)));
    engine
        .register_fn(names::SHL, move |a: Dynamic, b: Dynamic| f64::from(int(&a).wrapping_shl((int(&b) as u32) & 31)));
    engine.register_fn(names::SHR, move |a: Dynamic, b: Dynamic| f64::from(int(&a) >> ((int(&b) as u32) & 31)));
    engine.register_fn(names::USHR, |a: Dynamic, b: Dynamic| {
        f64::from(js::to_uint32(to_number(&a)) >> (js::to_uint32(to_number(&b)) & 31))
    });
    engine.register_fn(names::EQ, |a: Dynamic, b: Dynamic| values::loose_eq(&a, &b));
    engine.register_fn(names::NE, |a: Dynamic, b: Dynamic| !values::loose_eq(&a, &b));
    engine.register_fn(names::SEQ, |a: Dynamic, b: Dynamic| values::strict_eq(&a, &b));
    engine.register_fn(names::SNE, |a: Dynamic, b: Dynamic| !values::strict_eq(&a, &b));
    engine.register_fn(names::LT, |a: Dynamic, b: Dynamic| values::compare(&a, &b) == Some(Ordering::Less));
    engine.register_fn(names::LE, |a: Dynamic, b: Dynamic| {
        matches!(values::compare(&a, &b), Some(Ordering::Less | Ordering::Equal))
    });
    engine.register_fn(names::GT, |a: Dynamic, b: Dynamic| values::compare(&a, &b) == Some(Ordering::Greater));
    engine.register_fn(names::GE, |a: Dynamic, b: Dynamic| {
        matches!(values::compare(&a, &b), Some(Ordering::Greater | Ordering::Equal))
    });
    engine.register_fn(names::IN, has_property);
    engine.register_fn(names::TRUTHY, |a: Dynamic| values::truthy(&a));
    engine.register_fn(names::TYPEOF, |a: Dynamic| values::text(values::type_of(&a)));
    engine.register_fn(names::ARG, |a: Array, i: i64| -> Dynamic {
        usize::try_from(i).ok().and_then(|i| a.get(i).cloned()).unwrap_or(Dynamic::UNIT)
    });
    engine.register_fn(names::UNDEF, |name: ImmutableString| -> R {
        Err(fail(format!("ReferenceError: {name} is not defined")))
    });
    engine.register_fn(names::ASSIGN_ERROR, |name: ImmutableString| -> R {
        Err(fail(format!("TypeError: cannot assign to `{name}`")))
    });
    let s = state.clone();
    engine.register_fn(names::TICK, move |at: i64| -> R {
        let mut st = s.borrow_mut();
        st.ticks += 1;
        st.last_loop = u32::try_from(at).ok();
        if st.ticks > st.max_ticks {
            // Not catchable by the post's `try`.
            return Err(Box::new(EvalAltResult::ErrorTooManyOperations(Position::NONE)));
        }
        Ok(Dynamic::UNIT)
    });
    let s = state.clone();
    engine.register_fn(names::GLOBAL_GET, move |i: i64| -> Dynamic {
        let st = s.borrow();
        let i = usize::try_from(i).unwrap_or(usize::MAX);
        let plain = st.globals.get(i).cloned().unwrap_or_default();
        match st.objects.get(i) {
            // An object (or null) is there unless native code has since
            // stored something else.
            Some(o) if !o.is_unit() && plain == postc_runtime::value::Value::Null => o.clone(),
            _ => values::from_value(&plain),
        }
    });
    let s = state.clone();
    engine.register_fn(names::GLOBAL_SET, move |i: i64, v: Dynamic| -> Dynamic {
        let mut st = s.borrow_mut();
        let Ok(i) = usize::try_from(i) else { return v };
        if st.globals.len() <= i {
            st.globals.resize(i + 1, postc_runtime::value::Value::Null);
        }
        if st.objects.len() <= i {
            st.objects.resize(i + 1, Dynamic::UNIT);
        }
        match values::to_value(&v).filter(|_| !values::is_null(&v)) {
            Some(val) => {
                st.globals[i] = val;
                st.objects[i] = Dynamic::UNIT;
            }
            None => {
                st.globals[i] = postc_runtime::value::Value::Null;
                st.objects[i] = v.clone();
            }
        }
        v
    });
    let _ = num;
}
