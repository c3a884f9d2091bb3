//! Command-line interface: the commands, arguments and exit statuses of the product's contract.
//!
//! ```text
//! postc post    POST TOOLPATH [-o OUT] [--set NAME=VALUE]...   # stdout if no -o
//! postc post    TOOLPATH                                      # embedded default post
//! postc post    --post NAME TOOLPATH                          # a post of the library, by its name
//! postc posts   [DIR...] [--format human|json]                # the post library: embedded and user posts
//! postc check   FILE... [--format human|json] [--product P]     # posts (lints too) and toolpaths; exit 1 on any error
//! postc explain CODE                                          # one diagnostic code's documentation
//! postc check|post ... [--warn|--deny|--allow CODE|PREFIX|all]  # severity per code; also postc.toml
//! postc convert POST --to vectric|vcpost|cimco|fusion|ron [-o OUT] [--postc-extension]  # a post as another dialect's
//! postc inspect POST                                          # the IR, as RON
//! postc bench   POST [TOOLPATH] [--moves N]                   # throughput
//! postc toolpath gen --pattern NAME --moves N [-o OUT]        # synthetic toolpaths
//! postc probe-table POST                                      # empty probe-cycle table of a VcPost post
//! postc postp   DIR [--options FILE]                          # APT compatibility: DIR/cl.tap, MACHIN picks the controller
//! postc lsp                                                   # language server on stdio (docs/editors.md)
//! postc serve   [POST] [TOOLPATH] [--port N] [--bind ADDR]      # the post workbench in a browser (docs/workbench.md)
//! postc verify  PROGRAM --toolpath TOOLPATH [--post POST] [--controller C] [--tolerance MM] [--format human|json]
//! postc plot    PROGRAM --toolpath TOOLPATH -o plot.svg|plot.png [--post POST] [--controller C] [--tolerance MM]
//! postc explain TRACE.jsonl LINE [--output NC]                # why an NC line exists (`post --trace`)
//! postc completions bash|zsh|fish|elvish|powershell            # shell completions on stdout
//! postc man     DIR                                           # man pages of every subcommand
//! ```
//!
//! Exit status: 0 on success, 1 when an input has errors (after printing
//! every diagnostic), 2 for a bad command line.

mod bench;
mod check;
pub mod clock;
mod convert;
mod explain;
mod inspect;
mod levels;
mod lsp;
mod manual;
pub mod outputs;
mod plot;
mod post;
mod postp;
pub mod posts;
mod probe;
mod profile;
pub mod report;
mod serve;
pub mod sink;
mod stored;
mod toolpath;
mod trace;
pub(crate) mod verify;
mod verifying;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use postc_ir::codes::LevelRules;
use postc_ir::{Diagnostic, Dialect, Post, SourceMap};

/// postc: posts CNC toolpaths through Vectric, CIMCO, VcPost and Fusion post processors.
#[derive(Parser, Debug)]
#[command(name = "postc", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Diagnostics shown per file, for people (0: all); `--format json` lists every one.
    #[arg(long, global = true, value_name = "N", default_value_t = report::DEFAULT_MAX_DIAGNOSTICS)]
    max_diagnostics: usize,
    /// No summary line after writing files (`postc: wrote ...`) and no progress bars; diagnostics still print.
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    quiet: bool,
    /// Also say what each step did (the post compiled, the toolpath read, the program verified) and how long it took.
    #[arg(short, long, global = true)]
    verbose: bool,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Post a toolpath: POST TOOLPATH, TOOLPATH alone with the embedded G-code post, or --post NAME TOOLPATH with a post of the library (`postc posts`).
    ///
    /// The G-code it writes is verified while it is posted, on a second thread, as `postc verify PROGRAM --toolpath TOOLPATH --post POST` would (generic controller, 0.01 mm): every move replayed and compared with the toolpath, feeds, spindle, units, arcs, block numbers. Findings are VF diagnostics: a warning is printed and the program written; an error means no program is written and the exit status is 1. Their severities change as any code's (`--warn VF033`, `--deny VF`, `--allow VF035`, `postc.toml`); `--no-verify` skips verification.
    ///
    /// Not verified, with a VF044 note saying why: programs of families verify does not read (HPGL, ShopBot, Heidenhain conversational: by the post's or the output's extension or the program's first lines), programs from a call of a block or subroutine on (Sinumerik `CALL BLOCK`, LinuxCNC `o<name> call`), binary or non-G-code text output, lathe and rotary-wrapped posts, VcPost probe tables and composites event files. `--deny VF044` refuses to write a program that cannot be verified.
    Post(post::Args),
    /// List the post library: the embedded posts and the posts of the user's folders (DIR..., `[posts] dirs` in postc.toml, POSTC_POSTS), with name, dialect, units, extension and path.
    ///
    /// `postc post --post NAME TOOLPATH` selects a post of this list by its name (case and blanks do not matter; the trailing `(*.ext)` of a Vectric name may be left out). docs/posts.md describes the library.
    Posts(posts::Args),
    /// Convert a post to another dialect (Vectric .pp, VcPost, CIMCO, Fusion .cps, or the IR as RON); refused with reasons when the target cannot hold it.
    Convert(convert::Args),
    /// Check posts and toolpaths; exit 1 if any has an error.
    Check(check::Args),
    /// Print the documentation of a diagnostic code (PP027): what it means, an example, the fix; or, given TRACE.jsonl LINE, why line LINE of a posted program exists (from `postc post --trace`).
    Explain(explain::Args),
    /// Print a post's IR as RON.
    Inspect(inspect::Args),
    /// Measure posting throughput over a toolpath or a synthetic one.
    Bench(bench::Args),
    /// Print an empty probe-cycle table (CSV) for a VcPost post, from its keyword comments.
    ProbeTable(probe::Args),
    /// Post DIR/cl.tap for the controller its MACHIN names (a reimplementation of `postp`, the APT CL post processor for ACORN, FANUC, HAAS and TORMACH controllers).
    Postp(postp::Args),
    /// Replay a G-code program and compare its motion with the toolpath it was posted from; exit 1 when anything is out of tolerance.
    Verify(verify::Args),
    /// Run the language server (LSP on stdio) for editors: diagnostics, hover, definition, completion, quick fixes.
    Lsp(lsp::Args),
    /// Start the post workbench, a web page served on 127.0.0.1 (docs/workbench.md): edit a post with its diagnostics, see the program it writes over a toolpath, the trace of each NC line, verify's findings and the backplot; convert and save.
    ///
    /// Prints the URL to open on standard output and serves until interrupted. It reads only files in the folders of POST and TOOLPATH and in the corpus folder, and saves only in the folders of POST and TOOLPATH; requests from other origins are refused.
    Serve(serve::Args),
    /// Draw a program over its toolpath, top (XY) and front (XZ), with verify's findings marked: SVG, or PNG.
    Plot(plot::Args),
    /// Toolpath utilities.
    Toolpath {
        #[command(subcommand)]
        command: toolpath::Command,
    },
    /// Print the shell completion script for bash, zsh, fish, elvish or powershell.
    Completions(manual::CompletionsArgs),
    /// Write the man pages of postc and of each subcommand into a folder.
    Man(manual::ManArgs),
}

/// Post dialects as `--dialect` names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum DialectArg {
    /// A Vectric .pp post.
    Vectric,
    /// A CIMCO CNC-Calc JavaScript post (.js).
    Cimco,
    /// A Vericut VcPost post (.VcPost).
    Vcpost,
    /// A post's IR as RON (`postc convert --to ron`).
    Ron,
    /// An Autodesk Fusion / HSM post (.cps).
    Fusion,
}

impl From<DialectArg> for Dialect {
    fn from(d: DialectArg) -> Dialect {
        match d {
            DialectArg::Vectric => Dialect::Vectric,
            DialectArg::Cimco => Dialect::Cimco,
            DialectArg::Vcpost => Dialect::VcPost,
            DialectArg::Ron => Dialect::Ron,
            DialectArg::Fusion => Dialect::Fusion,
        }
    }
}

/// Runs the command line.
pub fn main() -> ExitCode {
    if postp::invoked_as_postp() {
        return postp::main();
    }
    let cli = Cli::parse();
    report::set_max_diagnostics(cli.max_diagnostics);
    report::set_verbosity(match (cli.quiet, cli.verbose) {
        (true, _) => report::Verbosity::Quiet,
        (false, true) => report::Verbosity::Verbose,
        (false, false) => report::Verbosity::Normal,
    });
    let result = match cli.command {
        Command::Post(args) => post::run(args),
        Command::Check(args) => check::run(args),
        Command::Explain(args) => explain::run(args),
        Command::Posts(args) => posts::run(args),
        Command::Convert(args) => convert::run(args),
        Command::Inspect(args) => inspect::run(args),
        Command::Bench(args) => bench::run(args),
        Command::ProbeTable(args) => probe::run(args),
        Command::Postp(args) => postp::run(args),
        Command::Verify(args) => verify::run(args),
        Command::Lsp(args) => lsp::run(args),
        Command::Plot(args) => plot::run(args),
        Command::Serve(args) => serve::run(args),
        Command::Toolpath { command } => toolpath::run(command),
        Command::Completions(args) => manual::completions(args),
        Command::Man(args) => manual::man(args),
    };
    report::summarize_held_back();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failed) => ExitCode::from(1),
    }
}

/// A command failed; its diagnostics have been printed.
#[derive(Debug)]
pub struct Failed;

/// Compiles a post (or the embedded default), printing its diagnostics;
/// fails when it has errors.
pub(crate) fn load_post(
    path: Option<&PathBuf>,
    dialect: Option<DialectArg>,
    sources: &mut SourceMap,
) -> Result<Post, Failed> {
    load_post_with(path, dialect, sources, &LevelRules::default())
}

/// [`load_post`] with severity rules (`--deny`, `--allow`, `postc.toml`)
/// applied to the post's diagnostics.
pub(crate) fn load_post_with(
    path: Option<&PathBuf>,
    dialect: Option<DialectArg>,
    sources: &mut SourceMap,
    rules: &LevelRules,
) -> Result<Post, Failed> {
    match path {
        Some(p) => {
            let started = std::time::Instant::now();
            let compiled = postc_driver::compile_post(p, dialect.map(Into::into), sources);
            loaded(compiled, &p.display().to_string(), sources, rules, started)
        }
        None => load_embedded(crate::library::DEFAULT, sources, rules),
    }
}

/// Compiles an embedded post (docs/posts.md), as [`load_post_with`] does a
/// file; its extension gives its dialect.
pub(crate) fn load_embedded(
    post: crate::library::Embedded,
    sources: &mut SourceMap,
    rules: &LevelRules,
) -> Result<Post, Failed> {
    let started = std::time::Instant::now();
    let path = std::path::Path::new(post.name);
    let compiled = postc_driver::compile_post_bytes(path, post.text, None, sources);
    loaded(compiled, post.name, sources, rules, started)
}

/// A compiled post's diagnostics printed; the post, unless it has errors
/// (under `-v`, what was compiled and how long it took since `started`).
fn loaded(
    mut compiled: postc_driver::Compiled,
    name: &str,
    sources: &mut SourceMap,
    rules: &LevelRules,
    started: std::time::Instant,
) -> Result<Post, Failed> {
    rules.apply(&mut compiled.diagnostics);
    report::eprint(sources, &compiled.diagnostics);
    match compiled.post {
        Some(post) if !compiled.has_errors() => {
            report::step(
                started,
                format_args!(
                    "compiled `{name}` ({:?} post `{}`: {} functions, {} handlers, {} variables)",
                    post.info.dialect,
                    post.info.name,
                    post.functions.len(),
                    post.handlers.len(),
                    post.variables.len()
                ),
            );
            Ok(post)
        }
        _ => {
            eprintln!("postc: `{name}` has errors; nothing was posted");
            Err(Failed)
        }
    }
}

/// Why a file named on the command line cannot be read: it does not
/// exist, it is a link to a file that does not, a loop of links, or the
/// system refuses it.
pub(crate) fn missing(path: &std::path::Path) -> String {
    let shown = path.display();
    match (std::fs::symlink_metadata(path), std::fs::metadata(path)) {
        (Ok(m), Err(e)) if m.file_type().is_symlink() => {
            if links_loop(path) {
                format!("`{shown}` is a loop of symbolic links: following them never reaches a file")
            } else if e.kind() == std::io::ErrorKind::NotFound {
                match std::fs::read_link(path) {
                    Ok(target) => {
                        format!("`{shown}` is a symbolic link to `{}`, which does not exist", target.display())
                    }
                    Err(_) => format!("`{shown}` is a symbolic link to a file that does not exist"),
                }
            } else {
                format!("`{shown}` is a symbolic link that cannot be followed: {e}")
            }
        }
        (_, Err(e)) if e.kind() != std::io::ErrorKind::NotFound => format!("cannot open `{shown}`: {e}"),
        _ => format!("`{shown}` does not exist"),
    }
}

/// Whether following the symbolic links from `path` comes back to a link
/// already passed (or goes on for more than 40 links, where systems stop).
fn links_loop(path: &std::path::Path) -> bool {
    let mut seen: Vec<PathBuf> = Vec::new();
    let mut at = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    for _ in 0..40 {
        if seen.contains(&at) {
            return true;
        }
        let Ok(target) = std::fs::read_link(&at) else { return false };
        seen.push(at.clone());
        at = match at.parent() {
            Some(dir) => dir.join(target),
            None => target,
        };
    }
    true
}

/// Prints one diagnostic that has no source (a bad argument, an I/O error).
pub(crate) fn fail(sources: &mut SourceMap, d: Diagnostic) -> Failed {
    report::eprint(sources, &[d]);
    Failed
}
