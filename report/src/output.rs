//! Where the outputs of the edges that post go (`-o` of the command
//! line, `out=` of the Python package): an output's path after its links,
//! a device or pipe told from a file ([`OutputTarget`]), and a whole
//! output in memory written so that a failure leaves nothing
//! ([`write_whole`]; docs/outputs.md, "Links, devices and pipes").

use std::path::Path;

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
