use postc_ir::Dialect;
use postc_lsp::analysis::*;

#[test]
fn a_missing_bracket_is_closed() {
    let text = "begin HEADER\n\"G0 [X [Y] [13]\"\n\"([TOOLNAME\"\n\"[NOT_A_LABEL\"\n";
    let f = fixes(Dialect::Vectric, text, 0, text.len());
    let fixed = apply(text, &f);
    assert_eq!(fixed, "begin HEADER\n\"G0 [X] [Y] [13]\"\n\"([TOOLNAME]\"\n\"[NOT_A_LABEL\"\n");
}

const PP: &str = "UNITS = \"MM\"\nVAR X_POSITION = [X|A|X|1.3]\nbegin FEED_MOVEE\n\"G1 [X]\"\nbegin HEADR\n";

#[test]
fn vectric_definition_and_hover() {
    let x = PP.rfind("[X]").unwrap() + 1;
    let (s, e) = definition(Dialect::Vectric, PP, x).unwrap();
    assert_eq!(&PP[s..e], "X_POSITION");
    let h = hover(Dialect::Vectric, PP, x).unwrap();
    assert!(h.markdown.contains("X_POSITION"), "{}", h.markdown);
    let h = hover(Dialect::Vectric, PP, PP.find("UNITS").unwrap()).unwrap();
    assert!(h.markdown.contains("INCHES"));
}

#[test]
fn vectric_fixes() {
    let f = fixes(Dialect::Vectric, PP, 0, PP.len());
    assert_eq!(f.len(), 2);
    assert_eq!(f[0].replacement, "FEED_MOVE");
    assert_eq!(&PP[f[0].start..f[0].end], "FEED_MOVEE");
    assert_eq!(f[1].replacement, "HEADER");
}

#[test]
fn cimco_and_vcpost_definitions() {
    let js = "var xyzFormat = createFormat({decimals: 3});\nfunction writeBlock(t) { return t; }\nfunction onLinear(x, y, z, m) {\n  return writeBlock(xyzFormat.format(x));\n}\n";
    let at = js.rfind("writeBlock").unwrap();
    let (s, _) = definition(Dialect::Cimco, js, at).unwrap();
    assert_eq!(s, js.find("writeBlock").unwrap());
    let at = js.rfind("xyzFormat").unwrap();
    assert_eq!(definition(Dialect::Cimco, js, at).unwrap().0, 4);
    let vb = "Sub GOTO\n  Out \"G1 <X>\"\n  Helper 1\nEnd Sub\nPrivate Sub Helper(A)\nEnd Sub\n";
    let (s, e) = definition(Dialect::VcPost, vb, vb.find("Helper").unwrap()).unwrap();
    assert_eq!(&vb[s..e], "Helper");
    assert!(s > vb.find("End Sub").unwrap());
    let names: Vec<String> = completion(Dialect::VcPost, vb, vb.len(), false).into_iter().map(|c| c.label).collect();
    assert!(names.contains(&"Helper".to_owned()) && names.contains(&"Sqr".to_owned()), "{names:?}");
    let names: Vec<String> = completion(Dialect::Cimco, js, js.len(), false).into_iter().map(|c| c.label).collect();
    assert!(names.contains(&"writeBlock".to_owned()) && names.contains(&"xyzFormat".to_owned()), "{names:?}");
    assert!(names.contains(&"MOVEMENT_RAPID".to_owned()) && names.iter().filter(|n| *n == "onLinear").count() == 1);
    assert!(completion(Dialect::Cimco, js, js.len(), true).is_empty());
    let h = hover(Dialect::VcPost, vb, vb.find("<X>").unwrap()).unwrap();
    assert!(h.markdown.contains("end point"), "{}", h.markdown);
}

const CPS: &str = "description = \"test\";\nfunction onLinear(x, y, z, feed) {\n  writeBlock(getParameter(\"operation-comment\"));\n}\nfunction onClose() {\n  redirectToFile(\"x\");\n  exportNCAs(\"a\", \"b\");\n  var p = PLANE_XY;\n}\n";

#[test]
fn fusion_hover_shows_the_declaration_and_what_postc_does() {
    let at = |word: &str| CPS.find(word).unwrap();
    let h = hover(Dialect::Fusion, CPS, at("getParameter")).unwrap();
    assert!(h.markdown.contains("getParameter(name: String): Value") && h.markdown.contains("postc's host defines it"));
    let h = hover(Dialect::Fusion, CPS, at("PLANE_XY")).unwrap();
    assert!(h.markdown.contains("Circular XY plane.") && h.markdown.contains("`PLANE_XY = 0`"), "{}", h.markdown);
    let h = hover(Dialect::Fusion, CPS, at("redirectToFile")).unwrap();
    assert!(h.markdown.contains("JS110"), "{}", h.markdown);
    let h = hover(Dialect::Fusion, CPS, at("exportNCAs")).unwrap();
    assert!(h.markdown.contains("JS109"), "{}", h.markdown);
    // The post's own entry point: its definition, then the declaration.
    let h = hover(Dialect::Fusion, CPS, at("onLinear")).unwrap();
    assert!(h.markdown.starts_with("```js\nfunction onLinear(x, y, z, feed) {"), "{}", h.markdown);
    assert!(h.markdown.contains("entry point, called by the host"), "{}", h.markdown);
}

#[test]
fn fusion_completion_offers_host_names_once() {
    let text = "function onOpen() {\n  getPar";
    let names: Vec<String> =
        completion(Dialect::Fusion, text, text.len(), false).into_iter().map(|c| c.label).collect();
    assert!(names.iter().any(|n| n == "getParameter"), "{names:?}");
    assert!(names.iter().any(|n| n == "PLANE_XY"), "{names:?}");
    assert_eq!(names.iter().filter(|n| *n == "onOpen").count(), 1, "{names:?}");
}
