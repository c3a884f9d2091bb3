use postc_report::display::*;
use std::ops::Range;

struct Plain(Vec<usize>, usize);

impl Plain {
    fn of(text: &str) -> Plain {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1).filter(|&i| i < text.len()));
        Plain(starts, text.len())
    }
}

impl Lines for Plain {
    fn line_of(&self, offset: usize) -> usize {
        self.0.partition_point(|&s| s <= offset).saturating_sub(1)
    }
    fn range_of(&self, line: usize) -> Option<Range<usize>> {
        let start = *self.0.get(line)?;
        Some(start..self.0.get(line + 1).copied().unwrap_or(self.1))
    }
}

#[test]
fn short_clean_lines_show_as_they_are() {
    let text = "a = 1\nb = 2\n";
    assert!(shown(text, &Plain::of(text), &[6, 7]).is_none());
}

#[test]
fn long_lines_are_cut_around_the_label() {
    let mut text = String::from("first\n");
    let start = text.len();
    text.push_str(&"x".repeat(10_000));
    text.push_str("BAD");
    text.push_str(&"y".repeat(10_000));
    text.push('\n');
    let bad = start + 10_000;
    let s = shown(&text, &Plain::of(&text), &[bad, bad + 3]).unwrap();
    let line = &s.text[s.line_range(1)];
    assert!(line.chars().count() < 2 * CONTEXT_CHARS + 10, "{line}");
    assert!(line.starts_with('…') && line.trim_end().ends_with('…'), "{line}");
    let (a, b) = (s.to_shown(bad, Side::Start), s.to_shown(bad + 3, Side::End));
    assert_eq!(&s.text[a..b], "BAD");
    assert_eq!(s.to_source(a), bad);
    assert_eq!(s.line_index(a), 1);
}

#[test]
fn a_label_over_a_whole_long_line_keeps_its_ends() {
    let text = format!("{}\n", "z".repeat(50_000_000 / 1000));
    let s = shown(&text, &Plain::of(&text), &[0, text.len() - 1]).unwrap();
    let (a, b) = (s.to_shown(0, Side::Start), s.to_shown(text.len() - 1, Side::End));
    assert!(b - a < 4 * CONTEXT_CHARS, "{}", &s.text[a..b]);
    assert!(s.text[a..b].contains('…'));
}

#[test]
fn control_characters_are_escaped() {
    let text = "G0\u{1b}[31m X1\u{7}\u{202e}\n";
    let s = shown(text, &Plain::of(text), &[2, 3]).unwrap();
    assert_eq!(s.text, "G0␛[31m X1␇\\u{202e}\n");
    assert_eq!(&s.text[s.to_shown(2, Side::Start)..s.to_shown(3, Side::End)], "␛");
    assert_eq!(escape_text("bad \u{1b} here"), "bad ␛ here");
}
