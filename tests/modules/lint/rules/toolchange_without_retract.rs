use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_m6_first() {
    let found = lint_vectric("begin TOOLCHANGE\n\"T[T] M6\"\n\"G0 Z[SAFEZ]\"\n");
    assert!(found.iter().any(|d| d.code == "LN004"), "{found:?}");
}

#[test]
fn quiet_after_a_retract() {
    let found = lint_vectric("begin TOOLCHANGE\n\"G0 Z[SAFEZ]\"\n\"T[T] M6\"\n");
    assert!(!found.iter().any(|d| d.code == "LN004"), "{found:?}");
    let found = lint_vectric("begin TOOLCHANGE\n\"G53 G0 Z0\"\n\"M06 T[T]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN004"), "{found:?}");
}
