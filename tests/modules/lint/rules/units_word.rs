use crate::modules::lint::lint_vectric;

/// The header of `Marlin_in_with_arcs_and_fan_control.pp`, a real post:
/// `UNITS = "INCHES"` and `G21`.
#[test]
fn fires_on_an_inch_post_that_writes_g21() {
    let found = lint_vectric("UNITS = \"INCHES\"\nbegin HEADER\n\"G90\"\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    let d = found.iter().find(|d| d.code == "LN017").unwrap_or_else(|| panic!("{found:?}"));
    assert!(d.message.starts_with("the post writes inches, but its text says G21"), "{}", d.message);
}

#[test]
fn quiet_when_the_words_agree_or_both_are_written() {
    for post in [
        "UNITS = \"MM\"\nbegin HEADER\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n",
        "UNITS = \"INCHES\"\nbegin HEADER\n\"G20\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n",
        "UNITS = \"INCHES\"\nbegin HEADER\n\"(G21 is metric, G20 is inch)\"\n\"G20\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n",
        "begin HEADER\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n",
    ] {
        let found = lint_vectric(post);
        assert!(!found.iter().any(|d| d.code == "LN017"), "{post}: {found:?}");
    }
}
