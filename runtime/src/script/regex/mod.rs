//! The regular expressions posts use in `replace`, `split`, `search` and
//! `test`: literals, `.`, classes (`[()]`, `[^0-9]`, `\d \w \s` and their
//! capitals), anchors `^ $`, groups `( )` and `(?: )`, alternation `|`,
//! and the quantifiers `* + ? {n} {n,} {n,m}` (greedy, or lazy with `?`);
//! flags `g`, `i`, `m`. A backtracking matcher over characters, with a
//! step limit so that a pathological pattern cannot hang a post.

use std::cell::Cell;

/// A compiled pattern.
#[derive(Debug)]
pub struct Regex {
    pub source: String,
    node: Node,
    pub global: bool,
    ignore_case: bool,
    multiline: bool,
    groups: usize,
}

#[derive(Debug, Clone)]
enum Node {
    Empty,
    Char(char),
    Any,
    Class(Vec<ClassItem>, bool),
    Start,
    End,
    Group(Box<Node>, Option<usize>),
    Concat(Vec<Node>),
    Alt(Vec<Node>),
    Repeat { node: Box<Node>, min: usize, max: usize, lazy: bool },
}

#[derive(Debug, Clone)]
enum ClassItem {
    Range(char, char),
    Digit(bool),
    Word(bool),
    Space(bool),
}

/// A match: the span of the whole match and of each group, in characters.
pub type Captures = Vec<Option<(usize, usize)>>;

const MAX_STEPS: usize = 1_000_000;
/// Longer texts are not matched.
const MAX_TEXT: usize = 4096;

impl Regex {
    /// Compiles a pattern; `Err` says what is wrong with it.
    pub fn new(source: &str, flags: &str) -> Result<Regex, String> {
        let chars: Vec<char> = source.chars().collect();
        let mut p = Parser { chars: &chars, pos: 0, groups: 0 };
        let node = p.alt()?;
        if p.pos < chars.len() {
            return Err(format!("unexpected `{}` in the regular expression", chars[p.pos]));
        }
        Ok(Regex {
            source: format!("/{source}/{flags}"),
            node,
            global: flags.contains('g'),
            ignore_case: flags.contains('i'),
            multiline: flags.contains('m'),
            groups: p.groups,
        })
    }

    /// The first match at or after character `from`.
    pub fn find_at(&self, text: &[char], from: usize) -> Option<Captures> {
        if text.len() > MAX_TEXT {
            // Matching recurses per character; such texts are not posts'.
            return None;
        }
        let m = Matcher { re: self, text, steps: Cell::new(0) };
        for start in from..=text.len() {
            let mut caps = vec![None; self.groups + 1];
            if let Some(end) = m.run(&self.node, start, &mut caps, &mut |_, e| Some(e)) {
                caps[0] = Some((start, end));
                return Some(caps);
            }
            if m.steps.get() > MAX_STEPS {
                return None;
            }
        }
        None
    }
}

struct Parser<'c> {
    chars: &'c [char],
    pos: usize,
    groups: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }

    fn alt(&mut self) -> Result<Node, String> {
        let mut options = vec![self.concat()?];
        while self.peek() == Some('|') {
            self.pos += 1;
            options.push(self.concat()?);
        }
        Ok(if options.len() == 1 { options.pop().unwrap_or(Node::Empty) } else { Node::Alt(options) })
    }

    fn concat(&mut self) -> Result<Node, String> {
        let mut items = Vec::new();
        while let Some(c) = self.peek() {
            if c == '|' || c == ')' {
                break;
            }
            let atom = self.atom()?;
            items.push(self.quantified(atom)?);
        }
        Ok(Node::Concat(items))
    }

    fn quantified(&mut self, atom: Node) -> Result<Node, String> {
        let (min, max) = match self.peek() {
            Some('*') => (0, usize::MAX),
            Some('+') => (1, usize::MAX),
            Some('?') => (0, 1),
            Some('{') => {
                let save = self.pos;
                match self.braces() {
                    Some(r) => {
                        self.pos -= 1;
                        r
                    }
                    None => {
                        self.pos = save;
                        return Ok(atom);
                    }
                }
            }
            _ => return Ok(atom),
        };
        self.pos += 1;
        let lazy = self.peek() == Some('?');
        if lazy {
            self.pos += 1;
        }
        Ok(Node::Repeat { node: Box::new(atom), min, max, lazy })
    }

    /// `{n}`, `{n,}`, `{n,m}`; leaves `pos` after the `}`.
    fn braces(&mut self) -> Option<(usize, usize)> {
        self.pos += 1;
        let num = |p: &mut Self| {
            let start = p.pos;
            while p.peek().is_some_and(|c| c.is_ascii_digit()) {
                p.pos += 1;
            }
            p.chars[start..p.pos].iter().collect::<String>().parse::<usize>().ok()
        };
        let min = num(self)?;
        let max = if self.peek() == Some(',') {
            self.pos += 1;
            num(self).unwrap_or(usize::MAX)
        } else {
            min
        };
        (self.peek() == Some('}')).then(|| {
            self.pos += 1;
            (min, max)
        })
    }

    fn atom(&mut self) -> Result<Node, String> {
        let Some(c) = self.peek() else { return Ok(Node::Empty) };
        self.pos += 1;
        Ok(match c {
            '.' => Node::Any,
            '^' => Node::Start,
            '$' => Node::End,
            '(' => {
                let index = if self.chars[self.pos..].starts_with(&['?', ':']) {
                    self.pos += 2;
                    None
                } else {
                    self.groups += 1;
                    Some(self.groups)
                };
                let inner = self.alt()?;
                if self.peek() != Some(')') {
                    return Err("a `(` in the regular expression is not closed".into());
                }
                self.pos += 1;
                Node::Group(Box::new(inner), index)
            }
            '[' => self.class()?,
            '\\' => self.escape(false)?,
            '*' | '+' | '?' => return Err(format!("`{c}` has nothing to repeat")),
            c => Node::Char(c),
        })
    }

    fn escape(&mut self, in_class: bool) -> Result<Node, String> {
        let Some(c) = self.peek() else { return Err("a `\\` ends the regular expression".into()) };
        self.pos += 1;
        let class = |item| Node::Class(vec![item], false);
        Ok(match c {
            'd' => class(ClassItem::Digit(true)),
            'D' => class(ClassItem::Digit(false)),
            'w' => class(ClassItem::Word(true)),
            'W' => class(ClassItem::Word(false)),
            's' => class(ClassItem::Space(true)),
            'S' => class(ClassItem::Space(false)),
            'n' => Node::Char('\n'),
            'r' => Node::Char('\r'),
            't' => Node::Char('\t'),
            'b' if in_class => Node::Char('\u{8}'),
            c => Node::Char(c),
        })
    }

    fn class(&mut self) -> Result<Node, String> {
        let negated = self.peek() == Some('^');
        if negated {
            self.pos += 1;
        }
        let mut items = Vec::new();
        let mut first = true;
        loop {
            let Some(c) = self.peek() else { return Err("a `[` in the regular expression is not closed".into()) };
            if c == ']' && !first {
                self.pos += 1;
                break;
            }
            first = false;
            self.pos += 1;
            let lo = if c == '\\' {
                match self.escape(true)? {
                    Node::Char(ch) => ch,
                    Node::Class(mut inner, _) => {
                        items.append(&mut inner);
                        continue;
                    }
                    _ => continue,
                }
            } else {
                c
            };
            if self.peek() == Some('-') && self.chars.get(self.pos + 1).is_some_and(|&n| n != ']') {
                self.pos += 1;
                let mut hi = self.peek().unwrap_or(lo);
                self.pos += 1;
                if hi == '\\'
                    && let Node::Char(ch) = self.escape(true)?
                {
                    hi = ch;
                }
                items.push(ClassItem::Range(lo, hi));
            } else {
                items.push(ClassItem::Range(lo, lo));
            }
        }
        Ok(Node::Class(items, negated))
    }
}

struct Matcher<'r, 't> {
    re: &'r Regex,
    text: &'t [char],
    steps: Cell<usize>,
}

type Cont<'k> = dyn FnMut(&mut Captures, usize) -> Option<usize> + 'k;

impl Matcher<'_, '_> {
    fn eq(&self, a: char, b: char) -> bool {
        a == b || (self.re.ignore_case && a.to_lowercase().eq(b.to_lowercase()))
    }

    fn class_has(&self, items: &[ClassItem], c: char) -> bool {
        items.iter().any(|i| match *i {
            ClassItem::Range(lo, hi) => {
                (lo..=hi).contains(&c)
                    || (self.re.ignore_case && c.to_lowercase().chain(c.to_uppercase()).any(|x| (lo..=hi).contains(&x)))
            }
            ClassItem::Digit(yes) => c.is_ascii_digit() == yes,
            ClassItem::Word(yes) => (c.is_ascii_alphanumeric() || c == '_') == yes,
            ClassItem::Space(yes) => c.is_whitespace() == yes,
        })
    }

    /// Matches `node` at `at`, then the continuation `k`.
    fn run(&self, node: &Node, at: usize, caps: &mut Captures, k: &mut Cont) -> Option<usize> {
        self.steps.set(self.steps.get() + 1);
        if self.steps.get() > MAX_STEPS {
            return None;
        }
        let text = self.text;
        match node {
            Node::Empty => k(caps, at),
            Node::Char(c) => {
                if at < text.len() && self.eq(text[at], *c) { k(caps, at + 1) } else { None }
            }
            Node::Any => {
                if at < text.len() && text[at] != '\n' { k(caps, at + 1) } else { None }
            }
            Node::Class(items, neg) => {
                if at < text.len() && self.class_has(items, text[at]) != *neg { k(caps, at + 1) } else { None }
            }
            Node::Start => {
                if at == 0 || (self.re.multiline && text[at - 1] == '\n') { k(caps, at) } else { None }
            }
            Node::End => {
                if at == text.len() || (self.re.multiline && text[at] == '\n') { k(caps, at) } else { None }
            }
            Node::Group(inner, index) => {
                let index = *index;
                self.run(inner, at, caps, &mut |caps: &mut Captures, end| {
                    let saved = index.and_then(|i| caps[i]);
                    if let Some(i) = index {
                        caps[i] = Some((at, end));
                    }
                    let r = k(caps, end);
                    if r.is_none()
                        && let Some(i) = index
                    {
                        caps[i] = saved;
                    }
                    r
                })
            }
            Node::Concat(items) => self.concat(items, at, caps, k),
            Node::Alt(options) => options.iter().find_map(|o| self.run(o, at, caps, k)),
            Node::Repeat { node, min, max, lazy } => self.repeat(node, (*min, *max, *lazy), at, 0, caps, k),
        }
    }

    fn concat(&self, items: &[Node], at: usize, caps: &mut Captures, k: &mut Cont) -> Option<usize> {
        match items.split_first() {
            None => k(caps, at),
            Some((first, rest)) => self.run(first, at, caps, &mut |caps: &mut Captures, end| self.concat(rest, end, caps, k)),
        }
    }

    fn repeat(&self, node: &Node, bounds: (usize, usize, bool), at: usize, count: usize, caps: &mut Captures, k: &mut Cont) -> Option<usize> {
        let (min, max, lazy) = bounds;
        let more = |caps: &mut Captures, k: &mut Cont| -> Option<usize> {
            if count >= max {
                return None;
            }
            self.run(node, at, caps, &mut |caps: &mut Captures, end| {
                if end == at && count >= min {
                    // An empty repetition would loop forever.
                    return None;
                }
                self.repeat(node, bounds, end, count + 1, caps, k)
            })
        };
        if count < min {
            return more(caps, k);
        }
        if lazy {
            if let Some(e) = k(caps, at) {
                return Some(e);
            }
            more(caps, k)
        } else {
            if let Some(e) = more(caps, k) {
                return Some(e);
            }
            k(caps, at)
        }
    }
}

mod text;

pub use text::{replace, split};

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
    }

    #[test]
    fn splits_like_javascript() {
        let re = Regex::new(",\\s*", "").unwrap();
        assert_eq!(split(&re, "a, b,c"), ["a", "b", "c"]);
        assert!(Regex::new("(", "").is_err());
        assert!(Regex::new("*", "").is_err());
    }

    #[test]
    fn pathological_patterns_stop() {
        let re = Regex::new("(a*)*b", "").unwrap();
        let text: Vec<char> = "a".repeat(40).chars().collect();
        assert!(re.find_at(&text, 0).is_none());
    }
}
