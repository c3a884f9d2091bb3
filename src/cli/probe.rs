//! VcPost's applications that are not driven by a toolpath:
//!
//! - `postc probe-table POST`: prints an empty probe-cycle table for a post,
//!   from its keyword comments (one row per probe Sub, its parameters as
//!   cells, `!` marking a mandatory one);
//! - `postc post POST TABLE.csv`: runs a probe-cycle table;
//! - `postc post POST FILE.vcp.ron|FILE.vcp.jsonl [--primer NAME]...`: runs a
//!   composites event file.
//!
//! `postc post` hands a file to [`run_calls`] when [`job_kind`] recognises
//! it: a `.csv` file is a probe table; a `.vcp.ron`/`.vcp.jsonl` file, or
//! one whose first line is `VcpFile(...)`, is a composites event file.

use postc_ir::codes;
use std::path::{Path, PathBuf};

use postc_ir::{CallSource, Diagnostic, Dialect, Post, SourceMap};
use postc_runtime::{Finished, RunOptions};

use super::{DialectArg, Failed, fail, load_post, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The VcPost post whose keyword comments make the table.
    #[arg(value_name = "POST")]
    post: PathBuf,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
}

/// `postc probe-table POST`.
pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let post = load_post(Some(&args.post), args.dialect, &mut sources)?;
    match postc_front_vcpost::table::template(&post) {
        Some(text) => {
            report::out(&text);
            Ok(())
        }
        None => Err(fail(
            &mut sources,
            Diagnostic::error(codes::PT016, format!("`{}` has no probe-cycle Subs", args.post.display())).help(
                "probe-cycle Subs carry a keyword comment: `' #Init`, `' #Rapid !X !Y !Z`, `' #Cycle !X !Y Width`, ...",
            ),
        )),
    }
}

/// Inputs of `postc post` that are not toolpaths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JobKind {
    /// A probe-cycle table (`.csv`).
    ProbeTable,
    /// A composites event file.
    Composites,
}

/// What a `postc post` input is, when it is not a toolpath.
pub fn job_kind(path: &Path) -> Option<JobKind> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if ext.as_deref() == Some("csv") {
        Some(JobKind::ProbeTable)
    } else if postc_front_vcpost::composites::is_composites_file(path, &postc_report::FsLoader) {
        Some(JobKind::Composites)
    } else {
        None
    }
}

/// What `postc post` passes on for a probe table or an event file.
pub struct Job<'a> {
    pub post: Option<&'a PathBuf>,
    pub input: &'a Path,
    pub kind: JobKind,
    pub dialect: Option<DialectArg>,
    pub primers: &'a [String],
    pub output: Option<&'a PathBuf>,
    pub options: RunOptions,
    /// `--no-verify` was not given: the note says that the program is not verified.
    pub verify: bool,
}

/// Runs a probe table or a composites event file through a VcPost post.
pub fn run_calls(job: Job<'_>) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let Some(post_path) = job.post else {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO006, format!("`{}` needs a VcPost post", job.input.display()))
                .help("postc post POST.VcPost TABLE.csv, or postc post POST.VcPost EVENTS.vcp.ron"),
        ));
    };
    let post = load_post(Some(post_path), job.dialect, &mut sources)?;
    if post.info.dialect != Dialect::VcPost {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO006, format!("`{}` is not a VcPost post", post_path.display()))
                .help("probe tables and composites event files are read against a VcPost post's Subs"),
        ));
    }
    if job.kind == JobKind::ProbeTable && !job.primers.is_empty() {
        report::eprint(
            &mut sources,
            &[Diagnostic::warning(codes::IO007, "--primer only applies to composites event files; ignored")],
        );
    }
    let mut source = open(&job, &post, &mut sources)?;
    let batch = super::outputs::Batch::default();
    let out = match job.output {
        Some(path) => {
            super::sink::file(path, &batch).map_err(|e| fail(&mut sources, super::outputs::cannot_write(path, &e)))?
        }
        None => super::sink::stdout(),
    };
    let mut options = job.options;
    let big = std::fs::metadata(job.input).map(|m| m.len() > (32 << 20)).unwrap_or(false);
    let spinner = big.then(|| report::spinner("running the calls")).flatten();
    if let Some(bar) = &spinner {
        let shown = bar.clone();
        options.progress = Some(Box::new(move |calls| shown.set_message(format!("ran {calls} calls"))));
    }
    let ran = postc_runtime::calls::run_calls(&postc_driver::for_calls(&post), &mut source, out, options);
    if let Some(bar) = spinner {
        bar.finish_and_clear();
    }
    match ran {
        Ok(report) => {
            report::eprint(&mut sources, &report.warnings);
            if job.verify {
                let what = match job.kind {
                    JobKind::ProbeTable => "a probe table",
                    JobKind::Composites => "a composites event file",
                };
                let name = job.output.map_or_else(|| "<standard output>".to_string(), |p| p.display().to_string());
                let note = Diagnostic::new(
                    postc_ir::Severity::Note,
                    codes::VF044,
                    format!("`{name}` was not verified: {what} has no toolpath moves to compare the program with"),
                );
                report::eprint(&mut sources, &[note]);
            }
            let inputs: Vec<&Path> = job.post.iter().map(|p| p.as_path()).chain([job.input]).collect();
            batch.commit(&inputs, Some(&sources)).map_err(|d| fail(&mut sources, d))?;
            if let Finished::Files(files) = &report.output {
                let names = files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>().join(", ");
                let parts = if files.len() > 1 { format!("{} parts: ", files.len()) } else { String::new() };
                report::wrote(format_args!("{parts}{names} ({} blocks, {} bytes)", report.blocks, report.bytes));
            }
            Ok(())
        }
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postc: posting failed; no output was written");
            Err(Failed)
        }
    }
}

/// Reads the input into a call source: a probe table whole (it is small
/// and its rows are checked together), an event file line by line.
fn open(job: &Job<'_>, post: &Post, sources: &mut SourceMap) -> Result<Box<dyn CallSource>, Failed> {
    match job.kind {
        JobKind::ProbeTable => {
            let bytes = std::fs::read(job.input).map_err(|e| {
                fail(sources, Diagnostic::error(codes::IO001, format!("cannot read `{}`: {e}", job.input.display())))
            })?;
            let Ok(text) = String::from_utf8(bytes) else {
                return Err(fail(
                    sources,
                    Diagnostic::error(codes::PT001, format!("`{}` is not UTF-8 text", job.input.display())),
                ));
            };
            let text = text.strip_prefix('\u{FEFF}').map(str::to_string).unwrap_or(text);
            let file = sources.add(job.input.display().to_string(), text);
            let (calls, diagnostics) = postc_front_vcpost::table::read(sources.text(file).unwrap_or(""), file, post);
            report::eprint(sources, &diagnostics);
            if postc_ir::diagnostic::has_errors(&diagnostics) {
                eprintln!("postc: `{}` has errors; nothing was posted", job.input.display());
                return Err(Failed);
            }
            Ok(Box::new(calls.into_iter()))
        }
        JobKind::Composites => {
            let mut diagnostics = Vec::new();
            let primers = postc_front_vcpost::composites::primers(post, job.primers, &mut diagnostics);
            report::eprint(sources, &diagnostics);
            if postc_ir::diagnostic::has_errors(&diagnostics) {
                return Err(Failed);
            }
            let reader = postc_front_vcpost::composites::open(job.input, sources, post, primers)
                .map_err(|d| fail(sources, d))?;
            Ok(Box::new(reader))
        }
    }
}
