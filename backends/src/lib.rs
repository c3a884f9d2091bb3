//! # postc backends
//!
//! A backend prints a compiled post IR ([`postc_ir::Post`]) as the text of
//! a post in one target: a Vectric `.pp` post ([`vectric`]), a Vericut
//! VcPost post ([`vcpost`]), a CIMCO CNC-Calc post ([`cimco`]), an
//! Autodesk Fusion `.cps` post ([`fusion`]) or the IR itself as RON
//! ([`ron`]). The two JavaScript targets share the Vectric rules printed
//! as JavaScript (`js_sections`). Backends read only the IR, never a dialect's
//! syntax tree, so a post of any dialect converts to any target that can
//! say what it does.
//!
//! A backend never writes a post that would post differently from its
//! source. What a target cannot express is refused with a
//! [`Diagnostic`] (codes `CV001`–`CV013`) that names the construct, points
//! at it in the source post where the IR knows where it came from, and
//! says why; nothing is written then. `tests/convert.rs` posts every
//! converted corpus post over every corpus toolpath and requires the same
//! bytes as the source post, and `docs/convert.md` holds the matrix of
//! what converts.
//!
//! Every converted post starts with a comment that names the file and
//! dialect it was converted from.

pub mod cimco;
pub mod fusion;
mod js_sections;
pub mod ron;
pub mod vcpost;
pub mod vectric;

use postc_ir::{Diagnostic, Dialect, Post};

/// The dialects `postc convert` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// A Vectric `.pp` post.
    Vectric,
    /// A Vericut VcPost post that Vericut runs: a VcPost post as itself, a
    /// post driven by APT words as a milling post. A post of another
    /// dialect driven by the kind of each move is refused (postc prints
    /// no VcPost milling post from one yet).
    VcPost,
    /// A VcPost post; a post of another dialect driven by the kind of each
    /// move as a *section post*: postc's extension, which Vericut does not
    /// run (`--postc-extension`).
    VcPostSections,
    /// A CIMCO CNC-Calc JavaScript post that CNC-Calc runs: a CIMCO post
    /// with code as itself, another post driven by the kind of move as a
    /// native CNC-Calc post (the CNC-Calc manual's entry points).
    Cimco,
    /// A CIMCO post, a post of another dialect as a *section post*:
    /// postc's extension, which CNC-Calc does not run (`--postc-extension`).
    CimcoSections,
    /// An Autodesk Fusion `.cps` post that Fusion's engine runs (from
    /// Vectric and CIMCO posts, and a Fusion post as written).
    Fusion,
    /// The IR as RON (loads back with `postc post converted.ron ...`).
    Ron,
}

impl Target {
    /// The extension a converted post gets.
    pub fn extension(self) -> &'static str {
        match self {
            Target::Vectric => "pp",
            Target::VcPost | Target::VcPostSections => "VcPost",
            Target::Cimco | Target::CimcoSections => "js",
            Target::Fusion => "cps",
            Target::Ron => "ron",
        }
    }
}

/// Prints `post` as a post of `target`: the bytes of the post file, or
/// every reason the target cannot hold it.
pub fn convert(post: &Post, target: Target) -> Result<Vec<u8>, Vec<Diagnostic>> {
    convert_warned(post, target).map(|(text, _)| text)
}

/// [`convert`], with the warnings of the conversion: constructs the target
/// leaves out, each at its place in the source.
pub fn convert_warned(post: &Post, target: Target) -> Result<(Vec<u8>, Vec<Diagnostic>), Vec<Diagnostic>> {
    match target {
        Target::Vectric => vectric::print(post).map(|t| (t, Vec::new())),
        Target::VcPost => vcpost::print(post).map(|t| (t, Vec::new())),
        Target::VcPostSections => vcpost::print_extension(post).map(|t| (t, Vec::new())),
        Target::Cimco => cimco::print(post),
        Target::CimcoSections => cimco::print_extension(post).map(|t| (t, Vec::new())),
        Target::Fusion => fusion::print(post),
        Target::Ron => ron::print(post).map(|t| (t.into_bytes(), Vec::new())),
    }
}

/// The dialect's name as people write it, for header comments.
pub(crate) fn dialect_name(d: Dialect) -> &'static str {
    match d {
        Dialect::Vectric => "Vectric",
        Dialect::Cimco => "CIMCO CNC-Calc JavaScript",
        Dialect::Fusion => "Autodesk Fusion JavaScript (.cps)",
        Dialect::VcPost => "Vericut VcPost",
        Dialect::Ron => "postc IR (RON)",
    }
}

/// A one-file post of `dialect` printed as its source file has it
/// (`PostInfo::written`), after the conversion `note` line and in the
/// file's own line ending: the bytes, when `compile` (the dialect's
/// frontend) reads them back as `post` (compared without spans, the
/// file's hash and the text itself); `None` otherwise, and the backend
/// prints the post from the IR. `encode` gives the file's bytes (`None`:
/// its encoding cannot hold the text).
pub(crate) fn as_written(
    post: &Post,
    dialect: Dialect,
    note: &str,
    compile: impl Fn(&std::path::Path, &[u8], &mut postc_ir::SourceMap) -> (Post, Vec<Diagnostic>),
    encode: impl Fn(&str) -> Option<Vec<u8>>,
) -> Option<Vec<u8>> {
    let written = post.info.written.as_str();
    if written.is_empty() || post.info.dialect != dialect {
        return None;
    }
    // A byte order mark stays first; a converted post's own note is not
    // the source's.
    let (bom, mut body) = match written.strip_prefix('\u{feff}') {
        Some(rest) => ("\u{feff}", rest),
        None => ("", written),
    };
    while let Some(line) = body.split_inclusive('\n').next()
        && postc_ir::post::is_conversion_note(line.trim_start_matches(['+', '\'', '/']))
    {
        body = &body[line.len()..];
    }
    let eol = if written.contains("\r\n") { "\r\n" } else { "\n" };
    let bytes = encode(&format!("{bom}{note}{eol}{body}"))?;
    let mut sources = postc_ir::SourceMap::new();
    let (back, diagnostics) = compile(std::path::Path::new(&post.info.source), &bytes, &mut sources);
    let normal = |p: &Post| {
        let mut p = p.clone();
        p.drop_spans();
        p.drop_written();
        p.info.revision.clear();
        ::ron::to_string(&p).ok().map(|t| without_offsets(&t))
    };
    (!diagnostics.iter().any(Diagnostic::is_error) && normal(&back) == normal(post)).then_some(bytes)
}

/// A JavaScript frontend names the temporaries of a destructuring pattern
/// and of a pattern parameter by the pattern's offset in the file
/// (`__postc_d1234`, `__postc_p1234`): a line added before it moves the
/// offset as it moves the spans, which the comparison of [`as_written`]
/// leaves out alike.
fn without_offsets(ron: &str) -> String {
    const TEMP: &str = "__postc_";
    let mut out = String::with_capacity(ron.len());
    let mut rest = ron;
    while let Some(i) = rest.find(TEMP) {
        let after = &rest[i + TEMP.len()..];
        let offset = after.strip_prefix(['d', 'p']).filter(|a| a.starts_with(|c: char| c.is_ascii_digit()));
        match offset {
            Some(digits) => {
                out.push_str(&rest[..i + TEMP.len() + 1]);
                rest = digits.trim_start_matches(|c: char| c.is_ascii_digit());
            }
            None => {
                out.push_str(&rest[..i + TEMP.len()]);
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// The file name of the post's source, without its folder.
pub(crate) fn source_name(post: &Post) -> &str {
    let s = post.info.source.as_str();
    s.rsplit(['/', '\\']).next().unwrap_or(s)
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/backends/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod cimco_body {
        pub use crate::cimco::body::{at, function};
    }
}
