//! The diagnostic codes of the Vectric frontend, and the one place that
//! turns a code into a [`Diagnostic`] with the right severity.
//!
//! Codes are stable: a code keeps its meaning forever, new codes are added
//! at the end.
//!
//! | code  | severity | meaning |
//! |-------|----------|---------|
//! | PP001 | error    | malformed `VAR` line: no name, no `=`, no `[` or `]`, or not 4 or 5 fields between the brackets |
//! | PP002 | error    | unknown variable name after `VAR` |
//! | PP003 | error    | the label of a `VAR` is not a value postc knows, and its name does not say which value it is |
//! | PP004 | error    | the "when output" field of a `VAR` is not `A` (always) or `C` (on change) |
//! | PP005 | error    | bad value format in a `VAR` (flags `- + 0 #`, width, `.` or `,`, decimals) |
//! | PP006 | error    | bad multiplier in a `VAR` |
//! | PP007 | error    | a quoted string has no closing quote |
//! | PP008 | error    | a `[nn]` character code is over 255 |
//! | PP009 | error    | a `[` in a string is never closed with `]` |
//! | PP010 | error    | unknown global statement (`NAME = value` outside a section) |
//! | PP011 | error    | bad value for a global statement (wrong kind or number of values) |
//! | PP012 | error    | an output line before the first `begin` section |
//! | PP013 | error    | `begin` without a section name |
//! | PP014 | error    | `SCRIPT` block without `ENDSCRIPT` |
//! | PP015 | error    | a global statement without `=` and a value |
//! | PP016 | warning  | unknown `[LABEL]` in an output string: it prints as written |
//! | PP017 | warning  | unknown section: its lines are kept out of the compiled post |
//! | PP018 | warning  | text outside quotes (or after the closing quote) is ignored |
//! | PP019 | warning  | the `POST_BASE` file cannot be read: the post compiles without it |
//! | PP020 | warning  | Lua script lines are kept but postc does not run them |
//! | PP021 | warning  | arc words print fewer decimals than positions: a controller's radius check may reject arcs |
//! | PP022 | warning  | a section appears twice: the later one replaces the earlier one |
//! | PP023 | warning  | a `VAR`, a label or a global statement appears twice: the later one wins |
//! | PP024 | warning  | stray blank inside a section name (`FIRST_CW _HELICAL_ARC_MOVE`) |
//! | PP025 | warning  | `VAR` with 3 fields: the prefix field is missing and taken as empty |
//! | PP026 | warning  | value format without a decimal separator: read as whole numbers |
//! | PP027 | warning  | no `UNITS` statement: the output is written in the toolpath's own units |
//! | PP028 | warning  | `SUBSTITUTE` has an odd number of characters: the last one is ignored |
//! | PP029 | warning  | a `VAR`'s label prints another value than its name says |
//! | PP030 | warning  | `POST_BASE` chain loops back or is too deep: the rest of the chain is ignored |
//! | PP031 | warning  | both `ROTARY_WRAP_X` and `ROTARY_WRAP_Y`: only the later one is used |
//! | PP032 | error    | a line the grammar could not read at all (should not happen; report it) |

use postc_ir::{Diagnostic, Severity};

macro_rules! codes {
    ($( $name:ident = $id:literal, $sev:ident, $summary:literal; )*) => {
        /// A diagnostic code of the Vectric frontend.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Code {
            $( #[doc = $summary] $name, )*
        }

        impl Code {
            /// Every code, in number order.
            pub const ALL: &'static [Code] = &[$(Code::$name,)*];

            /// The stable identifier (`PP001`).
            pub fn id(self) -> &'static str {
                match self { $(Code::$name => $id,)* }
            }

            /// How bad a diagnostic with this code is.
            pub fn severity(self) -> Severity {
                match self { $(Code::$name => Severity::$sev,)* }
            }

            /// One line saying what the code means.
            pub fn summary(self) -> &'static str {
                match self { $(Code::$name => $summary,)* }
            }
        }
    };
}

codes! {
    MalformedVar = "PP001", Error, "malformed VAR line";
    UnknownVarName = "PP002", Error, "unknown variable name after VAR";
    UnknownVarLabel = "PP003", Error, "VAR label is not a value postc knows";
    BadOutputMode = "PP004", Error, "when-output field is not A or C";
    BadFormat = "PP005", Error, "bad value format";
    BadMultiplier = "PP006", Error, "bad multiplier";
    UnterminatedString = "PP007", Error, "string without closing quote";
    BadCharCode = "PP008", Error, "character code over 255";
    UnclosedBracket = "PP009", Error, "[ without ]";
    UnknownGlobal = "PP010", Error, "unknown global statement";
    BadGlobalValue = "PP011", Error, "bad value for a global statement";
    OutputOutsideSection = "PP012", Error, "output line outside any section";
    MissingSectionName = "PP013", Error, "begin without a section name";
    UnterminatedScript = "PP014", Error, "SCRIPT without ENDSCRIPT";
    GlobalWithoutValue = "PP015", Error, "global statement without = value";
    UnknownLabel = "PP016", Warning, "unknown [LABEL] in an output string";
    UnknownSection = "PP017", Warning, "unknown section";
    StrayText = "PP018", Warning, "text outside quotes is ignored";
    MissingBase = "PP019", Warning, "POST_BASE file cannot be read";
    ScriptNotRun = "PP020", Warning, "Lua script kept but not run";
    CoarseArcWords = "PP021", Warning, "arc words coarser than positions";
    DuplicateSection = "PP022", Warning, "section appears twice";
    Duplicate = "PP023", Warning, "VAR, label or global statement appears twice";
    BlankInSectionName = "PP024", Warning, "stray blank in a section name";
    MissingPrefixField = "PP025", Warning, "VAR without a prefix field";
    FormatWithoutSeparator = "PP026", Warning, "value format without decimal separator";
    NoUnits = "PP027", Warning, "no UNITS statement";
    OddSubstitute = "PP028", Warning, "SUBSTITUTE with an odd number of characters";
    LabelNameMismatch = "PP029", Warning, "VAR label and name disagree";
    BaseChain = "PP030", Warning, "POST_BASE chain loops or is too deep";
    TwoRotaryWraps = "PP031", Warning, "both ROTARY_WRAP_X and ROTARY_WRAP_Y";
    Unreadable = "PP032", Error, "line the grammar could not read";
}

impl Code {
    /// A diagnostic with this code, its severity and `message`.
    pub fn diag(self, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(self.severity(), self.id(), message)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_numbered_in_order_and_documented() {
        let doc = include_str!("diagnostics.rs");
        for (i, code) in Code::ALL.iter().enumerate() {
            assert_eq!(code.id(), format!("PP{:03}", i + 1));
            let severity = match code.severity() {
                Severity::Error => "error",
                Severity::Warning => "warning",
                Severity::Note => "note",
            };
            let row = format!("//! | {} | {severity}", code.id());
            let found = doc.lines().any(|l| l.split_whitespace().collect::<Vec<_>>().join(" ").starts_with(&row));
            assert!(found, "doc table lacks a row for {} ({severity})", code.id());
        }
    }
}
