//! The diagnostic codes of the Vectric frontend, and the one place that
//! turns a code into a [`Diagnostic`] with the right severity.
//!
//! The codes themselves (severity, summary, documentation) are declared
//! once, in the registry `postc_ir::codes`; this enum names the `PP` entries
//! for the parser's call sites.

use postc_ir::codes;
use postc_ir::{Diagnostic, Severity};

macro_rules! codes {
    ($( $name:ident = $id:ident; )*) => {
        /// A diagnostic code of the Vectric frontend: a name for a `PP`
        /// entry of the registry.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Code {
            $( #[doc = concat!("`", stringify!($id), "`: see the registry `postc_ir::codes`.")] $name, )*
        }

        impl Code {
            /// Every code, in number order.
            pub const ALL: &'static [Code] = &[$(Code::$name,)*];

            /// The registry entry.
            pub fn entry(self) -> codes::Code {
                match self { $(Code::$name => codes::$id,)* }
            }
        }
    };
}

codes! {
    MalformedVar = PP001;
    UnknownVarName = PP002;
    UnknownVarLabel = PP003;
    BadOutputMode = PP004;
    BadFormat = PP005;
    BadMultiplier = PP006;
    UnterminatedString = PP007;
    BadCharCode = PP008;
    UnclosedBracket = PP009;
    UnknownGlobal = PP010;
    BadGlobalValue = PP011;
    OutputOutsideSection = PP012;
    MissingSectionName = PP013;
    UnterminatedScript = PP014;
    GlobalWithoutValue = PP015;
    UnknownLabel = PP016;
    UnknownSection = PP017;
    StrayText = PP018;
    MissingBase = PP019;
    ScriptNotRun = PP020;
    CoarseArcWords = PP021;
    DuplicateSection = PP022;
    Duplicate = PP023;
    BlankInSectionName = PP024;
    MissingPrefixField = PP025;
    FormatWithoutSeparator = PP026;
    NoUnits = PP027;
    OddSubstitute = PP028;
    LabelNameMismatch = PP029;
    BaseChain = PP030;
    TwoRotaryWraps = PP031;
    Unreadable = PP032;
    BareVariables = PP033;
}

impl Code {
    /// The stable identifier (`PP001`).
    pub fn id(self) -> &'static str {
        self.entry().code
    }

    /// How bad a diagnostic with this code is.
    pub fn severity(self) -> Severity {
        self.entry().severity
    }

    /// One line saying what the code means.
    pub fn summary(self) -> &'static str {
        self.entry().summary
    }

    /// A diagnostic with this code, its severity and `message`.
    pub fn diag(self, message: impl Into<String>) -> Diagnostic {
        self.entry().diag(message)
    }
}
