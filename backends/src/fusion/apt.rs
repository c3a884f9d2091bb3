//! A post driven by APT words (a VcPost milling post, a `postp`
//! controller) printed as an Autodesk Fusion `.cps` post that Fusion's
//! engine runs (docs/convert.md, "VcPost posts as Fusion posts").
//!
//! The Subs, Functions, registers and variables print as the CIMCO
//! backend prints them for CNC-Calc (`crate::cimco::apt`, BASIC's values
//! as the runtime computes them), as the body of the function whose value
//! is `vcPost`, so that their names never meet Fusion's; the adapter in
//! that body makes each APT record the runtime makes
//! (`runtime/src/apt_words.rs`), and Fusion's entry points after it call
//! the adapter in the toolpath's order (`apt.js`).
//!
//! Refused, each at its place, as for CNC-Calc: posts driven by probe
//! tables or composites calls (`CV001`), BASIC the printer has no
//! JavaScript for (`CV002`), output options no line carries (`CV004`), a
//! post without `Sub CIRCLE` (`CV010`). Left out with warning `CV008`: the
//! Subs of words Fusion makes no record of (`INSERT`, pass-through words).

use postc_ir::{Diagnostic, Post, Units};

use crate::cimco::apt::{Host, print_for};

/// The `.cps` post around the Subs: `{{NAME}}` marks what [`print`] fills in.
const TEMPLATE: &str = include_str!("apt.js");

/// Prints `post`, an APT-word post, as a `.cps` post, with the
/// conversion's warnings, or says why it cannot be one.
pub(super) fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    let (body, warnings) = print_for(post, Host::Fusion)?;
    let body = String::from_utf8_lossy(&body).into_owned();
    let name = if post.info.name.is_empty() { crate::source_name(post).to_string() } else { post.info.name.clone() };
    let extension = if post.info.file_extension.is_empty() { "nc" } else { post.info.file_extension.as_str() };
    // The runtime's factors (`Units::factor_to`), as JavaScript computes
    // them, and `Metric` as the runtime sets it: 1 when the program is in
    // millimetres.
    let (units, scale, metric) = match post.output_units() {
        Some(Units::Mm) => ("millimetres", "aptScale = unit == MM ? 1 : 25.4;", "1"),
        Some(Units::Inch) => ("inches", "aptScale = unit == MM ? 1 / 25.4 : 1;", "0"),
        None => ("the document's units", "aptScale = 1;", "unit == MM ? 1 : 0"),
    };
    let linebreak = String::from_utf8_lossy(&post.options.line_ending).into_owned();
    let text = TEMPLATE
        .replace("{{SETTINGS}}", &crate::js_sections::fusion_settings(&name, "Vericut", extension))
        .replace("{{LINEBREAK}}", &crate::js_sections::js_string(&linebreak))
        .replace("{{UNITS}}", units)
        .replace("{{SCALE}}", scale)
        .replace("{{METRIC}}", metric)
        .replace("{{SOURCE}}", body.trim_end());
    Ok((format!("{}//\n{text}", crate::cimco::header(post)).into_bytes(), warnings))
}
