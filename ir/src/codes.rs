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
    /// An extra column of the section's table: its title, and its cell for each code.
    pub extra: Option<(&'static str, &'static [(&'static str, &'static str)])>,
}

/// The prefixes: where each group of codes comes from.
pub const PREFIXES: &[(&str, &str)] = &[
    ("PP", "Vectric `.pp` posts (`frontends/vectric`)"),
    ("JS", "CIMCO JavaScript posts (`frontends/cimco`)"),
    ("VC", "VcPost posts (`frontends/vcpost`)"),
    ("PT", "VcPost probe-cycle tables"),
    ("CP", "VcPost composites event files"),
    ("CL", "APT CL files (`readers/apt`)"),
    ("PX", "`postc postp` and its controllers (`postp/`)"),
    ("TP", "native toolpaths (`readers/native`)"),
    ("RT", "the runtime, while posting"),
    ("IO", "files and the command line"),
    ("IR", "posts written as IR"),
    ("CV", "`postc convert` (`backends/`)"),
    ("VF", "`postc verify`: findings in a G-code program against its toolpath (`verify/`, `docs/verify.md`)"),
    ("LN", "lints over a compiled post (`lint/`): mistakes that compile and only show on the machine"),
];

/// The sections of `docs/diagnostics.md`, in order.
pub const SECTIONS: &[Section] = &[
    Section { title: "Vectric posts (PP)", prefixes: &["PP"], intro: "", extra: None },
    Section { title: "CIMCO posts (JS)", prefixes: &["JS"], intro: "", extra: None },
    Section { title: "VcPost posts (VC)", prefixes: &["VC"], intro: "", extra: None },
    Section { title: "VcPost probe tables (PT)", prefixes: &["PT"], intro: "", extra: None },
    Section { title: "VcPost composites files (CP)", prefixes: &["CP"], intro: "", extra: None },
    Section { title: "APT CL files (CL)", prefixes: &["CL"], intro: "", extra: None },
    Section { title: "postp (PX)", prefixes: &["PX"], intro: "", extra: None },
    Section {
        title: "Runtime, files and command line (RT, TP, IO, IR)",
        prefixes: &["IO", "IR", "TP", "RT"],
        intro: "",
        extra: None,
    },
    Section { title: "Converting posts (CV)", prefixes: &["CV"], intro: "", extra: None },
    Section {
        title: "postc verify (VF)",
        prefixes: &["VF"],
        intro: "Findings of `postc verify` (`docs/verify.md`). Each names the program's\nline and column; those about a move also point at the toolpath move.",
        extra: None,
    },
    Section {
        title: "Lints (LN)",
        prefixes: &["LN"],
        intro: "`postc check` runs the lints of `lint/` (one rule per file in\n`lint/src/rules/`) on every post that compiles without errors, whatever\nits dialect; `--product cut2d|vcarve|aspire|cut3d|photovcarve` adds what\nthat Vectric product does not support. The last column is how many of the\n112 real Vectric posts of `../shared/corpus/vectric` each rule fires on\n(`cargo test --test suite lint_corpus -- --nocapture`, 2026-11-25), with\nexamples; the project's own posts lint clean.\n\n`postc check --fix FILE...` first applies the fixes that are certain and\nrewrites each post whole (a temporary file renamed over it; a Windows-1252\nfile keeps its other bytes): a section name after `begin` with exactly one\nknown section within two edits (`begin HEADR` becomes `begin HEADER`), and\na known label whose `]` is missing in an output string (`\"G0 [X\"` becomes\n`\"G0 [X]\"`). The language server offers the same fixes as quick fixes.",
        extra: Some((
            "real posts",
            &[
                ("LN001", "0"),
                ("LN002", "9 (Marlin posts that switch a router on and off)"),
                ("LN003", "17 (grbl, estlcam)"),
                ("LN004", "15 (grbl TC, Laguna, Haas: a Haas M6 retracts by itself, the others do not)"),
                ("LN005", "6 (Buildbotics: `(*.gcode)` with `FILE_EXTENSION = \"ngc\"`)"),
                ("LN006", "— (only with `--product`)"),
                ("LN007", "0"),
                ("LN008", "0"),
                ("LN009", "0"),
                ("LN010", "3 (inch posts with 3-decimal arc words, for grbl)"),
                ("LN011", "0"),
                (
                    "LN012",
                    "1 (Langmuir crossfire, 9999); the project's gcode_noarcs_mm, noarcs_wrap_x_mm and text_output_mm wrap on purpose (pinned by their goldens)",
                ),
                ("LN013", "— (VcPost; the project's 5 posts and the 8 `postp` controllers: 0)"),
                ("LN014", "3 (wrapped posts that keep arc sections: Snapmaker 4-axis, Carvera Wrap X2A, grbl rotary)"),
                ("LN015", "— (CIMCO; the project's 12 posts: 0)"),
                (
                    "LN016",
                    "— (VcPost; the project's 5 posts: 0; the 8 `postp` controllers: 0 after removing a dead `Function Two` it found in ACORNM and TORMM)",
                ),
            ],
        )),
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
    // The intro's first part, the prefix table, then the intro's sections.
    let (head, rest) = INTRO.split_once("\n## ").map_or((INTRO, ""), |(h, r)| (h, r));
    let mut out = String::from(head.trim_end());
    out.push_str("\n\n| prefix | from |\n|---|---|\n");
    for (prefix, from) in PREFIXES {
        let _ = writeln!(out, "| `{prefix}` | {from} |");
    }
    if !rest.is_empty() {
        let _ = write!(out, "\n## {}\n", rest.trim_end());
    }
    for section in SECTIONS {
        let _ = write!(out, "\n## {}\n\n", section.title);
        if !section.intro.is_empty() {
            let _ = write!(out, "{}\n\n", section.intro);
        }
        match section.extra {
            Some((title, _)) => {
                let _ = write!(out, "| code | severity | meaning | {title} |\n|---|---|---|---|\n");
            }
            None => out.push_str("| code | severity | meaning |\n|---|---|---|\n"),
        }
        let codes: Vec<&Code> = ALL.iter().filter(|c| section.prefixes.iter().any(|p| c.code.starts_with(p))).collect();
        for c in &codes {
            let _ = write!(out, "| {} | {} | {} |", c.code, severity_word(c), c.summary.replace('|', "\\|"));
            if let Some((_, cells)) = section.extra {
                let cell = cells.iter().find(|(code, _)| *code == c.code).map_or("", |(_, cell)| cell);
                let _ = write!(out, " {} |", cell.replace('|', "\\|"));
            }
            out.push('\n');
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
    /// A `VAR` line declares an output variable: `VAR NAME = [LABEL|A or
    /// C|PREFIX|FORMAT|MULTIPLIER]`. This one lacks a part postc needs: the name, the `=`, the
    /// brackets, or it has not 4 or 5 fields between `[` and `]`.
    PP001: Error, "malformed `VAR` line: no name, no `=`, no `[` or `]`, or not 4 or 5 fields between the brackets",
        example = "VAR X_POSITION = X|C|X|1.3",
        fix = "Write it like `VAR X_POSITION = [X|C|X|1.3]`: label, A or C, prefix, format, and an optional multiplier.";
    /// The word after `VAR` is not one of the variable names of the Vectric guide (X_POSITION,
    /// FEED_RATE, SPINDLE_SPEED, ...). When it is a global statement's name, the help says how to
    /// write the statement.
    PP002: Error, "unknown variable name after `VAR`",
        example = "VAR X_POS = [X|C|X|1.3]",
        fix = "Use a name from the guide's table of variables, such as `X_POSITION`.";
    /// The first field of a `VAR` (the label output lines use, `[X]`) is not a value postc knows,
    /// and the `VAR`'s name does not say which value it is either, so postc cannot tell what to
    /// print.
    PP003: Error, "the label of a `VAR` is not a value postc knows, and its name does not say which value it is",
        fix = "Use a standard label such as `X`, `F` or `S`, or a standard `VAR` name whose value the label then prints.";
    /// The second field of a `VAR` says when the value prints: `A` every time, `C` only when it
    /// changed since it last printed.
    PP004: Error, "the \"when output\" field of a `VAR` is not `A` (always) or `C` (on change)",
        example = "VAR FEED_RATE = [F|X|F|1.0]",
        fix = "Write `A` or `C`.";
    /// The fourth field of a `VAR` says how the number prints: optional flags `-`, `+`, `0`, `#`,
    /// then the width, then `.` or `,` as the decimal separator, then the number of decimals.
    PP005: Error, "bad value format in a `VAR` (flags `- + 0 #`, width, `.` or `,`, decimals)",
        example = "VAR X_POSITION = [X|C|X|1.x]",
        fix = "Write a format such as `1.3`, `02.0`, `+1,3` or `-#5.0`.";
    /// The fifth field of a `VAR`, when present, is a number the value is multiplied by before it
    /// prints (such as 0.01666 to turn mm/min into mm/s).
    PP006: Error, "bad multiplier in a `VAR`",
        example = "VAR FEED_RATE = [F|C|F|1.1|x60]",
        fix = "Write a plain number, like `0.01666` or `-1`, or leave the field out.";
    /// A quoted string (an output line, a statement's value or a script call) runs to the end of
    /// the line without its closing `"`.
    PP007: Error, "a quoted string has no closing quote",
        example = "begin HEADER\n\"G0 [X] [Y]",
        fix = "End the string with `\"`; to print a quote inside it, write `[34]`.";
    /// `[nn]` in an output string prints the byte with that number; a byte is 0 to 255.
    PP008: Error, "a `[nn]` character code is over 255",
        example = "begin HEADER\n\"[300]\"",
        fix = "Use a code from 0 to 255, like `[13]` for a carriage return or `[34]` for a quote.";
    /// A `[` in an output string starts a variable or a character code, and needs its `]`.
    PP009: Error, "a `[` in a string is never closed with `]`",
        example = "begin HEADER\n\"G1 [X [Y]\"",
        fix = "Close the variable with `]`, or write `[91]` to print a `[`.";
    /// A line `NAME = value` outside any section is a global statement, and this name is not one
    /// postc knows (POST_NAME, FILE_EXTENSION, UNITS, LINE_ENDING, the LINE_NUMBER_ statements,
    /// SUBSTITUTE, TAPE_SPLITTING, ...).
    PP010: Error, "unknown global statement (`NAME = value` outside a section)",
        example = "UNIT = \"MM\"",
        fix = "Correct the name; the help lists the statements postc reads.";
    /// A global statement has a value of the wrong kind or the wrong number of values.
    PP011: Error, "bad value for a global statement (wrong kind or number of values)",
        example = "LINE_NUMBER_START = \"ten\"",
        fix = "Write the value as the help's example shows.";
    /// Output lines belong to a section: postc only knows when to print a line that follows a
    /// `begin SECTION` line.
    PP012: Error, "an output line before the first `begin` section",
        example = "\"%\"\nbegin HEADER\n\"G90\"",
        fix = "Put a `begin SECTION` line (like `begin HEADER`) before the lines it outputs.";
    /// `begin` opens a section and needs its name.
    PP013: Error, "`begin` without a section name",
        example = "begin\n\"G90\"",
        fix = "Write, for example, `begin HEADER` or `begin FEED_MOVE`.";
    /// A `SCRIPT` block (Lua) runs to the end of the file without its `ENDSCRIPT` line.
    PP014: Error, "`SCRIPT` block without `ENDSCRIPT`",
        example = "SCRIPT\nfunction f() end",
        fix = "End the block with a line that says `ENDSCRIPT`.";
    /// A global statement's name stands alone on its line: it needs `=` and a value.
    PP015: Error, "a global statement without `=` and a value",
        example = "UNITS",
        fix = "Write it like the help's example, such as `UNITS = \"MM\"`.";
    /// `[LABEL]` in an output line names no known variable and no label declared with `VAR`, so
    /// it prints as written, brackets and all.
    PP016: Warning, "unknown `[LABEL]` in an output string: it prints as written",
        example = "begin HEADER\n\"G0 [XX]\"",
        fix = "Correct the label, declare it with `VAR`, or write `[91]` and `[93]` to print square brackets.";
    /// `begin NAME` names a section postc does not know, so nothing ever calls it: its lines are
    /// left out of the compiled post.
    PP017: Warning, "unknown section: its lines are kept out of the compiled post",
        example = "begin HEADERS\n\"G90\"",
        fix = "Use a section name of the Vectric guide (HEADER, FOOTER, TOOLCHANGE, RAPID_MOVE, FEED_MOVE, CW_ARC_MOVE, ...).";
    /// In a `.pp` file, only quoted output lines, statements, `VAR` lines and comments (starting
    /// with `+` or `|`) mean something; other text, or text after an output line's closing quote,
    /// is ignored.
    PP018: Warning, "text outside quotes (or after the closing quote) is ignored",
        example = "begin HEADER\n\"G90\" G21\nthis is a note",
        fix = "Put output text between double quotes, and start a comment with `+` or `|`.";
    /// `POST_BASE` names another post this one builds on, and that file cannot be read (it is not
    /// there, it is not a regular file such as a folder or a device, or it is over 16 MiB). The
    /// post compiles without it, so the base's sections, `VAR`s and statements are missing.
    PP019: Warning, "the `POST_BASE` file cannot be read: the post compiles without it",
        example = "POST_BASE = \"missing_base.pp\"",
        fix = "Put the base post next to this one, or correct its name.";
    /// Vectric posts can call Lua (`SCRIPT` blocks and script calls). postc keeps those lines but
    /// does not run Lua: when posting, the lines are skipped (the runtime reports RT003).
    PP020: Warning, "Lua script lines are kept but postc does not run them",
        fix = "Write what the script prints as output lines, or accept that it is skipped.";
    /// Arc words (I, J, K, R) print with fewer decimals than the positions. Arc words come from
    /// the exact geometry while positions are rounded, so the radius at the start and at the end
    /// of an arc may differ by more than a controller with a tight radius check accepts, and it
    /// rejects the arc.
    PP021: Warning, "arc words print fewer decimals than positions: a controller's radius check may reject arcs",
        example = "VAR X_POSITION = [X|C|X|1.4]\nVAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.2]",
        fix = "Print arc words with at least as many decimals as positions, or post with `--exact-arcs` to compute them from the printed points.";
    /// The same section is written twice; the later one replaces the earlier one, whose lines
    /// never print.
    PP022: Warning, "a section appears twice: the later one replaces the earlier one",
        example = "begin HEADER\n\"G90\"\nbegin HEADER\n\"G21\"",
        fix = "Merge the two sections into one.";
    /// A `VAR`, a label or a global statement is set twice; the later one wins.
    PP023: Warning, "a `VAR`, a label or a global statement appears twice: the later one wins",
        example = "UNITS = \"MM\"\nUNITS = \"INCHES\"",
        fix = "Delete the one that should not apply.";
    /// A section name has a blank inside it; postc reads it as the name without the blank.
    PP024: Warning, "stray blank inside a section name (`FIRST_CW _HELICAL_ARC_MOVE`)",
        example = "begin FIRST_CW _HELICAL_ARC_MOVE",
        fix = "Write the name without the blank.";
    /// A `VAR` has 3 fields: the prefix field is missing, and postc reads it as an empty prefix.
    PP025: Warning, "`VAR` with 3 fields: the prefix field is missing and taken as empty",
        example = "VAR X_POSITION = [X|C|1.3]",
        fix = "Write the prefix field, even empty: `[X|C||1.3]` or `[X|C|X|1.3]`.";
    /// A value format without `.` or `,` has no decimals, so the value prints as a whole number.
    PP026: Warning, "value format without a decimal separator: read as whole numbers",
        example = "VAR X_POSITION = [X|C|X|3]",
        fix = "Write the decimals after a separator, such as `1.3`, if the value needs them.";
    /// Without a `UNITS` statement the post writes numbers in the toolpath's own units, whatever
    /// the machine expects.
    PP027: Warning, "no `UNITS` statement: the output is written in the toolpath's own units",
        example = "POST_NAME = \"My router\"",
        fix = "Add `UNITS = \"MM\"` or `UNITS = \"INCHES\"`.";
    /// `SUBSTITUTE` lists pairs: each character followed by its replacement. With an odd count
    /// the last character has no replacement and is ignored.
    PP028: Warning, "`SUBSTITUTE` has an odd number of characters: the last one is ignored",
        example = "SUBSTITUTE = \"({)\"",
        fix = "Write each character followed by its replacement; write `[32]` for a blank.";
    /// A `VAR`'s label decides what it prints. Here the label prints another value than the
    /// `VAR`'s name says (or is not a standard label, and prints the name's value).
    PP029: Warning, "a `VAR`'s label prints another value than its name says",
        example = "VAR X_POSITION = [Y|C|X|1.3]",
        fix = "Use the usual label of the name (the help says which).";
    /// `POST_BASE` files chain: a base can have its own base. This chain leads back to a post
    /// already read, or is too deep, and the rest of it is ignored.
    PP030: Warning, "`POST_BASE` chain loops back or is too deep: the rest of the chain is ignored",
        fix = "Break the loop, or shorten the chain.";
    /// `ROTARY_WRAP_X` and `ROTARY_WRAP_Y` both wrap an axis around a cylinder; a post wraps one.
    /// Only the later one is used.
    PP031: Warning, "both `ROTARY_WRAP_X` and `ROTARY_WRAP_Y`: only the later one is used",
        example = "ROTARY_WRAP_X = \"-A\"\nROTARY_WRAP_Y = \"-A\"",
        fix = "Keep the one your machine's rotary axis needs.";
    /// postc's grammar could not read this line at all. This should not happen: every line should
    /// read or give a specific error.
    PP032: Error, "a line the grammar could not read at all (should not happen; report it)",
        fix = "Report the line to postc's authors; meanwhile, rewrite or remove it.";
    /// A line of a section made only of variables, without quotes (`[F]`). The guides say every
    /// output line is quoted, but VCarve prints such a line as if it were (the ShopSabre post's
    /// HEADER ends with a bare `[F]`, and the programs VCarve wrote with it carry `F62.5` there),
    /// and so does postc. Other text outside quotes is ignored (PP018).
    PP033: Warning, "a line of variables without quotes: printed as if quoted, as VCarve prints it",
        example = "begin HEADER\n\"G90\"\n[F]",
        fix = "Put the line between double quotes: `\"[F]\"`.";
    /// This character cannot start anything in JavaScript at this place.
    JS001: Error, "a character that JavaScript does not allow here (`#`, `@`, a stray `\\`)",
        example = "var x = 1 # comment",
        fix = "Remove it; comments start with `//` or `/*`.";
    /// A string in quotes (or a template literal) reaches the end of the line without its closing
    /// quote.
    JS002: Error, "text in quotes (or a template literal) is not closed before the end of the line",
        example = "writeBlock(\"G0 X\" + x);\nwriteln(\"M30);",
        fix = "Close the string on the same line.";
    /// An escape sequence in a string is incomplete or not allowed: `\x` needs two hex digits,
    /// `\u` four, and octal escapes are not allowed.
    JS003: Error, "a bad escape sequence in text (`\\x4`, `\\u12`, octal `\\12`)",
        example = "var s = \"\\x4\";",
        fix = "Write the whole escape (`\\x41`, `\\u0041`) or the character itself.";
    /// A `/*` comment runs to the end of the file without its `*/`.
    JS004: Error, "a `/* ... */` comment is not closed",
        example = "/* header\nfunction onOpen() {}",
        fix = "Close the comment with `*/`.";
    /// A number is malformed: a prefix without digits, an exponent without digits, or letters
    /// straight after the digits.
    JS005: Error, "a malformed number (`0x`, `1e`, `3mm`)",
        example = "var x = 3mm;",
        fix = "Write the number alone (`3`), and a unit, if any, in a comment or a string.";
    /// A regular expression literal (`/.../`) reaches the end of the line without its closing
    /// `/`.
    JS006: Error, "a regular expression is not closed before the end of the line",
        example = "var re = /abc;",
        fix = "Close the regular expression with `/`.";
    /// The parser met a token where JavaScript does not allow one.
    JS007: Error, "syntax error: a token where it cannot be",
        example = "var = 3;",
        fix = "Correct the statement as the message says.";
    /// Two statements stand on one line with nothing between them; JavaScript needs a `;` (or a
    /// line break) there.
    JS008: Error, "two statements on one line without `;` between them",
        example = "var a = 1 var b = 2;",
        fix = "Put `;` between the statements.";
    /// The file ends in the middle of a statement or expression.
    JS009: Error, "the file ends in the middle of a statement or expression",
        example = "var x = 1 +",
        fix = "Complete the statement, or remove it.";
    /// A `{`, `(` or `[` is never closed.
    JS010: Error, "a `{`, `(` or `[` that is never closed",
        example = "function onOpen() {\n  writeln(\"%\");",
        fix = "Add the missing `}`, `)` or `]`; the label shows where the opening one is.";
    /// A `}`, `)` or `]` closes nothing.
    JS011: Error, "a `}`, `)` or `]` with nothing to close",
        example = "var a = 1;\n}",
        fix = "Remove it, or add the opening one it belongs to.";
    /// Only a variable or a property can be assigned to, or incremented with `++` / `--`.
    JS012: Error, "an assignment or `++`/`--` to something that is not a variable or property",
        example = "f() = 3;",
        fix = "Assign to a variable or a property.";
    /// Expressions or blocks are nested deeper than postc processes.
    JS013: Error, "code nested too deeply to process",
        fix = "Split the code into smaller functions or use intermediate variables.";
    /// `return` is only allowed inside a function.
    JS014: Error, "`return` outside a function",
        example = "return;",
        fix = "Remove it, or move the code into a function.";
    /// `break` and `continue` need a loop around them (`break` also works in a `switch`;
    /// `continue` does not).
    JS015: Error, "`break` or `continue` outside a loop (or `continue` in a `switch` only)",
        example = "function f() { break; }",
        fix = "Remove it, or restructure the code with an `if`.";
    /// A `switch` has more than one `default` label.
    JS016: Error, "more than one `default` in a `switch`",
        example = "switch (x) { default: a(); default: b(); }",
        fix = "Keep one `default`.";
    /// A `try` block needs a `catch` or a `finally` block after it.
    JS017: Error, "`try` without `catch` or `finally`",
        example = "try { f(); }",
        fix = "Add `catch (e) { ... }` or `finally { ... }`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there postc reads `let` and `const` as `var`
    /// (docs/fusion.md, "Language").
    JS018: Error, "`let` / `const` declarations",
        example = "let x = 1;",
        fix = "Declare the variable with `var`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there arrow functions are read, their `this`
    /// that of the function around them (docs/fusion.md, "Language").
    JS019: Error, "arrow functions (`=>`)",
        example = "var f = (x) => x * 2;",
        fix = "Write `function (x) { ... }`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS020: Error, "classes (`class`)",
        example = "class Tool {}",
        fix = "Write a constructor function and add methods to its `prototype`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there template literals are read, each
    /// substitution joined as JavaScript's `String(x)` gives it; a tagged template (`` tag`...` ``) is refused
    /// in every dialect.
    JS021: Error, "template literals (`` `...` ``)",
        example = "var s = `X${x}`;",
        fix = "Join the text with `+`: `\"X\" + x`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS022: Error, "getters and setters (`get x() {}`)",
        example = "var o = { get x() { return 1; } };",
        fix = "Use an ordinary property, or a function that returns the value.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS023: Error, "the `with` statement",
        example = "with (tool) { writeln(number); }",
        fix = "Write the object name in front of each property.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS024: Error, "labels (`outer:`, `break outer`)",
        example = "outer: for (var i = 0; i < 3; i++) { break outer; }",
        fix = "Leave the outer loop with a flag variable instead.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS025: Error, "the `delete` operator",
        example = "delete o.x;",
        fix = "Set the property to `undefined` instead.";
    /// `instanceof` is ES5, but no CNC-Calc post postc has seen uses it, and postc reads CIMCO posts
    /// without it, refusing it rather than guessing. A Fusion `.cps` post may use it: postc answers
    /// it from the prototype chain.
    JS027: Error, "the `instanceof` operator",
        example = "if (o instanceof Array) {}",
        fix = "Test a property of the object, or use `typeof`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS028: Error, "generator functions (`function*`) and `yield`",
        example = "function* f() { yield 1; }",
        fix = "Return an array of the values instead.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS029: Error, "`async` functions and `await`",
        example = "async function f() { await g(); }",
        fix = "Call the function directly; posts run synchronously.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS030: Error, "spread and rest syntax (`...`)",
        example = "f(...list);",
        fix = "Pass the values one by one, or read them from `arguments`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there array and object patterns are read in
    /// `var`, in assignments and in parameters, with default values (docs/fusion.md, "Language").
    JS031: Error, "destructuring (`var {a, b} = obj`)",
        example = "var {a, b} = o;",
        fix = "Read each property on its own: `var a = o.a;`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there default parameter values are read.
    JS032: Error, "default parameter values (`function f(a = 1)`)",
        example = "function f(a = 1) {}",
        fix = "Set the default in the body: `if (a === undefined) { a = 1; }`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there shorthand properties (`{ x }`) are read;
    /// methods and computed keys are refused in every dialect.
    JS033: Error, "shorthand properties, methods and computed keys in object literals",
        example = "var o = { x, f() {}, [key]: 1 };",
        fix = "Write `x: x`, `f: function () { ... }`, and set computed keys after creating the object: `o[key] = 1;`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS034: Error, "`for ... of` loops",
        example = "for (var x of list) {}",
        fix = "Loop over the indices: `for (var i = 0; i < list.length; i++)`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS035: Error, "the exponent operator (`**`)",
        example = "var a = b ** 2;",
        fix = "Use `Math.pow(b, 2)`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS036: Error, "optional chaining (`?.`), `??`, and logical assignment (`&&=`, `||=`, `??=`)",
        example = "var a = o?.x ?? 0;",
        fix = "Test the object first (`o && o.x`), write `(a !== undefined && a !== null) ? a : b` for `??`, and write logical assignments out: `a = a || b;`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS037: Error, "modules (`import`, `export`)",
        example = "import { f } from \"./lib.js\";",
        fix = "A post is a single file; remove the line.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS038: Error, "the `void` operator",
        example = "var u = void 0;",
        fix = "Use `undefined`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS039: Error, "the `debugger` statement",
        example = "debugger;",
        fix = "Remove the statement.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS040: Error, "regular expression flags other than `g`, `i`, `m`",
        example = "var re = /x/u;",
        fix = "Use only the flags `g`, `i` and `m`.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine in sloppy mode: there `0b101`, `0o17` and the
    /// legacy octal `010` (8; `08` and `09` are decimal) are read; BigInt is refused in every dialect.
    JS041: Error, "number forms outside ES5: `0b101`, `0o17`, `10n`, legacy octal `010`",
        example = "var a = 0b101, b = 010;",
        fix = "Write the number in decimal or hexadecimal (`0x1F`); remove a leading zero.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    ///
    /// Fusion `.cps` posts run on Autodesk's modern engine: there a trailing comma is allowed.
    JS042: Error, "a comma after the last argument or parameter",
        example = "f(a, b,);",
        fix = "Remove the comma.";
    /// CNC-Calc posts are written in the JavaScript of 2009 (ES5), and postc reads that language.
    /// This construct is not part of it, so postc refuses the post rather than guess.
    JS043: Error, "empty slots in an array literal (`[1, , 2]`)",
        example = "var a = [1, , 2];",
        fix = "Write `undefined` in the empty slot.";
    /// E4X (ECMAScript for XML) let old JavaScript engines read and write XML as values:
    /// `xml..c` (every `c` below), `e.@ss::Type` (an attribute in a namespace), `default xml
    /// namespace = "..."`. Some setup-sheet posts of the HSMWorks years write spreadsheets with it.
    /// It is not part of ES5 and no engine of today runs it, so postc refuses the post at the
    /// construct.
    JS044: Error, "E4X, ECMAScript for XML (`xml..name`, `node.@attribute`)",
        example = "var rows = xml..Row;",
        fix = "Build the XML as text with `+` and write it with `writeln`.";
    /// postc turns a CIMCO post's functions into a script for its script engine; this part of the
    /// post could not be translated. The post is valid JavaScript: this is a gap in postc.
    JS100: Error, "the post could not be turned into a script (a construct the Rhai translation lacks); report it",
        fix = "Report it to postc's authors with the post; meanwhile, rewriting the construct in plainer JavaScript may avoid it.";
    /// `createFormat`, `createVariable`, `globals` and `PostInfo` take properties postc knows;
    /// this one is not among them and has no effect.
    JS101: Warning, "a property postc does not know in `createFormat`/`createVariable`/`globals`/`PostInfo`; it is ignored",
        example = "var xyzFormat = createFormat({decimals: 3, colour: 1});",
        fix = "Correct the property's name, or remove it.";
    /// The post reads a name it never defines, and postc's host (the functions and variables
    /// CNC-Calc provides) does not provide it either. Reading it while posting is a JavaScript
    /// error.
    JS102: Warning, "a name the post never defines and postc's host does not provide",
        example = "function onOpen() { writeln(toolNumbr); }",
        fix = "Correct the name, or define it with `var`.";
    /// The post's `decimalMark` setting is the character between the whole part and the decimals;
    /// postc writes `.` or `,`, and `.` for any other mark.
    JS103: Warning, "`decimalMark` is neither `.` nor `,`",
        example = "var decimalMark = \";\";",
        fix = "Use `\".\"` or `\",\"`.";
    /// A number format prints at most 15 decimals (a double holds about 15 significant digits).
    JS104: Warning, "a format asks for more than 15 decimals",
        example = "var f = createFormat({decimals: 20});",
        fix = "Ask for 15 decimals or fewer.";
    /// postc calls `onLinear` for every feed move; a post without it prints nothing for them.
    JS105: Warning, "the post has no `onLinear`, so moves print nothing",
        example = "function onRapid(x, y, z) { writeBlock(\"G0\"); }",
        fix = "Define `function onLinear(x, y, z, feed) { ... }`.";
    /// The post assigns a value to a name that a `function` declaration defines. postc does not
    /// let a post replace a function this way.
    JS106: Error, "the post assigns to the name of a function",
        example = "function onOpen() {}\nonOpen = null;",
        fix = "Keep the function in a variable of its own: `var handler = onOpen;`.";
    /// A section post (postc's extension of CNC-Calc for posts driven by the kind of each move,
    /// docs/cimco.md) holds `var postcOptions = {...}`, variables made by
    /// `createVariable({prefix, label, modal}, createFormat({...}))` of constants, and one
    /// function per section that returns its lines; this construct is none of those.
    JS107: Error, "a section post holds something other than its options, its labelled variables and functions that return a section's lines",
        example = "var X = createVariable({prefix: \"X\", label: \"X\"}, createFormat({decimals: 3}));\nfunction FEED_MOVE() { if (X) { return \"\"; } return \"G1\" + X + \"\\n\"; }",
        fix = "Write the section as `return \"G1\" + X + \"\\n\";`, or write a CNC-Calc post with `onLinear` and friends.";
    /// postc runs a post's regular expressions in time linear in the text, with JavaScript's
    /// meaning (docs/cimco.md, "Regular expressions"). This pattern is not one it runs: it does
    /// not read as a JavaScript pattern, or it uses a backreference (`\1`) or lookaround (`(?=`,
    /// `(?!`, `(?<=`, `(?<!`), which have no linear-time form. The message names the construct;
    /// the post is refused when it is compiled.
    JS108: Error, "a regular expression postc cannot run: its pattern does not read, or uses a backreference or lookaround (no linear-time form)",
        example = "function clean(t) { return t.replace(/(a)\\1/g, \"a\"); }",
        fix = "Write the pattern without backreferences and lookaround (match the text and test it in code), or correct its syntax.";
    /// postc runs a Fusion `.cps` post whole in its engine, with Autodesk's host API written from
    /// Autodesk's public declarations (docs/fusion.md). This post uses a construct of JavaScript or
    /// a host function postc does not run yet; the message names it at its line, and the post is
    /// refused rather than run with a guess.
    JS109: Error, "a Fusion post uses a construct or host API postc does not run",
        example = "function onOpen() { getRegistryString(\"a\", \"b\"); }",
        fix = "Report it to postc's authors with the post; meanwhile, rewriting that part of the post in plainer JavaScript may avoid it.";
    /// A Fusion post calls a function of Autodesk's host that postc defines but does not run yet
    /// (records, cycle points, extra files, `include`, the tool renderer). The post runs; if a job
    /// takes it to this call, the post stops there with an error naming the function (RT036) and
    /// writes nothing.
    JS110: Warning, "a Fusion post calls host API postc does not run yet",
        example = "function onClose() { if (false) { redirectToFile(\"setup.txt\"); } }",
        fix = "Nothing to do if the job never reaches the call; otherwise report it to postc's authors with the post.";
    /// A Fusion post calls `include("name")` at its top level, and the file `name` beside the post
    /// cannot be read (it is not there, or it is not readable), or includes nest more than 8 files
    /// deep. Fusion's engine runs the included file where the call is: without it the post is
    /// incomplete, so it is refused.
    JS111: Error, "a Fusion post includes a file that cannot be read",
        example = "include(\"missing-common.js\");\nfunction onOpen() {}",
        fix = "Put the included file beside the post, under the name the post gives it.";
    /// The line does not read as VcPost: a word or symbol stands where the language allows none.
    /// The help, when there is one, says what was expected.
    VC001: Error, "a line VcPost cannot read (unexpected word or symbol)",
        example = "Sub Start\n  Out \"G90\" \"G21\"\nEnd Sub",
        fix = "Correct the line as the message says.";
    /// A string runs to the end of the line without its closing `"`.
    VC002: Error, "a string has no closing quote",
        example = "Sub Start\n  Out \"G90\nEnd Sub",
        fix = "Close the string; write `\"\"` for a quote inside it.";
    /// A character that means nothing in VcPost, or a malformed `[name]`.
    VC003: Error, "a character that means nothing in VcPost (or a bad `[name]`)",
        example = "Sub Start\n  X = 1 $ 2\nEnd Sub",
        fix = "Remove the character.";
    /// postc limits the size of what it reads so that a broken or hostile post cannot exhaust
    /// memory or time: line length, nesting of parentheses, blocks and expressions, and the
    /// number of variables.
    VC004: Error, "a line too long, parentheses, blocks or expressions nested too deeply, or too many variables",
        fix = "Split the line or calculation over several lines with intermediate variables, or move inner blocks into Subs of their own.";
    /// A `Sub` or `Function` runs to the end of the file without its `End Sub` / `End Function`.
    VC005: Error, "a `Sub` or `Function` has no `End Sub` / `End Function`",
        example = "Sub Start\n  Out \"G90\"",
        fix = "Add `End Sub` (or `End Function`) where it ends.";
    /// An `If ... Then` block has no `End If`.
    VC006: Error, "an `If` block has no `End If`",
        example = "Sub Start\n  If X > 0 Then\n    Out \"A\"\nEnd Sub",
        fix = "Add `End If` where the block ends.";
    /// A `For` loop has no `Next`.
    VC007: Error, "a `For` has no `Next`",
        example = "Sub Start\n  For I = 1 To 3\n    Out \"A\"\nEnd Sub",
        fix = "Add `Next` where the loop ends.";
    /// A `While` loop has no `Wend`, or a `Do` loop has no `Loop`.
    VC008: Error, "a `While` has no `Wend`, or a `Do` has no `Loop`",
        example = "Sub Start\n  Do\n    Out \"A\"\nEnd Sub",
        fix = "Add `Wend` or `Loop` where the loop ends.";
    /// A `Select Case` block has no `End Select`.
    VC009: Error, "a `Select Case` has no `End Select`",
        example = "Sub Start\n  Select Case X\n    Case 1\n      Out \"A\"\nEnd Sub",
        fix = "Add `End Select` where the block ends.";
    /// A line closes a block that is not open: `End If` without `If`, `Next` without `For`, and
    /// so on.
    VC010: Error, "a closing line without its opening (`End If` without `If`, `Next` without `For`, ...)",
        example = "Sub Start\n  Next\nEnd Sub",
        fix = "Remove the line, or add the line that opens the block above it.";
    /// A part of a block is in the wrong place: `Else` twice, `ElseIf` after `Else`, `Case` after
    /// `Case Else`, code between `Select Case` and the first `Case`, `Next J` closing `For I`, or
    /// a `Sub` inside a block.
    VC011: Error, "a block part in the wrong place (`Else` twice, `Case` after `Case Else`, code before the first `Case`, `Next J` closing `For I`, a `Sub` inside a block)",
        example = "Sub Start\n  If X > 0 Then\n  Else\n  Else\n  End If\nEnd Sub",
        fix = "Reorder the parts as the help says (every `ElseIf` before the `Else`, `Case Else` last).";
    /// A keyword comment (`' #Init`, `' #Probe`, ...) says what kind of routine a Sub is; a Sub
    /// can be only one kind.
    VC012: Error, "two different `#` keywords in one Sub",
        example = "Sub Start\n  ' #Init\n  ' #End\nEnd Sub",
        fix = "Split it into two Subs.";
    /// A probe-cycle Sub takes at most 16 parameters: the probe table has 16 parameter columns.
    VC013: Error, "more than 16 parameters in one Sub",
        fix = "Move common parameters to the #Approach Sub.";
    /// A parameter in a keyword comment is named like a keyword, a built-in function, a type name
    /// or `N`.
    VC014: Error, "a reserved name (keyword, built-in function, type name, `N`) used as a parameter",
        fix = "Choose another name, for example with a prefix: `P_Name`.";
    /// A parameter name starts with a letter and holds only letters, digits and `_`; `!` in front
    /// marks it mandatory.
    VC015: Error, "a parameter name that is not a valid name",
        fix = "Rename the parameter.";
    /// A keyword comment describes the Sub it is in; outside every Sub it is ignored.
    VC016: Warning, "a keyword comment outside any Sub (it is ignored)",
        example = "' #Init\nSub Start\nEnd Sub",
        fix = "Move the comment inside the Sub it describes, after the `Sub` line.";
    /// A comment starts with `#` but the word is not a VcPost keyword (#Init #End #Rapid #Move
    /// #Approach #Retract #Cycle #Save #Primer #Option #Probe) or tip (#C1 #C2 #N1 #N2 #S1 #S2).
    VC017: Warning, "an unknown `#` keyword in a comment",
        example = "Sub Start\n  ' #Inti\nEnd Sub",
        fix = "Correct the keyword (the help suggests the close one).";
    /// Only one Sub of a post may carry `#Init`, `#End`, `#Rapid`, `#Move`, `#Approach`,
    /// `#Retract` or `#Save`: the runtime calls that one.
    VC018: Error, "a keyword that only one Sub may carry (`#Init #End #Rapid #Move #Approach #Retract #Save`) on several",
        fix = "Keep the keyword on one Sub.";
    /// A parameter is listed twice in one Sub's keyword comment.
    VC019: Warning, "a parameter listed twice in one Sub",
        fix = "Remove the second one.";
    /// Registers have a fixed set of properties (Prefix, Format, DecimalPoint, Modal, ...); this
    /// is not one of them.
    VC020: Error, "an unknown register property",
        example = "X.Fromat = \"5.3\"",
        fix = "Correct the property's name (the help suggests the close one).";
    /// A register property is set to a value it cannot take.
    VC021: Error, "a register property set to a value it cannot take",
        fix = "Use a value of the kind the message names.";
    /// Register properties are fixed when the post is compiled; they are set at the top of the
    /// file, outside every Sub.
    VC022: Error, "a register property set inside a Sub",
        example = "Sub Start\n  X.Format = \"5.3\"\nEnd Sub",
        fix = "Set register properties at the top of the file, outside every Sub.";
    /// The post calls a function that is neither a VcPost built-in nor a `Function` of the post.
    VC023: Error, "an unknown function",
        example = "Sub Start\n  Out Fromat(X)\nEnd Sub",
        fix = "Correct the name (the help lists the available functions).";
    /// A function or Sub is called with more or fewer arguments than it takes.
    VC024: Error, "a function or Sub called with the wrong number of arguments",
        example = "Sub Start\n  Out UCase(\"a\", \"b\")\nEnd Sub",
        fix = "Pass the number of arguments it takes.";
    /// The post calls a Sub it does not define.
    VC025: Error, "a call of a Sub that does not exist",
        example = "Sub Start\n  Call Header\nEnd Sub",
        fix = "Define it with `Sub Name` ... `End Sub`, or correct the name.";
    /// A Sub or Function is defined twice, or is named like a built-in function.
    VC026: Error, "a Sub or Function defined twice, or named like a built-in function",
        example = "Sub Start\nEnd Sub\nSub Start\nEnd Sub",
        fix = "Rename or remove one of them.";
    /// Only variables and registers can be assigned to; this is a Sub, a built-in function, a
    /// `Const` or `N`.
    VC027: Error, "an assignment to something that is not a variable (a Sub, a built-in, a `Const`, `N`)",
        fix = "Assign to a variable instead.";
    /// `Exit For`, `Exit Do`, `Exit Sub` and `Exit Function` leave the block they name, and must
    /// be inside one.
    VC028: Error, "`Exit For`/`Exit Do`/`Exit Sub`/`Exit Function` outside its block, or out of another kind of loop",
        example = "Sub Start\n  Exit For\nEnd Sub",
        fix = "Remove it, or use the `Exit` that matches the block it is in.";
    /// Register properties are settings for printing and are not read in expressions; `.Previous`
    /// (the value a register had before its last assignment) is the only one that can be, and
    /// only of a register.
    VC029: Error, "a property other than `.Previous` read in an expression, or `.Previous` of a local",
        fix = "Remove the read, or keep the value in a variable of its own.";
    /// A variable is read but never set anywhere, and it is not one the runtime sets: it is
    /// always empty.
    VC030: Warning, "a variable read but never set anywhere, and not one the runtime sets",
        example = "Sub Start\n  Out \"T\" & Tool_Numbr\nEnd Sub",
        fix = "Assign it (`Name = ...`), correct the name, or declare it with `Dim Name` if the runtime sets it.";
    /// A Sub that is called for an APT word or a composites event gets its values as registers
    /// and variables, not as parameters.
    VC031: Error, "a Sub called for an APT word or a composites event that takes parameters",
        fix = "Remove the parameters; read the values from the registers (X, Y, Z, F, ...).";
    /// The post uses a BASIC feature postc does not support: arrays, `Exp`, an unknown `As` type,
    /// and the like.
    VC032: Error, "a BASIC feature postc does not support (arrays, `Exp`, an unknown `As` type, ...)",
        example = "Sub Start\n  Dim P(3)\nEnd Sub",
        fix = "Rewrite it without the feature (use separate variables `P1`, `P2`, ... instead of an array).";
    /// `<Name>` in an `Out` string prints a register or variable; this name is a keyword, which
    /// cannot be a register, so it prints as text.
    VC033: Warning, "`<Name>` in an `Out` string names a keyword; it prints as text",
        example = "Sub Start\n  Out \"<If>\"\nEnd Sub",
        fix = "Remove the brackets, or name a register.";
    /// A name is declared twice, or a local variable hides a register of the same name.
    VC034: Warning, "a name declared twice, or a local hiding a register",
        example = "Dim A\nDim A",
        fix = "Remove the second declaration, or rename the local.";
    /// postc passes every argument by value: changes the Sub makes to a `ByRef` parameter are not
    /// seen by the caller.
    VC035: Warning, "a `ByRef` parameter: postc passes every argument by value",
        example = "Sub Twice(ByRef V)\n  V = V * 2\nEnd Sub",
        fix = "Use a global variable to hand back a value.";
    /// A Sub is used as a value (in an expression), or a variable is called like a Sub.
    VC036: Error, "a Sub used as a value, or a variable called like a Sub",
        example = "Sub Header\nEnd Sub\nSub Start\n  X = Header\nEnd Sub",
        fix = "Call a Sub on a line of its own, or make it a Function.";
    /// `Option` lines (`Option Explicit`) change nothing in postc and are ignored.
    VC037: Warning, "an `Option ...` line (`Option Explicit`): ignored",
        example = "Option Explicit",
        fix = "Remove the line, or leave it.";
    /// `<Name` in an `Out` string starts a register interpolation and needs its `>`: here the
    /// string ends first, or another `<` comes before it.
    VC038: Error, "`<Name` in an `Out` string is never closed with `>` (at the end of the string, or another `<` before it)",
        example = "Sub Start\n  Out \"G0 <X\"\nEnd Sub",
        fix = "Write `<X>` to print the register, or move the `<` out of the template.";
    /// A probe table row is one line of CSV cells; this one does not split into cells: a quote is
    /// not closed, or text follows a closing quote.
    PT001: Error, "a row that does not split into cells (a quote not closed, text after a closing quote)",
        example = "Probe,\"X=1",
        fix = "Close the quote; write `\"\"` for a quote inside a quoted value.";
    /// The first cell of a row names a Sub of the post; this one names none.
    PT002: Error, "a row names no Sub of the post",
        fix = "Correct the name (the help lists the post's probe-cycle Subs).";
    /// The row names a Sub that has no probe-cycle keyword (#Init, #Rapid, #Move, #Approach,
    /// #Cycle, #Save, #Retract, #End), so it cannot be a row of the table.
    PT003: Error, "a row names a Sub that is not a probe-cycle Sub (no #Init ... #Save keyword)",
        fix = "Name a probe-cycle Sub, or add the keyword comment to the Sub.";
    /// Values are given by position first, then as `NAME=VALUE`; a positional value after a named
    /// one has no position.
    PT004: Error, "a positional value after a named one",
        fix = "Give values by position first, then as NAME=VALUE.";
    /// The row gives more values than the Sub has parameters.
    PT005: Error, "more values than the Sub has parameters",
        fix = "Remove the extra values.";
    /// `NAME=` names no parameter of the row's Sub.
    PT006: Error, "`NAME=` names no parameter of the Sub",
        fix = "Correct the name (the help lists the Sub's parameters).";
    /// A parameter is given twice in one row.
    PT007: Error, "a parameter given twice",
        fix = "Keep one value.";
    /// A mandatory parameter (`!` in the keyword comment) has no value where its Sub is called. A
    /// feature without an Approach row is an error when the #Approach Sub has mandatory
    /// parameters.
    PT008: Error, "a mandatory parameter without a value",
        fix = "Give the value, or the Approach row.";
    /// A bare value in a row is not a number; text goes in quotes.
    PT009: Error, "a bare value that is not a number",
        fix = "Write a number, or quote the text.";
    /// The #Init row starts the table; it must be the first row.
    PT010: Error, "an #Init row that is not the first row",
        fix = "Move it first.";
    /// The #End row ends the table; it must be the last row.
    PT011: Error, "an #End row that is not the last row",
        fix = "Move it last.";
    /// An #Approach row prepares a cycle; a #Cycle row must follow it.
    PT012: Error, "an #Approach row not followed by a #Cycle row",
        fix = "Add the #Cycle row after it.";
    /// A #Save row saves a cycle's result; it must come right after a #Cycle row.
    PT013: Error, "a #Save row not right after a #Cycle row",
        fix = "Move it right after the #Cycle row.";
    /// A #Retract row ends a feature; it must come after a #Cycle or #Save row.
    PT014: Error, "a #Retract row not after a #Cycle or #Save row",
        fix = "Move it after the feature's #Cycle or #Save row.";
    /// The table has no rows, so the runtime calls only the #Init and #End Subs.
    PT015: Warning, "a table without rows",
        fix = "Add rows; `postc probe-table POST` prints a template with one row per probe-cycle Sub.";
    /// `postc probe-table` prints a row per probe-cycle Sub, and the post has none (no keyword
    /// comments).
    PT016: Error, "`postc probe-table` on a post with no probe-cycle Subs (no keyword comments)",
        fix = "Add keyword comments (`' #Cycle`, ...) to the post's probe-cycle Subs.";
    /// A line of a composites event file must be a call of the file's kind. This one has a syntax
    /// error, names an unknown routine or variable, misses a variable its routine carries, or has
    /// a value of the wrong type.
    CP001: Error, "a line that is not a call of the file's kind (syntax, unknown routine or variable, a missing variable, a wrong type)",
        fix = "Correct the call; each call carries every variable Vericut's application notes list for its routine (docs/vcpost.md has the list).";
    /// A composites event file starts with its `VcpFile` header line.
    CP002: Error, "the first line is not the `VcpFile` header",
        fix = "Add the header the file's kind needs as the first line.";
    /// The calls of a composites event file follow a sequence (Vericut's post-processor notes); this call is not
    /// allowed at this place in it.
    CP003: Error, "a call the sequence does not allow here",
        fix = "Reorder the calls; docs/vcpost.md has the sequences Vericut's application notes allow.";
    /// The file ends before its sequence does (a call the sequence needs is missing at the end).
    CP004: Error, "the file ends before its sequence does",
        fix = "Add the missing calls.";
    /// The file (or `--primer`) names an option, probe or primer Sub the post does not have.
    CP005: Error, "an option, probe or `--primer` Sub the post does not have",
        fix = "Correct the name, or add the Sub to the post.";
    /// A value is outside what Vericut's post-processor notes allow: `LinkType`, `Rotation` other than -1, 0 or +1,
    /// `TowNum` below 0, or a list longer than 64.
    CP006: Error, "a value the seed does not allow (`LinkType`, `Rotation` other than -1, 0, +1; `TowNum` < 0; a list longer than 64)",
        fix = "Use an allowed value.";
    /// An option, probe or primer Sub is called, but it does not carry its `#Option`, `#Probe` or
    /// `#Primer` keyword, so Vericut would not offer it.
    CP007: Warning, "an option, probe or primer Sub without its `#Option`/`#Probe`/`#Primer` keyword",
        fix = "Add `' #Option` (or `#Probe`, `#Primer`) after its Sub line.";
    /// `AddCutA`, `AddCutB`, `AddCutI` and `AddCutJ` describe one cut and disagree with each
    /// other.
    CP008: Warning, "`AddCutA`, `AddCutB`, `AddCutI`, `AddCutJ` that disagree",
        fix = "Check the values the CAM system wrote.";
    /// A `getNthLength` list gives one number per tow; its length is not `TowsInPacket`. Missing
    /// tows read 0.
    CP009: Warning, "a `getNthLength` list whose length is not `TowsInPacket`",
        fix = "Give one number per tow, tow 0 first.";
    /// The composites event file cannot be read, or is not UTF-8 text.
    CP010: Error, "the file cannot be read, or is not UTF-8 text",
        fix = "Check the path, or save the file as UTF-8.";
    /// postc reads CL data as text: APT CL records such as `GOTO/1.5,2,0`, one per line. This
    /// file is binary (such as a binary CLSF).
    CL001: Error, "binary file, not CL text",
        fix = "Export the toolpath from the CAM system as a text CL file (NX: CLSF, Creo: Pro/CLfile ASCII, NCL: APT source `.as`) and post that file.";
    /// The file is an APT part program: it defines geometry (`PL1=PLANE/...`, `C1=CIRCLE/...`)
    /// and describes motion against it (`GO/TO,...`). CL data lists the tool positions an APT
    /// processor computed from it.
    CL002: Error, "APT part program, not CL data",
        example = "PL1=PLANE/0,0,1,0\nGO/TO,PL1",
        fix = "Run the part program through an APT processor (APT360, NCL, ...) and post the CL file it writes.";
    /// A record cannot be read as a CL record; it is skipped.
    CL003: Error, "syntax error in a record; the record is skipped",
        example = "GOTO/1,2,,3",
        fix = "Correct the record as the message and help say.";
    /// A record postc knows has arguments of the wrong number or kind; it is skipped.
    CL004: Error, "a known record with wrong arguments; skipped",
        example = "SPINDL/RPM",
        fix = "Give the record the arguments the help shows.";
    /// The record's word is not a CL or post-processor word postc knows; the record is skipped.
    CL005: Warning, "unknown word; skipped",
        example = "FOOBAR/1",
        fix = "If a post needs this word, tell postc's maintainers which CAM system writes it.";
    /// Two values stand side by side without a comma; they are read as two values.
    CL006: Warning, "two values with no comma between them",
        example = "GOTO/1 2,3",
        fix = "Put a comma between them.";
    /// A line of numbers continues the record above, whose line does not end with `$`. postc
    /// joins them.
    CL007: Warning, "a line of numbers joined to the record above without `$`",
        example = "GOTO/1,2\n3",
        fix = "End a line with `$` when the record goes on at the next line.";
    /// A line has numbers but no CL word (such as GOTO) before them, and no record to continue;
    /// it is skipped.
    CL008: Error, "a line of numbers that continues no record",
        example = "1,2,3",
        fix = "Start the record with its word: `GOTO/1,2,3`.";
    /// A word inside a known record is not understood and is ignored; the rest of the record is
    /// used.
    CL009: Warning, "a word not understood inside a known record; ignored",
        fix = "Check that the record means what the CAM system intended.";
    /// A CIRCLE record describes an arc whose end is the GOTO after it. Without that GOTO the
    /// circle is dropped.
    CL010: Warning, "CIRCLE with no GOTO after it; dropped",
        example = "CIRCLE/0,0,0,0,0,1,5\nFEDRAT/100",
        fix = "Make sure the CAM system writes the arc's GOTO right after the CIRCLE.";
    /// The arc's start and end lie at different distances from its centre. The arc is kept; a
    /// controller with a tight radius check may reject it.
    CL011: Warning, "arc end point not on the circle",
        fix = "Export with more decimals, or check the CAM system's arc output.";
    /// The arc lies in a tilted plane (not XY, ZX or YZ), which G2/G3 cannot describe; it is cut
    /// into straight feed moves.
    CL012: Warning, "arc in a tilted plane; cut into feed moves",
        fix = "None needed, unless the machine can cut tilted arcs; then output the operation as points.";
    /// A drilling cycle (CYCLE/DRILL, ...) is not ended by CYCLE/OFF; postc ends it where the
    /// message says.
    CL013: Warning, "drilling cycle not ended by CYCLE/OFF",
        example = "CYCLE/DRILL,5,IPM,100\nGOTO/0,0,0\nFINI",
        fix = "Add CYCLE/OFF after the cycle's holes.";
    /// The units of a toolpath cannot change once it moves: a UNITS record after the first move
    /// that would change them means the lengths after it are in other units than the moves
    /// before, which postc does not mix, so the toolpath is refused (ignoring the record posted
    /// inches as millimetres).
    CL014: Error, "UNITS after the first move changes the units of the lengths after it",
        fix = "Write the whole file in one unit, with UNITS before the first move.";
    /// END-OF-PATH closes a TOOL PATH record; one without a TOOL PATH before it is ignored.
    CL015: Warning, "END-OF-PATH without TOOL PATH",
        fix = "None needed; check the CAM system's output if paths are missing.";
    /// FINI ends a CL file; records after it are ignored.
    CL016: Warning, "records after FINI",
        example = "FINI\nGOTO/1,2,3",
        fix = "Remove them, or move FINI to the end.";
    /// NURBS spline motion is not supported: the tool moves straight to the next GOTO instead of
    /// along the spline. Only the first spline is reported.
    CL017: Warning, "NURBS spline not followed; reported once",
        fix = "Output the operation as GOTO points (NX: turn off NURBS output in the operation's machine control).";
    /// The last line ends with `$`, the mark of a record that goes on at the next line, but the
    /// file ends there; the record is read as it stands.
    CL018: Warning, "file ends after a `$`",
        example = "GOTO/1,2,$",
        fix = "Complete the record, or remove the `$`.";
    /// A feed per revolution (FEDRAT/...,IPR or MMPR) is used before any spindle speed is known,
    /// so it cannot be turned into a feed per minute; it is passed on as a feed per minute.
    CL019: Warning, "feed per revolution with no spindle speed known",
        example = "FEDRAT/0.1,MMPR\nGOTO/1,2,3",
        fix = "Set the spindle speed (SPINDL) before the feed.";
    /// A line, or a record continued over lines, is longer than 1 MiB; it is skipped.
    CL020: Error, "line or continued record over 1 MiB",
        fix = "Check the file: CL records are short.";
    /// The CL file cannot be opened or read (the message gives the system's reason).
    CL021: Error, "the file can't be opened or read",
        fix = "Check the path and the file's permissions.";
    /// An arc given with TLON,GOFWD needs an INDIRV before it to say its direction; without one
    /// it is taken as counter-clockwise.
    CL022: Warning, "TLON,GOFWD arc with no INDIRV; taken as counter-clockwise",
        fix = "Make sure the CAM system writes INDIRV before the arc.";
    /// A record gives a coordinate, feed, spindle speed, angle, dwell or power outside the range
    /// a machine can have (a coordinate beyond ±1 km, a negative feed, a number that is not finite;
    /// docs/toolpath-format.md, "Ranges"). The toolpath is refused: posting it would write a word
    /// no controller reads, such as a 309-digit `X`.
    CL023: Error, "a coordinate, feed or speed out of range (beyond ±1 km, negative feed, not finite)",
        example = "GOTO/1e308,5,0",
        fix = "Correct the record; check the CAM system's units and the operation that wrote it.";
    /// The CL file ends without FINI, the record that ends every CL file: it may have been cut
    /// short (a copy or transfer that stopped), and the program posted from it would end early.
    CL024: Warning, "the CL file ends without FINI: it may be cut short",
        example = "GOTO/1,2,3",
        fix = "Post the whole CL file; if it is whole, add FINI at its end.";
    /// A cutting move (GOTO, an arc, a drilled hole) comes before any FEDRAT: the CL file gives
    /// it no feed rate, so the program has none for it (a G-code program cuts with no F, which
    /// verify refuses, VF034) or the post's own default. Said once, at the first such move.
    CL025: Warning, "a cutting move before any feed rate (FEDRAT)",
        example = "GOTO/1,2,3",
        fix = "Export the toolpath with its feeds, or add FEDRAT before the first cutting move.";
    /// `postc postp DIR` posts the CL file `DIR/cl.tap`, as the original `postp` did; there is
    /// none.
    PX001: Error, "no `DIR/cl.tap`",
        fix = "Put the CL file at `DIR/cl.tap`, or give the folder that holds it.";
    /// The MACHIN statement picks the controller; postp needs it before the first motion or tool.
    PX002: Error, "no MACHIN before the first motion or tool",
        fix = "Add `MACHIN/name,...` at the top of the CL file.";
    /// MACHIN names a controller postp does not know (ACORN, FANUC, HAAS, TORMACH).
    PX003: Error, "MACHIN names no known controller",
        fix = "Name one of the controllers postp knows.";
    /// MACHIN's axis type is a number from 0 to 6 for a mill, and is not given for a lathe.
    PX004: Error, "MACHIN axis type not 0–6, or given for a lathe",
        fix = "Give an axis type from 0 to 6, or none for a lathe.";
    /// The options file (`--options`) cannot be read or parsed; the message gives the line and
    /// column.
    PX005: Error, "the options file cannot be read or parsed (line and column)",
        fix = "Correct the file at the line and column given.";
    /// postp's controllers are posts built into postc; one of them does not compile. This is a
    /// defect in postc's build.
    PX006: Error, "an embedded post does not compile (a build defect)",
        fix = "Report it to postc's authors.";
    /// THREAD, TURRET and SFM are lathe words; the MACHIN statement chose a mill.
    PX010: Error, "a lathe word (THREAD, TURRET, SFM) on a mill",
        fix = "Remove the word, or choose a lathe controller.";
    /// LOADTL, LETTER, RETRCT, ROTABL and CYCLE are mill words; the MACHIN statement chose a
    /// lathe.
    PX011: Error, "a mill word (LOADTL, LETTER, RETRCT, ROTABL, CYCLE) on a lathe",
        fix = "Remove the word, or choose a mill controller.";
    /// A postp word has arguments of the wrong number or kind.
    PX012: Error, "a postp word with wrong arguments",
        fix = "Give the word the arguments the message names.";
    /// MACHIN should be the first statement, and appear once.
    PX013: Warning, "MACHIN is not the first statement, or a second MACHIN",
        fix = "Move MACHIN to the top and remove the second one.";
    /// The CL word is valid, but postp does not use it; it is ignored.
    PX014: Warning, "a CL word postp does not use; ignored",
        fix = "None needed, unless the program needs what the word asks for.";
    /// A computed motion, or a MODE/91 (incremental) move, needs to know where the tool is, and
    /// no position has been set yet.
    PX015: Error, "a computed motion or MODE/91 move with the tool position unknown",
        fix = "Move the tool to a known position (GOTO) first.";
    /// CLEARP / CLRSRF give the clearance plane postp retracts to; this plane cannot be used (a
    /// named plane, a tilted CLEARP, or none defined).
    PX016: Error, "CLEARP/CLRSRF plane not usable (named, tilted CLEARP, none defined)",
        fix = "Give the plane as a Z height perpendicular to the tool axis.";
    /// A dwell given in revolutions needs the spindle speed to become a time, and none is known.
    PX017: Warning, "dwell in revolutions with no RPM known",
        fix = "Set the spindle speed before the dwell, or give the dwell in seconds.";
    /// LETTER engraves text in postp's font; characters outside the font are skipped, and a
    /// LETTER without the PPRINT that holds its text engraves nothing.
    PX018: Warning, "LETTER: characters outside the font, or no PPRINT after it",
        fix = "Use characters the font has, and put the PPRINT with the text after LETTER.";
    /// postp posts 3-axis mills and 2-axis lathes: multi-axis tool axes, and Y on a lathe, are
    /// ignored.
    PX019: Warning, "multi-axis tool axes, or Y on a lathe, ignored",
        fix = "Post the operation as 3-axis, or with a multi-axis post.";
    /// ROTABL turns a rotary table; the axis type MACHIN gives has no such axis.
    PX020: Error, "ROTABL on an axis MACHIN's axis type does not give",
        fix = "Choose the axis type of a machine with that rotary axis, or remove ROTABL.";
    /// The controllers postp knows have flood coolant only; COOLNT THRU and AIR are taken as
    /// FLOOD.
    PX021: Warning, "COOLNT THRU or AIR, taken as FLOOD",
        fix = "None needed, if flood coolant is right for the job.";
    /// Drilling cycles are not posted in incremental mode (MODE/91) or under cylindrical mapping.
    PX022: Error, "drilling cycle in MODE/91 or under cylindrical mapping",
        fix = "Switch back to absolute mode, or end the mapping, before the cycle.";
    /// A post or toolpath named on the command line does not exist, or cannot be opened.
    IO001: Error, "a post or toolpath file does not exist or cannot be opened",
        fix = "Check the path and the file's permissions.";
    /// Reading the toolpath failed part way (an I/O error while streaming it).
    IO002: Error, "a toolpath cannot be read (an I/O error while streaming)",
        fix = "Check the file and the disk it is on.";
    /// The program (or another output) cannot be written: the output file or its folder, or
    /// standard output.
    IO003: Error, "the program cannot be written (the output file or folder, or standard output)",
        fix = "Check that the folder exists and is writable, and that the disk has room.";
    /// postc tells a post's dialect from its extension (`.pp`, `.js`, `.VcPost`, `.ron`) or its
    /// content, and could not here.
    IO004: Error, "the dialect of a post cannot be told from its extension or content",
        fix = "Give the file its dialect's extension, or pass `--dialect`.";
    /// postc could not tell what kind of toolpath the file is, or `postc post` got a post where
    /// the toolpath belongs.
    IO006: Error, "the kind of a toolpath cannot be told, or `postc post` got a post where a toolpath belongs",
        fix = "Give the toolpath a known extension (`.apt`, `.cl`, `.cls`, `.ron`, `.jsonl`), and put the post first: `postc post POST TOOLPATH`.";
    /// A command-line value is not valid: `--set NAME=VALUE`, a toolpath pattern, a
    /// `--warn`/`--deny`/`--allow` selector, a `postc.toml` that does not read. It is a warning
    /// when the value is ignored (`--primer` for a file that is not a composites event file).
    IO007: Error | Warning, "a bad command-line value (`--set NAME=VALUE`, a toolpath pattern)",
        fix = "Correct the value as the message says.";
    /// The post splits its output into parts (TAPE_SPLITTING), and there is no `-o`: the parts go
    /// to standard output one after the other.
    IO008: Warning, "the post splits its output into parts (TAPE_SPLITTING) but there is no `-o`: the parts go to standard output one after the other",
        fix = "Give `-o OUT` to write each part to its own file.";
    /// `postc explain TRACE.jsonl LINE` reads the trace `postc post --trace` wrote; a line of
    /// this file is not a trace record.
    IO010: Error, "`postc explain`: a line of the trace file is not a postc trace record",
        fix = "Give the trace file `postc post --trace` wrote, unchanged.";
    /// The trace has no record for that NC line (of that output file, with `--output`).
    IO011: Error, "`postc explain`: the trace has no record for that line (of that output file)",
        fix = "Check the line number (from 1) and, for a program split into parts, which part with `--output`.";
    /// An output of the command (`-o`, `--trace`, a tape-split part) is one of the files the
    /// command reads (the post, the toolpath, a `POST_BASE` file), or two outputs are the same
    /// file; links are followed, so a symbolic or hard link to an input counts as the input.
    /// postc refuses before it reads or writes anything, so no input is lost.
    IO012: Error, "an output path is one of the command's inputs, or two outputs are the same file",
        example = "postc post job.pp job.ron -o job.ron",
        fix = "Write each output to a file of its own that the command does not read.";
    /// `postc post --post NAME` found no post of that name among the embedded posts and the
    /// user's post folders (`postc posts` lists them); the message names the nearest names, when
    /// a typing mistake is likely.
    IO013: Error, "no post in the library has the name `--post` gives",
        example = "postc post --post \"Linuxcnc mm\" job.ron",
        fix = "Give a name `postc posts` lists (case and blanks do not matter), or the post's path.";
    /// `postc post --post NAME` found several posts of that name (an embedded one and a user's
    /// copy, or two user folders); the message lists their paths.
    IO014: Error, "several posts in the library have the name `--post` gives",
        fix = "Give one of them a name of its own (POST_NAME, PostInfo.title, description), or post with the path.";
    /// A post written as IR in RON (as `postc convert --to ron` writes) does not read.
    IR001: Error, "a post written as IR in RON does not read",
        fix = "Correct the RON at the place the message gives.";
    /// A post's IR is inconsistent: an id that names no format, variable, function, global or
    /// script; a non-finite multiplier; or a chord tolerance, step budget or tape split of 0. The
    /// message points at the item of a RON post that holds it.
    IR002: Error, "a post's IR is inconsistent (an id that names no format, variable, function, global or script; a non-finite multiplier; a chord tolerance, step budget or tape split of 0): points at the item of a RON post that holds it",
        fix = "Correct the item the message points at.";
    /// A line of a RON toolpath is not a valid event: an unknown event or field, or a bad value.
    TP001: Error, "a RON toolpath line is not a valid event (unknown event or field, bad value)",
        fix = "Correct the line (docs list the events and their fields).";
    /// A line of a JSON Lines toolpath is not a valid event.
    TP002: Error, "a JSON Lines toolpath line is not a valid event",
        fix = "Correct the line.";
    /// Toolpaths are text; this one is not valid UTF-8.
    TP003: Error, "the toolpath is not text (not valid UTF-8)",
        fix = "Save the toolpath as UTF-8 text.";
    /// An event gives a coordinate, feed, spindle speed, angle, dwell or power outside the range a
    /// machine can have (a coordinate beyond ±1 km, a negative feed, a number that is not finite;
    /// docs/toolpath-format.md, "Ranges"). The toolpath is refused.
    TP004: Error, "a coordinate, feed or speed out of range (beyond ±1 km, negative feed, not finite)",
        fix = "Correct the event; check the toolpath's units.";
    /// The toolpath ends without its `End` event: it may have been cut short (a copy or transfer
    /// that stopped), and the program posted from it would end early.
    TP005: Warning, "the toolpath ends without an End event: it may be cut short",
        fix = "Post the whole toolpath; if it is whole, end it with `End`.";
    /// An event a Python program gives the `postc` package (an item of the iterable passed as
    /// the toolpath) is not an event of the native schema: a dict of one event name and its
    /// fields (`{"Feed": {"x": 10, "y": 5, "z": -1}}`) or a unit event's name (`"End"`).
    TP006: Error, "an event of a Python toolpath iterable is not a valid event",
        example = "postc.post(\"job.pp\", [{\"Feed\": {\"x\": 10, \"y\": 5}}])",
        fix = "Give each event as docs/toolpath-format.md writes it in JSON, as a dict (or a unit event's name as a string).";
    /// Every event may run at most a step budget of statements, so that a loop that never ends
    /// stops. The post ran past it; the message points at the loop.
    RT002: Error, "a post ran more than its step budget for one event (a loop that never ends); points at the loop",
        fix = "Correct the loop's condition.";
    /// The post calls Lua scripts, which postc keeps but does not run; those lines are skipped
    /// and the rest of the post runs as written.
    RT003: Warning, "the post calls Lua scripts, which postc keeps but does not run; those lines are skipped",
        fix = "Write what the script prints as output lines, or accept that it is skipped.";
    /// Calls nest deeper than 200 levels, which means endless recursion.
    RT004: Error, "calls nest deeper than 200 levels (endless recursion)",
        fix = "Give the recursive function a way to stop.";
    /// A script function was called, but the post has no script host to run it.
    RT005: Error, "a script function was called but the post has no script host",
        fix = "Report it to postc's authors with the post.";
    /// The post has no DWELL_MOVE section, so the toolpath's dwells print nothing.
    RT010: Warning, "the post has no DWELL_MOVE section, so dwells are skipped",
        fix = "Add `begin DWELL_MOVE` with the controller's dwell line, if the job needs dwells.";
    /// A toolpath has one Job event, at its start; a second one after output began is ignored.
    RT011: Warning, "a second Job event after output began is ignored",
        fix = "Post the jobs separately, or merge them.";
    /// The post has no FEED_MOVE section, so feed moves print nothing.
    RT012: Warning, "the post has no FEED_MOVE section, so feed moves print nothing",
        fix = "Add `begin FEED_MOVE` with a line such as `\"G1[X][Y][Z][F]\"`.";
    /// A DrillPoint event came outside a drilling cycle (no cycle start before it).
    RT013: Error, "a DrillPoint outside a drilling cycle",
        fix = "Check the toolpath: a drilling cycle starts before its points.";
    /// Tape splitting starts a new part at a retract near the maximum length; no retract came
    /// within the tolerance, so the part was split inside a cut.
    RT014: Warning, "a tape-split part reached its maximum with no retract in its tolerance and was split inside a cut",
        fix = "Raise the TAPE_SPLITTING tolerance so that a retract falls inside it.";
    /// The post wraps an axis around a cylinder (ROTARY_WRAP_X / _Y), which needs the wrap
    /// diameter, and the job gives none.
    RT015: Warning, "the post wraps an axis around a cylinder but the job gives no wrap diameter",
        fix = "Give the job a `wrap_diameter`.";
    /// An event carries a value that is not a finite number (NaN or infinity).
    RT016: Error, "an event carries a value that is not a finite number",
        fix = "Correct the toolpath: every coordinate, feed and time must be an ordinary number.";
    /// An arc the post linearizes needs more than 10,000 chords to stay within the chord
    /// tolerance; it is cut into 10,000, so it may stray farther than the tolerance.
    RT017: Warning, "an arc needs more than 10,000 chords to stay within the tolerance; it is cut into 10,000",
        fix = "Raise the tolerance (`--set tolerance=MM`), or give the post an arc section.";
    /// A longhand peck cycle would need more than 1,000 pecks for one hole; it is drilled in
    /// 1,000.
    RT018: Warning, "a longhand peck cycle would need more than 1,000 pecks for a hole; it is drilled in 1,000",
        fix = "Check the peck depth of the cycle.";
    /// A post driven by APT words handles each record's word in a Sub of that name; it has none
    /// for this word, so those records are skipped.
    RT020: Warning, "a post driven by APT words has no Sub for a record's word; those records are skipped",
        fix = "Add `Sub WORD` ... `End Sub` to the post to handle them.";
    /// A post driven by APT words has no Sub for CIRCLE, so arcs become GOTO moves to their end
    /// points.
    RT021: Warning, "a post driven by APT words has no Sub for CIRCLE; arcs become GOTO moves",
        fix = "Add a CIRCLE Sub to the post, if the machine should cut arcs.";
    /// The script postc made from a CIMCO post does not compile. This is a gap in postc.
    RT022: Error, "the script made from a CIMCO post does not compile",
        fix = "Report it to postc's authors with the post.";
    /// A CIMCO post stopped with a JavaScript error (thrown by the post, or a runtime error); the
    /// message points at the JS line and column.
    RT023: Error, "a CIMCO post stopped with a JavaScript error (points at the JS line and column)",
        fix = "Correct the post at that line.";
    /// A probe table or composites event file calls a Sub the post lacks; those calls are
    /// skipped.
    RT030: Warning, "a probe table or composites file calls a Sub the post lacks; those calls are skipped",
        fix = "Add the Sub to the post, or correct the name in the table or file.";
    /// A post built a text longer than 16 MiB (or, in a script, an array or object of more than
    /// 2^20 items): a loop that keeps adding. It is stopped at its loop and no output is written.
    RT031: Error, "a post built a text past 16 MiB (or, in a script, an array or object past 2^20 items): stopped at its loop, no output written",
        fix = "Correct the loop.";
    /// A format or output variable was given a value that is not a finite number (NaN, or an
    /// infinity): a key missing from a table, `undefined`, text that is not a number, a division
    /// by zero. No controller reads such a word and a 0 in its place moves the machine where the
    /// post never meant, so the run stops at the post's line and no output is written.
    RT032: Error, "the post formats a value that is not a finite number (NaN or infinity); no output is written",
        fix = "Check the value before formatting it: give the table the missing key, or test the value with isNaN().";
    /// A post line prints only values the job does not give (a tool number for a job with no
    /// tool, a home position or material size it does not state): the line is left out, as
    /// `T[T] M6` must be for a job with no tool, rather than printed as `T M6`.
    RT033: Warning, "a post line prints only values the job does not give; the line is left out",
        fix = "Nothing to do when the job has no such value; otherwise give the toolpath the tool, home or material.";
    /// A post line prints an address letter of its text with no number after it (`T[T]` for a
    /// job with no tool prints `T`): a controller reads that as an error, or as zero.
    RT034: Warning, "a post line prints an address letter with no number after it (the job gives no value for it)",
        fix = "Print the letter as the variable's prefix (`[T|A|T|1.0]`) so that it goes with the value, or give the job the value.";
    /// The toolpath changes how the tool cuts (cutter compensation, coolant, a new spindle
    /// speed, a spindle stop followed by moves) and the post has no handler to write it: the
    /// program runs on as before, which is not what the toolpath asked. Events that change
    /// nothing on the part (a spindle stop before a tool change, a restart or the end, whose
    /// sections stop the spindle themselves; a toolpath's end) are not reported.
    RT035: Warning, "the toolpath changes how the tool cuts (compensation, coolant, spindle speed, a spindle stop) and the post cannot write it",
        fix = "Add the handler to the post, or post with a post that has it.";
    /// The post threw a value (`throw`) that no `try` caught: it stops there, as a JavaScript
    /// engine stops; the message is what it threw.
    RT036: Error, "the post threw an error no `try` caught (points at the `throw`)",
        fix = "Read the message: the post stops on purpose (an unknown cycle, a missing tool); give the toolpath what it needs, or correct the post.";
    /// A JavaScript type error in the post's code: a property of `undefined` or `null`, a call of
    /// what is not a function, a method a value does not have, a name the post never defines
    /// (`ReferenceError`). A `try` catches it; uncaught, the post stops, and the message points at
    /// the expression that raised it (the property read or set, the method call, the name), line
    /// and column, with the function it is in; a call of a value that is no function points at
    /// its statement (in a Fusion post; at the function in a CIMCO post).
    RT037: Error, "a JavaScript type error: a property of undefined, a call of what is not a function, a method a value lacks",
        fix = "Correct the post where the message says: check the value before using it.";
    /// postc's regular expressions keep no `lastIndex`, so what reads or moves it is refused
    /// rather than answered as if it were 0: `exec`, reading or setting `lastIndex`, and `test` of
    /// a pattern with the `g` flag (JavaScript starts it where the previous `test` stopped). Under
    /// the `m` flag, `^` and `$` see only `\n` as a line end, where JavaScript also sees `\r`,
    /// U+2028 and U+2029: such a pattern over a text holding one is refused too, and so is a
    /// function as the replacement of `replace`. A `try` does not catch it: the post stops, and
    /// no output is written.
    RT038: Error, "a regular expression used in a way postc does not run: its `lastIndex` (`exec`, `lastIndex`, `test` under `g`), `^`/`$` under `m` over `\\r` or U+2028/U+2029, a function as a replacement",
        example = "var re = /\\d+/g;\nfunction onOpen() { while (re.test(s)) { n++; } }",
        fix = "Drop the `g` flag from a pattern given to `test`; find matches with `replace`, `split` or `search`.";
    /// Outside a method, `this` is JavaScript's global object, and its properties are the post's
    /// globals, functions and output variables: postc reads them by name (`this[name]`), but
    /// does not set them through it, because the engine reads a global the post never assigns
    /// by name as the constant it starts as. Setting a property the post does not declare is
    /// allowed. A `try` does not catch it: the post stops, and no output is written.
    RT039: Error, "the post sets one of its own globals, functions or output variables through the global object (`this.name = ...` outside a method), which postc does not run",
        example = "var counter = 1;\nfunction bump() { this.counter = 2; }",
        fix = "Assign the global by its name: `counter = 2`.";
    /// A move of the toolpath tilts the tool (a CL file's `GOTO/x,y,z,i,j,k` with a tool axis
    /// that is not +Z, from a multi-axis operation), and the post is driven by the kind of each
    /// move (Vectric, CIMCO, Fusion): it writes X, Y and Z, so the machine would hold the tool
    /// upright at the point the tilted tool's tip should reach, and cut another shape.
    RT040: Error, "a move tilts the tool away from Z, and the post writes X, Y and Z only",
        example = "GOTO/10,0,0,0.5,0,0.8660254",
        fix = "Post the toolpath with a post for a machine with rotary axes, or program the operation for three axes in the CAM system.";
    /// A move of the toolpath turns a rotary axis (`"a": 90` on a native move, an A, B or C
    /// position away from 0) and the post reads no such axis: the program would leave the part
    /// where it was and cut the rest of the move as if it had turned.
    RT041: Error, "a move turns a rotary axis the post does not write",
        example = "{\"Feed\":{\"x\":10.0,\"y\":0.0,\"z\":-1.0,\"a\":90.0}}",
        fix = "Post the toolpath with a post that writes the axis (a 4th-axis post), or program the operation without it.";
    /// The target dialect has no place for one of the post's handlers: an event it has no section
    /// for (coolant, drilling cycles, comments, ...), a post driven by APT words, or (VcPost) a post
    /// of another dialect driven by the kind of each move, which postc prints as a VcPost
    /// milling post not yet and as a section post only with `--postc-extension`.
    CV001: Error, "the target dialect has no place for a handler of the post: an event it has no section for (coolant, drill cycles, comments, ...), a post driven by APT words, or a post driven by the kind of each move where postc prints no form of it the target's engine runs",
        fix = "Convert to RON (`--to ron`), which holds every post, or drop the handler from the source post; `--postc-extension` writes a section post, which only postc runs.";
    /// The post has code (functions, globals, statements other than output lines) and the
    /// target's sections hold only lines.
    CV002: Error, "the post has code (functions, globals, statements other than output lines) and the target's sections hold only lines",
        fix = "Convert to RON, or keep the post in its own dialect.";
    /// A number format the target's formats cannot write: trimmed zeros, a width of the integer
    /// digits, no leading zero, a prefix of its own.
    CV003: Error, "a number format the target's formats cannot write (trimmed zeros, width of the integer digits, no leading zero, a prefix of its own)",
        fix = "Convert to RON, or change the format in the source post.";
    /// An output option that no statement of the target sets: a lathe mapping, a chord tolerance,
    /// a step budget, multi-character substitutions.
    CV004: Error, "an output option no statement of the target sets (a lathe mapping, a chord tolerance, a step budget, multi-character substitutions)",
        fix = "Convert to RON, or drop the option in the source post.";
    /// A variable the target cannot declare: set by code, a prefix with `|`, `]` or a line break,
    /// two variables printing one label, or a label with no VAR name printed its own way.
    CV005: Error, "a variable the target cannot declare: set by code, a prefix with `|`, `]` or a line break, two variables printing one label, or a label with no VAR name printed its own way",
        fix = "Convert to RON, or change the variable in the source post.";
    /// Converting a post to its own dialect printed text that its frontend compiles to another
    /// post: the post is not one that frontend makes from any text (a RON post edited by hand:
    /// handlers that are not the ones derived from its functions, a function body no source
    /// writes). The message names what differs.
    CV006: Error, "the printed post would compile to a different post: the post is not one its dialect's frontend makes (a RON post edited by hand?); the message names what differs",
        fix = "Convert to RON, or convert the post the RON was made from.";
    /// A section the converted post prints prints a value the target engine never hands the post:
    /// CNC-Calc (the CNC-Calc manual) hands the end point and movement of each move, the centre and direction
    /// of each arc and the feed, and nothing of the job, the tool or the toolpath (`[T]`,
    /// `[TOOLNAME]`, `[SAFEZ]`, the material, the home position).
    CV007: Error, "a section the converted post prints prints a value the target engine never hands a post (the tool, the job, the toolpath)",
        fix = "Drop the value from the section, or convert with `--postc-extension` (a section post, which only postc runs).";
    /// A section the target engine never calls is left out of the converted post: CNC-Calc
    /// (the CNC-Calc manual) calls nothing at a tool change, a toolpath start or a dwell.
    CV008: Warning, "a section the target engine never calls is left out of the converted post",
        fix = "Check that the program does without it, or convert with `--postc-extension`.";
    /// The IR cannot be written as RON. This is a bug in postc.
    CV009: Error, "the IR cannot be written as RON (a postc bug)",
        fix = "Report it to postc's authors with the post.";
    /// A rule of the source the target engine gives the post no way to follow: a helical plunge
    /// section (CNC-Calc does not say which arcs plunge), an empty line (CNC-Calc writes only
    /// lines that are not empty).
    CV010: Error, "a rule of the source the target engine gives the post no way to follow (which arcs plunge, empty lines)",
        fix = "Drop the construct from the source post, or convert with `--postc-extension`.";
    /// The target engine hands a value the post prints with less precision than the post prints
    /// it: CNC-Calc's getFeedrate gives the feed to a tenth (a feed per minute), and a post that
    /// prints finer feeds prints the engine's tenth.
    CV011: Warning, "the target engine hands a value with less precision than the converted post prints it (the feed, to a tenth)",
        fix = "Print the feed to a tenth or coarser, or check that the machine's feeds are given to a tenth.";
    /// The target has no converter for the post's form yet: `--to fusion` writes `.cps` posts
    /// from Vectric posts, CIMCO posts and VcPost posts driven by APT words, and a Fusion post as
    /// its file is written; a VcPost section post, and a Fusion post the IR does not keep as
    /// written (a RON post, a file that is not UTF-8), are refused. Nothing is written.
    CV012: Error, "the post's form does not convert to the target yet (`--to fusion` converts Vectric posts, CIMCO posts, VcPost posts driven by APT words, and Fusion posts as written)",
        fix = "Convert the post to Vectric first (`postc convert POST --to vectric`), then to Fusion.";
    /// The target engine hands the converted post a value other than the one postc hands the
    /// source: a drilling cycle's name, which CNC-Calc hands (`drillHeader.name`, "Drilling
    /// (G81)") and Fusion does not (it hands the cycle's type: the converted post is given the
    /// type's CNC-Calc name, "Drilling", "Peck drilling", ...).
    CV013: Warning, "the target engine hands the converted post a value other than postc hands the source (a drilling cycle's name)",
        fix = "Check that the post reads the cycle's kind the way the converted post is given it (docs/convert.md).";
    /// verify reads G-code programs; this one is HPGL, ShopBot, Heidenhain conversational, or
    /// text whose first blocks cannot be read. It is refused, and the message says which families
    /// verify reads.
    VF001: Error, "the program is not G-code (HPGL, ShopBot, Heidenhain conversational, or text whose first blocks cannot be read): verify refuses it and says which families it reads",
        fix = "Check that the program is G-code.";
    /// The program is binary data, a line holds NUL bytes, or the program cannot be read.
    VF002: Error, "the program is binary data, a line holds NUL bytes, or the program cannot be read",
        fix = "Check the file: verify reads G-code text.";
    /// A line is longer than 64 KiB; it is skipped.
    VF003: Error, "a line longer than 64 KiB; it is skipped",
        fix = "Check the program: G-code blocks are short.";
    /// A block cannot be read: a letter without a number, a number without a letter, a name or
    /// statement of no family verify reads (docs/verify.md: `#` and R parameters, `[ ]`
    /// expressions and the Sinumerik, Okuma and Heidenhain ISO statements are read), an
    /// unclosed comment or bracket, or a second word of one letter. A warning when the
    /// line is text the toolpath asked to be inserted as it is (an APT `INSERT`, a native
    /// `Insert` event): the toolpath's text, written as asked, not a fault of the post.
    VF004: Error | Warning, "a block cannot be read: a letter without a number, a number without a letter, a name or statement of no family verify reads, an unclosed comment or bracket, or a second word of one letter (a warning for text the toolpath inserts as it is)",
        fix = "Correct the post that wrote the block; for inserted text, make it a comment in the CAM system.";
    /// verify does not know this G code, letter or block, and ignores it; or it reads a
    /// statement it does not replay (a jump, a loop, a Sinumerik frame, a system variable set),
    /// or a value it cannot compute (a parameter the program never sets), and says so. What it
    /// does on the machine is not checked.
    VF005: Warning, "a G code, letter or block verify does not know, a statement it does not replay, or a value it cannot compute (it is ignored)",
        fix = "None needed if the code is right for the controller.";
    /// The post wraps an axis onto a rotary axis; verify does not compare rotary-wrapped
    /// programs.
    VF006: Error, "the post wraps an axis onto a rotary axis: verify does not compare rotary-wrapped programs",
        fix = "Check the program another way (a simulator).";
    /// The post is a lathe post; verify compares milling programs only.
    VF007: Error, "the post is a lathe post: verify compares milling programs only",
        fix = "Check the program another way (a simulator).";
    /// After G92 the coordinates are offset, so positions after it are not compared.
    VF008: Warning, "G92 coordinate offsets: positions after it are not compared",
        fix = "Use work offsets (G54 ...) instead of G92, if the post can.";
    /// No longer reported: `postc post` verifies a program split into parts as the parts joined.
    /// The code stays so that `postc.toml` files that name it still read.
    VF009: Warning, "not reported: `postc post` verifies tape-split parts joined (a post that split its output was once not verified)",
        fix = "Nothing to do.";
    /// A cutting move goes where the toolpath does not (or is an arc where the toolpath moves
    /// straight).
    VF010: Error, "a cutting move off the toolpath (or an arc where the toolpath moves straight)",
        fix = "Look at the post's move sections and variable formats around the line given.";
    /// The program ends before cutting moves of the toolpath: it is truncated, or moves were
    /// dropped. A warning when the program has moves to positions verify cannot compute (a
    /// parameter the program never sets, VF005): they may be the moves it misses.
    VF011: Error | Warning, "the program ends before cutting moves of the toolpath (truncated, or moves dropped; a warning when the program has moves to positions verify cannot compute, which may be them)",
        fix = "Check the post's sections for the missing moves, and that the program was written whole.";
    /// A rapid move where the toolpath cuts: the tool would cut at rapid speed.
    VF012: Error, "a rapid move where the toolpath cuts",
        fix = "Check the post's move sections: the feed section prints G0, or a modal G1 is lost.";
    /// An arc turns the other way, lies in another plane, or has another centre than the
    /// toolpath's.
    VF013: Error, "an arc turns the other way, lies in another plane, or has another centre than the toolpath's",
        fix = "Check the post's arc sections (G2/G3, plane, and whether I J K are absolute or incremental).";
    /// A chord of a linearized arc lies farther from the arc than the chord tolerance.
    VF014: Error, "a chord of a linearized arc lies farther from the arc than the chord tolerance",
        fix = "Lower the post's chord tolerance.";
    /// An arc's start and end radii differ by more than the controller accepts; it would reject
    /// the arc.
    VF020: Error, "an arc's start and end radii differ by more than the controller accepts",
        fix = "Print arc words with as many decimals as positions, or post with `--exact-arcs`.";
    /// An arc offset word (I, J or K) lies outside the active plane (such as K in G17).
    VF021: Error, "an arc offset word (I, J or K) outside the active plane",
        fix = "Print the offsets of the active plane only.";
    /// An R arc over 180° needs a negative R; this one has the wrong sign.
    VF022: Error, "an R arc with the wrong sign of R (over 180° needs a negative R)",
        fix = "Check how the post prints R, or print I J K instead.";
    /// An R arc that cannot be: a full circle, or R shorter than half the chord.
    VF023: Error, "an R arc that cannot be: a full circle, or R shorter than half the chord",
        fix = "Print I J K for such arcs.";
    /// A drilling cycle needs its R (retract plane) and Z (depth) words.
    VF024: Error, "a drilling cycle without its R and Z words",
        fix = "Print R and Z in the post's drilling section.";
    /// The numbers are in the other unit than G20/G21 says (inches in a G21 program, or the
    /// reverse).
    VF030: Error, "the numbers are in the other unit than G20/G21 says (inches in a G21 program or the reverse)",
        fix = "Make the post's UNITS and its G20/G21 line agree.";
    /// The program's G20/G21 contradicts the post's units.
    VF031: Error, "the program's G20/G21 contradicts the post's units",
        fix = "Make the post's UNITS and its G20/G21 line agree.";
    /// The program moves before it says G20 or G21, so the machine uses whatever unit was active.
    VF032: Warning, "the program moves before it says G20 or G21",
        fix = "Print G20 or G21 in the header.";
    /// A cut's feed differs from the toolpath's (after unit conversion).
    VF033: Error, "a cut's feed differs from the toolpath's (after unit conversion)",
        fix = "Check the feed variable's format and multiplier in the post.";
    /// A cutting move comes before any feed rate is set.
    VF034: Error, "a cutting move before any feed rate is set",
        fix = "Print the feed on the first feed move (a FIRST_FEED_MOVE section, or an always-printed F).";
    /// A cut with the spindle (or jet) off. A warning when the post cannot switch it on at all,
    /// a property of the post rather than a fault of the run: a jet toolpath (laser, plasma,
    /// waterjet) through a section post with no JET_TOOL_ON section or through an APT-word post
    /// (given no jet records): it is not a jet post; a spindle toolpath through a section post with
    /// no SPINDLE_ON section and no M3 or M4 in any line (a post for a spindle switched on by
    /// hand); or an APT-word post (VcPost) over a toolpath that gives the tool a speed but never
    /// switches the spindle on (such a post starts it only from SPINDL records). A spindle
    /// switched on by `S0 M3` and given no speed since (outside G96 and jets) is off.
    VF035: Error | Warning, "a cut with the spindle (or jet) off (a warning when the post cannot switch it on: a jet through a post with no jet section, a spindle through a post that never prints M3/M4, an APT-word post never told to start it)",
        fix = "Start the spindle in the header or tool change (M3/M4 with S); post jet toolpaths with a post that has a JET_TOOL_ON section; give an APT-word post's toolpath a spindle-on event.";
    /// A cut at constant surface speed (G96) whose S differs from the toolpath's surface speed
    /// (after unit conversion: metres a minute under G21, feet under G20).
    VF036: Error, "a cut's constant surface speed (the S of G96) differs from the toolpath's",
        fix = "Check how the post converts the tool's surface speed into its S word (metres or feet a minute).";
    /// A rapid move the toolpath does not make goes below the toolpath's lowest rapid height,
    /// into the material.
    VF037: Error, "a rapid move the toolpath does not make goes below the toolpath's lowest rapid height into the material",
        fix = "Check the post's rapid and tool-change sections for moves of their own.";
    /// A tool change (M6) with the tool down in the material (or below the safe height when the
    /// job gives no material).
    VF038: Error, "a tool change (M6) with the tool down in the material (or below the safe height when the job gives no material)",
        fix = "Retract Z before the tool change in the post's TOOLCHANGE section.";
    /// Block numbers must increase; this one does not (a wrap, or a restart).
    VF040: Error, "a block number that does not increase",
        fix = "Raise LINE_NUMBER_MAXIMUM, or drop block numbers.";
    /// A block number is over the post's (or the controller's) maximum.
    VF041: Error, "a block number over the post's (or the controller's) maximum",
        fix = "Raise the maximum, or let numbers wrap, or drop block numbers.";
    /// A comment holds a character the controller refuses: `(` inside a comment, `%` or `;` on
    /// Fanuc/Haas, control characters, non-ASCII on Fanuc/Haas/grbl. These are warnings for the
    /// generic controller and errors for the named ones.
    VF042: Error | Warning, "a comment character the controller refuses: `(` inside a comment, `%` or `;` on Fanuc/Haas, control characters, non-ASCII on Fanuc/Haas/grbl (warnings for the generic controller)",
        fix = "Filter the comment text in the post (SUBSTITUTE in a Vectric post).";
    /// A word or block longer than the controller reads: a number of more than 8 digits for
    /// Fanuc and Haas (Fanuc alarm PS0003 "TOO MANY DIGITS"), a block of more than 255 characters
    /// for LinuxCNC and the generic controller ("Command too long"), of more than 80 characters
    /// besides blanks and comments for grbl (error 11). docs/verify.md, "Word and block length".
    VF043: Error, "a word or block longer than the controller reads (Fanuc/Haas 8 digits, LinuxCNC 255 characters, grbl 80)",
        example = "G1 X100000000000000000000000000000000000000 F100",
        fix = "Check the toolpath's coordinates and the post's number format.";
    /// `postc post` did not verify the program it wrote, and says why: the post writes a family
    /// verify does not read (HPGL, ShopBot, Heidenhain conversational, by the post's or the
    /// output's extension, or by the program's first lines), the program is binary data or text
    /// whose first blocks do not read as G-code, or the post is a lathe or rotary-wrapped one.
    /// verify gives it too, at a call of a block or subroutine written elsewhere in the program
    /// (Sinumerik `CALL BLOCK`, LinuxCNC `o<name> call`): the moves from there on are not
    /// compared.
    /// A note; `--deny VF044` refuses to write a program that could not be verified.
    VF044: Note, "`postc post` did not verify the program: verify does not read what the post writes (the note says why)",
        fix = "Nothing to do: the program is written as posted. `--deny VF044` refuses programs that cannot be verified.";
    /// The post writes feed moves, but no section prints a feed rate, so the machine cuts at
    /// whatever feed was set before the program ran.
    LN001: Warning, "a G-code post writes feed moves but no section prints a feed rate",
        fix = "Print `[F]` on the first feed move (FIRST_FEED_MOVE) or on every feed move.";
    /// The post starts the spindle (SPINDLE_ON, or M3/M4 in the header or tool change) but never
    /// prints a spindle speed, so every tool runs at the speed the spindle was left at. Posts for
    /// machines whose spindle speed is set by hand (a trim router) do this on purpose.
    LN002: Warning, "the post starts the spindle (SPINDLE_ON, or M3/M4 in the header or tool change) but never prints a spindle speed",
        fix = "Print `[S]` with the spindle start, unless the speed is set by hand.";
    /// A comment line prints text the user chose (a tool or toolpath name, notes, a file name)
    /// between `(` and `)`; a name with a `)` in it ends the comment early and the controller
    /// reads the rest as words.
    LN003: Warning, "a `( )` comment prints a name or notes (`[TOOLPATH_NAME]`, `[TOOLNAME]`, ...) that can hold `)`, and `SUBSTITUTE` does not replace parentheses",
        example = "begin HEADER\n\"( [TOOLPATH_NAME] )\"",
        fix = "Replace parentheses in such text with `SUBSTITUTE = \"([)]\"`, or drop the name from the comment.";
    /// The tool change section changes the tool (M6) before anything moves Z up or home: on a
    /// machine that does not retract by itself, the tool is pulled sideways out of the work. (A
    /// Haas M6 retracts by itself.)
    LN004: Warning, "TOOLCHANGE changes the tool (M6) before any line raises Z or goes home (G28/G30/G53)",
        example = "begin TOOLCHANGE\n\"M6 T[T]\"",
        fix = "Raise Z (or go home with G28/G30/G53) before the M6.";
    /// The `POST_NAME` promises what the post does not do. The names of Vectric's own posts
    /// follow a convention (the 2012 Vectric post guide): `(mm)`/`(inch)` the units, `(*.tap)` the file extension,
    /// `Arc`/`Arcs` true arcs, `ATC` tool changes, `TS n` tape splitting, `WX`/`WY` a wrapped
    /// axis. A user picks a post by that name.
    LN005: Warning, "`POST_NAME` says `(mm)`/`(inch)`, `(*.ext)`, Arcs or no arcs, ATC, `TS`/`TSn`, WX/WY, and the post does otherwise",
        example = "POST_NAME = \"My router (mm) (*.tap)\"\nFILE_EXTENSION = \"nc\"",
        fix = "Make the name say what the post does, or the post do what the name says.";
    /// With `postc check --product NAME`: the chosen Vectric product's post processor does not
    /// support this statement, section or variable (the 2012 Vectric post guide's table); that product rejects it or
    /// silently ignores it.
    LN006: Warning, "with `--product`: a statement, section or variable that Vectric product does not support, or accepts and ignores (the 2012 Vectric post guide's table)",
        fix = "Remove it, or use the post with a product that supports it.";
    /// A variable is declared and never printed (a Vectric `VAR` under a name of the post's own,
    /// a CIMCO `createVariable`). It is dead text a reader must still understand, and often a
    /// sign of a typo. `VAR`s under their standard names are the guides' template and are not
    /// reported.
    LN007: Warning, "a variable is declared and never printed (a Vectric `VAR` under a name of the post's own, a CIMCO `createVariable`); `VAR`s under their standard names are the guides' template and are not reported",
        fix = "Print it where it was meant to be printed, or remove it.";
    /// A CIMCO `createFormat` that no variable or `format()` call uses.
    LN008: Warning, "a CIMCO `createFormat` that no variable or `format()` call uses",
        fix = "Use it where it was meant to be used, or remove it.";
    /// A CIMCO function that nothing calls (entry points `on...` excepted).
    LN009: Warning, "a CIMCO function that nothing calls (entry points `on...` excepted)",
        fix = "Call it, correct the name of its caller, or remove it.";
    /// Arc words (I J K, absolute centres, R) print so few decimals that the radius at the start
    /// and at the end of an arc can differ by more than a controller accepts: grbl refuses more
    /// than 0.005 mm, LinuxCNC more than 0.0283 mm (docs/verify.md has the limits and their
    /// sources). Rounding a centre word moves the centre, so the two radii can disagree even when
    /// the toolpath's arc is exact.
    LN010: Warning, "a G-code post prints arc words (I J K, absolute centres, R) so coarsely that rounding alone can make an arc's start and end radii differ by more than grbl (0.005 mm) or LinuxCNC (0.0283 mm) accepts (docs/verify.md has the limits and sources)",
        fix = "Print arc words with more decimals (at least as many as positions), or post with `--exact-arcs`.";
    /// The post splits long programs into files (`TAPE_SPLITTING`) and only its tool change
    /// starts the spindle. Every part starts with the header (followed by `SPINDLE_ON` when the
    /// post has one, as the first part does); the tool change is not repeated at a split, so a
    /// part run on its own cuts with the spindle stopped.
    LN011: Warning, "`TAPE_SPLITTING`, and only the tool change starts the spindle: every part begins with the header (and `SPINDLE_ON`, when the post has one), never with the tool change",
        fix = "Start the spindle in the header or in a `SPINDLE_ON` section too.";
    /// The post prints block numbers (`[N]`) and `LINE_NUMBER_MAXIMUM` is reached after fewer
    /// blocks than a long program has: numbering then starts again, so block numbers repeat,
    /// which controllers that search for a block number (`GOTO`, restart at a block) get wrong;
    /// `postc verify` reports it (VF040).
    LN012: Warning, "the post prints `[N]` and `LINE_NUMBER_MAXIMUM` is reached in fewer than 100,000 blocks (and no tape-split part is that long): block numbers start again and repeat",
        fix = "Raise `LINE_NUMBER_MAXIMUM`, or drop block numbers.";
    /// A VcPost `Out` template prints a register (`<Name>`) that nothing sets: no statement
    /// assigns it, the runtime does not load it (the APT record registers, the composites
    /// variables), and no table or application passes it as a Sub parameter. It prints empty
    /// every time; usually the register's name is misspelt.
    LN013: Warning, "a VcPost `Out` prints a register (`<Name>`) that no statement assigns, the runtime does not load and no table or application passes: it prints empty every time (often a misspelt name)",
        fix = "Correct the register's name, or assign it before the `Out`.";
    /// A section the runtime never runs for this post: under `ROTARY_WRAP_X`/`_Y` every arc is
    /// cut into feed moves (a G2/G3 cannot turn the rotary axis), and with `MAX_ARC_RADIUS = 0`
    /// every arc is over the limit; the arc sections are dead text a reader expects arcs from.
    LN014: Warning, "a section the post can never run: arc sections under `ROTARY_WRAP` or with `MAX_ARC_RADIUS = 0`",
        fix = "Remove the section, or unwrap the axis to print true arcs.";
    /// A CIMCO global read but never given a value: declared without one (`var drill;`) and
    /// assigned nowhere, at the top level or in any function, native or script. Every read gets
    /// `undefined`, which prints as `undefined` or turns arithmetic into NaN.
    LN015: Warning, "a CIMCO global is read but never given a value",
        fix = "Give it a value where it is declared, or assign it before it is read.";
    /// A VcPost `Sub` or `Function` that nothing can call: no statement of the post calls it,
    /// its name is not an event the applications raise (an APT major word such as `GOTO`, a
    /// composites routine such as `CamPoint`), and it has no keyword comment (`#Cycle`,
    /// `#Option`, `#Probe`, ...) or tip that offers it to a probe table or an option card.
    /// The Vericut guide calls those comment lines "not essential, but very desirable": a Sub
    /// a table names without one still runs, but nothing offers its name, and a reader of the
    /// post cannot tell it from dead code.
    LN016: Warning, "a VcPost `Sub` or `Function` that no statement calls, that is not an event the applications raise, and that no keyword comment offers to a table or option card",
        fix = "Add the keyword comment of its role (`' #Option`, `' #Cycle`, `' #Probe`, ...) after the `Sub` line when a table or option calls it by name; otherwise call it or remove it.";
    /// The post states its units (Vectric `UNITS`, VcPost `Postc.Units`, a section post's
    /// `postcOptions.units`), and its text writes the units word of the other system only: `G21`
    /// (millimetres) in a post that writes inches, or `G20` in one that writes millimetres. The
    /// controller then reads every length 25.4 times too small or too large.
    LN017: Warning, "the post states its units but writes only the other system's units word (`G21` in an inch post, `G20` in a millimetre post)",
        example = "UNITS = \"INCHES\"\nbegin HEADER\n\"G21 G90\"",
        fix = "Make the units statement and the units word agree.";
}
