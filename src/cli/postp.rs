//! `postc postp DIR [--options FILE]`: the APT CL post processor `postp` (a Windows console program, `postp DIR > out`), reimplemented.
//! Reads `DIR/cl.tap` and writes the program for the controller its
//! `MACHIN` names to standard output (whole, or nothing on an error).
//!
//! Invoked under the name `postp` (a link or copy of the binary whose file
//! stem is `postp`), the binary takes the same arguments without the
//! subcommand: `postp DIR > out.nc`, as the seed's program does.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

use super::{Failed, report};
use postc_postp::Settings;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The folder holding cl.tap.
    #[arg(value_name = "DIR")]
    dir: PathBuf,
    /// An options file (RON) whose fields replace the controller's defaults.
    #[arg(long, value_name = "FILE")]
    options: Option<PathBuf>,
    /// Write the program here (whole, or not at all) instead of standard output.
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
}

/// `postp DIR`: the seed's command line.
#[derive(Parser, Debug)]
#[command(name = "postp", version, about = "APT post processor: posts DIR/cl.tap for the controller its MACHIN names")]
struct Standalone {
    #[command(flatten)]
    args: Args,
}

/// Whether the program was invoked as `postp`.
pub fn invoked_as_postp() -> bool {
    std::env::args_os()
        .next()
        .map(PathBuf::from)
        .and_then(|p| p.file_stem().map(|s| s.to_string_lossy().eq_ignore_ascii_case("postp")))
        .unwrap_or(false)
}

/// The `postp` entry point.
pub fn main() -> ExitCode {
    match run(Standalone::parse().args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failed) => ExitCode::from(1),
    }
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let settings = Settings { options: args.options.clone(), now: Some(super::clock::now()), ..Settings::default() };
    let cl = args.dir.join("cl.tap");
    let started = std::time::Instant::now();
    let mut inputs: Vec<&std::path::Path> = vec![&cl];
    inputs.extend(args.options.as_deref());
    let batch = super::outputs::Batch::default();
    let out = match &args.output {
        Some(path) => {
            super::outputs::check_paths(&inputs, &[path]).map_err(|d| super::fail(&mut sources, d))?;
            super::sink::file(path, &batch)
                .map_err(|e| super::fail(&mut sources, super::outputs::cannot_write(path, &e)))?
        }
        None => super::sink::stdout(),
    };
    match postc_postp::post(&cl, &settings, out, &mut sources) {
        Ok(r) => {
            report::eprint(&mut sources, &r.warnings);
            batch.commit(&inputs, Some(&sources)).map_err(|d| super::fail(&mut sources, d))?;
            if let Some(path) = &args.output {
                report::wrote(format_args!(
                    "{} ({} blocks, {} bytes, in {:.2} s)",
                    path.display(),
                    r.blocks,
                    r.bytes,
                    started.elapsed().as_secs_f64()
                ));
            }
            Ok(())
        }
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postp: nothing was written");
            Err(Failed)
        }
    }
}
