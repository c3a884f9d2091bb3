use postc_postp::options::*;

#[test]
fn patches_replace_only_what_they_give() {
    let p = Patch::parse("(end: \"M02\", retractz: At(2.5), sequence: On(start: 100, increment: 5))").unwrap();
    let o = Options::default().apply(p);
    assert_eq!(o.end, "M02");
    assert_eq!(o.retractz, RetractZ::At(2.5));
    assert_eq!(o.sequence, Sequence::On { start: 100.0, increment: 5.0 });
    assert_eq!(o.rewind, "M30");
}

#[test]
fn bad_files_say_where() {
    let (_, line, col) = Patch::parse("(\n  ends: \"M02\")").unwrap_err();
    assert_eq!((line, col), (2, 3));
}

#[test]
fn every_embedded_file_is_complete() {
    for c in postc_postp::controller::Controller::ALL {
        let p = Patch::parse(c.default_options()).unwrap_or_else(|e| panic!("{c}: {e:?}"));
        assert!(p.is_complete(), "{c}: the embedded options file must give every field");
    }
}
