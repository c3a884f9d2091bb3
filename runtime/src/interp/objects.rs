//! JavaScript's arrays, objects and function values in the interpreter:
//! reading and setting properties, the built-in methods of arrays, texts
//! and numbers, calling function values, `throw` and `try`.
//!
//! A property is looked up by its key's text: arrays and texts answer
//! `length` and indices, objects and functions their own properties, and
//! what a value misses is looked for along its prototype chain
//! ([`super::protos`]). Errors a JavaScript engine throws (reading a
//! property of `undefined`, calling what is not a function) are
//! [`TYPE_ERROR`]s, which `try` catches as it catches a `throw`.

use postc_ir::{Diagnostic, FunctionId, OutputRef, Span};

use super::Result;
use super::ops::js_number;
use super::protos::{self, Found, Protos, find_builtin, find_in, function_own, kind_of, props_of};
use crate::engine::Engine;
use crate::js::{self, ProtoKind};
use crate::regex::{self, Property};
use crate::value::{Callee, Closure, Object, Text, Value};

/// JavaScript's global object: `this` outside a method. The post's
/// globals, functions and output variables are its properties, read and
/// set by name ([`Engine::global_member`]); other properties live on
/// [`GlobalObject::object`].
pub struct GlobalObject {
    /// The object `this` evaluates to, compared by identity.
    pub(crate) object: std::rc::Rc<std::cell::RefCell<Object>>,
    names: std::collections::HashMap<Box<[u8]>, GlobalName>,
}

/// What a name of the global object stands for.
#[derive(Clone, Copy)]
enum GlobalName {
    Global(postc_ir::GlobalId),
    Function(FunctionId),
    Variable(postc_ir::VarId),
}

impl GlobalObject {
    fn new(post: &postc_ir::Post) -> GlobalObject {
        let mut names = std::collections::HashMap::new();
        let mut add = |name: &str, what: Option<GlobalName>| {
            if let Some(what) = what {
                names.entry(name.as_bytes().into()).or_insert(what);
            }
        };
        for (i, g) in post.globals.iter().enumerate() {
            add(&g.name, postc_ir::GlobalId::from_usize(i).map(GlobalName::Global));
        }
        for (i, f) in post.functions.iter().enumerate() {
            add(&f.name, FunctionId::from_usize(i).map(GlobalName::Function));
        }
        for (i, v) in post.variables.iter().enumerate() {
            add(&v.name, postc_ir::VarId::from_usize(i).map(GlobalName::Variable));
        }
        GlobalObject { object: Default::default(), names }
    }
}

/// The code of a value the post threw and did not catch.
pub const THROWN: &str = "RT036";

/// The code of a JavaScript type error in native code (a property of
/// `undefined`, a call of what is not a function): `try` catches it.
pub const TYPE_ERROR: &str = "RT037";

/// Arrays grow to at most this many items (a post's arrays hold words,
/// not toolpaths).
pub const MAX_ITEMS: usize = 1 << 20;

/// A use of a regular expression postc does not run ([`regex::UNSUPPORTED`]):
/// not a `TypeError`, so `try` does not catch it.
pub(crate) fn unsupported(message: String) -> Box<Diagnostic> {
    Box::new(Diagnostic::error(regex::UNSUPPORTED, message).note("no output is written"))
}

/// JavaScript's `ReferenceError` for a name the post never defines: a
/// [`TYPE_ERROR`] too, so that `try` catches it as JavaScript's does.
pub(crate) fn reference_error(name: &Text) -> Box<Diagnostic> {
    Box::new(Diagnostic::error(TYPE_ERROR, format!("ReferenceError: {name} is not defined")))
}

/// A JavaScript `TypeError` of native code.
pub(crate) fn type_error(message: String) -> Box<Diagnostic> {
    Box::new(Diagnostic::error(TYPE_ERROR, format!("TypeError: {message}")))
}

/// A key as text: numbers as JavaScript writes them (`a[1]` is `a["1"]`).
fn key_text(key: &Value) -> Text {
    match key {
        Value::Text(t) => t.clone(),
        other => other.to_text(),
    }
}

/// An array index a key names, if it is one ([`js::array_index`]), below
/// the most items an array holds.
fn index(key: &Value) -> Option<usize> {
    let key = match key {
        Value::Num(n) => js::Key::Number(*n),
        Value::Text(t) => js::Key::Text(t.as_str()),
        _ => js::Key::Other,
    };
    js::array_index(key).map(|i| i as usize).filter(|&i| i < MAX_ITEMS)
}

/// `value[key]`: own properties first, then the value's prototype chain.
pub(crate) fn member(value: &Value, key: &Value, protos: &Protos) -> Result<Value> {
    Ok(match value {
        Value::Object(o) => {
            let o = o.borrow();
            let k = key_text(key);
            match o.get(k.as_bytes()) {
                Some(v) if o.builtin.is_none() => v.clone(),
                _ => inherited(find_in(&o, k.as_bytes(), protos, false), &k),
            }
        }
        // `list.length`, the commonest read of an array, told first.
        Value::Array(items) if matches!(key, Value::Text(k) if k.as_bytes() == b"length") => {
            Value::Num(items.borrow().len() as f64)
        }
        Value::Array(items) => {
            let items = items.borrow();
            match index(key) {
                Some(i) => items.get(i).cloned().unwrap_or(Value::Undefined),
                None => {
                    let k = key_text(key);
                    if k.as_bytes() == b"length" {
                        Value::Num(items.len() as f64)
                    } else {
                        inherited(find_builtin(ProtoKind::Array, k.as_bytes(), protos, false), &k)
                    }
                }
            }
        }
        Value::Text(t) => match index(key) {
            Some(i) => match t.ascii_bytes() {
                Some(b) => b.get(i).map_or(Value::Undefined, |c| Value::Text(Text::from_bytes(&[*c]))),
                None => t.chars().nth(i).map_or(Value::Undefined, |c| Value::text(c.encode_utf8(&mut [0; 4]))),
            },
            None => {
                let k = key_text(key);
                if k.as_bytes() == b"length" {
                    Value::Num(t.ascii_bytes().map_or_else(|| t.chars().count(), <[u8]>::len) as f64)
                } else {
                    inherited(find_builtin(ProtoKind::String, k.as_bytes(), protos, false), &k)
                }
            }
        },
        Value::Null | Value::Undefined => {
            let what = if matches!(value, Value::Null) { "null" } else { "undefined" };
            return Err(type_error(format!("cannot read property '{}' of {what}", key_text(key))));
        }
        Value::Regex(r) => {
            let k = key_text(key);
            match r.0.property(&k) {
                Some(Property::Text(t)) => Value::text(t),
                Some(Property::Flag(b)) => Value::Bool(b),
                None => match regex::unsupported_member(&k) {
                    Some(why) => return Err(unsupported(why)),
                    None => inherited(find_builtin(ProtoKind::RegExp, k.as_bytes(), protos, false), &k),
                },
            }
        }
        Value::Func(f) => {
            let k = key_text(key);
            match function_own(f, k.as_bytes()) {
                Some(v) => v,
                None => inherited(find_builtin(ProtoKind::Function, k.as_bytes(), protos, false), &k),
            }
        }
        Value::Num(_) | Value::Bool(_) => {
            let kind = if matches!(value, Value::Num(_)) { ProtoKind::Number } else { ProtoKind::Boolean };
            let k = key_text(key);
            inherited(find_builtin(kind, k.as_bytes(), protos, false), &k)
        }
        Value::Output(_) => Value::Undefined,
    })
}

/// A property found along a chain, as a value; `undefined` when none.
fn inherited(found: Option<Found>, name: &Text) -> Value {
    found.map_or(Value::Undefined, |f| f.into_value(name))
}

/// `value[key] = v`.
pub(crate) fn set_member(value: &Value, key: &Value, v: Value) -> Result<()> {
    match value {
        Value::Object(o) => o.borrow_mut().set(key_text(key), v),
        Value::Array(items) => {
            let mut items = items.borrow_mut();
            match index(key) {
                Some(i) => {
                    if i >= items.len() {
                        items.resize(i + 1, Value::Undefined);
                    }
                    items[i] = v;
                }
                // `a.length = n` cuts or grows the array.
                None if key_text(key).as_bytes() == b"length" => {
                    let n = js_number(&v);
                    if n >= 0.0 && n.fract() == 0.0 && n <= MAX_ITEMS as f64 {
                        items.resize(n as usize, Value::Undefined);
                    }
                }
                None => {}
            }
        }
        Value::Null | Value::Undefined => {
            let what = if matches!(value, Value::Null) { "null" } else { "undefined" };
            return Err(type_error(format!("cannot set property '{}' of {what}", key_text(key))));
        }
        Value::Regex(_) => {
            if let Some(why) = regex::unsupported_member(&key_text(key)) {
                return Err(unsupported(why));
            }
        }
        // A function's own properties: `F.prototype = p` replaces its prototype.
        Value::Func(f) => props_of(f).borrow_mut().set(key_text(key), v),
        _ => {}
    }
    Ok(())
}

/// The names `for (k in value)` walks: the value's own, then, with the
/// run's prototypes, the enumerable ones of its prototype chain that it
/// does not have (what the post set there).
pub(crate) fn keys(value: &Value, chain: Option<&Protos>) -> Value {
    let mut names: Vec<Text> = match value {
        Value::Object(o) => {
            // ES2015 property order: array indices first, ascending, then
            // the other names in the order they were made.
            let o = o.borrow();
            let mut indices: Vec<(u32, &Text)> =
                o.keys.iter().filter_map(|k| array_index(k.as_str()).map(|i| (i, k))).collect();
            indices.sort_by_key(|(i, _)| *i);
            let names = o.keys.iter().filter(|k| array_index(k.as_str()).is_none());
            let hidden = |k: &&Text| o.hidden_constructor && k.as_bytes() == b"constructor";
            indices.into_iter().map(|(_, k)| k).chain(names).filter(|k| !hidden(k)).cloned().collect()
        }
        Value::Array(items) => (0..items.borrow().len()).map(|i| Text::new(&i.to_string())).collect(),
        Value::Text(t) => (0..t.chars().count()).map(|i| Text::new(&i.to_string())).collect(),
        // A function's `prototype` is not enumerable.
        Value::Func(f) => match f.props.get() {
            Some(p) => p.borrow().keys.iter().filter(|k| k.as_bytes() != b"prototype").cloned().collect(),
            None => Vec::new(),
        },
        _ => Vec::new(),
    };
    if let Some(protos) = chain {
        let inherited = protos::chain_keys(value, protos);
        names.extend(inherited.into_iter().filter(|k| !has_own(value, k)));
    }
    Value::array(names.into_iter().map(Value::Text).collect())
}

/// Whether a value has a property of its own (`hasOwnProperty`).
fn has_own(value: &Value, k: &Text) -> bool {
    let key = Value::Text(k.clone());
    match value {
        Value::Object(o) => o.borrow().find(k.as_bytes()).is_some(),
        Value::Array(items) => index(&key).is_some_and(|i| i < items.borrow().len()) || k.as_bytes() == b"length",
        Value::Text(t) => index(&key).is_some_and(|i| i < t.chars().count()) || k.as_bytes() == b"length",
        Value::Func(f) => function_own(f, k.as_bytes()).is_some(),
        _ => false,
    }
}

/// JavaScript `key in value`: the value's own properties and those of its
/// prototype chain (what the post added to the prototypes, and every
/// built-in property Node.js has); a TypeError for a value that is not an
/// object.
pub(crate) fn has_property(key: &Value, value: &Value, protos: &Protos) -> Result<Value> {
    let k = key_text(key);
    let found = match value {
        Value::Object(o) => find_in(&o.borrow(), k.as_bytes(), protos, true).is_some(),
        Value::Array(items) => {
            index(key).is_some_and(|i| i < items.borrow().len())
                || find_builtin(ProtoKind::Array, k.as_bytes(), protos, true).is_some()
        }
        Value::Func(f) => {
            function_own(f, k.as_bytes()).is_some()
                || find_builtin(ProtoKind::Function, k.as_bytes(), protos, true).is_some()
        }
        Value::Regex(_) => find_builtin(ProtoKind::RegExp, k.as_bytes(), protos, true).is_some(),
        Value::Output(_) => {
            matches!(k.as_str(), "format" | "reset" | "getLast") || js::prototype_has(ProtoKind::Object, &k)
        }
        _ => return Err(type_error(format!("cannot use 'in' to search for '{k}' in {}", describe(value)))),
    };
    Ok(Value::Bool(found))
}

/// The array index a property name is (`"2"`, not `"02"` or `"-1"`).
fn array_index(name: &str) -> Option<u32> {
    js::array_index(js::Key::Text(name))
}

impl Engine<'_> {
    /// A method of a format or an output variable held as a value: what
    /// `f.format(x)`, `v.format(x)`, `v.reset()` and `v.getLast()` do when
    /// the post names them directly.
    fn output_method(&mut self, output: OutputRef, name: &str, args: Vec<Value>, span: Option<Span>) -> Result<Value> {
        // The first argument taken, and the list kept as a spare.
        let mut args = args;
        let arg = args.first_mut().map_or(Value::Undefined, std::mem::take);
        self.give_back(args);
        let word = match (output, name) {
            (OutputRef::Format(f), "format") => {
                // The engine's reused buffer, as a named format's word is made.
                let mut buf = std::mem::take(&mut self.scratch);
                buf.clear();
                self.writers[f.index()].write(js_number(&arg), &mut buf);
                self.scratch_text(buf)
            }
            (OutputRef::Variable(v), "format") => self.format_through_var(v, arg),
            (OutputRef::Variable(v), "reset") => {
                self.forget_var(v);
                return Ok(Value::Undefined);
            }
            (OutputRef::Variable(v), "getLast") => return Ok(Value::Num(self.var_value(v).num())),
            (_, other) => return Err(type_error(format!("a format or output variable has no method '{other}'"))),
        };
        self.finite(span)?;
        Ok(word)
    }

    /// Calls a function value with `this` and arguments.
    pub(crate) fn call_value(&mut self, callee: &Value, this: Value, mut args: Vec<Value>) -> Result<Value> {
        let Value::Func(closure) = callee else {
            return Err(type_error(format!("{} is not a function", describe(callee))));
        };
        let closure: &Closure = closure;
        let function = match &closure.callee {
            Callee::Post(f) => *f,
            Callee::Method(kind, name) => return self.run_method(*kind, name, this, args),
        };
        if !closure.captures.is_empty() {
            // The captures, then the arguments, in spare storage.
            let mut all = self.spare();
            all.reserve(closure.captures.len() + args.len());
            for v in &closure.captures {
                all.push(v.clone());
            }
            all.append(&mut args);
            // The arguments' list is empty now: kept as a spare as it is.
            let emptied = std::mem::replace(&mut args, all);
            if self.spare_frames.len() < 64 {
                self.spare_frames.push(emptied);
            }
        }
        self.this_stack.push(this);
        let result = self.call(function, args);
        self.this_stack.pop();
        result
    }

    /// The one value of a post function that captures nothing, made when
    /// it is first needed.
    pub(crate) fn function_value(&mut self, function: FunctionId) -> Value {
        let i = function.index();
        if i >= self.function_values.len() {
            self.function_values.resize(self.post.functions.len().max(i + 1), None);
        }
        self.function_values[i].get_or_insert_with(|| closure(function, Vec::new())).clone()
    }

    /// The object a method runs on; outside a method, and in a function
    /// called as a value, JavaScript's global object (a post's functions
    /// are not strict-mode code).
    pub(crate) fn this(&self) -> Value {
        match self.this_stack.last() {
            Some(Value::Undefined) | None => Value::Object(self.global_object().object.clone()),
            Some(this) => this.clone(),
        }
    }

    /// The run's global object, made when first read.
    fn global_object(&self) -> &GlobalObject {
        self.global_object.get_or_init(|| GlobalObject::new(self.post))
    }

    /// Whether `value` is the global object.
    #[inline]
    pub(crate) fn is_global_object(&self, value: &Value) -> bool {
        match (value, self.global_object.get()) {
            (Value::Object(o), Some(g)) => std::rc::Rc::ptr_eq(o, &g.object),
            _ => false,
        }
    }

    /// `this[key]` on the global object: the post's global, function or
    /// output variable of that name, else a property set on the object.
    pub(crate) fn global_member(&mut self, key: &Value) -> Result<Value> {
        let k = key_text(key);
        let g = self.global_object();
        match g.names.get(k.as_bytes()).copied() {
            Some(GlobalName::Global(i)) => Ok(self.globals.get(i.index()).cloned().unwrap_or(Value::Undefined)),
            Some(GlobalName::Function(f)) => Ok(self.function_value(f)),
            Some(GlobalName::Variable(v)) => Ok(Value::Output(OutputRef::Variable(v))),
            None => member(&Value::Object(g.object.clone()), key, &self.protos),
        }
    }

    /// The property `name` set on the global object (`this.name = v`),
    /// if the post set one.
    pub(crate) fn global_property(&self, name: &Text) -> Option<Value> {
        self.global_object.get()?.object.borrow().get(name.as_bytes()).cloned()
    }

    /// `this[key] = v` on the global object: sets a property the post does
    /// not declare. Setting one of the post's own names this way is
    /// refused (RT039): `prepare` reads a global the post never assigns by
    /// name as the constant it starts as.
    pub(crate) fn set_global_member(&mut self, key: &Value, v: Value) -> Result<()> {
        let k = key_text(key);
        let g = self.global_object();
        if g.names.contains_key(k.as_bytes()) {
            return Err(Box::new(
                Diagnostic::error(
                    "RT039",
                    format!(
                        "postc does not set `{k}` through the global object (`this.{k} = ...`); assign it by its name"
                    ),
                )
                .note("no output is written"),
            ));
        }
        set_member(&Value::Object(g.object.clone()), key, v)
    }

    /// `object.method(args)`: the object's own function property, or one
    /// found along its prototype chain: a built-in method of arrays, texts,
    /// numbers and the rest, or a method the post added to a prototype.
    /// Calling a method that is on no chain is a TypeError at `span`.
    pub(crate) fn invoke(
        &mut self,
        object: Value,
        method: &Text,
        hint: &std::cell::Cell<u32>,
        args: Vec<Value>,
        span: Option<Span>,
    ) -> Result<Value> {
        // A built-in method of an array or a text (`words.push(w)`,
        // `f.substring(1)`), which nothing a post adds to a prototype
        // replaces (`find_builtin` answers built-ins first): run with no
        // search. A text's `replace` may call post code: found below.
        match &object {
            Value::Array(items) if let Some(m) = ArrayMethod::of(method.as_bytes()) => {
                let mut args = args;
                let result = self.array_method(items, m, &mut args);
                self.give_back(args);
                return result.map_err(|e| at(e, span));
            }
            Value::Text(t)
                if method.as_bytes() != b"replace" && protos::has_method(ProtoKind::String, method.as_bytes()) =>
            {
                let result = text_method(t, method, &args);
                self.give_back(args);
                return result.map_err(|e| at(e, span));
            }
            _ => {}
        }
        if self.is_global_object(&object) {
            let f = self.global_member(&Value::Text(method.clone()))?;
            return self.call_value(&f, object, args).map_err(|e| at(e, span));
        }
        let found = match &object {
            Value::Object(o) => {
                let o = o.borrow();
                // An own method, the commonest call: no walk, and found
                // through the site's inline cache (`crate::exec::Text`).
                match o.find_hinted(method.as_bytes(), hint) {
                    Some(i) if o.builtin.is_none() => Some(Found::Value(o.values[i].clone())),
                    _ => find_in(&o, method.as_bytes(), &self.protos, false),
                }
            }
            Value::Output(o) => return self.output_method(*o, method, args, span),
            Value::Null | Value::Undefined => {
                return Err(at(type_error(format!("cannot call method '{method}' of {}", describe(&object))), span));
            }
            Value::Regex(_) if let Some(why) = regex::unsupported_member(method) => return Err(unsupported(why)),
            Value::Func(f) if let Some(own) = function_own(f, method.as_bytes()) => Some(Found::Value(own)),
            other => kind_of(other).and_then(|kind| find_builtin(kind, method.as_bytes(), &self.protos, false)),
        };
        match found {
            Some(Found::Value(f)) => self.call_value(&f, object, args).map_err(|e| at(e, span)),
            Some(Found::Method(kind)) => self.run_method(kind, method, object, args).map_err(|e| at(e, span)),
            None => {
                let what = match &object {
                    Value::Object(_) => "the object".to_string(),
                    Value::Text(_) => "a text".to_string(),
                    other => describe(other),
                };
                Err(at(type_error(format!("{what} has no method '{method}'")), span))
            }
        }
    }

    /// `text.replace(pattern, f)`: each match (every one under the `g`
    /// flag, else the first; a text pattern its first occurrence) replaced
    /// by what `f(match, group 1, ..., index, text)` returns, as text.
    fn replace_by_function(&mut self, t: &Text, pattern: &Value, f: &Value) -> Result<Value> {
        let found = match pattern {
            Value::Regex(r) => regex::matches(&r.0, t).map_err(unsupported)?,
            other => {
                let needle = other.to_text();
                t.find(needle.as_str())
                    .map(|start| regex::Match {
                        start,
                        end: start + needle.len(),
                        groups: vec![Some(needle.to_string())],
                    })
                    .into_iter()
                    .collect()
            }
        };
        let mut out = String::with_capacity(t.len());
        let mut last = 0;
        for m in found {
            out.push_str(&t[last..m.start]);
            let mut args: Vec<Value> =
                m.groups.iter().map(|g| g.as_deref().map_or(Value::Undefined, Value::text)).collect();
            args.push(Value::Num(m.index(t)));
            args.push(Value::Text(t.clone()));
            let got = self.call_value(f, Value::Undefined, args)?;
            let got = self.text_of(got)?;
            got.append_to(&mut out);
            last = m.end;
        }
        out.push_str(&t[last.min(t.len())..]);
        Ok(Value::Text(Text::from(out)))
    }

    /// Runs the built-in method `name` of values of `kind` on `this` (a
    /// method called on a value, or held as a value and called with
    /// `call` or `apply`). A TypeError when `this` is not of that kind
    /// (texts take any value but null and undefined, as their text).
    fn run_method(&mut self, kind: ProtoKind, name: &str, this: Value, mut args: Vec<Value>) -> Result<Value> {
        let result = self.run_method_with(kind, name, this, &mut args);
        self.give_back(args);
        result
    }

    /// [`Self::run_method`] with its arguments, which it may take.
    fn run_method_with(&mut self, kind: ProtoKind, name: &str, this: Value, args: &mut Vec<Value>) -> Result<Value> {
        let arg = |i: usize| args.get(i).cloned().unwrap_or(Value::Undefined);
        let wrong =
            |this: &Value| type_error(format!("{}.prototype.{name} called on {}", kind.constructor(), describe(this)));
        match (kind, &this) {
            (ProtoKind::Object, _) => self.object_method(name, this, args),
            (ProtoKind::Array, Value::Array(items)) => match ArrayMethod::of(name.as_bytes()) {
                Some(m) => self.array_method(items, m, args),
                None => Err(type_error(format!("an array has no method '{name}'"))),
            },
            (ProtoKind::String, Value::Null | Value::Undefined) => Err(wrong(&this)),
            // A function as the replacement: called with each match, its
            // groups, its index and the text, as JavaScript does, when the
            // post's options allow it (a post with no script tier).
            (ProtoKind::String, Value::Text(t))
                if name == "replace"
                    && matches!(args.get(1), Some(Value::Func(_)))
                    && self.post.options.function_replacements =>
            {
                let (pattern, with) = (arg(0), arg(1));
                self.replace_by_function(t, &pattern, &with)
            }
            (ProtoKind::String, Value::Text(t)) => text_method(t, name, args),
            (ProtoKind::String, other) => text_method(&other.to_text(), name, args),
            (ProtoKind::Number, Value::Num(n)) => match name {
                "toFixed" => Ok(Value::text(&js::to_fixed(*n, js_number(&arg(0)).max(0.0)))),
                "toPrecision" => match arg(0) {
                    Value::Undefined => Ok(Value::text(&js::number_to_string(*n))),
                    p => js::to_precision(*n, js_number(&p)).map(|s| Value::text(&s)).map_err(type_error),
                },
                "toString" => match arg(0) {
                    Value::Undefined => Ok(Value::text(&js::number_to_string(*n))),
                    r => js::radix_string(*n, js_number(&r)).map(|s| Value::text(&s)).map_err(type_error),
                },
                "valueOf" => Ok(this.clone()),
                other => Err(type_error(format!("a number has no method '{other}'"))),
            },
            (ProtoKind::Boolean, Value::Bool(_)) => match name {
                "toString" => Ok(Value::Text(this.to_text())),
                _ => Ok(this.clone()),
            },
            (ProtoKind::Function, Value::Func(_)) => match name {
                "call" => {
                    let this_arg = arg(0);
                    let mut rest = self.spare();
                    rest.extend(args.drain(..).skip(1));
                    self.call_value(&this, this_arg, rest)
                }
                "apply" => {
                    let list = match arg(1) {
                        Value::Array(items) => items.borrow().clone(),
                        _ => Vec::new(),
                    };
                    self.call_value(&this, arg(0), list)
                }
                _ => Ok(Value::Text(this.to_text())),
            },
            (ProtoKind::RegExp, Value::Regex(r)) => match name {
                "test" => {
                    let text = arg(0).to_text();
                    r.0.test(&text).map(Value::Bool).map_err(unsupported)
                }
                _ => Ok(Value::Text(this.to_text())),
            },
            _ => Err(wrong(&this)),
        }
    }

    /// The built-in methods of `Object.prototype`, on any `this`.
    fn object_method(&mut self, name: &str, this: Value, args: &mut [Value]) -> Result<Value> {
        let arg = args.first_mut().map(std::mem::take).unwrap_or(Value::Undefined);
        Ok(match name {
            "hasOwnProperty" => match &this {
                Value::Null | Value::Undefined => {
                    return Err(type_error("Cannot convert undefined or null to object".into()));
                }
                _ => Value::Bool(has_own(&this, &key_text(&arg))),
            },
            "isPrototypeOf" => match &this {
                Value::Object(o) => Value::Bool(protos::chain_has(&arg, o, &self.protos)),
                _ => Value::Bool(false),
            },
            "toString" => protos::tag(&this),
            "valueOf" => this,
            other => return Err(type_error(format!("the object has no method '{other}'"))),
        })
    }

    fn array_method(
        &mut self,
        items: &std::rc::Rc<std::cell::RefCell<Vec<Value>>>,
        method: ArrayMethod,
        args: &mut Vec<Value>,
    ) -> Result<Value> {
        let arg = |i: usize| args.get(i).cloned().unwrap_or(Value::Undefined);
        let len = items.borrow().len();
        // A relative index (`slice(-2)`) as an offset into the array.
        let at = |v: Value, default: usize| match v {
            Value::Undefined => default,
            v => {
                let x = js_number(&v);
                let x = if x.is_nan() { 0.0 } else { x.trunc() };
                if x < 0.0 { (len as f64 + x).max(0.0) as usize } else { (x as usize).min(len) }
            }
        };
        Ok(match method {
            ArrayMethod::Push => {
                let mut items = items.borrow_mut();
                if items.len() + args.len() > MAX_ITEMS {
                    return Err(too_many());
                }
                items.extend(args.drain(..));
                Value::Num(items.len() as f64)
            }
            ArrayMethod::Pop => items.borrow_mut().pop().unwrap_or(Value::Undefined),
            ArrayMethod::Shift => {
                let mut items = items.borrow_mut();
                if items.is_empty() { Value::Undefined } else { items.remove(0) }
            }
            ArrayMethod::Unshift => {
                let mut items = items.borrow_mut();
                if items.len() + args.len() > MAX_ITEMS {
                    return Err(too_many());
                }
                items.splice(0..0, args.drain(..));
                Value::Num(items.len() as f64)
            }
            ArrayMethod::Join => {
                let sep = match arg(0) {
                    Value::Undefined => Text::new(","),
                    v => key_text(&v),
                };
                // An object's text is its `toString`'s (post code, which
                // may change the array: the items are read first).
                let mut texts = Vec::new();
                if items.borrow().iter().any(|v| matches!(v, Value::Object(_))) {
                    let list = items.borrow().clone();
                    for v in list {
                        texts.push(if let Value::Object(_) = v { self.text_of(v)? } else { v });
                    }
                }
                // Built as bytes in the engine's reused buffer: a text is
                // copied as it is (its bytes are UTF-8 already, and a
                // short one is copied whole), so the result is checked
                // once, not each part; only the result is allocated, and
                // a short one not at all.
                let mut s = std::mem::take(&mut self.scratch);
                s.clear();
                // Another value's text (a number) is written in the text
                // buffer of `+` chains first.
                let mut other_text = std::mem::take(&mut self.chain_text);
                let list = items.borrow();
                let list = if texts.is_empty() { &list[..] } else { &texts[..] };
                for (i, item) in list.iter().enumerate() {
                    if i > 0 {
                        sep.append_to_bytes(&mut s);
                    }
                    match item {
                        Value::Null | Value::Undefined => {}
                        Value::Text(t) => t.append_to_bytes(&mut s),
                        other => {
                            other_text.clear();
                            other.append_to(&mut other_text);
                            s.extend_from_slice(other_text.as_bytes());
                        }
                    }
                    if s.len() > crate::interp::MAX_TEXT_BYTES {
                        let len = s.len();
                        (self.scratch, self.chain_text) = (s, other_text);
                        return Err(Box::new(crate::interp::text_budget_error(len)));
                    }
                }
                let joined = Value::Text(Text::from_bytes(&s));
                (self.scratch, self.chain_text) = (s, other_text);
                joined
            }
            ArrayMethod::IndexOf => {
                let target = arg(0);
                let from = at(arg(1), 0);
                let found = items.borrow().iter().skip(from).position(|v| super::ops::strict_eq(v, &target));
                Value::Num(found.map_or(-1.0, |i| (i + from) as f64))
            }
            ArrayMethod::Slice => {
                let (a, b) = (at(arg(0), 0), at(arg(1), len));
                let mut part = self.spare();
                if a < b {
                    part.extend_from_slice(&items.borrow()[a..b]);
                }
                self.new_array(part)
            }
            ArrayMethod::Concat => {
                let mut all = self.spare();
                all.extend_from_slice(&items.borrow());
                for a in args.drain(..) {
                    match a {
                        Value::Array(more) => all.extend(more.borrow().iter().cloned()),
                        other => all.push(other),
                    }
                }
                if all.len() > MAX_ITEMS {
                    self.give_back(all);
                    return Err(too_many());
                }
                self.new_array(all)
            }
            ArrayMethod::Reverse => {
                items.borrow_mut().reverse();
                Value::Array(items.clone())
            }
            ArrayMethod::Splice => {
                let start = at(arg(0), 0);
                let count = match args.get(1) {
                    None => len - start,
                    Some(v) => (js_number(v).max(0.0) as usize).min(len - start),
                };
                let added: Vec<Value> = args.iter().skip(2).cloned().collect();
                let removed: Vec<Value> = items.borrow_mut().splice(start..start + count, added).collect();
                Value::array(removed)
            }
            ArrayMethod::ForEach | ArrayMethod::Map | ArrayMethod::Filter | ArrayMethod::Some | ArrayMethod::Every => {
                let f = arg(0);
                // A callback that only returns a plain expression runs with
                // no call made, in one frame for the whole walk
                // (`Engine::run_callback_in`). It runs no post code, so the
                // array stays as it is while it runs: its items are read
                // where they are, one at a time. Any other callback walks
                // the items as they were when the method was called, a
                // snapshot in spare storage.
                let callback = self.callback_function(&f);
                let mut snapshot = self.spare();
                if callback.is_none() {
                    snapshot.extend(items.borrow().iter().cloned());
                }
                let count = if callback.is_some() { len } else { snapshot.len() };
                let mut out = self.spare();
                let mut decided = None;
                // Which of the five, told once for the whole walk.
                let each = match method {
                    ArrayMethod::Map => Each::Map,
                    ArrayMethod::Filter => Each::Filter,
                    ArrayMethod::Some => Each::Some,
                    ArrayMethod::Every => Each::Every,
                    _ => Each::Visit,
                };
                let mut frame = self.spare();
                for i in 0..count {
                    let item = match callback {
                        Some(_) => items.borrow().get(i).cloned().unwrap_or(Value::Undefined),
                        None => snapshot.get_mut(i).map_or(Value::Undefined, std::mem::take),
                    };
                    let called = match callback {
                        Some(id) => self.run_callback_in(id, [&item, &Value::Num(i as f64)], items, &mut frame),
                        None => {
                            let mut call_args = self.spare();
                            call_args.extend([item.clone(), Value::Num(i as f64), Value::Array(items.clone())]);
                            self.call_value(&f, Value::Undefined, call_args)
                        }
                    };
                    let r = match called {
                        Ok(r) => r,
                        Err(e) => {
                            decided = Some(Err(e));
                            break;
                        }
                    };
                    // What the walk does not keep is let go where it is,
                    // with no drop call (`Value::let_go`).
                    let truthy = r.truthy();
                    match each {
                        Each::Map => {
                            out.push(r);
                            item.let_go();
                        }
                        Each::Filter => {
                            r.let_go();
                            if truthy {
                                out.push(item);
                            } else {
                                item.let_go();
                            }
                        }
                        Each::Some if truthy => {
                            decided = Some(Ok(Value::Bool(true)));
                            break;
                        }
                        Each::Every if !truthy => {
                            decided = Some(Ok(Value::Bool(false)));
                            break;
                        }
                        _ => {
                            r.let_go();
                            item.let_go();
                        }
                    }
                }
                self.give_back(frame);
                self.give_back(snapshot);
                if let Some(decided) = decided {
                    self.give_back(out);
                    return decided;
                }
                if matches!(method, ArrayMethod::Map | ArrayMethod::Filter) {
                    return Ok(self.new_array(out));
                }
                self.give_back(out);
                match method {
                    ArrayMethod::Some => Value::Bool(false),
                    ArrayMethod::Every => Value::Bool(true),
                    _ => Value::Undefined,
                }
            }
            ArrayMethod::Sort => {
                let f = arg(0);
                let mut list = items.borrow().clone();
                // Insertion sort with the post's comparison (stable, as
                // ES2019 requires; posts sort a handful of items).
                for i in 1..list.len() {
                    let mut j = i;
                    while j > 0 {
                        let order = match &f {
                            Value::Undefined => {
                                if list[j - 1].to_text() > list[j].to_text() {
                                    1.0
                                } else {
                                    0.0
                                }
                            }
                            f => js_number(&self.call_value(
                                f,
                                Value::Undefined,
                                vec![list[j - 1].clone(), list[j].clone()],
                            )?),
                        };
                        if order > 0.0 {
                            list.swap(j - 1, j);
                            j -= 1;
                        } else {
                            break;
                        }
                    }
                }
                *items.borrow_mut() = list;
                Value::Array(items.clone())
            }
            ArrayMethod::ToString => Value::Text(Value::Array(items.clone()).to_text()),
        })
    }
}

/// The built-in methods of a text.
fn text_method(t: &Text, name: &str, args: &[Value]) -> Result<Value> {
    let arg = |i: usize| args.get(i).cloned().unwrap_or(Value::Undefined);
    // ASCII text is indexed by its bytes, one character each, with no
    // list of characters made (`f.substring(1)` of a feed word).
    let bytes = t.ascii_bytes().filter(|_| matches!(name, "substring" | "substr" | "slice" | "charAt" | "charCodeAt"));
    let chars: Vec<char> = if bytes.is_some() { Vec::new() } else { t.chars().collect() };
    let len = bytes.map_or(chars.len(), <[u8]>::len);
    let int = |v: Value, default: f64| match v {
        Value::Undefined => default,
        v => {
            let x = js_number(&v);
            if x.is_nan() { 0.0 } else { x.trunc() }
        }
    };
    let slice = |a: usize, b: usize| {
        let (a, b) = (a.min(len), b.min(len).max(a.min(len)));
        match bytes {
            Some(bytes) => Value::Text(Text::from_bytes(&bytes[a..b])),
            None => Value::text(&chars[a..b].iter().collect::<String>()),
        }
    };
    let rel = |x: f64| if x < 0.0 { (len as f64 + x).max(0.0) as usize } else { (x as usize).min(len) };
    Ok(match name {
        "substring" => {
            let a = int(arg(0), 0.0).clamp(0.0, len as f64) as usize;
            let b = int(arg(1), len as f64).clamp(0.0, len as f64) as usize;
            slice(a.min(b), a.max(b))
        }
        "substr" => {
            let a = rel(int(arg(0), 0.0));
            let n = int(arg(1), len as f64).max(0.0) as usize;
            slice(a, a.saturating_add(n))
        }
        "slice" => {
            let (a, b) = (rel(int(arg(0), 0.0)), rel(int(arg(1), len as f64)));
            if a < b { slice(a, b) } else { Value::text("") }
        }
        "charAt" => {
            let i = int(arg(0), 0.0);
            if i >= 0.0 && (i as usize) < len { slice(i as usize, i as usize + 1) } else { Value::text("") }
        }
        "charCodeAt" => {
            let i = int(arg(0), 0.0);
            if i >= 0.0 && (i as usize) < len {
                Value::Num(match bytes {
                    Some(bytes) => f64::from(bytes[i as usize]),
                    None => f64::from(chars[i as usize] as u32),
                })
            } else {
                Value::Num(f64::NAN)
            }
        }
        "indexOf" | "lastIndexOf" => {
            let needle: Vec<char> = key_text(&arg(0)).chars().collect();
            let fits = |i: usize| i + needle.len() <= len && chars[i..i + needle.len()] == needle[..];
            let found = if name == "indexOf" {
                let from = int(arg(1), 0.0).clamp(0.0, len as f64) as usize;
                (from..=len).find(|&i| fits(i))
            } else {
                let from = int(arg(1), len as f64).clamp(0.0, len as f64) as usize;
                (0..=from.min(len)).rev().find(|&i| fits(i))
            };
            Value::Num(found.map_or(-1.0, |i| i as f64))
        }
        "toUpperCase" | "toLocaleUpperCase" => Value::text(&t.to_uppercase()),
        "toLowerCase" | "toLocaleLowerCase" => Value::text(&t.to_lowercase()),
        "trim" => Value::text(t.trim()),
        "trimStart" | "trimLeft" => Value::text(t.trim_start()),
        "trimEnd" | "trimRight" => Value::text(t.trim_end()),
        "startsWith" | "endsWith" | "includes" => {
            let needle: Vec<char> = key_text(&arg(0)).chars().collect();
            let fits = |i: usize| i + needle.len() <= len && chars[i..i + needle.len()] == needle[..];
            Value::Bool(match name {
                "startsWith" => fits(int(arg(1), 0.0).clamp(0.0, len as f64) as usize),
                "endsWith" => {
                    let end = int(arg(1), len as f64).clamp(0.0, len as f64) as usize;
                    end >= needle.len() && fits(end - needle.len())
                }
                _ => (int(arg(1), 0.0).clamp(0.0, len as f64) as usize..=len).any(fits),
            })
        }
        "repeat" => {
            let n = int(arg(0), 0.0);
            if !(0.0..f64::INFINITY).contains(&n) {
                return Err(Box::new(Diagnostic::error(
                    TYPE_ERROR,
                    format!("RangeError: Invalid count value: {}", js::number_to_string(n)),
                )));
            }
            let bytes = (n as usize).saturating_mul(t.len());
            if bytes > crate::interp::MAX_TEXT_BYTES {
                return Err(Box::new(crate::interp::text_budget_error(bytes)));
            }
            Value::text(&t.repeat(n as usize))
        }
        "padStart" | "padEnd" => {
            let target = int(arg(0), 0.0).max(0.0) as usize;
            let fill: Vec<char> = match arg(1) {
                Value::Undefined => vec![' '],
                v => key_text(&v).chars().collect(),
            };
            if target > crate::interp::MAX_TEXT_BYTES {
                return Err(Box::new(crate::interp::text_budget_error(target)));
            }
            if target <= len || fill.is_empty() {
                Value::Text(t.clone())
            } else {
                let pad: String = fill.iter().cycle().take(target - len).collect();
                Value::text(&if name == "padStart" { pad + t.as_ref() } else { t.to_string() + &pad })
            }
        }
        "split" => {
            let parts: Vec<Value> = match arg(0) {
                Value::Undefined => vec![Value::Text(t.clone())],
                Value::Regex(r) => regex::split(&r.0, t).map_err(unsupported)?.iter().map(|p| Value::text(p)).collect(),
                sep => {
                    let sep = key_text(&sep);
                    if sep.is_empty() {
                        chars.iter().map(|c| Value::text(c.encode_utf8(&mut [0; 4]))).collect()
                    } else {
                        t.split(sep.as_str()).map(Value::text).collect()
                    }
                }
            };
            Value::array(parts)
        }
        "replace" => {
            let with = match arg(1) {
                Value::Func(_) => return Err(unsupported(regex::FUNCTION_REPLACEMENT.to_string())),
                v => v.to_text(),
            };
            let out = match arg(0) {
                Value::Regex(r) => regex::replace(&r.0, t, &with).map_err(unsupported)?,
                pattern => regex::replace_text(t, &pattern.to_text(), &with),
            };
            Value::Text(Text::from(out))
        }
        "match" => {
            // A text pattern is made a regular expression, as JavaScript
            // does; the `g` flag gives every match's text, else the first
            // match and its groups (`undefined` for a group that took no
            // part). postc's arrays hold no `index` or `input`.
            let re = match arg(0) {
                Value::Regex(r) => r.0.clone(),
                Value::Undefined => std::rc::Rc::new(regex::Regex::new("(?:)", "").map_err(type_error)?),
                pattern => std::rc::Rc::new(
                    regex::Regex::new(&pattern.to_text(), "")
                        .map_err(|e| type_error(format!("the pattern of `match` does not read: {e}")))?,
                ),
            };
            let found = regex::matches(&re, t).map_err(unsupported)?;
            if found.is_empty() {
                Value::Null
            } else if re.global() {
                Value::array(found.iter().map(|m| Value::text(&t[m.start..m.end])).collect())
            } else {
                let groups = found.into_iter().next().map(|m| m.groups).unwrap_or_default();
                Value::array(groups.into_iter().map(|g| g.map_or(Value::Undefined, |g| Value::text(&g))).collect())
            }
        }
        "search" => Value::Num(match arg(0) {
            Value::Regex(r) => regex::search(&r.0, t).map_err(unsupported)?,
            pattern => regex::search_text(t, &pattern.to_text())
                .map_err(|e| type_error(format!("the pattern of `search` does not read: {e}")))?,
        }),
        "concat" => {
            let mut s = t.to_string();
            args.iter().for_each(|a| a.append_to(&mut s));
            Value::Text(Text::from(s))
        }
        "toString" | "valueOf" => Value::Text(t.clone()),
        other => return Err(type_error(format!("a text has no method '{other}'"))),
    })
}

fn too_many() -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(
            crate::interp::TEXT_BUDGET,
            format!("the post built an array of more than {MAX_ITEMS} items and was stopped"),
        )
        .note("no output is written"),
    )
}

/// How a value is named in a type error.
pub(crate) fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Undefined => "undefined".into(),
        Value::Text(t) => format!("the text \"{t}\""),
        Value::Num(n) => format!("the number {}", js::number_to_string(*n)),
        Value::Bool(b) => format!("{b}"),
        Value::Array(_) => "an array".into(),
        Value::Object(_) => "an object".into(),
        Value::Func(_) => "a function".into(),
        Value::Output(_) => "a format or output variable".into(),
        Value::Regex(r) => format!("the regular expression {}", r.0.to_text()),
    }
}

/// A new object of properties.
pub(crate) fn object(props: Vec<(Text, Value)>) -> Value {
    let mut o = Object::default();
    for (k, v) in props {
        o.set(k, v);
    }
    Value::object(o)
}

/// A new function value.
pub(crate) fn closure(function: FunctionId, captures: Vec<Value>) -> Value {
    Value::Func(std::rc::Rc::new(Closure::post(function, captures)))
}

/// An error placed at `span` when it has no place yet (a TypeError of
/// the call the post wrote there, not one from inside the function it
/// called).
pub(crate) fn at(e: Box<Diagnostic>, span: Option<Span>) -> Box<Diagnostic> {
    match span {
        Some(s) if e.primary_span().is_none() => Box::new(e.at(s, "here")),
        _ => e,
    }
}

/// The error of a value thrown and not caught, at the `throw`.
pub(crate) fn uncaught(value: &Value, span: Option<Span>) -> Box<Diagnostic> {
    let text = match value {
        Value::Object(o) => {
            let o = o.borrow();
            match (o.get(b"name"), o.get(b"message")) {
                (Some(n), Some(m)) => format!("{}: {}", n.to_text(), m.to_text()),
                (None, Some(m)) => m.to_text().to_string(),
                _ => "[object Object]".into(),
            }
        }
        other => other.to_text().to_string(),
    };
    let d = Diagnostic::error(THROWN, format!("the post stopped with an error it threw: {text}"))
        .note("no output is written");
    Box::new(match span {
        Some(s) => d.at(s, "thrown here"),
        None => d,
    })
}

/// The built-in methods of arrays, told from their names once: a call
/// (`words.push(w)`) is told by `invoke` and run by `array_method` with no
/// second look at the name.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum ArrayMethod {
    Push,
    Pop,
    Shift,
    Unshift,
    Join,
    IndexOf,
    Slice,
    Concat,
    Reverse,
    Splice,
    ForEach,
    Map,
    Filter,
    Some,
    Every,
    Sort,
    ToString,
}

impl ArrayMethod {
    /// The built-in array method of this name, if there is one.
    pub(crate) fn of(name: &[u8]) -> Option<ArrayMethod> {
        Some(match name {
            b"push" => ArrayMethod::Push,
            b"pop" => ArrayMethod::Pop,
            b"shift" => ArrayMethod::Shift,
            b"unshift" => ArrayMethod::Unshift,
            b"join" => ArrayMethod::Join,
            b"indexOf" => ArrayMethod::IndexOf,
            b"slice" => ArrayMethod::Slice,
            b"concat" => ArrayMethod::Concat,
            b"reverse" => ArrayMethod::Reverse,
            b"splice" => ArrayMethod::Splice,
            b"forEach" => ArrayMethod::ForEach,
            b"map" => ArrayMethod::Map,
            b"filter" => ArrayMethod::Filter,
            b"some" => ArrayMethod::Some,
            b"every" => ArrayMethod::Every,
            b"sort" => ArrayMethod::Sort,
            b"toString" => ArrayMethod::ToString,
            _ => return None,
        })
    }
}

/// Which array method walks its items with a callback (`Visit`: forEach).
#[derive(Clone, Copy)]
enum Each {
    Visit,
    Map,
    Filter,
    Some,
    Every,
}
