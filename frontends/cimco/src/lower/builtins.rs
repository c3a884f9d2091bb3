//! What the lowering knows of the names postc's CNC-Calc host gives every
//! post: constants, global functions, `Math`, and the methods of texts,
//! arrays and output variables. `docs/cimco.md` lists them with their
//! meaning; the names the host registers are [`crate::host_names`].

use super::consts::Const;
use crate::host_names as names;

/// Movement types passed as the last argument of `onLinear` and
/// `onCircular`, and to `getFeedrate`.
pub const MOVEMENT_RAPID: f64 = 0.0;
pub const MOVEMENT_CUTTING: f64 = 1.0;
pub const MOVEMENT_PLUNGE: f64 = 2.0;

/// The value of a constant the host defines.
pub fn constant(name: &str) -> Option<Const> {
    let n = match name {
        "MOVEMENT_RAPID" => MOVEMENT_RAPID,
        "MOVEMENT_CUTTING" | "MOVEMENT_FEED" => MOVEMENT_CUTTING,
        "MOVEMENT_PLUNGE" => MOVEMENT_PLUNGE,
        "MOVEMENT_RETRACT" => 3.0,
        "COMPENSATION_OFF" => 0.0,
        "COMPENSATION_LEFT" => 1.0,
        "COMPENSATION_RIGHT" => 2.0,
        "POST_TYPE_MILL" => 0.0,
        "POST_TYPE_TURN" => 1.0,
        "DEGRESSION_NONE" => 0.0,
        "DEGRESSION_VALUE" => 1.0,
        "DEGRESSION_FACTOR" => 2.0,
        "NaN" => f64::NAN,
        "Infinity" => f64::INFINITY,
        "undefined" => return Some(Const::Undefined),
        _ => return None,
    };
    Some(Const::Num(n))
}

/// `Math.NAME` constants (one table for the lowering and the script host).
pub use crate::host_names::math_constant;

/// `Math` functions the host provides.
pub const MATH_FUNCTIONS: &[&str] = &[
    "abs", "acos", "asin", "atan", "atan2", "ceil", "cos", "exp", "floor", "log", "max", "min", "pow", "random",
    "round", "sin", "sqrt", "tan",
];

/// Global functions the host provides.
pub use crate::host_names::FUNCTIONS;

/// Whether a name is something the host provides as an object (`Math`).
pub fn is_object(name: &str) -> bool {
    matches!(
        name,
        "Math" | names::CREATE_FORMAT | names::CREATE_VARIABLE | names::ARRAY_FN | names::OBJECT_FN | names::ERROR_FN
    )
}

/// Whether the host knows the name at all.
pub fn knows(name: &str) -> bool {
    constant(name).is_some() || FUNCTIONS.contains(&name) || name == "Math" || name == "arguments"
}

/// Whether a host function returns a number, text or boolean.
pub fn plain_function(name: &str) -> bool {
    matches!(
        name,
        names::GET_FEEDRATE
            | names::GET_COMPENSATION
            | names::PARSE_INT
            | names::PARSE_FLOAT
            | names::IS_NAN
            | names::IS_FINITE
            | names::STRING
            | names::NUMBER
            | names::BOOLEAN
    )
}

/// Whether a method of that name returns a number, text or boolean.
pub fn plain_method(name: &str) -> bool {
    matches!(
        name,
        "format"
            | "getLast"
            | "reset"
            | "toUpperCase"
            | "toLowerCase"
            | "substr"
            | "substring"
            | "charAt"
            | "charCodeAt"
            | "indexOf"
            | "lastIndexOf"
            | "toFixed"
            | "replace"
            | "join"
            | "trim"
            | "trimStart"
            | "trimEnd"
            | "startsWith"
            | "endsWith"
            | "includes"
            | "repeat"
            | "padStart"
            | "padEnd"
            | "toString"
            | "push"
            | "search"
            | "test"
    )
}

/// The entry points postc calls with an object (the drill header).
pub fn entry_takes_object(name: &str) -> bool {
    matches!(name, "onDrillingHeader" | "onDrilling")
}

/// The built-in a `Math.name(...)` call is, with the number of arguments
/// it reads (`min` and `max` read all they are given: `None`); `pow`,
/// `min()` and `max()` with no argument are the lowerings' own.
pub fn math(name: &str) -> Option<(postc_ir::Builtin, Option<usize>)> {
    use postc_ir::Builtin;
    let b = match name {
        "abs" => Builtin::Abs,
        "sqrt" => Builtin::Sqrt,
        "sin" => Builtin::Sin,
        "cos" => Builtin::Cos,
        "tan" => Builtin::Tan,
        "atan" => Builtin::Atan,
        "atan2" => Builtin::Atan2,
        "asin" => Builtin::Asin,
        "acos" => Builtin::Acos,
        "exp" => Builtin::Exp,
        "log" => Builtin::Log,
        "floor" => Builtin::Floor,
        "ceil" => Builtin::Ceil,
        "round" => Builtin::JsRound,
        "min" => Builtin::Min,
        "max" => Builtin::Max,
        _ => return None,
    };
    let arity = match b {
        Builtin::Atan2 => Some(2),
        Builtin::Min | Builtin::Max => None,
        _ => Some(1),
    };
    Some((b, arity))
}
