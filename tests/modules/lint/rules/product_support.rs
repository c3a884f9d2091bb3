use crate::modules::lint::lint_vectric_for;
use postc_lint::Product;

const POST: &str = "POST_NAME = \"x\"\nTAPE_SPLITTING = 1000 100 \"%s_%d.tap\" 1 \"NO\"\nbegin HEADER\n\"([DATE])\"\nbegin FIRST_PLUNGE_MOVE\n\"G1[Z][F]\"\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J]\"\n";

#[test]
fn fires_for_photovcarve() {
    let found = lint_vectric_for(POST, Some(Product::PhotoVcarve));
    let n = found.iter().filter(|d| d.code == "LN006").count();
    // TAPE_SPLITTING, FIRST_PLUNGE_MOVE, CW_ARC_MOVE, [DATE], [I], [J].
    assert_eq!(n, 6, "{found:?}");
}

#[test]
fn quiet_for_aspire_and_without_a_product() {
    assert!(!lint_vectric_for(POST, Some(Product::Aspire)).iter().any(|d| d.code == "LN006"));
    assert!(!lint_vectric_for(POST, None).iter().any(|d| d.code == "LN006"));
}
