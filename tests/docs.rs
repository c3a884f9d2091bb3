//! The examples in docs/ read: every ```ron and ```json block of
//! docs/toolpath-format.md is a valid toolpath.

use postc_ir::EventSource;
use postc_reader_native::{NativeReader, Syntax};

fn blocks(text: &str, fence: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current: Option<String> = None;
    for line in text.lines() {
        match &mut current {
            None if line.trim() == format!("```{fence}") => current = Some(String::new()),
            Some(block) if line.trim() == "```" => {
                out.push(std::mem::take(block));
                current = None;
            }
            Some(block) => {
                block.push_str(line);
                block.push('\n');
            }
            None => {}
        }
    }
    out
}

#[test]
fn toolpath_format_examples_read() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/toolpath-format.md")).unwrap();
    let mut read = 0;
    for (fence, syntax) in [("ron", Syntax::Ron), ("json", Syntax::JsonLines)] {
        for block in blocks(&doc, fence) {
            let mut sources = postc_report::source_map();
            let file = sources.add("doc", block.clone());
            let mut reader = NativeReader::new(block.as_bytes(), Some(syntax), file);
            let mut diags = Vec::new();
            while reader.next_event(&mut diags).is_some() {
                read += 1;
            }
            assert!(diags.is_empty(), "{fence} block:\n{block}\n{diags:?}");
        }
    }
    assert!(read > 20, "only {read} events in the examples");
}
