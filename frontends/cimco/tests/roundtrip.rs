//! The tree is faithful enough to print back as JavaScript: printing a
//! valid fixture and parsing the print gives the same tree, and printing
//! that again gives the same text.

use std::fs;
use std::path::Path;

use postc_front_cimco::{dump::dump, parse, print::to_js};
use postc_ir::FileId;

/// A dump without the `line:column` of each line, so trees parsed from
/// differently laid-out text compare equal.
fn shape(text: &str) -> String {
    let (program, diagnostics) = parse(text, FileId(0));
    assert!(diagnostics.is_empty(), "printed text did not parse:\n{text}\n{diagnostics:#?}");
    dump(&program, text)
        .lines()
        .map(|l| {
            let indent = l.len() - l.trim_start().len();
            let rest = l.trim_start().split_once(' ').map_or("", |(_, r)| r);
            format!("{}{rest}\n", " ".repeat(indent))
        })
        .collect()
}

#[test]
fn valid_fixtures_print_back() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/valid");
    let mut count = 0;
    for entry in fs::read_dir(&dir).expect("fixture directory") {
        let path = entry.expect("directory entry").path();
        let text = fs::read_to_string(&path).expect("fixture text");
        let (program, _) = parse(&text, FileId(0));
        let printed = to_js(&program);
        let (reparsed, _) = parse(&printed, FileId(0));
        assert_eq!(to_js(&reparsed), printed, "{}: printing is not stable", path.display());
        assert_eq!(shape(&printed), shape(&text), "{}: the printed tree differs", path.display());
        count += 1;
    }
    assert!(count >= 2);
}

#[test]
fn printing_keeps_needed_parentheses() {
    for text in [
        "x = (a + b) * c;\n",
        "x = a - (b - c);\n",
        "x = (a, b);\n",
        "x = (a ? b : c) ? d : e;\n",
        "x = -(-a);\n",
        "x = - -a;\n",
        "x = (1.5).toFixed(2);\n",
        "x = new (f())();\n",
        "x = (a = b) + 1;\n",
        "(function () {\n})();\n",
        "x = !(a && b);\n",
        "x = typeof (a + b);\n",
    ] {
        let (program, diagnostics) = parse(text, FileId(0));
        assert!(diagnostics.is_empty(), "{text}: {diagnostics:#?}");
        let printed = to_js(&program);
        assert_eq!(shape(&printed), shape(text), "{text} printed as {printed}");
    }
}
