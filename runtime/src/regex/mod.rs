//! JavaScript's regular expressions, for the interpreter and for the
//! CIMCO script host alike (one implementation, one meaning): the pattern
//! translated from JavaScript's syntax and meaning and run by the `regex`
//! crate, and the text methods that take one (`replace`, `split`,
//! `search`, and `test` of a regular expression: [`text`]).
//!
//! The `regex` crate matches in time linear in the text, so no pattern can
//! hang a post and no text is too long. The translation keeps what
//! JavaScript means where the two syntaxes differ (`docs/cimco.md`,
//! "Regular expressions"):
//!
//! - `.` is any character but the line terminators `\n \r \u2028 \u2029`;
//! - `\d \w` are ASCII (`[0-9]`, `[0-9A-Za-z_]`), `\s` is JavaScript's
//!   white space and line terminators, and their capitals are the
//!   complements; `\b \B` are ASCII word boundaries;
//! - `\xHH`, `\uHHHH`, `\cX`, `\0`, `\/` and escaped punctuation;
//! - Annex B leniencies: a `{` that does not start a quantifier and a `]`
//!   outside a class are literal; `[]` matches nothing and `[^]` anything;
//! - flags `g` (every match), `i` (`(?i)`), `m` (`(?m)`).
//!
//! Backreferences (`\1`) and lookaround (`(?=`, `(?!`, `(?<=`, `(?<!`) have
//! no linear-time form: such a pattern is refused with a message naming
//! the construct, never a silent mismatch.
//!
//! A compiled [`Regex`] holds no state: postc's regular expressions keep
//! no `lastIndex`. So one compiled pattern may serve every evaluation of
//! its literal (the runtime compiles a literal once, when the post is
//! prepared), and what depends on `lastIndex` (`exec`, reading or setting
//! `lastIndex`, `test` of a pattern with the `g` flag, which JavaScript
//! starts at the `lastIndex` the previous `test` left) is refused with
//! [`UNSUPPORTED`] rather than answered as if `lastIndex` were 0.

pub mod text;

pub use text::{Match, matches, replace, replace_text, search, search_text, split};

/// The code of a use of a regular expression that depends on the
/// `lastIndex` postc's regular expressions do not keep (`exec`,
/// `lastIndex`, `test` under the `g` flag), or of a replacement given as a
/// function: the post stops there, and a `try` does not catch it.
pub const UNSUPPORTED: &str = "RT038";

/// A regular expression value: one evaluation of a literal. JavaScript
/// makes a new object each time a literal is evaluated, so each value has
/// its own identity (`===`); they share the pattern, compiled once.
#[derive(Debug)]
pub struct RegExp(pub std::rc::Rc<Regex>);

/// A compiled pattern.
#[derive(Debug)]
pub struct Regex {
    /// The pattern as the post wrote it, between the slashes.
    source: String,
    flags: String,
    /// The `m` flag and a `^` or `$` in the pattern: line ends matter.
    line_anchors: bool,
    compiled: regex::Regex,
}

/// JavaScript's `\s`: white space and line terminators.
const JS_SPACE: &str = r"\t\n\x0B\x0C\r \xA0\x{1680}\x{2000}-\x{200A}\x{2028}\x{2029}\x{202F}\x{205F}\x{3000}\x{FEFF}";

/// A property of a regular expression ([`Regex::property`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Property<'r> {
    Text(&'r str),
    Flag(bool),
}

/// What postc says of a method or property of a regular expression it
/// does not run: `exec` and `lastIndex` (state postc does not keep), for
/// [`UNSUPPORTED`].
pub fn unsupported_member(name: &str) -> Option<String> {
    match name {
        "exec" | "lastIndex" => Some(format!(
            "`{name}` of a regular expression reads or moves its `lastIndex`, which postc's regular expressions do not keep"
        )),
        _ => None,
    }
}

/// What postc says of a replacement given as a function, for [`UNSUPPORTED`].
pub const FUNCTION_REPLACEMENT: &str =
    "a function as the replacement of `replace` is not supported; build the text with a loop";

/// Generous compile-size limits: a post's patterns are short, and a huge
/// one is refused rather than allowed to take the memory.
const SIZE_LIMIT: usize = 1 << 20;

impl Regex {
    /// Compiles a JavaScript pattern; `Err` says what is wrong with it.
    pub fn new(source: &str, flags: &str) -> Result<Regex, String> {
        let mut prefix = String::new();
        for f in flags.chars() {
            match f {
                'g' => {}
                'i' => prefix.push('i'),
                'm' => prefix.push('m'),
                other => return Err(format!("the flag `{other}` is not supported (only g, i and m)")),
            }
        }
        let (body, anchors) = translate(source)?;
        let pattern = if prefix.is_empty() { body } else { format!("(?{prefix}){body}") };
        let compiled =
            regex::RegexBuilder::new(&pattern).size_limit(SIZE_LIMIT).dfa_size_limit(SIZE_LIMIT).build().map_err(
                |e| match e {
                    regex::Error::CompiledTooBig(_) => "the regular expression is too large".to_string(),
                    other => format!("the regular expression does not read: {}", first_line(&other.to_string())),
                },
            )?;
        Ok(Regex {
            source: source.to_string(),
            flags: flags.to_string(),
            line_anchors: anchors && flags.contains('m'),
            compiled,
        })
    }

    /// The pattern between the slashes (JavaScript's `source`).
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The flags as written.
    pub fn flags(&self) -> &str {
        &self.flags
    }

    /// Whether a flag is set (`'g'`, `'i'`, `'m'`).
    pub fn has_flag(&self, flag: char) -> bool {
        self.flags.contains(flag)
    }

    /// The `g` flag: `replace` replaces every match.
    pub fn global(&self) -> bool {
        self.has_flag('g')
    }

    /// `String(re)`: `/source/flags`.
    pub fn to_text(&self) -> String {
        format!("/{}/{}", self.source, self.flags)
    }

    /// A property JavaScript gives a regular expression (`source`,
    /// `global`, `ignoreCase`, `multiline`, `flags`), as text or a flag;
    /// `None` for others. `lastIndex` is not one: see [`UNSUPPORTED`].
    pub fn property(&self, name: &str) -> Option<Property<'_>> {
        Some(match name {
            "source" => Property::Text(&self.source),
            "flags" => Property::Text(&self.flags),
            "global" => Property::Flag(self.has_flag('g')),
            "ignoreCase" => Property::Flag(self.has_flag('i')),
            "multiline" => Property::Flag(self.has_flag('m')),
            _ => return None,
        })
    }

    /// `re.test(text)`; `Err` (for [`UNSUPPORTED`]) under the `g` flag,
    /// whose answer depends on the `lastIndex` a previous call left.
    pub fn test(&self, text: &str) -> Result<bool, String> {
        self.check(text)?;
        if self.global() {
            return Err(format!(
                "`test` of {} with the `g` flag starts where the previous `test` stopped (its `lastIndex`), which postc does not keep; drop the `g` flag",
                self.to_text()
            ));
        }
        Ok(self.compiled.is_match(text))
    }

    /// `Ok` when the pattern means in `text` what it means in JavaScript:
    /// under the `m` flag, `^` and `$` of the `regex` crate see only `\n`
    /// as a line end, where JavaScript also sees `\r`, `\u2028` and
    /// `\u2029`; such a pattern over text holding one of those is refused
    /// (for [`UNSUPPORTED`]) rather than matched differently.
    pub fn check(&self, text: &str) -> Result<(), String> {
        if self.line_anchors && text.contains(['\r', '\u{2028}', '\u{2029}']) {
            return Err(format!(
                "{} reads `^` and `$` at line ends, and the text holds a line end other than `\\n` (`\\r`, U+2028 or U+2029), which postc's `^` and `$` do not see",
                self.to_text()
            ));
        }
        Ok(())
    }

    /// The first match at or after byte `from` of `text`, with its groups.
    pub(crate) fn captures_at<'t>(&self, text: &'t str, from: usize) -> Option<regex::Captures<'t>> {
        self.compiled.captures_at(text, from)
    }

    /// Whether the pattern matches anywhere in `text`.
    #[doc(hidden)]
    pub fn is_match(&self, text: &str) -> bool {
        self.compiled.is_match(text)
    }
}

fn first_line(s: &str) -> &str {
    s.lines()
        .rev()
        .find(|l| l.starts_with("error:"))
        .map_or(s.lines().next().unwrap_or(s), |l| l.trim_start_matches("error: "))
}

/// JavaScript pattern syntax to `regex` crate syntax, keeping the meaning;
/// and whether the pattern has a `^` or `$` anchor.
fn translate(source: &str) -> Result<(String, bool), String> {
    let chars: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len() + 16);
    let mut i = 0;
    let mut open_groups = 0usize;
    let mut anchors = false;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '\\' => {
                i += 1;
                let Some(&e) = chars.get(i) else { return Err("the pattern ends with `\\`".into()) };
                i = escape(&chars, i, e, false, &mut out)?;
                continue;
            }
            '.' => out.push_str(r"[^\n\r\x{2028}\x{2029}]"),
            '[' => {
                i = class(&chars, i, &mut out)?;
                continue;
            }
            ']' => out.push_str(r"\]"),
            '{' => {
                if let Some(end) = quantifier_braces(&chars, i) {
                    out.extend(&chars[i..=end]);
                    i = end + 1;
                    continue;
                }
                out.push_str(r"\{");
            }
            '}' => out.push_str(r"\}"),
            '(' => {
                open_groups += 1;
                if chars.get(i + 1) == Some(&'?') {
                    match (chars.get(i + 2), chars.get(i + 3)) {
                        (Some(':'), _) => {
                            out.push_str("(?:");
                            i += 3;
                            continue;
                        }
                        (Some('='), _) | (Some('!'), _) | (Some('<'), Some('=')) | (Some('<'), Some('!')) => {
                            return Err("lookaround (`(?=`, `(?!`, `(?<=`, `(?<!`) is not supported".into());
                        }
                        (Some('<'), _) => {
                            out.push_str("(?P<");
                            i += 3;
                            continue;
                        }
                        _ => return Err("`(?` starts no group JavaScript knows".into()),
                    }
                }
                out.push('(');
            }
            ')' => {
                if open_groups == 0 {
                    return Err("unmatched `)`".into());
                }
                open_groups -= 1;
                out.push(')');
            }
            '#' | '&' | '~' | '-' => {
                out.push('\\');
                out.push(c);
            }
            '^' | '$' => {
                anchors = true;
                out.push(c);
            }
            _ => out.push(c),
        }
        i += 1;
    }
    Ok((out, anchors))
}

/// `{n}`, `{n,}` or `{n,m}` at `start`: the index of its `}`.
fn quantifier_braces(chars: &[char], start: usize) -> Option<usize> {
    let mut i = start + 1;
    let digits = |i: &mut usize| {
        let from = *i;
        while chars.get(*i).is_some_and(char::is_ascii_digit) {
            *i += 1;
        }
        *i > from
    };
    if !digits(&mut i) {
        return None;
    }
    if chars.get(i) == Some(&',') {
        i += 1;
        digits(&mut i);
    }
    (chars.get(i) == Some(&'}')).then_some(i)
}

/// An escape whose letter is at `i`; the index after it.
fn escape(chars: &[char], i: usize, e: char, in_class: bool, out: &mut String) -> Result<usize, String> {
    let class_or_set = |set: &str, negated: bool, out: &mut String| {
        // Inside a class, a nested class is a union in the `regex` crate.
        out.push('[');
        if negated {
            out.push('^');
        }
        out.push_str(set);
        out.push(']');
    };
    match e {
        'd' | 'D' => class_or_set("0-9", e == 'D', out),
        'w' | 'W' => class_or_set("0-9A-Za-z_", e == 'W', out),
        's' | 'S' => class_or_set(JS_SPACE, e == 'S', out),
        'b' if in_class => out.push_str(r"\x08"),
        'b' => out.push_str(r"(?-u:\b)"),
        'B' if !in_class => out.push_str(r"(?-u:\B)"),
        'n' => out.push_str(r"\n"),
        'r' => out.push_str(r"\r"),
        't' => out.push_str(r"\t"),
        'v' => out.push_str(r"\x0B"),
        'f' => out.push_str(r"\x0C"),
        '0' if !chars.get(i + 1).is_some_and(char::is_ascii_digit) => out.push_str(r"\x00"),
        '1'..='9' if !in_class => return Err(format!("the backreference `\\{e}` is not supported")),
        'x' | 'u' => {
            let len = if e == 'x' { 2 } else { 4 };
            let hex_at = |at: usize| -> Option<u32> {
                let hex: String = chars.iter().skip(at).take(len).collect();
                (hex.len() == len && hex.chars().all(|h| h.is_ascii_hexdigit()))
                    .then(|| u32::from_str_radix(&hex, 16).ok())
                    .flatten()
            };
            if let Some(unit) = hex_at(i + 1) {
                // A surrogate pair written as two escapes is the one
                // character it encodes (postc's texts hold characters,
                // not UTF-16 units); a lone surrogate matches no
                // character and is refused by the `regex` crate.
                let pair = e == 'u'
                    && !in_class
                    && (0xD800..0xDC00).contains(&unit)
                    && chars.get(i + 5) == Some(&'\\')
                    && chars.get(i + 6) == Some(&'u');
                let low = pair.then(|| hex_at(i + 7)).flatten().filter(|low| (0xDC00..0xE000).contains(low));
                if let Some(low) = low {
                    let c = 0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00);
                    out.push_str(&format!(r"\x{{{c:X}}}"));
                    return Ok(i + 11);
                }
                out.push_str(&format!(r"\x{{{unit:X}}}"));
                return Ok(i + 1 + len);
            }
            out.push(e);
        }
        'c' if chars.get(i + 1).is_some_and(char::is_ascii_alphabetic) => {
            let letter = chars[i + 1] as u32;
            out.push_str(&format!(r"\x{:02X}", letter % 32));
            return Ok(i + 2);
        }
        _ if e.is_ascii_alphanumeric() => out.push(e),
        // Escaped punctuation is itself (`regex::escape` escapes what is
        // special to the `regex` crate: `& ~ - #` included).
        _ => out.push_str(&regex::escape(e.encode_utf8(&mut [0; 4]))),
    }
    Ok(i + 1)
}

/// A class `[...]` starting at `start`; the index after its `]`.
fn class(chars: &[char], start: usize, out: &mut String) -> Result<usize, String> {
    let mut i = start + 1;
    let negated = chars.get(i) == Some(&'^');
    if negated {
        i += 1;
    }
    if chars.get(i) == Some(&']') {
        // `[]` matches nothing, `[^]` any character.
        out.push_str(if negated { r"[\x00-\x{10FFFF}]" } else { r"[^\x00-\x{10FFFF}]" });
        return Ok(i + 1);
    }
    out.push('[');
    if negated {
        out.push('^');
    }
    while i < chars.len() {
        let c = chars[i];
        match c {
            ']' => {
                out.push(']');
                return Ok(i + 1);
            }
            '\\' => {
                i += 1;
                let Some(&e) = chars.get(i) else { break };
                i = escape(chars, i, e, true, out)?;
                continue;
            }
            '[' | '&' | '~' | '^' => {
                out.push('\\');
                out.push(c);
            }
            '-' if i == start + 1 + usize::from(negated) || chars.get(i + 1) == Some(&']') => out.push_str(r"\-"),
            _ => out.push(c),
        }
        i += 1;
    }
    Err("a character class `[` has no closing `]`".into())
}
