//! `postc post`: posts a toolpath through a post, to a file (written whole
//! or not at all) or to standard output. A VcPost probe table (`.csv`) or
//! composites event file goes to `probe.rs` instead.

use postc_ir::codes;
use std::path::{Path, PathBuf};

use postc_driver::settings::{apply_sets, file_info};
use postc_ir::codes::{Level, LevelRules};
use postc_ir::{Diagnostic, Severity, SourceMap};
use postc_runtime::output::Sink;
use postc_runtime::{Finished, Output, RunOptions};
use postc_verify::{Controller, FOREIGN_EXTENSIONS, Settings};

use super::verifying::{Outcome, Verification};
use super::{DialectArg, Failed, fail, load_post_with, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// POST TOOLPATH, or just TOOLPATH to use the embedded G-code post (or the post `--post` names).
    #[arg(required = true, num_args = 1..=2, value_name = "POST TOOLPATH")]
    files: Vec<PathBuf>,
    /// Post with the library's post of this name (`postc posts` lists them): case and blanks do not matter, and a Vectric name's trailing `(*.ext)` may be left out.
    #[arg(long = "post", value_name = "NAME")]
    post_name: Option<String>,
    /// Write the program here (tape-split parts go beside it) instead of to standard output.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// Set a job value: date, time (what [DATE] and [TIME] print), tolerance (mm, 0.0001 to 1, for linearized arcs), property.NAME (a Fusion post's property, as its post dialog sets it).
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
    /// Verify the program (the default) and print verify's summary line as well.
    #[arg(long, conflicts_with = "no_verify")]
    verify: bool,
    /// Do not verify the program while posting it: write it as posted, whatever verify would find.
    #[arg(long)]
    no_verify: bool,
    #[command(flatten)]
    levels: super::levels::Flags,
    /// Write which post statement wrote each output line, for which toolpath event, as JSON Lines (docs/trace.md); read it with `postc explain TRACE LINE`.
    #[arg(long, value_name = "TRACE.jsonl")]
    trace: Option<PathBuf>,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let started = std::time::Instant::now();
    let mut sources = postc_report::source_map();
    args.levels.check(&mut sources)?;
    let chosen = match &args.post_name {
        None => None,
        Some(_) if args.files.len() == 2 => {
            return Err(fail(
                &mut sources,
                Diagnostic::error(
                    codes::IO006,
                    format!("`--post` names the post, and `{}` is given as a post too", args.files[0].display()),
                )
                .help(
                    "give the post by name (`postc post --post NAME TOOLPATH`) or by path (`postc post POST TOOLPATH`)",
                ),
            ));
        }
        Some(name) => Some(super::posts::find(name).map_err(|d| fail(&mut sources, d))?),
    };
    let (embedded, chosen_file) = match chosen.map(|e| e.origin) {
        Some(super::posts::Origin::Embedded(i)) => (Some(crate::library::EMBEDDED[i]), None),
        Some(super::posts::Origin::File(p)) => (None, Some(p)),
        None => (None, None),
    };
    let (post_path, toolpath) = match args.files.as_slice() {
        [toolpath] => (chosen_file.as_ref(), toolpath),
        [post, toolpath] => (Some(post), toolpath),
        _ => unreachable!("clap takes one or two files"),
    };
    let inputs: Vec<&Path> = args.files.iter().chain(&chosen_file).map(PathBuf::as_path).collect();
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
            verify: !args.no_verify,
        };
        return super::probe::run_calls(job);
    }
    if let Some(post) = post_path
        && args.dialect.is_none()
        && postc_driver::is_toolpath(post, &postc_report::FsLoader)
        && !postc_driver::is_toolpath(toolpath, &postc_report::FsLoader)
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
    if post_path.is_none() && embedded.is_none() && !postc_driver::is_toolpath(toolpath, &postc_report::FsLoader) {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO006, format!("`{}` is not a toolpath", toolpath.display()))
                .help("give a post and a toolpath (`postc post POST TOOLPATH`), or a toolpath alone to use the embedded G-code post"),
        ));
    }
    let rules = args.levels.rules_for(Some(post_path.unwrap_or(toolpath))).map_err(|d| fail(&mut sources, d))?;
    let post = match embedded {
        Some(e) => super::load_embedded(e, &mut sources, &rules)?,
        None => load_post_with(post_path, args.dialect, &mut sources, &rules)?,
    };
    let mut options = RunOptions {
        exact_arcs: args.exact_arcs,
        script_host: postc_driver::script_host(&post),
        ..super::clock::run_options()
    };
    apply_sets(&args.sets, &mut options).map_err(|d| fail(&mut sources, d))?;
    let post = postc_driver::settings::post_for_run(post, &mut options);
    if let Some(out) = &args.output {
        options.file = Some(file_info(out));
    }
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).map_err(|d| fail(&mut sources, d))?;
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
    let mut unverified = Vec::new();
    let verification = match (args.no_verify, not_verified(&args, &post)) {
        (true, _) => None,
        (false, Some(why)) => {
            unverified.push(why);
            None
        }
        (false, None) => {
            let file = sources.add_streamed(name.clone());
            let settings = Settings::from_post(&post, Controller::Generic, 0.01);
            let count_lines = args.trace.is_some() && post.options.tape_splitting.is_some();
            let started = Verification::start(file, settings, count_lines).map_err(|e| {
                fail(
                    &mut sources,
                    Diagnostic::error(codes::IO003, format!("cannot start verifying the program: {e}"))
                        .help("post with `--no-verify` to write it unverified"),
                )
            })?;
            Some((started, file))
        }
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
    let spinner = big.then(|| report::spinner("posting")).flatten();
    if let Some(bar) = &spinner {
        let shown = bar.clone();
        options.progress = Some(Box::new(move |events| shown.set_message(format!("posted {events} events"))));
    }
    let run = match &verification {
        Some((v, _)) => postc_runtime::run(&post, &mut v.source(&mut *source), out, options),
        None => postc_runtime::run(&post, &mut source, out, options),
    };
    if let Some(bar) = spinner {
        bar.finish_and_clear();
    }
    let mut report = match run {
        Ok(report) => report,
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postc: posting failed; no output was written");
            return Err(Failed);
        }
    };
    rules.apply(&mut report.warnings);
    report::eprint(&mut sources, &report.warnings);
    report::step(
        started,
        format_args!(
            "posted {} toolpath events from `{}` into {} blocks, {} bytes{}",
            report.events,
            toolpath.display(),
            report.blocks,
            report.bytes,
            if verification.is_some() { ", verified while posting" } else { "" }
        ),
    );
    if postc_ir::diagnostic::has_errors(&report.warnings) {
        match &args.output {
            Some(_) => eprintln!("postc: a denied warning was reported while posting; nothing was written"),
            None => eprintln!("postc: a denied warning was reported while posting"),
        }
        return Err(Failed);
    }
    let tape = post.options.tape_splitting.as_ref();
    let cannot_write = |sources: &mut SourceMap, e: std::io::Error| {
        report::eprint(sources, &[Diagnostic::error(codes::IO003, format!("could not write the program: {e}"))]);
        eprintln!("postc: posting failed; no output was written");
        Failed
    };
    let mut written = Vec::new();
    let mut held_stdout = None;
    let mut verdict = None;
    if let Some((v, file)) = verification {
        let finish = v.finish();
        written.push(file);
        // The program's lines, to show with verify's findings: read back
        // from the sink before it is staged.
        let held = match (&finish.outcome, &finish.program) {
            (Outcome::Verified { report }, Some(p)) if !report.findings.is_empty() => p.written(super::verifying::HOLD),
            _ => None,
        };
        // A program for files is staged now (committed below, or dropped);
        // standard output waits for the verdict.
        report.output = match (finish.program, args.output.is_some()) {
            (Some(p), true) => p.finish(tape).map_err(|e| cannot_write(&mut sources, e))?,
            (p, _) => {
                held_stdout = p;
                Finished::Streamed
            }
        };
        verdict = Some((finish.outcome, held, finish.bytes, finish.part_lines, file));
    }
    let trace = match recorder {
        Some(recorder) => {
            let outputs = match &report.output {
                Finished::Files(files) => files.clone(),
                _ => vec![PathBuf::from("-")],
            };
            Some(recorder.finish(&sources, &post, &outputs, &batch).map_err(|d| fail(&mut sources, d))?)
        }
        None => None,
    };
    if let Some((outcome, held, bytes, part_lines, file)) = verdict {
        let outputs = match &report.output {
            Finished::Files(files) => files.iter().map(|f| f.display().to_string()).collect(),
            _ => vec!["-".to_string()],
        };
        let checked = Checked {
            name: &name,
            file,
            to_stdout: args.output.is_none(),
            bytes,
            summary: args.verify,
            trace: trace.as_deref().map(|t| (t, outputs.as_slice(), part_lines.as_slice())),
        };
        unverified.extend(checked.judge(outcome, held, &rules, &mut sources)?);
    }
    for why in unverified {
        let mut note = vec![postc_verify::unverified(&name, &why)];
        rules.apply(&mut note);
        report::eprint(&mut sources, &note);
        if postc_ir::diagnostic::has_errors(&note) {
            eprintln!("postc: the program could not be verified and VF044 is denied; the program was not written");
            return Err(Failed);
        }
    }
    if let Some(p) = held_stdout {
        p.finish(tape).map_err(|e| cannot_write(&mut sources, e))?;
    }
    batch.commit_except(&inputs, Some(&sources), &written).map_err(|d| fail(&mut sources, d))?;
    if let Finished::Files(files) = &report.output {
        let names = files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>().join(", ");
        let parts = if files.len() > 1 { format!("{} parts: ", files.len()) } else { String::new() };
        report::wrote(format_args!(
            "{parts}{names} ({} blocks, {} bytes, from {} toolpath events in {:.2} s)",
            report.blocks,
            report.bytes,
            report.events,
            started.elapsed().as_secs_f64()
        ));
    }
    Ok(())
}

/// Why `post` cannot verify what the post writes, known before it runs
/// (docs/verify.md, "While posting"): a family other than G-code by the
/// post's or the output's extension, a lathe
/// post, a rotary-wrapped post.
fn not_verified(args: &Args, post: &postc_ir::Post) -> Option<String> {
    let foreign = |ext: &str| FOREIGN_EXTENSIONS.iter().find(|(e, _)| e.eq_ignore_ascii_case(ext)).map(|(_, f)| *f);
    let output_ext = args.output.as_deref().and_then(Path::extension).map(|e| e.to_string_lossy().into_owned());
    if let Some(family) = foreign(&post.info.file_extension) {
        return Some(format!(
            "the post writes `.{}` files, {family}, which verify does not read",
            post.info.file_extension
        ));
    }
    if let Some((ext, family)) = output_ext.as_deref().and_then(|e| Some((e, foreign(e)?))) {
        return Some(format!("its extension `.{ext}` is that of {family}, which verify does not read"));
    }
    if post.options.lathe {
        return Some(format!("`{}` is a lathe post; verify compares milling programs only", post.info.name));
    }
    if post.options.rotary_wrap.is_some() {
        return Some(format!(
            "`{}` wraps an axis onto a rotary axis; verify does not compare rotary-wrapped programs",
            post.info.name
        ));
    }
    None
}

/// A program verified while it was posted, to be judged.
struct Checked<'a> {
    name: &'a str,
    file: postc_ir::FileId,
    to_stdout: bool,
    bytes: u64,
    /// `--verify` was given: print verify's summary line.
    summary: bool,
    /// The trace of the run (`--trace`), staged, with the names of the
    /// program's parts as it gives them and the lines before each part
    /// after the first: findings then name the post line too.
    trace: Option<(&'a Path, &'a [String], &'a [u64])>,
}

impl Checked<'_> {
    /// Prints the findings, with the severities the rules give them; fails
    /// when an error remains (the program is then not written). Returns
    /// why the program was not verified, when verify could not read it.
    fn judge(
        &self,
        outcome: Outcome,
        held: Option<Vec<u8>>,
        rules: &LevelRules,
        sources: &mut SourceMap,
    ) -> Result<Option<String>, Failed> {
        let report = match outcome {
            Outcome::Foreign(family) => {
                return Ok(Some(format!("its first lines are {family}, which verify does not read")));
            }
            Outcome::Stalled { bytes, events } => {
                let mut stalled = vec![Diagnostic::error(
                    codes::VF011,
                    format!(
                        "the post wrote nothing for {events} toolpath events in a row after the program's first {bytes} bytes: the program does not make those moves"
                    ),
                )
                .help("check the post's move sections: verification stopped here")];
                self.apply(rules, &mut stalled, None);
                return self.verdict(&stalled, sources);
            }
            Outcome::Verified { report } => report,
        };
        if let Some(why) = postc_verify::not_gcode(&report) {
            return Ok(Some(why));
        }
        if let Some(bytes) = &held
            && !report.findings.is_empty()
        {
            sources.hold(self.file, String::from_utf8_lossy(bytes).into_owned());
        }
        let mut report = report;
        let mut findings = std::mem::take(&mut report.findings);
        let lines: Vec<u64> = match held {
            // The line of each finding's primary label, as `postc verify` gives it.
            Some(_) => findings
                .iter()
                .zip(&report.lines)
                .map(|(d, (line, _))| {
                    d.primary_span()
                        .filter(|s| s.file == self.file)
                        .and_then(|s| sources.line_column(s.file, s.start))
                        .map_or(*line, |(l, _)| l as u64)
                })
                .collect(),
            None => {
                for (d, &(line, line_start)) in findings.iter_mut().zip(&report.lines) {
                    self.locate(d, line, line_start);
                }
                report.lines.iter().map(|(line, _)| *line).collect()
            }
        };
        if let Some((trace, outputs, part_lines)) = self.trace {
            let wanted = lines.iter().enumerate().map(|(i, l)| (*l, i)).collect();
            let line_of = |r: &super::trace::Record| {
                let part = outputs.iter().position(|o| *o == r.output)?;
                Some(part.checked_sub(1).map_or(0, |p| part_lines.get(p).copied().unwrap_or(0)) + r.line)
            };
            super::trace::annotate_lines(trace, wanted, &line_of, &mut findings, sources)
                .map_err(|d| super::fail(sources, d))?;
        }
        self.apply(rules, &mut findings, Some(&report));
        self.verdict(&findings, sources)
    }

    /// Gives each finding the severity the rules set for its code
    /// (verification findings' errors included) and drops the allowed
    /// ones; prints verify's summary line for `--verify`.
    fn apply(&self, rules: &LevelRules, findings: &mut Vec<Diagnostic>, report: Option<&postc_verify::Report>) {
        findings.retain_mut(|d| {
            match rules.level(d.code) {
                Some(Level::Allow) => return false,
                Some(Level::Warn) => d.severity = Severity::Warning,
                Some(Level::Deny) => d.severity = Severity::Error,
                None => {}
            }
            true
        });
        if let Some(report) = report
            && self.summary
        {
            let s = report.stats;
            eprintln!(
                "postc verify: `{}`: {} error(s), {} warning(s); {} lines, {} moves replayed, {} of {} toolpath moves made",
                self.name, report.errors, report.warnings, s.lines, s.motions, s.matched, s.expected
            );
        }
    }

    /// Prints the findings; fails when an error remains.
    fn verdict(&self, findings: &[Diagnostic], sources: &mut SourceMap) -> Result<Option<String>, Failed> {
        report::eprint(sources, findings);
        let mut denied: Vec<&str> = findings.iter().filter(|d| d.is_error()).map(|d| d.code).collect();
        if denied.is_empty() {
            return Ok(None);
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
            denied.iter().map(|c| format!("`--warn {c}`")).collect::<Vec<_>>().join(" ")
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
