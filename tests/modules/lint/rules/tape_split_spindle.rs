use crate::modules::lint::lint_vectric;

const SPLIT: &str = "TAPE_SPLITTING = 1000 100 \"%s_%d.tap\" 1 \"NO\"\n";

#[test]
fn fires_when_only_the_tool_change_starts_it() {
    let found = lint_vectric(&format!("{SPLIT}begin HEADER\n\"G21\"\nbegin TOOLCHANGE\n\"T[T] M6\"\n\"[S] M3\"\n"));
    assert!(found.iter().any(|d| d.code == "LN011"), "{found:?}");
}

#[test]
fn quiet_with_spindle_on_or_without_splitting() {
    let found = lint_vectric(&format!("{SPLIT}begin HEADER\n\"G21\"\nbegin SPINDLE_ON\n\"[S] M3\"\n"));
    assert!(!found.iter().any(|d| d.code == "LN011"), "{found:?}");
    let found = lint_vectric("begin HEADER\n\"G21\"\nbegin TOOLCHANGE\n\"T[T] M6\"\n\"[S] M3\"\n");
    assert!(!found.iter().any(|d| d.code == "LN011"), "{found:?}");
}
