//! `postc check` costs the same per diagnostic wherever it is in the file:
//! a CL file of many bad records checks in linear time.
//! Each diagnostic's line and column come from a line index built once per
//! file, not from reading the file again from its start.

use postc_report::Render as _;
use std::path::Path;
use std::time::{Duration, Instant};

use crate::many_errors;
use many_errors::bad_cl;

/// Checks a file as `postc check` does, both output forms: the JSON array
/// (every diagnostic's line and column) and the rendering for people.
fn check(path: &Path) -> (usize, Duration) {
    let start = Instant::now();
    let mut sources = postc_report::source_map();
    let diagnostics = postc_driver::check_toolpath(path, &mut sources);
    let name = path.display().to_string();
    let json: Vec<_> = diagnostics.iter().map(|d| sources.to_json(d, &name)).collect();
    assert!(json.iter().all(|d| d.line.is_some() && d.column.is_some()));
    let rendered = sources.render(&diagnostics, false);
    assert!(!rendered.is_empty());
    (diagnostics.len(), start.elapsed())
}

#[test]
fn many_bad_records_check_in_linear_time() {
    let dir = tempfile::tempdir().unwrap();
    let small = dir.path().join("small.cl");
    let large = dir.path().join("large.cl");
    std::fs::write(&small, bad_cl(1 << 20)).unwrap();
    std::fs::write(&large, bad_cl(4 << 20)).unwrap();
    check(&small); // warm the page cache and the allocator
    let (n_small, t_small) = check(&small);
    let (n_large, t_large) = check(&large);
    assert!(n_small > 10_000 && n_large > 3 * n_small, "{n_small} and {n_large} diagnostics");
    let ratio = t_large.as_secs_f64() / t_small.as_secs_f64().max(1e-6);
    eprintln!("{n_small} diagnostics in {t_small:?}, {n_large} in {t_large:?}: ratio {ratio:.2} for 4x the size");
    // Linear work makes this about 4; work that grows with the square of the
    // diagnostics makes it about 16. The bound is generous against noise.
    assert!(ratio < 8.0, "4x the bad records took {ratio:.1}x the time ({t_small:?} -> {t_large:?})");
}

#[test]
fn streamed_positions_match_the_held_text() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("positions.cl");
    let text = "GOTO/1,2,3\n$$ é à ü\nGOTO/4,Q5,6\r\n\nFINI";
    std::fs::write(&path, text).unwrap();
    let mut held = postc_report::source_map();
    let held_id = held.add("positions.cl", text);
    let mut streamed = postc_report::source_map();
    let streamed_id = streamed.add_streamed(path.display().to_string());
    for offset in 0..=text.len() + 3 {
        if !text.is_char_boundary(offset.min(text.len())) {
            continue;
        }
        assert_eq!(streamed.line_column(streamed_id, offset), held.line_column(held_id, offset), "offset {offset}");
    }
}

/// A loader over the file system that counts the bytes it hands out and
/// never hands out more than [`READ_CAP`] from one file: the work of a
/// check is bounded by what it reads, so counting bytes bounds it without
/// a clock.
struct Counting {
    read: std::sync::Arc<std::sync::atomic::AtomicU64>,
}

/// Far more than any post, far less than a run without end.
const READ_CAP: u64 = 64 << 20;

impl Counting {
    fn count(&self, n: usize) {
        self.read.fetch_add(n as u64, std::sync::atomic::Ordering::Relaxed);
    }
}

impl postc_ir::SourceLoader for Counting {
    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        self.read_at(path, 0, READ_CAP)
    }

    fn open(&self, path: &Path) -> std::io::Result<postc_ir::source::SourceReader> {
        use std::io::Read as _;
        let mut bytes = Vec::new();
        postc_report::FsLoader.open(path)?.take(READ_CAP).read_to_end(&mut bytes)?;
        self.count(bytes.len());
        Ok(Box::new(std::io::Cursor::new(bytes)))
    }

    fn read_at(&self, path: &Path, offset: u64, len: u64) -> std::io::Result<Vec<u8>> {
        use std::io::{Read as _, Seek as _};
        let mut file = postc_report::FsLoader.open(path)?;
        file.seek(std::io::SeekFrom::Start(offset))?;
        let mut bytes = Vec::new();
        file.take(len.min(READ_CAP)).read_to_end(&mut bytes)?;
        self.count(bytes.len());
        Ok(bytes)
    }

    fn len(&self, path: &Path) -> std::io::Result<u64> {
        postc_report::FsLoader.len(path)
    }

    fn exists(&self, path: &Path) -> bool {
        postc_report::FsLoader.exists(path)
    }

    fn is_file(&self, path: &Path) -> bool {
        postc_report::FsLoader.is_file(path)
    }

    fn read_dir(&self, dir: &Path) -> std::io::Result<Vec<std::ffi::OsString>> {
        postc_report::FsLoader.read_dir(dir)
    }

    fn canonicalize(&self, path: &Path) -> std::path::PathBuf {
        postc_report::FsLoader.canonicalize(path)
    }
}

/// Two mutants of corpus posts name `POST_BASE = "/dev/urandom"`: reading
/// that base never ended (over 30 s and 8 GB). `postc check` and `postc
/// post` read a base only when it is a regular file, so checking each
/// reads a few times its own size, and says why the base was not read.
#[test]
fn fault_posts_read_no_more_than_their_size() {
    let faults = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/faults");
    if !faults.is_dir() {
        crate::support::referee_missing("check_scaling", "../shared/faults");
        println!("skipped: ../shared/faults not found");
        return;
    }
    for name in ["vectric-slow-check.pp", "vectric-slow-post.pp"] {
        let path = faults.join(name);
        let size = std::fs::metadata(&path).unwrap().len();
        let read = std::sync::Arc::new(std::sync::atomic::AtomicU64::new(0));
        let mut sources = postc_ir::SourceMap::with_loader(std::sync::Arc::new(Counting { read: read.clone() }));
        let compiled = postc_driver::compile_post(&path, None, &mut sources);
        let mut diagnostics = compiled.diagnostics.clone();
        if let Some(post) = &compiled.post {
            diagnostics.extend(postc_lint::lint(post, &postc_lint::Options::default()));
            if !postc_ir::diagnostic::has_errors(&diagnostics) {
                let toolpath = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/toolpaths/standard.ron");
                let mut events = postc_driver::open_toolpath(&toolpath, &mut sources).unwrap();
                let _ = postc_runtime::run(
                    post,
                    &mut events,
                    postc_runtime::Output::discard(),
                    postc_driver::run_options(post),
                );
            }
        }
        let read = read.load(std::sync::atomic::Ordering::Relaxed);
        assert!(read <= 4 * size + (64 << 10), "{name}: {read} bytes read for a post of {size}");
        let base = diagnostics.iter().find(|d| d.code == "PP019").unwrap_or_else(|| panic!("{name}: {diagnostics:?}"));
        assert!(base.message.contains("not a regular file"), "{name}: {}", base.message);
        let json = sources.to_json(base, name);
        assert_eq!(json.line, Some(if name.contains("check") { 25 } else { 116 }), "{name}: {json:?}");
    }
}
