//! `postc check`: lints posts and validates toolpaths, printing every
//! diagnostic; exits 1 when any file has an error.

use postc_ir::codes;
use std::path::PathBuf;

use postc_ir::Diagnostic;

use super::report::{self, Format};
use super::{DialectArg, Failed};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Posts (.pp, .js, .cps, .VcPost, .ron) and toolpaths (.apt, .cl, .cls, .ron, .jsonl, ...).
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// Diagnostics for people, or one JSON array of {file, severity, code, message, line, column, end_line, end_column}.
    #[arg(long, value_enum, default_value = "human")]
    format: Format,
    /// The posts' dialect, when their extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    #[command(flatten)]
    levels: super::levels::Flags,
    /// The Vectric product the posts are for: warn about what its post processor does not support (the 2012 Vectric post guide's table).
    #[arg(long, value_enum)]
    product: Option<ProductArg>,
    /// Apply the fixes that are certain (a misspelt section name with one close match, a label's missing `]`), rewriting each post whole, then check it.
    #[arg(long)]
    fix: bool,
}

/// Vectric products as `--product` names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ProductArg {
    /// Cut2D: no rotary wrapping.
    Cut2d,
    /// VCarve: everything.
    Vcarve,
    /// Aspire: everything.
    Aspire,
    /// Cut3D: no DIRECT_OUTPUT, SUBSTITUTE, TAPE_SPLITTING, rotary wrapping, FIRST_PLUNGE_MOVE, and fewer variables.
    Cut3d,
    /// PhotoVCarve: as Cut3D, and no arcs or NEW_SEGMENT.
    Photovcarve,
}

impl From<ProductArg> for postc_lint::Product {
    fn from(p: ProductArg) -> postc_lint::Product {
        match p {
            ProductArg::Cut2d => postc_lint::Product::Cut2d,
            ProductArg::Vcarve => postc_lint::Product::Vcarve,
            ProductArg::Aspire => postc_lint::Product::Aspire,
            ProductArg::Cut3d => postc_lint::Product::Cut3d,
            ProductArg::Photovcarve => postc_lint::Product::PhotoVcarve,
        }
    }
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    args.levels.check(&mut sources)?;
    let mut all: Vec<(String, Diagnostic)> = Vec::new();
    for file in &args.files {
        let name = file.display().to_string();
        if args.fix && file.exists() && !postc_driver::is_toolpath(file, &postc_report::FsLoader) {
            match fix(file, args.dialect) {
                Ok(0) => {}
                Ok(n) => eprintln!("postc: fixed {n} problem(s) in `{name}`"),
                Err(d) => {
                    all.push((name, d));
                    continue;
                }
            }
        }
        let started = std::time::Instant::now();
        let big = std::fs::metadata(file).is_ok_and(|m| m.len() > (32 << 20));
        let spinner = big.then(|| report::spinner("checking")).flatten();
        let diagnostics = if !file.exists() {
            vec![Diagnostic::error(codes::IO001, super::missing(file))]
        } else if postc_driver::is_toolpath(file, &postc_report::FsLoader) {
            postc_driver::check_toolpath(file, &mut sources)
        } else {
            let options = postc_lint::Options { product: args.product.map(Into::into) };
            postc_lint::check_post(file, args.dialect.map(Into::into), &options, &mut sources)
        };
        if let Some(bar) = spinner {
            bar.finish_and_clear();
        }
        report::step(started, format_args!("checked `{name}`: {} diagnostic(s)", diagnostics.len()));
        let mut diagnostics = diagnostics;
        match args.levels.rules_for(Some(file)) {
            Ok(rules) => rules.apply(&mut diagnostics),
            Err(d) => diagnostics.push(d),
        }
        all.extend(diagnostics.into_iter().map(|d| (name.clone(), d)));
    }
    let errors = all.iter().filter(|(_, d)| d.is_error()).count();
    match args.format {
        Format::Json => report::out(&(report::json(&sources, &all) + "\n")),
        Format::Human => {
            let diagnostics: Vec<_> = all.iter().map(|(_, d)| d.clone()).collect();
            report::eprint(&mut sources, &diagnostics);
            report::summarize_held_back();
            let warnings = all.len() - errors;
            if errors > 0 || warnings > 0 {
                eprintln!("postc: {errors} error(s), {warnings} warning(s) in {} file(s)", args.files.len());
            } else {
                report::summary(format_args!("checked {} file(s): no problems", args.files.len()));
            }
        }
    }
    if errors > 0 { Err(Failed) } else { Ok(()) }
}

/// Applies the certain fixes to a post file, rewriting it whole (a
/// temporary file renamed over it) when there is any; the number applied.
/// The file is read and written back as it is stored (`super::stored`:
/// UTF-8 or a byte per character, a BOM, CR LF), so its other bytes do
/// not change.
fn fix(file: &std::path::Path, dialect: Option<DialectArg>) -> Result<usize, Diagnostic> {
    let io = |e: std::io::Error| Diagnostic::error(codes::IO003, format!("cannot fix `{}`: {e}", file.display()));
    let bytes = std::fs::read(file).map_err(io)?;
    let dialect = match dialect {
        Some(d) => d.into(),
        None => match postc_driver::post_dialect(file, &bytes) {
            Some(d) => d,
            None => return Ok(0),
        },
    };
    let (text, how) = super::stored::decode(&bytes);
    let fixes = postc_lsp::analysis::fixes(dialect, &text, 0, text.len());
    if fixes.is_empty() {
        return Ok(0);
    }
    let fixed = postc_lsp::analysis::apply(&text, &fixes);
    let out = super::stored::encode(&fixed, how)
        .map_err(|e| Diagnostic::error(codes::IO003, format!("cannot fix `{}`: {e}", file.display())))?;
    // The fixed post replaces the file (keeping its mode), through a
    // temporary file beside it (docs/outputs.md).
    super::outputs::write_whole(file, &out, &[], None)?;
    Ok(fixes.len())
}
