//! `postc bench`: posting throughput of a post over a toolpath file or a
//! synthetic toolpath, with a progress bar, into a sink that counts bytes.

use postc_ir::codes;
use std::path::PathBuf;
use std::time::Instant;

use postc_ir::{Diagnostic, EventSource, SourceMap};
use postc_runtime::{Output, RunOptions};

use super::{DialectArg, Failed, fail, load_post, report};
use postc_reader_synthetic::Synthetic;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The post to measure.
    post: PathBuf,
    /// A toolpath to post; a synthetic one when absent.
    toolpath: Option<PathBuf>,
    /// Moves of the synthetic toolpath (at most 10000000000).
    #[arg(long, default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(0..=super::toolpath::MAX_MOVES))]
    moves: u64,
    /// Pattern of the synthetic toolpath.
    #[arg(long, default_value = "zigzag", value_parser = super::toolpath::patterns())]
    pattern: String,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    /// Also print where the time goes, per handler and post function: calls, share of the run, native or script (slower: the clock is read at every call).
    #[arg(long)]
    profile: bool,
}

/// Throughput of one run.
pub struct Measured {
    pub events: u64,
    pub bytes: u64,
    pub seconds: f64,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let post = load_post(Some(&args.post), args.dialect, &mut sources)?;
    let (mut source, total): (Box<dyn EventSource>, Option<u64>) = match &args.toolpath {
        Some(path) => (postc_driver::open_toolpath(path, &mut sources).map_err(|d| fail(&mut sources, d))?, None),
        None => match Synthetic::new(&args.pattern, args.moves) {
            Some(s) => (Box::new(s), Some(args.moves)),
            None => {
                return Err(fail(
                    &mut sources,
                    Diagnostic::error(codes::IO007, format!("there is no toolpath pattern `{}`", args.pattern))
                        .help(format!("patterns: {}", super::toolpath::pattern_names())),
                ));
            }
        },
    };
    let mut options =
        postc_runtime::RunOptions { script_host: postc_driver::script_host(&post), ..super::clock::run_options() };
    let profiler = args.profile.then(super::profile::Profiler::default);
    if let Some(p) = &profiler {
        options.profile = Some(Box::new(p.clone()));
    }
    let bar = match total {
        Some(n) => report::progress(n, report::Unit::Events, "posting"),
        None => report::spinner("posting"),
    };
    if let Some(bar) = &bar {
        let shown = bar.clone();
        options.progress = Some(match total {
            Some(_) => Box::new(move |events| shown.set_position(events)),
            None => Box::new(move |events| shown.set_message(format!("posted {events} events"))),
        });
    }
    let measured = measure(&post, &mut source, options, &mut sources);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let measured = measured?;
    print_measured(&args, &measured);
    if let Some(p) = &profiler {
        report::out(&p.report(&post, std::time::Duration::from_secs_f64(measured.seconds)));
    }
    Ok(())
}

fn measure(
    post: &postc_ir::Post,
    source: &mut Box<dyn EventSource>,
    options: RunOptions,
    sources: &mut SourceMap,
) -> Result<Measured, Failed> {
    let start = Instant::now();
    match postc_runtime::run(post, source, Output::discard(), options) {
        Ok(r) => Ok(Measured { events: r.events, bytes: r.bytes, seconds: start.elapsed().as_secs_f64() }),
        Err(diagnostics) => {
            report::eprint(sources, &diagnostics);
            Err(Failed)
        }
    }
}

fn print_measured(args: &Args, m: &Measured) {
    let what = match &args.toolpath {
        Some(p) => p.display().to_string(),
        None => format!("synthetic {} toolpath of {} moves", args.pattern, args.moves),
    };
    report::out(&format!("post:       {}\n", args.post.display()));
    report::out(&format!("toolpath:   {what}\n"));
    report::out(&format!("events:     {}\n", m.events));
    report::out(&format!("output:     {:.1} MB\n", m.bytes as f64 / 1e6));
    report::out(&format!("time:       {:.3} s\n", m.seconds));
    report::out(&format!(
        "throughput: {:.0} moves/s ({:.1} MB/s of output)\n",
        m.events as f64 / m.seconds,
        m.bytes as f64 / 1e6 / m.seconds
    ));
}
