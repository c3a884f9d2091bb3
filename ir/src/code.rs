//! Statements and expressions: the bodies of handlers and functions.
//!
//! A Vectric section is a list of [`Stmt::Line`]s whose pieces are literal
//! bytes and variables. CIMCO functions that only format, compare and
//! concatenate, and all VcPost Subs, lower to the rest of this small
//! language: assignments, conditionals, loops, calls and returns over
//! [`Value`]s that are numbers, text or booleans. What a dialect cannot say
//! here runs as a [`crate::post::Script`].
//!
//! The JavaScript dialects' values follow JavaScript's own semantics,
//! defined once in [`crate::js`] (ToNumber, ToString, the order of texts,
//! 32-bit conversions): the frontend's compile-time values and the
//! runtime's interpreter, constant folder and script host read them there,
//! so a value folded when the post is compiled is the value it computes
//! when it runs.
//!
//! The IR says what a post means, not how it runs fast: a CIMCO handler is
//! `Write(onLinear(x, y, z, movement))` and `onLinear` returns its text.
//! The runtime prepares its own fast form (postc-runtime's `prepare`:
//! functions' text built straight in the output); nothing here is an
//! execution strategy.

use serde::{Deserialize, Serialize};

use crate::diagnostic::Span;
use crate::id::{FormatId, FunctionId, GlobalId, LocalId, ScriptId, VarId};
use crate::quantity::Quantity;

/// One statement.
/// Where in the post a member, an assignment to one or a name stands: the
/// place of the error it may raise when it runs. It takes no part in
/// equality: two expressions that differ only in where they stand compute
/// the same, and a pass that compares expressions takes them as one.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Site(pub Option<Span>);

impl PartialEq for Site {
    fn eq(&self, _: &Site) -> bool {
        true
    }
}

impl Site {
    pub fn is_none(&self) -> bool {
        self.0.is_none()
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Stmt {
    /// Write one block: the pieces, then the line ending. Vectric output
    /// strings, VcPost `Out`, CIMCO lines. `span` is the post text that
    /// wrote it (the section line, the `Out` statement), for diagnostics
    /// and `--trace`.
    Line {
        pieces: Vec<Piece>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    /// Write the value of an expression as output text; each line of the
    /// text becomes a block (CIMCO handlers return their blocks as text).
    Write(Expr),
    /// Assign a value to a place.
    Assign(Place, Expr),
    /// Evaluate for effect (a call whose result is not used).
    Eval(Expr),
    /// `if` / `else if` / `else`.
    If { branches: Vec<(Expr, Vec<Stmt>)>, otherwise: Vec<Stmt> },
    /// A loop; the runtime stops it with a diagnostic at `span` when the
    /// post's step budget runs out.
    While {
        cond: Expr,
        body: Vec<Stmt>,
        span: Option<Span>,
        /// Runs after each pass through `body`, `continue` included,
        /// before `cond` is tested again (a `for` loop's update).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        step: Vec<Stmt>,
    },
    /// Leave the innermost loop.
    Break,
    /// Next iteration of the innermost loop.
    Continue,
    /// Leave the function, with a value or without.
    Return(Option<Expr>),
    /// Run a script call (a Vectric `<!>` Lua call, which postc keeps but
    /// does not run).
    Script(ScriptId),
    /// Make a variable forget what it printed last, so that the next value
    /// prints whatever it is (CIMCO/HSM `xOutput.reset()`).
    Forget(VarId),
    /// `object[key] = value`: sets a property of an object, an element of
    /// an array (growing it, as JavaScript does), or nothing for other
    /// values; a TypeError for `undefined` and `null`, reported at `span`
    /// (the assignment in the post).
    SetMember {
        object: Expr,
        key: Expr,
        value: Expr,
        #[serde(default, skip_serializing_if = "Site::is_none")]
        span: Site,
    },
    /// `throw value`: leaves every function up to the innermost `try`;
    /// with none, the post stops with an error at `span`.
    Throw {
        value: Expr,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    /// `try { body } catch (local) { handler } finally { last }`: a
    /// `throw` (or a run-time error of the post's code) in `body` runs
    /// `handler` with the thrown value in `local`; `last` runs however the
    /// two end. Step budgets, nesting limits and text budgets are not
    /// caught.
    Try { body: Vec<Stmt>, catch: Option<(LocalId, Vec<Stmt>)>, finally: Vec<Stmt> },
    /// Where the text a handler writes next comes from: a CIMCO entry
    /// point's `return` statement, placed before it; a statement of a
    /// Fusion post's own text that calls a function, placed before it. It
    /// does nothing when the post runs; `--trace` reports the blocks the
    /// handler writes after it at this span (the latest one the handler
    /// passed, so that a line names the statement that returned it even
    /// when the function was inlined into the handler; under a host's API
    /// compiled with the post, the latest of the innermost post function
    /// still running), and an error the host's code raises under it is
    /// also placed there.
    Origin(Span),
}

/// One piece of an output block.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Piece {
    /// Bytes written as they are.
    Text(Vec<u8>),
    /// A variable, formatted from its source with its prefix and modality.
    Var(VarId),
    /// The text of an expression.
    Expr(Expr),
}

/// Where an assignment stores.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Place {
    /// A function parameter or local, by slot.
    Local(LocalId),
    /// A global.
    Global(GlobalId),
    /// The value of a variable (VcPost register).
    Var(VarId),
}

/// A format or an output variable, held as a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum OutputRef {
    Format(FormatId),
    Variable(VarId),
}

/// One expression.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Expr {
    Number(f64),
    Text(String),
    Bool(bool),
    /// No value: JavaScript's `null` (and BASIC's empty value).
    Null,
    /// JavaScript's `undefined`: what a variable holds before it is
    /// given a value, a missing argument, a missing property.
    Undefined,
    /// A value the runtime knows (position, feed, tool name, ...), in the
    /// post's units.
    Quantity(Quantity),
    /// A function parameter or local.
    Local(LocalId),
    /// A global.
    Global(GlobalId),
    /// A variable's current value.
    Var(VarId),
    /// The value a variable had before its last assignment (VcPost
    /// `.Previous`, CIMCO `getLast()`).
    Previous(VarId),
    /// Format a value through a variable: its prefix, format and modality;
    /// updates what the variable last printed (CIMCO `xOutput.format(v)`).
    FormatVar {
        var: VarId,
        value: Box<Expr>,
        /// The post text that asks for it: where a value that is not a
        /// finite number is reported.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    /// Format a value with a format alone (CIMCO `xyzFormat.format(v)`).
    Format {
        format: FormatId,
        value: Box<Expr>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `cond ? a : b`
    Choose(Box<Expr>, Box<Expr>, Box<Expr>),
    /// Call a post function.
    Call(FunctionId, Vec<Expr>),
    /// Call a built-in function.
    Builtin(Builtin, Vec<Expr>),
    /// `[a, b, c]`: a new array.
    Array(Vec<Expr>),
    /// `{k: v, ...}`: a new object, its properties in this order.
    Object(Vec<(String, Expr)>),
    /// `/pattern/flags`: a JavaScript regular expression, a new value each
    /// time it is evaluated (JavaScript's meaning of the pattern; flags
    /// among `g`, `i`, `m`, each at most once). `span` is the literal in
    /// the post, where a pattern postc cannot run is reported.
    Regex {
        pattern: String,
        flags: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    /// `value[key]` (`value.key`): a property of an object or a function,
    /// an element or the `length` of an array or a text; what the value
    /// does not have is looked for along its prototype chain (an object
    /// made by `new F()` reads the methods of `F.prototype`; every value
    /// reads the built-in methods of its kind as function values);
    /// `undefined` when there is none. A TypeError for a property of
    /// `undefined` or `null`, reported at `span` (the member in the post).
    Member {
        object: Box<Expr>,
        key: Box<Expr>,
        #[serde(default, skip_serializing_if = "Site::is_none")]
        span: Site,
    },
    /// A name the post never defines, read or called: JavaScript's
    /// `ReferenceError` when it runs (`try` catches it), reported at
    /// `span` (the name in the post); a property of the global object
    /// when the post set one (`this._ = ...`).
    Undeclared {
        name: String,
        #[serde(default, skip_serializing_if = "Site::is_none")]
        span: Site,
    },
    /// `object.method(args)`: the function the object holds under that
    /// name, its own or its prototype chain's, called with `this` the
    /// object; or a built-in method of an array, a text, a number, a
    /// function (`push`, `join`, `indexOf`, `substring`, `toFixed`, `call`,
    /// ...). A TypeError when there is none.
    Invoke {
        object: Box<Expr>,
        method: String,
        args: Vec<Expr>,
        /// The call in the post: where a method that formats a value that
        /// is not a finite number is reported.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<Span>,
    },
    /// A format or an output variable as a value (a CNC-Calc post hands
    /// `xyzFormat` to a helper that calls `f.format(x)`): its methods are
    /// those of the host object, called through [`Expr::Invoke`].
    Output(OutputRef),
    /// A post function as a value. The function's first parameters take
    /// `captures`, the values it closes over, when the value is made (a
    /// local that changes after it is captured lives in a cell the maker
    /// and the closure share: a one-item array); the caller's arguments
    /// fill the rest. A function value has properties of its own, its
    /// `prototype` first (`{constructor: f}` until the post sets another).
    /// A function with no captures is one value however often it is made
    /// (a top-level function is one object in JavaScript): the same
    /// identity and the same `prototype` everywhere.
    Closure {
        function: FunctionId,
        captures: Vec<Expr>,
    },
    /// Calls a function value with `args` (`this` undefined).
    CallValue(Box<Expr>, Vec<Expr>),
    /// The object a method was called on (`undefined` elsewhere).
    This,
    /// The arguments the function was called with, as an array
    /// (JavaScript's `arguments`); the function says it reads them
    /// ([`crate::Function::uses_arguments`]).
    Arguments,
    /// A function of the post's host, the API its dialect's engine gives
    /// posts (CNC-Calc's drilling data, Fusion's `getParameter`), by name:
    /// the runtime asks the run's host, which the edge picks by the
    /// post's dialect.
    Host {
        name: String,
        args: Vec<Expr>,
    },
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum UnaryOp {
    Neg,
    Not,
    /// To a number (JavaScript unary `+`).
    Plus,
    /// Bitwise not on the value as a 32-bit integer (JavaScript `~`).
    BitNot,
    /// The JavaScript type name: "number", "string", "boolean", "undefined".
    Typeof,
}

/// Binary operators. `Add` adds numbers and joins text; `Concat` always
/// joins as text (BASIC `&`).
///
/// Number conversions: the arithmetic and comparison operators read text
/// that is not a number as 0, and null as 0 (BASIC's `Val`, which VcPost
/// needs). JavaScript reads such text as NaN: a dialect with JavaScript's
/// meaning (CIMCO) converts operands explicitly with [`UnaryOp::Plus`]
/// (JavaScript `Number()`: NaN for text that is not a number and for
/// null) before `Sub`, `Mul`, `Div`, `Rem` and [`UnaryOp::Neg`], and
/// compares with the `Js*` operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Rem,
    Pow,
    IntDiv,
    Concat,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
    /// Equal in value and type (JavaScript `===`).
    StrictEq,
    /// JavaScript `!==`.
    StrictNe,
    /// Bitwise operators on the values as 32-bit integers (JavaScript).
    BitAnd,
    BitOr,
    BitXor,
    Shl,
    /// Arithmetic (`>>`) and logical (`>>>`) right shift.
    Shr,
    UShr,
    /// JavaScript's loose `==` and `!=`: text with text compares as text;
    /// null equals only null; otherwise both sides are read as JavaScript
    /// numbers (so `"abc" == 0` is false, NaN equals nothing).
    JsEq,
    JsNe,
    /// JavaScript's `<`, `<=`, `>`, `>=`: text with text compares as text,
    /// otherwise as JavaScript numbers (false when either is NaN).
    JsLt,
    JsLe,
    JsGt,
    JsGe,
}

/// Built-in functions, shared by the dialects that lower to native code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Builtin {
    Abs,
    Sqrt,
    Sin,
    Cos,
    Tan,
    Atan,
    Atan2,
    Floor,
    Ceil,
    /// Round half away from zero to an integer (or to `n` decimals).
    Round,
    /// Truncate toward zero.
    Trunc,
    Min,
    Max,
    /// Length of a text.
    Len,
    /// `Left(s, n)`.
    Left,
    /// `Right(s, n)`.
    Right,
    /// `Mid(s, start1, [len])`, 1-based.
    Mid,
    Upper,
    Lower,
    /// Number to text (shortest form); other values as text, `null` as
    /// nothing (VcPost's empty value) or, in a post whose text is
    /// JavaScript's (`OutputOptions::js_text`), as `null`, as `+` reads it.
    Str,
    /// JavaScript's ToString (`String(v)`, a template literal's
    /// substitution): `null` is `"null"`, `undefined` `"undefined"`, an
    /// object's `toString` (its own or its prototype chain's) is asked
    /// first, then its `valueOf`.
    JsString,
    /// Text to number (0 when it is not a number).
    Val,
    /// `Format(value, "0.000")`: a VB-style picture format.
    FormatPicture,
    /// Text of a character code.
    Chr,
    Asin,
    Acos,
    Exp,
    /// Natural logarithm.
    Log,
    /// JavaScript `Math.round`: half up, toward positive infinity.
    JsRound,
    /// JavaScript `parseInt(text, [radix])`: NaN when no digits lead.
    ParseInt,
    /// JavaScript `parseFloat(text)`: NaN when no number leads.
    ParseFloat,
    /// JavaScript `isNaN(value)`.
    IsNaN,
    /// JavaScript `Number(value)`: NaN for text that is not a number.
    ToNumber,
    /// JavaScript `value.toFixed(digits)`.
    ToFixed,
    /// JavaScript `text.substring(start, [end])`: the indices read as
    /// integers (NaN as 0), clamped to the text, swapped when start is past
    /// end; a missing or null end is the end of the text. Indices count
    /// characters.
    Substring,
    /// The names `for (k in value)` walks: an object's properties in
    /// their order, an array's or a text's indices, as texts; then the
    /// properties of its prototype chain it does not have, each
    /// prototype's in their order (those the post set: a function's first
    /// `prototype.constructor` and the built-in methods are not listed).
    Keys,
    /// JavaScript `Object.keys(value)`: the names of [`Builtin::Keys`]
    /// that are the value's own.
    OwnKeys,
    /// JavaScript `key in value`: whether the object, array or function
    /// has the property, its own or its prototype chain's (`"length" in
    /// [1]`, `"toString" in {}`, a method the post put on `F.prototype`);
    /// a TypeError for any other value.
    HasProperty,
    /// JavaScript `new F(args)`: the first operand is `F`, the rest its
    /// arguments. `F` runs with a new empty object as `this`, whose
    /// prototype is `F.prototype` (when that is an object; else
    /// `Object.prototype`); the value is what `F` returns when that is an
    /// object, an array or a function, else the new object. A TypeError
    /// when `F` is not a function of the post.
    Construct,
    /// The prototype object of one of JavaScript's built-in constructors,
    /// named by the operand as text: `"Object"`, `"Array"`, `"String"`,
    /// `"Number"`, `"Boolean"`, `"Function"`, `"RegExp"`
    /// (`String.prototype`). One object per run. Its built-in methods are
    /// those of values of that kind (`Array.prototype.slice`, as a function
    /// value run on the `this` it is called with); a method the post adds
    /// to it is found by every value of that kind that has no built-in
    /// method of that name (`String.prototype.f = ...`, then `"a".f()`).
    Prototype,
    /// JavaScript `Object.create(proto)`: a new empty object whose
    /// prototype is the operand, an object, or none for `null`; a
    /// TypeError for any other value.
    CreateObject,
    /// JavaScript `value instanceof F`, the second operand `F.prototype`:
    /// whether that object is on the prototype chain of the first (never
    /// for a text, a number or a boolean); a TypeError when the second is
    /// not an object.
    InstanceOf,
    /// JavaScript `Array.isArray(value)`.
    IsArray,
    /// JavaScript `new RegExp(pattern, flags)` of a pattern made when the
    /// post runs (a literal pattern is an [`Expr::Regex`], compiled once):
    /// compiled at each evaluation; a pattern postc does not read stops
    /// the post there (JS108). Operands: the pattern (a text, or a regular
    /// expression whose source is taken) and the flags (`undefined` for
    /// none, or the regular expression's own).
    NewRegExp,
    /// A number format of a host written in JavaScript (Fusion's
    /// `createFormat`), as its `__postc_formatNumber(spec, value)`: the
    /// text of the value under the specifiers of the `spec` object
    /// (`scale`, `offset`, `cyclicLimit`, `cyclicSign`, `decimals`,
    /// `trim`, `trimLeadZero`, `forceDecimal`, `zeropad`, `width`,
    /// `forceSign`, `decimalSymbol`, `prefix`, `suffix`), with
    /// JavaScript's arithmetic and number text; `undefined` when the
    /// scaled value is not a finite number (the host then raises its
    /// error at the post's call).
    FormatNumber,
    /// The words of a block of a host written in JavaScript (Fusion's
    /// `formatWords`), as its `__postc_words(list, separator, start)`:
    /// the items of the list from `start` (0 when absent), arrays and
    /// objects with a `length` walked into, `undefined`, `null` and empty
    /// texts left out, the rest as JavaScript's `String` writes them,
    /// joined by the separator.
    Words,
    /// What the `format(value)` method of an output variable or modal of
    /// a host written in JavaScript (Fusion's `createVariable`,
    /// `createModal`) prints, as its `__postc_formatOutput(output, value,
    /// hostFormat, modal)`: the value through the output's format when
    /// that is one of the host's (its `format` is the function
    /// `hostFormat` is), compared with the last text; `undefined`, having
    /// changed nothing, where the host's JavaScript does more (another
    /// format, an `onchange` to call, ...), which then runs.
    FormatOutput,
    /// A post property's value, of a host written in JavaScript (Fusion's
    /// `getProperty(name, otherwise)` of a name), as its
    /// `__postc_property(properties, name, otherwise)`: `properties[name]`,
    /// `otherwise` when that is `undefined`, its `value` when it is an
    /// object whose `value` is not `undefined`.
    Property,
    /// A setting the user gave that the post cannot take, of a host written
    /// in JavaScript (Fusion's post property that the post does not have,
    /// or a value its type does not take), as its
    /// `__postc_settingError(message)`: the run stops with the message as
    /// an error of the command line (IO007), which names no place in the
    /// post or the toolpath.
    SettingError,
}
