//! VcPost corpus goldens: every VcPost post of `corpus/posts/vcpost/` run
//! over the inputs of its application, compared byte for byte with the
//! committed programs in `corpus/expected/vcpost/`:
//!
//! - milling: `fanuc_mill` over every native toolpath (`corpus/toolpaths/`
//!   and `corpus/toolpaths/vcpost/`) and over [`APT_FILES`] of
//!   `../shared/corpus/apt/` (left out when `../shared` is not there);
//! - probe-cycle programming: each table `corpus/probe/POST__NAME.csv`
//!   through the post named before `__`;
//! - composites: each event file `corpus/composites/POST__NAME.vcp.*`
//!   through the post named before `__`.
//!
//! The expected file is `POST__INPUT.EXT`, INPUT the input's name without
//! its (last, or `.vcp.*`) extension and EXT the post's (see [`extension`]).
//! Every corpus VcPost must compile without any diagnostic.
//!
//! `POSTC_BLESS=1 cargo test --test suite vcpost_corpus` rewrites the expected
//! files and removes those no input makes any more, as
//! `tests/corpus_goldens.rs` does. Read every blessed file before
//! committing it.

use postc_report::Render as _;
use std::path::{Path, PathBuf};

use crate::support::{Goldens, all_files as files};
use postc_ir::{Post, SourceMap};
use postc_runtime::{Finished, Output, RunOptions};

/// The APT CL files of `../shared/corpus/apt/` with a golden: a drilling
/// file, arcs, an NX CLSF, a Creo file, an inch file, an NCL file without
/// feeds and a peck cycle without a peck.
const APT_FILES: &[&str] = &[
    "aamorim1913__AptPostProcessor/Guincho_Lbar.apt",
    "aamorim1913__AptPostProcessor/Teflon-gasket.apt",
    "HumMan__CLSFProcessor/_1_KONTUR_NAR_40_N2.cls",
    "HumMan__CLSFProcessor/deep_drill.clsf",
    "MichaHofft__CreoPost/profilfraesen_2.ncl.2",
    "mbourque__creo_nc_tools/Haas_Machine__mworks.ncl",
    "sashainna__NCL_in_VisualStudio/upside_down.as",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The extension of the programs a corpus post writes.
fn extension(post: &str) -> &'static str {
    match post {
        "fanuc_mill" => "ngc",
        "siemens_probe" => "mpf",
        _ => "nc",
    }
}

fn compile(stem: &str) -> Result<Post, String> {
    let path = root().join("corpus/posts/vcpost").join(format!("{stem}.VcPost"));
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post(&path, None, &mut sources);
    if !compiled.diagnostics.is_empty() {
        return Err(format!("{stem}: {}", sources.render(&compiled.diagnostics, false)));
    }
    compiled.post.ok_or_else(|| format!("{stem}: no post"))
}

fn memory(
    result: Result<postc_runtime::RunReport, Vec<postc_ir::Diagnostic>>,
    sources: &mut SourceMap,
) -> Result<Vec<u8>, String> {
    match result {
        Ok(report) => match report.output {
            Finished::Memory(mut parts) if parts.len() == 1 => Ok(parts.remove(0)),
            _ => Err("not one program".into()),
        },
        Err(d) => Err(sources.render(&d, false)),
    }
}

/// Runs one input through a post: a toolpath, a probe table or an event file.
fn run(post: &Post, input: &Path) -> Result<Vec<u8>, String> {
    let mut sources = postc_report::source_map();
    let name = input.to_string_lossy().to_ascii_lowercase();
    if name.ends_with(".csv") {
        let text = std::fs::read_to_string(input).map_err(|e| e.to_string())?;
        let file = sources.add(input.display().to_string(), text.clone());
        let (calls, diagnostics) = postc_front_vcpost::table::read(&text, file, post);
        if !diagnostics.is_empty() {
            return Err(sources.render(&diagnostics, false));
        }
        let result = postc_runtime::calls::run_calls(
            &postc_driver::for_calls(post),
            &mut calls.into_iter(),
            Output::memory(),
            RunOptions::default(),
        );
        memory(result, &mut sources)
    } else if postc_front_vcpost::composites::is_composites_file(input, &postc_report::FsLoader) {
        let mut reader =
            postc_front_vcpost::composites::open(input, &mut sources, post, Vec::new()).map_err(|d| d.message)?;
        let result = postc_runtime::calls::run_calls(
            &postc_driver::for_calls(post),
            &mut reader,
            Output::memory(),
            RunOptions::default(),
        );
        memory(result, &mut sources)
    } else {
        let mut source = postc_driver::open_toolpath(input, &mut sources).map_err(|d| d.message)?;
        let result = postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post));
        memory(result, &mut sources)
    }
}

/// An input's name without its extension (`.vcp.ron` counts as one).
fn input_stem(path: &Path) -> String {
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    let lower = name.to_ascii_lowercase();
    match lower.find(".vcp.") {
        Some(i) => name[..i].to_string(),
        None => path.file_stem().unwrap().to_string_lossy().into_owned(),
    }
}

/// Every (post, input, expected file name) of the corpus.
fn jobs() -> (Vec<(String, PathBuf, String)>, bool) {
    let mut jobs = Vec::new();
    let mut toolpaths = files(&root().join("corpus/toolpaths"));
    toolpaths.extend(files(&root().join("corpus/toolpaths/vcpost")));
    let shared = root().join("../shared/corpus/apt");
    let have_shared = shared.is_dir();
    if have_shared {
        toolpaths.extend(APT_FILES.iter().map(|f| shared.join(f)));
    }
    for t in toolpaths {
        jobs.push(("fanuc_mill".to_string(), t.clone(), format!("fanuc_mill__{}.ngc", input_stem(&t))));
    }
    for dir in ["corpus/probe", "corpus/composites"] {
        for input in files(&root().join(dir)) {
            let stem = input_stem(&input);
            let post = stem.split("__").next().unwrap_or_default().to_string();
            jobs.push((post.clone(), input, format!("{stem}.{}", extension(&post))));
        }
    }
    (jobs, have_shared)
}

#[test]
fn vcpost_corpus_matches_its_goldens() {
    let expected_dir = root().join("corpus/expected/vcpost");
    let (jobs, have_shared) = jobs();
    assert!(jobs.len() >= 14, "only {} corpus jobs", jobs.len());
    let mut goldens = Goldens::new();
    let mut posts = std::collections::HashMap::new();
    for (stem, input, target) in &jobs {
        let post = posts.entry(stem.clone()).or_insert_with(|| compile(stem));
        let post = match post {
            Ok(p) => &*p,
            Err(e) => {
                goldens.fail(e.clone());
                continue;
            }
        };
        let path = expected_dir.join(target);
        // A golden whose input fails to run is not stale.
        goldens.made.insert(path.clone());
        let output = match run(post, input) {
            Ok(o) => o,
            Err(e) => {
                goldens.fail(format!("{target}: {} failed:\n{e}", input.display()));
                continue;
            }
        };
        goldens.check(&path, &output);
    }
    if have_shared {
        goldens.sweep(files(&expected_dir), "no input makes this file any more");
    }
    goldens.finish("VcPost goldens", "vcpost_corpus");
}
