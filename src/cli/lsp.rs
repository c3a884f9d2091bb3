//! `postc lsp`: the language server on stdio (`docs/editors.md`).

use super::Failed;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Accepted for editors that pass it (VS Code clients do); stdio is the only transport.
    #[arg(long)]
    stdio: bool,
}

pub fn run(_args: Args) -> Result<(), Failed> {
    postc_lsp::run_stdio(std::sync::Arc::new(postc_report::FsLoader)).map_err(|e| {
        eprintln!("postc lsp: {e}");
        Failed
    })
}
