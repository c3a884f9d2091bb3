//! The registry of every diagnostic code postc reports: one declaration per
//! code with its default severity, a one-line summary, and its
//! documentation (what it means, an example, the fix). Frontends, readers,
//! backends, `postc verify` and the command line name their codes through
//! the constants declared here (`codes::PP001`), so a code is declared once;
//! `docs/diagnostics.md` is rendered from this file ([`markdown`]) and
//! `postc explain CODE` prints one entry ([`Code::explain`]).
//!
//! Codes are stable: a code keeps its meaning forever, new codes are added
//! at the end of their prefix. The runtime still writes its `RT` codes as
//! literals; `tests/diagnostic_codes.rs` checks that every code written in
//! the source is declared here.
//!
//! Severity can be changed per code, per prefix or for all codes with
//! [`LevelRules`] (`--warn`, `--deny`, `--allow` and `postc.toml`).

use std::fmt::Write as _;

use crate::diagnostic::{Diagnostic, Severity};

/// One diagnostic code and its documentation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Code {
    /// The stable identifier, such as `PP012`.
    pub code: &'static str,
    /// The severity a diagnostic with this code has unless configured otherwise.
    pub severity: Severity,
    /// True when the code is reported with either severity (its documentation says when).
    pub varies: bool,
    /// One line: what the code means.
    pub summary: &'static str,
    /// What it means, for a post author; empty when the summary says it all.
    pub meaning: &'static str,
    /// A few lines of post or toolpath text that trigger it; empty when none can be shown briefly.
    pub example: &'static str,
    /// What to do about it; empty when not written yet.
    pub fix: &'static str,
}

impl From<Code> for &'static str {
    fn from(code: Code) -> &'static str {
        code.code
    }
}

macro_rules! declare_codes {
    ($(
        $(#[doc = $doc:literal])*
        $id:ident : $sev:ident $(| $alt:ident)?, $summary:literal
        $(, example = $example:literal)?
        $(, fix = $fix:literal)?
        ;
    )*) => {
        $(
            #[doc = $summary]
            #[doc = ""]
            $(#[doc = $doc])*
            pub const $id: Code = Code {
                code: stringify!($id),
                severity: Severity::$sev,
                varies: declare_codes!(@varies $($alt)?),
                summary: $summary,
                meaning: concat!($($doc, "\n",)*),
                example: concat!($($example)?),
                fix: concat!($($fix)?),
            };
        )*

        /// Every code, grouped by prefix in the order of [`SECTIONS`].
        pub const ALL: &[Code] = &[$($id,)*];
    };
    (@varies) => { false };
    (@varies $alt:ident) => { true };
}

/// A part of `docs/diagnostics.md`: the codes of some prefixes.
#[derive(Clone, Copy, Debug)]
pub struct Section {
    pub title: &'static str,
    pub prefixes: &'static [&'static str],
    /// A paragraph above the section's table, or empty.
    pub intro: &'static str,
}

/// The prefixes: where each group of codes comes from.
pub const PREFIXES: &[(&str, &str)] = &[
    ("PP", "Vectric `.pp` posts (`frontends/vectric`)"),
    ("JS", "CIMCO JavaScript posts (`frontends/cimco`)"),
    ("VC", "VcPost posts (`frontends/vcpost`)"),
    ("PT", "VcPost probe-cycle tables"),
    ("CP", "VcPost composites event files"),
    ("CL", "APT CL files (`frontends/apt`)"),
    ("PX", "`postc postp` and its controllers (`postp/`)"),
    ("TP", "native toolpaths (`frontends/src/native.rs`)"),
    ("RT", "the runtime, while posting"),
    ("IO", "files and the command line"),
    ("IR", "posts written as IR"),
    ("CV", "`postc convert` (`backends/`)"),
    ("VF", "`postc verify`: findings in a G-code program against its toolpath (`verify/`, `docs/verify.md`)"),
];

/// The sections of `docs/diagnostics.md`, in order.
pub const SECTIONS: &[Section] = &[
    Section { title: "Vectric posts (PP)", prefixes: &["PP"], intro: "" },
    Section { title: "CIMCO posts (JS)", prefixes: &["JS"], intro: "" },
    Section { title: "VcPost posts (VC)", prefixes: &["VC"], intro: "" },
    Section { title: "VcPost probe tables (PT)", prefixes: &["PT"], intro: "" },
    Section { title: "VcPost composites files (CP)", prefixes: &["CP"], intro: "" },
    Section { title: "APT CL files (CL)", prefixes: &["CL"], intro: "" },
    Section { title: "postp (PX)", prefixes: &["PX"], intro: "" },
    Section {
        title: "Runtime, files and command line (RT, TP, IO, IR)",
        prefixes: &["IO", "IR", "TP", "RT"],
        intro: "",
    },
    Section { title: "Converting posts (CV)", prefixes: &["CV"], intro: "" },
    Section {
        title: "postc verify (VF)",
        prefixes: &["VF"],
        intro: "Findings of `postc verify` (`docs/verify.md`). Each names the program's\nline and column; those about a move also point at the toolpath move.",
    },
];

/// The registry entry of `code` (`PP012`), if there is one.
pub fn lookup(code: &str) -> Option<&'static Code> {
    ALL.iter().find(|c| c.code == code)
}

/// Whether `text` has the shape of a code: two upper-case letters and three digits.
pub fn is_code_shaped(text: &str) -> bool {
    let b = text.as_bytes();
    b.len() == 5 && b[..2].iter().all(u8::is_ascii_uppercase) && b[2..].iter().all(u8::is_ascii_digit)
}

/// Whether a diagnostic of `code` may be reported with `severity`: the code
/// is in the registry and has that default severity (or either severity when
/// its entry says it varies). The `Diagnostic` constructors check this in
/// debug builds.
pub fn severity_ok(code: &str, severity: Severity) -> bool {
    lookup(code).is_some_and(|c| c.varies || c.severity == severity)
}

/// Codes that look like `code` (same prefix and a close number, or one
/// character off), for "did you mean" in `postc explain`.
pub fn similar(code: &str) -> Vec<&'static str> {
    let upper = code.trim().to_ascii_uppercase();
    if let Some(c) = lookup(&upper) {
        return vec![c.code];
    }
    let off_by_one = |c: &Code| {
        c.code.len() == upper.len() && c.code.bytes().zip(upper.bytes()).filter(|(a, b)| a != b).count() == 1
    };
    let mut out: Vec<&'static str> = ALL.iter().filter(|c| off_by_one(c)).map(|c| c.code).collect();
    if out.is_empty()
        && let (Some(prefix), Some(number)) = (upper.get(..2), upper.get(2..).and_then(|n| n.parse::<i64>().ok()))
    {
        let mut near: Vec<&Code> = ALL.iter().filter(|c| c.code.starts_with(prefix)).collect();
        near.sort_by_key(|c| (c.code[2..].parse::<i64>().unwrap_or(0) - number).abs());
        out = near.iter().take(3).map(|c| c.code).collect();
        out.sort_unstable();
    }
    out.truncate(5);
    out
}

/// The documentation lines of a `///` block without their leading blank.
fn paragraphs(text: &str) -> String {
    let lines: Vec<&str> = text.lines().map(|l| l.strip_prefix(' ').unwrap_or(l)).collect();
    lines.join("\n").trim().to_string()
}

fn severity_word(code: &Code) -> String {
    if code.varies {
        let other = if code.severity == Severity::Error { Severity::Warning } else { Severity::Error };
        format!("{} or {other}", code.severity)
    } else {
        code.severity.to_string()
    }
}

impl Code {
    /// The code's documentation as `postc explain` prints it.
    pub fn explain(&self) -> String {
        let mut out = format!("{}: {}\n\nseverity: {}", self.code, self.summary, severity_word(self));
        if !self.varies && self.severity == Severity::Warning {
            out.push_str(" (`--deny ");
            out.push_str(self.code);
            out.push_str("` makes it an error, `--allow ");
            out.push_str(self.code);
            out.push_str("` hides it)");
        }
        out.push('\n');
        let meaning = paragraphs(self.meaning);
        if !meaning.is_empty() {
            let _ = write!(out, "\n{meaning}\n");
        }
        if !self.example.is_empty() {
            out.push_str("\nExample:\n\n");
            for line in self.example.trim_end().lines() {
                let _ = writeln!(out, "    {line}");
            }
        }
        if !self.fix.is_empty() {
            let _ = write!(out, "\nFix: {}\n", self.fix.trim());
        }
        out
    }

    /// A diagnostic with this code, its registry severity and `message`.
    pub fn diag(self, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(self.severity, self.code, message)
    }
}

/// The text of `docs/diagnostics.md` above the first section: what a code
/// is, and how to change a code's severity.
const INTRO: &str = include_str!("codes_intro.md");

/// `docs/diagnostics.md`, rendered from the registry.
pub fn markdown() -> String {
    let mut out = String::from(INTRO.trim_end());
    out.push_str("\n\n| prefix | from |\n|---|---|\n");
    for (prefix, from) in PREFIXES {
        let _ = writeln!(out, "| `{prefix}` | {from} |");
    }
    for section in SECTIONS {
        let _ = write!(out, "\n## {}\n\n", section.title);
        if !section.intro.is_empty() {
            let _ = write!(out, "{}\n\n", section.intro);
        }
        out.push_str("| code | severity | meaning |\n|---|---|---|\n");
        let codes: Vec<&Code> = ALL.iter().filter(|c| section.prefixes.iter().any(|p| c.code.starts_with(p))).collect();
        for c in &codes {
            let _ = writeln!(out, "| {} | {} | {} |", c.code, severity_word(c), c.summary.replace('|', "\\|"));
        }
        for c in codes.iter().filter(|c| !c.meaning.is_empty() || !c.example.is_empty() || !c.fix.is_empty()) {
            let _ = write!(out, "\n### {}\n\n", c.code);
            let meaning = paragraphs(c.meaning);
            if !meaning.is_empty() {
                let _ = write!(out, "{meaning}\n\n");
            }
            if !c.example.is_empty() {
                let _ = write!(out, "```text\n{}\n```\n\n", c.example.trim_end());
            }
            if !c.fix.is_empty() {
                let _ = write!(out, "**Fix:** {}\n\n", c.fix.trim());
            }
            out.truncate(out.trim_end().len());
            out.push('\n');
        }
    }
    out
}

/// What a rule does to the diagnostics it selects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// Hide them.
    Allow,
    /// Report them as warnings.
    Warn,
    /// Report them as errors.
    Deny,
}

/// Severity rules: `--warn`/`--deny`/`--allow` and `postc.toml`'s
/// `[diagnostics]`. A selector is a code (`PP027`), a prefix (`PP`) or
/// `all`. For each diagnostic the most specific rule wins (a code over a
/// prefix over `all`), rules added later win over earlier ones of the same
/// specificity, and the command line's rules (added after the file's) win
/// over the file's. Rules change warnings only: an error stays an error,
/// since a post or toolpath with an error cannot be used.
#[derive(Clone, Debug, Default)]
pub struct LevelRules {
    /// (selector, level, source rank): later ranks win over earlier ones.
    rules: Vec<(String, Level, u8)>,
}

impl LevelRules {
    /// Checks a selector: a known code, a known prefix, or `all`.
    pub fn check_selector(selector: &str) -> Result<String, String> {
        let s = selector.trim();
        if s.eq_ignore_ascii_case("all") {
            return Ok("all".into());
        }
        let upper = s.to_ascii_uppercase();
        if lookup(&upper).is_some() || PREFIXES.iter().any(|(p, _)| *p == upper) {
            return Ok(upper);
        }
        let hint = similar(&upper);
        if hint.is_empty() {
            Err(format!("`{s}` is not a diagnostic code, a prefix (PP, JS, VC, ...) or `all`"))
        } else {
            Err(format!("`{s}` is not a diagnostic code; did you mean {}?", hint.join(", ")))
        }
    }

    /// Adds a rule; `rank` orders sources (the file 0, the command line 1).
    pub fn add(&mut self, selector: &str, level: Level, rank: u8) -> Result<(), String> {
        let s = Self::check_selector(selector)?;
        self.rules.push((s, level, rank));
        Ok(())
    }

    pub fn is_empty(&self) -> bool {
        self.rules.is_empty()
    }

    /// The level the rules give `code`, if any rule selects it.
    pub fn level(&self, code: &str) -> Option<Level> {
        let specificity = |s: &str| match s {
            "all" => 0,
            s if s.len() == 2 => 1,
            _ => 2,
        };
        let selects = |s: &str| s == "all" || s == code || (s.len() == 2 && code.starts_with(s));
        self.rules
            .iter()
            .enumerate()
            .filter(|(_, (s, _, _))| selects(s))
            .max_by_key(|(i, (s, _, rank))| (*rank, specificity(s), *i))
            .map(|(_, (_, level, _))| *level)
    }

    /// Applies the rules: drops allowed warnings, turns denied warnings into errors.
    pub fn apply(&self, diagnostics: &mut Vec<Diagnostic>) {
        if self.rules.is_empty() {
            return;
        }
        diagnostics.retain_mut(|d| {
            if d.severity == Severity::Error {
                return true;
            }
            match self.level(d.code) {
                Some(Level::Allow) => false,
                Some(Level::Warn) => {
                    d.severity = Severity::Warning;
                    true
                }
                Some(Level::Deny) => {
                    d.severity = Severity::Error;
                    true
                }
                None => true,
            }
        });
    }
}

declare_codes! {
    PP001: Error, "malformed `VAR` line: no name, no `=`, no `[` or `]`, or not 4 or 5 fields between the brackets";
    PP002: Error, "unknown variable name after `VAR`";
    PP003: Error, "the label of a `VAR` is not a value postc knows, and its name does not say which value it is";
    PP004: Error, "the \"when output\" field of a `VAR` is not `A` (always) or `C` (on change)";
    PP005: Error, "bad value format in a `VAR` (flags `- + 0 #`, width, `.` or `,`, decimals)";
    PP006: Error, "bad multiplier in a `VAR`";
    PP007: Error, "a quoted string has no closing quote";
    PP008: Error, "a `[nn]` character code is over 255";
    PP009: Error, "a `[` in a string is never closed with `]`";
    PP010: Error, "unknown global statement (`NAME = value` outside a section)";
    PP011: Error, "bad value for a global statement (wrong kind or number of values)";
    PP012: Error, "an output line before the first `begin` section";
    PP013: Error, "`begin` without a section name";
    PP014: Error, "`SCRIPT` block without `ENDSCRIPT`";
    PP015: Error, "a global statement without `=` and a value";
    PP016: Warning, "unknown `[LABEL]` in an output string: it prints as written";
    PP017: Warning, "unknown section: its lines are kept out of the compiled post";
    PP018: Warning, "text outside quotes (or after the closing quote) is ignored";
    PP019: Warning, "the `POST_BASE` file cannot be read: the post compiles without it";
    PP020: Warning, "Lua script lines are kept but postc does not run them";
    PP021: Warning, "arc words print fewer decimals than positions: a controller's radius check may reject arcs";
    PP022: Warning, "a section appears twice: the later one replaces the earlier one";
    PP023: Warning, "a `VAR`, a label or a global statement appears twice: the later one wins";
    PP024: Warning, "stray blank inside a section name (`FIRST_CW _HELICAL_ARC_MOVE`)";
    PP025: Warning, "`VAR` with 3 fields: the prefix field is missing and taken as empty";
    PP026: Warning, "value format without a decimal separator: read as whole numbers";
    PP027: Warning, "no `UNITS` statement: the output is written in the toolpath's own units";
    PP028: Warning, "`SUBSTITUTE` has an odd number of characters: the last one is ignored";
    PP029: Warning, "a `VAR`'s label prints another value than its name says";
    PP030: Warning, "`POST_BASE` chain loops back or is too deep: the rest of the chain is ignored";
    PP031: Warning, "both `ROTARY_WRAP_X` and `ROTARY_WRAP_Y`: only the later one is used";
    PP032: Error, "a line the grammar could not read at all (should not happen; report it)";
    JS001: Error, "a character that JavaScript does not allow here (`#`, `@`, a stray `\\`)";
    JS002: Error, "text in quotes (or a template literal) is not closed before the end of the line";
    JS003: Error, "a bad escape sequence in text (`\\x4`, `\\u12`, octal `\\12`)";
    JS004: Error, "a `/* ... */` comment is not closed";
    JS005: Error, "a malformed number (`0x`, `1e`, `3mm`)";
    JS006: Error, "a regular expression is not closed before the end of the line";
    JS007: Error, "syntax error: a token where it cannot be";
    JS008: Error, "two statements on one line without `;` between them";
    JS009: Error, "the file ends in the middle of a statement or expression";
    JS010: Error, "a `{`, `(` or `[` that is never closed";
    JS011: Error, "a `}`, `)` or `]` with nothing to close";
    JS012: Error, "an assignment or `++`/`--` to something that is not a variable or property";
    JS013: Error, "code nested too deeply to process";
    JS014: Error, "`return` outside a function";
    JS015: Error, "`break` or `continue` outside a loop (or `continue` in a `switch` only)";
    JS016: Error, "more than one `default` in a `switch`";
    JS017: Error, "`try` without `catch` or `finally`";
    JS018: Error, "`let` / `const` declarations";
    JS019: Error, "arrow functions (`=>`)";
    JS020: Error, "classes (`class`)";
    JS021: Error, "template literals (`` `...` ``)";
    JS022: Error, "getters and setters (`get x() {}`)";
    JS023: Error, "the `with` statement";
    JS024: Error, "labels (`outer:`, `break outer`)";
    JS025: Error, "the `delete` operator";
    JS026: Error, "the `in` operator (outside `for (var k in obj)`)";
    JS027: Error, "the `instanceof` operator";
    JS028: Error, "generator functions (`function*`) and `yield`";
    JS029: Error, "`async` functions and `await`";
    JS030: Error, "spread and rest syntax (`...`)";
    JS031: Error, "destructuring (`var {a, b} = obj`)";
    JS032: Error, "default parameter values (`function f(a = 1)`)";
    JS033: Error, "shorthand properties, methods and computed keys in object literals";
    JS034: Error, "`for ... of` loops";
    JS035: Error, "the exponent operator (`**`)";
    JS036: Error, "optional chaining (`?.`), `??`, and logical assignment (`&&=`, `||=`, `??=`)";
    JS037: Error, "modules (`import`, `export`)";
    JS038: Error, "the `void` operator";
    JS039: Error, "the `debugger` statement";
    JS040: Error, "regular expression flags other than `g`, `i`, `m`";
    JS041: Error, "number forms outside ES5: `0b101`, `0o17`, `10n`, legacy octal `010`";
    JS042: Error, "a comma after the last argument or parameter";
    JS043: Error, "empty slots in an array literal (`[1, , 2]`)";
    JS100: Error, "the post could not be turned into a script (a construct the Rhai translation lacks); report it";
    JS101: Warning, "a property postc does not know in `createFormat`/`createVariable`/`globals`/`PostInfo`; it is ignored";
    JS102: Warning, "a name the post never defines and postc's host does not provide";
    JS103: Warning, "`decimalMark` is neither `.` nor `,`";
    JS104: Warning, "a format asks for more than 15 decimals";
    JS105: Warning, "the post has no `onLinear`, so moves print nothing";
    JS106: Error, "the post assigns to the name of a function";
    VC001: Error, "a line VcPost cannot read (unexpected word or symbol)";
    VC002: Error, "a string has no closing quote";
    VC003: Error, "a character that means nothing in VcPost (or a bad `[name]`)";
    VC004: Error, "a line too long, parentheses, blocks or expressions nested too deeply, too many variables, or more than 500 problems in one file";
    VC005: Error, "a `Sub` or `Function` has no `End Sub` / `End Function`";
    VC006: Error, "an `If` block has no `End If`";
    VC007: Error, "a `For` has no `Next`";
    VC008: Error, "a `While` has no `Wend`, or a `Do` has no `Loop`";
    VC009: Error, "a `Select Case` has no `End Select`";
    VC010: Error, "a closing line without its opening (`End If` without `If`, `Next` without `For`, ...)";
    VC011: Error, "a block part in the wrong place (`Else` twice, `Case` after `Case Else`, code before the first `Case`, `Next J` closing `For I`, a `Sub` inside a block)";
    VC012: Error, "two different `#` keywords in one Sub";
    VC013: Error, "more than 16 parameters in one Sub";
    VC014: Error, "a reserved name (keyword, built-in function, type name, `N`) used as a parameter";
    VC015: Error, "a parameter name that is not a valid name";
    VC016: Warning, "a keyword comment outside any Sub (it is ignored)";
    VC017: Warning, "an unknown `#` keyword in a comment";
    VC018: Error, "a keyword that only one Sub may carry (`#Init #End #Rapid #Move #Approach #Retract #Save`) on several";
    VC019: Warning, "a parameter listed twice in one Sub";
    VC020: Error, "an unknown register property";
    VC021: Error, "a register property set to a value it cannot take";
    VC022: Error, "a register property set inside a Sub";
    VC023: Error, "an unknown function";
    VC024: Error, "a function or Sub called with the wrong number of arguments";
    VC025: Error, "a call of a Sub that does not exist";
    VC026: Error, "a Sub or Function defined twice, or named like a built-in function";
    VC027: Error, "an assignment to something that is not a variable (a Sub, a built-in, a `Const`, `N`)";
    VC028: Error, "`Exit For`/`Exit Do`/`Exit Sub`/`Exit Function` outside its block, or out of another kind of loop";
    VC029: Error, "a property other than `.Previous` read in an expression, or `.Previous` of a local";
    VC030: Warning, "a variable read but never set anywhere, and not one the runtime sets";
    VC031: Error, "a Sub called for an APT word or a composites event that takes parameters";
    VC032: Error, "a BASIC feature postc does not support (arrays, `Exp`, an unknown `As` type, ...)";
    VC033: Warning, "`<Name>` in an `Out` string names a keyword; it prints as text";
    VC034: Warning, "a name declared twice, or a local hiding a register";
    VC035: Warning, "a `ByRef` parameter: postc passes every argument by value";
    VC036: Error, "a Sub used as a value, or a variable called like a Sub";
    VC037: Warning, "an `Option ...` line (`Option Explicit`): ignored";
    VC038: Error, "`<Name` in an `Out` string is never closed with `>` (at the end of the string, or another `<` before it)";
    PT001: Error, "a row that does not split into cells (a quote not closed, text after a closing quote)";
    PT002: Error, "a row names no Sub of the post";
    PT003: Error, "a row names a Sub that is not a probe-cycle Sub (no #Init ... #Save keyword)";
    PT004: Error, "a positional value after a named one";
    PT005: Error, "more values than the Sub has parameters";
    PT006: Error, "`NAME=` names no parameter of the Sub";
    PT007: Error, "a parameter given twice";
    PT008: Error, "a mandatory parameter without a value";
    PT009: Error, "a bare value that is not a number";
    PT010: Error, "an #Init row that is not the first row";
    PT011: Error, "an #End row that is not the last row";
    PT012: Error, "an #Approach row not followed by a #Cycle row";
    PT013: Error, "a #Save row not right after a #Cycle row";
    PT014: Error, "a #Retract row not after a #Cycle or #Save row";
    PT015: Warning, "a table without rows";
    PT016: Error, "`postc probe-table` on a post with no probe-cycle Subs (no keyword comments)";
    CP001: Error, "a line that is not a call of the file's kind (syntax, unknown routine or variable, a missing variable, a wrong type)";
    CP002: Error, "the first line is not the `VcpFile` header";
    CP003: Error, "a call the sequence does not allow here";
    CP004: Error, "the file ends before its sequence does";
    CP005: Error, "an option, probe or `--primer` Sub the post does not have";
    CP006: Error, "a value the seed does not allow (`LinkType`, `Rotation` other than -1, 0, +1; `TowNum` < 0; a list longer than 64)";
    CP007: Warning, "an option, probe or primer Sub without its `#Option`/`#Probe`/`#Primer` keyword";
    CP008: Warning, "`AddCutA`, `AddCutB`, `AddCutI`, `AddCutJ` that disagree";
    CP009: Warning, "a `getNthLength` list whose length is not `TowsInPacket`";
    CP010: Error, "the file cannot be read, or is not UTF-8 text";
    CL001: Error, "binary file, not CL text";
    CL002: Error, "APT part program, not CL data";
    CL003: Error, "syntax error in a record; the record is skipped";
    CL004: Error, "a known record with wrong arguments; skipped";
    CL005: Warning, "unknown word; skipped";
    CL006: Warning, "two values with no comma between them";
    CL007: Warning, "a line of numbers joined to the record above without `$`";
    CL008: Error, "a line of numbers that continues no record";
    CL009: Warning, "a word not understood inside a known record; ignored";
    CL010: Warning, "CIRCLE with no GOTO after it; dropped";
    CL011: Warning, "arc end point not on the circle";
    CL012: Warning, "arc in a tilted plane; cut into feed moves";
    CL013: Warning, "drilling cycle not ended by CYCLE/OFF";
    CL014: Warning, "UNITS after the first move; ignored";
    CL015: Warning, "END-OF-PATH without TOOL PATH";
    CL016: Warning, "records after FINI";
    CL017: Warning, "NURBS spline not followed; reported once";
    CL018: Warning, "file ends after a `$`";
    CL019: Warning, "feed per revolution with no spindle speed known";
    CL020: Error, "line or continued record over 1 MiB";
    CL021: Error, "the file can't be opened or read";
    CL022: Warning, "TLON,GOFWD arc with no INDIRV; taken as counter-clockwise";
    PX001: Error, "no `DIR/cl.tap`";
    PX002: Error, "no MACHIN before the first motion or tool";
    PX003: Error, "MACHIN names no known controller";
    PX004: Error, "MACHIN axis type not 0–6, or given for a lathe";
    PX005: Error, "the options file cannot be read or parsed (line and column)";
    PX006: Error, "an embedded post does not compile (a build defect)";
    PX010: Error, "a lathe word (THREAD, TURRET, SFM) on a mill";
    PX011: Error, "a mill word (LOADTL, LETTER, RETRCT, ROTABL, CYCLE) on a lathe";
    PX012: Error, "a postp word with wrong arguments";
    PX013: Warning, "MACHIN is not the first statement, or a second MACHIN";
    PX014: Warning, "a CL word postp does not use; ignored";
    PX015: Error, "a computed motion or MODE/91 move with the tool position unknown";
    PX016: Error, "CLEARP/CLRSRF plane not usable (named, tilted CLEARP, none defined)";
    PX017: Warning, "dwell in revolutions with no RPM known";
    PX018: Warning, "LETTER: characters outside the font, or no PPRINT after it";
    PX019: Warning, "multi-axis tool axes, or Y on a lathe, ignored";
    PX020: Error, "ROTABL on an axis MACHIN's axis type does not give";
    PX021: Warning, "COOLNT THRU or AIR, taken as FLOOD";
    PX022: Error, "drilling cycle in MODE/91 or under cylindrical mapping";
    IO001: Error, "a post or toolpath file does not exist or cannot be opened";
    IO002: Error, "a toolpath cannot be read (an I/O error while streaming)";
    IO003: Error, "the program cannot be written (the output file or folder, or standard output)";
    IO004: Error, "the dialect of a post cannot be told from its extension or content";
    IO006: Error, "the kind of a toolpath cannot be told, or `postc post` got a post where a toolpath belongs";
    IO007: Error | Warning, "a bad command-line value (`--set NAME=VALUE`, a toolpath pattern)";
    IO008: Warning, "the post splits its output into parts (TAPE_SPLITTING) but there is no `-o`: the parts go to standard output one after the other";
    IR001: Error, "a post written as IR in RON does not read";
    IR002: Error, "a post's IR is inconsistent (an id that names no format, variable, function, global or script; a non-finite multiplier; a chord tolerance, step budget or tape split of 0): points at the item of a RON post that holds it";
    TP001: Error, "a RON toolpath line is not a valid event (unknown event or field, bad value)";
    TP002: Error, "a JSON Lines toolpath line is not a valid event";
    TP003: Error, "the toolpath is not text (not valid UTF-8)";
    RT002: Error, "a post ran more than its step budget for one event (a loop that never ends); points at the loop";
    RT003: Warning, "the post calls Lua scripts, which postc keeps but does not run; those lines are skipped";
    RT004: Error, "calls nest deeper than 200 levels (endless recursion)";
    RT005: Error, "a script function was called but the post has no script host";
    RT010: Warning, "the post has no DWELL_MOVE section, so dwells are skipped";
    RT011: Warning, "a second Job event after output began is ignored";
    RT012: Warning, "the post has no FEED_MOVE section, so feed moves print nothing";
    RT013: Error, "a DrillPoint outside a drilling cycle";
    RT014: Warning, "a tape-split part reached its maximum with no retract in its tolerance and was split inside a cut";
    RT015: Warning, "the post wraps an axis around a cylinder but the job gives no wrap diameter";
    RT016: Error, "an event carries a value that is not a finite number";
    RT017: Warning, "an arc needs more than 10,000 chords to stay within the tolerance; it is cut into 10,000";
    RT018: Warning, "a longhand peck cycle would need more than 1,000 pecks for a hole; it is drilled in 1,000";
    RT020: Warning, "a post driven by APT words has no Sub for a record's word; those records are skipped";
    RT021: Warning, "a post driven by APT words has no Sub for CIRCLE; arcs become GOTO moves";
    RT022: Error, "the script made from a CIMCO post does not compile";
    RT023: Error, "a CIMCO post stopped with a JavaScript error (points at the JS line and column)";
    RT030: Warning, "a probe table or composites file calls a Sub the post lacks; those calls are skipped";
    RT031: Error, "a post built a text past 16 MiB (or, in a script, an array or object past 2^20 items): stopped at its loop, no output written";
    CV001: Error, "the target dialect has no place for a handler of the post: an event it has no section for (coolant, drill cycles, comments, ...), or a post driven by APT words";
    CV002: Error, "the post has code (functions, globals, statements other than output lines) and the target's sections hold only lines";
    CV003: Error, "a number format the target's formats cannot write (trimmed zeros, width of the integer digits, no leading zero, a prefix of its own)";
    CV004: Error, "an output option no statement of the target sets (a lathe mapping, a chord tolerance, a step budget, multi-character substitutions)";
    CV005: Error, "a variable the target cannot declare: set by code, a prefix with `|`, `]` or a line break, two variables printing one label, or a label with no VAR name printed its own way";
    CV009: Error, "the IR cannot be written as RON (a postc bug)";
    VF001: Error, "the program is not G-code (HPGL, ShopBot, Heidenhain conversational, or text whose first blocks cannot be read): verify refuses it and says which families it reads";
    VF002: Error, "the program is binary data, a line holds NUL bytes, or the program cannot be read";
    VF003: Error, "a line longer than 64 KiB; it is skipped";
    VF004: Error, "a block cannot be read: a letter without a number, a number without a letter, a parameter or expression, an unclosed comment, or a second word of one letter";
    VF005: Warning, "a G code, letter or block verify does not know (it is ignored)";
    VF006: Error, "the post wraps an axis onto a rotary axis: verify does not compare rotary-wrapped programs";
    VF007: Error, "the post is a lathe post: verify compares milling programs only";
    VF008: Warning, "G92 coordinate offsets: positions after it are not compared";
    VF009: Warning, "`postc post --verify` with a post that split its output into parts: the parts are not verified";
    VF010: Error, "a cutting move off the toolpath (or an arc where the toolpath moves straight)";
    VF011: Error, "the program ends before cutting moves of the toolpath (truncated, or moves dropped)";
    VF012: Error, "a rapid move where the toolpath cuts";
    VF013: Error, "an arc turns the other way, lies in another plane, or has another centre than the toolpath's";
    VF014: Error, "a chord of a linearized arc lies farther from the arc than the chord tolerance";
    VF020: Error, "an arc's start and end radii differ by more than the controller accepts";
    VF021: Error, "an arc offset word (I, J or K) outside the active plane";
    VF022: Error, "an R arc with the wrong sign of R (over 180° needs a negative R)";
    VF023: Error, "an R arc that cannot be: a full circle, or R shorter than half the chord";
    VF024: Error, "a drilling cycle without its R and Z words";
    VF030: Error, "the numbers are in the other unit than G20/G21 says (inches in a G21 program or the reverse)";
    VF031: Error, "the program's G20/G21 contradicts the post's units";
    VF032: Warning, "the program moves before it says G20 or G21";
    VF033: Error, "a cut's feed differs from the toolpath's (after unit conversion)";
    VF034: Error, "a cutting move before any feed rate is set";
    VF035: Error, "a cut with the spindle (or jet) off";
    VF037: Error, "a rapid move the toolpath does not make goes below the toolpath's lowest rapid height into the material";
    VF038: Error, "a tool change (M6) with the tool down in the material (or below the safe height when the job gives no material)";
    VF040: Error, "a block number that does not increase";
    VF041: Error, "a block number over the post's (or the controller's) maximum";
    VF042: Error | Warning, "a comment character the controller refuses: `(` inside a comment, `%` or `;` on Fanuc/Haas, control characters, non-ASCII on Fanuc/Haas/grbl (warnings for the generic controller)";
}
