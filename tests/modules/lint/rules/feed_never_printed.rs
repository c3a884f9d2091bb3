use crate::modules::lint::lint_vectric;

#[test]
fn fires_without_a_feed() {
    let found = lint_vectric("begin HEADER\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][Y][Z]\"\n");
    assert!(found.iter().any(|d| d.code == "LN001"), "{found:?}");
}

#[test]
fn quiet_with_a_feed() {
    let found = lint_vectric("begin FEED_MOVE\n\"G1[X][Y][Z]\"\nbegin FEED_RATE_CHANGE\n\"F[F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN001"), "{found:?}");
}
