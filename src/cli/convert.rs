//! `postc convert POST --to vectric|vcpost|cimco|ron [-o OUT]`: prints a post of any
//! dialect as a post of another (`postc_backends`). A post the target
//! cannot hold is refused with a diagnostic per reason, and nothing is
//! written; `-o` writes the whole file or none of it.

use postc_ir::codes;
use std::io::Write;
use std::path::{Path, PathBuf};

use postc_backends::Target;
use postc_ir::Diagnostic;

use super::{DialectArg, Failed, fail, report};

/// The dialects `convert` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum TargetArg {
    /// A Vectric .pp post.
    Vectric,
    /// A Vericut VcPost post (posts driven by APT words and application calls).
    Vcpost,
    /// A CIMCO CNC-Calc JavaScript post (a CIMCO post as itself; another post driven by the kind of move as a section post).
    Cimco,
    /// An Autodesk Fusion .cps post that Fusion runs (from a Vectric post: onSection per toolpath, the Vectric rules as JavaScript; from a CIMCO post: the CNC-Calc post as written, called in CNC-Calc's order; from a VcPost milling post: its Subs, called through the APT records of Fusion's calls; a Fusion post as it is written).
    Fusion,
    /// The post's IR as RON (postc post reads it back).
    Ron,
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The post to convert.
    post: PathBuf,
    /// The dialect to write.
    #[arg(long, value_enum)]
    to: TargetArg,
    /// Write the converted post here instead of standard output.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// The source post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    /// With `--to cimco` or `--to vcpost`: write a post of another dialect
    /// driven by the kind of each move (a Vectric post) as a section post,
    /// postc's extension that only postc runs, instead of a post the
    /// vendor's engine runs (docs/cimco.md and docs/vcpost.md, "Section
    /// posts").
    #[arg(long)]
    postc_extension: bool,
}

/// Warnings that mean the source was not read whole: `convert` stops on
/// them, as errors, and writes nothing (a converted post would silently
/// lack what was not read).
pub(super) const NOT_READ_WHOLE: &[&str] = &["PP019", "PP030"];

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let outputs: Vec<&Path> = args.output.iter().map(PathBuf::as_path).collect();
    super::outputs::check_paths(&[&args.post], &outputs).map_err(|d| fail(&mut sources, d))?;
    let mut rules = postc_ir::codes::LevelRules::default();
    for code in NOT_READ_WHOLE {
        // Rank 2: above the file's and the command line's rules.
        let _ = rules.add(code, postc_ir::codes::Level::Deny, 2);
    }
    let post = super::load_post_with(Some(&args.post), args.dialect, &mut sources, &rules)?;
    let target = match args.to {
        TargetArg::Vectric => Target::Vectric,
        TargetArg::Vcpost if args.postc_extension => Target::VcPostSections,
        TargetArg::Vcpost => Target::VcPost,
        TargetArg::Cimco if args.postc_extension => Target::CimcoSections,
        TargetArg::Cimco => Target::Cimco,
        TargetArg::Fusion => Target::Fusion,
        TargetArg::Ron => Target::Ron,
    };
    let text = match postc_backends::convert_warned(&post, target) {
        Ok((text, warnings)) => {
            report::eprint(&mut sources, &warnings);
            text
        }
        Err(diagnostics) => {
            report::eprint(&mut sources, &diagnostics);
            eprintln!("postc: `{}` cannot be converted to {:?}; nothing was written", args.post.display(), args.to);
            return Err(Failed);
        }
    };
    match &args.output {
        Some(path) => {
            super::outputs::write_whole(path, &text, &[&args.post], Some(&sources))
                .map_err(|d| fail(&mut sources, d))?;
            let lines = text.iter().filter(|&&b| b == b'\n').count();
            report::wrote(format_args!(
                "{} (a {} post, {lines} lines)",
                path.display(),
                format!("{:?}", args.to).to_ascii_lowercase()
            ));
            Ok(())
        }
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout.write_all(&text).and_then(|()| stdout.flush()).map_err(|e| {
                fail(&mut sources, Diagnostic::error(codes::IO003, format!("cannot write the converted post: {e}")))
            })
        }
    }
}
