use crate::modules::lint::lint_vectric;

#[test]
fn fires_when_the_spindle_starts_without_a_speed() {
    let found = lint_vectric("begin HEADER\n\"G21\"\n\"M3\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    assert!(found.iter().any(|d| d.code == "LN002"), "{found:?}");
}

#[test]
fn quiet_with_a_speed_or_a_hand_set_spindle() {
    let found = lint_vectric("begin HEADER\n\"M3 [S]\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN002"), "{found:?}");
    let found = lint_vectric("begin HEADER\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN002"), "{found:?}");
}
