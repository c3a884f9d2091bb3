//! `postc plot`: a backplot of a G-code program over the toolpath it was
//! posted from, top (XY) and front (XZ), with verify's findings marked and
//! numbered (`docs/plot.md`). SVG, or PNG rendered with resvg.

use postc_ir::codes;
use std::path::{Path, PathBuf};

use postc_ir::{Diagnostic, SourceMap};

use super::report::Format;
use super::verify::{ControllerArg, Job, Opened, open, post_for, toolpath};
use super::{DialectArg, Failed, fail};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The G-code program to plot.
    program: PathBuf,
    /// The toolpath the program was posted from (.ron, .jsonl, APT CL).
    #[arg(long, value_name = "TOOLPATH")]
    toolpath: PathBuf,
    /// The plot to write: `.svg`, or `.png` (rendered with resvg).
    #[arg(short, long, value_name = "OUT")]
    output: PathBuf,
    /// The post that wrote the program (as for `postc verify`).
    #[arg(long, value_name = "POST")]
    post: Option<PathBuf>,
    /// The controller whose limits apply (as for `postc verify`).
    #[arg(long, value_enum, default_value = "generic")]
    controller: ControllerArg,
    /// Tolerance in mm (as for `postc verify`).
    #[arg(long, value_name = "MM", default_value_t = 0.01)]
    tolerance: f64,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
    /// The program was written by `postc postp` from TOOLPATH (as for `postc verify`).
    #[arg(long, conflicts_with = "post")]
    postp: bool,
}

/// What `-o` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Svg,
    Png,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let ext = args.output.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    let kind = match ext.as_str() {
        "svg" => Kind::Svg,
        "png" => Kind::Png,
        _ => {
            return Err(fail(
                &mut sources,
                Diagnostic::error(
                    codes::IO007,
                    format!("`-o {}`: a plot is written as `.svg` or `.png`", args.output.display()),
                )
                .help("name the output file `plot.svg` or `plot.png`"),
            ));
        }
    };
    let inputs: Vec<&Path> =
        [&args.program, &args.toolpath].into_iter().chain(&args.post).map(PathBuf::as_path).collect();
    super::outputs::check_paths(&inputs, &[&args.output]).map_err(|d| fail(&mut sources, d))?;
    let (post, postp) = post_for(args.post.as_ref(), args.dialect, args.postp, &args.toolpath, &mut sources)?;
    let job = Job {
        program: &args.program,
        toolpath: &args.toolpath,
        post: post.as_ref(),
        controller: args.controller.into(),
        tolerance: args.tolerance,
        format: Format::Human,
        postp,
        trace: None,
    };
    let svg = plot(&job, &mut sources)?;
    let bytes = match kind {
        Kind::Svg => svg.into_bytes(),
        Kind::Png => png(&svg).map_err(|e| {
            fail(&mut sources, Diagnostic::error(codes::IO003, format!("cannot render the plot as PNG: {e}")))
        })?,
    };
    super::outputs::write_whole(&args.output, &bytes, &inputs, None).map_err(|d| fail(&mut sources, d))?;
    super::report::wrote(format_args!("{} ({} bytes of {})", args.output.display(), bytes.len(), ext.to_uppercase()));
    Ok(())
}

/// Verifies the program, drawing its moves and the toolpath's; the SVG text.
/// The findings are printed as `postc verify` prints them (they do not fail the plot).
pub(crate) fn plot(job: &Job, sources: &mut SourceMap) -> Result<String, Failed> {
    let Opened { reader, file, settings, name, size } = open(job, sources)?;
    let mut drawn = toolpath(job, sources)?;
    let mut source = toolpath(job, sources)?;
    let (mut reader, bar) = Opened::with_progress(reader, size, "plotting");
    let (mut plot, report) = postc_verify::plot::draw(&mut reader, file, &mut drawn, &mut source, &settings, sources);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    plot.title = format!("{} over {}", file_name(job.program), file_name(job.toolpath));
    report_findings(sources, &report, &name);
    Ok(plot.svg())
}

fn report_findings(sources: &mut SourceMap, report: &postc_verify::Report, name: &str) {
    super::report::eprint(sources, &report.findings);
    eprintln!(
        "postc plot: `{name}`: {} error(s), {} warning(s) marked; {} moves replayed, {} of {} toolpath moves made",
        report.errors, report.warnings, report.stats.motions, report.stats.matched, report.stats.expected
    );
}

fn file_name(p: &Path) -> String {
    p.file_name().map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into_owned())
}

/// Renders the SVG as PNG with resvg, with the system's fonts (without
/// any, the text is left out and the drawing stays readable by colour).
pub fn png(svg: &str) -> Result<Vec<u8>, String> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| e.to_string())?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| format!("a {}x{} image is too large", size.width(), size.height()))?;
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| e.to_string())
}
