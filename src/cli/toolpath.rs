//! `postc toolpath gen`: writes a synthetic toolpath as native events.

use postc_ir::codes;
use std::io::Write;
use std::path::PathBuf;

use postc_frontends::native::{Syntax, write_event};
use postc_ir::{Diagnostic, EventSource};

use super::{Failed, fail};
use postc_frontends::synthetic::{PATTERNS, Synthetic};

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Generate a synthetic toolpath (zigzag, arcs, mixed, standard).
    Gen {
        /// The pattern: zigzag, arcs, mixed or standard.
        #[arg(long, default_value = "zigzag")]
        pattern: String,
        /// Number of moves.
        #[arg(long, default_value_t = 1000)]
        moves: u64,
        /// Write here (.ron or .jsonl) instead of standard output (RON).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
}

pub fn run(command: Command) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let Command::Gen { pattern, moves, output } = command;
    let Some(mut generator) = Synthetic::new(&pattern, moves) else {
        return Err(fail(
            &mut sources,
            Diagnostic::error(codes::IO007, format!("there is no toolpath pattern `{pattern}`"))
                .help(format!("patterns: {}", PATTERNS.join(", "))),
        ));
    };
    let syntax = match output.as_ref().and_then(|p| p.extension()).and_then(|e| e.to_str()) {
        Some("jsonl" | "json") => Syntax::JsonLines,
        _ => Syntax::Ron,
    };
    let write = |w: &mut dyn Write, generator: &mut Synthetic| -> std::io::Result<()> {
        let mut line = String::new();
        let mut diags = Vec::new();
        while let Some((event, _)) = generator.next_event(&mut diags) {
            line.clear();
            write_event(&event, syntax, &mut line);
            w.write_all(line.as_bytes())?;
        }
        w.flush()
    };
    let result = match &output {
        Some(path) => {
            let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(std::path::Path::new("."));
            tempfile::NamedTempFile::new_in(dir).and_then(|tmp| {
                let mut w = std::io::BufWriter::new(tmp);
                write(&mut w, &mut generator)?;
                w.into_inner().map_err(|e| e.into_error())?.persist(path).map_err(|e| e.error)?;
                Ok(())
            })
        }
        None => write(&mut std::io::BufWriter::new(std::io::stdout().lock()), &mut generator),
    };
    result.map_err(|e| fail(&mut sources, Diagnostic::error(codes::IO003, format!("cannot write the toolpath: {e}"))))
}
