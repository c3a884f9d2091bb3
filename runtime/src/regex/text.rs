//! `replace`, `split` and `search` as JavaScript does them, with a
//! regular expression or a text as the pattern: every match under the `g`
//! flag, else the first (a text pattern replaces its first occurrence); an
//! empty match moves on by one character; `split` keeps the groups;
//! `search` counts UTF-16 units. A replacement reads `$$`, `$&`,
//! `` $` `` (the text before the match), `$'` (the text after it),
//! `$1`..`$99` (a group the pattern has; `$01` is `$1`) and `$<name>` (a
//! named group, when the pattern has named groups); anything else is
//! itself, as JavaScript's `GetSubstitution` reads it.

use super::Regex;

/// The first match at or after `from`, moving past empty matches as
/// JavaScript's `lastIndex` does.
fn next_after(text: &str, at: usize) -> usize {
    text[at..].chars().next().map_or(text.len() + 1, |c| at + c.len_utf8())
}

/// What a replacement can name of one match.
struct Found<'t> {
    text: &'t str,
    /// The match and its groups (absent when a group took no part).
    groups: Vec<Option<(usize, usize)>>,
    /// The group names of the pattern, when it has named groups.
    names: Option<Vec<Option<&'t str>>>,
}

impl Found<'_> {
    fn group(&self, n: usize) -> &str {
        self.groups.get(n).copied().flatten().map_or("", |(a, b)| &self.text[a..b])
    }
}

/// `text.replace(re, replacement)`; `Err` when postc cannot give
/// JavaScript's answer ([`Regex::check`]).
pub fn replace(re: &Regex, text: &str, replacement: &str) -> Result<String, String> {
    re.check(text)?;
    let mut out = String::with_capacity(text.len());
    let mut last = 0;
    let mut pos = 0;
    let named = re.compiled.capture_names().any(|n| n.is_some());
    while pos <= text.len() {
        let Some(caps) = re.captures_at(text, pos) else { break };
        let whole = caps.get(0).expect("group 0 is the match");
        out.push_str(&text[last..whole.start()]);
        let found = Found {
            text,
            groups: caps.iter().map(|g| g.map(|m| (m.start(), m.end()))).collect(),
            names: named.then(|| re.compiled.capture_names().collect()),
        };
        expand(replacement, &found, &mut out);
        last = whole.end();
        pos = if whole.is_empty() { next_after(text, whole.end()) } else { whole.end() };
        if !re.global() {
            break;
        }
    }
    out.push_str(&text[last.min(text.len())..]);
    Ok(out)
}

/// One match of a pattern: where it is (bytes) and its groups' texts
/// (`None` for a group that took no part), the match itself first.
#[derive(Debug, Clone, PartialEq)]
pub struct Match {
    pub start: usize,
    pub end: usize,
    pub groups: Vec<Option<String>>,
}

impl Match {
    /// The UTF-16 index of the match in `text`, as JavaScript counts it.
    pub fn index(&self, text: &str) -> f64 {
        utf16_len(&text[..self.start])
    }
}

/// The matches `replace` and `match` see: every one under the `g` flag
/// (an empty match moves on by one character), else the first; `Err` as
/// for [`replace`].
pub fn matches(re: &Regex, text: &str) -> Result<Vec<Match>, String> {
    re.check(text)?;
    let mut out = Vec::new();
    let mut pos = 0;
    while pos <= text.len() {
        let Some(caps) = re.captures_at(text, pos) else { break };
        let whole = caps.get(0).expect("group 0 is the match");
        out.push(Match {
            start: whole.start(),
            end: whole.end(),
            groups: caps.iter().map(|g| g.map(|m| m.as_str().to_string())).collect(),
        });
        pos = if whole.is_empty() { next_after(text, whole.end()) } else { whole.end() };
        if !re.global() {
            break;
        }
    }
    Ok(out)
}

/// `text.replace(pattern, replacement)` with a text pattern: its first
/// occurrence, the replacement read as for a pattern without groups.
pub fn replace_text(text: &str, pattern: &str, replacement: &str) -> String {
    let Some(at) = text.find(pattern) else { return text.to_string() };
    let mut out = String::with_capacity(text.len() + replacement.len());
    out.push_str(&text[..at]);
    let found = Found { text, groups: vec![Some((at, at + pattern.len()))], names: None };
    expand(replacement, &found, &mut out);
    out.push_str(&text[at + pattern.len()..]);
    out
}

/// The replacement of one match, its `$` patterns read.
fn expand(replacement: &str, found: &Found<'_>, out: &mut String) {
    let r = replacement.as_bytes();
    let groups = found.groups.len() - 1;
    let (start, end) = found.groups[0].unwrap_or((0, 0));
    let mut i = 0;
    let mut literal_from = 0;
    while i < r.len() {
        if r[i] != b'$' || i + 1 >= r.len() {
            i += 1;
            continue;
        }
        let digit = |k: usize| r.get(k).filter(|c| c.is_ascii_digit()).map(|c| usize::from(c - b'0'));
        let (taken, consumed): (&str, usize) = match r[i + 1] {
            b'$' => ("$", 2),
            b'&' => (&found.text[start..end], 2),
            b'`' => (&found.text[..start], 2),
            b'\'' => (&found.text[end..], 2),
            b'0'..=b'9' => {
                let one = digit(i + 1).unwrap_or(0);
                // Two digits when that group exists, as JavaScript reads `$10`.
                match digit(i + 2).map(|d| one * 10 + d).filter(|&n| n >= 1 && n <= groups) {
                    Some(n) => (found.group(n), 3),
                    None if one >= 1 && one <= groups => (found.group(one), 2),
                    None => ("", 0),
                }
            }
            b'<' => match (&found.names, replacement[i + 2..].find('>')) {
                (Some(names), Some(close)) => {
                    let name = &replacement[i + 2..i + 2 + close];
                    let n = names.iter().position(|n| *n == Some(name));
                    (n.map_or("", |n| found.group(n)), close + 3)
                }
                _ => ("", 0),
            },
            _ => ("", 0),
        };
        if consumed == 0 {
            i += 1;
            continue;
        }
        out.push_str(&replacement[literal_from..i]);
        out.push_str(taken);
        i += consumed;
        literal_from = i;
    }
    out.push_str(&replacement[literal_from..]);
}

/// `text.split(re)`: the parts between matches, and each match's groups;
/// `Err` as for [`replace`].
pub fn split(re: &Regex, text: &str) -> Result<Vec<String>, String> {
    re.check(text)?;
    if text.is_empty() {
        // JavaScript: an empty text splits into nothing when the pattern
        // matches it, else into one empty part.
        return Ok(if re.is_match(text) { Vec::new() } else { vec![String::new()] });
    }
    let mut parts = Vec::new();
    let mut last = 0;
    let mut pos = 0;
    while pos < text.len() {
        let Some(caps) = re.captures_at(text, pos) else { break };
        let whole = caps.get(0).expect("group 0 is the match");
        if whole.end() >= text.len() && whole.is_empty() {
            break;
        }
        if whole.end() == last || (whole.is_empty() && whole.start() == last) {
            pos = next_after(text, pos.max(whole.start()));
            continue;
        }
        parts.push(text[last..whole.start()].to_string());
        for group in caps.iter().skip(1) {
            parts.push(group.map_or(String::new(), |m| m.as_str().to_string()));
        }
        last = whole.end();
        pos = if whole.is_empty() { next_after(text, last) } else { last };
    }
    parts.push(text[last..].to_string());
    Ok(parts)
}

/// `text.search(re)`: the UTF-16 index of the first match, or -1; `Err`
/// as for [`replace`].
pub fn search(re: &Regex, text: &str) -> Result<f64, String> {
    re.check(text)?;
    Ok(re.captures_at(text, 0).and_then(|c| c.get(0)).map_or(-1.0, |m| utf16_len(&text[..m.start()])))
}

/// `text.search(pattern)` with a text pattern: JavaScript makes it a
/// regular expression, so it must compile as one (`Err` says why not;
/// without flags, [`Regex::check`] has nothing to refuse).
pub fn search_text(text: &str, pattern: &str) -> Result<f64, String> {
    Regex::new(pattern, "").and_then(|re| search(&re, text))
}

fn utf16_len(s: &str) -> f64 {
    s.encode_utf16().count() as f64
}
