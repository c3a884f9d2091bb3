use postc_front_cimco::docs::*;

#[test]
fn comments_directly_above_a_statement_are_its() {
    let text = "// head\n// two\n\n// not mine\n\n// one\n  // two\nfunction f() {}\n";
    assert_eq!(head(text), (vec![" head".to_string(), " two".to_string()], 15));
    let at = text.find("function").unwrap_or(0);
    assert_eq!(before(text, at, 0), [" one", " two"]);
    assert_eq!(before("x;\nfunction f() {}", 3, 0), Vec::<String>::new());
    assert_eq!(head("// only a comment run before code\nvar x = 1;\n"), (Vec::new(), 0));
    let block = "/*\n * Haas post.\n * Second.\n */\n\nvar x;\n";
    assert_eq!(head(block).0, [" Haas post.", " Second."]);
}
