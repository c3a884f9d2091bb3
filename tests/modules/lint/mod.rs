mod rules;

use postc_ir::{Diagnostic, SourceMap};
use postc_lint::{Options, Product};
use std::path::Path;

fn compile(name: &str, text: &str, product: Option<Product>) -> Vec<Diagnostic> {
    let mut sources = SourceMap::new();
    let compiled = postc_driver::compile_post_bytes(Path::new(name), text.as_bytes(), None, &mut sources);
    let post = compiled.post.unwrap_or_else(|| panic!("does not compile: {:?}", compiled.diagnostics));
    postc_lint::lint(&post, &Options { product })
}

pub fn lint_vectric(text: &str) -> Vec<Diagnostic> {
    compile("t.pp", text, None)
}

pub fn lint_vectric_for(text: &str, product: Option<Product>) -> Vec<Diagnostic> {
    compile("t.pp", text, product)
}

pub fn lint_cimco(text: &str) -> Vec<Diagnostic> {
    compile("t.js", text, None)
}

pub fn lint_vcpost(text: &str) -> Vec<Diagnostic> {
    compile("t.VcPost", text, None)
}
