//! The CNC-Calc host: output variables and formats (`format`, `getLast`,
//! bound at compile time or made by `createFormat` / `createVariable` while
//! the post runs), `getFeedrate`, the compensation passed to
//! `onCompensation`, the `drillHeader` objects of `onDrillingHeader` and
//! `onDrilling`, and the global functions. `docs/cimco.md` gives the
//! rules.

use std::cell::RefCell;
use std::rc::Rc;

use postc_front_cimco::host_names as names;
use postc_ir::event::{CompSide, DrillKind};
use postc_ir::{Justify, NumberFormat, Padding, PointStyle, SignStyle, WidthOf};
use rhai::{Array, Dynamic, Engine, EvalAltResult, NativeCallContext};

use crate::compiled::{Context, Shared, State};
use crate::ops::fail;
use crate::values::{
    self, DynFormat, DynVar, DynVarState, FmtRef, JsArr, JsObj, ObjKind, VarRef, num, text, to_number, to_string,
};
use postc_runtime::js;
use postc_runtime::number::NumberWriter;
use postc_runtime::value::Value;

type R = Result<Dynamic, Box<EvalAltResult>>;

pub fn register(engine: &mut Engine, state: &Shared) {
    engine.register_type_with_name::<VarRef>("variable");
    engine.register_type_with_name::<FmtRef>("format");
    engine.register_type_with_name::<DynVar>("variable");
    engine.register_type_with_name::<DynFormat>("format");
    engine.register_fn(names::VAR_REF, |id: i64| VarRef(id as u16));
    engine.register_fn(names::FORMAT_REF, |id: i64| FmtRef(id as u16));
    let s = state.clone();
    engine.register_fn(names::VAR_FORMAT, move |ctx: NativeCallContext, id: i64, v: Dynamic| {
        finite(text(format_var(&mut s.borrow_mut(), id as u16, to_number(&v))), ctx.call_position())
    });
    let s = state.clone();
    engine.register_fn(names::VAR_LAST, move |id: i64| num(last(&s.borrow(), id as u16)));
    let s = state.clone();
    engine.register_fn(names::FORMAT_FORMAT, move |ctx: NativeCallContext, id: i64, v: Dynamic| {
        finite(text(format_with(&s.borrow(), id as u16, to_number(&v))), ctx.call_position())
    });
    let s = state.clone();
    engine.register_fn(names::FEEDRATE, move |ctx: NativeCallContext, m: Dynamic| {
        finite(text(feedrate(&mut s.borrow_mut(), &m)), ctx.call_position())
    });
    let s = state.clone();
    engine.register_fn(names::COMPENSATION, move || {
        num(match s.borrow().ctx.comp {
            CompSide::Off => 0.0,
            CompSide::Left => 1.0,
            CompSide::Right => 2.0,
        })
    });
    let s = state.clone();
    engine.register_fn(names::DRILL_HEADER, move || drill_header(&s.borrow()));
    let s = state.clone();
    engine.register_fn(names::TURN_DRILL, move || turn_drill(&s.borrow()));
}

/// The host's `getFeedrate(movement)`: nothing for a rapid, else the feed
/// of the move with one decimal, or four when it is per revolution.
fn feedrate(st: &mut State, movement: &Dynamic) -> String {
    let var = if st.ctx.feed_per_rev { st.feed_rev_var } else { st.feed_var };
    match var {
        Some(var) if to_number(movement) != 0.0 => {
            let feed = st.ctx.feed;
            format_var(st, var, feed)
        }
        _ => String::new(),
    }
}

/// Formats through a compile-time variable; shares the engine's modal memory.
fn format_var(st: &mut State, id: u16, v: f64) -> String {
    let i = id as usize;
    let State { vars, writers, prefixes, modal, var_formats, .. } = st;
    let (Some(state), Some(prefix), Some(&f)) = (vars.get_mut(i), prefixes.get(i), var_formats.get(i)) else {
        return String::new();
    };
    let Some(w) = writers.get(f as usize) else { return String::new() };
    let mut buf = Vec::new();
    state.format_number(modal.get(i).copied().unwrap_or(true), w, prefix, v, &mut buf);
    String::from_utf8_lossy(&buf).into_owned()
}

fn last(st: &State, id: u16) -> f64 {
    st.vars.get(id as usize).map_or(0.0, |v| match *v.value() {
        Value::Null => 0.0,
        ref other => other.num(),
    })
}

fn format_with(st: &State, id: u16, v: f64) -> String {
    let mut buf = Vec::new();
    if let Some(w) = st.writers.get(id as usize) {
        w.write(v, &mut buf);
    }
    String::from_utf8_lossy(&buf).into_owned()
}

/// A value that is not a finite number, given to a format at `at`: the
/// host reports it as the runtime does (`RT032`) at the JavaScript line.
/// It is a system error, so the post's `try` does not catch it, as in
/// native code (docs/cimco.md, formats): no program is written past a
/// word that could not be formatted.
#[derive(Clone, Copy, Debug)]
pub struct NonFinite(pub f64, pub rhai::Position);

impl std::fmt::Display for NonFinite {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "a format was given {}", self.0)
    }
}

impl std::error::Error for NonFinite {}

fn non_finite(v: f64, at: rhai::Position) -> Box<rhai::EvalAltResult> {
    Box::new(rhai::EvalAltResult::ErrorSystem(String::new(), Box::new(NonFinite(v, at))))
}

/// The formatted word, or the error of a format at `at` given a value
/// that is not a finite number.
fn finite(word: Dynamic, at: rhai::Position) -> R {
    match postc_runtime::number::take_non_finite() {
        None => Ok(word),
        Some(v) => Err(non_finite(v, at)),
    }
}

/// `format`, `getLast` and `reset` of output variables and `format` of
/// formats, whichever way
/// they were made.
pub fn output_method(state: &Shared, o: &Dynamic, name: &str, args: &Array, at: rhai::Position) -> Option<R> {
    let a0 = || args.first().map_or(f64::NAN, to_number);
    if let Some(VarRef(id)) = o.clone().try_cast::<VarRef>() {
        return Some(match name {
            "format" => finite(text(format_var(&mut state.borrow_mut(), id, a0())), at),
            "getLast" => Ok(num(last(&state.borrow(), id))),
            "reset" => {
                if let Some(v) = state.borrow_mut().vars.get_mut(id as usize) {
                    v.forget();
                }
                Ok(Dynamic::UNIT)
            }
            _ => Err(fail(format!("TypeError: an output variable has no method '{name}'"))),
        });
    }
    if let Some(FmtRef(id)) = o.clone().try_cast::<FmtRef>() {
        return Some(match name {
            "format" => finite(text(format_with(&state.borrow(), id, a0())), at),
            _ => Err(fail(format!("TypeError: a format has no method '{name}'"))),
        });
    }
    if let Some(DynFormat(w)) = o.clone().try_cast::<DynFormat>() {
        return Some(match name {
            "format" => {
                let mut buf = Vec::new();
                w.write(a0(), &mut buf);
                finite(text(String::from_utf8_lossy(&buf).into_owned()), at)
            }
            _ => Err(fail(format!("TypeError: a format has no method '{name}'"))),
        });
    }
    if let Some(DynVar(v)) = o.clone().try_cast::<DynVar>() {
        let epoch = state.borrow().ctx.epoch;
        let mut var = v.borrow_mut();
        return Some(match name {
            "format" => {
                let value = a0();
                let mut buf = var.prefix.as_bytes().to_vec();
                var.writer.write(value, &mut buf);
                if let Some(v) = postc_runtime::number::take_non_finite() {
                    return Some(Err(non_finite(v, at)));
                }
                let t = String::from_utf8_lossy(&buf).into_owned();
                var.last_value = value;
                let same = !var.force && var.last_text.as_ref().is_some_and(|(l, e)| *e == epoch && *l == t);
                var.last_text = Some((t.clone(), epoch));
                Ok(text(if same { String::new() } else { t }))
            }
            "getLast" => Ok(num(var.last_value)),
            "reset" => {
                var.last_text = None;
                Ok(Dynamic::UNIT)
            }
            _ => Err(fail(format!("TypeError: an output variable has no method '{name}'"))),
        });
    }
    None
}

/// A global's value by name (for `decimalMark` and the drilling fields).
fn global(st: &State, name: &str) -> Dynamic {
    let Some(i) = st.global_names.iter().position(|g| g == name) else { return Dynamic::UNIT };
    match (st.objects.get(i), st.globals.get(i)) {
        (Some(o), Some(Value::Null)) if !o.is_unit() => o.clone(),
        (_, Some(v)) => values::from_value(v),
        _ => Dynamic::UNIT,
    }
}

/// The format `createFormat` makes from its properties (docs/cimco.md).
pub fn cimco_format(props: &Dynamic, mark: char) -> NumberFormat {
    let get = |k: &str| props.clone().try_cast::<JsObj>().and_then(|o| o.get(k)).unwrap_or(Dynamic::UNIT);
    let n = |k: &str, d: f64| {
        let v = get(k);
        if v.is_unit() { d } else { to_number(&v) }
    };
    let decimals = n("decimals", 0.0);
    let decimals = if decimals.is_finite() { decimals.clamp(0.0, 15.0) as u8 } else { 0 };
    let width = n("width", 0.0);
    let force_decimal = values::truthy(&get("forceDecimal"));
    let scale = n("scale", 1.0);
    let prefix = get("prefix");
    NumberFormat {
        decimals,
        width: if width.is_finite() { width.clamp(0.0, 64.0) as u8 } else { 0 },
        width_of: WidthOf::IntegerDigits,
        padding: if values::truthy(&get("zeropad")) { Padding::Zero } else { Padding::Space },
        justify: Justify::Right,
        sign: if values::truthy(&get("forceSign")) { SignStyle::Always } else { SignStyle::Negative },
        point: if force_decimal { PointStyle::Always } else { PointStyle::WithDecimals },
        trim_zeros: !force_decimal,
        leading_zero: true,
        decimal_mark: mark,
        multiplier: if scale.is_finite() { scale } else { 1.0 },
        prefix: if prefix.is_unit() { String::new() } else { to_string(&prefix) },
        rounding: postc_ir::Rounding::Binary,
        negative_zero: false,
        span: None,
        name: None,
    }
}

/// The global functions of the host.
pub fn host_call(_ctx: &NativeCallContext, state: &Shared, name: &str, args: Array) -> R {
    let a = |i: usize| args.get(i).cloned().unwrap_or(Dynamic::UNIT);
    Ok(match name {
        names::PARSE_INT => num(js::parse_int(&to_string(&a(0)), if a(1).is_unit() { 0.0 } else { to_number(&a(1)) })),
        names::PARSE_FLOAT => num(js::parse_float(&to_string(&a(0)))),
        names::IS_NAN => Dynamic::from_bool(to_number(&a(0)).is_nan()),
        names::IS_FINITE => Dynamic::from_bool(to_number(&a(0)).is_finite()),
        names::STRING => text(if args.is_empty() { String::new() } else { to_string(&a(0)) }),
        names::NUMBER => num(if args.is_empty() { 0.0 } else { to_number(&a(0)) }),
        names::BOOLEAN => Dynamic::from_bool(values::truthy(&a(0))),
        names::ARRAY_FN => {
            Dynamic::from(JsArr::new(if args.len() == 1 && a(0).is::<f64>() { Vec::new() } else { args }))
        }
        names::OBJECT_FN => Dynamic::from(JsObj::new(ObjKind::Plain)),
        names::ERROR_FN => {
            let o = JsObj::new(ObjKind::Plain);
            o.set("message", text(to_string(&a(0))));
            o.set("name", text("Error"));
            Dynamic::from(o)
        }
        names::GET_COMPENSATION => text(""),
        names::GET_FEEDRATE => text(feedrate(&mut state.borrow_mut(), &a(0))),
        names::CREATE_FORMAT => {
            let st = state.borrow();
            let mark = match to_string(
                &[global(&st, names::DECIMAL_MARK), global(&st, names::GLOBALS_DECIMAL_MARK)]
                    .into_iter()
                    .find(|v| !v.is_unit())
                    .unwrap_or(Dynamic::UNIT),
            )
            .as_str()
            {
                "," => ',',
                _ => '.',
            };
            Dynamic::from(DynFormat(Rc::new(NumberWriter::new(&cimco_format(&a(0), mark)))))
        }
        names::CREATE_VARIABLE => {
            let st = state.borrow();
            let props = a(0);
            let get = |k: &str| props.clone().try_cast::<JsObj>().and_then(|o| o.get(k)).unwrap_or(Dynamic::UNIT);
            let writer = match (a(1).clone().try_cast::<FmtRef>(), a(1).clone().try_cast::<DynFormat>()) {
                (Some(FmtRef(id)), _) => st.writers.get(id as usize).cloned().map(Rc::new),
                (_, Some(DynFormat(w))) => Some(w),
                _ => None,
            }
            .unwrap_or_else(|| Rc::new(NumberWriter::new(&cimco_format(&Dynamic::UNIT, '.'))));
            let prefix = get("prefix");
            Dynamic::from(DynVar(Rc::new(RefCell::new(DynVarState {
                writer,
                prefix: if prefix.is_unit() { String::new() } else { to_string(&prefix) },
                force: values::truthy(&get("force")),
                last_text: None,
                last_value: 0.0,
            }))))
        }
        _ => return Err(fail(format!("ReferenceError: {name} is not defined"))),
    })
}

fn kind_name(kind: DrillKind) -> &'static str {
    match kind {
        DrillKind::Drill => "Drilling",
        DrillKind::Deep => "Peck drilling",
        DrillKind::ChipBreak => "Chip breaking",
        DrillKind::Tap => "Tapping",
        DrillKind::Bore => "Boring",
        DrillKind::Ream => "Reaming",
    }
}

/// A field of the drilling data CNC-Calc hands a post.
pub(crate) enum Field {
    Num(f64),
    Bool(bool),
    Text(String),
}

/// The cycle's name, and whether the post's fields list (`MillDrillingFields`,
/// `TurnDrillingFields`) marks it long-hand (`longhand_of` reads the list).
fn name_and_longhand(ctx: &Context, longhand_of: &dyn Fn(&str) -> bool) -> (String, bool) {
    let Some(c) = &ctx.drill else { return (String::new(), false) };
    let name = if c.name.is_empty() { kind_name(c.kind).to_string() } else { c.name.clone() };
    let longhand = longhand_of(&name);
    (name, longhand)
}

/// The `drillHeader` of `onDrillingHeader`, every field of the CNC-Calc Post Processor Manual's table.
pub(crate) fn drill_header_fields(ctx: &Context, longhand_of: &dyn Fn(&str) -> bool) -> Vec<(&'static str, Field)> {
    let Some(c) = ctx.drill.clone() else { return Vec::new() };
    let (name, longhand) = name_and_longhand(ctx, longhand_of);
    let feed = c.feed.unwrap_or(ctx.plunge_feed);
    let peck = c.peck.filter(|p| *p > 0.0).unwrap_or(0.0);
    let dwell = c.dwell.filter(|d| *d > 0.0);
    use Field::{Bool as B, Num as N};
    vec![
        ("name", Field::Text(name)),
        ("isLonghand", B(longhand)),
        ("retractPlane", N(c.retract_plane)),
        // The CNC-Calc Post Processor Manual: "the absolute reference plane. If either the safe distance
        // or end depth is given as relative coordinates, they are relative to
        // this plane" -- the top of the holes; safeDistance is the R plane.
        ("referencePlane", N(c.surface.unwrap_or(c.reference_plane))),
        ("safeDistanceIsAbsolute", B(true)),
        ("safeDistance", N(c.reference_plane)),
        ("endDepthIsAbsolute", B(true)),
        ("endDepth", N(c.depth)),
        ("firstDepth", N(peck)),
        ("firstFeedrateFactor", N(1.0)),
        ("degressionType", N(0.0)),
        ("degression", N(0.0)),
        ("peckingRetract", N(0.0)),
        ("minimumDepth", N(0.0)),
        ("usePlungingFeedrate", B(true)),
        ("plungingFeedrate", N(feed)),
        ("useRetractFeedrate", B(false)),
        ("retractFeedrate", N(feed)),
        ("useTopDwelling", B(false)),
        ("topDwelling", N(0.0)),
        ("useBottomDwelling", B(dwell.is_some())),
        ("bottomDwelling", N(dwell.unwrap_or(0.0))),
        ("pitch", N(c.pitch.unwrap_or(0.0))),
        ("useTappingSpeed", B(false)),
        ("tappingSpeed", N(ctx.spindle)),
        ("useRetractSpeed", B(false)),
        ("retractSpeed", N(ctx.spindle)),
    ]
}

/// The `drillHeader` of `onDrilling` (turning), every field of the CNC-Calc Post Processor Manual's
/// table, under both spellings where the seed uses two.
pub(crate) fn turn_drill_fields(ctx: &Context, longhand_of: &dyn Fn(&str) -> bool) -> Vec<(&'static str, Field)> {
    let Some(c) = ctx.drill.clone() else { return Vec::new() };
    let (name, longhand) = name_and_longhand(ctx, longhand_of);
    let feed = c.feed.unwrap_or(ctx.plunge_feed);
    let pecking = matches!(c.kind, DrillKind::Deep | DrillKind::ChipBreak) && c.peck.is_some_and(|p| p > 0.0);
    let peck = if pecking { c.peck.unwrap_or(0.0) } else { 0.0 };
    let dwell = c.dwell.filter(|d| *d > 0.0);
    use Field::{Bool as B, Num as N};
    let mut out = Vec::new();
    let mut set = |ks: &[&'static str], v: Field| {
        for k in ks {
            out.push((
                *k,
                match &v {
                    Field::Num(n) => N(*n),
                    Field::Bool(b) => B(*b),
                    Field::Text(t) => Field::Text(t.clone()),
                },
            ));
        }
    };
    set(&["name", "Name"], Field::Text(name));
    set(&["isLonghand"], B(longhand));
    // The hole's top: the turned toolpath keeps the lathe's Z in X.
    set(&["startDepth"], N(if ctx.lathe { ctx.pos[0] } else { ctx.pos[2] }));
    set(&["endDepth"], N(c.depth));
    set(&["safeDistance"], N(c.reference_plane));
    set(&["retractDistance"], N(c.retract_plane));
    set(&["usePlungingFeedrate"], B(true));
    set(&["plungingFeedrate"], N(feed));
    set(&["useRetractFeedrate"], B(false));
    set(&["retractFeedrate"], N(feed));
    set(&["pitch", "Pitch"], N(c.pitch.unwrap_or(0.0)));
    set(&["usePecking", "UsePecking"], B(pecking));
    set(&["firstPeckDepth"], N(peck));
    set(&["subsequentPecksDepths", "subsequentPeckDepths"], N(peck));
    set(&["peckClearance"], N(0.0));
    set(&["peckRetract", "PeckRetract"], N(0.0));
    set(&["useUpperDwell"], B(false));
    set(&["upperDwell"], N(0.0));
    set(&["useLowerDwell"], B(dwell.is_some()));
    set(&["lowerDwell"], N(dwell.unwrap_or(0.0)));
    set(&["useDrillTipCompensation"], B(false));
    set(&["drillDiameter"], N(ctx.tool_diameter));
    set(&["drillTipAngle"], N(118.0));
    out
}

/// Whether the post's fields list (a Rhai array of objects) marks cycle
/// `name` long-hand.
fn rhai_longhand(st: &State, list: &str, name: &str) -> bool {
    global(st, list)
        .try_cast::<JsArr>()
        .and_then(|a| {
            a.0.borrow().iter().find_map(|e| {
                let o = e.clone().try_cast::<JsObj>()?;
                (o.get("name").map(|n| to_string(&n)).as_deref() == Some(name))
                    .then(|| o.get("isLonghand").is_some_and(|v| values::truthy(&v)))
            })
        })
        .unwrap_or(false)
}

/// Fields as a Rhai object.
fn rhai_object(fields: Vec<(&'static str, Field)>) -> Dynamic {
    let o = JsObj::new(ObjKind::Plain);
    for (k, v) in fields {
        o.set(
            k,
            match v {
                Field::Num(n) => num(n),
                Field::Bool(b) => Dynamic::from_bool(b),
                Field::Text(t) => text(t),
            },
        );
    }
    Dynamic::from(o)
}

fn drill_header(st: &State) -> Dynamic {
    rhai_object(drill_header_fields(&st.ctx, &|n| rhai_longhand(st, names::MILL_DRILLING_FIELDS, n)))
}

fn turn_drill(st: &State) -> Dynamic {
    rhai_object(turn_drill_fields(&st.ctx, &|n| rhai_longhand(st, names::TURN_DRILLING_FIELDS, n)))
}
