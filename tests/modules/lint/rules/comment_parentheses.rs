use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_a_name_in_a_comment() {
    let found = lint_vectric("begin HEADER\n\"( [TOOLPATH_NAME] )\"\n");
    assert!(found.iter().any(|d| d.code == "LN003"), "{found:?}");
}

#[test]
fn quiet_when_parentheses_are_substituted_or_not_a_comment() {
    let found = lint_vectric("SUBSTITUTE = \"({)}\"\nbegin HEADER\n\"( [TOOLPATH_NAME] )\"\n");
    assert!(!found.iter().any(|d| d.code == "LN003"), "{found:?}");
    let found = lint_vectric("begin HEADER\n\"'[TOOLPATH_NAME]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN003"), "{found:?}");
}
