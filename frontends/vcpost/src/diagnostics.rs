//! The diagnostic codes of the VcPost frontend, and the helpers that build
//! the diagnostics shared by several passes.
//!
//! | code  | severity | what it means |
//! |-------|----------|---------------|
//! | VC001 | error    | a line VcPost cannot read (unexpected word or symbol) |
//! | VC002 | error    | a string has no closing quote |
//! | VC003 | error    | a character that means nothing in VcPost (or a bad `[name]`) |
//! | VC004 | error    | a line too long, parentheses, blocks or expressions nested too deeply, too many variables, or more than 500 problems in one file |
//! | VC005 | error    | a `Sub` or `Function` has no `End Sub` / `End Function` |
//! | VC006 | error    | an `If` block has no `End If` |
//! | VC007 | error    | a `For` has no `Next` |
//! | VC008 | error    | a `While` has no `Wend`, or a `Do` has no `Loop` |
//! | VC009 | error    | a `Select Case` has no `End Select` |
//! | VC010 | error    | a closing line without its opening (`End If` without `If`, `Next` without `For`, ...) |
//! | VC011 | error    | a block part in the wrong place (`Else` twice, `Case` after `Case Else`, code before the first `Case`, `Next J` closing `For I`, a `Sub` inside a block) |
//! | VC012 | error    | two different `#` keywords in one Sub |
//! | VC013 | error    | more than 16 parameters in one Sub |
//! | VC014 | error    | a reserved name (keyword, built-in function, type name, `N`) used as a parameter |
//! | VC015 | error    | a parameter name that is not a valid name |
//! | VC016 | warning  | a keyword comment outside any Sub (it is ignored) |
//! | VC017 | warning  | an unknown `#` keyword in a comment |
//! | VC018 | error    | a keyword that only one Sub may carry (`#Init #End #Rapid #Move #Approach #Retract #Save`) on several |
//! | VC019 | warning  | a parameter listed twice in one Sub |
//! | VC020 | error    | an unknown register property |
//! | VC021 | error    | a register property set to a value it cannot take |
//! | VC022 | error    | a register property set inside a Sub |
//! | VC023 | error    | an unknown function |
//! | VC024 | error    | a function or Sub called with the wrong number of arguments |
//! | VC025 | error    | a call of a Sub that does not exist |
//! | VC026 | error    | a Sub or Function defined twice, or named like a built-in function |
//! | VC027 | error    | an assignment to something that is not a variable (a Sub, a built-in, a `Const`, `N`) |
//! | VC028 | error    | `Exit For`/`Exit Do`/`Exit Sub`/`Exit Function` outside its block, or out of another kind of loop |
//! | VC029 | error    | a property other than `.Previous` read in an expression, or `.Previous` of a local |
//! | VC030 | warning  | a variable read but never set anywhere, and not one the runtime sets |
//! | VC031 | error    | a Sub called for an APT word or a composites event that takes parameters |
//! | VC032 | error    | a BASIC feature postc does not support (arrays, `Exp`, an unknown `As` type, ...) |
//! | VC033 | warning  | `<Name>` in an `Out` string names a keyword; it prints as text |
//! | VC034 | warning  | a name declared twice, or a local hiding a register |
//! | VC035 | warning  | a `ByRef` parameter: postc passes every argument by value |
//! | VC036 | error    | a Sub used as a value, or a variable called like a Sub |
//! | VC037 | warning  | an `Option ...` line (`Option Explicit`): ignored |

use postc_ir::{Diagnostic, Span};

pub const SYNTAX: &str = "VC001";
pub const UNTERMINATED_STRING: &str = "VC002";
pub const BAD_CHAR: &str = "VC003";
pub const TOO_COMPLEX: &str = "VC004";
pub const MISSING_END_SUB: &str = "VC005";
pub const MISSING_END_IF: &str = "VC006";
pub const MISSING_NEXT: &str = "VC007";
pub const MISSING_LOOP_END: &str = "VC008";
pub const MISSING_END_SELECT: &str = "VC009";
pub const STRAY_CLOSER: &str = "VC010";
pub const MISPLACED: &str = "VC011";
pub const TWO_KEYWORDS: &str = "VC012";
pub const TOO_MANY_PARAMS: &str = "VC013";
pub const RESERVED_PARAM: &str = "VC014";
pub const BAD_PARAM_NAME: &str = "VC015";
pub const KEYWORD_OUTSIDE_SUB: &str = "VC016";
pub const UNKNOWN_KEYWORD: &str = "VC017";
pub const DUPLICATE_KEYWORD_SUB: &str = "VC018";
pub const DUPLICATE_PARAM: &str = "VC019";
pub const UNKNOWN_PROPERTY: &str = "VC020";
pub const BAD_PROPERTY_VALUE: &str = "VC021";
pub const PROPERTY_IN_SUB: &str = "VC022";
pub const UNKNOWN_FUNCTION: &str = "VC023";
pub const ARGUMENT_COUNT: &str = "VC024";
pub const UNKNOWN_SUB: &str = "VC025";
pub const DUPLICATE_SUB: &str = "VC026";
pub const NOT_ASSIGNABLE: &str = "VC027";
pub const MISPLACED_EXIT: &str = "VC028";
pub const BAD_PROPERTY_READ: &str = "VC029";
pub const NEVER_SET: &str = "VC030";
pub const HANDLER_WITH_PARAMS: &str = "VC031";
pub const UNSUPPORTED: &str = "VC032";
pub const KEYWORD_IN_TEMPLATE: &str = "VC033";
pub const DECLARED_TWICE: &str = "VC034";
pub const BYREF: &str = "VC035";
pub const NOT_A_VALUE: &str = "VC036";
pub const OPTION_IGNORED: &str = "VC037";
pub const UNCLOSED_REGISTER: &str = "VC038";

/// Every code with its one-line meaning, in order (for documentation and
/// for a test that the table above stays complete).
pub const ALL: &[&str] = &[
    SYNTAX,
    UNTERMINATED_STRING,
    BAD_CHAR,
    TOO_COMPLEX,
    MISSING_END_SUB,
    MISSING_END_IF,
    MISSING_NEXT,
    MISSING_LOOP_END,
    MISSING_END_SELECT,
    STRAY_CLOSER,
    MISPLACED,
    TWO_KEYWORDS,
    TOO_MANY_PARAMS,
    RESERVED_PARAM,
    BAD_PARAM_NAME,
    KEYWORD_OUTSIDE_SUB,
    UNKNOWN_KEYWORD,
    DUPLICATE_KEYWORD_SUB,
    DUPLICATE_PARAM,
    UNKNOWN_PROPERTY,
    BAD_PROPERTY_VALUE,
    PROPERTY_IN_SUB,
    UNKNOWN_FUNCTION,
    ARGUMENT_COUNT,
    UNKNOWN_SUB,
    DUPLICATE_SUB,
    NOT_ASSIGNABLE,
    MISPLACED_EXIT,
    BAD_PROPERTY_READ,
    NEVER_SET,
    HANDLER_WITH_PARAMS,
    UNSUPPORTED,
    KEYWORD_IN_TEMPLATE,
    DECLARED_TWICE,
    BYREF,
    NOT_A_VALUE,
    OPTION_IGNORED,
    UNCLOSED_REGISTER,
];

/// Message the lexer gives an unterminated string (mapped to VC002).
pub const UNTERMINATED_STRING_MSG: &str = "this text has no closing quote `\"`";
/// Message the lexer gives a bad `[name]` (mapped to VC003).
pub const BAD_BRACKET_NAME_MSG: &str =
    "a name in brackets must start with a letter and hold only letters, digits and `_`";
/// Start of the message the lexer gives a stray character (mapped to VC003).
pub const BAD_CHAR_MSG: &str = "VcPost does not understand the character ";

/// A lexer error, by its message.
pub fn lexical(span: Span, reason: &str) -> Diagnostic {
    if reason == UNTERMINATED_STRING_MSG {
        Diagnostic::error(UNTERMINATED_STRING, "a string has no closing quote")
            .at(span, "the string starts here and runs to the end of the line")
            .help("end the text with `\"`; write `\"\"` for a quote inside the text")
    } else if reason == BAD_BRACKET_NAME_MSG {
        Diagnostic::error(BAD_CHAR, "this bracketed name is not a valid name")
            .at(span, "not a name")
            .help(BAD_BRACKET_NAME_MSG)
    } else {
        Diagnostic::error(BAD_CHAR, reason.to_string())
            .at(span, "not part of VcPost")
            .help("comments start with `'`; text must be inside double quotes")
    }
}

/// A line refused because it is too long or nests too deeply.
pub fn too_complex(span: Span, tokens: usize, depth: usize) -> Diagnostic {
    let what = if tokens > crate::lexer::MAX_LINE_TOKENS {
        format!("this line is too long ({tokens} words and symbols; at most {})", crate::lexer::MAX_LINE_TOKENS)
    } else {
        format!("parentheses are nested too deeply ({depth} levels; at most {})", crate::lexer::MAX_PAREN_DEPTH)
    };
    Diagnostic::error(TOO_COMPLEX, what)
        .at(span, "this line is skipped")
        .help("split the calculation over several lines with intermediate variables")
}

/// The closest of `candidates` to `name` (ignoring case), if it is close
/// enough to be a likely typing mistake.
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let lower = name.to_lowercase();
    candidates
        .into_iter()
        .map(|c| (edit_distance(&lower, &c.to_lowercase()), c))
        .filter(|(d, c)| {
            let len = c.chars().count();
            len >= 3 && *d > 0 && *d <= (len / 3).max(1)
        })
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let old = row[j + 1];
            row[j + 1] = (row[j + 1] + 1).min(row[j] + 1).min(prev + usize::from(ca != *cb));
            prev = old;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_numbered_in_order() {
        for (i, code) in ALL.iter().enumerate() {
            assert_eq!(*code, format!("VC{:03}", i + 1));
        }
    }

    #[test]
    fn suggestions() {
        assert_eq!(suggest("Fromat", ["Format", "Prefix"]), Some("Format"));
        assert_eq!(suggest("Clearnce", ["Clearance", "X"]), Some("Clearance"));
        assert_eq!(suggest("Q", ["X", "Y"]), None);
    }
}
