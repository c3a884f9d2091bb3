//! `postc post`: posts a toolpath through a post, to a file (written whole
//! or not at all) or to standard output. A VcPost probe table (`.csv`) or
//! composites event file goes to `probe.rs` instead.

use postc_ir::codes;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use postc_ir::Diagnostic;
use postc_ir::event::FileInfo;
use postc_runtime::{Finished, RunOptions};

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
    /// After posting to OUT, replay what was written and compare it with the toolpath (`postc verify`); needs -o.
    #[arg(long)]
    verify: bool,
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
    if args.verify && args.output.is_none() {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO007, "`--verify` checks the file that was written: give it with `-o OUT`"),
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
    let out = match &args.output {
        Some(path) => {
            super::sink::file(path, &batch).map_err(|e| fail(&mut sources, super::outputs::cannot_write(path, &e)))?
        }
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
            super::sink::stdout()
        }
    };
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
    match postc_runtime::run(&post, &mut source, out, options) {
        Ok(mut report) => {
            rules.apply(&mut report.warnings);
            report::eprint(&mut sources, &report.warnings);
            if postc_ir::diagnostic::has_errors(&report.warnings) {
                match &report.output {
                    Finished::Files(_) => {
                        eprintln!("postc: a denied warning was reported while posting; nothing was written")
                    }
                    _ => eprintln!("postc: a denied warning was reported while posting"),
                }
                return Err(Failed);
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
            match (&report.output, args.verify) {
                (Finished::Files(files), true) if files.len() == 1 => {
                    let job = super::verify::Job {
                        program: &files[0],
                        toolpath,
                        post: Some(&post),
                        controller: postc_verify::Controller::Generic,
                        tolerance: 0.01,
                        format: report::Format::Human,
                        postp: None,
                        trace: args.trace.as_deref(),
                    };
                    super::verify::verify(&job, &mut sources)
                }
                (Finished::Files(_), true) => {
                    let mut warning = vec![Diagnostic::warning(
                        codes::VF009,
                        "the post split its output into parts; `--verify` reads one program, so the parts were not verified",
                    )];
                    rules.apply(&mut warning);
                    report::eprint(&mut sources, &warning);
                    if postc_ir::diagnostic::has_errors(&warning) { Err(Failed) } else { Ok(()) }
                }
                _ => Ok(()),
            }
        }
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postc: posting failed; no output was written");
            Err(Failed)
        }
    }
}
