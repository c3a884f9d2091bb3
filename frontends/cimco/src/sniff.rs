//! Content sniffing: does a file look like a CIMCO CNC-Calc post?
//!
//! Used to find the dialect of a post whose extension does not say. A
//! CIMCO post declares the functions CNC-Calc calls (`function onLinear`,
//! `function onCircular`, ...) or builds its formats with `createFormat(` /
//! `createVariable(`, or fills `MillDrillingFields` / `TurnDrillingFields`.
//! Vectric `.pp` and VcPost files contain none of these outside comments.

/// Functions CNC-Calc calls; a post that declares one is a CIMCO post.
const HANDLERS: &[&str] = &[
    "onInit",
    "onOpen",
    "onClose",
    "onLinear",
    "onCircular",
    "onRapid",
    "onCompensation",
    "onDrillingHeader",
    "onDrillingPoint",
    "onDrillingFooter",
    "onDrilling",
];

/// Calls and globals only CIMCO posts use.
const CALLS: &[&str] = &["createFormat", "createVariable"];
const GLOBALS: &[&str] = &["MillDrillingFields", "TurnDrillingFields"];

/// Only the start of a file is looked at.
const SNIFF_LIMIT: usize = 256 * 1024;

/// Whether `bytes` look like a CIMCO CNC-Calc JavaScript post.
pub fn looks_like_cimco(bytes: &[u8]) -> bool {
    let bytes = &bytes[..bytes.len().min(SNIFF_LIMIT)];
    let text = String::from_utf8_lossy(bytes);
    let words = Words { text: &text, pos: 0 };
    let mut previous = "";
    for (word, rest) in words {
        let next_is_paren = rest.trim_start().starts_with('(');
        if previous == "function" && HANDLERS.contains(&word) && next_is_paren {
            return true;
        }
        if CALLS.contains(&word) && next_is_paren {
            return true;
        }
        if GLOBALS.contains(&word) && rest.trim_start().starts_with('=') {
            return true;
        }
        previous = word;
    }
    false
}

/// The identifier-like words of a text, each with the text after it.
/// Comments and strings are not told apart; the markers are specific
/// enough.
struct Words<'a> {
    text: &'a str,
    pos: usize,
}

impl<'a> Iterator for Words<'a> {
    type Item = (&'a str, &'a str);

    fn next(&mut self) -> Option<Self::Item> {
        let is_word = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '$';
        let rest = &self.text[self.pos..];
        let start = self.pos + rest.find(is_word)?;
        let len = self.text[start..].find(|c: char| !is_word(c)).unwrap_or(self.text.len() - start);
        self.pos = start + len;
        Some((&self.text[start..start + len], &self.text[start + len..]))
    }
}
