//! Script hosts: how the runtime runs the functions a post keeps as
//! scripts (`Body::Script`), without knowing their language.
//!
//! The runtime names no script language and no dialect. Whoever runs a
//! post (the command line, `postc_driver::script_host`, tests) hands
//! [`run`](crate::run) a [`ScriptHostFactory`] in
//! [`RunOptions::script_host`](crate::RunOptions::script_host); the
//! runtime calls it once per run, after the engine is built and before
//! the post's one-time code runs, when the post has scripts. A post that
//! calls a script function with no host gets RT005.
//!
//! Native code and scripts share one state: before a script runs, the
//! engine's variables (their values and modal memory) and globals move
//! into the host ([`Engine::lend_shared`]), and back when it returns
//! ([`Engine::return_shared`]), so an output variable formatted natively
//! and from a script keeps one modal memory.

use postc_ir::{Diagnostic, Event, ScriptId, Variable};

use crate::engine::Engine;
use crate::number::NumberWriter;
use crate::value::Value;

pub use crate::engine::VarState;
pub use crate::interp::{MAX_TEXT_BYTES, NON_FINITE, TEXT_BUDGET, non_finite_error, text_budget_error};

/// Runs the script functions of one post for one run.
pub trait ScriptHost {
    /// Sees each event before it is dispatched (after `lathe` turned it),
    /// to keep what its functions read that no quantity carries.
    fn observe(&mut self, _event: &Event) {}

    /// Calls the script function of post function `name` with `args`.
    fn call(&mut self, engine: &mut Engine<'_>, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>>;

    /// Calls function `name` of the host's API, which native code names
    /// (`Expr::Host`): the data a dialect's engine hands posts that no
    /// quantity carries (CNC-Calc's drilling header).
    fn host_call(&mut self, _engine: &mut Engine<'_>, name: &str, _args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
        Err(Box::new(Diagnostic::error("RT005", format!("the post's host has no function `{name}`"))))
    }
}

/// Builds the host of one run: compiles the post's scripts, once.
pub type ScriptHostFactory = fn(&Engine<'_>) -> Result<Box<dyn ScriptHost>, Diagnostic>;

/// Whether a variable is on-change (prints only when its text changes).
pub fn is_modal(var: &Variable) -> bool {
    crate::engine::is_modal(var)
}

impl VarState {
    /// The variable's current value.
    pub fn value(&self) -> &Value {
        &self.value
    }

    /// Forgets what the variable printed last: its next value prints.
    pub fn forget(&mut self) {
        self.has_last = false;
        self.key = None;
        self.last_value = f64::NAN;
    }

    /// Prints `v` through the variable (`modal` when it is on-change) into
    /// `out`, and makes it the variable's value.
    pub fn format_number(&mut self, modal: bool, w: &NumberWriter, prefix: &[u8], v: f64, out: &mut Vec<u8>) {
        crate::engine::put_number(modal, w, self, prefix, v, out);
        self.previous = std::mem::replace(&mut self.value, Value::Num(v));
    }
}

impl Engine<'_> {
    /// The number writer of each format of the post.
    pub fn writers(&self) -> &[NumberWriter] {
        &self.writers
    }

    /// The prefix of each variable as printed.
    pub fn prefixes(&self) -> &[Vec<u8>] {
        &self.prefixes
    }

    /// How many times modal memory was cleared so far in the run.
    pub fn modal_epoch(&self) -> u64 {
        self.modal_epoch
    }

    /// Moves the variables' state and the globals out, for a script call.
    pub fn lend_shared(&mut self) -> (Vec<VarState>, Vec<Value>) {
        (std::mem::take(&mut self.vars), std::mem::take(&mut self.globals))
    }

    /// Moves them back after the call.
    pub fn return_shared(&mut self, (vars, globals): (Vec<VarState>, Vec<Value>)) {
        self.vars = vars;
        self.globals = globals;
    }

    /// Calls a script function through the run's host.
    /// Calls a function of the host's API ([`ScriptHost::host_call`]).
    pub(crate) fn call_host(&mut self, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
        let Some(mut host) = self.script_host.take() else {
            return Err(Box::new(Diagnostic::error(
                "RT005",
                format!("the post calls `{name}` of its host, and this run has no host"),
            )));
        };
        let result = host.host_call(self, name, args);
        self.script_host = Some(host);
        result
    }

    pub(crate) fn call_script(&mut self, id: ScriptId, name: &str, args: Vec<Value>) -> Result<Value, Box<Diagnostic>> {
        let Some(mut host) = self.script_host.take() else {
            let why = if self.post.scripts.is_empty() {
                format!("this post has no script to run it (script {})", id.raw())
            } else {
                "this run has no script host for the post's scripts".to_string()
            };
            return Err(Box::new(Diagnostic::error("RT005", format!("function `{name}` is a script, and {why}"))));
        };
        let result = host.call(self, name, args);
        self.script_host = Some(host);
        result
    }
}
