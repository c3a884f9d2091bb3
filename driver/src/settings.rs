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
/// with `--set tolerance` is the post's, so that the runtime cuts arcs at
/// it and verifying the program judges the chords by it.
pub fn post_for_run(mut post: postc_ir::Post, options: &RunOptions) -> postc_ir::Post {
    if let Some(tolerance) = options.arc_tolerance {
        post.options.arc_tolerance = tolerance;
    }
    post
}

/// Where an output (`-o`, `out=`) goes: the path it names, after
/// symbolic links (docs/outputs.md, "Links, devices and pipes").
#[derive(Debug, PartialEq, Eq)]
pub enum OutputTarget {
    /// A file (or no file yet): replaced by renaming a temporary file
    /// beside it onto it.
    File(std::path::PathBuf),
    /// A device, a pipe or a socket: written into, never replaced.
    Stream(std::path::PathBuf),
}

impl OutputTarget {
    /// The output `path` names: the file its symbolic links lead to (a
    /// link to a file not there yet leads to the new file's place).
    pub fn of(path: &Path) -> OutputTarget {
        let mut at = path.to_path_buf();
        // As many links as the system follows in one path (Linux: 40).
        for _ in 0..40 {
            match std::fs::symlink_metadata(&at) {
                Ok(m) if m.file_type().is_symlink() => match std::fs::read_link(&at) {
                    Ok(next) => {
                        at = match at.parent() {
                            Some(dir) if next.is_relative() => dir.join(next),
                            _ => next,
                        };
                    }
                    Err(_) => break,
                },
                Ok(m) if !m.is_file() && !m.is_dir() => return OutputTarget::Stream(at),
                _ => break,
            }
        }
        OutputTarget::File(at)
    }
}

/// Writes a whole output already in memory: into a device or a pipe as it
/// is, else to a temporary file beside the file the path's links lead to,
/// renamed over it (created as `open` creates files, so with the user's
/// umask); on an error nothing is left behind.
pub fn write_whole(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    let path = match OutputTarget::of(path) {
        OutputTarget::Stream(stream) => {
            let mut to = std::fs::OpenOptions::new().write(true).open(stream)?;
            return to.write_all(bytes).and_then(|()| to.flush());
        }
        OutputTarget::File(file) => file,
    };
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let temp = dir.join(format!(".{name}.postc-{}.tmp", std::process::id()));
    let written = std::fs::File::create(&temp).and_then(|mut f| f.write_all(bytes).and_then(|()| f.sync_all()));
    match written.and_then(|()| std::fs::rename(&temp, &path)) {
        Ok(()) => Ok(()),
        Err(e) => {
            let _ = std::fs::remove_file(&temp);
            Err(e)
        }
    }
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
