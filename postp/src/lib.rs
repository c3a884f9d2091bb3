//! `postp`: the APT CL post processor (a Windows console program), reimplemented. It reads `DIR/cl.tap`, and
//! the file's `MACHIN/name[,axis type]` chooses one of eight controllers
//! (ACORNM, ACORNL, FANUCM, FANUCL, HAASM, HAASL, TORMM, TORML).
//!
//! How a CL file becomes a program:
//!
//! 1. [`head`] reads the head of the file with the CL reader until MACHIN
//!    (it must come before any motion or tool) and takes the units.
//! 2. The controller's post (a VcPost file, one Sub per APT word, embedded
//!    from `corpus/posts/postp/NAME.VcPost`) is compiled, and its options
//!    (`NAME.ron`, overridden field by field by `--options FILE`) are set
//!    as the post's globals before its first statement runs ([`options`]).
//! 3. The CL reader's events go through the [`transform`], which computes
//!    the motions the CL file does not hold (RETRCT, CLRSRF/NOW, LETTER),
//!    applies TRANS and ROTABL's cylindrical mapping, checks every word and
//!    the machine it is used on, and hands the post each word with fixed
//!    arguments.
//! 4. The runtime runs the post over those events (APT-word dispatch) and
//!    writes the program whole, or nothing when there is an error.
//!
//! `docs/apt.md` ("Controllers") documents each controller's output, the
//! options and the words the posts receive.

pub mod controller;
pub mod font;
pub mod letter;
pub mod options;
pub mod transform;

use std::path::{Path, PathBuf};

use postc_ir::event::{Arg, Event, FileInfo};
use postc_ir::{Diagnostic, Dialect, EventSource, Post, SourceLoader, SourceMap, Span, Units};
use postc_runtime::{Output, RunOptions, RunReport};

pub use controller::{Controller, Kind};
pub use options::{Options, Patch};
use transform::{Machine, Transform, codes};

/// What a run needs besides the CL file.
#[derive(Clone, Debug, Default)]
pub struct Settings {
    /// `--options FILE`: fields replacing the controller's defaults.
    pub options: Option<PathBuf>,
    /// A controller instead of the file's MACHIN (tests).
    pub machine: Option<Controller>,
    /// Now, as a Unix time: what the post prints as the date and time
    /// (see [`RunOptions::now`]); the caller reads the clock.
    pub now: Option<i64>,
}

/// The controller and machine a CL file asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct Head {
    pub controller: Controller,
    pub axis_type: u8,
    pub units: Units,
    /// MACHIN not first.
    pub warnings: Vec<Diagnostic>,
}

/// Reads the head of a CL file: MACHIN and the units.
pub fn head(cl: &Path, forced: Option<Controller>, sources: &mut SourceMap) -> Result<Head, Vec<Diagnostic>> {
    let mut reader = postc_driver::open_toolpath(cl, sources).map_err(|d| vec![d])?;
    let mut diags = Vec::new();
    let mut units = Units::Mm;
    let mut before: Option<Span> = None;
    let mut found: Option<(Vec<Arg>, Span)> = None;
    while let Some((event, span)) = reader.next_event(&mut diags) {
        match event {
            Event::Job(job) => units = job.units,
            Event::Command(c) if c.word.eq_ignore_ascii_case("MACHIN") => {
                found = Some((c.args, span));
                break;
            }
            Event::Rapid(_) | Event::Feed(_) | Event::Arc(_) | Event::Tool(_) | Event::DrillCycle(_) | Event::End => {
                break;
            }
            // The reader makes these itself, stamped with a later record.
            Event::ToolpathStart(_) | Event::ToolpathEnd => {}
            _ => {
                before.get_or_insert(span);
            }
        }
    }
    if postc_ir::diagnostic::has_errors(&diags) {
        return Err(diags);
    }
    let mut warnings = Vec::new();
    let (controller, axis_type) = match (found, forced) {
        (_, Some(c)) => (c, 0),
        (None, None) => {
            return Err(vec![
                Diagnostic::error(
                    codes::NO_MACHIN,
                    format!("{} has no MACHIN statement before its first motion", cl.display()),
                )
                .help(format!("start the file with MACHIN/name, name one of {}", controller::names())),
            ]);
        }
        (Some((args, span)), None) => {
            let name = match args.first() {
                Some(Arg::Word(w)) => w.clone(),
                _ => String::new(),
            };
            let Some(c) = Controller::from_name(&name) else {
                return Err(vec![
                    Diagnostic::error(codes::UNKNOWN_MACHIN, format!("MACHIN/{name} is not a controller postp knows"))
                        .at(span, "unknown controller")
                        .help(format!("the names are {}", controller::names())),
                ]);
            };
            let axis = match args.get(1) {
                None => Some(0),
                Some(Arg::Number(n)) if (0.0..=6.0).contains(n) && n.fract() == 0.0 => Some(*n as u8),
                _ => None,
            };
            match axis {
                Some(0) => {}
                Some(_) if c.kind() == Kind::Mill && args.len() == 2 => {}
                _ => {
                    let d = Diagnostic::error(
                        codes::BAD_AXIS_TYPE,
                        format!("MACHIN/{name}: the axis type is 0 to 6, on mills only"),
                    )
                    .at(span, "this axis type")
                    .help("1: A, 2: B, 3: A and B (head), 4: A and B, 5: A and C, 6: B and C");
                    return Err(vec![d]);
                }
            }
            if let Some(first) = before.filter(|b| b.start < span.start) {
                warnings.push(
                    Diagnostic::warning(codes::MACHIN_NOT_FIRST, "MACHIN must be the first statement")
                        .at(span, "MACHIN")
                        .also(first, "this came before it"),
                );
            }
            (c, axis.unwrap_or(0))
        }
    };
    Ok(Head { controller, axis_type, units, warnings })
}

/// The controller's options with the `--options` file applied.
pub fn load_options(c: Controller, file: Option<&Path>, sources: &mut SourceMap) -> Result<Options, Diagnostic> {
    let bad = |name: &str, text: &str, (msg, line, col): (String, usize, usize), sources: &mut SourceMap| {
        let id = sources.add(name.to_string(), text.to_string());
        let start = offset(text, line, col);
        Diagnostic::error(codes::BAD_OPTIONS, format!("options file: {msg}"))
            .at(Span::new(id, start, (start + 1).min(text.len().max(start))), "here")
            .help("see the options schema in docs/apt.md")
    };
    let defaults = Patch::parse(c.default_options())
        .map_err(|e| bad(&format!("<embedded>/postp/{}.ron", c.name()), c.default_options(), e, sources))?;
    let mut options = Options::default().apply(defaults);
    if let Some(path) = file {
        let text = read_text(sources.loader(), path).map_err(|e| {
            Diagnostic::error(codes::BAD_OPTIONS, format!("cannot read the options file {}: {e}", path.display()))
        })?;
        let patch = Patch::parse(&text).map_err(|e| bad(&path.display().to_string(), &text, e, sources))?;
        options = options.apply(patch);
    }
    Ok(options)
}

/// A text file read through the loader, refused when it is not UTF-8.
fn read_text(loader: &dyn SourceLoader, path: &Path) -> std::io::Result<String> {
    String::from_utf8(loader.read(path)?)
        .map_err(|_| std::io::Error::new(std::io::ErrorKind::InvalidData, "stream did not contain valid UTF-8"))
}

/// The byte offset of a 1-based line and column.
fn offset(text: &str, line: usize, col: usize) -> usize {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    (start + col.saturating_sub(1)).min(text.len())
}

/// Compiles a controller's post with its options set.
pub fn compile(head: &Head, options: &Options, sources: &mut SourceMap) -> Result<Post, Vec<Diagnostic>> {
    let c = head.controller;
    let name = c.post_name();
    let compiled = postc_driver::compile_post_bytes(Path::new(&name), c.post_source(), Some(Dialect::VcPost), sources);
    match compiled.post {
        Some(mut post) if !compiled.has_errors() => {
            options.inject(&mut post, head.units, head.axis_type, c.name());
            Ok(post)
        }
        _ => {
            let mut d = compiled.diagnostics;
            d.push(Diagnostic::error(codes::POST_FAILED, format!("the embedded {c} post does not compile")));
            Err(d)
        }
    }
}

/// Posts a CL file (`DIR/cl.tap` for `postc postp DIR`) into `out`.
pub fn post(
    cl: &Path,
    settings: &Settings,
    out: Output,
    sources: &mut SourceMap,
) -> Result<RunReport, Vec<Diagnostic>> {
    if !sources.loader().is_file(cl) {
        return Err(vec![
            Diagnostic::error(codes::NO_CL, format!("there is no CL file {}", cl.display()))
                .help("postp DIR reads DIR/cl.tap, the CL file of the part program"),
        ]);
    }
    let head = head(cl, settings.machine, sources)?;
    let options = load_options(head.controller, settings.options.as_deref(), sources).map_err(|d| vec![d])?;
    let post = compile(&head, &options, sources)?;
    post_compiled(&post, cl, &head, &options, settings.now, out, sources)
}

/// Posts `cl` with a controller post already compiled (by [`compile`], or
/// converted from it and read back): the CL file's words go through the
/// [`transform`] to the post.
pub fn post_compiled(
    post: &Post,
    cl: &Path,
    head: &Head,
    options: &Options,
    now: Option<i64>,
    out: Output,
    sources: &mut SourceMap,
) -> Result<RunReport, Vec<Diagnostic>> {
    let reader = postc_driver::open_toolpath(cl, sources).map_err(|d| vec![d])?;
    let machine = Machine {
        kind: head.controller.kind(),
        name: head.controller.name(),
        axes: controller::rotary_axes(head.axis_type),
        retractz: options.retractz,
    };
    let mut source = Transform::new(reader, machine);
    // No file name: the program's first PARTNO is the CL file's own.
    let run = RunOptions { file: Some(FileInfo::default()), now, ..postc_driver::run_options(post) };
    let prepend = |mut d: Vec<Diagnostic>| {
        d.splice(0..0, head.warnings.iter().cloned());
        d
    };
    match postc_runtime::run(post, &mut source, out, run) {
        Ok(mut report) => {
            report.warnings = prepend(std::mem::take(&mut report.warnings));
            Ok(report)
        }
        Err(d) => Err(prepend(d)),
    }
}

/// What the tests of this crate's modules (the root suite's
/// `tests/modules/postp/`) reach that is not its interface: nothing
/// else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod font {
        pub use crate::font::GLYPHS;
    }
}
