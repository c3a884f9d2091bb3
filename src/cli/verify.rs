//! `postc verify`: reads a G-code program, replays it and compares its
//! motion with the toolpath it was posted from (`docs/verify.md`). Exits 1
//! when anything is out of tolerance.

use postc_ir::codes;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};

use postc_ir::{Diagnostic, Post, SourceMap};
use postc_verify::{Controller, Settings};

use super::report::{self, Format};
use super::{DialectArg, Failed, fail, load_post};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The G-code program to verify.
    program: PathBuf,
    /// The toolpath the program was posted from (.ron, .jsonl, APT CL).
    #[arg(long, value_name = "TOOLPATH")]
    toolpath: PathBuf,
    /// The post that wrote the program: verify learns its units, rounding, arc tolerance and block numbering.
    #[arg(long, value_name = "POST")]
    post: Option<PathBuf>,
    /// The controller whose limits apply (arc radius, block numbers, comment characters).
    #[arg(long, value_enum, default_value = "generic")]
    controller: ControllerArg,
    /// Tolerance in mm; the post's own rounding when that is coarser.
    #[arg(long, value_name = "MM", default_value_t = 0.01)]
    tolerance: f64,
    /// Findings for people, or one JSON array as `check --format json` prints.
    #[arg(long, value_enum, default_value = "human")]
    format: Format,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    /// The program was written by `postc postp` from TOOLPATH (a CL file): compare with the moves postp posts from, with its controller's post.
    #[arg(long, conflicts_with = "post")]
    postp: bool,
    /// The trace `postc post --trace` wrote with the program: each finding also names the post line that wrote it and the toolpath event.
    #[arg(long, value_name = "TRACE.jsonl")]
    trace: Option<PathBuf>,
}

/// Controllers as `--controller` names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ControllerArg {
    /// LinuxCNC: its arc radius tolerance, blocks of at most 252 characters.
    #[value(name = "linuxcnc")]
    LinuxCnc,
    /// Fanuc: 0.01 mm arc radius difference, at most 8 digits a word.
    Fanuc,
    /// Haas: as Fanuc.
    Haas,
    /// grbl: its arc radius tolerance, 80 characters a line without blanks and comments.
    Grbl,
    /// Any RS274 controller: LinuxCNC's limits.
    Generic,
}

impl From<ControllerArg> for Controller {
    fn from(c: ControllerArg) -> Controller {
        match c {
            ControllerArg::LinuxCnc => Controller::LinuxCnc,
            ControllerArg::Fanuc => Controller::Fanuc,
            ControllerArg::Haas => Controller::Haas,
            ControllerArg::Grbl => Controller::Grbl,
            ControllerArg::Generic => Controller::Generic,
        }
    }
}

/// Program files up to this size are loaded whole so findings show their
/// lines; larger ones are streamed and only located by line and column.
const LOAD_LIMIT: u64 = 16 << 20;

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let (post, postp) = post_for(args.post.as_ref(), args.dialect, args.postp, &args.toolpath, &mut sources)?;
    let job = Job {
        program: &args.program,
        toolpath: &args.toolpath,
        post: post.as_ref(),
        controller: args.controller.into(),
        tolerance: args.tolerance,
        format: args.format,
        postp,
        trace: args.trace.as_deref(),
    };
    verify(&job, &mut sources)
}

/// The post a program was written by (`--post`, or postp's for `--postp`), and postp's machine.
pub(crate) fn post_for(
    path: Option<&PathBuf>,
    dialect: Option<DialectArg>,
    postp: bool,
    toolpath: &Path,
    sources: &mut SourceMap,
) -> Result<(Option<Post>, Option<postc_postp::transform::Machine>), Failed> {
    match path {
        Some(path) => Ok((Some(load_post(Some(path), dialect, sources)?), None)),
        None if postp => {
            let report = |sources: &mut SourceMap, d: Vec<Diagnostic>| {
                report::eprint(sources, &d);
                Failed
            };
            let head = postc_postp::head(toolpath, None, sources).map_err(|d| report(sources, d))?;
            let options =
                postc_postp::load_options(head.controller, None, sources).map_err(|d| report(sources, vec![d]))?;
            let post = postc_postp::compile(&head, &options, sources).map_err(|d| report(sources, d))?;
            let machine = postc_postp::transform::Machine {
                kind: head.controller.kind(),
                name: head.controller.name(),
                axes: postc_postp::controller::rotary_axes(head.axis_type),
                retractz: options.retractz,
            };
            Ok((Some(post), Some(machine)))
        }
        None => Ok((None, None)),
    }
}

/// One verification: what `postc verify` and `postc post --verify` run.
pub struct Job<'a> {
    pub program: &'a Path,
    pub toolpath: &'a Path,
    pub post: Option<&'a Post>,
    pub controller: Controller,
    pub tolerance: f64,
    pub format: Format,
    /// The program came from `postc postp`: the toolpath's events go through postp's transform.
    pub postp: Option<postc_postp::transform::Machine>,
    /// The trace of the run that wrote the program (`postc post --trace`):
    /// findings then name the post line and the toolpath event too.
    pub trace: Option<&'a Path>,
}

/// A program opened for verification: its reader, its id in the source
/// map, the settings, and the toolpath's events.
pub(crate) struct Opened {
    pub reader: BufReader<std::fs::File>,
    pub file: postc_ir::FileId,
    pub settings: Settings,
    pub name: String,
    /// The program's size in bytes, for the progress bar.
    pub size: u64,
}

impl Opened {
    /// The program's reader, moving a progress bar of `message` over its
    /// bytes on a terminal (the bar, to clear when the work ends).
    pub fn with_progress(
        reader: BufReader<std::fs::File>,
        size: u64,
        message: &'static str,
    ) -> (Box<dyn std::io::BufRead>, Option<indicatif::ProgressBar>) {
        match report::progress(size, report::Unit::Bytes, message) {
            Some(bar) => (Box::new(bar.wrap_read(reader)), Some(bar)),
            None => (Box::new(reader), None),
        }
    }
}

pub fn verify(job: &Job, sources: &mut SourceMap) -> Result<(), Failed> {
    let started = std::time::Instant::now();
    let Opened { reader, file: file_id, settings, name, size } = open(job, sources)?;
    let mut source = toolpath(job, sources)?;
    let (mut reader, bar) = Opened::with_progress(reader, size, "verifying");
    let mut report = postc_verify::verify(&mut reader, file_id, &mut source, &settings);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    report::step(started, format_args!("replayed `{name}` ({size} bytes) against `{}`", job.toolpath.display()));
    if let Some(trace) = job.trace {
        super::trace::annotate(trace, job.program, &mut report.findings, sources).map_err(|d| fail(sources, d))?;
    }
    let shown = report.findings.len() as u64;
    let total = report.errors + report.warnings;
    match job.format {
        Format::Json => {
            let all: Vec<_> = report.findings.iter().map(|d| (name.clone(), d.clone())).collect();
            report::out(&(report::json(sources, &all) + "\n"));
        }
        Format::Human => {
            report::eprint(sources, &report.findings);
            let more = if total > shown { format!(" ({} more not shown)", total - shown) } else { String::new() };
            let s = report.stats;
            eprintln!(
                "postc verify: `{name}`: {} error(s), {} warning(s){more}; {} lines, {} moves replayed, {} of {} toolpath moves made",
                report.errors, report.warnings, s.lines, s.motions, s.matched, s.expected
            );
        }
    }
    if report.errors > 0 { Err(Failed) } else { Ok(()) }
}

/// Opens the program: settings from the post, refusals of other families, the reader.
pub(crate) fn open(job: &Job, sources: &mut SourceMap) -> Result<Opened, Failed> {
    let name = job.program.display().to_string();
    if !(job.tolerance.is_finite() && job.tolerance > 0.0) {
        return Err(fail(
            sources,
            Diagnostic::error(
                codes::IO007,
                format!("`--tolerance {}`: the tolerance must be a positive number of mm", job.tolerance),
            ),
        ));
    }
    let settings = match job.post {
        Some(post) => Settings::from_post(post, job.controller, job.tolerance),
        None => Settings { controller: job.controller, tolerance: job.tolerance, ..Settings::default() },
    };
    if let Some(refused) = job.post.and_then(|post| postc_verify::post_refusal(&name, post)) {
        return Err(fail(sources, refused));
    }
    let file = std::fs::File::open(job.program)
        .map_err(|e| fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}"))))?;
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut reader = BufReader::with_capacity(1 << 16, file);
    let mut head = Vec::with_capacity(4096);
    if let Err(e) = reader.by_ref().take(4096).read_to_end(&mut head) {
        return Err(fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}"))));
    }
    let ext = job.program.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    if let Some(refused) = postc_verify::refusal(&name, None, &ext, &head) {
        return Err(fail(sources, refused));
    }
    let file_id = if size <= LOAD_LIMIT {
        let mut bytes = head;
        if let Err(e) = reader.read_to_end(&mut bytes) {
            return Err(fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}"))));
        }
        let id = sources.add(name.clone(), String::from_utf8_lossy(&bytes).into_owned());
        reader = BufReader::with_capacity(
            1 << 16,
            std::fs::File::open(job.program)
                .map_err(|e| fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}"))))?,
        );
        id
    } else {
        reader = BufReader::with_capacity(
            1 << 16,
            std::fs::File::open(job.program)
                .map_err(|e| fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{name}`: {e}"))))?,
        );
        sources.add_streamed(name.clone())
    };
    Ok(Opened { reader, file: file_id, settings, name, size })
}

/// The toolpath's events, through postp's transform for a postp program.
pub(crate) fn toolpath(job: &Job, sources: &mut SourceMap) -> Result<Box<dyn postc_ir::EventSource>, Failed> {
    let reader_events = postc_driver::open_toolpath(job.toolpath, sources).map_err(|d| fail(sources, d))?;
    Ok(match &job.postp {
        Some(machine) => Box::new(postc_postp::transform::Transform::new(reader_events, machine.clone())),
        None => reader_events,
    })
}
