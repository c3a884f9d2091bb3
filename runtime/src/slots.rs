//! Names the runtime sets in a post: registers (variables the post assigns)
//! and globals, found by name without case.
//!
//! The APT-word dispatcher sets `X`, `G`, `Text`, ... before each record's
//! handler; the Sub-call runner sets the variables of each probe-table row
//! and composites call. A name the post does not use is skipped: the post
//! never reads it, so nothing is lost.

use std::collections::HashMap;

use postc_ir::{Post, ValueSource};

use crate::engine::Engine;
use crate::value::Value;

/// Where a name lives in the post.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Slot {
    /// A register (IR variable with an assigned value).
    Var(postc_ir::VarId),
    /// A global.
    Global(postc_ir::GlobalId),
}

/// The settable names of a post, keyed in ASCII upper case.
pub(crate) struct Slots {
    map: HashMap<String, Slot>,
}

impl Slots {
    /// Every global and every assigned variable of the post; a register
    /// wins over a global of the same name.
    pub(crate) fn new(post: &Post) -> Slots {
        let mut map = HashMap::new();
        for (i, g) in post.globals.iter().enumerate() {
            if let Some(i) = postc_ir::GlobalId::from_usize(i) {
                map.insert(g.name.to_ascii_uppercase(), Slot::Global(i));
            }
        }
        for (i, v) in post.variables.iter().enumerate() {
            if v.source == ValueSource::Assigned
                && let Some(i) = postc_ir::VarId::from_usize(i)
            {
                map.insert(v.name.to_ascii_uppercase(), Slot::Var(i));
            }
        }
        Slots { map }
    }

    /// The slot of a name already in upper case.
    pub(crate) fn get(&self, upper: &str) -> Option<Slot> {
        self.map.get(upper).copied()
    }

    /// Sets a name given in upper case; a name the post lacks is skipped.
    pub(crate) fn set(&self, eng: &mut Engine, upper: &str, value: Value) {
        match self.get(upper) {
            Some(Slot::Var(id)) => eng.set_var(id, value),
            Some(Slot::Global(i)) => eng.set_global(i, value),
            None => {}
        }
    }
}
