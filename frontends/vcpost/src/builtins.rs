//! The built-in functions of VcPost: their BASIC names, how many arguments
//! each takes, and what each lowers to in the IR. Also the BASIC functions
//! postc knows of but does not provide, so that using one gives a clear
//! "not supported" instead of "unknown function".

use postc_ir::Builtin;

/// What a built-in lowers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lowering {
    /// One IR built-in, arguments passed as they are.
    Ir(Builtin),
    /// `Format(x)` with one argument is `Str(x)`; with two, a picture format.
    Format,
    /// `IIf(c, a, b)`: the IR's `Choose`.
    IIf,
    /// `Sgn(x)`: -1, 0 or 1, built from comparisons.
    Sgn,
}

/// One built-in function.
#[derive(Clone, Copy, Debug)]
pub struct BuiltinFn {
    /// The name as documented.
    pub name: &'static str,
    pub min_args: usize,
    pub max_args: usize,
    pub lowering: Lowering,
    /// What it does, for help texts.
    pub summary: &'static str,
}

const fn f(
    name: &'static str,
    min_args: usize,
    max_args: usize,
    lowering: Lowering,
    summary: &'static str,
) -> BuiltinFn {
    BuiltinFn { name, min_args, max_args, lowering, summary }
}

/// Every built-in function.
pub const BUILTINS: &[BuiltinFn] = &[
    f("Abs", 1, 1, Lowering::Ir(Builtin::Abs), "Abs(x): absolute value"),
    f("Sqr", 1, 1, Lowering::Ir(Builtin::Sqrt), "Sqr(x): square root"),
    f("Sin", 1, 1, Lowering::Ir(Builtin::Sin), "Sin(angle): sine of an angle in radians"),
    f("Cos", 1, 1, Lowering::Ir(Builtin::Cos), "Cos(angle): cosine of an angle in radians"),
    f("Tan", 1, 1, Lowering::Ir(Builtin::Tan), "Tan(angle): tangent of an angle in radians"),
    f("Atn", 1, 1, Lowering::Ir(Builtin::Atan), "Atn(x): arc tangent, in radians"),
    f("Int", 1, 1, Lowering::Ir(Builtin::Floor), "Int(x): largest whole number not above x"),
    f("Fix", 1, 1, Lowering::Ir(Builtin::Trunc), "Fix(x): x without its fraction"),
    f("Round", 1, 2, Lowering::Ir(Builtin::Round), "Round(x[, decimals]): rounds half away from zero"),
    f("Len", 1, 1, Lowering::Ir(Builtin::Len), "Len(text): number of characters"),
    f("Left", 2, 2, Lowering::Ir(Builtin::Left), "Left(text, n): first n characters"),
    f("Right", 2, 2, Lowering::Ir(Builtin::Right), "Right(text, n): last n characters"),
    f("Mid", 2, 3, Lowering::Ir(Builtin::Mid), "Mid(text, start[, length]): characters from start (1 is the first)"),
    f("UCase", 1, 1, Lowering::Ir(Builtin::Upper), "UCase(text): upper case"),
    f("LCase", 1, 1, Lowering::Ir(Builtin::Lower), "LCase(text): lower case"),
    f("Str", 1, 1, Lowering::Ir(Builtin::Str), "Str(x): number as text"),
    f("CStr", 1, 1, Lowering::Ir(Builtin::Str), "CStr(x): number as text"),
    f("Val", 1, 1, Lowering::Ir(Builtin::Val), "Val(text): text as a number (0 if it is not one)"),
    f("Format", 1, 2, Lowering::Format, "Format(x, \"0.000\"): number as text through a picture"),
    f("Chr", 1, 1, Lowering::Ir(Builtin::Chr), "Chr(code): the character with that code"),
    f("IIf", 3, 3, Lowering::IIf, "IIf(condition, a, b): a when the condition holds, else b"),
    f("Sgn", 1, 1, Lowering::Sgn, "Sgn(x): -1, 0 or 1"),
];

/// BASIC functions postc does not provide.
pub const UNSUPPORTED: &[&str] = &[
    "Asc", "CBool", "CDbl", "CInt", "CLng", "CSng", "Date", "Exp", "Hex", "InStr", "InputBox", "LTrim", "Log",
    "MsgBox", "Now", "Oct", "RTrim", "Replace", "Rnd", "Shell", "Space", "Split", "StrComp", "String", "Time", "Timer",
    "Trim",
];

/// The built-in a name stands for, ignoring case.
pub fn lookup(name: &str) -> Option<&'static BuiltinFn> {
    BUILTINS.iter().find(|b| b.name.eq_ignore_ascii_case(name))
}

/// Whether a name is a BASIC function postc does not provide.
pub fn is_unsupported(name: &str) -> bool {
    UNSUPPORTED.iter().any(|u| u.eq_ignore_ascii_case(name))
}
