use postc_front_vcpost::csv::*;
use postc_ir::{FileId, Span};

fn cells(line: &str) -> Vec<(Option<String>, String, bool)> {
    split(line, 0, FileId(0)).unwrap().into_iter().map(|f| (f.name.map(|n| n.0), f.value, f.quoted)).collect()
}

#[test]
fn splits_names_quotes_and_blanks() {
    let got = cells(r#" WallThick , 10, Y = -2.5 ,"a, ""b""",Note="x=1", , "#);
    let want = vec![
        (None, "WallThick".to_string(), false),
        (None, "10".into(), false),
        (Some("Y".into()), "-2.5".into(), false),
        (None, "a, \"b\"".into(), true),
        (Some("Note".into()), "x=1".into(), true),
    ];
    assert_eq!(got, want);
    assert_eq!(
        cells("Rapid,,1"),
        vec![(None, "Rapid".into(), false), (None, "".into(), false), (None, "1".into(), false)]
    );
    assert_eq!(cells("a b=1"), vec![(None, "a b=1".into(), false)]);
}

#[test]
fn refuses_broken_quotes() {
    for bad in [r#"A,"open"#, r#"A,x"y"#, r#"A,"x"y"#] {
        let d = split(bad, 0, FileId(0)).unwrap_err();
        assert_eq!(d.code, BAD_QUOTE, "{bad}");
    }
}

#[test]
fn spans_point_at_values() {
    let f = split("Move, X=12", 100, FileId(0)).unwrap();
    assert_eq!(f[1].value_span, Span::new(FileId(0), 108, 110));
    assert_eq!(f[1].name.as_ref().unwrap().1, Span::new(FileId(0), 106, 107));
}

#[test]
fn quote_round_trips() {
    let q = quote("a, \"b\"");
    assert_eq!(cells(&q)[0].1, "a, \"b\"");
    assert_eq!(quote("X"), "X");
}
