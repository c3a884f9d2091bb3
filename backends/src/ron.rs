//! The RON backend: the IR itself, as the text `postc post` and
//! `postc inspect` read back (`postc post converted.ron TOOLPATH`).
//!
//! Spans are dropped: they point into the source post's files, which a
//! RON post does not come with, and a span into the wrong file would send
//! a diagnostic to the wrong place. Everything else is kept, so the RON
//! post posts exactly as its source does.

use postc_ir::codes;
use postc_ir::{Diagnostic, Post};

/// The IR of `post` as RON, after a header comment naming its source.
pub fn print(post: &Post) -> Result<String, Vec<Diagnostic>> {
    let mut post = post.clone();
    post.drop_spans();
    let config = ::ron::ser::PrettyConfig::new().struct_names(false).compact_arrays(true);
    let text = ::ron::ser::to_string_pretty(&post, config)
        .map_err(|e| vec![Diagnostic::error(codes::CV009, format!("the IR cannot be written as RON: {e}"))])?;
    Ok(format!(
        "// Converted by postc from {} ({})\n{text}\n",
        crate::source_name(&post),
        crate::dialect_name(post.info.dialect)
    ))
}
