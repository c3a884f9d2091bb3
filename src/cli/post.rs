//! `postc post`: posts a toolpath through a post, to a file (written whole
//! or not at all) or to standard output. A VcPost probe table (`.csv`) or
//! composites event file goes to `probe.rs` instead.

use postc_ir::codes;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use postc_ir::codes::{Level, LevelRules};
use postc_ir::{Diagnostic, Severity, SourceMap};
use postc_ir::event::FileInfo;
use postc_runtime::output::Sink;
use postc_runtime::{Finished, Output, RunOptions};
use postc_verify::{Controller, Settings};

use super::verifying::{Outcome, Verification};
use super::{DialectArg, Failed, fail, load_post_with, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// POST TOOLPATH, or just TOOLPATH to use the embedded G-code post.
    #[arg(required = true, num_args = 1..=2, value_name = "POST TOOLPATH")]
    files: Vec<PathBuf>,
    /// Write the program here (tape-split parts go beside it) instead of to standard output.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// Set a job value: date, time (what [DATE] and [TIME] print), tolerance (mm, for linearized arcs).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
    /// Compute arc words from the printed start and end points, so the radius agrees at both ends.
    #[arg(long)]
    exact_arcs: bool,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    /// VcPost composites: run this #Primer Sub before the event file's calls (repeatable).
    #[arg(long, value_name = "NAME")]
    primer: Vec<String>,
    /// Verify the program (the default), and print verify's summary: it is replayed while it is posted and compared with the toolpath, as `postc verify` does; a program with an error finding is not written.
    #[arg(long, conflicts_with = "no_verify")]
    verify: bool,
    /// Do not verify the program: write it whatever it does.
    #[arg(long)]
    no_verify: bool,
    #[command(flatten)]
    levels: super::levels::Flags,
    /// Write which post statement wrote each output line, for which toolpath event, as JSON Lines (docs/trace.md); read it with `postc explain TRACE LINE`.
    #[arg(long, value_name = "TRACE.jsonl")]
    trace: Option<PathBuf>,
}

/// `--set` names and what they do.
const SETTINGS: &str = "date, time, tolerance";

/// Applies `--set NAME=VALUE` pairs to the run options.
pub(crate) fn apply_sets(sets: &[String], options: &mut RunOptions) -> Result<(), Diagnostic> {
    for set in sets {
        let Some((name, value)) = set.split_once('=') else {
            return Err(Diagnostic::error(codes::IO007, format!("`--set {set}` needs the form NAME=VALUE"))
                .help(format!("known names: {SETTINGS}")));
        };
        match name.trim().to_ascii_lowercase().as_str() {
            "date" => options.date = Some(value.to_string()),
            "time" => options.time = Some(value.to_string()),
            "tolerance" | "arc_tolerance" => match value.trim().parse::<f64>() {
                Ok(t) if t > 0.0 => options.arc_tolerance = Some(t),
                _ => {
                    return Err(Diagnostic::error(
                        codes::IO007,
                        format!("`--set {set}`: the tolerance must be a positive number of mm"),
                    ));
                }
            },
            other => {
                return Err(Diagnostic::error(codes::IO007, format!("`--set {other}` is not a setting postc knows"))
                    .help(format!("known names: {SETTINGS}")));
            }
        }
    }
    Ok(())
}

/// The output file as `[TP_FILENAME]`, `[TP_DIR]` and `[TP_EXT]` print it.
fn file_info(path: &Path) -> FileInfo {
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    FileInfo {
        name: path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
        dir: absolute.parent().map(|p| p.display().to_string()).unwrap_or_default(),
        extension: path.extension().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
    }
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    args.levels.check(&mut sources)?;
    let (post_path, toolpath) = match args.files.as_slice() {
        [toolpath] => (None, toolpath),
        [post, toolpath] => (Some(post), toolpath),
        _ => unreachable!("clap takes one or two files"),
    };
    let inputs: Vec<&Path> = args.files.iter().map(PathBuf::as_path).collect();
    let outputs: Vec<&Path> = args.output.iter().chain(&args.trace).map(PathBuf::as_path).collect();
    super::outputs::check_paths(&inputs, &outputs).map_err(|d| fail(&mut sources, d))?;
    if let Some(kind) = super::probe::job_kind(toolpath) {
        let mut options = super::clock::run_options();
        apply_sets(&args.sets, &mut options).map_err(|d| fail(&mut sources, d))?;
        options.file = args.output.as_deref().map(file_info);
        let job = super::probe::Job {
            post: post_path,
            input: toolpath,
            kind,
            dialect: args.dialect,
            primers: &args.primer,
            output: args.output.as_ref(),
            options,
        };
        return super::probe::run_calls(job);
    }
    if let Some(post) = post_path
        && args.dialect.is_none()
        && postc_frontends::is_toolpath(post, &postc_report::FsLoader)
        && !postc_frontends::is_toolpath(toolpath, &postc_report::FsLoader)
        && toolpath.exists()
    {
        return Err(fail(
            &mut sources,
            Diagnostic::error(
                codes::IO006,
                format!("`{}` is a toolpath and `{}` is not: the post comes first", post.display(), toolpath.display()),
            )
            .help(format!("postc post {} {}", toolpath.display(), post.display())),
        ));
    }
    if post_path.is_none() && !postc_frontends::is_toolpath(toolpath, &postc_report::FsLoader) {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO006, format!("`{}` is not a toolpath", toolpath.display()))
                .help("give a post and a toolpath (`postc post POST TOOLPATH`), or a toolpath alone to use the embedded G-code post"),
        ));
    }
    let rules = args.levels.rules_for(Some(post_path.unwrap_or(toolpath))).map_err(|d| fail(&mut sources, d))?;
    let post = load_post_with(post_path, args.dialect, &mut sources, &rules)?;
    let mut options = RunOptions {
        exact_arcs: args.exact_arcs,
        script_host: postc_frontends::script_host(&post),
        ..super::clock::run_options()
    };
    apply_sets(&args.sets, &mut options).map_err(|d| fail(&mut sources, d))?;
    if let Some(out) = &args.output {
        options.file = Some(file_info(out));
    }
    let mut source = postc_frontends::open_toolpath(toolpath, &mut sources).map_err(|d| fail(&mut sources, d))?;
    let batch = super::outputs::Batch::default();
    let program: Box<dyn Sink> = match &args.output {
        Some(path) => Box::new(
            super::sink::FileSink::new(path, &batch)
                .map_err(|e| fail(&mut sources, super::outputs::cannot_write(path, &e)))?,
        ),
        None => {
            if post.options.tape_splitting.is_some() {
                let mut warning = vec![Diagnostic::warning(
                    codes::IO008,
                    "the post splits its output into parts, but there is no -o; all parts go to standard output one after the other",
                )];
                rules.apply(&mut warning);
                report::eprint(&mut sources, &warning);
                if postc_ir::diagnostic::has_errors(&warning) {
                    return Err(Failed);
                }
            }
            Box::new(super::sink::StdoutSink::default())
        }
    };
    let name = args.output.as_ref().map_or_else(|| "<standard output>".to_string(), |p| p.display().to_string());
    let verification = match verified(&args, &post) {
        true => {
            let file = sources.add_streamed(name.clone());
            let settings = Settings::from_post(&post, Controller::Generic, 0.01);
            let started = Verification::start(file, settings).map_err(|e| {
                fail(
                    &mut sources,
                    Diagnostic::error(codes::IO003, format!("cannot start verifying the program: {e}"))
                        .help("post with `--no-verify` to write it unverified"),
                )
            })?;
            Some((started, file))
        }
        false => None,
    };
    let out = Output::new(match &verification {
        Some((v, _)) => v.sink(program),
        None => program,
    });
    let recorder = match &args.trace {
        Some(path) => {
            let r = super::trace::Recorder::new(path).map_err(|e| {
                fail(
                    &mut sources,
                    Diagnostic::error(codes::IO003, format!("cannot write the trace `{}`: {e}", path.display())),
                )
            })?;
            options.trace = Some(r.sink());
            Some(r)
        }
        None => None,
    };
    let big = std::fs::metadata(toolpath).map(|m| m.len() > (32 << 20)).unwrap_or(false);
    if big && std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_message("posting");
        options.progress = Some(Box::new(move |events| bar.set_message(format!("posted {events} events"))));
    }
    let run = match &verification {
        Some((v, _)) => postc_runtime::run(&post, &mut v.source(&mut *source), out, options),
        None => postc_runtime::run(&post, &mut source, out, options),
    };
    match run {
        Ok(mut report) => {
            rules.apply(&mut report.warnings);
            report::eprint(&mut sources, &report.warnings);
            if postc_ir::diagnostic::has_errors(&report.warnings) {
                match &args.output {
                    Some(_) => eprintln!("postc: a denied warning was reported while posting; nothing was written"),
                    None => eprintln!("postc: a denied warning was reported while posting"),
                }
                return Err(Failed);
            }
            if let Some((v, file)) = verification {
                let (outcome, program, bytes) = v.finish();
                let checked = Checked { name: &name, file, to_stdout: args.output.is_none(), bytes, summary: args.verify };
                checked.judge(outcome, &rules, &mut sources)?;
                let tape = post.options.tape_splitting.as_ref();
                report.output = match program.map(|p| p.finish(tape)) {
                    Some(Ok(output)) => output,
                    Some(Err(e)) => {
                        report::eprint(
                            &mut sources,
                            &[Diagnostic::error(codes::IO003, format!("could not write the program: {e}"))],
                        );
                        eprintln!("postc: posting failed; no output was written");
                        return Err(Failed);
                    }
                    None => Finished::Streamed,
                };
            }
            if let Some(recorder) = recorder {
                let outputs = match &report.output {
                    Finished::Files(files) => files.clone(),
                    _ => vec![PathBuf::from("-")],
                };
                recorder.finish(&sources, &post, &outputs, &batch).map_err(|d| fail(&mut sources, d))?;
            }
            batch.commit(&inputs, Some(&sources)).map_err(|d| fail(&mut sources, d))?;
            if let Finished::Files(files) = &report.output
                && files.len() > 1
            {
                eprintln!(
                    "postc: wrote {} parts: {}",
                    files.len(),
                    files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>().join(", ")
                );
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

/// Output extensions of families verify does not read.
pub(crate) const FOREIGN_EXTENSIONS: &[(&str, &str)] =
    &[("plt", "HPGL"), ("hpgl", "HPGL"), ("hpg", "HPGL"), ("sbp", "ShopBot"), ("h", "Heidenhain conversational")];

/// Whether `post` verifies the program: unless `--no-verify`, and unless
/// verify cannot read it (docs/verify.md, "While posting"): a family
/// other than G-code by the post's or the output's extension, a lathe
/// post, a rotary-wrapped post.
fn verified(args: &Args, post: &postc_ir::Post) -> bool {
    let foreign = |ext: &str| FOREIGN_EXTENSIONS.iter().any(|(e, _)| e.eq_ignore_ascii_case(ext));
    let output_ext = args.output.as_deref().and_then(Path::extension).map(|e| e.to_string_lossy().into_owned());
    !args.no_verify
        && !foreign(&post.info.file_extension)
        && !output_ext.is_some_and(|e| foreign(&e))
        && !post.options.lathe
        && post.options.rotary_wrap.is_none()
}

/// A program verified while it was posted, to be judged.
struct Checked<'a> {
    name: &'a str,
    file: postc_ir::FileId,
    to_stdout: bool,
    bytes: u64,
    /// `--verify` was given: print verify's summary line.
    summary: bool,
}

impl Checked<'_> {
    /// Prints the findings, with the severities the rules give them; fails
    /// when an error remains (the program is then not written).
    fn judge(&self, outcome: Outcome, rules: &LevelRules, sources: &mut SourceMap) -> Result<(), Failed> {
        let Outcome::Verified { report, held } = outcome else { return Ok(()) };
        // Twenty blocks that do not read before any move: text output, not
        // a G-code program verify reads (docs/verify.md).
        if report.findings.iter().any(|d| d.code == codes::VF001.code) {
            return Ok(());
        }
        let mut findings: Vec<Diagnostic> = Vec::new();
        for (mut d, (line, line_start)) in report.findings.into_iter().zip(report.lines) {
            match rules.level(d.code) {
                Some(Level::Allow) => continue,
                Some(Level::Warn) => d.severity = Severity::Warning,
                Some(Level::Deny) => d.severity = Severity::Error,
                None => {}
            }
            if held.is_none() {
                self.locate(&mut d, line, line_start);
            }
            findings.push(d);
        }
        if let Some(bytes) = &held
            && !findings.is_empty()
        {
            sources.hold(self.file, String::from_utf8_lossy(bytes).into_owned());
        }
        report::eprint(sources, &findings);
        if self.summary {
            let s = report.stats;
            eprintln!(
                "postc verify: `{}`: {} error(s), {} warning(s); {} lines, {} moves replayed, {} of {} toolpath moves made",
                self.name, report.errors, report.warnings, s.lines, s.motions, s.matched, s.expected
            );
        }
        let mut denied: Vec<&str> = findings.iter().filter(|d| d.is_error()).map(|d| d.code).collect();
        if denied.is_empty() {
            return Ok(());
        }
        denied.sort_unstable();
        denied.dedup();
        let written = if self.to_stdout && self.bytes > super::sink::HOLD_STDOUT as u64 {
            format!(
                "the program was not finished on standard output (its first {} MiB had gone out: postc holds back only {} MiB)",
                self.bytes / (1 << 20),
                super::sink::HOLD_STDOUT >> 20
            )
        } else {
            "the program was not written".to_string()
        };
        eprintln!(
            "postc: verifying the program found errors ({}); {written}. To write it anyway, post with `--no-verify`, or let these findings through with {}",
            denied.join(", "),
            denied.iter().map(|c| format!("`--allow {c}`")).collect::<Vec<_>>().join(" ")
        );
        Err(Failed)
    }

    /// A finding in a program too long to hold: its labels in the program
    /// become a note with the line and column.
    fn locate(&self, d: &mut Diagnostic, line: u64, line_start: usize) {
        let mut notes = Vec::new();
        d.labels.retain(|l| {
            if l.span.file != self.file {
                return true;
            }
            let column = l.span.start.saturating_sub(line_start) + 1;
            notes.push(format!("{}:{line}:{column}: {}", self.name, l.message));
            false
        });
        d.notes.splice(0..0, notes);
    }
}
