//! The diagnostic codes of the VcPost frontend, and the helpers that build
//! the diagnostics shared by several passes.
//!
//! Its diagnostic codes are declared in the registry `postc_ir::codes`
//! (rendered as docs/diagnostics.md; `postc explain CODE`).

use postc_ir::codes;
use postc_ir::{Diagnostic, Span};

pub const SYNTAX: &str = codes::VC001.code;
pub const UNTERMINATED_STRING: &str = codes::VC002.code;
pub const BAD_CHAR: &str = codes::VC003.code;
pub const TOO_COMPLEX: &str = codes::VC004.code;
pub const MISSING_END_SUB: &str = codes::VC005.code;
pub const MISSING_END_IF: &str = codes::VC006.code;
pub const MISSING_NEXT: &str = codes::VC007.code;
pub const MISSING_LOOP_END: &str = codes::VC008.code;
pub const MISSING_END_SELECT: &str = codes::VC009.code;
pub const STRAY_CLOSER: &str = codes::VC010.code;
pub const MISPLACED: &str = codes::VC011.code;
pub const TWO_KEYWORDS: &str = codes::VC012.code;
pub const TOO_MANY_PARAMS: &str = codes::VC013.code;
pub const RESERVED_PARAM: &str = codes::VC014.code;
pub const BAD_PARAM_NAME: &str = codes::VC015.code;
pub const KEYWORD_OUTSIDE_SUB: &str = codes::VC016.code;
pub const UNKNOWN_KEYWORD: &str = codes::VC017.code;
pub const DUPLICATE_KEYWORD_SUB: &str = codes::VC018.code;
pub const DUPLICATE_PARAM: &str = codes::VC019.code;
pub const UNKNOWN_PROPERTY: &str = codes::VC020.code;
pub const BAD_PROPERTY_VALUE: &str = codes::VC021.code;
pub const PROPERTY_IN_SUB: &str = codes::VC022.code;
pub const UNKNOWN_FUNCTION: &str = codes::VC023.code;
pub const ARGUMENT_COUNT: &str = codes::VC024.code;
pub const UNKNOWN_SUB: &str = codes::VC025.code;
pub const DUPLICATE_SUB: &str = codes::VC026.code;
pub const NOT_ASSIGNABLE: &str = codes::VC027.code;
pub const MISPLACED_EXIT: &str = codes::VC028.code;
pub const BAD_PROPERTY_READ: &str = codes::VC029.code;
pub const NEVER_SET: &str = codes::VC030.code;
pub const HANDLER_WITH_PARAMS: &str = codes::VC031.code;
pub const UNSUPPORTED: &str = codes::VC032.code;
pub const KEYWORD_IN_TEMPLATE: &str = codes::VC033.code;
pub const DECLARED_TWICE: &str = codes::VC034.code;
pub const BYREF: &str = codes::VC035.code;
pub const NOT_A_VALUE: &str = codes::VC036.code;
pub const OPTION_IGNORED: &str = codes::VC037.code;
pub const UNCLOSED_REGISTER: &str = codes::VC038.code;

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
        .map(|c| (strsim::levenshtein(&lower, &c.to_lowercase()), c))
        .filter(|(d, c)| {
            let len = c.chars().count();
            len >= 3 && *d > 0 && *d <= (len / 3).max(1)
        })
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}
