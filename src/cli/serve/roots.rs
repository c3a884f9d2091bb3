//! The folders the workbench may touch: it reads files in the folders of
//! the POST and TOOLPATH it was started with, in the corpus folder and in
//! its own folder of dropped files; it writes only in the folders of POST
//! and TOOLPATH. A path is judged after `..` and symbolic links are
//! resolved, so neither leads out of a folder.

use std::path::{Path, PathBuf};

/// What a request wants to do with a path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    Read,
    Write,
}

pub struct Roots {
    /// Folders that may be read and written.
    writable: Vec<PathBuf>,
    /// Folders that may only be read.
    readable: Vec<PathBuf>,
    /// Where dropped toolpaths are kept.
    pub dropped: PathBuf,
    /// The corpus folder, if there is one.
    pub corpus: Option<PathBuf>,
}

impl Roots {
    pub fn new(post: Option<&Path>, toolpath: Option<&Path>, corpus: Option<&Path>, dropped: &Path) -> Roots {
        let folder = |file: &Path| {
            let dir = match file.parent() {
                Some(p) if !p.as_os_str().is_empty() => p,
                _ => Path::new("."),
            };
            std::fs::canonicalize(dir).ok()
        };
        let mut writable: Vec<PathBuf> = [post, toolpath].into_iter().flatten().filter_map(folder).collect();
        writable.dedup();
        let corpus = corpus.and_then(|c| std::fs::canonicalize(c).ok());
        let dropped = std::fs::canonicalize(dropped).unwrap_or_else(|_| dropped.to_path_buf());
        let readable = corpus.iter().cloned().chain([dropped.clone()]).collect();
        Roots { writable, readable, dropped, corpus }
    }

    /// The path, resolved, when `access` to it is allowed; why not, else.
    /// A file that does not exist yet is judged by its folder.
    pub fn confine(&self, path: &Path, access: Access) -> Result<PathBuf, String> {
        let resolved = match std::fs::canonicalize(path) {
            Ok(p) => p,
            Err(_) => {
                let (Some(dir), Some(name)) = (path.parent(), path.file_name()) else {
                    return Err(format!("`{}` is not a file's path", path.display()));
                };
                let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
                match std::fs::canonicalize(dir) {
                    Ok(d) => d.join(name),
                    Err(_) => return Err(format!("the folder of `{}` does not exist", path.display())),
                }
            }
        };
        let inside = |roots: &[PathBuf]| roots.iter().any(|r| resolved.starts_with(r));
        let allowed = match access {
            Access::Write => inside(&self.writable),
            Access::Read => inside(&self.writable) || inside(&self.readable),
        };
        if allowed {
            Ok(resolved)
        } else {
            Err(format!(
                "`{}` is outside the folders this workbench was started with; it may {} only {}",
                path.display(),
                if access == Access::Write { "write" } else { "read" },
                self.describe(access)
            ))
        }
    }

    fn describe(&self, access: Access) -> String {
        let mut all: Vec<String> = self.writable.iter().map(|p| format!("`{}`", p.display())).collect();
        if access == Access::Read {
            all.extend(self.corpus.iter().map(|p| format!("`{}`", p.display())));
        }
        if all.is_empty() { "the files dropped on it".to_string() } else { all.join(", ") }
    }
}
