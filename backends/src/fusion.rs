//! The Fusion backend: a post printed as an Autodesk Fusion `.cps` post
//! that Fusion's engine runs (docs/convert.md, "Fusion posts").
//!
//! A Vectric post (driven by the kind of each move, its sections output
//! lines) prints through [`crate::js_sections`] with Fusion's entry
//! points. Posts of the other dialects are refused (`CV012`) until their
//! forms are written.

use postc_ir::{Diagnostic, Dialect, Post, codes};

/// Prints `post` as a `.cps` post, with the conversion's warnings, or says
/// why it cannot be one.
pub fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    if post.info.dialect != Dialect::Vectric {
        return Err(vec![crate::cimco::refusal(
            codes::CV012.code,
            post.info.span,
            format!(
                "a {} post does not convert to Fusion yet: only Vectric posts do",
                crate::dialect_name(post.info.dialect)
            ),
            "docs/convert.md, \"Fusion posts\"",
        )]);
    }
    crate::js_sections::print(post, crate::js_sections::Host::Fusion)
}
