//! The diagnostics of the CIMCO JavaScript frontend: their codes, their
//! wording, and the JavaScript constructs postc does not accept.
//!
//! Its diagnostic codes are declared in the registry `postc_ir::codes`
//! (rendered as docs/diagnostics.md; `postc explain CODE`).

use crate::Syntax;
use postc_ir::codes;
use postc_ir::{Diagnostic, FileId, Span};

pub const UNEXPECTED_CHARACTER: &str = codes::JS001.code;
/// E4X (ECMAScript for XML), which the lexer meets as `.@`.
pub const E4X: &str = codes::JS044.code;
pub const UNTERMINATED_TEXT: &str = codes::JS002.code;
pub const BAD_ESCAPE: &str = codes::JS003.code;
pub const UNTERMINATED_COMMENT: &str = codes::JS004.code;
pub const MALFORMED_NUMBER: &str = codes::JS005.code;
pub const UNTERMINATED_REGEX: &str = codes::JS006.code;
pub const SYNTAX_ERROR: &str = codes::JS007.code;
pub const MISSING_SEMICOLON: &str = codes::JS008.code;
pub const UNEXPECTED_END: &str = codes::JS009.code;
pub const UNCLOSED: &str = codes::JS010.code;
pub const UNMATCHED_CLOSER: &str = codes::JS011.code;
pub const INVALID_ASSIGNMENT: &str = codes::JS012.code;
pub const TOO_DEEP: &str = codes::JS013.code;
pub const RETURN_OUTSIDE_FUNCTION: &str = codes::JS014.code;
pub const JUMP_OUTSIDE_LOOP: &str = codes::JS015.code;
pub const DUPLICATE_DEFAULT: &str = codes::JS016.code;
pub const TRY_WITHOUT_HANDLER: &str = codes::JS017.code;

/// The JavaScript that is not part of the subset CNC-Calc posts use. Each
/// has its own code, names itself, and says what to write instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Construct {
    Let,
    Const,
    Arrow,
    Class,
    Template,
    TaggedTemplate,
    GetterSetter,
    With,
    Label,
    Delete,
    Instanceof,
    Generator,
    Async,
    Spread,
    Destructuring,
    DefaultParam,
    Shorthand,
    Method,
    ComputedKey,
    ForOf,
    Exponent,
    OptionalChaining,
    Nullish,
    LogicalAssign,
    Module,
    Void,
    Debugger,
    RegexFlag,
    BinaryOctal,
    BigInt,
    LegacyOctal,
    TrailingComma,
    ArrayHole,
    E4x,
}

impl Construct {
    /// The diagnostic code.
    pub fn code(self) -> &'static str {
        use Construct::*;
        match self {
            Let | Const => codes::JS018.code,
            Arrow => codes::JS019.code,
            Class => codes::JS020.code,
            Template | TaggedTemplate => codes::JS021.code,
            GetterSetter => codes::JS022.code,
            With => codes::JS023.code,
            Label => codes::JS024.code,
            Delete => codes::JS025.code,
            Instanceof => codes::JS027.code,
            Generator => codes::JS028.code,
            Async => codes::JS029.code,
            Spread => codes::JS030.code,
            Destructuring => codes::JS031.code,
            DefaultParam => codes::JS032.code,
            Shorthand | Method | ComputedKey => codes::JS033.code,
            ForOf => codes::JS034.code,
            Exponent => codes::JS035.code,
            OptionalChaining | Nullish | LogicalAssign => codes::JS036.code,
            Module => codes::JS037.code,
            Void => codes::JS038.code,
            Debugger => codes::JS039.code,
            RegexFlag => codes::JS040.code,
            BinaryOctal | BigInt | LegacyOctal => codes::JS041.code,
            TrailingComma => codes::JS042.code,
            ArrayHole => codes::JS043.code,
            E4x => codes::JS044.code,
        }
    }

    /// The construct's name, as the message and label show it.
    pub fn name(self) -> &'static str {
        use Construct::*;
        match self {
            Let => "`let` declarations",
            Const => "`const` declarations",
            Arrow => "arrow functions (`=>`)",
            Class => "classes (`class`)",
            Template => "template literals (`` `...` ``)",
            TaggedTemplate => "tagged templates (`` tag`...` ``)",
            GetterSetter => "getters and setters (`get x() {}`)",
            With => "the `with` statement",
            Label => "labels (`outer:`, `break outer`)",
            Delete => "the `delete` operator",
            Instanceof => "the `instanceof` operator",
            Generator => "generator functions (`function*`) and `yield`",
            Async => "`async` functions and `await`",
            Spread => "spread and rest syntax (`...`)",
            Destructuring => "destructuring (`var {a, b} = obj`)",
            DefaultParam => "default parameter values (`function f(a = 1)`)",
            Shorthand => "shorthand properties (`{ x }`)",
            Method => "methods in object literals (`{ f() {} }`)",
            ComputedKey => "computed property names (`{ [key]: value }`)",
            ForOf => "`for ... of` loops",
            Exponent => "the exponent operator (`**`)",
            OptionalChaining => "optional chaining (`?.`)",
            Nullish => "the `??` operator",
            LogicalAssign => "logical assignment (`&&=`, `||=`, `??=`)",
            Module => "modules (`import` and `export`)",
            Void => "the `void` operator",
            Debugger => "the `debugger` statement",
            RegexFlag => "regular expression flags other than `g`, `i` and `m`",
            BinaryOctal => "binary and octal numbers (`0b101`, `0o17`)",
            BigInt => "BigInt numbers (`10n`)",
            LegacyOctal => "numbers with a leading zero (`010`, an octal number in old JavaScript)",
            TrailingComma => "a comma after the last argument or parameter",
            ArrayHole => "empty slots in an array (`[1, , 2]`)",
            E4x => "E4X, ECMAScript for XML (`xml..name`, `node.@attribute`, `default xml namespace`)",
        }
    }

    /// What to write instead.
    pub fn help(self) -> &'static str {
        use Construct::*;
        match self {
            Let | Const => "declare the variable with `var`",
            Arrow => "write `function (x) { ... }`",
            Class => "write a constructor function and add methods to its `prototype`",
            Template => "join the text with `+`: \"X\" + x",
            TaggedTemplate => "call the function with the text and the values: `tag([\"a\", \"b\"], x)`",
            GetterSetter => "use an ordinary property, or a function that returns the value",
            With => "write the object name in front of each property",
            Label => "leave the outer loop with a flag variable instead",
            Delete => "set the property to `undefined` instead",
            Instanceof => "test a property of the object, or use `typeof`",
            Generator => "return an array of the values instead",
            Async => "call the function directly; posts run synchronously",
            Spread => "pass the values one by one, or read them from `arguments`",
            Destructuring => "read each property on its own: `var a = obj.a;`",
            DefaultParam => "set the default in the body: `if (a === undefined) { a = 1; }`",
            Shorthand => "write the property as `x: x`",
            Method => "write the method as `f: function () { ... }`",
            ComputedKey => "create the object first, then set `obj[key] = value;`",
            ForOf => "loop over the indices: `for (var i = 0; i < list.length; i++)`",
            Exponent => "use `Math.pow(a, b)`",
            OptionalChaining => "test the object first: `a && a.b`",
            Nullish => "write `(a !== undefined && a !== null) ? a : b`",
            LogicalAssign => "write the assignment out: `a = a || b;`",
            Module => "a post is a single file; remove the line",
            Void => "use `undefined`",
            Debugger => "remove the statement",
            RegexFlag => "use only the flags `g`, `i` and `m`",
            BinaryOctal | BigInt => "write the number in decimal or hexadecimal (`0x1F`)",
            LegacyOctal => "remove the leading zero, or write the number in hexadecimal",
            TrailingComma => "remove the comma",
            ArrayHole => "write `undefined` in the empty slot",
            E4x => {
                "build the XML as text with `+`; E4X was an extension of old JavaScript engines, removed from them and never part of ES5"
            }
        }
    }

    /// The diagnostic at the construct, in a CNC-Calc post.
    pub fn diagnostic(self, span: Span) -> Diagnostic {
        self.diagnostic_as(span, Syntax::Cimco)
    }

    /// The diagnostic at the construct, in a post read as `syntax`.
    pub fn diagnostic_as(self, span: Span, syntax: Syntax) -> Diagnostic {
        let verb = if self.is_plural() { "are" } else { "is" };
        let message = match (syntax, self) {
            (Syntax::Cimco, _) => format!("{} {verb} not part of the JavaScript that CNC-Calc posts use", self.name()),
            (Syntax::Fusion, Construct::E4x) => {
                format!("postc does not read {}: no engine of today runs it", self.name())
            }
            (Syntax::Fusion, _) => format!("postc does not read {} in Fusion posts yet", self.name()),
        };
        Diagnostic::error(self.code(), message).at(span, "not supported by postc").help(self.help())
    }

    fn is_plural(self) -> bool {
        use Construct::*;
        !matches!(
            self,
            With | Delete
                | Spread
                | Destructuring
                | Instanceof
                | Exponent
                | OptionalChaining
                | Nullish
                | LogicalAssign
                | Void
                | Debugger
                | TrailingComma
        )
    }
}

/// A diagnostic from the lexer.
pub(crate) fn lexical(
    code: &'static str,
    file: FileId,
    start: usize,
    end: usize,
    message: impl Into<String>,
    label: &'static str,
) -> Diagnostic {
    Diagnostic::error(code, message).at(Span::new(file, start, end), label)
}
