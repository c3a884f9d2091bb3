//! The settings of a run that its caller gives (the CLI's `--set` and
//! `-o`, the Python package's `set=` and `out=`): one meaning for every
//! edge that posts.

use std::path::Path;

use postc_ir::Diagnostic;
use postc_ir::codes;
use postc_ir::event::FileInfo;
use postc_runtime::RunOptions;

/// The names [`apply_sets`] knows.
pub const SETTINGS: &str = "date, time, tolerance, property.NAME";

/// Applies `NAME=VALUE` settings (`--set`) to the run options: `date` and
/// `time` (what `[DATE]` and `[TIME]` print), `tolerance` (mm, for
/// linearized arcs), `property.NAME` (a post property, as the user sets
/// it in Fusion's post dialog: docs/fusion.md, choice 25).
pub fn apply_sets(sets: &[String], options: &mut RunOptions) -> Result<(), Diagnostic> {
    for set in sets {
        let Some((name, value)) = set.split_once('=') else {
            return Err(Diagnostic::error(codes::IO007, format!("`--set {set}` needs the form NAME=VALUE"))
                .help(format!("known names: {SETTINGS}")));
        };
        if let Some(property) = name.trim().strip_prefix("property.").filter(|p| !p.is_empty()) {
            options.properties.push((property.to_string(), value.to_string()));
            continue;
        }
        match name.trim().to_ascii_lowercase().as_str() {
            "date" => options.date = Some(value.to_string()),
            "time" => options.time = Some(value.to_string()),
            "tolerance" | "arc_tolerance" => match value.trim().parse::<f64>() {
                Ok(t) if (MIN_TOLERANCE..=MAX_TOLERANCE).contains(&t) => options.arc_tolerance = Some(t),
                _ => {
                    return Err(Diagnostic::error(
                        codes::IO007,
                        format!("`--set {set}`: the tolerance must be a number of mm from {MIN_TOLERANCE} to {MAX_TOLERANCE}"),
                    )
                    .help("the chord tolerance of arcs a post cuts into straight moves; CAM systems use 0.001 to 0.1 mm"));
                }
            },
            _ => {
                let name = name.trim();
                return Err(Diagnostic::error(codes::IO007, format!("`--set {name}` is not a setting postc knows"))
                    .help(format!(
                        "known names: {SETTINGS}; a post's property is set as `--set property.{name}={value}`"
                    )));
            }
        }
    }
    Ok(())
}

/// The smallest and the largest `--set tolerance`, mm: chords finer than
/// a tenth of a micrometre are finer than any program prints (its words
/// repeat, and the blocks that would carry a feed print nothing), and a
/// chord a millimetre from its arc is no longer the arc's shape
/// (docs/vectric.md, decision 35).
pub const MIN_TOLERANCE: f64 = 0.0001;
pub const MAX_TOLERANCE: f64 = 1.0;

/// The post as a run with `options` posts it: the chord tolerance set
/// with `--set tolerance` moves from the options into the post, so that
/// the runtime cuts arcs at it and verifying the program (which reads the
/// post) judges the chords by it, and the runtime copies no post to
/// apply it again.
pub fn post_for_run(mut post: postc_ir::Post, options: &mut RunOptions) -> postc_ir::Post {
    if let Some(tolerance) = options.arc_tolerance.take() {
        post.options.arc_tolerance = tolerance;
    }
    post
}

/// The output file as `[TP_FILENAME]`, `[TP_DIR]` and `[TP_EXT]` print it.
pub fn file_info(path: &Path) -> FileInfo {
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    FileInfo {
        name: path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
        dir: absolute.parent().map(|p| p.display().to_string()).unwrap_or_default(),
        extension: path.extension().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
    }
}
