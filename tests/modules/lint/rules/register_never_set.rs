use postc_ir::SourceMap;
use std::path::Path;

fn lint(text: &str) -> Vec<postc_ir::Diagnostic> {
    let mut sources = SourceMap::new();
    let post = postc_driver::compile_post_bytes(Path::new("t.VcPost"), text.as_bytes(), None, &mut sources)
        .post
        .expect("compiles");
    postc_lint::lint(&post, &postc_lint::Options::default())
}

#[test]
fn fires_on_a_misspelt_register() {
    let found = lint("Sub GOTO\n  Spindel = 100\n  Out \"G1 <X> S<Spindle>\"\nEnd Sub\n");
    let msgs: Vec<_> = found.iter().filter(|d| d.code == "LN013").map(|d| d.message.clone()).collect();
    assert_eq!(msgs.len(), 1, "{found:?}");
    assert!(msgs[0].contains("<Spindle>"), "{msgs:?}");
}

#[test]
fn quiet_on_set_and_runtime_registers() {
    let found = lint("Sub GOTO\n  Spindle = 100\n  Out \"G1 <X> <Y> S<Spindle>\"\nEnd Sub\n");
    assert!(!found.iter().any(|d| d.code == "LN013"), "{found:?}");
}
