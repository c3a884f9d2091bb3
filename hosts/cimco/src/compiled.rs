//! The compiled script of a run: the Rhai engine, built and the script
//! compiled once, called for each script function, with the engine's
//! shared state moved in for the call.

use std::cell::RefCell;
use std::rc::Rc;

use postc_ir::event::{CompSide, DrillCycle};
use postc_ir::{Diagnostic, Script, Span};
use rhai::{AST, Array, CallFnOptions, Dynamic, EvalAltResult, Position, Scope};

use postc_front_cimco::host_names;
use postc_runtime::Engine;
use postc_runtime::number::NumberWriter;
use postc_runtime::script_host::{self as runtime, VarState};
use postc_runtime::value::Value;

use crate::Notes;
use crate::values::{self, JsObj};

/// Everything host functions read and write, shared with the registered
/// functions through an `Rc`.
pub(crate) struct State {
    /// The engine's variables and globals, moved in for a call.
    pub vars: Vec<VarState>,
    pub globals: Vec<Value>,
    /// Globals holding objects (same indices as `globals`).
    pub objects: Vec<Dynamic>,
    pub writers: Vec<NumberWriter>,
    pub prefixes: Vec<Vec<u8>>,
    pub modal: Vec<bool>,
    /// The format of each variable.
    pub var_formats: Vec<u16>,
    /// Function objects by Rhai name, made once each.
    pub functions: std::collections::HashMap<String, JsObj>,
    /// Regular expressions by pattern and flags, compiled once each.
    pub regexes: std::collections::HashMap<(String, String), std::rc::Rc<postc_runtime::regex::Regex>>,
    pub ctx: Context,
    /// Names of globals, to find `MillDrillingFields` and friends.
    pub global_names: Vec<String>,
    pub feed_var: Option<u16>,
    /// The variable of feeds per revolution (more decimals).
    pub feed_rev_var: Option<u16>,
    /// Loop iterations of the current call, the most allowed, and the
    /// post offset of the loop that ran last.
    pub ticks: u64,
    pub max_ticks: u64,
    pub last_loop: Option<u32>,
}

/// What the machine says when a script runs.
#[derive(Clone, Debug, Default)]
pub(crate) struct Context {
    pub feed: f64,
    pub feed_per_rev: bool,
    pub plunge_feed: f64,
    pub spindle: f64,
    pub tool_diameter: f64,
    pub pos: [f64; 3],
    pub drill: Option<DrillCycle>,
    pub comp: CompSide,
    pub epoch: u64,
    pub lathe: bool,
}

impl Context {
    /// What the host functions read now: the machine's state and the
    /// notes of the last events.
    pub(crate) fn of(eng: &Engine, notes: &Notes) -> Context {
        let m = &eng.machine;
        Context {
            feed: m.feed,
            feed_per_rev: m.toolpath.feed_per_rev,
            plunge_feed: m.tool.plunge_feed,
            spindle: m.spindle_speed,
            tool_diameter: m.tool.diameter,
            pos: m.pos,
            drill: notes.drill.clone(),
            comp: notes.comp,
            epoch: eng.modal_epoch(),
            lathe: eng.post.options.lathe,
        }
    }
}

pub(crate) type Shared = Rc<RefCell<State>>;

/// A compiled script and its engine.
pub(crate) struct Compiled {
    engine: rhai::Engine,
    ast: AST,
    pub(crate) state: Shared,
    script: Script,
}

impl Compiled {
    pub(crate) fn new(eng: &Engine) -> Result<Compiled, Diagnostic> {
        let post = eng.post;
        let script = post.scripts.first().cloned().unwrap_or_else(|| Script {
            language: postc_ir::ScriptLanguage::Rhai,
            source: String::new(),
            span: None,
            span_map: Vec::new(),
        });
        let state = Rc::new(RefCell::new(State {
            vars: Vec::new(),
            globals: Vec::new(),
            objects: vec![Dynamic::UNIT; post.globals.len()],
            writers: eng.writers().to_vec(),
            prefixes: eng.prefixes().to_vec(),
            modal: post.variables.iter().map(runtime::is_modal).collect(),
            var_formats: post.variables.iter().map(|v| v.format.raw()).collect(),
            functions: Default::default(),
            regexes: Default::default(),
            ctx: Context { lathe: post.options.lathe, ..Context::default() },
            global_names: post.globals.iter().map(|g| g.name.clone()).collect(),
            feed_var: post.variables.iter().position(|v| v.name == host_names::FEED_VAR).map(|i| i as u16),
            feed_rev_var: post.variables.iter().position(|v| v.name == host_names::FEED_REV_VAR).map(|i| i as u16),
            ticks: 0,
            max_ticks: post.options.step_budget.max(1),
            last_loop: None,
        }));
        let mut engine = rhai::Engine::new_raw();
        // Loops count their own iterations (`__tick`), which names the
        // loop; Rhai's operation limit is the backstop.
        engine.set_max_operations(post.options.step_budget.max(1).saturating_mul(64));
        engine.set_max_call_levels(48);
        engine.set_max_expr_depths(256, 256);
        // The same text budget as native code (RT031); arrays and object
        // tables get one too, so no post can take all the memory.
        engine.set_max_string_size(runtime::MAX_TEXT_BYTES);
        engine.set_max_array_size(MAX_ITEMS);
        engine.set_max_map_size(MAX_ITEMS);
        engine.disable_symbol("eval");
        engine.register_iterator::<Array>();
        engine.on_print(|_| {});
        engine.on_debug(|_, _, _| {});
        crate::ops::register(&mut engine, &state);
        crate::props::register(&mut engine, &state);
        crate::cnc_calc::register(&mut engine, &state);
        let ast = engine.compile(&script.source).map_err(|e| {
            let pos = e.position();
            let d = Diagnostic::error(
                "RT022",
                format!("the script made from this post does not compile: {}", e.err_type()),
            );
            match span_at(&script, pos) {
                Some(s) => d.at(s, "here"),
                None => d,
            }
            .note("this is a bug in postc")
        })?;
        Ok(Compiled { engine, ast, state, script })
    }

    /// Calls the script function of post function `name`.
    pub(crate) fn call(
        &mut self,
        eng: &mut Engine,
        notes: &Notes,
        name: &str,
        args: Vec<Value>,
    ) -> Result<Value, Box<Diagnostic>> {
        {
            let mut st = self.state.borrow_mut();
            (st.vars, st.globals) = eng.lend_shared();
            st.ctx = Context::of(eng, notes);
            st.ticks = 0;
            st.last_loop = None;
        }
        let arr: Array = args.iter().map(values::from_value).collect();
        let fn_name = Script::function_name(name);
        let mut scope = Scope::new();
        let options = CallFnOptions::new().eval_ast(false).rewind_scope(true);
        let result = self.engine.call_fn_with_options::<Dynamic>(options, &mut scope, &self.ast, &fn_name, (arr,));
        {
            let mut st = self.state.borrow_mut();
            let shared = (std::mem::take(&mut st.vars), std::mem::take(&mut st.globals));
            eng.return_shared(shared);
        }
        match result {
            Ok(v) => Ok(values::to_value(&v).unwrap_or(Value::Null)),
            Err(e) => Err(Box::new(self.diagnostic(&e, name))),
        }
    }

    /// An error of the script as a diagnostic at the JavaScript line.
    fn diagnostic(&self, err: &EvalAltResult, name: &str) -> Diagnostic {
        let (inner, pos) = innermost(err);
        let mut span = span_at(&self.script, pos);
        if let (EvalAltResult::ErrorTooManyOperations(_), Some(at), Some(whole)) =
            (inner, self.state.borrow().last_loop, self.script.span)
        {
            span = Some(Span::new(whole.file, at as usize, at as usize + 1));
        }
        // Rhai gives a too-large value no position: the loop it grew in.
        if let (EvalAltResult::ErrorDataTooLarge(..), None, Some(at), Some(whole)) =
            (inner, span, self.state.borrow().last_loop, self.script.span)
        {
            span = Some(Span::new(whole.file, at as usize, at as usize + 1));
        }
        if let EvalAltResult::ErrorSystem(_, e) = inner
            && let Some(u) = e.downcast_ref::<crate::ops::Unsupported>()
        {
            let d = Diagnostic::error(postc_runtime::regex::UNSUPPORTED, u.message.clone());
            return match span_at(&self.script, u.at) {
                Some(s) => d.at(s, "here"),
                None => d,
            };
        }
        if let EvalAltResult::ErrorSystem(_, e) = inner
            && let Some(crate::cnc_calc::NonFinite(n, at)) = e.downcast_ref::<crate::cnc_calc::NonFinite>()
        {
            return *runtime::non_finite_error(*n, span_at(&self.script, *at).or(span));
        }
        let d = match inner {
            EvalAltResult::ErrorTooManyOperations(_) => Diagnostic::error(
                "RT002",
                format!(
                    "the post ran more than {} loop steps for one event in `{name}` and was stopped (a loop that never ends?)",
                    self.state.borrow().max_ticks
                ),
            ),
            EvalAltResult::ErrorStackOverflow(_) | EvalAltResult::ErrorTooManyModules(_) => {
                Diagnostic::error("RT004", format!("calls nest too deep in `{name}` (endless recursion?)"))
            }
            EvalAltResult::ErrorDataTooLarge(what, _) if what.contains("Length of string") => {
                runtime::text_budget_error(runtime::MAX_TEXT_BYTES + 1)
            }
            EvalAltResult::ErrorDataTooLarge(what, _) => Diagnostic::error(
                runtime::TEXT_BUDGET,
                format!(
                    "the post built an array or object of more than {MAX_ITEMS} items in `{name}` and was stopped ({})",
                    what.to_lowercase()
                ),
            )
            .note("no output is written"),
            EvalAltResult::ErrorRuntime(v, _) => {
                Diagnostic::error("RT023", format!("the post stopped with an error: {}", values::to_string(v)))
            }
            other => Diagnostic::error("RT023", format!("the post stopped with an error: {}", message(other))),
        };
        let label = match inner {
            EvalAltResult::ErrorDataTooLarge(..) => "this loop builds it",
            _ if inner.to_string().contains("many operations") => "this loop did not finish",
            _ => "while running this",
        };
        match span {
            Some(s) => d.at(s, label),
            None => d,
        }
    }
}

/// The most items an array or object table of a script may hold.
pub const MAX_ITEMS: usize = 1 << 20;

/// The innermost error of a chain of calls, and where it happened.
fn innermost(err: &EvalAltResult) -> (&EvalAltResult, Position) {
    let mut cur = err;
    let mut pos = err.position();
    loop {
        match cur {
            EvalAltResult::ErrorInFunctionCall(_, _, inner, p) => {
                if !p.is_none() {
                    pos = *p;
                }
                cur = inner;
                if !cur.position().is_none() {
                    pos = cur.position();
                }
            }
            other => {
                if !other.position().is_none() {
                    pos = other.position();
                }
                return (other, pos);
            }
        }
    }
}

/// An error's message without Rhai's position.
fn message(err: &EvalAltResult) -> String {
    let mut m = err.to_string();
    if let Some(i) = m.find(" (line ") {
        m.truncate(i);
    }
    m.replace("js_", "")
}

/// The place in the post a position of the script comes from.
pub(crate) fn span_at(script: &Script, pos: Position) -> Option<Span> {
    let file = script.span?.file;
    let (line, col) = (pos.line()?, pos.position().unwrap_or(1));
    let start: usize = script.source.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    let offset = (start + col.saturating_sub(1)).min(script.source.len()) as u32;
    let i = script.span_map.partition_point(|(r, _)| *r <= offset);
    let js = if i == 0 { script.span?.start as u32 } else { script.span_map[i - 1].1 };
    Some(Span::new(file, js as usize, js as usize + 1))
}
