//! Properties, methods and calls of translated scripts: `__get`, `__set`,
//! `__keys`, `__callm` (methods of texts, numbers, arrays, regular
//! expressions, objects and output variables), `__call`, `__new`, object
//! and array literals, function objects, `Math`.

use postc_front_cimco::host_names as names;
use rhai::{Array, Dynamic, Engine, EvalAltResult, FnPtr, ImmutableString, Map, NativeCallContext};

use crate::compiled::Shared;
use crate::ops::{fail, unsupported};
use crate::values::{self, JsArr, JsObj, JsRegex, ObjKind, num, text, to_number, to_string};
use postc_runtime::js;
use postc_runtime::regex::{self, Property, RegExp, Regex};

type R = Result<Dynamic, Box<EvalAltResult>>;

pub fn register(engine: &mut Engine, state: &Shared) {
    engine.register_type_with_name::<JsObj>("object");
    engine.register_type_with_name::<JsArr>("array");
    engine.register_type_with_name::<JsRegex>("regexp");
    engine.register_fn(names::OBJECT, |pairs: Array| {
        let o = JsObj::new(ObjKind::Plain);
        let mut it = pairs.into_iter();
        while let (Some(k), Some(v)) = (it.next(), it.next()) {
            o.set(&to_string(&k), v);
        }
        o
    });
    engine.register_fn(names::ARRAY, |items: Array| JsArr::new(items));
    engine.register_fn(names::FUNCTION, |f: FnPtr| JsObj::new(ObjKind::Function(f)));
    let s = state.clone();
    engine.register_fn(names::FUNCTION_OBJECT, move |name: ImmutableString| -> R {
        let mut st = s.borrow_mut();
        if let Some(o) = st.functions.get(name.as_str()) {
            return Ok(Dynamic::from(o.clone()));
        }
        let f = FnPtr::new(name.as_str()).map_err(|_| fail(format!("{name} is not a function")))?;
        let o = JsObj::new(ObjKind::Function(f));
        st.functions.insert(name.to_string(), o.clone());
        Ok(Dynamic::from(o))
    });
    // Each evaluation of a literal is a new value (its own identity), of
    // the pattern compiled the first time.
    let s = state.clone();
    engine.register_fn(names::REGEX, move |p: ImmutableString, f: ImmutableString| -> R {
        let key = (p.to_string(), f.to_string());
        let known = s.borrow().regexes.get(&key).cloned();
        let compiled = match known {
            Some(r) => r,
            None => {
                let r = std::rc::Rc::new(Regex::new(&p, &f).map_err(|e| fail(format!("SyntaxError: {e}")))?);
                s.borrow_mut().regexes.insert(key, r.clone());
                r
            }
        };
        Ok(Dynamic::from(JsRegex(std::rc::Rc::new(RegExp(compiled)))))
    });
    engine.register_fn(names::MATH_OBJECT, || JsObj::new(ObjKind::Math));
    engine.register_fn(names::HOST_FUNCTION, |name: ImmutableString| JsObj::new(ObjKind::Host(name.to_string())));
    engine.register_fn(names::MATH, |name: ImmutableString, args: Array| -> R { math(&name, &args) });
    engine.register_fn(names::GET, |ctx: NativeCallContext, o: Dynamic, k: Dynamic| -> R {
        regex_member(&o, &k, ctx.call_position())?;
        get(&o, &k)
    });
    engine.register_fn(names::SET, |ctx: NativeCallContext, o: Dynamic, k: Dynamic, v: Dynamic| -> R {
        regex_member(&o, &k, ctx.call_position())?;
        set(&o, &k, v)
    });
    engine.register_fn(names::KEYS, |o: Dynamic| -> Array { keys(&o) });
    // A `return`, `break` or `continue` leaving a `try` is thrown as a
    // jump and caught by the translation of that `try`, which runs the
    // `finally` and then jumps (kind 1, 2, 3); other thrown values are 0.
    engine.register_type_with_name::<Jump>("jump");
    engine.register_fn(names::JUMP, |kind: i64, value: Dynamic| Dynamic::from(Jump(kind, value)));
    engine.register_fn(names::JUMP_KIND, |e: Dynamic| e.try_cast::<Jump>().map_or(0, |j| j.0));
    engine.register_fn(names::JUMP_VALUE, |e: Dynamic| e.try_cast::<Jump>().map_or(Dynamic::UNIT, |j| j.1));
    engine.register_type_with_name::<crate::ops::HostError>("error");
    engine.register_fn(names::CAUGHT, |e: Dynamic| -> Dynamic {
        if let Some(crate::ops::HostError(t)) = e.clone().try_cast::<crate::ops::HostError>() {
            let o = JsObj::new(ObjKind::Plain);
            let (name, message) = js::error_parts(&t).unwrap_or(("Error", &t));
            o.set("message", text(message.to_string()));
            o.set("name", text(name));
            return Dynamic::from(o);
        }
        match e.clone().try_cast::<Map>() {
            Some(m) => {
                let o = JsObj::new(ObjKind::Plain);
                let msg = m.get("message").map_or_else(|| "error".to_string(), |v| v.to_string());
                o.set("message", text(msg));
                o.set("name", text("Error"));
                Dynamic::from(o)
            }
            None => e,
        }
    });
    let s = state.clone();
    engine.register_fn(
        names::CALL_METHOD,
        move |ctx: NativeCallContext, o: Dynamic, name: ImmutableString, args: Array| -> R {
            method(&ctx, &s, o, &name, args)
        },
    );
    let s = state.clone();
    engine.register_fn(names::CALL, move |ctx: NativeCallContext, f: Dynamic, args: Array| -> R {
        call(&ctx, &s, &f, Dynamic::UNIT, args)
    });
    let s = state.clone();
    engine.register_fn(names::NEW, move |ctx: NativeCallContext, f: Dynamic, args: Array| -> R {
        construct(&ctx, &s, &f, args)
    });
    let s = state.clone();
    engine.register_fn(names::HOST, move |ctx: NativeCallContext, name: ImmutableString, args: Array| -> R {
        crate::cnc_calc::host_call(&ctx, &s, &name, args)
    });
}

/// The element a key names ([`js::array_index`]).
fn index_of(k: &Dynamic) -> Option<usize> {
    let i = if let Some(t) = k.read_lock::<ImmutableString>() {
        js::array_index(js::Key::Text(t.as_str()))
    } else if k.is::<f64>() || k.is::<i64>() {
        js::array_index(js::Key::Number(to_number(k)))
    } else {
        js::array_index(js::Key::Other)
    };
    i.map(|i| i as usize)
}

/// `o[k]`.
pub fn get(o: &Dynamic, k: &Dynamic) -> R {
    if o.is_unit() || values::is_null(o) {
        return Err(fail(format!("TypeError: cannot read property '{}' of {}", to_string(k), to_string(o))));
    }
    if let Some(s) = o.clone().try_cast::<ImmutableString>() {
        if k.is::<ImmutableString>() && to_string(k) == "length" {
            return Ok(num(s.chars().count() as f64));
        }
        return Ok(index_of(k).and_then(|i| s.chars().nth(i)).map_or(Dynamic::UNIT, |c| text(c.to_string())));
    }
    if let Some(a) = o.clone().try_cast::<JsArr>() {
        if k.is::<ImmutableString>() && to_string(k) == "length" {
            return Ok(num(a.0.borrow().len() as f64));
        }
        return Ok(index_of(k).and_then(|i| a.0.borrow().get(i).cloned()).unwrap_or(Dynamic::UNIT));
    }
    if let Some(obj) = o.clone().try_cast::<JsObj>() {
        let key = to_string(k);
        if let Some(v) = obj.get(&key) {
            return Ok(v);
        }
        if key == "prototype" && obj.function().is_some() {
            let proto = JsObj::new(ObjKind::Plain);
            obj.set("prototype", Dynamic::from(proto.clone()));
            return Ok(Dynamic::from(proto));
        }
        if let ObjKind::Math = obj.0.borrow().kind
            && let Some(c) = postc_front_cimco::host_names::math_constant(&key)
        {
            return Ok(num(c));
        }
        return Ok(Dynamic::UNIT);
    }
    if let Some(m) = o.clone().try_cast::<Map>() {
        return Ok(m.get(to_string(k).as_str()).cloned().unwrap_or(Dynamic::UNIT));
    }
    if let Some(r) = o.clone().try_cast::<JsRegex>() {
        return Ok(match r.0.0.property(&to_string(k)) {
            Some(Property::Text(t)) => text(t),
            Some(Property::Flag(b)) => Dynamic::from_bool(b),
            None => Dynamic::UNIT,
        });
    }
    Ok(Dynamic::UNIT)
}

/// A property of a regular expression that postc does not keep
/// (`lastIndex`) is refused, read or set.
fn regex_member(o: &Dynamic, k: &Dynamic, at: rhai::Position) -> Result<(), Box<EvalAltResult>> {
    if o.is::<JsRegex>()
        && let Some(why) = regex::unsupported_member(&to_string(k))
    {
        return Err(unsupported(why, at));
    }
    Ok(())
}

/// `o[k] = v`; the value of the assignment.
fn set(o: &Dynamic, k: &Dynamic, v: Dynamic) -> R {
    if o.is_unit() || values::is_null(o) {
        return Err(fail(format!("TypeError: cannot set property '{}' of {}", to_string(k), to_string(o))));
    }
    if let Some(obj) = o.clone().try_cast::<JsObj>() {
        obj.set(&to_string(k), v.clone());
    } else if let Some(a) = o.clone().try_cast::<JsArr>() {
        let mut items = a.0.borrow_mut();
        if k.is::<ImmutableString>() && to_string(k) == "length" {
            let n = to_number(&v);
            if n >= 0.0 && n.fract() == 0.0 && n < 1e7 {
                items.resize(n as usize, Dynamic::UNIT);
            }
        } else if let Some(i) = index_of(k).filter(|i| *i < 1 << 24) {
            if items.len() <= i {
                items.resize(i + 1, Dynamic::UNIT);
            }
            items[i] = v.clone();
        }
    }
    Ok(v)
}

fn keys(o: &Dynamic) -> Array {
    if let Some(obj) = o.clone().try_cast::<JsObj>() {
        // JavaScript's order: keys that are array indices ascending, then
        // the other keys in the order they were added.
        let props = &obj.0.borrow().props;
        let mut indices: Vec<(u32, &str)> =
            props.iter().filter_map(|(k, _)| array_index(k).map(|i| (i, k.as_str()))).collect();
        indices.sort_by_key(|(i, _)| *i);
        let others = props.iter().map(|(k, _)| k.as_str()).filter(|k| array_index(k).is_none());
        return indices.into_iter().map(|(_, k)| k).chain(others).map(|k| Dynamic::from(k.to_string())).collect();
    }
    let n = if let Some(a) = o.clone().try_cast::<JsArr>() {
        a.0.borrow().len()
    } else if let Some(s) = o.clone().try_cast::<ImmutableString>() {
        s.chars().count()
    } else {
        0
    };
    (0..n).map(|i| text(i.to_string())).collect()
}

/// `n.toString(radix)`: whole numbers in any radix from 2 to 36, as
/// JavaScript writes them; a fraction only in radix 10.
fn radix_string(n: f64, radix: f64) -> Result<String, Box<rhai::EvalAltResult>> {
    js::radix_string(n, radix).map_err(fail)
}

/// A key that is an array index (`"0"`, `"10"`, not `"01"` or `"-1"`):
/// the canonical text of a whole number below 2^32 - 1.
fn array_index(k: &str) -> Option<u32> {
    let n: u32 = k.parse().ok()?;
    (n != u32::MAX && n.to_string() == k).then_some(n)
}

/// Calls a function value with `this`.
pub fn call(ctx: &NativeCallContext, state: &Shared, f: &Dynamic, mut this: Dynamic, args: Array) -> R {
    if let Some(obj) = f.clone().try_cast::<JsObj>() {
        let kind = match &obj.0.borrow().kind {
            ObjKind::Function(p) => Ok(p.clone()),
            ObjKind::Host(name) => Err(Some(name.clone())),
            _ => Err(None),
        };
        return match kind {
            Ok(p) => p.call_raw(ctx, Some(&mut this), [Dynamic::from_array(args)]),
            Err(Some(name)) => crate::cnc_calc::host_call(ctx, state, &name, args),
            Err(None) => Err(fail("TypeError: an object is not a function")),
        };
    }
    if let Some(p) = f.clone().try_cast::<FnPtr>() {
        return p.call_raw(ctx, Some(&mut this), [Dynamic::from_array(args)]);
    }
    Err(fail(format!("TypeError: {} is not a function", to_string(f))))
}

fn construct(ctx: &NativeCallContext, state: &Shared, f: &Dynamic, args: Array) -> R {
    if let Some(obj) = f.clone().try_cast::<JsObj>() {
        if let ObjKind::Host(name) = &obj.0.borrow().kind {
            let name = name.clone();
            return crate::cnc_calc::host_call(ctx, state, &name, args);
        }
        if obj.function().is_some() {
            let proto = get(f, &text("prototype"))?.try_cast::<JsObj>();
            let this = JsObj::new(ObjKind::Plain);
            this.0.borrow_mut().proto = proto;
            let result = call(ctx, state, f, Dynamic::from(this.clone()), args)?;
            return Ok(if result.is::<JsObj>() || result.is::<JsArr>() { result } else { Dynamic::from(this) });
        }
    }
    Err(fail(format!("TypeError: {} is not a constructor", to_string(f))))
}

fn arg(args: &Array, i: usize) -> Dynamic {
    args.get(i).cloned().unwrap_or(Dynamic::UNIT)
}

/// `o.name(args)`.
fn method(ctx: &NativeCallContext, state: &Shared, o: Dynamic, name: &str, args: Array) -> R {
    if o.is_unit() || values::is_null(&o) {
        return Err(fail(format!("TypeError: cannot call method '{name}' of {}", to_string(&o))));
    }
    if let Some(s) = o.clone().try_cast::<ImmutableString>() {
        return crate::methods::string_method(&s, name, &args, ctx.call_position());
    }
    if o.is::<f64>() || o.is::<i64>() {
        let n = to_number(&o);
        return match name {
            "toFixed" => Ok(text(js::to_fixed(n, to_number(&arg(&args, 0)).max(0.0)))),
            "toPrecision" => match arg(&args, 0) {
                p if p.is_unit() => Ok(text(js::number_to_string(n))),
                p => js::to_precision(n, to_number(&p)).map(text).map_err(fail),
            },
            "toString" => match arg(&args, 0) {
                r if r.is_unit() => Ok(text(js::number_to_string(n))),
                r => radix_string(n, to_number(&r)).map(text),
            },
            _ => Err(fail(format!("TypeError: a number has no method '{name}'"))),
        };
    }
    if let Some(a) = o.clone().try_cast::<JsArr>() {
        return crate::methods::array_method(&a, name, args);
    }
    if let Some(r) = o.clone().try_cast::<JsRegex>() {
        let at = ctx.call_position();
        return match name {
            "test" => r.0.0.test(&to_string(&arg(&args, 0))).map(Dynamic::from_bool).map_err(|e| unsupported(e, at)),
            "toString" => Ok(text(r.0.0.to_text())),
            _ => match regex::unsupported_member(name) {
                Some(why) => Err(unsupported(why, at)),
                None => Err(fail(format!("TypeError: a regular expression has no method '{name}'"))),
            },
        };
    }
    if let Some(r) = crate::cnc_calc::output_method(state, &o, name, &args, ctx.call_position()) {
        return r;
    }
    if let Some(obj) = o.clone().try_cast::<JsObj>() {
        if let ObjKind::Math = obj.0.borrow().kind {
            return math(name, &args);
        }
        if let Some(f) = obj.get(name) {
            return call(ctx, state, &f, o, args);
        }
        return match name {
            "toString" => Ok(text(to_string(&o))),
            "hasOwnProperty" => {
                let k = to_string(&arg(&args, 0));
                Ok(Dynamic::from_bool(obj.0.borrow().props.iter().any(|(p, _)| p.as_str() == k)))
            }
            "call" if obj.function().is_some() => {
                let mut args = args;
                let this = if args.is_empty() { Dynamic::UNIT } else { args.remove(0) };
                call(ctx, state, &o, this, args)
            }
            "apply" if obj.function().is_some() => {
                let this = arg(&args, 0);
                let list = arg(&args, 1).try_cast::<JsArr>().map(|a| a.0.borrow().clone()).unwrap_or_default();
                call(ctx, state, &o, this, list)
            }
            _ => Err(fail(format!("TypeError: the object has no method '{name}'"))),
        };
    }
    Err(fail(format!("TypeError: {} has no method '{name}'", values::type_of(&o))))
}

/// `Math.name(args)`.
pub fn math(name: &str, args: &Array) -> R {
    let n = |i: usize| args.get(i).map_or(f64::NAN, to_number);
    let v = match name {
        "abs" => n(0).abs(),
        "acos" => n(0).acos(),
        "asin" => n(0).asin(),
        "atan" => n(0).atan(),
        "atan2" => n(0).atan2(n(1)),
        "ceil" => n(0).ceil(),
        "cos" => n(0).cos(),
        "exp" => n(0).exp(),
        "floor" => n(0).floor(),
        "log" => n(0).ln(),
        "max" => js::math_max(args.iter().map(to_number)),
        "min" => js::math_min(args.iter().map(to_number)),
        "pow" => js::math_pow(n(0), n(1)),
        // Posts must print the same program every time.
        "random" => 0.5,
        "round" => js::math_round(n(0)),
        "sin" => n(0).sin(),
        "sqrt" => n(0).sqrt(),
        "tan" => n(0).tan(),
        _ => return Err(fail(format!("TypeError: Math.{name} is not a function"))),
    };
    Ok(num(v))
}

/// A `return` (1), `break` (2) or `continue` (3) on its way out of a `try`,
/// with the returned value.
#[derive(Clone)]
struct Jump(i64, Dynamic);
