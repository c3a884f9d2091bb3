//! The regular expressions posts use in `replace`, `split`, `search` and
//! `test`, run by the `regex` crate after a translation from JavaScript's
//! syntax and meaning.
//!
//! The `regex` crate matches in time linear in the text, so no pattern can
//! hang a post and no text is too long (the hand-written backtracker this
//! replaces gave up silently past 4,096 characters and on a step overflow).
//! The translation keeps what JavaScript means where the two syntaxes
//! differ (`docs/cimco.md`, "Regular expressions"):
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
//! no linear-time form: such a pattern is a `SyntaxError` naming the
//! construct, never a silent mismatch.

mod text;

pub use text::{replace, search, split};

/// A compiled pattern.
#[derive(Debug)]
pub struct Regex {
    /// The pattern as the post wrote it, `/source/flags`.
    pub source: String,
    pub global: bool,
    compiled: regex::Regex,
}

/// JavaScript's `\s`: white space and line terminators.
const JS_SPACE: &str = r"\t\n\x0B\x0C\r \xA0\x{1680}\x{2000}-\x{200A}\x{2028}\x{2029}\x{202F}\x{205F}\x{3000}\x{FEFF}";

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
        let body = translate(source)?;
        let pattern = if prefix.is_empty() { body } else { format!("(?{prefix}){body}") };
        let compiled =
            regex::RegexBuilder::new(&pattern).size_limit(SIZE_LIMIT).dfa_size_limit(SIZE_LIMIT).build().map_err(
                |e| match e {
                    regex::Error::CompiledTooBig(_) => "the regular expression is too large".to_string(),
                    other => format!("the regular expression does not read: {}", first_line(&other.to_string())),
                },
            )?;
        Ok(Regex { source: format!("/{source}/{flags}"), global: flags.contains('g'), compiled })
    }

    /// The first match at or after byte `from` of `text`, with its groups.
    pub fn captures_at<'t>(&self, text: &'t str, from: usize) -> Option<regex::Captures<'t>> {
        self.compiled.captures_at(text, from)
    }

    /// Whether the pattern matches anywhere in `text`.
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

/// JavaScript pattern syntax to `regex` crate syntax, keeping the meaning.
fn translate(source: &str) -> Result<String, String> {
    let chars: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len() + 16);
    let mut i = 0;
    let mut open_groups = 0usize;
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
            _ => out.push(c),
        }
        i += 1;
    }
    Ok(out)
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
            let hex: String = chars.iter().skip(i + 1).take(len).collect();
            if hex.len() == len && hex.chars().all(|h| h.is_ascii_hexdigit()) {
                out.push_str(&format!(r"\x{{{hex}}}"));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_like_javascript() {
        let re = Regex::new("[()]", "g").unwrap();
        assert_eq!(replace(&re, "a(b)c", ""), "abc");
        let re = Regex::new("(\\d+)mm", "").unwrap();
        assert_eq!(replace(&re, "6mm and 3mm", "$1 millimetres"), "6 millimetres and 3mm");
        let re = Regex::new("^\\s+|\\s+$", "g").unwrap();
        assert_eq!(replace(&re, "  x y  ", ""), "x y");
        let re = Regex::new("o", "gi").unwrap();
        assert_eq!(replace(&re, "fOo", "0"), "f00");
        let re = Regex::new("a*?b", "").unwrap();
        assert_eq!(replace(&re, "aaab", "X"), "X");
        // Empty matches advance one character, as JavaScript's do.
        let re = Regex::new("a*", "g").unwrap();
        assert_eq!(replace(&re, "baaac", "-"), "-b--c-");
        assert_eq!(replace(&re, "aaa", "X"), "XX");
        let re = Regex::new("x", "").unwrap();
        assert_eq!(replace(&re, "axb", "[$&|$$|$0]"), "a[x|$|$0]b");
    }

    #[test]
    fn splits_like_javascript() {
        let re = Regex::new(",\\s*", "").unwrap();
        assert_eq!(split(&re, "a, b,c"), ["a", "b", "c"]);
        let re = Regex::new("(-)", "").unwrap();
        assert_eq!(split(&re, "a-b"), ["a", "-", "b"]);
        let re = Regex::new("", "").unwrap();
        assert_eq!(split(&re, "abc"), ["a", "b", "c"]);
        assert!(Regex::new("(", "").is_err());
        assert!(Regex::new("*", "").is_err());
    }

    #[test]
    fn javascript_meaning_is_kept() {
        // `.` stops at line terminators; `\d` and `\w` are ASCII.
        assert!(!Regex::new("^.$", "").unwrap().is_match("\r"));
        assert!(!Regex::new("\\d", "").unwrap().is_match("\u{0663}"));
        assert!(Regex::new("^\\s$", "").unwrap().is_match("\u{FEFF}"));
        // Annex B: lone braces and brackets are literal; `[]` and `[^]`.
        assert!(Regex::new("a{", "").unwrap().is_match("a{"));
        assert!(Regex::new("a]", "").unwrap().is_match("a]"));
        assert!(!Regex::new("[]", "").unwrap().is_match("abc"));
        assert!(Regex::new("^[^]$", "").unwrap().is_match("\n"));
        assert!(Regex::new("^\\x41\\u0042\\cA$", "").unwrap().is_match("AB\u{1}"));
        assert!(Regex::new("[&~-]", "").unwrap().is_match("~"));
        assert!(Regex::new("\\/", "").unwrap().is_match("a/b"));
        assert!(Regex::new("^a b$", "").unwrap().is_match("a b"));
        assert!(Regex::new("\\bx", "").unwrap().is_match("a x"));
        assert!(Regex::new("^x$", "m").unwrap().is_match("a\nx\nb"));
    }

    #[test]
    fn what_has_no_linear_form_is_refused() {
        assert!(Regex::new("(a)\\1", "").unwrap_err().contains("backreference"));
        assert!(Regex::new("a(?=b)", "").unwrap_err().contains("lookaround"));
        assert!(Regex::new("(?<!a)b", "").unwrap_err().contains("lookaround"));
        assert!(Regex::new("a", "y").unwrap_err().contains("flag"));
    }

    #[test]
    fn pathological_patterns_and_long_texts_are_linear() {
        let re = Regex::new("(a*)*b", "").unwrap();
        assert!(!re.is_match(&"a".repeat(100_000)));
        // Texts past the old 4,096-character limit match.
        let long = format!("{}(x)", "y".repeat(10_000));
        let re = Regex::new("[()]", "g").unwrap();
        assert_eq!(replace(&re, &long, ""), format!("{}x", "y".repeat(10_000)));
        assert_eq!(search(&re, &long), 10_000);
    }
}
