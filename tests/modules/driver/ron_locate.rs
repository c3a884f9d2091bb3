use postc_driver::testing::ron_locate::*;

const TEXT: &str = "// header\n(\n    info: (name: \"a, [b]\"),\n    options: (step_budget: 0),\n    formats: [(decimals: 3), (decimals: 1)],\n    handlers: [\n        (key: Section(RapidMove), body: [Line(pieces: [Var(0)])]),\n        (key: Section(FeedMove), body: [Line(pieces: [Var(9)])]),\n    ],\n)\n";

#[test]
fn finds_list_elements_and_fields() {
    let at = |f, i| item(TEXT, f, i).map(|(s, e)| &TEXT[s..e]);
    assert_eq!(at("formats", Some(1)), Some("(decimals: 1)"));
    assert_eq!(at("handlers", Some(1)), Some("(key: Section(FeedMove), body: [Line(pieces: [Var(9)])])"));
    assert_eq!(at("options", None), Some("(step_budget: 0)"));
    assert_eq!(at("handlers", Some(2)), None);
    assert_eq!(at("variables", Some(0)), None);
}
