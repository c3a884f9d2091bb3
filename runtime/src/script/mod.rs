//! The script host: runs the Rhai script a CIMCO post compiles to, for the
//! functions that do not lower to native IR.
//!
//! - [`js`]: JavaScript's conversions (number text, `parseInt`, `toFixed`);
//! - `values`: JavaScript values in Rhai with reference semantics;
//! - `ops`, `props`, `regex`: the operators, properties, methods and
//!   regular expressions the translated script calls;
//! - `cimco`: the CNC-Calc host functions (`createFormat`,
//!   `createVariable`, `getFeedrate`, the drill headers, compensation) and
//!   the turning of a lathe toolpath into the runtime's plane;
//! - `host`: the Rhai engine, compiled once per run, and the call in and
//!   out of it; `blocks`: text written by the fast path becoming blocks.
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

mod blocks;
mod cimco;
mod host;
pub mod js;
mod methods;
mod ops;
mod props;
mod regex;
mod values;

use postc_ir::event::{CompSide, DrillCycle, Event};
use postc_ir::{Diagnostic, Dialect};

use crate::engine::Engine;
use crate::value::Value;

pub use cimco::turn_event;

/// What the engine keeps for CIMCO posts.
#[derive(Default)]
pub(crate) struct Ext {
    pub host: Option<Box<host::ScriptHost>>,
    /// A frame reused by handler bodies, so that their locals cost no
    /// allocation per event.
    pub frame: Vec<Value>,
    /// Counts the clearings of modal memory (for variables made by scripts).
    pub epoch: u64,
    pub notes: Notes,
}

/// Event data the host functions read that no quantity carries.
#[derive(Clone, Debug, Default)]
pub(crate) struct Notes {
    pub drill: Option<DrillCycle>,
    pub comp: CompSide,
}

/// Compiles the post's scripts, once per run.
pub fn attach(engine: &mut Engine) -> Result<(), Diagnostic> {
    if engine.post.scripts.is_empty() {
        return Ok(());
    }
    let h = host::ScriptHost::new(engine)?;
    engine.cimco.host = Some(Box::new(h));
    Ok(())
}

/// Notes what the host functions need from an event, before it is dispatched.
pub fn observe(engine: &mut Engine, event: &Event) {
    if engine.post.info.dialect != Dialect::Cimco {
        return;
    }
    match event {
        Event::DrillCycle(c) => engine.cimco.notes.drill = Some(c.clone()),
        Event::CutterComp(c) => engine.cimco.notes.comp = c.side,
        _ => {}
    }
}

/// Calls a script function with arguments.
pub(crate) fn call(engine: &mut Engine, id: u16, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
    let Some(mut h) = engine.cimco.host.take() else {
        return Err(Box::new(Diagnostic::error(
            "RT005",
            format!("function `{name}` is a script, and this post has no script to run it (script {id})"),
        )));
    };
    let result = h.call(engine, name, args);
    engine.cimco.host = Some(h);
    result
}
