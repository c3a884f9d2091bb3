use postc_front_cimco::testing::strings::*;

#[test]
fn decodes_escapes() {
    assert_eq!(decode(r"a\nb\t\x41\u00B0\'\\").0, "a\nb\tA\u{b0}'\\");
    assert_eq!(decode(r"\uD83D\uDE00").0, "\u{1F600}");
    assert_eq!(decode("a\\\nb").0, "ab");
    assert_eq!(decode(r"\0").0, "\0");
}

#[test]
fn reports_bad_escapes() {
    assert_eq!(decode(r"\x4").1.len(), 1);
    assert_eq!(decode(r"\u12").1.len(), 1);
    assert_eq!(decode(r"\12").1.len(), 1);
    assert_eq!(decode(r"\u{41}").1.len(), 1);
}

#[test]
fn quote_round_trips() {
    for s in ["plain", "a\"b", "back\\slash", "line\nbreak", "\u{1}", "G\u{b0}"] {
        let q = quote(s);
        assert_eq!(decode(&q[1..q.len() - 1]).0, s);
    }
}
