//! What the conversion matrices share (`tests/convert_native.rs`,
//! `tests/convert_fusion.rs`): the tally of converted and refused posts,
//! the real Vectric posts of `../shared`, and converting one post as
//! `postc convert` does.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use postc_backends::Target;
use postc_ir::Post;

use super::{compile_warned, files, stem};

/// Diagnostics that mean a source was not read whole: `postc convert`
/// stops on them.
pub const NOT_READ_WHOLE: &[&str] = &["PP019", "PP030"];

/// Which posts converted, and why the others did not.
#[derive(Default)]
pub struct Tally {
    pub converted: usize,
    pub warned: usize,
    pub refused: BTreeMap<String, usize>,
    /// Programs the other engine printed as postc posts the source.
    pub compared: usize,
    /// Posts every applicable program of which the other engine printed
    /// identically.
    pub identical_posts: usize,
}

impl Tally {
    /// Adds the counts of `other` to these.
    pub fn add(&mut self, other: Tally) {
        self.converted += other.converted;
        self.warned += other.warned;
        self.compared += other.compared;
        self.identical_posts += other.identical_posts;
        for (reason, n) in other.refused {
            *self.refused.entry(reason).or_default() += n;
        }
    }

    /// One line: the counts, and the refusals by reason.
    pub fn show(&self, what: &str, total: usize) -> String {
        let refused: Vec<String> = self.refused.iter().map(|(k, n)| format!("{n} {k}")).collect();
        format!(
            "{what}: {total} posts, {} converted ({} with warnings), {} posts with every program identical, {} programs identical under Node.js; refused: {}",
            self.converted,
            self.warned,
            self.identical_posts,
            self.compared,
            if refused.is_empty() { "none".into() } else { refused.join(", ") }
        )
    }
}

/// The real Vectric posts of `../shared/corpus/vectric` (none, said, when
/// it is not there; under `CI=true` its absence fails `test`).
pub fn real_vectric_posts(test: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/vectric");
    let mut real = Vec::new();
    match std::fs::read_dir(&dir) {
        Ok(entries) => {
            for entry in entries.flatten() {
                if entry.path().is_dir() {
                    real.extend(files(&entry.path(), "pp"));
                }
            }
        }
        Err(_) => super::referee_missing(test, "../shared/corpus/vectric"),
    }
    real.sort();
    real
}

/// Converts the post at `path` to `target` as `postc convert` does (a
/// source not read whole is refused), counting the outcome in `tally`:
/// the source's IR and the converted post, written into `dir` as
/// `{n}_{stem}.{extension}`; `None` when it is refused.
pub fn convert_counted(
    path: &Path,
    n: usize,
    target: Target,
    extension: &str,
    dir: &Path,
    tally: &mut Tally,
) -> Option<(Post, PathBuf)> {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(path, None, &mut sources);
    let unread: Vec<&str> =
        compiled.diagnostics.iter().map(|d| d.code).filter(|c| NOT_READ_WHOLE.contains(c)).collect();
    if !unread.is_empty() {
        *tally.refused.entry(format!("{} (not read whole)", unread.join("+"))).or_default() += 1;
        return None;
    }
    let post = match compile_warned(path) {
        Ok(p) => p,
        Err(e) => {
            *tally.refused.entry("do not compile".into()).or_default() += 1;
            eprintln!("{e}");
            return None;
        }
    };
    let (text, warnings) = match postc_backends::convert_warned(&post, target) {
        Ok(ok) => ok,
        Err(reasons) => {
            let mut codes: Vec<&str> = reasons.iter().map(|d| d.code).collect();
            codes.sort_unstable();
            codes.dedup();
            *tally.refused.entry(codes.join("+")).or_default() += 1;
            return None;
        }
    };
    tally.converted += 1;
    if !warnings.is_empty() {
        tally.warned += 1;
    }
    let converted = dir.join(format!("{n}_{}.{extension}", stem(path)));
    std::fs::write(&converted, &text).expect("write the converted post");
    Some((post, converted))
}
