//! The Fusion backend: a post printed as an Autodesk Fusion `.cps` post
//! that Fusion's engine runs (docs/convert.md, "Fusion posts").
//!
//! A Vectric post (driven by the kind of each move, its sections output
//! lines) prints through [`crate::js_sections`] with Fusion's entry
//! points. A CIMCO post with code prints as written inside a scope of its
//! own, called by Fusion's entry points in CNC-Calc's order ([`cimco`]).
//! A Fusion post prints as its file was written, after the conversion
//! note, when the Fusion frontend reads that text back as the same post
//! ([`crate::as_written`]). A post driven by APT words (a VcPost milling
//! post) prints its Subs called by Fusion's entry points through the APT
//! records postc's runtime makes ([`apt`]). Other posts (a VcPost section
//! post) are refused (`CV012`).

mod apt;
mod cimco;

use postc_ir::{Diagnostic, Dialect, Post, codes};

/// Prints `post` as a `.cps` post, with the conversion's warnings, or says
/// why it cannot be one.
pub fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    if post.info.dialect == Dialect::Fusion {
        let note = format!("// {}{} (Autodesk Fusion)", postc_ir::post::CONVERSION_NOTE, crate::source_name(post));
        return match crate::as_written(post, Dialect::Fusion, &note, postc_front_cimco::fusion::compile, |t| {
            Some(t.as_bytes().to_vec())
        }) {
            Some(bytes) => Ok((bytes, Vec::new())),
            None => Err(vec![crate::cimco::refusal(
                codes::CV012.code,
                post.info.span,
                "this Fusion post is not kept as its file was written (a RON post, or a file that is not UTF-8), and a Fusion post prints only as written".into(),
                "docs/convert.md, \"Fusion posts\"",
            )]),
        };
    }
    if post.info.dialect == Dialect::Cimco && !post.functions.is_empty() {
        return cimco::print(post);
    }
    if post.info.dispatch == postc_ir::post::Dispatch::AptWords {
        return apt::print(post);
    }
    if post.info.dialect != Dialect::Vectric {
        return Err(vec![crate::cimco::refusal(
            codes::CV012.code,
            post.info.span,
            format!(
                "a {} post driven by sections does not convert to Fusion yet: Vectric, CIMCO, APT-word (VcPost milling) and Fusion posts do",
                crate::dialect_name(post.info.dialect)
            ),
            "docs/convert.md, \"Fusion posts\"",
        )]);
    }
    crate::js_sections::print(post, crate::js_sections::Host::Fusion)
}
