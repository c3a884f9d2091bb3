//! The names the Rhai script of a CIMCO post calls and the CNC-Calc
//! script host (`postc-cimco-host`) registers: one table both sides
//! import, so that a name is spelled once.
//!
//! The lowering (`lower::rhai`) writes calls of these functions into the
//! script it generates; the host registers a Rhai function under each.
//! The global functions of CNC-Calc ([`FUNCTIONS`]) are called through
//! [`HOST`] by their JavaScript names; the hidden variables and globals
//! are names in the post's IR that the host looks up.

// Literals Rhai has no syntax for.
/// `null`.
pub const NULL: &str = "__null";
/// `NaN`.
pub const NAN: &str = "__nan";
/// `Infinity`.
pub const INF: &str = "__inf";
/// `undefined` read through a name the post never defined (throws).
pub const UNDEF: &str = "__undef";

// Operators with JavaScript's meaning.
/// `a + b`.
pub const ADD: &str = "__add";
/// `a + b + c ...` folded left.
pub const ADDS: &str = "__adds";
pub const SUB: &str = "__sub";
pub const MUL: &str = "__mul";
pub const DIV: &str = "__div";
pub const REM: &str = "__rem";
/// Unary `-`.
pub const NEG: &str = "__neg";
/// Unary `+`.
pub const POS: &str = "__pos";
pub const BNOT: &str = "__bnot";
pub const BAND: &str = "__band";
pub const BOR: &str = "__bor";
pub const BXOR: &str = "__bxor";
pub const SHL: &str = "__shl";
pub const SHR: &str = "__shr";
pub const USHR: &str = "__ushr";
pub const EQ: &str = "__eq";
pub const NE: &str = "__ne";
/// `===`.
pub const SEQ: &str = "__seq";
/// `!==`.
pub const SNE: &str = "__sne";
pub const LT: &str = "__lt";
pub const LE: &str = "__le";
pub const GT: &str = "__gt";
pub const GE: &str = "__ge";
pub const IN: &str = "__in";
/// Truthiness.
pub const TRUTHY: &str = "__t";
pub const TYPEOF: &str = "__typeof";
/// The `i`-th argument of a call, `undefined` past the end.
pub const ARG: &str = "__arg";
/// Assigning to something that cannot be assigned (throws).
pub const ASSIGN_ERROR: &str = "__assign_error";
/// One iteration of the loop at a post offset (the step budget).
pub const TICK: &str = "__tick";
/// Reads a global by index.
pub const GLOBAL_GET: &str = "__gg";
/// Writes a global by index.
pub const GLOBAL_SET: &str = "__gs";

// Objects, arrays, functions, properties and calls.
/// An object literal from key, value pairs.
pub const OBJECT: &str = "__obj";
/// An array literal.
pub const ARRAY: &str = "__arr";
/// A function expression.
pub const FUNCTION: &str = "__fn";
/// The function object of a top-level function, by its Rhai name.
pub const FUNCTION_OBJECT: &str = "__fnobj";
/// A regular expression literal.
pub const REGEX: &str = "__regex";
/// The `Math` object.
pub const MATH_OBJECT: &str = "__math_obj";
/// A CNC-Calc global function used as a value.
pub const HOST_FUNCTION: &str = "__hostfn";
/// `Math.name(args)`.
pub const MATH: &str = "__math";
/// `o[k]`.
pub const GET: &str = "__get";
/// `o[k] = v`.
pub const SET: &str = "__set";
/// The keys of `for (k in o)`.
pub const KEYS: &str = "__keys";
/// A `return`, `break` or `continue` leaving a `try`, thrown.
pub const JUMP: &str = "__jump";
pub const JUMP_KIND: &str = "__jump_kind";
pub const JUMP_VALUE: &str = "__jump_value";
/// The value a `catch` sees.
pub const CAUGHT: &str = "__caught";
/// `o.name(args)`.
pub const CALL_METHOD: &str = "__callm";
/// `f(args)`.
pub const CALL: &str = "__call";
/// `new F(args)`.
pub const NEW: &str = "__new";
/// The output primitive of a host written in JavaScript (Fusion's):
/// `__postc_writeln(text, eol)` writes the text as it is, then the line
/// ending `eol` (the host's `EOL`, which `setEOL` changes), as one block.
pub const WRITE_LINE: &str = "__postc_writeln";
/// The number format of a host written in JavaScript:
/// `__postc_formatNumber(spec, value)` (`Builtin::FormatNumber`).
pub const FORMAT_NUMBER: &str = "__postc_formatNumber";
/// The words of a block of a host written in JavaScript:
/// `__postc_words(list, separator, start)` (`Builtin::Words`).
pub const WORDS: &str = "__postc_words";
/// An output variable's or modal's `format` of a host written in
/// JavaScript: `__postc_formatOutput(output, value, hostFormat, modal)`
/// (`Builtin::FormatOutput`).
pub const FORMAT_OUTPUT: &str = "__postc_formatOutput";
/// A post property's value of a host written in JavaScript:
/// `__postc_property(properties, name, otherwise)` (`Builtin::Property`).
pub const PROPERTY: &str = "__postc_property";
/// A setting the post cannot take, of a host written in JavaScript:
/// `__postc_settingError(message)` (`Builtin::SettingError`).
pub const SETTING_ERROR: &str = "__postc_settingError";
/// Whether the job is in millimetres, for a host written in JavaScript:
/// `__postc_jobUnitIsMm()`, which the host's top level reads before the
/// post's own runs (the `UNITS` quantity is `"Mm"`).
pub const JOB_UNIT_IS_MM: &str = "__postc_jobUnitIsMm";
/// A CNC-Calc global function by name ([`FUNCTIONS`]).
pub const HOST: &str = "__host";

// Output variables and formats bound at compile time, and CNC-Calc's state.
/// The output variable with an IR variable id.
pub const VAR_REF: &str = "__vref";
/// The format with an IR format id.
pub const FORMAT_REF: &str = "__fref";
/// `xOutput.format(v)` of a compile-time variable.
pub const VAR_FORMAT: &str = "__vfmt";
/// `xOutput.getLast()` of a compile-time variable.
pub const VAR_LAST: &str = "__vlast";
/// `xFormat.format(v)` of a compile-time format.
pub const FORMAT_FORMAT: &str = "__ffmt";
/// `getFeedrate(movement)`.
pub const FEEDRATE: &str = "__feedrate";
/// The compensation side passed to `onCompensation`.
pub const COMPENSATION: &str = "__comp";
/// The `drillHeader` of `onDrillingHeader`.
pub const DRILL_HEADER: &str = "__drill_header";
/// The `drillHeader` of `onDrilling` (turning).
pub const TURN_DRILL: &str = "__turn_drill";

/// The CNC-Calc global functions (called through [`HOST`]).
pub const CREATE_FORMAT: &str = "createFormat";
pub const CREATE_VARIABLE: &str = "createVariable";
pub const GET_FEEDRATE: &str = "getFeedrate";
pub const GET_COMPENSATION: &str = "getCompensation";
pub const PARSE_INT: &str = "parseInt";
pub const PARSE_FLOAT: &str = "parseFloat";
pub const IS_NAN: &str = "isNaN";
pub const IS_FINITE: &str = "isFinite";
pub const STRING: &str = "String";
pub const NUMBER: &str = "Number";
pub const BOOLEAN: &str = "Boolean";
pub const ARRAY_FN: &str = "Array";
pub const OBJECT_FN: &str = "Object";
pub const ERROR_FN: &str = "Error";

/// Global functions the host provides.
pub const FUNCTIONS: &[&str] = &[
    CREATE_FORMAT,
    CREATE_VARIABLE,
    GET_FEEDRATE,
    GET_COMPENSATION,
    PARSE_INT,
    PARSE_FLOAT,
    IS_NAN,
    IS_FINITE,
    STRING,
    NUMBER,
    BOOLEAN,
    ARRAY_FN,
    OBJECT_FN,
    ERROR_FN,
];

/// The hidden output variable `getFeedrate` formats a feed through.
pub const FEED_VAR: &str = "__postc_feed";
/// The same, for feeds per revolution (more decimals).
pub const FEED_REV_VAR: &str = "__postc_feed_rev";

/// Globals of the post the host reads by name: the decimal mark of
/// `createFormat`, and the field lists that mark a drill cycle longhand.
pub const DECIMAL_MARK: &str = "decimalMark";
pub const GLOBALS_DECIMAL_MARK: &str = "globals.decimalMark";
pub const MILL_DRILLING_FIELDS: &str = "MillDrillingFields";
pub const TURN_DRILLING_FIELDS: &str = "TurnDrillingFields";

/// Every Rhai function the script may call and the host registers.
pub const SCRIPT_FUNCTIONS: &[&str] = &[
    NULL,
    NAN,
    INF,
    UNDEF,
    ADD,
    ADDS,
    SUB,
    MUL,
    DIV,
    REM,
    NEG,
    POS,
    BNOT,
    BAND,
    BOR,
    BXOR,
    SHL,
    SHR,
    USHR,
    EQ,
    NE,
    SEQ,
    SNE,
    LT,
    LE,
    GT,
    GE,
    TRUTHY,
    TYPEOF,
    ARG,
    ASSIGN_ERROR,
    TICK,
    GLOBAL_GET,
    GLOBAL_SET,
    OBJECT,
    ARRAY,
    FUNCTION,
    FUNCTION_OBJECT,
    REGEX,
    MATH_OBJECT,
    HOST_FUNCTION,
    MATH,
    GET,
    SET,
    KEYS,
    JUMP,
    JUMP_KIND,
    JUMP_VALUE,
    CAUGHT,
    CALL_METHOD,
    CALL,
    NEW,
    HOST,
    VAR_REF,
    FORMAT_REF,
    VAR_FORMAT,
    VAR_LAST,
    FORMAT_FORMAT,
    FEEDRATE,
    COMPENSATION,
    DRILL_HEADER,
    TURN_DRILL,
];

/// `Math.NAME` constants.
pub fn math_constant(name: &str) -> Option<f64> {
    use std::f64::consts as c;
    Some(match name {
        "PI" => c::PI,
        "E" => c::E,
        "LN2" => c::LN_2,
        "LN10" => c::LN_10,
        "LOG2E" => c::LOG2_E,
        "LOG10E" => c::LOG10_E,
        "SQRT2" => c::SQRT_2,
        "SQRT1_2" => c::FRAC_1_SQRT_2,
        _ => return None,
    })
}
