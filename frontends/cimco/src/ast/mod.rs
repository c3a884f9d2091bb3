//! The syntax tree of a CIMCO CNC-Calc post: the ES5 subset that posts use.
//!
//! Every statement and expression carries the byte [`Span`] it was parsed
//! from, so that the lowering (to native IR statements, or to Rhai source
//! with a span map) can point every later error back at the post. The tree
//! is faithful enough to print back as JavaScript ([`crate::print`]):
//! parentheses are not kept (the printer puts back the ones precedence
//! needs), `else if` chains are kept flat in [`StmtKind::If`], strings and
//! numbers are kept as their values.
//!
//! Nodes are built with [`Expr::new`] and [`Stmt::new`], which record how
//! deep the node is; the parser refuses trees deeper than
//! [`MAX_TREE_DEPTH`], so every recursive walk over a tree it returns is
//! bounded (parsing, dumping and printing the deepest accepted trees runs
//! on a 1 MiB thread stack in a debug build; see `tests/robustness.rs`).

mod depth;
mod ops;

use postc_ir::Span;

pub use ops::{AssignOp, BinaryOp, LogicalOp, UnaryOp, UpdateOp};

use depth::{expr_children_depth, stmt_children_depth};

/// The deepest tree the parser returns; deeper parts become
/// [`ExprKind::Error`] with a diagnostic.
pub const MAX_TREE_DEPTH: u32 = 256;

/// A whole post file.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// A name as written, with where it was written.
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    pub name: String,
    pub span: Span,
}

/// A function declaration or function expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    /// `None` for an anonymous function expression.
    pub name: Option<Ident>,
    pub params: Vec<Ident>,
    pub body: Vec<Stmt>,
    /// The braces and everything between them.
    pub body_span: Span,
    /// From `function` to the closing brace.
    pub span: Span,
    /// An arrow function (`(a) => a + 1`, Fusion): `this` is the `this` of
    /// the function around it; an expression body is the `return` of that
    /// expression.
    pub arrow: bool,
}

/// One statement.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
    depth: u32,
}

/// The kinds of statements.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// `var a = 1, b;`
    Var(Vec<VarDeclarator>),
    /// `function name(a, b) { ... }`
    Function(Function),
    /// An expression evaluated for its effect: `a = 1;`, `f(x);`.
    Expr(Expr),
    /// `{ ... }`
    Block(Vec<Stmt>),
    /// `;`
    Empty,
    /// `if (c) s else if (d) t else u`: the first branch and every
    /// `else if` branch in order, then the final `else`.
    If {
        branches: Vec<IfBranch>,
        otherwise: Option<Box<Stmt>>,
    },
    /// `switch (x) { case 1: ... default: ... }`; cases fall through.
    Switch {
        discriminant: Expr,
        cases: Vec<SwitchCase>,
    },
    /// `for (init; test; update) body`
    For {
        init: Option<ForInit>,
        test: Option<Expr>,
        update: Option<Expr>,
        body: Box<Stmt>,
    },
    /// `for (var k in obj) body` (`declared`) or `for (k in obj) body`.
    ForIn {
        declared: bool,
        name: Ident,
        object: Expr,
        body: Box<Stmt>,
    },
    /// `while (cond) body`
    While {
        cond: Expr,
        body: Box<Stmt>,
    },
    /// `do body while (cond);`
    DoWhile {
        body: Box<Stmt>,
        cond: Expr,
    },
    Break,
    Continue,
    /// `return;` or `return value;`
    Return(Option<Expr>),
    /// `throw value;`
    Throw(Expr),
    /// `try { } catch (e) { } finally { }`; at least one of the two
    /// clauses is present.
    Try {
        block: Vec<Stmt>,
        handler: Option<CatchClause>,
        finalizer: Option<Vec<Stmt>>,
    },
    /// A statement that did not parse; its diagnostic has been reported.
    Error,
}

/// `name = init` in a `var` statement.
#[derive(Clone, Debug, PartialEq)]
pub struct VarDeclarator {
    pub name: Ident,
    pub init: Option<Expr>,
    pub span: Span,
}

/// One `if` or `else if` branch.
#[derive(Clone, Debug, PartialEq)]
pub struct IfBranch {
    pub cond: Expr,
    pub body: Stmt,
}

/// `case test:` (or `default:` when `test` is `None`) and the statements
/// up to the next case.
#[derive(Clone, Debug, PartialEq)]
pub struct SwitchCase {
    pub test: Option<Expr>,
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// The first clause of a `for (;;)` loop.
#[derive(Clone, Debug, PartialEq)]
pub enum ForInit {
    Var(Vec<VarDeclarator>),
    Expr(Expr),
}

/// `catch (param) { body }`
#[derive(Clone, Debug, PartialEq)]
pub struct CatchClause {
    pub param: Ident,
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// One expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
    depth: u32,
}

/// The kinds of expressions.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number(f64),
    /// A string literal, escapes decoded.
    String(String),
    Bool(bool),
    Null,
    Undefined,
    This,
    /// `` `text ${a} more ${b}` `` (Fusion): the pieces of text, escapes
    /// decoded, one more than the substitutions between them.
    Template {
        quasis: Vec<String>,
        exprs: Vec<Expr>,
    },
    /// `/pattern/flags`, as written (escapes kept).
    Regex {
        pattern: String,
        flags: String,
    },
    /// A variable or function name.
    Ident(String),
    /// `[a, b, c]`
    Array(Vec<Expr>),
    /// `{ key: value, ... }`
    Object(Vec<Property>),
    /// `function (a) { ... }`, possibly named.
    Function(Box<Function>),
    /// `object.property`
    Member {
        object: Box<Expr>,
        property: Ident,
    },
    /// `object[index]`
    Index {
        object: Box<Expr>,
        index: Box<Expr>,
    },
    /// `callee(args)`
    Call {
        callee: Box<Expr>,
        args: Vec<Expr>,
    },
    /// `new callee(args)`; `new Foo` has no arguments.
    New {
        callee: Box<Expr>,
        args: Vec<Expr>,
    },
    /// `-x`, `+x`, `!x`, `~x`, `typeof x`
    Unary {
        op: UnaryOp,
        operand: Box<Expr>,
    },
    /// `++x`, `x--`
    Update {
        op: UpdateOp,
        prefix: bool,
        target: Box<Expr>,
    },
    /// Arithmetic, bitwise, comparison and equality operators.
    Binary {
        op: BinaryOp,
        left: Box<Expr>,
        right: Box<Expr>,
    },
    /// `&&` and `||`, which yield one of their operands.
    Logical {
        op: LogicalOp,
        left: Box<Expr>,
        right: Box<Expr>,
    },
    /// `target = value`, `target += value`, ...
    Assign {
        op: AssignOp,
        target: Box<Expr>,
        value: Box<Expr>,
    },
    /// `test ? consequent : alternate`
    Conditional {
        test: Box<Expr>,
        consequent: Box<Expr>,
        alternate: Box<Expr>,
    },
    /// `a, b, c`
    Sequence(Vec<Expr>),
    /// An expression that did not parse; its diagnostic has been reported.
    Error,
}

/// `key: value` in an object literal.
#[derive(Clone, Debug, PartialEq)]
pub struct Property {
    pub key: PropertyKey,
    pub value: Expr,
    pub span: Span,
}

/// The key of a property: its name as JavaScript sees it, and how it was
/// written.
#[derive(Clone, Debug, PartialEq)]
pub struct PropertyKey {
    pub name: String,
    pub written: KeyForm,
    pub span: Span,
}

/// How a property key was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyForm {
    /// `prefix: ...` (also keywords: `default: ...`)
    Ident,
    /// `"prefix": ...`
    String,
    /// `10: ...`
    Number,
}

impl Expr {
    /// Builds an expression and records its depth.
    pub fn new(kind: ExprKind, span: Span) -> Expr {
        let depth = 1 + expr_children_depth(&kind);
        Expr { kind, span, depth }
    }

    /// An error placeholder.
    pub fn error(span: Span) -> Expr {
        Expr::new(ExprKind::Error, span)
    }

    /// How many nodes deep the tree under this expression is (1 for a leaf).
    pub fn depth(&self) -> u32 {
        self.depth
    }

    /// Whether this expression can be assigned to (`x`, `a.b`, `a[i]`).
    pub fn is_assignable(&self) -> bool {
        matches!(self.kind, ExprKind::Ident(_) | ExprKind::Member { .. } | ExprKind::Index { .. } | ExprKind::Error)
    }
}

impl Stmt {
    /// Builds a statement and records its depth.
    pub fn new(kind: StmtKind, span: Span) -> Stmt {
        let depth = 1 + stmt_children_depth(&kind);
        Stmt { kind, span, depth }
    }

    /// An error placeholder.
    pub fn error(span: Span) -> Stmt {
        Stmt::new(StmtKind::Error, span)
    }

    /// How many nodes deep the tree under this statement is.
    pub fn depth(&self) -> u32 {
        self.depth
    }
}
