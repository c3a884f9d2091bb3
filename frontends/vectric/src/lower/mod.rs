//! Lowering: from parsed files to the IR [`Post`].
//!
//! 1. [`base`] reads the post and its `POST_BASE` chain;
//! 2. [`collect`] applies each file, deepest base first, to one [`Model`]:
//!    later files replace whole sections and override `VAR`s and global
//!    statements one by one;
//! 3. [`emit`] turns the model into IR, giving undeclared labels their
//!    default formats, and [`lint`] checks the result.

mod base;
mod collect;
mod emit;
mod globals;
mod lint;
mod model;

use std::path::Path;

use postc_ir::{Diagnostic, Post, SourceMap, Span};

use model::Model;

/// Compiles a post file and its bases.
pub fn compile(path: &Path, bytes: &[u8], sources: &mut SourceMap) -> (Post, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let chain = base::load_chain(path, bytes, sources, &mut diags);
    let mut model = Model::default();
    for loaded in &chain {
        collect::collect(&mut model, &loaded.ast, loaded.encoding, &mut diags);
    }
    let main = chain.last().map(|l| l.ast.file).unwrap_or_default();
    let mut post = emit::emit(&model, &path.display().to_string(), Span::new(main, 0, 0), &mut diags);
    if post.variables.iter().any(|v| v.source == postc_ir::ValueSource::Quantity(postc_ir::Quantity::Revision)) {
        post.info.revision = crate::revision::revision(bytes);
    }
    if chain.iter().any(|l| l.encoding == crate::decode::Encoding::Windows1252) {
        post.info.text_encoding = postc_ir::post::TextEncoding::Windows1252;
    }
    // The file as written, for the Vectric backend: only a post that is
    // one file (a `POST_BASE` post is printed whole, from the IR).
    if let [_] = chain.as_slice() {
        post.info.written = sources.text(main).unwrap_or_default().to_string();
    }
    diags.sort_by_key(|d| d.primary_span().map_or((main.0, 0), |s| (s.file.0, s.start)));
    (post, diags)
}
