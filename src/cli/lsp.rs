//! `postc lsp`: the language server on stdio (`docs/editors.md`).

use super::Failed;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Accepted for editors that pass it (VS Code clients do); stdio is the only transport.
    #[arg(long)]
    stdio: bool,
}

pub fn run(_args: Args) -> Result<(), Failed> {
    serve_stdio().map_err(|e| {
        eprintln!("postc lsp: {e}");
        Failed
    })
}

/// The server on stdin/stdout until the client says `exit`, reading the
/// files documents name from disk.
fn serve_stdio() -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
    let (connection, io_threads) = lsp_server::Connection::stdio();
    postc_lsp::serve(&connection, std::sync::Arc::new(postc_report::FsLoader))?;
    drop(connection);
    io_threads.join()?;
    Ok(())
}
