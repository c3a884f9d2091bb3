//! The files a command writes, and the rules they follow (docs/outputs.md):
//!
//! - no output may be one of the command's inputs, and no two outputs may
//!   be the same file, after links are resolved ([`check_paths`], before
//!   anything is read or written; [`Batch::commit`] checks again against
//!   every file the command read, `POST_BASE` files and tape-split part
//!   names included);
//! - every output is written to a temporary file beside its target
//!   ([`Temp`]), and all the outputs of one command are renamed into place
//!   together when the whole command succeeded ([`Batch`]), or none is;
//! - an output gets the mode of the file it replaces, or the mode a new
//!   file gets under the user's umask (read from the temporary file
//!   itself, which is created with `0o666` and so gets `0o666 & !umask`);
//! - an output named by a symbolic link is written to the file the link
//!   names, and the link stays ([`OutputTarget`]);
//! - an output that is not a file but a device or a pipe (`/dev/null`, a
//!   FIFO a controller's sender reads) is never replaced: the program is
//!   kept in a temporary file of the system's temporary folder and copied
//!   into it at the commit, and an error writing it (`/dev/full`: no space
//!   left) fails the command;
//! - on SIGINT, SIGTERM or SIGHUP the temporary files and folders
//!   ([`TempDir`]) are removed and postc exits with 128 + the signal's
//!   number (130, 143, 129).

use std::cell::RefCell;
use std::fs::{File, Permissions};
use std::io;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::{Mutex, MutexGuard};

use postc_ir::{Diagnostic, SourceMap, codes};
use postc_report::output::OutputTarget;

/// Temporary files that exist now, removed if a signal ends the process.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    PENDING.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Temporary folders that exist now, removed (with what they hold) if a
/// signal ends the process.
static PENDING_DIRS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending_dirs() -> MutexGuard<'static, Vec<PathBuf>> {
    PENDING_DIRS.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A temporary folder (`postc serve` keeps dropped files in one): removed
/// with its files when dropped, or when a signal ends postc.
pub struct TempDir(Option<tempfile::TempDir>);

impl TempDir {
    /// A new folder in the system's temporary folder, named `prefix...`.
    pub fn new(prefix: &str) -> io::Result<TempDir> {
        on_signal_remove_pending();
        let mut list = pending_dirs();
        let dir = tempfile::Builder::new().prefix(prefix).tempdir()?;
        list.push(dir.path().to_path_buf());
        Ok(TempDir(Some(dir)))
    }

    pub fn path(&self) -> &Path {
        self.0.as_ref().map_or(Path::new(""), |d| d.path())
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        if let Some(dir) = self.0.take() {
            let mut list = pending_dirs();
            unregister(&mut list, dir.path());
            drop(dir);
        }
    }
}

/// Creates a temporary file with `create` and adds it to the pending list,
/// holding the list meanwhile, and with the signal handler installed
/// first: a signal finds the file either not yet created or listed.
fn created(create: impl FnOnce() -> io::Result<tempfile::NamedTempFile>) -> io::Result<tempfile::NamedTempFile> {
    on_signal_remove_pending();
    let mut list = pending();
    let file = create()?;
    list.push(file.path().to_path_buf());
    Ok(file)
}

fn unregister(list: &mut Vec<PathBuf>, path: &Path) {
    if let Some(i) = list.iter().rposition(|p| p == path) {
        list.swap_remove(i);
    }
}

/// Installs, once, the handler that removes the pending temporary files
/// and exits when SIGINT, SIGTERM or SIGHUP arrives. A commit holds the
/// list's lock while it renames, so a signal lands before or after it.
#[cfg(unix)]
fn on_signal_remove_pending() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(|| {
        let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else { return };
        let spawned = std::thread::Builder::new().name("postc-signals".into()).spawn(move || {
            if let Some(signal) = signals.forever().next() {
                for path in pending().drain(..) {
                    let _ = std::fs::remove_file(path);
                }
                for path in pending_dirs().drain(..) {
                    let _ = std::fs::remove_dir_all(path);
                }
                std::process::exit(128 + signal);
            }
        });
        drop(spawned);
    });
}

#[cfg(not(unix))]
fn on_signal_remove_pending() {}

/// A temporary file: removed when dropped, or when a signal ends postc.
pub struct Temp {
    file: Option<tempfile::NamedTempFile>,
    /// The mode a new file gets under the umask, to give the output when
    /// it replaces no file.
    new_mode: Option<Permissions>,
}

impl Temp {
    /// A temporary file to become `target`: in the folder of the file it
    /// replaces, or in the system's temporary folder for a device or a
    /// pipe ([`OutputTarget`]).
    pub fn beside(target: &Path) -> io::Result<Temp> {
        let target = match OutputTarget::of(target) {
            OutputTarget::File(path) => path,
            OutputTarget::Stream(_) => return Temp::scratch(),
        };
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let mut builder = tempfile::Builder::new();
        builder.prefix(".postc-").suffix(".part");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            builder.permissions(Permissions::from_mode(0o666));
        }
        let file = created(|| builder.tempfile_in(dir)).map_err(|e| why_not_created(dir, e))?;
        let new_mode = file.as_file().metadata()?.permissions();
        // Private while it is written; the output's mode is set when it is committed.
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            file.as_file().set_permissions(Permissions::from_mode(0o600))?;
        }
        Ok(Temp { file: Some(file), new_mode: Some(new_mode) })
    }

    /// A scratch file in the system's temporary folder, never committed.
    pub fn scratch() -> io::Result<Temp> {
        let file = created(tempfile::NamedTempFile::new)?;
        Ok(Temp { file: Some(file), new_mode: None })
    }

    fn inner(&self) -> io::Result<&tempfile::NamedTempFile> {
        self.file.as_ref().ok_or_else(|| io::Error::other("the temporary file is gone"))
    }

    /// The open file.
    pub fn file(&self) -> io::Result<&File> {
        Ok(self.inner()?.as_file())
    }

    /// Where the file is.
    pub fn path(&self) -> io::Result<&Path> {
        Ok(self.inner()?.path())
    }

    /// Renames the file to `target` (the file its links lead to), with
    /// the mode of the file it replaces or of a new file, or copies it
    /// into a device or a pipe; the caller holds the pending list.
    fn persist(mut self, target: &Path, list: &mut Vec<PathBuf>) -> io::Result<()> {
        let Some(file) = self.file.take() else { return Err(io::Error::other("the temporary file is gone")) };
        let target = match OutputTarget::of(target) {
            OutputTarget::File(path) => path,
            OutputTarget::Stream(path) => {
                let path_of_temp = file.path().to_path_buf();
                let copied = file.reopen().and_then(|mut from| {
                    let mut to = std::fs::OpenOptions::new().write(true).open(&path)?;
                    io::copy(&mut from, &mut to)?;
                    io::Write::flush(&mut to)
                });
                drop(file);
                unregister(list, &path_of_temp);
                return copied;
            }
        };
        let target = target.as_path();
        let mode = match std::fs::metadata(target) {
            Ok(m) if m.is_file() => Some(m.permissions()),
            _ => self.new_mode.take(),
        };
        if let Some(mode) = mode {
            file.as_file().set_permissions(mode)?;
        }
        let path = file.path().to_path_buf();
        match file.persist(target) {
            Ok(_) => {
                unregister(list, &path);
                Ok(())
            }
            Err(e) => {
                // Dropping the file the error hands back removes it.
                drop(e.file);
                unregister(list, &path);
                Err(e.error)
            }
        }
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        if let Some(file) = self.file.take() {
            let path = file.path().to_path_buf();
            drop(file);
            unregister(&mut pending(), &path);
        }
    }
}

/// An error creating a temporary file in `dir`, said of the folder (the
/// temporary file's own name means nothing to the user).
fn why_not_created(dir: &Path, e: io::Error) -> io::Error {
    match std::fs::metadata(dir) {
        Err(_) => io::Error::new(io::ErrorKind::NotFound, format!("the folder `{}` does not exist", dir.display())),
        Ok(m) if !m.is_dir() => io::Error::other(format!("`{}` is not a folder", dir.display())),
        Ok(_) => io::Error::new(e.kind(), format!("cannot create a file in `{}`: {}", dir.display(), e.kind())),
    }
}

/// The outputs of one command, staged and committed together.
#[derive(Clone, Default)]
pub struct Batch(Rc<RefCell<Vec<(Temp, PathBuf)>>>);

impl Batch {
    /// Adds a complete temporary file, to become `target` at the commit.
    /// Writes `bytes` whole to a temporary file beside `target` and stages
    /// it to become `target`.
    pub fn stage_bytes(&self, target: &Path, bytes: &[u8]) -> Result<(), Diagnostic> {
        let temp = Temp::beside(target).map_err(|e| cannot_write(target, &e))?;
        io::Write::write_all(&mut temp.file().map_err(|e| cannot_write(target, &e))?, bytes)
            .map_err(|e| cannot_write(target, &e))?;
        self.stage(temp, target.to_path_buf());
        Ok(())
    }

    pub fn stage(&self, temp: Temp, target: PathBuf) {
        self.0.borrow_mut().push((temp, target));
    }

    /// The targets staged so far.
    pub fn targets(&self) -> Vec<PathBuf> {
        self.0.borrow().iter().map(|(_, t)| t.clone()).collect()
    }

    /// Renames every staged file into place: first checks that no target
    /// is an input (one of `inputs`, or a file `sources` read), another
    /// target, or a folder, then syncs each file and renames them all
    /// while holding the pending list, so that a signal finds all or none
    /// of them renamed.
    pub fn commit(&self, inputs: &[&Path], sources: Option<&SourceMap>) -> Result<(), Diagnostic> {
        self.commit_except(inputs, sources, &[])
    }

    /// [`Batch::commit`], where the files `written` of `sources` are this
    /// command's own outputs (a program verified as it was written), not
    /// files it read.
    pub fn commit_except(
        &self,
        inputs: &[&Path],
        sources: Option<&SourceMap>,
        written: &[postc_ir::FileId],
    ) -> Result<(), Diagnostic> {
        let staged = std::mem::take(&mut *self.0.borrow_mut());
        let targets: Vec<&Path> = staged.iter().map(|(_, t)| t.as_path()).collect();
        let mut read: Vec<PathBuf> = inputs.iter().map(|p| p.to_path_buf()).collect();
        if let Some(sources) = sources {
            read.extend(
                (0..sources.len() as u32)
                    .map(postc_ir::FileId)
                    .filter(|id| !written.contains(id))
                    .map(|id| PathBuf::from(sources.name(id)))
                    .filter(|p| p.is_file()),
            );
        }
        let read: Vec<&Path> = read.iter().map(PathBuf::as_path).collect();
        check_paths(&read, &targets)?;
        for (temp, target) in &staged {
            if target.is_dir() {
                return Err(cannot_write(target, &io::Error::other("it is a folder")));
            }
            temp.file().and_then(File::sync_all).map_err(|e| cannot_write(target, &e))?;
        }
        let mut list = pending();
        for (temp, target) in staged {
            temp.persist(&target, &mut list).map_err(|e| cannot_write(&target, &e))?;
        }
        Ok(())
    }
}

/// Writes one output whole (a command whose only output is `bytes`): a
/// temporary file beside `target`, committed as [`Batch::commit`] does.
pub fn write_whole(
    target: &Path,
    bytes: &[u8],
    inputs: &[&Path],
    sources: Option<&SourceMap>,
) -> Result<(), Diagnostic> {
    let batch = Batch::default();
    batch.stage_bytes(target, bytes)?;
    batch.commit(inputs, sources)
}

/// IO003 for an output.
pub fn cannot_write(target: &Path, e: &io::Error) -> Diagnostic {
    Diagnostic::error(codes::IO003, format!("cannot write `{}`: {e}", target.display()))
}

/// What a path is, to tell whether two paths are one file: the file
/// itself when it exists (device and inode on Unix, so hard links are one
/// file), else its absolute path with the folder's links resolved.
#[derive(PartialEq, Eq, Debug)]
enum Identity {
    #[cfg(unix)]
    Inode(u64, u64),
    Path(PathBuf),
}

fn identity(path: &Path) -> Identity {
    #[cfg(unix)]
    if let Ok(m) = std::fs::metadata(path) {
        use std::os::unix::fs::MetadataExt;
        return Identity::Inode(m.dev(), m.ino());
    }
    if let Ok(p) = std::fs::canonicalize(path) {
        return Identity::Path(p);
    }
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    match (absolute.parent(), absolute.file_name()) {
        (Some(dir), Some(name)) => {
            Identity::Path(std::fs::canonicalize(dir).map_or_else(|_| absolute.clone(), |d| d.join(name)))
        }
        _ => Identity::Path(absolute),
    }
}

/// Refuses (IO012) an output that is one of the inputs, or two outputs
/// that are the same file.
pub fn check_paths(inputs: &[&Path], outputs: &[&Path]) -> Result<(), Diagnostic> {
    let inputs: Vec<(Identity, &Path)> = inputs.iter().map(|p| (identity(p), *p)).collect();
    let mut seen: Vec<(Identity, &Path)> = Vec::new();
    for out in outputs {
        let id = identity(out);
        if let Some((_, input)) = inputs.iter().find(|(i, _)| *i == id) {
            let same = if input == out { String::new() } else { format!(" (`{}`)", input.display()) };
            return Err(Diagnostic::error(
                codes::IO012,
                format!("the output `{}` is an input of this command{same}; nothing was written", out.display()),
            )
            .help("write the output to another file"));
        }
        if let Some((_, other)) = seen.iter().find(|(i, _)| *i == id) {
            return Err(Diagnostic::error(
                codes::IO012,
                format!(
                    "two outputs of this command are the same file (`{}` and `{}`); nothing was written",
                    other.display(),
                    out.display()
                ),
            )
            .help("give each output its own file"));
        }
        seen.push((id, out));
    }
    Ok(())
}
