use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_a_name_the_post_contradicts() {
    let found = lint_vectric(
        "POST_NAME = \"Router Arcs (inch) (*.nc)\"\nFILE_EXTENSION = \"tap\"\nUNITS = \"MM\"\nbegin FEED_MOVE\n\"G1[X][F]\"\n",
    );
    let n = found.iter().filter(|d| d.code == "LN005").count();
    assert_eq!(n, 3, "{found:?}");
}

#[test]
fn quiet_when_the_name_is_true() {
    let found = lint_vectric(
        "POST_NAME = \"Router Arcs (mm) (*.tap)\"\nFILE_EXTENSION = \"tap\"\nUNITS = \"MM\"\nbegin FEED_MOVE\n\"G1[X][F]\"\nbegin CW_ARC_MOVE\n\"G2[X][I][F]\"\n",
    );
    assert!(!found.iter().any(|d| d.code == "LN005"), "{found:?}");
}
