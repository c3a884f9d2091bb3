//! The methods of texts and arrays in translated scripts: `substr`,
//! `indexOf`, `split` and `replace` (with regular expressions), `push`,
//! `join`, `slice`, ...

use rhai::{Array, Dynamic, EvalAltResult};

use postc_runtime::regex;
use rhai::Position;

use crate::ops::{fail, unsupported};
use crate::values::{self, JsArr, JsRegex, num, text, to_number, to_string};

type R = Result<Dynamic, Box<EvalAltResult>>;

fn arg(args: &Array, i: usize) -> Dynamic {
    args.get(i).cloned().unwrap_or(Dynamic::UNIT)
}

fn clamp_index(v: f64, len: usize) -> usize {
    if v.is_nan() {
        0
    } else if v < 0.0 {
        (len as f64 + v).max(0.0) as usize
    } else {
        (v as usize).min(len)
    }
}

/// `s.name(args)`; `at` is the call, where an error of what postc does
/// not run is reported.
pub(super) fn string_method(s: &str, name: &str, args: &Array, at: Position) -> R {
    let chars: Vec<char> = s.chars().collect();
    let len = chars.len();
    let a = |i: usize| arg(args, i);
    let sub = |from: usize, to: usize| -> Dynamic {
        text(chars[from.min(len)..to.min(len).max(from.min(len))].iter().collect::<String>())
    };
    Ok(match name {
        "toUpperCase" => text(s.to_uppercase()),
        "toLowerCase" => text(s.to_lowercase()),
        "toString" | "valueOf" => text(s),
        "trim" => text(s.trim()),
        "charAt" => {
            let i = to_number(&a(0));
            text(if i >= 0.0 && (i as usize) < len { chars[i as usize].to_string() } else { String::new() })
        }
        "charCodeAt" => {
            let i = if a(0).is_unit() { 0.0 } else { to_number(&a(0)) };
            num(if i >= 0.0 && (i as usize) < len { f64::from(chars[i as usize] as u32) } else { f64::NAN })
        }
        "indexOf" | "lastIndexOf" => {
            let needle: Vec<char> = to_string(&a(0)).chars().collect();
            let found = if name == "indexOf" {
                let from = if a(1).is_unit() { 0 } else { clamp_index(to_number(&a(1)).max(0.0), len) };
                (from..=len.saturating_sub(needle.len()))
                    .find(|&i| i + needle.len() <= len && chars[i..i + needle.len()] == needle[..])
            } else {
                // The search starts at `fromIndex` (JavaScript: NaN or
                // missing is +Infinity; below 0 is 0) and runs backwards.
                let from = match a(1) {
                    v if v.is_unit() => usize::MAX,
                    v => {
                        let n = to_number(&v);
                        if n.is_nan() { usize::MAX } else { n.max(0.0).min(usize::MAX as f64) as usize }
                    }
                };
                (0..=len.saturating_sub(needle.len()).min(from))
                    .rev()
                    .find(|&i| i + needle.len() <= len && chars[i..i + needle.len()] == needle[..])
            };
            num(found.map_or(-1.0, |i| i as f64))
        }
        "substring" => {
            let f = |v: Dynamic, d: usize| if v.is_unit() { d } else { clamp_index(to_number(&v).max(0.0), len) };
            let (x, y) = (f(a(0), 0), f(a(1), len));
            sub(x.min(y), x.max(y))
        }
        "substr" => {
            let start = if a(0).is_unit() { 0 } else { clamp_index(to_number(&a(0)), len) };
            let count = if a(1).is_unit() { len } else { to_number(&a(1)).max(0.0).min(len as f64) as usize };
            sub(start, start + count)
        }
        "slice" => {
            let start = if a(0).is_unit() { 0 } else { clamp_index(to_number(&a(0)), len) };
            let end = if a(1).is_unit() { len } else { clamp_index(to_number(&a(1)), len) };
            sub(start, end)
        }
        "concat" => {
            let mut out = s.to_string();
            for x in args {
                out.push_str(&to_string(x));
            }
            text(out)
        }
        "split" => {
            let sep = a(0);
            let parts: Vec<String> = if sep.is_unit() {
                vec![s.to_string()]
            } else if let Some(r) = sep.clone().try_cast::<JsRegex>() {
                regex::split(&r.0.0, s).map_err(|e| unsupported(e, at))?
            } else {
                let sep = to_string(&sep);
                if sep.is_empty() {
                    chars.iter().map(|c| c.to_string()).collect()
                } else {
                    s.split(sep.as_str()).map(String::from).collect()
                }
            };
            Dynamic::from(JsArr::new(parts.into_iter().map(text).collect()))
        }
        "replace" => {
            let with = a(1);
            if with.is::<rhai::FnPtr>()
                || with.clone().try_cast::<values::JsObj>().is_some_and(|o| o.function().is_some())
            {
                return Err(unsupported(regex::FUNCTION_REPLACEMENT.to_string(), at));
            }
            let with = to_string(&with);
            match a(0).try_cast::<JsRegex>() {
                Some(r) => text(regex::replace(&r.0.0, s, &with).map_err(|e| unsupported(e, at))?),
                None => text(regex::replace_text(s, &to_string(&a(0)), &with)),
            }
        }
        // As the interpreter's `match` (postc_runtime's `text_method`).
        "match" => {
            let made;
            let re = match a(0).try_cast::<JsRegex>() {
                Some(r) => {
                    made = r.0.0.clone();
                    &made
                }
                None => {
                    let pattern = if a(0).is_unit() { "(?:)".to_string() } else { to_string(&a(0)) };
                    made = std::rc::Rc::new(
                        regex::Regex::new(&pattern, "").map_err(|e| fail(format!("SyntaxError: {e}")))?,
                    );
                    &made
                }
            };
            let found = regex::matches(re, s).map_err(|e| unsupported(e, at))?;
            if found.is_empty() {
                Dynamic::from(values::JsNull)
            } else if re.global() {
                Dynamic::from(JsArr::new(found.iter().map(|m| text(&s[m.start..m.end])).collect()))
            } else {
                let groups = found.into_iter().next().map(|m| m.groups).unwrap_or_default();
                Dynamic::from(JsArr::new(groups.into_iter().map(|g| g.map_or(Dynamic::UNIT, text)).collect()))
            }
        }
        "search" => match a(0).try_cast::<JsRegex>() {
            Some(r) => num(regex::search(&r.0.0, s).map_err(|e| unsupported(e, at))?),
            None => num(regex::search_text(s, &to_string(&a(0))).map_err(|e| fail(format!("SyntaxError: {e}")))?),
        },
        _ => return Err(fail(format!("TypeError: text has no method '{name}'"))),
    })
}

pub(super) fn array_method(a: &JsArr, name: &str, args: Array) -> R {
    let len = a.0.borrow().len();
    Ok(match name {
        "push" => {
            let mut items = a.0.borrow_mut();
            items.extend(args);
            num(items.len() as f64)
        }
        "pop" => a.0.borrow_mut().pop().unwrap_or(Dynamic::UNIT),
        "shift" => {
            let mut items = a.0.borrow_mut();
            if items.is_empty() { Dynamic::UNIT } else { items.remove(0) }
        }
        "unshift" => {
            let mut items = a.0.borrow_mut();
            for (i, x) in args.into_iter().enumerate() {
                items.insert(i, x);
            }
            num(items.len() as f64)
        }
        "join" => {
            let sep = if args.first().is_none_or(|s| s.is_unit()) { ",".to_string() } else { to_string(&args[0]) };
            let items = a.0.borrow();
            let parts: Vec<String> = items
                .iter()
                .map(|x| if x.is_unit() || values::is_null(x) { String::new() } else { to_string(x) })
                .collect();
            text(parts.join(&sep))
        }
        "toString" => text(to_string(&Dynamic::from(a.clone()))),
        "indexOf" => {
            let x = arg(&args, 0);
            num(a.0.borrow().iter().position(|y| values::strict_eq(&x, y)).map_or(-1.0, |i| i as f64))
        }
        "slice" => {
            let start = if arg(&args, 0).is_unit() { 0 } else { clamp_index(to_number(&arg(&args, 0)), len) };
            let end = if arg(&args, 1).is_unit() { len } else { clamp_index(to_number(&arg(&args, 1)), len) };
            let items = a.0.borrow();
            Dynamic::from(JsArr::new(items[start.min(end)..end].to_vec()))
        }
        "concat" => {
            let mut items = a.0.borrow().clone();
            for x in args {
                match x.clone().try_cast::<JsArr>() {
                    Some(other) => items.extend(other.0.borrow().iter().cloned()),
                    None => items.push(x),
                }
            }
            Dynamic::from(JsArr::new(items))
        }
        "reverse" => {
            a.0.borrow_mut().reverse();
            Dynamic::from(a.clone())
        }
        _ => return Err(fail(format!("TypeError: an array has no method '{name}'"))),
    })
}
