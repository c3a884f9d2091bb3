use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_arcs_under_a_wrap() {
    let found = lint_vectric(
        "ROTARY_WRAP_Y = \"-A\"\nbegin FEED_MOVE\n\"G1[X][Y][F]\"\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n",
    );
    assert!(found.iter().any(|d| d.code == "LN014"), "{found:?}");
}

#[test]
fn quiet_without_a_wrap() {
    let found = lint_vectric("begin FEED_MOVE\n\"G1[X][Y][F]\"\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN014"), "{found:?}");
}
