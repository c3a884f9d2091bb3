//! A CIMCO CNC-Calc post printed as an Autodesk Fusion `.cps` post that
//! Fusion's engine runs (docs/convert.md, "CIMCO posts as Fusion posts").
//!
//! The CNC-Calc post is printed as the CIMCO backend prints it (its text
//! as written where the IR keeps it, [`crate::cimco::print`]) inside a
//! function scope, `cncCalc`, beside the CNC-Calc host names it calls
//! (`createFormat`, `createVariable`, `getFeedrate`, the `MOVEMENT_`,
//! `COMPENSATION_`, `DEGRESSION_` and `POST_TYPE_` constants), so that its
//! names and Fusion's do not meet; Fusion's entry points after it call the
//! post's in CNC-Calc's order, as postc's CIMCO runtime does
//! (docs/cimco.md, "Call order"): `cnc_calc.js`.
//!
//! Refused, each at its place: a lathe post (Fusion's turning sections
//! are not CNC-Calc's lathe calls, `CV004`), a post without `onCircular`
//! (postc cuts its arcs into chords, `CV010`). Converted with a warning: a
//! post with drilling functions (Fusion hands a cycle's type, not its
//! CNC-Calc name, `CV013`).

use postc_ir::{Diagnostic, Post, Units, codes};

use crate::cimco::refusal;

/// The CNC-Calc entry points the Fusion entry points call (docs/cimco.md,
/// "Call order"); `cnc_calc.js` reads each through `cncCalc.entry`.
const ENTRY_POINTS: &[&str] = &[
    "onInit",
    "onOpen",
    "onToolChange",
    "onLinear",
    "onCircular",
    "onCompensation",
    "onDwell",
    "onComment",
    "onToolpathEnd",
    "onDrillingHeader",
    "onDrillingPoint",
    "onDrillingFooter",
    "onClose",
];

/// The `.cps` post around the CNC-Calc post: `{{NAME}}` marks what
/// [`print`] fills in.
const TEMPLATE: &str = include_str!("cnc_calc.js");

/// Prints `post`, a CIMCO post with code, as a `.cps` post, with the
/// conversion's warnings, or says why it cannot be one.
pub(super) fn print(post: &Post) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    let function = |name: &str| post.functions.iter().find(|f| f.name == name);
    let mut errors = Vec::new();
    if post.options.lathe {
        errors.push(refusal(
            codes::CV004.code,
            post.info.span,
            "a CNC-Calc lathe post (PostInfo.type POST_TYPE_TURN, or an onLinear of three parameters), which the converted Fusion post does not carry".into(),
            "the converted post is a milling post: Fusion calls it with X, Y and Z",
        ));
    }
    if function("onCircular").is_none() {
        errors.push(refusal(
            codes::CV010.code,
            function("onLinear").and_then(|f| f.span),
            "the post has no onCircular, so postc cuts its arcs into onLinear chords; the converted post is handed Fusion's arcs whole"
                .into(),
            "add an onCircular to the source post",
        ));
    }
    let source = match crate::cimco::print(post) {
        Ok((bytes, _)) => String::from_utf8_lossy(&bytes).into_owned(),
        Err(mut e) => {
            errors.append(&mut e);
            String::new()
        }
    };
    if !errors.is_empty() {
        return Err(errors);
    }
    let mut warnings = Vec::new();
    if let Some(f) = function("onDrillingHeader") {
        let mut d = Diagnostic::warning(
            codes::CV013.code,
            "Fusion hands a drilling cycle's type and no name: the converted post's drillHeader.name is the type's CNC-Calc name (Drilling, Peck drilling, Chip breaking, Tapping, Boring, Reaming)",
        )
        .note("a toolpath whose cycles CNC-Calc names otherwise (\"Drilling (G81)\") posts differently through the converted post".to_string());
        if let Some(span) = f.span {
            d = d.at(span, "reads the cycle");
        }
        warnings.push(d);
    }
    // The CIMCO backend's conversion note is this post's first line.
    let body = source.split_once('\n').map_or("", |(_, rest)| rest);
    let name = if post.info.name.is_empty() { crate::source_name(post).to_string() } else { post.info.name.clone() };
    let extension = if post.info.file_extension.is_empty() { "nc" } else { post.info.file_extension.as_str() };
    // The runtime's factors (`Units::factor_to`), as JavaScript computes them.
    let (units, scale) = match post.output_units() {
        Some(Units::Mm) => ("millimetres", "cncScale = unit == MM ? 1 : 25.4;"),
        Some(Units::Inch) => ("inches", "cncScale = unit == MM ? 1 / 25.4 : 1;"),
        None => ("the document's units", "cncScale = 1;"),
    };
    // The entry points the post does not define are undefined in its
    // scope, not Fusion's functions of the same names.
    let undefined: Vec<&str> = ENTRY_POINTS.iter().copied().filter(|name| function(name).is_none()).collect();
    let undefined = if undefined.is_empty() {
        String::new()
    } else {
        format!("    // The CNC-Calc entry points the post does not define.\n    var {};\n", undefined.join(", "))
    };
    // Arcs outside XY are cut into chords within the runtime's tolerance,
    // in the post's units (`arc_tolerance` is in mm).
    let tolerance = match post.output_units() {
        Some(Units::Inch) => post.options.arc_tolerance * Units::Inch.factor_to(Units::Mm).recip(),
        _ => post.options.arc_tolerance,
    };
    let text = TEMPLATE
        .replace("{{SETTINGS}}", &crate::js_sections::fusion_settings(&name, "CIMCO", extension))
        .replace("{{TOLERANCE}}", &crate::js_sections::number(tolerance))
        .replace("{{UNDEFINED}}", &undefined)
        .replace("{{UNITS}}", units)
        .replace("{{SCALE}}", scale)
        .replace("{{SOURCE}}", body.trim_end());
    Ok((format!("{}//\n{text}", crate::cimco::header(post)).into_bytes(), warnings))
}
