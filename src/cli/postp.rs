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
    let settings = Settings { options: args.options, now: Some(super::clock::now()), ..Settings::default() };
    let cl = args.dir.join("cl.tap");
    match postc_postp::post(&cl, &settings, super::sink::stdout(), &mut sources) {
        Ok(r) => {
            report::eprint(&mut sources, &r.warnings);
            Ok(())
        }
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postp: nothing was written");
            Err(Failed)
        }
    }
}
