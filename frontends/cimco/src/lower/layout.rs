//! Where everything lives in the IR: the index of each global, of each
//! function (the post's own and the ones postc adds), and the names the
//! script side uses for them.

use std::collections::HashMap;

use postc_ir::{Expr, FunctionId, Global, GlobalId};

use super::consts::Const;
use super::model::Model;

/// Functions and variables postc adds to every post.
pub use crate::made::{COMPENSATION, DRILL_HEADER, FEED_REV_VAR, FEED_VAR, FEEDRATE, INIT, TURN_DRILL};
/// Decimals of a feed per revolution (a feed per minute has one).
pub const FEED_PER_REV_DECIMALS: u8 = 4;

/// IR indices of globals and functions.
pub struct Layout {
    pub globals: Vec<Global>,
    pub global_index: HashMap<String, GlobalId>,
    /// IR function of each top-level JS function.
    pub top_fn: Vec<FunctionId>,
    /// IR functions by name (the post's and postc's).
    pub fn_index: HashMap<String, FunctionId>,
    pub fn_names: Vec<String>,
    /// The specializations of functions that read `arguments`: by the
    /// function and the number of arguments (`native::variadic`), in the
    /// order they were added.
    pub variadic: HashMap<(super::scope::FnId, usize), FunctionId>,
    pub clones: Vec<(super::scope::FnId, usize)>,
    /// Top-level functions lowered before their turn (a caller needed
    /// what they return), until [`super::functions`] takes them.
    pub lowered: HashMap<super::scope::FnId, super::native::Lowered>,
    /// What each function that returns an object or array natively
    /// returns, or why it cannot.
    pub returns: HashMap<super::scope::FnId, Result<super::native::RetShape, super::native::Why>>,
    /// Functions being lowered now.
    pub lowering: std::collections::HashSet<super::scope::FnId>,
    /// Functions whose IR is reshaped (`native::Native::reshaped`).
    pub reshaped: std::collections::HashSet<super::scope::FnId>,
}

impl Layout {
    pub fn new(model: &Model) -> Layout {
        let mut l = Layout {
            globals: Vec::new(),
            global_index: HashMap::new(),
            top_fn: Vec::new(),
            fn_index: HashMap::new(),
            fn_names: Vec::new(),
            variadic: HashMap::new(),
            clones: Vec::new(),
            lowered: HashMap::new(),
            returns: HashMap::new(),
            lowering: Default::default(),
            reshaped: Default::default(),
        };
        for g in &model.globals {
            let initial = match &g.constant {
                Some(c) => const_expr(c),
                // `var g;`: undefined until the post's top level gives it a value.
                None => Expr::Undefined,
            };
            let i = l.add_global(&g.name, initial);
            l.globals[i.index()].implicit = !g.declared;
            l.globals[i.index()].span = g.declared_at;
        }
        for &id in &model.scopes.top_fns {
            let name = model.scopes.funcs[id].name.clone().unwrap_or_default();
            let f = l.add_fn(&name);
            l.top_fn.push(f);
        }
        l
    }

    pub fn add_global(&mut self, name: &str, initial: Expr) -> GlobalId {
        if let Some(&i) = self.global_index.get(name) {
            return i;
        }
        let i = GlobalId::new(self.globals.len() as u16);
        self.globals.push(Global { name: name.to_string(), initial, implicit: false, span: None });
        self.global_index.insert(name.to_string(), i);
        i
    }

    /// Adds a function; a second function of the same name (a JavaScript
    /// redeclaration) gets its own index, and calls by name reach the last.
    pub fn add_fn(&mut self, name: &str) -> FunctionId {
        let i = FunctionId::new(self.fn_names.len() as u16);
        self.fn_names.push(name.to_string());
        self.fn_index.insert(name.to_string(), i);
        i
    }

    pub fn function(&self, name: &str) -> Option<FunctionId> {
        self.fn_index.get(name).copied()
    }
}

/// A constant as an IR expression.
pub fn const_expr(c: &Const) -> Expr {
    match c {
        Const::Num(n) => Expr::Number(*n),
        Const::Str(s) => Expr::Text(s.clone()),
        Const::Bool(b) => Expr::Bool(*b),
        Const::Null => Expr::Null,
        Const::Undefined => Expr::Undefined,
    }
}
