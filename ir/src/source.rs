//! Reading source files through a loader the caller provides.
//!
//! The IR and the frontends never open a file: whatever they need to read
//! beyond the bytes they are given (a Vectric post's `POST_BASE` chain, the
//! lines of a toolpath streamed from disk when a diagnostic points into it)
//! they ask the [`SourceLoader`] of the [`SourceMap`](crate::SourceMap) for.
//! The command line gives the map a loader over the file system
//! (`postc_report::FsLoader`); tests and the language server can give it
//! files held in memory ([`MemoryLoader`]). A map without a loader reads
//! nothing ([`NoFiles`]). gleam's `io.rs` (a `FileSystemReader` trait in the
//! compiler core, implemented by the CLI) is the model.

use std::collections::HashMap;
use std::ffi::OsString;
use std::io::{self, Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};

/// A file opened through a [`SourceLoader`]: read from the start, or from
/// anywhere after a seek.
pub trait ReadSeek: Read + Seek {}

impl<T: Read + Seek> ReadSeek for T {}

/// An open file of a [`SourceLoader`].
pub type SourceReader = Box<dyn ReadSeek + Send>;

/// Where source files come from.
pub trait SourceLoader: Send + Sync {
    /// The whole file.
    fn read(&self, path: &Path) -> io::Result<Vec<u8>>;

    /// The file opened for reading, for files too large to hold
    /// (toolpaths are streamed through it). Unbuffered: callers buffer.
    fn open(&self, path: &Path) -> io::Result<SourceReader>;

    /// `len` bytes of the file from byte `offset` (fewer at its end).
    fn read_at(&self, path: &Path, offset: u64, len: u64) -> io::Result<Vec<u8>> {
        let mut file = self.open(path)?;
        file.seek(SeekFrom::Start(offset))?;
        let mut bytes = Vec::with_capacity(usize::try_from(len).unwrap_or(0).min(1 << 20));
        file.take(len).read_to_end(&mut bytes)?;
        Ok(bytes)
    }

    /// The file's size in bytes.
    fn len(&self, path: &Path) -> io::Result<u64>;

    /// Whether something (a file or a folder) is at `path`.
    fn exists(&self, path: &Path) -> bool;

    /// Whether a file (not a folder) is at `path`.
    fn is_file(&self, path: &Path) -> bool;

    /// The names of the entries of a folder.
    fn read_dir(&self, dir: &Path) -> io::Result<Vec<OsString>>;

    /// One name for every path to the same file (to find `POST_BASE` loops);
    /// the path itself where the loader cannot tell.
    fn canonicalize(&self, path: &Path) -> PathBuf {
        path.to_path_buf()
    }
}

fn not_found(path: &Path) -> io::Error {
    io::Error::new(io::ErrorKind::NotFound, format!("{} is not loaded", path.display()))
}

/// The loader of a map nobody gave one: there are no files.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoFiles;

impl SourceLoader for NoFiles {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        Err(not_found(path))
    }

    fn open(&self, path: &Path) -> io::Result<SourceReader> {
        Err(not_found(path))
    }

    fn len(&self, path: &Path) -> io::Result<u64> {
        Err(not_found(path))
    }

    fn exists(&self, _path: &Path) -> bool {
        false
    }

    fn is_file(&self, _path: &Path) -> bool {
        false
    }

    fn read_dir(&self, dir: &Path) -> io::Result<Vec<OsString>> {
        Err(not_found(dir))
    }
}

/// Files held in memory, by path (tests, the language server's open
/// documents).
#[derive(Clone, Debug, Default)]
pub struct MemoryLoader {
    files: HashMap<PathBuf, Vec<u8>>,
}

impl MemoryLoader {
    pub fn new() -> MemoryLoader {
        MemoryLoader::default()
    }

    /// Adds (or replaces) a file.
    pub fn insert(&mut self, path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) -> &mut MemoryLoader {
        self.files.insert(path.into(), bytes.into());
        self
    }

    fn get(&self, path: &Path) -> io::Result<&[u8]> {
        self.files.get(path).map(Vec::as_slice).ok_or_else(|| not_found(path))
    }
}

impl SourceLoader for MemoryLoader {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.get(path).map(<[u8]>::to_vec)
    }

    fn open(&self, path: &Path) -> io::Result<SourceReader> {
        Ok(Box::new(io::Cursor::new(self.get(path)?.to_vec())))
    }

    fn read_at(&self, path: &Path, offset: u64, len: u64) -> io::Result<Vec<u8>> {
        let bytes = self.get(path)?;
        let start = usize::try_from(offset).unwrap_or(usize::MAX).min(bytes.len());
        let end = start.saturating_add(usize::try_from(len).unwrap_or(usize::MAX)).min(bytes.len());
        Ok(bytes[start..end].to_vec())
    }

    fn len(&self, path: &Path) -> io::Result<u64> {
        self.get(path).map(|b| b.len() as u64)
    }

    fn exists(&self, path: &Path) -> bool {
        self.files.contains_key(path) || self.files.keys().any(|p| p.parent() == Some(path))
    }

    fn is_file(&self, path: &Path) -> bool {
        self.files.contains_key(path)
    }

    fn read_dir(&self, dir: &Path) -> io::Result<Vec<OsString>> {
        let dir = if dir == Path::new(".") { Path::new("") } else { dir };
        let names: Vec<OsString> = self
            .files
            .keys()
            .filter(|p| p.parent() == Some(dir))
            .filter_map(|p| p.file_name().map(OsString::from))
            .collect();
        if names.is_empty() { Err(not_found(dir)) } else { Ok(names) }
    }
}
