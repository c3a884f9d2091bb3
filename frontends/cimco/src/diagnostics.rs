//! The diagnostics of the CIMCO JavaScript frontend: their codes, their
//! wording, and the JavaScript constructs postc does not accept.
//!
//! | code  | meaning |
//! |-------|---------|
//! | JS001 | a character that JavaScript does not allow here (`#`, `@`, a stray `\`) |
//! | JS002 | text in quotes (or a template literal) is not closed before the end of the line |
//! | JS003 | a bad escape sequence in text (`\x4`, `\u12`, octal `\12`) |
//! | JS004 | a `/* ... */` comment is not closed |
//! | JS005 | a malformed number (`0x`, `1e`, `3mm`) |
//! | JS006 | a regular expression is not closed before the end of the line |
//! | JS007 | syntax error: a token where it cannot be |
//! | JS008 | two statements on one line without `;` between them |
//! | JS009 | the file ends in the middle of a statement or expression |
//! | JS010 | a `{`, `(` or `[` that is never closed |
//! | JS011 | a `}`, `)` or `]` with nothing to close |
//! | JS012 | an assignment or `++`/`--` to something that is not a variable or property |
//! | JS013 | code nested too deeply to process |
//! | JS014 | `return` outside a function |
//! | JS015 | `break` or `continue` outside a loop (or `continue` in a `switch` only) |
//! | JS016 | more than one `default` in a `switch` |
//! | JS017 | `try` without `catch` or `finally` |
//! | JS018 | `let` / `const` declarations |
//! | JS019 | arrow functions (`=>`) |
//! | JS020 | classes (`class`) |
//! | JS021 | template literals (`` `...` ``) |
//! | JS022 | getters and setters (`get x() {}`) |
//! | JS023 | the `with` statement |
//! | JS024 | labels (`outer:`, `break outer`) |
//! | JS025 | the `delete` operator |
//! | JS026 | the `in` operator (outside `for (var k in obj)`) |
//! | JS027 | the `instanceof` operator |
//! | JS028 | generator functions (`function*`) and `yield` |
//! | JS029 | `async` functions and `await` |
//! | JS030 | spread and rest syntax (`...`) |
//! | JS031 | destructuring (`var {a, b} = obj`) |
//! | JS032 | default parameter values (`function f(a = 1)`) |
//! | JS033 | shorthand properties, methods and computed keys in object literals |
//! | JS034 | `for ... of` loops |
//! | JS035 | the exponent operator (`**`) |
//! | JS036 | optional chaining (`?.`), `??`, and logical assignment (`&&=`, `||=`, `??=`) |
//! | JS037 | modules (`import`, `export`) |
//! | JS038 | the `void` operator |
//! | JS039 | the `debugger` statement |
//! | JS040 | regular expression flags other than `g`, `i`, `m` |
//! | JS041 | number forms outside ES5: `0b101`, `0o17`, `10n`, legacy octal `010` |
//! | JS042 | a comma after the last argument or parameter |
//! | JS043 | empty slots in an array literal (`[1, , 2]`) |
//! | JS100 | the post could not be turned into a script (a construct the Rhai translation lacks); report it |
//! | JS101 | a property postc does not know in `createFormat`/`createVariable`/`globals`/`PostInfo`; it is ignored |
//! | JS102 | a name the post never defines and postc's host does not provide |
//! | JS103 | `decimalMark` is neither `.` nor `,` |
//! | JS104 | a format asks for more than 15 decimals |
//! | JS105 | the post has no `onLinear`, so moves print nothing |
//! | JS106 | the post assigns to the name of a function |

use postc_ir::{Diagnostic, FileId, Span};

pub const UNEXPECTED_CHARACTER: &str = "JS001";
pub const UNTERMINATED_TEXT: &str = "JS002";
pub const BAD_ESCAPE: &str = "JS003";
pub const UNTERMINATED_COMMENT: &str = "JS004";
pub const MALFORMED_NUMBER: &str = "JS005";
pub const UNTERMINATED_REGEX: &str = "JS006";
pub const SYNTAX_ERROR: &str = "JS007";
pub const MISSING_SEMICOLON: &str = "JS008";
pub const UNEXPECTED_END: &str = "JS009";
pub const UNCLOSED: &str = "JS010";
pub const UNMATCHED_CLOSER: &str = "JS011";
pub const INVALID_ASSIGNMENT: &str = "JS012";
pub const TOO_DEEP: &str = "JS013";
pub const RETURN_OUTSIDE_FUNCTION: &str = "JS014";
pub const JUMP_OUTSIDE_LOOP: &str = "JS015";
pub const DUPLICATE_DEFAULT: &str = "JS016";
pub const TRY_WITHOUT_HANDLER: &str = "JS017";

/// The JavaScript that is not part of the subset CNC-Calc posts use. Each
/// has its own code, names itself, and says what to write instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Construct {
    Let,
    Const,
    Arrow,
    Class,
    Template,
    GetterSetter,
    With,
    Label,
    Delete,
    In,
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
}

impl Construct {
    /// The diagnostic code.
    pub fn code(self) -> &'static str {
        use Construct::*;
        match self {
            Let | Const => "JS018",
            Arrow => "JS019",
            Class => "JS020",
            Template => "JS021",
            GetterSetter => "JS022",
            With => "JS023",
            Label => "JS024",
            Delete => "JS025",
            In => "JS026",
            Instanceof => "JS027",
            Generator => "JS028",
            Async => "JS029",
            Spread => "JS030",
            Destructuring => "JS031",
            DefaultParam => "JS032",
            Shorthand | Method | ComputedKey => "JS033",
            ForOf => "JS034",
            Exponent => "JS035",
            OptionalChaining | Nullish | LogicalAssign => "JS036",
            Module => "JS037",
            Void => "JS038",
            Debugger => "JS039",
            RegexFlag => "JS040",
            BinaryOctal | BigInt | LegacyOctal => "JS041",
            TrailingComma => "JS042",
            ArrayHole => "JS043",
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
            GetterSetter => "getters and setters (`get x() {}`)",
            With => "the `with` statement",
            Label => "labels (`outer:`, `break outer`)",
            Delete => "the `delete` operator",
            In => "the `in` operator",
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
            GetterSetter => "use an ordinary property, or a function that returns the value",
            With => "write the object name in front of each property",
            Label => "leave the outer loop with a flag variable instead",
            Delete => "set the property to `undefined` instead",
            In => "compare the property with `undefined`: `obj.x !== undefined`",
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
        }
    }

    /// The diagnostic at the construct.
    pub fn diagnostic(self, span: Span) -> Diagnostic {
        let verb = if self.is_plural() { "are" } else { "is" };
        Diagnostic::error(
            self.code(),
            format!("{} {verb} not part of the JavaScript that CNC-Calc posts use", self.name()),
        )
        .at(span, "not supported by postc")
        .help(self.help())
    }

    fn is_plural(self) -> bool {
        use Construct::*;
        !matches!(
            self,
            With | Delete
                | Spread
                | Destructuring
                | In
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
