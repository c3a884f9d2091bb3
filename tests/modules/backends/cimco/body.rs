use postc_backends::testing::cimco_body::*;

/// A regular expression literal prints as `/pattern/flags`, and the
/// printed function compiles back to the same IR.
#[test]
fn a_regular_expression_prints_as_itself() {
    let js = "var linebreak = \"\\n\";\nfunction clean(t) {\n    return t.replace(/[(\\/)]/gi, \"\");\n}\nfunction onLinear(x, y, z, m) { return clean(\"(G1)\") + linebreak; }\n";
    let compile = |text: &str| {
        let mut sources = postc_ir::SourceMap::new();
        let (mut post, diags) =
            postc_front_cimco::compile(std::path::Path::new("regex.js"), text.as_bytes(), &mut sources);
        assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
        post.drop_spans();
        post
    };
    let post = compile(js);
    let clean = post.functions.iter().find(|f| f.name == "clean").expect("function clean");
    let decl = function(&post, clean).expect("printed");
    let text = postc_front_cimco::print::to_js(&postc_front_cimco::Program { body: vec![decl], span: at() });
    assert!(text.contains("return t.replace(/[(\\/)]/gi, \"\");"), "{text}");
    let back =
        compile(&js.replace(js.lines().skip(1).take(3).collect::<Vec<_>>().join("\n").as_str(), text.trim_end()));
    let again = back.functions.iter().find(|f| f.name == "clean").expect("function clean");
    assert_eq!(again.body, clean.body);
}
