//! `postc toolpath gen`: writes a synthetic toolpath as native events.

use postc_ir::codes;
use std::io::Write;
use std::path::{Path, PathBuf};

use postc_ir::{Diagnostic, EventSource};
use postc_reader_native::{Syntax, write_event};

use super::outputs::{Batch, Temp};
use super::{Failed, fail};
use postc_reader_synthetic::{PATTERNS, Synthetic};

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Generate a synthetic toolpath (zigzag, arcs, mixed, standard).
    Gen {
        /// The pattern.
        #[arg(long, default_value = "zigzag", value_parser = patterns())]
        pattern: String,
        /// Number of moves (at most 10000000000: about a terabyte of RON).
        #[arg(long, default_value_t = 1000, value_parser = clap::value_parser!(u64).range(0..=MAX_MOVES))]
        moves: u64,
        /// Write here (.ron or .jsonl) instead of standard output (RON).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
}

/// The patterns `--pattern` takes, each with its help line.
pub(super) fn patterns() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(
        PATTERNS.iter().map(|(name, help)| clap::builder::PossibleValue::new(*name).help(*help)),
    )
}

/// The pattern names, for a message.
pub(super) fn pattern_names() -> String {
    PATTERNS.iter().map(|(name, _)| *name).collect::<Vec<_>>().join(", ")
}

/// The most moves `toolpath gen` and `bench` make: 10^10 moves are about
/// a terabyte of RON, and a day of generating.
pub const MAX_MOVES: u64 = 10_000_000_000;

/// The bytes a synthetic toolpath of `moves` moves takes, from the bytes
/// of its first moves (at most 2000).
fn estimated_bytes(pattern: &str, moves: u64, syntax: Syntax) -> u64 {
    let sample = moves.min(2000);
    let Some(mut generator) = Synthetic::new(pattern, sample) else { return 0 };
    let mut line = String::new();
    let mut bytes = 0u64;
    let mut diags = Vec::new();
    while let Some((event, _)) = generator.next_event(&mut diags) {
        line.clear();
        write_event(&event, syntax, &mut line);
        bytes += line.len() as u64;
    }
    bytes.saturating_mul(moves).checked_div(sample).unwrap_or(bytes)
}

/// Bytes free for this user on the file system of `dir`.
#[cfg(unix)]
fn free_bytes(dir: &Path) -> Option<u64> {
    let s = rustix::fs::statvfs(dir).ok()?;
    Some(s.f_bavail.saturating_mul(s.f_frsize))
}

#[cfg(not(unix))]
fn free_bytes(_dir: &Path) -> Option<u64> {
    None
}

pub fn run(command: Command) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let started = std::time::Instant::now();
    let Command::Gen { pattern, moves, output } = command;
    let Some(mut generator) = Synthetic::new(&pattern, moves) else {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO007, format!("there is no toolpath pattern `{pattern}`"))
                .help(format!("patterns: {}", super::toolpath::pattern_names())),
        ));
    };
    let syntax = match output.as_ref().and_then(|p| p.extension()).and_then(|e| e.to_str()) {
        Some("jsonl" | "json") => Syntax::JsonLines,
        _ => Syntax::Ron,
    };
    let write = |w: &mut dyn Write, generator: &mut Synthetic| -> std::io::Result<()> {
        let bar = super::report::progress(moves, super::report::Unit::Moves, "generating");
        let mut line = String::new();
        let mut diags = Vec::new();
        let mut events = 0u64;
        while let Some((event, _)) = generator.next_event(&mut diags) {
            line.clear();
            write_event(&event, syntax, &mut line);
            w.write_all(line.as_bytes())?;
            events += 1;
            if events.is_multiple_of(65_536)
                && let Some(bar) = &bar
            {
                bar.set_position(generator.moves_made());
            }
        }
        if let Some(bar) = bar {
            bar.finish_and_clear();
        }
        w.flush()
    };
    let result = match &output {
        Some(path) => {
            super::outputs::check_paths(&[], &[path]).map_err(|d| fail(&mut sources, d))?;
            let dir = match path.parent() {
                Some(p) if !p.as_os_str().is_empty() => p,
                _ => Path::new("."),
            };
            let needed = estimated_bytes(&pattern, moves, syntax);
            if let Some(free) = free_bytes(dir)
                && needed > free
            {
                return Err(fail(
                    &mut sources,
                    Diagnostic::error(
                        codes::IO003,
                        format!(
                            "{moves} {pattern} moves take about {:.1} GB, and `{}` has {:.1} GB free; nothing was written",
                            needed as f64 / 1e9,
                            dir.display(),
                            free as f64 / 1e9
                        ),
                    )
                    .help("ask for fewer moves, or write to a disk with room"),
                ));
            }
            let batch = Batch::default();
            Temp::beside(path)
                .and_then(|temp| {
                    let mut w = std::io::BufWriter::new(temp.file()?);
                    write(&mut w, &mut generator)?;
                    drop(w);
                    batch.stage(temp, path.clone());
                    Ok(())
                })
                .map_err(|e| fail(&mut sources, super::outputs::cannot_write(path, &e)))?;
            batch.commit(&[], None).map_err(|d| fail(&mut sources, d))?;
            let bytes = std::fs::metadata(path).map_or(0, |m| m.len());
            super::report::wrote(format_args!(
                "{} ({moves} {pattern} moves, {bytes} bytes, in {:.2} s)",
                path.display(),
                started.elapsed().as_secs_f64()
            ));
            return Ok(());
        }
        None => write(&mut std::io::BufWriter::new(std::io::stdout().lock()), &mut generator),
    };
    result.map_err(|e| fail(&mut sources, Diagnostic::error(codes::IO003, format!("cannot write the toolpath: {e}"))))
}
