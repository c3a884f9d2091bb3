//! # The CNC-Calc script host
//!
//! Runs the Rhai script a CIMCO post compiles to (`postc_front_cimco`),
//! for the functions that do not lower to native IR. The runtime knows
//! nothing of it: it calls script functions through
//! [`postc_runtime::script_host::ScriptHost`], and the edge (the command
//! line, `postc_driver::script_host`, tests) hands it [`compile`] for a
//! post whose scripts are Rhai.
//!
//! - `values`: JavaScript values in Rhai with reference semantics;
//! - `ops`, `props`, `methods`: the operators, properties and methods
//!   the translated script calls (JavaScript's conversions are the
//!   runtime's, [`postc_runtime::js`], and so are its regular
//!   expressions, [`postc_runtime::regex`], which native code runs too);
//! - `cnc_calc`: the CNC-Calc host functions (`createFormat`,
//!   `createVariable`, `getFeedrate`, the drill headers, compensation);
//! - `compiled`: the Rhai engine, compiled once per run, and the call in
//!   and out of it.
//!
//! Every name the script calls and the host registers is a constant of
//! [`postc_front_cimco::host_names`], the one table the lowering and this
//! host share.
//!
//! Native code and scripts share one state: before a script runs, the
//! engine's variables (their values and modal memory) and globals move
//! into the host, and back when it returns, so an output variable
//! formatted natively and from a script keeps one modal memory.
//!
//! A post is untrusted code: the Rhai engine has no modules, no `eval`,
//! no printing, and no file, network or process functions; a script call
//! stops after `OutputOptions::step_budget` operations with a diagnostic
//! at the JavaScript line it was running.

mod cnc_calc;
mod compiled;
mod methods;
mod ops;
mod props;
mod values;

use postc_front_cimco::host_names as names;
use postc_ir::Diagnostic;
use postc_ir::event::{CompSide, DrillCycle, Event};
use postc_runtime::Engine;
use postc_runtime::script_host::ScriptHost;
use postc_runtime::value::Value;

pub use compiled::MAX_ITEMS;

/// Compiles the post's scripts, once per run: the
/// [`postc_runtime::script_host::ScriptHostFactory`] of Rhai scripts.
pub fn compile(engine: &Engine<'_>) -> Result<Box<dyn ScriptHost>, Diagnostic> {
    Ok(Box::new(RhaiHost { compiled: compiled::Compiled::new(engine)?, notes: Notes::default() }))
}

/// The Rhai host of one run.
struct RhaiHost {
    compiled: compiled::Compiled,
    notes: Notes,
}

/// Event data the host functions read that no quantity carries.
#[derive(Clone, Debug, Default)]
pub(crate) struct Notes {
    pub drill: Option<DrillCycle>,
    pub comp: CompSide,
}

impl ScriptHost for RhaiHost {
    /// Notes what the host functions need from an event, before it is dispatched.
    fn observe(&mut self, event: &Event) {
        match event {
            Event::DrillCycle(c) => self.notes.drill = Some(c.clone()),
            Event::CutterComp(c) => self.notes.comp = c.side,
            _ => {}
        }
    }

    fn call(&mut self, engine: &mut Engine<'_>, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
        self.compiled.call(engine, &self.notes, name, args)
    }

    /// The data CNC-Calc hands the entry points, as values of the post's
    /// native code: the drilling headers (the argument is the post's fields
    /// list, which says which cycles are long-hand) and the compensation
    /// side.
    fn host_call(&mut self, engine: &mut Engine<'_>, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
        let ctx = compiled::Context::of(engine, &self.notes);
        let list = args.into_iter().next().unwrap_or(Value::Undefined);
        let longhand = |n: &str| value_longhand(&list, n);
        match name {
            names::DRILL_HEADER => Ok(value_object(cnc_calc::drill_header_fields(&ctx, &longhand))),
            names::TURN_DRILL => Ok(value_object(cnc_calc::turn_drill_fields(&ctx, &longhand))),
            names::COMPENSATION => Ok(Value::Num(match ctx.comp {
                CompSide::Off => 0.0,
                CompSide::Left => 1.0,
                CompSide::Right => 2.0,
            })),
            _ => Err(Box::new(Diagnostic::error("RT005", format!("the CNC-Calc host has no function `{name}`")))),
        }
    }
}

/// Fields as an object of native code.
fn value_object(fields: Vec<(&'static str, cnc_calc::Field)>) -> Value {
    let mut o = postc_runtime::value::Object::default();
    for (k, v) in fields {
        let v = match v {
            cnc_calc::Field::Num(n) => Value::Num(n),
            cnc_calc::Field::Bool(b) => Value::Bool(b),
            cnc_calc::Field::Text(t) => Value::text(&t),
        };
        o.set(postc_runtime::value::Text::new(k), v);
    }
    Value::object(o)
}

/// Whether a fields list (an array of objects) marks cycle `name` long-hand.
fn value_longhand(list: &Value, name: &str) -> bool {
    let Value::Array(items) = list else { return false };
    items.borrow().iter().any(|e| match e {
        Value::Object(o) => {
            let o = o.borrow();
            o.get(b"name").is_some_and(|n| n.to_text().as_str() == name)
                && o.get(b"isLonghand").is_some_and(Value::truthy)
        }
        _ => false,
    })
}
