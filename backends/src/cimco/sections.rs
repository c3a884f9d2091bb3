//! Section posts: a post driven by the kind of each move (a Vectric
//! post, a VcPost section post) printed as a CNC-Calc JavaScript *section
//! post*, postc's extension (docs/cimco.md, "Section posts"): a
//! `postcOptions` object for what Vectric's global statements say, one
//! `createVariable({prefix, label, modal}, createFormat({...}))` per
//! variable, and one function per section that returns its lines.
//!
//! What a section post cannot hold is refused:
//!
//! - a post driven by APT words or application calls is `CV001`;
//! - code (functions, globals, statements run first, handlers that are not
//!   output lines: VcPost posts) is `CV002`; a CIMCO post's code prints as
//!   the post it is (`code`), not as a section post;
//! - output options no `postcOptions` key sets (a lathe, a chord
//!   tolerance, a step budget, exact arcs, modal memory kept across
//!   toolpaths) are `CV004`;
//! - a variable that does not print a Vectric label, output text that is
//!   not text in the post's encoding or holds a line break, are `CV005`
//!   and `CV002`.
//!
//! Output text of a Windows-1252 post is written as characters, with
//! `textEncoding: "windows-1252"`, so its bytes come back unchanged.

use crate::js_sections::{js_string, number};
use std::collections::HashSet;

use postc_ir::codes;
use postc_ir::post::{BlockNumbers, Dispatch, Section, WrappedAxis};
use postc_ir::{
    CommentTarget, Diagnostic, HandlerKey, Justify, Modality, NumberFormat, OutputOptions, Padding, Piece, PointStyle,
    Post, SignStyle, Span, Stmt, TextEncoding, Units, ValueSource, VarId, WidthOf,
};

/// Prints `post` as a CIMCO section post, or says why it cannot be one.
pub fn print(post: &Post) -> Result<Vec<u8>, Vec<Diagnostic>> {
    let mut p = Printer { post, out: String::new(), errors: Vec::new(), names: Vec::new() };
    p.check_shape();
    if !p.errors.is_empty() {
        return Err(p.errors);
    }
    p.header();
    p.options();
    p.variables();
    p.sections();
    if p.errors.is_empty() { Ok(p.out.into_bytes()) } else { Err(p.errors) }
}

struct Printer<'p> {
    post: &'p Post,
    out: String,
    errors: Vec<Diagnostic>,
    /// Each variable's JavaScript name.
    names: Vec<String>,
}

/// The names a section post gives a meaning of its own.
const SECTION_POST_NAMES: &[&str] = &["createVariable", "createFormat", "postcOptions"];

fn is_identifier(name: &str) -> bool {
    crate::js_sections::is_js_name(name, SECTION_POST_NAMES)
        && Section::from_name(name).is_none_or(|s| s.name() != name)
}

impl Printer<'_> {
    fn refuse(&mut self, code: &'static str, span: Option<Span>, message: String, why: &str) {
        self.errors.push(super::refusal(code, span, message, why));
    }

    fn check_shape(&mut self) {
        let post = self.post;
        if post.info.dispatch != Dispatch::Sections {
            self.refuse(
                codes::CV001.code,
                None,
                "this post is driven by APT words or application calls, which a CNC-Calc post has no form for".into(),
                "a CNC-Calc post runs per kind of move",
            );
            return;
        }
        let code = post.handlers.iter().find(|h| {
            !h.body
                .iter()
                .all(|s| matches!(s, Stmt::Line { pieces, .. } if pieces.iter().all(|p| !matches!(p, Piece::Expr(_)))))
        });
        if let Some(h) = code {
            self.refuse(
                codes::CV002.code,
                h.span.or_else(|| post.functions.iter().find_map(|f| f.span)),
                "this post's handlers are code, which a section post has no form for".into(),
                "a post of another dialect prints as a section post, whose sections are output lines; only a CIMCO post's code prints as CNC-Calc functions (docs/convert.md)",
            );
        }
        if !post.scripts.is_empty() {
            self.refuse(codes::CV002.code, None, "this post has scripts".into(), "a section post has none");
        }
        let o = &post.options;
        let d = OutputOptions::default();
        for (what, yes) in [
            ("a chord tolerance", o.arc_tolerance != d.arc_tolerance),
            ("exact arcs", o.exact_arcs != d.exact_arcs),
            ("a step budget", o.step_budget != d.step_budget),
            ("a lathe mapping", o.lathe != d.lathe),
            ("modal memory kept across toolpaths", !o.forget_modal_at_toolpath_start),
        ] {
            if yes {
                self.refuse(
                    codes::CV004.code,
                    None,
                    format!("the post sets {what}, which no `postcOptions` key sets"),
                    "a section post sets what Vectric's global statements set",
                );
            }
        }
    }

    fn header(&mut self) {
        self.out.push_str(&super::header(self.post));
        self.out.push_str(&format!("//{}\n\n", postc_front_cimco::docs::SECTION_POST_NOTE));
    }

    fn options(&mut self) {
        let post = self.post;
        let (info, o) = (&post.info, &post.options);
        let mut keys: Vec<String> = Vec::new();
        let source = crate::source_name(post);
        let stem = source.rsplit_once('.').map_or(source, |s| s.0);
        if !info.name.is_empty() && info.name != stem {
            keys.push(format!("name: {}", js_string(&info.name)));
        }
        if !info.file_extension.is_empty() {
            keys.push(format!("fileExtension: {}", js_string(&info.file_extension)));
        }
        match info.units {
            Some(Units::Mm) => keys.push("units: \"MM\"".into()),
            Some(Units::Inch) => keys.push("units: \"INCH\"".into()),
            None => {}
        }
        if o.line_ending != OutputOptions::default().line_ending {
            match std::str::from_utf8(&o.line_ending) {
                Ok(t) if !t.is_empty() => keys.push(format!("lineEnding: {}", js_string(t))),
                _ => self.refuse(codes::CV004.code, None, "a line ending that is not text".into(), ""),
            }
        }
        if !o.substitutions.is_empty() {
            let mut pairs = Vec::new();
            for s in &o.substitutions {
                match (std::str::from_utf8(&s.from), std::str::from_utf8(&s.to)) {
                    (Ok(f), Ok(t)) => pairs.push(format!("[{}, {}]", js_string(f), js_string(t))),
                    _ => self.refuse(codes::CV004.code, None, "a substitution that is not text".into(), ""),
                }
            }
            keys.push(format!("substitute: [{}]", pairs.join(", ")));
        }
        if let Some(r) = o.spindle_speed_range {
            keys.push(format!(
                "spindleSpeedRange: [{}, {}, {}, {}]",
                number(r.out_min),
                number(r.out_max),
                number(r.rpm_min),
                number(r.rpm_max)
            ));
        }
        if let Some(w) = o.rotary_wrap {
            let axis = if w.axis == WrappedAxis::X { "X" } else { "Y" };
            let letter = w.letter.map(|l| l.to_string()).unwrap_or_default();
            keys.push(format!("rotaryWrap: [\"{axis}\", {}, {}]", js_string(&letter), w.reversed));
        }
        if let Some(r) = o.min_arc_radius {
            keys.push(format!("minArcRadius: {}", number(r)));
        }
        if let Some(r) = o.max_arc_radius {
            keys.push(format!("maxArcRadius: {}", number(r)));
        }
        for (key, on) in [
            ("inverseTimeFeed", o.inverse_time_feed),
            ("laserSupport", info.laser_support),
            ("printDirect", info.print_direct),
            ("rapidPlungeToStartZ", info.rapid_plunge_to_start_z),
            ("onChangeByValue", o.on_change_by_value),
            ("rapidForgetsFeed", o.rapid_forgets_feed),
        ] {
            if on {
                keys.push(format!("{key}: true"));
            }
        }
        if let Some(d) = &info.direct_output {
            keys.push(format!("directOutput: {}", js_string(d)));
        }
        if !info.revision.is_empty() {
            keys.push(format!("revision: {}", js_string(&info.revision)));
        }
        if info.text_encoding == TextEncoding::Windows1252 {
            keys.push("textEncoding: \"windows-1252\"".into());
        }
        let b = o.block_numbers;
        if b != BlockNumbers::default() {
            keys.push(format!("blockNumbers: [{}, {}, {}]", number(b.start), number(b.increment), number(b.maximum)));
        }
        if let Some(t) = &o.tape_splitting {
            keys.push(format!(
                "tapeSplitting: [{}, {}, {}, {}, {}]",
                t.max_lines,
                t.tolerance,
                js_string(&t.name_format),
                t.start_index,
                t.index_on_first_file
            ));
        }
        if keys.is_empty() {
            return;
        }
        self.out.push_str("var postcOptions = {\n");
        for k in keys {
            self.out.push_str(&format!("    {k},\n"));
        }
        self.out.push_str("};\n\n");
    }

    fn variables(&mut self) {
        let post = self.post;
        let mut taken: HashSet<String> = HashSet::new();
        for (id, v) in post.variables.iter().enumerate() {
            let ValueSource::Quantity(q) = v.source else {
                self.refuse(
                    codes::CV005.code,
                    v.span,
                    format!("`{}` is set by code, not a Vectric label", v.name),
                    "a section post's variables print labels",
                );
                self.names.push(String::new());
                continue;
            };
            let wanted = if is_identifier(&v.name) { v.name.clone() } else { format!("v_{}", q.label()) };
            let mut name = wanted.clone();
            let mut n = 1;
            while taken.contains(&name) || !is_identifier(&name) {
                n += 1;
                name = format!("{wanted}_{n}");
            }
            taken.insert(name.clone());
            let Ok(prefix) = String::from_utf8(v.prefix.clone()) else {
                self.refuse(codes::CV005.code, v.span, format!("the prefix of `{}` is not text", v.name), "");
                continue;
            };
            let mut var_keys = vec![format!("prefix: {}", js_string(&prefix)), format!("label: \"{}\"", q.label())];
            if v.modality == Modality::OnChange {
                var_keys.push("modal: true".into());
            }
            let format = post.formats.get(v.format.index()).cloned().unwrap_or_default();
            let format_keys = format_keys(&format);
            self.out.push_str(&super::comment(post, &CommentTarget::Variable(VarId::new(id as u16))));
            self.out.push_str(&format!(
                "var {name} = createVariable({{{}}}, createFormat({{{}}}));\n",
                var_keys.join(", "),
                format_keys.join(", ")
            ));
            self.names.push(name);
        }
        self.out.push('\n');
    }

    /// Output text in the post's encoding, as characters.
    fn decode(&self, bytes: &[u8]) -> Option<String> {
        if self.post.info.text_encoding == TextEncoding::Windows1252 {
            Some(encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes).0.into_owned())
        } else {
            String::from_utf8(bytes.to_vec()).ok()
        }
    }

    fn sections(&mut self) {
        let post = self.post;
        for section in Section::ALL.iter().copied() {
            let Some(h) = post.handlers.iter().find(|h| h.key == HandlerKey::Section(section)) else { continue };
            let mut lines = Vec::new();
            for s in &h.body {
                let Stmt::Line { pieces, span } = s else { continue };
                let mut parts: Vec<String> = Vec::new();
                for p in pieces {
                    match p {
                        Piece::Text(bytes) => match self.decode(bytes) {
                            Some(t) if !t.contains('\n') => parts.push(js_string(&t)),
                            _ => self.refuse(
                                codes::CV002.code,
                                *span,
                                "output text that is not UTF-8 or holds a line break".into(),
                                "a section post's text is JavaScript strings, lines ended by \"\\n\"",
                            ),
                        },
                        Piece::Var(v) => parts.push(self.names.get(v.index()).cloned().unwrap_or_default()),
                        Piece::Expr(_) => {}
                    }
                }
                // The line ends inside its last text, or after its last variable.
                match pieces.last() {
                    Some(Piece::Text(_)) if parts.last().is_some_and(|l| l.ends_with('"')) => {
                        if let Some(last) = parts.last_mut() {
                            last.insert_str(last.len() - 1, "\\n");
                        }
                    }
                    _ => parts.push("\"\\n\"".into()),
                }
                lines.push(parts.join(" + "));
            }
            self.out.push_str(&super::comment(post, &CommentTarget::Handler(h.key.clone())));
            self.out.push_str(&format!("function {}() {{\n", section.name()));
            if lines.is_empty() {
                self.out.push_str("    return \"\";\n");
            } else {
                self.out.push_str(&format!("    return {};\n", lines.join(" +\n        ")));
            }
            self.out.push_str("}\n\n");
        }
    }
}

/// The `createFormat` keys of a format: those that differ from the IR's
/// defaults (a section post's formats start from them).
fn format_keys(f: &NumberFormat) -> Vec<String> {
    let d = NumberFormat::default();
    let mut k = Vec::new();
    if f.decimals != d.decimals {
        k.push(format!("decimals: {}", f.decimals));
    }
    if f.width != d.width {
        k.push(format!("width: {}", f.width));
    }
    if f.width_of != d.width_of {
        k.push(format!("widthOfIntegerDigits: {}", f.width_of == WidthOf::IntegerDigits));
    }
    if f.padding != d.padding {
        k.push(format!("zeropad: {}", f.padding == Padding::Zero));
    }
    if f.justify != d.justify {
        k.push(format!("justifyLeft: {}", f.justify == Justify::Left));
    }
    if f.sign != d.sign {
        k.push(format!("forceSign: {}", f.sign == SignStyle::Always));
    }
    if f.point != d.point {
        k.push(format!("forceDecimal: {}", f.point == PointStyle::Always));
    }
    if f.trim_zeros != d.trim_zeros {
        k.push(format!("trim: {}", f.trim_zeros));
    }
    if f.leading_zero != d.leading_zero {
        k.push(format!("leadingZero: {}", f.leading_zero));
    }
    if f.decimal_mark != d.decimal_mark {
        k.push(format!("decimalMark: {}", js_string(&f.decimal_mark.to_string())));
    }
    if f.multiplier != d.multiplier {
        k.push(format!("scale: {}", number(f.multiplier)));
    }
    if f.prefix != d.prefix {
        k.push(format!("prefix: {}", js_string(&f.prefix)));
    }
    if f.rounding != d.rounding {
        k.push(format!("binaryRounding: {}", f.rounding == postc_ir::format::Rounding::Binary));
    }
    if f.negative_zero != d.negative_zero {
        k.push(format!("negativeZero: {}", f.negative_zero));
    }
    k
}
