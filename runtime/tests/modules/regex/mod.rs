use postc_runtime::regex::*;

#[test]
fn replaces_like_javascript() {
    let re = Regex::new("[()]", "g").unwrap();
    assert_eq!(replace(&re, "a(b)c", "").unwrap(), "abc");
    let re = Regex::new("(\\d+)mm", "").unwrap();
    assert_eq!(replace(&re, "6mm and 3mm", "$1 millimetres").unwrap(), "6 millimetres and 3mm");
    let re = Regex::new("^\\s+|\\s+$", "g").unwrap();
    assert_eq!(replace(&re, "  x y  ", "").unwrap(), "x y");
    let re = Regex::new("o", "gi").unwrap();
    assert_eq!(replace(&re, "fOo", "0").unwrap(), "f00");
    let re = Regex::new("a*?b", "").unwrap();
    assert_eq!(replace(&re, "aaab", "X").unwrap(), "X");
    // Empty matches advance one character, as JavaScript's do.
    let re = Regex::new("a*", "g").unwrap();
    assert_eq!(replace(&re, "baaac", "-").unwrap(), "-b--c-");
    assert_eq!(replace(&re, "aaa", "X").unwrap(), "XX");
    let re = Regex::new("x", "").unwrap();
    assert_eq!(replace(&re, "axb", "[$&|$$|$0]").unwrap(), "a[x|$|$0]b");
    // What Node.js prints for these replacements.
    let re = Regex::new("(b)", "").unwrap();
    assert_eq!(replace(&re, "abc", "$01").unwrap(), "abc");
    assert_eq!(replace(&re, "abc", "$00|$2|$10").unwrap(), "a$00|$2|b0c");
    assert_eq!(replace(&re, "abc", "[$`|$'|$<x>]").unwrap(), "a[a|c|$<x>]c");
    let re = Regex::new("(?<x>b)", "").unwrap();
    assert_eq!(replace(&re, "abc", "[$<x>|$<y>|$<x]").unwrap(), "a[b||$<x]c");
    let re = Regex::new("(a)(b)(c)(d)(e)(f)(g)(h)(i)(j)", "").unwrap();
    assert_eq!(replace(&re, "abcdefghijk", "[$10|$11|$1]").unwrap(), "[j|a1|a]k");
    assert_eq!(replace_text("abc", "b", "[$`|$'|$&|$$|$1|$<x>]"), "a[a|c|b|$|$1|$<x>]c");
    assert_eq!(replace_text("xx", "", "-"), "-xx");
    assert_eq!(replace_text("xx", "y", "-"), "xx");
}

#[test]
fn searches_count_utf16_units() {
    assert_eq!(search(&Regex::new("b", "").unwrap(), "a\u{1F600}b"), Ok(3.0));
    assert_eq!(search_text("a\u{1F600}b", "b"), Ok(3.0));
    // A text pattern is a regular expression to `search`.
    assert_eq!(search_text("a.b", "."), Ok(0.0));
    assert!(search_text("a", "(").is_err());
}

#[test]
fn properties_and_text() {
    let re = Regex::new("a\\/b", "gi").unwrap();
    assert_eq!(re.to_text(), "/a\\/b/gi");
    assert_eq!(re.property("source"), Some(Property::Text("a\\/b")));
    assert_eq!(re.property("global"), Some(Property::Flag(true)));
    assert_eq!(re.property("multiline"), Some(Property::Flag(false)));
    assert_eq!(re.property("lastIndex"), None);
    assert!(unsupported_member("lastIndex").is_some());
    assert!(re.test("x").unwrap_err().contains("lastIndex"));
    assert_eq!(Regex::new("b", "i").unwrap().test("aB"), Ok(true));
}

#[test]
fn line_anchors_over_other_line_ends_are_refused() {
    let re = Regex::new("^x", "gm").unwrap();
    assert_eq!(replace(&re, "x\nx", "y"), Ok("y\ny".to_string()));
    for text in ["x\rx", "x\u{2028}x", "x\u{2029}x"] {
        assert!(replace(&re, text, "y").unwrap_err().contains("line end"), "{text:?}");
        assert!(split(&re, text).is_err() && search(&re, text).is_err());
    }
    assert!(Regex::new("^x", "m").unwrap().test("a\rx").is_err());
    // Without `m`, or without anchors, `\r` is a character like others.
    assert_eq!(replace(&Regex::new("^x", "g").unwrap(), "x\rx", "y"), Ok("y\rx".to_string()));
    assert_eq!(replace(&Regex::new("x", "gm").unwrap(), "x\rx", "y"), Ok("y\ry".to_string()));
}

#[test]
fn splits_like_javascript() {
    let re = Regex::new(",\\s*", "").unwrap();
    assert_eq!(split(&re, "a, b,c").unwrap(), ["a", "b", "c"]);
    let re = Regex::new("(-)", "").unwrap();
    assert_eq!(split(&re, "a-b").unwrap(), ["a", "-", "b"]);
    let re = Regex::new("", "").unwrap();
    assert_eq!(split(&re, "abc").unwrap(), ["a", "b", "c"]);
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
    // A surrogate pair is the character it encodes; a lone one is refused.
    assert!(Regex::new("a\\ud83d\\ude00b", "").unwrap().is_match("a\u{1F600}b"));
    assert!(Regex::new("\\ud83d", "").is_err());
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
    assert_eq!(replace(&re, &long, "").unwrap(), format!("{}x", "y".repeat(10_000)));
    assert_eq!(search(&re, &long), Ok(10_000.0));
}
