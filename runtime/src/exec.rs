//! The runtime's executable form of post code.
//!
//! The IR ([`postc_ir::Stmt`], [`postc_ir::Expr`]) says what a post means:
//! a handler writes what `onLinear(x, y, z, movement)` returns, a function
//! returns `"G1" + xOutput.format(x) + "\n"`. How that is run fast is the
//! runtime's business, not the IR's: [`crate::prepare`] turns each post into
//! [`Code`] of the statements below, which are the IR's own plus the
//! *output-buffer operations* of the fast path ([`Stmt::Emit`],
//! [`Stmt::Mark`], [`Stmt::MoveBack`], [`Stmt::Truncate`], [`Stmt::Cut`],
//! [`Stmt::Blocks`], [`Expr::Written`]): a function's text is built straight in the output
//! instead of in a value, so a move allocates nothing.
//!
//! Text literals are held as the values they read as ([`Text`]), so
//! reading one allocates nothing.
//!
//! Nothing outside the runtime sees these types: a post on disk, a backend
//! and a lint read the IR only.

use postc_ir::{
    BinaryOp, Builtin, FunctionId, GlobalId, LocalId, Place, Quantity, ScriptId, Site, Span, UnaryOp, VarId,
};

use crate::value::Value;

/// One statement. The IR's ([`postc_ir::Stmt`], which documents each), then
/// the output-buffer operations of the fast path.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    Line {
        pieces: Vec<Piece>,
        span: Option<Span>,
    },
    Write(Expr),
    Assign(Place, Expr),
    Eval(Expr),
    If {
        branches: Vec<(Expr, Vec<Stmt>)>,
        otherwise: Vec<Stmt>,
    },
    While {
        cond: Expr,
        body: Vec<Stmt>,
        span: Option<Span>,
        step: Vec<Stmt>,
    },
    SetMember {
        object: Expr,
        key: Expr,
        value: Expr,
        span: Site,
    },
    Throw {
        value: Expr,
        span: Option<Span>,
    },
    Try {
        body: Vec<Stmt>,
        catch: Option<(LocalId, Vec<Stmt>)>,
        finally: Vec<Stmt>,
    },
    Break,
    Continue,
    Return(Option<Expr>),
    Script(ScriptId),
    Forget(VarId),
    Origin(Span),
    /// Append the text of the pieces to the output without ending a block:
    /// a function's text, built where it will be written.
    Emit(Vec<Piece>),
    /// Store the output's current length in a local: a mark for
    /// [`Stmt::MoveBack`], [`Stmt::Truncate`], [`Stmt::Blocks`] and
    /// [`Expr::Written`].
    Mark(LocalId),
    /// Move the text written since mark `from` back to mark `to`, before
    /// the text written between the two marks (`text = "N10 " + text`).
    MoveBack {
        to: LocalId,
        from: LocalId,
    },
    /// Drop the text written since a mark.
    Truncate(LocalId),
    /// Drop the first characters of the text written since a mark, as
    /// `Builtin::Substring` with one index counts them
    /// (`text.substring(1)` of a text built in the output).
    Cut {
        at: LocalId,
        chars: usize,
    },
    /// Turn the text written since a mark into blocks, as [`Stmt::Write`]
    /// does with a value: each line that is not empty becomes a block.
    Blocks(LocalId),
    /// One word of a block built in the output, in one step: when `cond`
    /// holds, `sep` if a word came before, then the word's pieces
    /// ([`crate::prepare`]'s `fuse` makes it of the statements a joined
    /// word array lowers to; it does what they do, in their order).
    Word {
        cond: Expr,
        word: Vec<Piece>,
        sep: Vec<u8>,
        before: WordsBefore,
    },
    /// A block's run of words in one step ([`WordRun`]).
    Words(Box<WordRun>),
}

/// A run of words joined into a block ([`Stmt::Words`]): the statements
/// `general` (the count set to 0 or the mark set, one [`Stmt::Word`] per
/// local of `locals`, each printed when its text is not empty, and the
/// `if` that drops an empty block and leaves), run in one step when every
/// word is a text, and as written otherwise. `crate::prepare`'s `fuse`
/// makes it last, after every pass that rewrites locals, so `locals`,
/// `sep`, `before` and `empty` always say what `general` does.
#[derive(Clone, Debug, PartialEq)]
pub struct WordRun {
    pub general: Vec<Stmt>,
    /// The local of each word, in order.
    pub locals: Vec<LocalId>,
    /// Written between two words.
    pub sep: Vec<u8>,
    /// The count or the mark the words are told apart by.
    pub before: WordsBefore,
    /// When no word printed: the block's mark to truncate to, then `break`.
    pub empty: Option<LocalId>,
}

/// How a [`Stmt::Word`] knows whether a word came before it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WordsBefore {
    /// A local counts the words (`if (n > 0) sep; word; n += 1`).
    Count(LocalId),
    /// Text was written since a mark (`if (!written) { drop it; word }
    /// else { sep + word }`).
    Written(LocalId),
}

/// One piece of an output block (see [`postc_ir::Piece`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Piece {
    Text(Vec<u8>),
    Var(VarId),
    Expr(Expr),
    /// An element of an array as `join` writes it: `undefined` and null
    /// as nothing, anything else as [`Piece::Expr`] writes it. `prepare`
    /// makes it of the IR's `c == null ? "" : c` that a word array kept as
    /// its joined text writes (`lower/native/arrays.rs` in the CIMCO front
    /// end), so that a word stays one piece.
    Joined(Expr),
}

/// One expression: the IR's ([`postc_ir::Expr`], which documents each),
/// and [`Expr::Written`].
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    Number(f64),
    Text(Text),
    Bool(bool),
    Null,
    Undefined,
    /// Whether any text was written since a mark ([`Stmt::Mark`]).
    Written(LocalId),
    Quantity(Quantity),
    Local(LocalId),
    Global(GlobalId),
    Var(VarId),
    Previous(VarId),
    FormatVar {
        var: VarId,
        value: Box<Expr>,
        span: Option<Span>,
    },
    Format {
        format: postc_ir::FormatId,
        value: Box<Expr>,
        span: Option<Span>,
    },
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    Choose(Box<Expr>, Box<Expr>, Box<Expr>),
    Call(FunctionId, Vec<Expr>),
    Builtin(Builtin, Vec<Expr>),
    /// `local == ""` with `op` one of `==`, `!=`, `===`, `!==`: text is
    /// asked its length, any other value compared as `op` says
    /// ([`crate::prepare`]'s `fuse` makes it of the `Binary`).
    LocalEmpty {
        local: LocalId,
        op: BinaryOp,
    },
    /// `typeof local === "string"` (`is`) or `!==` (not `is`).
    LocalIsText {
        local: LocalId,
        is: bool,
    },
    /// `a && b && ...` (`all`) or `a || b || ...` (not `all`), flattened:
    /// the operands in order, stopping at the first that decides.
    Chain {
        all: bool,
        operands: Vec<Expr>,
    },
    Array(Vec<Expr>),
    Object(Vec<(Text, Expr)>),
    /// A regular expression literal, compiled when the post is prepared.
    Regex {
        literal: RegexLiteral,
        span: Option<Span>,
    },
    /// `object[key]`, and the member in the post.
    Member(Box<Expr>, Box<Expr>, Site),
    /// A name the post never defines ([`postc_ir::Expr::Undeclared`]).
    Undeclared {
        name: crate::value::Text,
        span: Site,
    },
    Output(postc_ir::OutputRef),
    Invoke {
        object: Box<Expr>,
        method: Text,
        args: Vec<Expr>,
        span: Option<Span>,
    },
    Closure {
        function: FunctionId,
        captures: Vec<Expr>,
    },
    CallValue(Box<Expr>, Vec<Expr>),
    This,
    Arguments,
    Host {
        name: Text,
        args: Vec<Expr>,
    },
    /// `parseFloat(text.substring(from))`: the number at character `from`
    /// of the text of `value`, read where the text is formatted, with no
    /// text made (a field post's `parseFloat(getFeedrate(m).substring(1))`).
    ParseFloatFrom {
        value: Box<Expr>,
        from: usize,
    },
}

impl Expr {
    /// A text literal.
    pub fn text(s: &str) -> Expr {
        Expr::Text(Text(Value::text(s), std::cell::Cell::new(0)))
    }

    /// Calls `f` on each expression this one is made of (operands,
    /// arguments, the value a format takes), not deeper.
    pub fn for_each_operand_mut(&mut self, mut f: impl FnMut(&mut Expr)) {
        match self {
            Expr::FormatVar { value, .. }
            | Expr::Format { value, .. }
            | Expr::Unary(_, value)
            | Expr::ParseFloatFrom { value, .. } => f(value),
            Expr::Binary(_, a, b) => {
                f(a);
                f(b);
            }
            Expr::Choose(c, a, b) => {
                f(c);
                f(a);
                f(b);
            }
            Expr::Call(_, args)
            | Expr::Builtin(_, args)
            | Expr::Chain { operands: args, .. }
            | Expr::Array(args)
            | Expr::Closure { captures: args, .. }
            | Expr::Host { args, .. } => args.iter_mut().for_each(f),
            Expr::Object(props) => props.iter_mut().for_each(|(_, v)| f(v)),
            Expr::Member(a, b, _) => {
                f(a);
                f(b);
            }
            Expr::Invoke { object, args, .. } | Expr::CallValue(object, args) => {
                f(object);
                args.iter_mut().for_each(f);
            }
            Expr::This
            | Expr::Undefined
            | Expr::Arguments
            | Expr::Output(_)
            | Expr::Regex { .. }
            | Expr::Undeclared { .. } => {}
            Expr::LocalEmpty { .. }
            | Expr::LocalIsText { .. }
            | Expr::Number(_)
            | Expr::Text(_)
            | Expr::Bool(_)
            | Expr::Null
            | Expr::Written(_)
            | Expr::Quantity(_)
            | Expr::Local(_)
            | Expr::Global(_)
            | Expr::Var(_)
            | Expr::Previous(_) => {}
        }
    }

    /// How many expressions this one is made of, itself included.
    pub fn size(&mut self) -> usize {
        let mut n = 1;
        self.for_each_operand_mut(|a| n += a.size());
        n
    }

    /// Calls `f` on every local the expression reads, at any depth
    /// ([`Expr::Local`] and the marks of [`Expr::Written`]).
    pub fn for_each_local_mut(&mut self, f: &mut impl FnMut(&mut LocalId)) {
        match self {
            Expr::Local(k)
            | Expr::Written(k)
            | Expr::LocalEmpty { local: k, .. }
            | Expr::LocalIsText { local: k, .. } => f(k),
            e => e.for_each_operand_mut(|a| a.for_each_local_mut(f)),
        }
    }
}

/// How a statement uses a local it names outside its expressions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LocalUse {
    /// Read (`Truncate(m)` reads mark `m`).
    Read,
    /// Written (`x = ...`, `Mark(m)`).
    Write,
    /// Read, then perhaps written (the count of a [`Stmt::Word`]).
    Update,
}

impl Stmt {
    /// Calls `f` on the statement's own expressions, in the order they are
    /// evaluated; not those of statements nested in it.
    pub fn for_each_expr_mut(&mut self, mut f: impl FnMut(&mut Expr)) {
        let pieces = |pieces: &mut Vec<Piece>, f: &mut dyn FnMut(&mut Expr)| {
            for p in pieces {
                if let Piece::Expr(e) | Piece::Joined(e) = p {
                    f(e);
                }
            }
        };
        match self {
            Stmt::Line { pieces: p, .. } | Stmt::Emit(p) => pieces(p, &mut f),
            Stmt::Write(e) | Stmt::Assign(_, e) | Stmt::Eval(e) | Stmt::Return(Some(e)) => f(e),
            Stmt::If { branches, .. } => branches.iter_mut().for_each(|(c, _)| f(c)),
            Stmt::While { cond, .. } => f(cond),
            Stmt::SetMember { object, key, value, .. } => {
                f(object);
                f(key);
                f(value);
            }
            Stmt::Throw { value, .. } => f(value),
            Stmt::Try { .. } => {}
            Stmt::Word { cond, word, .. } => {
                f(cond);
                pieces(word, &mut f);
            }
            // Its statements are its body.
            Stmt::Words(_)
            | Stmt::Break
            | Stmt::Continue
            | Stmt::Return(None)
            | Stmt::Script(_)
            | Stmt::Forget(_)
            | Stmt::Origin(_)
            | Stmt::Mark(_)
            | Stmt::MoveBack { .. }
            | Stmt::Truncate(_)
            | Stmt::Cut { .. }
            | Stmt::Blocks(_) => {}
        }
    }

    /// Calls `f` on each statement list nested in this statement.
    pub fn for_each_body_mut(&mut self, mut f: impl FnMut(&mut Vec<Stmt>)) {
        match self {
            Stmt::If { branches, otherwise } => {
                branches.iter_mut().for_each(|(_, b)| f(b));
                f(otherwise);
            }
            Stmt::While { body, step, .. } => {
                f(body);
                f(step);
            }
            Stmt::Try { body, catch, finally } => {
                f(body);
                if let Some((_, handler)) = catch {
                    f(handler);
                }
                f(finally);
            }
            Stmt::Words(run) => f(&mut run.general),
            _ => {}
        }
    }

    /// Calls `f` on the locals the statement names outside its
    /// expressions (assigned places and marks), with how it uses each.
    pub fn for_each_named_local_mut(&mut self, mut f: impl FnMut(LocalUse, &mut LocalId)) {
        match self {
            Stmt::Assign(Place::Local(k), _) | Stmt::Mark(k) | Stmt::Try { catch: Some((k, _)), .. } => {
                f(LocalUse::Write, k)
            }
            Stmt::MoveBack { to, from } => {
                f(LocalUse::Read, to);
                f(LocalUse::Read, from);
            }
            Stmt::Truncate(k) | Stmt::Cut { at: k, .. } | Stmt::Blocks(k) => f(LocalUse::Read, k),
            Stmt::Word { before: WordsBefore::Count(k), .. } => f(LocalUse::Update, k),
            Stmt::Word { before: WordsBefore::Written(k), .. } => f(LocalUse::Read, k),
            _ => {}
        }
    }
}

/// Whether statements use JavaScript's objects: arrays, objects,
/// properties, methods, function values, `this`, `throw`, `try`, or a
/// loop with a step. The fast-path passes of [`crate::prepare`] are
/// written for code without them and leave such code as it is.
pub fn uses_objects(body: &mut [Stmt]) -> bool {
    fn expr(e: &mut Expr) -> bool {
        if matches!(
            e,
            Expr::Array(_)
                | Expr::Builtin(
                    Builtin::Keys
                        | Builtin::OwnKeys
                        | Builtin::HasProperty
                        | Builtin::JsString
                        | Builtin::Construct
                        | Builtin::NewRegExp
                        | Builtin::FormatNumber
                        | Builtin::Words
                        | Builtin::FormatOutput
                        | Builtin::Property
                        | Builtin::SettingError
                        | Builtin::Prototype
                        | Builtin::CreateObject
                        | Builtin::InstanceOf,
                    _
                )
                | Expr::Object(_)
                | Expr::Regex { .. }
                | Expr::Undeclared { .. }
                | Expr::Member(..)
                | Expr::Invoke { .. }
                | Expr::Closure { .. }
                | Expr::CallValue(..)
                | Expr::This
                | Expr::Arguments
                | Expr::Output(_)
                | Expr::Host { .. }
        ) {
            return true;
        }
        let mut found = false;
        e.for_each_operand_mut(|a| found |= expr(a));
        found
    }
    body.iter_mut().any(|s| {
        if matches!(s, Stmt::SetMember { .. } | Stmt::Throw { .. } | Stmt::Try { .. })
            || matches!(s, Stmt::While { step, .. } if !step.is_empty())
        {
            return true;
        }
        let mut found = false;
        s.for_each_expr_mut(|e| found |= expr(e));
        s.for_each_body_mut(|b| found |= uses_objects(b));
        found
    })
}

/// A text literal: the text value it reads as (shared, never copied), and
/// the text itself through `Deref`.
///
/// A literal that names a property (`o.name`, `o.name(...)`, `o.name =
/// v`) is also that site's *inline cache*: the index among an object's
/// keys where the name was found last ([`crate::value::Object::find_hinted`]).
/// Objects a constructor or a literal makes have their keys in one order,
/// so a site that reads the same property of such objects finds it at
/// the remembered index with one comparison instead of a scan. The cache
/// is a hint, checked at every use: it changes how fast a property is
/// found, never which.
#[derive(Clone)]
pub struct Text(Value, std::cell::Cell<u32>);

impl PartialEq for Text {
    /// The same text (the cache is no part of the literal's meaning).
    fn eq(&self, other: &Text) -> bool {
        self.0 == other.0
    }
}

impl std::fmt::Debug for Text {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl Text {
    /// A literal of the text.
    pub fn new(text: crate::value::Text) -> Text {
        Text(Value::Text(text), std::cell::Cell::new(0))
    }

    /// The value the literal reads as.
    #[inline]
    pub fn value(&self) -> &Value {
        &self.0
    }

    /// The site's inline cache ([`Text`]).
    #[inline]
    pub fn hint(&self) -> &std::cell::Cell<u32> {
        &self.1
    }

    /// Whether the literal is `""`, from its length (not through `str`,
    /// whose view of short text checks it is UTF-8 each time).
    #[inline]
    pub fn is_empty(&self) -> bool {
        match &self.0 {
            Value::Text(t) => t.is_empty(),
            _ => true,
        }
    }
}

impl std::ops::Deref for Text {
    type Target = str;

    fn deref(&self) -> &str {
        match &self.0 {
            Value::Text(t) => t,
            _ => "",
        }
    }
}

/// A regular expression literal: its pattern compiled once, when the post
/// is prepared, and shared by every value the literal makes (they keep no
/// state: [`crate::regex`]); or why postc cannot run it, reported with
/// code JS108 when the literal is evaluated (`postc_driver` refuses
/// such a post when it is compiled; a post built some other way meets it
/// here).
#[derive(Clone, Debug)]
pub struct RegexLiteral(pub Result<std::rc::Rc<crate::regex::Regex>, std::rc::Rc<str>>);

impl RegexLiteral {
    /// Compiles `/pattern/flags`.
    pub fn new(pattern: &str, flags: &str) -> RegexLiteral {
        RegexLiteral(crate::regex::Regex::new(pattern, flags).map(std::rc::Rc::new).map_err(std::rc::Rc::from))
    }
}

impl PartialEq for RegexLiteral {
    /// The same compiled pattern, or the same reason.
    fn eq(&self, other: &RegexLiteral) -> bool {
        match (&self.0, &other.0) {
            (Ok(a), Ok(b)) => std::rc::Rc::ptr_eq(a, b),
            (Err(a), Err(b)) => a == b,
            _ => false,
        }
    }
}

/// A post function as the runtime runs it; its name and span stay in the
/// post's [`postc_ir::Function`].
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    /// Number of parameters.
    pub params: usize,
    /// The function reads `arguments`: its calls keep them.
    pub uses_arguments: bool,
    /// The function reads `this`: called plainly (`f()`), its `this` is
    /// the global object, whatever method called it.
    pub uses_this: bool,
    /// Parameters not passed and locals not yet set hold `undefined`
    /// (JavaScript), not null.
    pub starts_undefined: bool,
    /// Parameters plus locals.
    pub slots: u16,
    pub body: Body,
    /// The expression the function's body only returns, when it runs no
    /// post code (no call, method, constructor or host function) and
    /// reads no `this` nor `arguments`: a call evaluates it, with the one
    /// step its `return` costs ([`returned`]).
    pub returns: Option<Expr>,
    /// The post's function this one runs for: itself, or the function a
    /// specialised copy was made from (`prepare/factories.rs`), whose name
    /// and span diagnostics, `--trace` and `--profile` report.
    pub origin: FunctionId,
}

impl Function {
    /// What a parameter not passed, a local before its value and a call
    /// that returns nothing hold: `undefined` or null.
    pub fn fill(&self) -> Expr {
        if self.starts_undefined { Expr::Undefined } else { Expr::Null }
    }
}

/// Native statements, or a script the host runs.
#[derive(Clone, Debug, PartialEq)]
pub enum Body {
    Native(Vec<Stmt>),
    Script(ScriptId),
}

/// A post's code, prepared to run: every function, every handler body, the
/// one-time code and the globals' starting values, in the post's order.
#[derive(Clone, Debug, Default)]
pub struct Code {
    pub functions: Vec<Function>,
    pub handlers: Vec<Vec<Stmt>>,
    /// The slots of the frame the handlers share: the most any uses. A
    /// handler starts as `null` the locals it may read before writing
    /// them, and finds the others as the last event left them.
    pub handler_slots: usize,
    pub init: Vec<Stmt>,
    pub globals: Vec<Expr>,
}

/// The runtime form of IR statements.
pub fn stmts(body: &[postc_ir::Stmt]) -> Vec<Stmt> {
    body.iter().map(stmt).collect()
}

/// The runtime form of one IR statement.
pub fn stmt(s: &postc_ir::Stmt) -> Stmt {
    use postc_ir::Stmt as S;
    match s {
        S::Line { pieces, span } => Stmt::Line { pieces: pieces.iter().map(piece).collect(), span: *span },
        S::Write(e) => Stmt::Write(expr(e)),
        S::Assign(p, e) => Stmt::Assign(*p, expr(e)),
        S::Eval(e) => Stmt::Eval(expr(e)),
        S::If { branches, otherwise } => Stmt::If {
            branches: branches.iter().map(|(c, b)| (expr(c), stmts(b))).collect(),
            otherwise: stmts(otherwise),
        },
        S::While { cond, body, span, step } => {
            Stmt::While { cond: expr(cond), body: stmts(body), span: *span, step: stmts(step) }
        }
        S::SetMember { object, key, value, span } => {
            Stmt::SetMember { object: expr(object), key: expr(key), value: expr(value), span: *span }
        }
        S::Throw { value, span } => Stmt::Throw { value: expr(value), span: *span },
        S::Try { body, catch, finally } => {
            Stmt::Try { body: stmts(body), catch: catch.as_ref().map(|(k, b)| (*k, stmts(b))), finally: stmts(finally) }
        }
        S::Break => Stmt::Break,
        S::Continue => Stmt::Continue,
        S::Return(e) => Stmt::Return(e.as_ref().map(expr)),
        S::Script(id) => Stmt::Script(*id),
        S::Forget(v) => Stmt::Forget(*v),
        S::Origin(span) => Stmt::Origin(*span),
    }
}

/// The runtime form of one piece.
pub fn piece(p: &postc_ir::Piece) -> Piece {
    match p {
        postc_ir::Piece::Text(bytes) => Piece::Text(bytes.clone()),
        postc_ir::Piece::Var(v) => Piece::Var(*v),
        postc_ir::Piece::Expr(e) => Piece::Expr(expr(e)),
    }
}

/// The runtime form of one IR expression.
pub fn expr(e: &postc_ir::Expr) -> Expr {
    use postc_ir::Expr as E;
    let boxed = |e: &postc_ir::Expr| Box::new(expr(e));
    let list = |args: &[postc_ir::Expr]| args.iter().map(expr).collect();
    match e {
        E::Number(n) => Expr::Number(*n),
        E::Text(s) => Expr::text(s),
        E::Bool(b) => Expr::Bool(*b),
        E::Null => Expr::Null,
        E::Quantity(q) => Expr::Quantity(*q),
        E::Local(k) => Expr::Local(*k),
        E::Global(g) => Expr::Global(*g),
        E::Var(v) => Expr::Var(*v),
        E::Previous(v) => Expr::Previous(*v),
        E::FormatVar { var, value, span } => Expr::FormatVar { var: *var, value: boxed(value), span: *span },
        E::Format { format, value, span } => Expr::Format { format: *format, value: boxed(value), span: *span },
        E::Unary(op, a) => Expr::Unary(*op, boxed(a)),
        E::Binary(op, a, b) => Expr::Binary(*op, boxed(a), boxed(b)),
        E::Choose(c, a, b) => Expr::Choose(boxed(c), boxed(a), boxed(b)),
        E::Call(f, args) => Expr::Call(*f, list(args)),
        E::Builtin(b, args) => Expr::Builtin(*b, list(args)),
        E::Undefined => Expr::Undefined,
        E::Array(items) => Expr::Array(list(items)),
        E::Object(props) => {
            Expr::Object(props.iter().map(|(k, v)| (Text::new(crate::value::Text::new(k)), expr(v))).collect())
        }
        E::Regex { pattern, flags, span } => Expr::Regex { literal: RegexLiteral::new(pattern, flags), span: *span },
        E::Member { object, key, span } => Expr::Member(boxed(object), boxed(key), *span),
        E::Undeclared { name, span } => Expr::Undeclared { name: crate::value::Text::new(name), span: *span },
        E::Invoke { object, method, args, span } => Expr::Invoke {
            object: boxed(object),
            method: Text::new(crate::value::Text::shared(method)),
            args: list(args),
            span: *span,
        },
        E::Closure { function, captures } => Expr::Closure { function: *function, captures: list(captures) },
        E::CallValue(f, args) => Expr::CallValue(boxed(f), list(args)),
        E::This => Expr::This,
        E::Arguments => Expr::Arguments,
        E::Output(o) => Expr::Output(*o),
        E::Host { name, args } => Expr::Host { name: Text::new(crate::value::Text::new(name)), args: list(args) },
    }
}

/// Whether a function's own body reads `this` (a function it makes is a
/// function of its own).
fn reads_this(f: &postc_ir::Function) -> bool {
    use postc_ir::visit::{Visit, walk_expr};
    struct Finds(bool);
    impl Visit for Finds {
        fn visit_expr(&mut self, e: &postc_ir::Expr) {
            self.0 |= matches!(e, postc_ir::Expr::This);
            walk_expr(self, e);
        }
    }
    let mut finds = Finds(false);
    if let postc_ir::Body::Native(body) = &f.body {
        for s in body {
            finds.visit_stmt(s);
        }
    }
    finds.0
}

/// The runtime form of a post function.
pub fn function(id: FunctionId, f: &postc_ir::Function) -> Function {
    Function {
        origin: id,
        returns: None,
        params: f.params.len(),
        uses_arguments: f.uses_arguments,
        uses_this: reads_this(f),
        starts_undefined: f.starts_undefined,
        slots: f.slots,
        body: match &f.body {
            postc_ir::Body::Native(b) => Body::Native(stmts(b)),
            postc_ir::Body::Script(id) => Body::Script(*id),
        },
    }
}

/// The expression a function body only returns, when evaluating it runs
/// no post code and reads no `this` nor `arguments` ([`Function::returns`]).
pub fn returned(body: &[Stmt]) -> Option<Expr> {
    fn plain(e: &Expr) -> bool {
        if matches!(
            e,
            Expr::Call(..)
                | Expr::CallValue(..)
                | Expr::Invoke { .. }
                | Expr::Host { .. }
                | Expr::Builtin(Builtin::Construct | Builtin::JsString, _)
                | Expr::This
                | Expr::Arguments
        ) {
            return false;
        }
        let mut ok = true;
        let mut e = e.clone();
        e.for_each_operand_mut(|a| ok &= plain(a));
        ok
    }
    match body {
        [Stmt::Return(Some(e))] if plain(e) => Some(e.clone()),
        _ => None,
    }
}
