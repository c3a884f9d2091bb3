//! Real posts: every Vectric post of `../shared/corpus/vectric/*/*.pp` (the
//! public posts the project is measured against, found beside this
//! repository and never copied into it) compiles with no error and posts
//! `corpus/toolpaths/standard.ron` without an error or a panic, twice, with
//! byte-identical output. When `../shared/corpus` is not there the test
//! fails under `CI=true` and is skipped, with a message, elsewhere.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

use postc_ir::diagnostic::has_errors;
use postc_ir::{Post, Severity};
use postc_runtime::{Finished, Output};

fn manifest() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `DIR/*/*.pp` (any case of the extension), sorted.
fn posts(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("list the Vectric corpus") {
        let sub = entry.expect("directory entry").path();
        if !sub.is_dir() {
            continue;
        }
        for file in std::fs::read_dir(&sub).expect("list a corpus folder") {
            let path = file.expect("directory entry").path();
            if path.is_file() && path.extension().is_some_and(|e| e.eq_ignore_ascii_case("pp")) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The program a post writes for the standard toolpath, parts joined.
fn post_standard(post: &Post, toolpath: &Path) -> Result<Vec<u8>, String> {
    let mut sources = postc_report::source_map();
    let mut source =
        postc_driver::open_toolpath(toolpath, &mut sources).map_err(|d| format!("{} {}", d.code, d.message))?;
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => Ok(parts.concat()),
            _ => Err("a memory run did not finish in memory".into()),
        },
        Err(diagnostics) => {
            let list: Vec<String> = diagnostics
                .iter()
                .filter(|d| d.severity == Severity::Error)
                .map(|d| format!("{} {}", d.code, d.message))
                .collect();
            Err(format!("posting failed: {}", list.join("; ")))
        }
    }
}

/// Runs `f`, turning a panic into an error message.
fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(panic) => {
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "a panic".into());
            Err(format!("panicked: {message}"))
        }
    }
}

#[test]
fn every_real_vectric_post_compiles_and_posts_the_standard_job_the_same_way_twice() {
    let shared = manifest().join("../shared/corpus");
    if !shared.is_dir() {
        crate::support::referee_missing("real_posts", "../shared/corpus");
        println!("skipped: ../shared/corpus not found");
        return;
    }
    let toolpath = manifest().join("corpus/toolpaths/standard.ron");
    let posts = posts(&shared.join("vectric"));
    assert!(!posts.is_empty(), "no .pp files under {}", shared.join("vectric").display());

    let mut failures = Vec::new();
    for path in &posts {
        let name = path.strip_prefix(&shared).unwrap_or(path).display().to_string();
        let result = guarded(|| {
            let mut sources = postc_report::source_map();
            let compiled = postc_driver::compile_post(path, None, &mut sources);
            if has_errors(&compiled.diagnostics) {
                let errors: Vec<String> = compiled
                    .diagnostics
                    .iter()
                    .filter(|d| d.severity == Severity::Error)
                    .map(|d| format!("{} {}", d.code, d.message))
                    .collect();
                return Err(format!("does not compile: {}", errors.join("; ")));
            }
            let post = compiled.post.ok_or("compiled to no post")?;
            let first = post_standard(&post, &toolpath)?;
            let second = post_standard(&post, &toolpath)?;
            if first.is_empty() {
                return Err("posted nothing".into());
            }
            if first != second {
                let at = first.iter().zip(&second).position(|(a, b)| a != b).unwrap_or(first.len().min(second.len()));
                return Err(format!("two runs differ from byte {at} ({} and {} bytes)", first.len(), second.len()));
            }
            Ok(())
        });
        if let Err(e) = result {
            failures.push(format!("{name}: {e}"));
        }
    }
    assert!(failures.is_empty(), "{} of {} real posts fail:\n{}", failures.len(), posts.len(), failures.join("\n"));
    println!("{} real Vectric posts compile and post {} identically twice", posts.len(), toolpath.display());
}
