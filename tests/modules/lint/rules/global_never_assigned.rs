use crate::modules::lint::lint_cimco;

#[test]
fn fires_on_a_global_never_assigned() {
    let found = lint_cimco("var offset;\nfunction onLinear(x, y, z, movement) { return \"G1 X\" + (x + offset); }\n");
    let d = found.iter().find(|d| d.code == "LN015" && d.message.contains("`offset`")).expect("LN015");
    // The warning stands at the declaration `var offset;` (bytes 4..10).
    let span = d.primary_span().expect("a position");
    assert_eq!((span.start, span.end), (4, 10), "{d:?}");
}

#[test]
fn quiet_when_it_is_assigned_somewhere() {
    let found = lint_cimco(
        "var offset;\nfunction onOpen(c) { offset = 2; return \"\"; }\nfunction onLinear(x, y, z, movement) { return \"G1 X\" + (x + offset); }\n",
    );
    assert!(!found.iter().any(|d| d.code == "LN015"), "{found:?}");
}
