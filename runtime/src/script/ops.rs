//! The operators of translated scripts: JavaScript's `+ - * / %`, the
//! bitwise operators, comparisons, equality, truthiness and `typeof`, and
//! literals Rhai has no syntax for (`null`, `NaN`, `Infinity`).

use std::cmp::Ordering;

use rhai::{Array, Dynamic, Engine, EvalAltResult, ImmutableString, Position};

use super::host::Shared;
use super::js;
use super::values::{self, JsNull, num, to_number};

type R = Result<Dynamic, Box<EvalAltResult>>;

/// An error that stops the script, reported at the calling line.
pub fn fail(message: impl Into<String>) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorRuntime(Dynamic::from(ImmutableString::from(message.into())), Position::NONE))
}

pub fn register(engine: &mut Engine, state: &Shared) {
    engine.register_type_with_name::<JsNull>("null");
    engine.register_fn("__null", || JsNull);
    engine.register_fn("__nan", || f64::NAN);
    engine.register_fn("__inf", || f64::INFINITY);
    engine.register_fn("__add", |a: Dynamic, b: Dynamic| values::add(&a, &b));
    engine.register_fn("__adds", |items: Array| {
        let mut it = items.into_iter();
        let first = it.next().unwrap_or(Dynamic::UNIT);
        it.fold(first, |acc, x| values::add(&acc, &x))
    });
    engine.register_fn("__sub", |a: Dynamic, b: Dynamic| to_number(&a) - to_number(&b));
    engine.register_fn("__mul", |a: Dynamic, b: Dynamic| to_number(&a) * to_number(&b));
    engine.register_fn("__div", |a: Dynamic, b: Dynamic| to_number(&a) / to_number(&b));
    engine.register_fn("__rem", |a: Dynamic, b: Dynamic| to_number(&a) % to_number(&b));
    engine.register_fn("__neg", |a: Dynamic| -to_number(&a));
    engine.register_fn("__pos", |a: Dynamic| to_number(&a));
    engine.register_fn("__bnot", |a: Dynamic| f64::from(!js::to_int32(to_number(&a))));
    let int = |a: &Dynamic| js::to_int32(to_number(a));
    engine.register_fn("__band", move |a: Dynamic, b: Dynamic| f64::from(int(&a) & int(&b)));
    engine.register_fn("__bor", move |a: Dynamic, b: Dynamic| f64::from(int(&a) | int(&b)));
    engine.register_fn("__bxor", move |a: Dynamic, b: Dynamic| f64::from(int(&a) ^ int(&b)));
    engine.register_fn("__shl", move |a: Dynamic, b: Dynamic| f64::from(int(&a).wrapping_shl((int(&b) as u32) & 31)));
    engine.register_fn("__shr", move |a: Dynamic, b: Dynamic| f64::from(int(&a) >> ((int(&b) as u32) & 31)));
    engine.register_fn("__ushr", |a: Dynamic, b: Dynamic| {
        f64::from(js::to_uint32(to_number(&a)) >> (js::to_uint32(to_number(&b)) & 31))
    });
    engine.register_fn("__eq", |a: Dynamic, b: Dynamic| values::loose_eq(&a, &b));
    engine.register_fn("__ne", |a: Dynamic, b: Dynamic| !values::loose_eq(&a, &b));
    engine.register_fn("__seq", |a: Dynamic, b: Dynamic| values::strict_eq(&a, &b));
    engine.register_fn("__sne", |a: Dynamic, b: Dynamic| !values::strict_eq(&a, &b));
    engine.register_fn("__lt", |a: Dynamic, b: Dynamic| values::compare(&a, &b) == Some(Ordering::Less));
    engine.register_fn("__le", |a: Dynamic, b: Dynamic| {
        matches!(values::compare(&a, &b), Some(Ordering::Less | Ordering::Equal))
    });
    engine.register_fn("__gt", |a: Dynamic, b: Dynamic| values::compare(&a, &b) == Some(Ordering::Greater));
    engine.register_fn("__ge", |a: Dynamic, b: Dynamic| {
        matches!(values::compare(&a, &b), Some(Ordering::Greater | Ordering::Equal))
    });
    engine.register_fn("__t", |a: Dynamic| values::truthy(&a));
    engine.register_fn("__typeof", |a: Dynamic| values::text(values::type_of(&a)));
    engine.register_fn("__arg", |a: Array, i: i64| -> Dynamic {
        usize::try_from(i).ok().and_then(|i| a.get(i).cloned()).unwrap_or(Dynamic::UNIT)
    });
    engine.register_fn("__undef", |name: ImmutableString| -> R {
        Err(fail(format!("ReferenceError: {name} is not defined")))
    });
    engine.register_fn("__assign_error", |name: ImmutableString| -> R {
        Err(fail(format!("TypeError: cannot assign to `{name}`")))
    });
    let s = state.clone();
    engine.register_fn("__tick", move |at: i64| -> R {
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
    engine.register_fn("__gg", move |i: i64| -> Dynamic {
        let st = s.borrow();
        let i = usize::try_from(i).unwrap_or(usize::MAX);
        let plain = st.globals.get(i).cloned().unwrap_or_default();
        match st.objects.get(i) {
            // An object (or null) is there unless native code has since
            // stored something else.
            Some(o) if !o.is_unit() && plain == crate::value::Value::Null => o.clone(),
            _ => values::from_value(&plain),
        }
    });
    let s = state.clone();
    engine.register_fn("__gs", move |i: i64, v: Dynamic| -> Dynamic {
        let mut st = s.borrow_mut();
        let Ok(i) = usize::try_from(i) else { return v };
        if st.globals.len() <= i {
            st.globals.resize(i + 1, crate::value::Value::Null);
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
                st.globals[i] = crate::value::Value::Null;
                st.objects[i] = v.clone();
            }
        }
        v
    });
    let _ = num;
}
