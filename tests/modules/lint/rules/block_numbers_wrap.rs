use crate::modules::lint::lint_vectric;

#[test]
fn fires_on_a_small_maximum() {
    let found = lint_vectric(
        "POST_NAME = \"x\"\nLINE_NUMBER_INCREMENT = 10\nLINE_NUMBER_MAXIMUM = 9999\nbegin FEED_MOVE\n\"[N]G1[X][F]\"\n",
    );
    assert!(found.iter().any(|d| d.code == "LN012"), "{found:?}");
}

/// A post with no `POST_NAME` has no span of its own: the warning
/// stands at the section that prints `[N]` (the mutation fuzzer's
/// case, a diagnostic with no position).
#[test]
fn stands_at_the_section_that_prints_block_numbers() {
    let found =
        lint_vectric("LINE_NUMBER_INCREMENT = 10\nLINE_NUMBER_MAXIMUM = 990\nbegin FEED_MOVE\n\"[N]G1[X][F]\"\n");
    let d = found.iter().find(|d| d.code == "LN012").expect("LN012");
    assert!(d.primary_span().is_some(), "{d:?}");
}

#[test]
fn quiet_on_a_large_maximum_or_without_block_numbers() {
    let found = lint_vectric("LINE_NUMBER_MAXIMUM = 999999\nbegin FEED_MOVE\n\"[N]G1[X][F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN012"), "{found:?}");
    let found = lint_vectric("LINE_NUMBER_MAXIMUM = 9999\nbegin FEED_MOVE\n\"G1[X][F]\"\n");
    assert!(!found.iter().any(|d| d.code == "LN012"), "{found:?}");
}
