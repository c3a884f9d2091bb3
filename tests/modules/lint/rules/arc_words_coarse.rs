use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_two_decimals_in_mm() {
    let found = lint_vectric(
        "UNITS = \"MM\"\nVAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.2]\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n",
    );
    let n = found.iter().filter(|d| d.code == "LN010").count();
    assert_eq!(n, 1, "{found:?}");
}

#[test]
fn quiet_on_three_decimals_in_mm_and_four_in_inches() {
    let found = lint_vectric("UNITS = \"MM\"\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN010"), "{found:?}");
    let found = lint_vectric(
        "UNITS = \"INCHES\"\nVAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.4]\nVAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.4]\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n",
    );
    assert!(!found.iter().any(|d| d.code == "LN010"), "{found:?}");
}
