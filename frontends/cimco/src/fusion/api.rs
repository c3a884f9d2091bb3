//! The names of Fusion's host API: every function, constant and variable
//! Autodesk's declarations for posts list (`vs-code-extension/res/language
//! files/globals.d.ts` of Autodesk/cam-posteditor, MIT, commit 2165f3e), with
//! each one's declaration and the declaration's own comment
//! (`declarations.tsv`, one line a name, made from that file). A post that
//! uses one of these that postc's host does not define is refused (JS109);
//! any other name the post never defines is JavaScript's `ReferenceError`
//! when it is used. The language server shows a name's declaration on hover
//! and offers the names as completions.

use std::sync::LazyLock;

/// What a declared name is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A host function (`getParameter`) or a post's entry point (`onLinear`).
    Function,
    /// A constant in capitals (`PLANE_XY`, `COMMAND_COOLANT_ON`).
    Constant,
    /// A setting or object the host or the post fills (`tolerance`, `tool`).
    Variable,
}

/// One declared name.
#[derive(Clone, Copy, Debug)]
pub struct Declaration {
    pub name: &'static str,
    pub kind: Kind,
    /// As declared: `getParameter(name: String): Value`, `tool: Tool`.
    pub signature: &'static str,
    /// The declaration's own comment; empty where it has none.
    pub doc: &'static str,
}

const TABLE: &str = include_str!("declarations.tsv");

static DECLARATIONS: LazyLock<Vec<Declaration>> = LazyLock::new(|| {
    let mut all: Vec<Declaration> = TABLE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .filter_map(|l| {
            let mut fields = l.split('\t');
            let name = fields.next()?;
            let kind = match fields.next()? {
                "function" => Kind::Function,
                "constant" => Kind::Constant,
                _ => Kind::Variable,
            };
            Some(Declaration { name, kind, signature: fields.next()?, doc: fields.next().unwrap_or("") })
        })
        .collect();
    all.sort_by_key(|d| d.name);
    all
});

/// Every declared name, sorted.
pub fn declarations() -> &'static [Declaration] {
    &DECLARATIONS
}

/// The declaration of `name`, if Autodesk's declarations list it.
pub fn declaration(name: &str) -> Option<&'static Declaration> {
    let all = declarations();
    all.binary_search_by(|d| d.name.cmp(name)).ok().map(|i| &all[i])
}

/// Whether Autodesk's declarations list `name`.
pub fn is_declared(name: &str) -> bool {
    declaration(name).is_some()
}
