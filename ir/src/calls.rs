//! Sub calls: how the applications that are not driven by toolpath events
//! reach a post.
//!
//! VcPost's probe-cycle programming (a table of rows) and its composites
//! application (an event file of routine calls) do not produce toolpath
//! [`crate::Event`]s: each of their records names a Sub of the post and the
//! variables to set before calling it. Their readers produce [`SubCall`]s
//! through a [`CallSource`], and the runtime runs them in order: it sets each
//! variable the post has (a register or a global, names compared without
//! case), then calls the Sub.
//!
//! A [`CallValue::List`] is not a variable: it fills the globals a
//! [`crate::CallList`] of the post names (VcPost composites'
//! `getNthLength1(tow)` is a function its frontend makes to read the
//! `tow`-th of those globals, so it returns the `tow`-th number of the
//! `getNthLength1` list of the current call).
//!
//! This module was added for the VcPost applications; nothing else in the IR
//! changed for them.

use serde::{Deserialize, Serialize};

use crate::diagnostic::{Diagnostic, Span};

/// One call of a post's Sub.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SubCall {
    /// The Sub's name; compared without case.
    pub sub: String,
    /// Variables set before the call, in order; names compared without case.
    /// Names the post does not use are skipped.
    pub vars: Vec<(String, CallValue)>,
    /// Where the call comes from (a table row, an event line).
    pub span: Span,
    /// What the runtime does when the post has no such Sub.
    pub missing: MissingSub,
}

/// What a post says about one of its Subs for the applications that call
/// Subs by name (VcPost keyword comments: `'#Cycle !X !Y Depth`): its role
/// keyword, its parameters in table order, and the tips of its input
/// fields. Kept in [`crate::PostInfo::subs`], so that probe tables and
/// composites files can be read against a compiled post.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SubSignature {
    /// The Sub's name, as written.
    pub name: String,
    /// Its role keyword without the `#` (`Init`, `Cycle`, `Option`, ...), when
    /// it has one.
    pub keyword: Option<String>,
    /// Parameters in table order.
    pub params: Vec<SubParam>,
    /// Tips of an option Sub's input fields.
    pub tips: Vec<SubTip>,
}

/// One parameter of a [`SubSignature`].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SubParam {
    pub name: String,
    /// A table row must give it (`!Name`).
    pub required: bool,
}

/// The tip of one input field of an option Sub (`#C1 Operator message`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SubTip {
    /// The field, without the `#` (`C1`, `N2`, `S1`, ...).
    pub slot: String,
    pub text: String,
}

/// A value a call sets.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum CallValue {
    Number(f64),
    Text(String),
    /// The table of a runtime-provided function, indexed from 0.
    List(Vec<f64>),
}

/// What to do when a post has no Sub for a call.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum MissingSub {
    /// Skip it silently (a routine the post may leave out by design).
    Skip,
    /// Skip it, with one warning per Sub name.
    #[default]
    Warn,
}

/// A stream of calls, read one at a time.
pub trait CallSource {
    /// The next call; `None` at the end. Problems go into `diagnostics`;
    /// after an error a source goes on with the next record, so that every
    /// problem is reported.
    fn next_call(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<SubCall>;
}

impl<S: CallSource + ?Sized> CallSource for Box<S> {
    fn next_call(&mut self, diagnostics: &mut Vec<Diagnostic>) -> Option<SubCall> {
        (**self).next_call(diagnostics)
    }
}

/// A list of calls already read (a probe table, a test).
impl CallSource for std::vec::IntoIter<SubCall> {
    fn next_call(&mut self, _diagnostics: &mut Vec<Diagnostic>) -> Option<SubCall> {
        self.next()
    }
}
