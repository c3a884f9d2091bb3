//! Globals that the lists of a Sub call fill ([`postc_ir::CallList`]).
//!
//! A frontend makes a function whose values change at every call read a
//! table of hidden globals, and names those globals in
//! [`postc_ir::Post::call_lists`]. Before each call, a
//! [`postc_ir::CallValue::List`] of a table's name fills its globals
//! ([`Tables::fill`]); the globals past the list, and every table the call
//! does not carry, read 0 ([`Tables::clear_except`]), so no value outlives
//! its call. The runtime knows nothing of the functions themselves.

use postc_ir::{GlobalId, Post};

use crate::engine::Engine;
use crate::value::Value;

/// The tables of a post.
#[derive(Debug, Default)]
pub(crate) struct Tables {
    /// Upper-case list name, first global, globals in the table, entries
    /// set last time.
    tables: Vec<(String, u16, usize, usize)>,
}

impl Tables {
    /// The tables the post names.
    pub(crate) fn new(post: &Post) -> Tables {
        let tables = post
            .call_lists
            .iter()
            .map(|l| (l.name.to_ascii_uppercase(), l.first.raw(), usize::from(l.len), 0))
            .collect();
        Tables { tables }
    }

    /// Whether `upper` names a table.
    pub(crate) fn has(&self, upper: &str) -> bool {
        self.tables.iter().any(|(n, ..)| n == upper)
    }

    /// Fills a table from a call's list; entries past the list (and past
    /// the table) read 0.
    pub(crate) fn fill(&mut self, eng: &mut Engine, upper: &str, values: &[f64]) {
        let Some((_, first, len, used)) = self.tables.iter_mut().find(|(n, ..)| n == upper) else { return };
        let n = values.len().min(*len);
        for (k, v) in values.iter().take(n).enumerate() {
            eng.set_global(GlobalId::new(*first + k as u16), Value::Num(*v));
        }
        for k in n..*used {
            eng.set_global(GlobalId::new(*first + k as u16), Value::Num(0.0));
        }
        *used = n;
    }

    /// Empties the tables a call did not fill, so no value outlives its call.
    pub(crate) fn clear_except(&mut self, eng: &mut Engine, filled: &[String]) {
        let names: Vec<String> = self
            .tables
            .iter()
            .filter(|(n, _, _, used)| *used > 0 && !filled.contains(n))
            .map(|(n, ..)| n.clone())
            .collect();
        for name in names {
            self.fill(eng, &name, &[]);
        }
    }
}
