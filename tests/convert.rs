//! `postc convert`: every corpus post converted to every target either is
//! refused with a diagnostic, or posts every toolpath it applies to with
//! the same bytes and the same warnings as its source (but for the hash
//! `[REVISION]` prints, which a converted Vectric post takes from its own
//! file, as VCarve does: [`with_revision`]).
//!
//! - the project's posts (`corpus/posts/`): each post converted to
//!   another dialect is pinned in `corpus/converted/<target>/<source
//!   dialect>/` (a byte-exact golden of `tests/support`: bless with
//!   `POSTC_BLESS=1`); one converted to its own dialect is held to its
//!   source by tests/convert_own_dialect.rs;
//! - the real Vectric posts of `../shared/corpus/vectric`: converted and
//!   posted, not pinned (their text is not the project's to commit);
//! - converting a converted post to its own target gives the same text (a
//!   fixed point), and a converted post compiles with no diagnostic the
//!   source did not have.
//!
//! The test prints the matrix (source dialect x target: converted /
//! refused, by reason) that `docs/convert.md` records.

use crate::support;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::support::{blessing, check_golden, corpus, diff, files, stem};
use postc_backends::Target;
use postc_ir::{Dialect, Post, SourceMap};
use postc_runtime::{Finished, Output, RunOptions};

// CIMCO as section posts (`--postc-extension`): the native CNC-Calc form
// has its own matrix, under Node.js (tests/convert_native.rs).
const TARGETS: [Target; 4] = [Target::Vectric, Target::VcPostSections, Target::CimcoSections, Target::Ron];

struct Case {
    post: PathBuf,
    /// Where the source post comes from: "own" or "real".
    origin: &'static str,
    toolpaths: Vec<PathBuf>,
}

fn shared_vectric() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/vectric");
    dir.is_dir().then_some(dir)
}

fn cases() -> Vec<Case> {
    let toolpaths = files(&corpus().join("toolpaths"), "ron");
    let mut cases = Vec::new();
    for post in files(&corpus().join("posts/vectric"), "pp") {
        cases.push(Case { post, origin: "own", toolpaths: toolpaths.clone() });
    }
    let cimco = corpus().join("toolpaths/cimco");
    for post in files(&corpus().join("posts/cimco"), "js") {
        let lathe = stem(&post).contains("lathe");
        let toolpaths = if lathe {
            vec![cimco.join("lathe.ron")]
        } else {
            vec![cimco.join("mill.ron"), cimco.join("drill.ron"), corpus().join("toolpaths/standard.ron")]
        };
        cases.push(Case { post, origin: "own", toolpaths });
    }
    for post in files(&corpus().join("posts/vcpost"), "VcPost") {
        let toolpaths = if stem(&post) == "fanuc_mill" {
            let mut t = toolpaths.clone();
            t.extend(files(&corpus().join("toolpaths/vcpost"), "ron"));
            t
        } else {
            // Probe-table and composites posts run over Sub calls; their
            // conversions are checked as IR below.
            Vec::new()
        };
        cases.push(Case { post, origin: "own", toolpaths });
    }
    match shared_vectric() {
        Some(dir) => {
            let mut real = Vec::new();
            for entry in std::fs::read_dir(&dir).expect("list ../shared/corpus/vectric").flatten() {
                if entry.path().is_dir() {
                    real.extend(files(&entry.path(), "pp"));
                }
            }
            real.sort();
            let standard = vec![corpus().join("toolpaths/standard.ron"), corpus().join("toolpaths/arcs_mm.ron")];
            for post in real {
                cases.push(Case { post, origin: "real", toolpaths: standard.clone() });
            }
        }
        None => crate::support::referee_missing("convert", "../shared/corpus/vectric"),
    }
    cases
}

/// Compiles post bytes; the diagnostics as `CODE message` lines.
fn compile_bytes(path: &Path, bytes: &[u8], dialect: Option<Dialect>) -> (Option<Post>, Vec<String>) {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(path, bytes, dialect, &mut sources);
    let errors = compiled.has_errors();
    let diags = compiled.diagnostics.iter().map(|d| format!("{} {}", d.code, d.message)).collect();
    (if errors { None } else { compiled.post }, diags)
}

/// The parts of a program, or the diagnostics of a failed run.
type Program = Result<Vec<Vec<u8>>, Vec<String>>;

/// Posts a toolpath: the program, and the warnings.
fn post(post: &Post, toolpath: &Path) -> (Program, Vec<String>) {
    let mut sources = postc_report::source_map();
    let mut source = match postc_driver::open_toolpath(toolpath, &mut sources) {
        Ok(s) => s,
        Err(d) => return (Err(vec![format!("{} {}", d.code, d.message)]), Vec::new()),
    };
    let options =
        RunOptions { date: Some("2026-01-01".into()), time: Some("12:00".into()), ..postc_driver::run_options(post) };
    match postc_runtime::run(post, &mut source, Output::memory(), options) {
        Ok(report) => {
            let warnings = report.warnings.iter().map(|d| format!("{} {}", d.code, d.message)).collect();
            match report.output {
                Finished::Memory(parts) => (Ok(parts), warnings),
                _ => (Err(vec!["a memory run did not finish in memory".into()]), warnings),
            }
        }
        Err(d) => (Err(d.iter().map(|d| format!("{} {}", d.code, d.message)).collect()), Vec::new()),
    }
}

/// The source's program as a converted post prints it: a Vectric post
/// prints the hash of its own file for `[REVISION]` (docs/vectric.md,
/// "REVISION_COMMENT": VCarve hashes the post file, and a converted post is
/// another file), so the source's hash is replaced by the converted post's.
/// Posts of the other targets keep the source's hash (`revision`).
fn with_revision(program: Program, from: &Post, to: &Post) -> Program {
    let (old, new) = (from.info.revision.as_bytes(), to.info.revision.as_bytes());
    if old.is_empty() || old == new {
        return program;
    }
    program.map(|parts| {
        parts
            .into_iter()
            .map(|part| {
                let mut out = Vec::with_capacity(part.len());
                let mut rest = &part[..];
                while let Some(i) = rest.windows(old.len()).position(|w| w == old) {
                    out.extend_from_slice(&rest[..i]);
                    out.extend_from_slice(new);
                    rest = &rest[i + old.len()..];
                }
                out.extend_from_slice(rest);
                out
            })
            .collect()
    })
}

fn target_name(t: Target) -> &'static str {
    match t {
        Target::Vectric => "vectric",
        Target::VcPost | Target::VcPostSections => "vcpost",
        Target::Cimco | Target::CimcoSections => "cimco",
        Target::Fusion => "fusion",
        Target::Ron => "ron",
    }
}

fn target_dialect(t: Target) -> Dialect {
    match t {
        Target::Vectric => Dialect::Vectric,
        Target::VcPost | Target::VcPostSections => Dialect::VcPost,
        Target::Cimco | Target::CimcoSections => Dialect::Cimco,
        Target::Fusion => Dialect::Fusion,
        Target::Ron => Dialect::Ron,
    }
}

/// The IR with what a RON post cannot keep (spans) left out.
fn without_spans(post: &Post) -> Post {
    let text = String::from_utf8(postc_backends::convert(post, Target::Ron).expect("every post converts to RON"))
        .expect("RON is text");
    ron::from_str(&text).expect("the RON backend's text reads back")
}

#[test]
fn converted_posts_post_as_their_sources() {
    let scratch = tempfile::tempdir().expect("a scratch folder");
    let mut failures = Vec::new();
    // (source dialect and origin, target) -> outcome -> count
    let mut matrix: BTreeMap<(String, &str), BTreeMap<String, usize>> = BTreeMap::new();
    let mut pinned = BTreeSet::new();
    let mut programs = 0usize;
    let mut round_trips = 0usize;
    for case in cases() {
        let name = case.post.display().to_string();
        let bytes = std::fs::read(&case.post).expect("read the post");
        // Compiled by its path from the repository root (tests run there),
        // so that the RON of a pinned post names no folder of this machine.
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let relative = case.post.strip_prefix(root).unwrap_or(&case.post);
        let (source, source_diags) = compile_bytes(relative, &bytes, None);
        let Some(source) = source else {
            failures.push(format!("{name}: the source does not compile: {source_diags:?}"));
            continue;
        };
        let dialect = format!("{:?} ({})", source.info.dialect, case.origin);
        for target in TARGETS {
            let outcome = matrix.entry((dialect.clone(), target_name(target))).or_default();
            let converted = match postc_backends::convert(&source, target) {
                Ok(c) => c,
                Err(refusals) => {
                    if refusals.is_empty() {
                        failures.push(format!("{name} -> {}: refused without a reason", target_name(target)));
                    }
                    let codes: BTreeSet<&str> = refusals.iter().map(|d| d.code).collect();
                    let key = format!("refused: {}", codes.into_iter().collect::<Vec<_>>().join(" "));
                    *outcome.entry(key).or_default() += 1;
                    continue;
                }
            };
            *outcome.entry("converted".into()).or_default() += 1;
            let file = format!("{}.{}", stem(&case.post), target.extension());
            let folder = format!("{:?}", source.info.dialect).to_ascii_lowercase();
            std::fs::create_dir_all(scratch.path().join(&folder)).expect("a scratch folder");
            let path = scratch.path().join(&folder).join(&file);
            std::fs::write(&path, &converted).expect("write the converted post");
            let (back, back_diags) = compile_bytes(&path, &converted, Some(target_dialect(target)));
            let Some(back) = back else {
                failures.push(format!("{name} -> {file}: the converted post does not compile: {back_diags:?}"));
                continue;
            };
            let old: BTreeSet<&str> = source_diags.iter().map(|d| d.split(' ').next().unwrap_or("")).collect();
            // PP027 (no UNITS) is not said of a post with a POST_BASE, which
            // might set them; the converted post is whole, and says it.
            let based = String::from_utf8_lossy(&bytes).to_ascii_uppercase().contains("POST_BASE");
            let new: Vec<&String> = back_diags
                .iter()
                .filter(|d| !old.contains(d.split(' ').next().unwrap_or("")))
                .filter(|d| !(based && d.starts_with("PP027")))
                .collect();
            if !new.is_empty() {
                failures.push(format!("{name} -> {file}: the converted post has new diagnostics: {new:?}"));
            }
            // It lints as its source does: no lint the source did not get.
            let lints = |p: &Post| -> BTreeSet<&'static str> {
                postc_lint::lint(p, &postc_lint::Options::default()).iter().map(|d| d.code).collect()
            };
            let new_lints: Vec<&str> = lints(&back).difference(&lints(&source)).copied().collect();
            if !new_lints.is_empty() {
                failures.push(format!("{name} -> {file}: the converted post gets new lints: {new_lints:?}"));
            }
            if target == Target::Ron && without_spans(&source) != back {
                failures.push(format!("{name} -> {file}: the RON post reads back as a different IR"));
            }
            // A fixed point: converting the converted post again gives the
            // same text (but for the header comment, which names the source
            // file and dialect, when they differ).
            let body = |text: &[u8]| -> Vec<u8> {
                let own = source.info.dialect == target_dialect(target);
                let skip = if own { 0 } else { text.iter().position(|b| *b == b'\n').map_or(0, |i| i + 1) };
                text[skip..].to_vec()
            };
            match postc_backends::convert(&back, target) {
                Ok(again) if body(&again) == body(&converted) => {}
                Ok(again) => {
                    failures.push(format!("{name} -> {file}: converting again differs\n{}", diff(&converted, &again)))
                }
                Err(d) => failures.push(format!("{name} -> {file}: converting again is refused: {:?}", d[0].message)),
            }
            for toolpath in &case.toolpaths {
                programs += 1;
                let pair = format!("{} over {}", file, stem(toolpath));
                let (want, want_warnings) = post(&source, toolpath);
                let want = with_revision(want, &source, &back);
                let (got, got_warnings) = post(&back, toolpath);
                match (want, got) {
                    (Ok(want), Ok(got)) => {
                        if want != got {
                            failures
                                .push(format!("{pair}: the program differs\n{}", diff(&want.concat(), &got.concat())));
                        }
                    }
                    (Err(want), Err(got)) => {
                        if want != got {
                            failures.push(format!("{pair}: fails differently: {want:?} vs {got:?}"));
                        }
                    }
                    (want, got) => failures.push(format!("{pair}: source {:?}, converted {:?}", want.err(), got.err())),
                }
                if want_warnings != got_warnings {
                    failures.push(format!("{pair}: warnings differ: {want_warnings:?} vs {got_warnings:?}"));
                }
            }
            // Round trips: convert(convert(P, X), Y) posts as P wherever both
            // steps succeed.
            for second in TARGETS.into_iter().filter(|t| *t != target) {
                let Ok(twice) = postc_backends::convert(&back, second) else { continue };
                let path = scratch.path().join(&folder).join(format!("{file}.{}", second.extension()));
                std::fs::write(&path, &twice).expect("write the twice-converted post");
                let (Some(again), _) = compile_bytes(&path, &twice, Some(target_dialect(second))) else {
                    failures.push(format!("{name} -> {file} -> {}: does not compile", target_name(second)));
                    continue;
                };
                round_trips += 1;
                for toolpath in &case.toolpaths {
                    let (want, _) = post(&source, toolpath);
                    let want = with_revision(want, &source, &again);
                    let (got, _) = post(&again, toolpath);
                    if want.as_ref().ok() != got.as_ref().ok() {
                        failures.push(format!(
                            "{name} -> {} -> {} over {}: posts differently from the source",
                            target_name(target),
                            target_name(second),
                            stem(toolpath)
                        ));
                    }
                }
            }
            // A post converted to its own dialect is held to its source
            // (tests/convert_own_dialect.rs), not to a pinned copy.
            if case.origin == "own" && source.info.dialect != target_dialect(target) {
                let dir = corpus().join("converted").join(target_name(target)).join(&folder);
                let pin = dir.join(&file);
                pinned.insert(pin.clone());
                if let Err(e) = check_golden(&pin, &converted) {
                    failures.push(e);
                }
            }
        }
    }
    for target in TARGETS {
        let dir = corpus().join("converted").join(target_name(target));
        // `postp/` folders belong to `postp_controllers_convert`.
        let folders = std::fs::read_dir(&dir)
            .into_iter()
            .flatten()
            .flatten()
            .filter(|e| e.path().is_dir() && e.file_name() != "postp");
        for entry in folders.flat_map(|f| std::fs::read_dir(f.path()).into_iter().flatten().flatten()) {
            if !pinned.contains(&entry.path()) {
                if blessing() {
                    let _ = std::fs::remove_file(entry.path());
                } else {
                    failures.push(format!("{}: no corpus post converts to it any more", entry.path().display()));
                }
            }
        }
    }
    eprintln!("convert matrix ({programs} programs compared, {round_trips} round trips through two targets):");
    for ((dialect, target), outcomes) in &matrix {
        eprintln!("  {dialect} -> {target}: {outcomes:?}");
    }
    assert!(
        failures.is_empty(),
        "{} conversion failures:\n\n{}\n\nIf pinned posts changed on purpose, read them and bless: POSTC_BLESS=1 cargo test --test suite convert",
        failures.len(),
        failures.join("\n\n")
    );
}

/// A short turning job for the lathe controllers (the mill controllers post
/// `corpus/toolpaths/apt/postp_demo.apt`).
const TURNING: &str = "MACHIN/FANUCL\nUNITS/MM\nPARTNO SHAFT\nTURRET/1\nSPINDL/180,SFM,CLW\nCOOLNT/FLOOD\n\
FEDRAT/0.25,MMPR\nRAPID\nGOTO/15,0,2\nGOTO/12.5,0,0\nGOTO/12.5,0,-25\nCIRCLE/18.5,0,-25,0,1,0,6\nGOTO/18.5,0,-31\n\
GOTO/20,0,-31\nCOOLNT/OFF\nSPINDL/OFF\nFINI\n";

/// The eight `postp` controllers: each controller post, compiled with its
/// options for a CL file, converts to RON and to VcPost (and is refused by
/// Vectric: it runs one Sub per APT word; and by CNC-Calc: its PARTNO
/// prints the part name), and posting the CL file through
/// the converted posts writes the same program as through the source.
#[test]
fn postp_controllers_convert() {
    let mill = corpus().join("toolpaths/apt/postp_demo.apt");
    let scratch = tempfile::tempdir().expect("a scratch folder");
    let lathe = scratch.path().join("shaft.apt");
    std::fs::write(&lathe, TURNING).expect("write the turning job");
    let mut failures = Vec::new();
    for controller in postc_postp::Controller::ALL {
        let cl = if controller.kind() == postc_postp::Kind::Lathe { &lathe } else { &mill };
        let cl = cl.as_path();
        let mut sources = postc_report::source_map();
        let head = postc_postp::head(cl, Some(controller), &mut sources).expect("the demo CL file's head");
        let options = postc_postp::load_options(controller, None, &mut sources).expect("the controller's options");
        let source = postc_postp::compile(&head, &options, &mut sources).expect("the controller's post");
        let refusals =
            postc_backends::convert(&source, Target::Vectric).expect_err("APT-word posts have no section form");
        assert!(refusals.iter().any(|d| d.code == "CV001"), "{controller:?}: {refusals:?}");
        // CNC-Calc runs APT-word Subs through an adapter, but hands no part
        // name for PARTNO (tests/convert_apt_cimco.rs).
        let refusals = postc_backends::convert(&source, Target::Cimco).expect_err("PARTNO reads the part name");
        assert!(
            refusals.iter().all(|d| d.code == "CV007" && d.message.contains("PARTNO")),
            "{controller:?}: {refusals:?}"
        );
        let ron = postc_backends::convert(&source, Target::Ron).expect("every post converts to RON");
        let pin = corpus().join("converted/ron/postp").join(format!("{}.ron", controller.name()));
        if let Err(e) = check_golden(&pin, &ron) {
            failures.push(e);
        }
        let (back, diags) = compile_bytes(Path::new("controller.ron"), &ron, Some(Dialect::Ron));
        let Some(back) = back else {
            failures.push(format!("{controller:?}: the RON post does not compile: {diags:?}"));
            continue;
        };
        let program = |post: &Post, sources: &mut SourceMap| match postc_postp::post_compiled(
            post,
            cl,
            &head,
            &options,
            None,
            Output::memory(),
            sources,
        ) {
            Ok(report) => match report.output {
                Finished::Memory(parts) => Ok(parts.concat()),
                _ => Err("not in memory".to_string()),
            },
            Err(d) => Err(d.iter().map(|d| format!("{} {}", d.code, d.message)).collect::<Vec<_>>().join("; ")),
        };
        let want = program(&source, &mut sources);
        let got = program(&back, &mut sources);
        match (&want, got) {
            (Ok(w), Ok(g)) if *w == g => {}
            (Ok(w), Ok(g)) => failures.push(format!("{controller:?}: the program differs\n{}", diff(w, &g))),
            (w, g) => failures.push(format!("{controller:?}: source {:?}, converted {:?}", w.as_ref().err(), g.err())),
        }
        // The controller as a VcPost post of its own: pinned, a fixed point,
        // and it posts the CL file as the controller does.
        let vcpost = match postc_backends::convert(&source, Target::VcPost) {
            Ok(v) => v,
            Err(d) => {
                failures.push(format!("{controller:?}: refused by VcPost: {:?}", d[0].message));
                continue;
            }
        };
        let pin = corpus().join("converted/vcpost/postp").join(format!("{}.VcPost", controller.name()));
        if let Err(e) = check_golden(&pin, &vcpost) {
            failures.push(e);
        }
        let path = scratch.path().join(format!("{}.VcPost", controller.name()));
        let (back, diags) = compile_bytes(&path, &vcpost, Some(Dialect::VcPost));
        let Some(back) = back else {
            failures.push(format!("{controller:?}: the VcPost post does not compile: {diags:?}"));
            continue;
        };
        match postc_backends::convert(&back, Target::VcPost) {
            Ok(again) if again == vcpost => {}
            Ok(again) => failures.push(format!("{controller:?}: converting again differs\n{}", diff(&vcpost, &again))),
            Err(d) => failures.push(format!("{controller:?}: converting again is refused: {:?}", d[0].message)),
        }
        match (want, program(&back, &mut sources)) {
            (Ok(w), Ok(g)) if w == g => {}
            (Ok(w), Ok(g)) => failures.push(format!("{controller:?} as VcPost: the program differs\n{}", diff(&w, &g))),
            (w, g) => failures.push(format!("{controller:?} as VcPost: source {:?}, converted {:?}", w.err(), g.err())),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// A RON post with any of its numbers changed (ids out of range, formats
/// that do not exist, budgets of 0) gives diagnostics or posts, and every
/// backend converts or refuses it: never a panic. Posts of all three dialects, each number set to 0 and to 65535.
#[test]
fn mutated_ron_posts_never_panic() {
    let posts = [
        corpus().join("converted/ron/vectric/gcode_mm.ron"),
        corpus().join("converted/ron/cimco/fanuc_mill.ron"),
        corpus().join("converted/ron/cimco/haas_field.ron"),
        corpus().join("converted/ron/vcpost/fanuc_mill.ron"),
    ];
    let toolpath = corpus().join("toolpaths/seed_job.ron");
    let mut refused = 0;
    let mut tried = 0;
    for path in posts {
        let text = std::fs::read_to_string(&path).expect("a pinned RON post");
        // The start of every run of digits that stands alone (an id, a count).
        let numbers: Vec<(usize, usize)> = text
            .char_indices()
            .filter(|&(i, c)| {
                c.is_ascii_digit() && !text[..i].ends_with(|p: char| p.is_ascii_alphanumeric() || p == '.' || p == '-')
            })
            .map(|(i, _)| (i, text[i..].find(|c: char| !c.is_ascii_digit()).map_or(text.len(), |n| i + n)))
            .filter(|&(_, end)| !text[end..].starts_with('.'))
            .step_by(3)
            .take(400)
            .collect();
        for (start, end) in numbers {
            for replacement in ["0", "65535"] {
                tried += 1;
                let mutated = format!("{}{replacement}{}", &text[..start], &text[end..]);
                if std::env::var_os("POSTC_TRACE_MUTATIONS").is_some() {
                    let line = text[..start].lines().count();
                    eprintln!("{}:{line}: {} -> {replacement}", path.display(), &text[start..end]);
                }
                let (back, _) = compile_bytes(Path::new("mutated.ron"), mutated.as_bytes(), Some(Dialect::Ron));
                match back {
                    Some(mut back) => {
                        // Every backend takes it or refuses it, without a panic.
                        for target in TARGETS {
                            let _ = postc_backends::convert(&back, target);
                        }
                        // A mutated loop runs to the step budget (RT002):
                        // a small one keeps the test quick.
                        back.options.step_budget = back.options.step_budget.min(20_000);
                        let _ = post(&back, &toolpath);
                    }
                    None => refused += 1,
                }
            }
        }
    }
    assert!(tried > 1000 && refused > 0, "{tried} mutations, {refused} refused");
}

/// VcPost templates: text that looks like a register (`"(A<" & "B>)"`),
/// quotes, control characters and keyword names survive a conversion to
/// VcPost, and the converted post posts the same program.
#[test]
fn vcpost_templates_and_names_survive_conversion() {
    let source = "X.Prefix = \" X\"\nX.Decimals = 3\nN.Start = 5\n\
        Sub GOTO\n  Out \"<N> (A<\" & \"B>) \"\"q\"\"<X>\" & Chr(9) & X\n  If X > 1 Then [End]\nEnd Sub\n\
        Sub [End]\n  Out \"<< >> <>\"\nEnd Sub\n";
    let (Some(source_post), diags) = compile_bytes(Path::new("t.VcPost"), source.as_bytes(), None) else {
        panic!("the source compiles")
    };
    let converted = postc_backends::convert(&source_post, Target::VcPost).expect("converts");
    let text = String::from_utf8(converted.clone()).expect("UTF-8");
    assert!(text.contains("(A<\" & \"B>) \"\"q\"\"<X>\" & Chr(9) & X"), "{text}");
    assert!(text.contains("Sub [End]"), "{text}");
    let (Some(back), back_diags) = compile_bytes(Path::new("back.VcPost"), &converted, None) else {
        panic!("the converted post compiles:\n{text}")
    };
    assert_eq!(diags, back_diags);
    let toolpath = corpus().join("toolpaths/standard.ron");
    let (want, _) = post(&source_post, &toolpath);
    let (got, _) = post(&back, &toolpath);
    assert_eq!(want.expect("posts"), got.expect("posts"));
}

/// A section post written by hand (postc's extension of VcPost,
/// docs/vcpost.md) posts what the Vectric post it mirrors posts; a wrong
/// `Postc.` option is a diagnostic.
#[test]
fn a_handwritten_vcpost_section_post_posts_as_its_vectric_twin() {
    let vectric = "POST_NAME = \"twin\"\nFILE_EXTENSION = \"nc\"\nUNITS = MM\nLINE_ENDING = \"[13][10]\"\n\
        VAR X_POSITION = [X|C|X|1.3]\nVAR Y_POSITION = [Y|C|Y|1.3]\nVAR Z_POSITION = [Z|C|Z|1.3]\nVAR FEED_RATE = [F|C|F|1.1]\n\
        begin HEADER\n\"G21 G90\"\nbegin RAPID_MOVE\n\"G0[X][Y][Z]\"\nbegin FEED_MOVE\n\"G1[X][Y][Z][F]\"\nbegin FOOTER\n\"M30\"\n";
    // The twin says Vectric's rules: values compared, the feed printed
    // again after a rapid, `-0.000` kept (docs/vectric.md).
    let vcpost = "Postc.Name = \"twin\"\nPostc.FileExtension = \"nc\"\nPostc.Units = \"MM\"\nPostc.LineEnding = \"CRLF\"\n\
        Postc.OnChangeByValue = True\nPostc.RapidForgetsFeed = True\n\
        X.Prefix = \"X\"\nX.Decimals = 3\nX.TrailingZeros = True\nX.Width = 1\nX.NegativeZero = True\nX.Modal = True\n\
        Y.Prefix = \"Y\"\nY.Decimals = 3\nY.TrailingZeros = True\nY.Width = 1\nY.NegativeZero = True\nY.Modal = True\n\
        Z.Prefix = \"Z\"\nZ.Decimals = 3\nZ.TrailingZeros = True\nZ.Width = 1\nZ.NegativeZero = True\nZ.Modal = True\n\
        F.Prefix = \"F\"\nF.Decimals = 1\nF.TrailingZeros = True\nF.Width = 1\nF.NegativeZero = True\nF.Modal = True\n\
        Sub HEADER\n  Out \"G21 G90\"\nEnd Sub\nSub RAPID_MOVE\n  Out \"G0<X><Y><Z>\"\nEnd Sub\n\
        Sub FEED_MOVE\n  Out \"G1<X><Y><Z><F>\"\nEnd Sub\nSub FOOTER\n  Out \"M30\"\nEnd Sub\n";
    let (Some(a), _) = compile_bytes(Path::new("twin.pp"), vectric.as_bytes(), None) else {
        panic!("the Vectric post")
    };
    let (Some(b), diags) = compile_bytes(Path::new("twin.VcPost"), vcpost.as_bytes(), None) else {
        panic!("the section post compiles")
    };
    assert!(diags.is_empty(), "{diags:?}");
    for toolpath in ["standard.ron", "arcs_mm.ron"] {
        let toolpath = corpus().join("toolpaths").join(toolpath);
        let (want, _) = post(&a, &toolpath);
        let (got, _) = post(&b, &toolpath);
        assert_eq!(want.expect("posts"), got.expect("posts"));
    }
    let wrong = "Postc.Units = \"cm\"\nPostc.Colour = 1\nSub HEADER\n  Out \"%\"\nEnd Sub\n";
    let (_, diags) = compile_bytes(Path::new("wrong.VcPost"), wrong.as_bytes(), None);
    assert!(diags.iter().any(|d| d.starts_with("VC021")), "{diags:?}");
    assert!(diags.iter().any(|d| d.starts_with("VC020")), "{diags:?}");
}

/// `Postc.ModalMemory = "Program"` keeps what `Modal` registers printed
/// across toolpaths (CNC-Calc's rule), `"Toolpath"` (the default) forgets
/// it as each toolpath starts (Vectric's); the VcPost backend prints the
/// statement, so a post that keeps its memory converts and posts the same.
#[test]
fn vcpost_modal_memory_for_the_whole_program() {
    let body = "X.Modal = True\nZ.Modal = True\nSub RAPID_MOVE\n  Out \"G0<X><Z>\"\nEnd Sub\n\
        Sub FEED_MOVE\n  Out \"G1<X><Z>\"\nEnd Sub\n";
    let program = |text: &str| {
        let (Some(p), diags) = compile_bytes(Path::new("modal.VcPost"), text.as_bytes(), None) else {
            panic!("compiles: {text}")
        };
        assert!(diags.is_empty(), "{diags:?}");
        p
    };
    let kept = program(&format!("Postc.ModalMemory = \"Program\"\n{body}"));
    let forgot = program(&format!("Postc.ModalMemory = \"Toolpath\"\n{body}"));
    assert!(!kept.options.forget_modal_at_toolpath_start);
    assert!(forgot.options.forget_modal_at_toolpath_start);
    let toolpath = corpus().join("toolpaths/standard.ron");
    let (k, _) = post(&kept, &toolpath);
    let (f, _) = post(&forgot, &toolpath);
    let (k, f) = (k.expect("posts").concat(), f.expect("posts").concat());
    assert!(k.len() < f.len(), "the whole program's memory prints fewer words");
    // Printed from the IR (not as written), the statement comes back.
    let mut from_ir = kept.clone();
    from_ir.drop_written();
    let text = postc_backends::convert(&from_ir, Target::VcPost).expect("converts");
    let text = String::from_utf8(text).expect("UTF-8");
    assert!(text.contains("Postc.ModalMemory = \"Program\""), "{text}");
    let back = program(&text);
    assert_eq!(post(&back, &toolpath).0.expect("posts").concat(), k);
    let (_, diags) = compile_bytes(Path::new("bad.VcPost"), b"Postc.ModalMemory = \"Job\"\n", None);
    assert!(diags.iter().any(|d| d.starts_with("VC021")), "{diags:?}");
}

/// A CIMCO section post written by hand (postc's extension, docs/cimco.md)
/// posts what the Vectric post it mirrors posts; a section function that
/// does more than return its lines is JS107.
#[test]
fn a_handwritten_cimco_section_post_posts_as_its_vectric_twin() {
    let vectric = "POST_NAME = \"twin\"\nFILE_EXTENSION = \"nc\"\nUNITS = MM\n\
        VAR X_POSITION = [X|C|X|1.3]\nVAR Y_POSITION = [Y|C|Y|1.3]\nVAR FEED_RATE = [F|C|F|1.1]\n\
        begin HEADER\n\"G21 G90\"\nbegin RAPID_MOVE\n\"G0[X][Y]\"\nbegin FEED_MOVE\n\"G1[X][Y][F]\"\nbegin FOOTER\n\"M30\"\n";
    // The twin says Vectric's rules: values compared, the feed printed
    // again after a rapid, `-0.000` kept (docs/vectric.md).
    let js = r#"var postcOptions = {name: "twin", fileExtension: "nc", units: "MM", lineEnding: "\r\n", onChangeByValue: true, rapidForgetsFeed: true};
var X_POSITION = createVariable({prefix: "X", label: "X", modal: true}, createFormat({decimals: 3, trim: false, negativeZero: true}));
var Y_POSITION = createVariable({prefix: "Y", label: "Y", modal: true}, createFormat({decimals: 3, trim: false, negativeZero: true}));
var FEED_RATE = createVariable({prefix: "F", label: "F", modal: true}, createFormat({decimals: 1, trim: false, negativeZero: true}));
function HEADER() { return "G21 G90\n"; }
function RAPID_MOVE() { return "G0" + X_POSITION + Y_POSITION + "\n"; }
function FEED_MOVE() { return "G1" + X_POSITION + Y_POSITION + FEED_RATE + "\n"; }
function FOOTER() { return "M30\n"; }
"#;
    let (Some(a), _) = compile_bytes(Path::new("twin.pp"), vectric.as_bytes(), None) else {
        panic!("the Vectric post")
    };
    let (Some(b), diags) = compile_bytes(Path::new("twin.js"), js.as_bytes(), None) else {
        panic!("the section post compiles")
    };
    assert!(diags.is_empty(), "{diags:?}");
    for toolpath in ["standard.ron", "arcs_mm.ron"] {
        let toolpath = corpus().join("toolpaths").join(toolpath);
        let (want, _) = post(&a, &toolpath);
        let (got, _) = post(&b, &toolpath);
        assert_eq!(want.expect("posts"), got.expect("posts"));
    }
    let wrong = "var X = createVariable({prefix: \"X\", label: \"X\"}, createFormat({}));\n\
        function FEED_MOVE() { if (X) { return \"\"; } return \"G1\" + X + \"\\n\"; }\n";
    let (_, diags) = compile_bytes(Path::new("wrong.js"), wrong.as_bytes(), None);
    assert!(diags.iter().any(|d| d.starts_with("JS107")), "{diags:?}");
}

/// The source's comments come along: the head of the file, a `VAR`'s and
/// a section's in Vectric, the head and a Sub's in VcPost. A comment that
/// reads like a VcPost keyword comment does not turn into one, and the
/// conversion note is not read back as a comment.
#[test]
fn comments_survive_conversion() {
    let pp = "+ Router post, mm.\n+ Second line.\n\nPOST_NAME = \"c\"\nUNITS = \"MM\"\n\n\
              + The X word.\nVAR X_POSITION = [X|C|X|1.3]\n\n\
              + #Init looks like a keyword.\nbegin HEADER\n\"G21\"\n+ inside\n\"G90\"\n\nbegin FEED_MOVE\n\"G1[X]\"\n";
    let (post, diagnostics) = compile_bytes(Path::new("c.pp"), pp.as_bytes(), None);
    let mut post = post.unwrap_or_else(|| panic!("{diagnostics:?}"));
    // To its own dialect, the post prints as written (docs/convert.md, "A
    // post converted to its own dialect") ...
    let as_written = String::from_utf8(postc_backends::convert(&post, Target::Vectric).expect("converts"));
    assert_eq!(as_written.expect("text"), format!("+ Converted by postc from c.pp (Vectric)\n{pp}"));
    // ... and from the IR alone (a RON post) each comment goes where the
    // IR says it stands. (Vectric posts printed from the IR end their
    // lines with CR LF.)
    post.drop_written();
    let vectric = String::from_utf8(postc_backends::convert(&post, Target::Vectric).expect("converts"))
        .expect("text")
        .replace("\r\n", "\n");
    let head = vectric.find("+ Router post, mm.\n+ Second line.").expect("the head");
    let var = vectric.find("+ The X word.\nVAR X_POSITION").expect("the VAR's comment");
    let section =
        vectric.find("+ #Init looks like a keyword.\n+ inside\nbegin HEADER").expect("the section's comments");
    assert!(
        vectric.starts_with("+ Converted by postc from c.pp (Vectric)\n") && head < var && var < section,
        "{vectric}"
    );
    let vcpost =
        String::from_utf8(postc_backends::convert(&post, Target::VcPostSections).expect("converts")).expect("text");
    assert!(vcpost.contains("' Router post, mm.\n' Second line.\n"), "{vcpost}");
    assert!(vcpost.contains("' # Init looks like a keyword.\n' inside\nSub HEADER"), "{vcpost}");
    // Read back, each converts to the same text again.
    for (name, text) in [("c2.pp", &vectric), ("c2.VcPost", &vcpost)] {
        let (back, diagnostics) = compile_bytes(Path::new(name), text.as_bytes(), None);
        let back = back.unwrap_or_else(|| panic!("{diagnostics:?}"));
        assert_eq!(
            back.comment(&postc_ir::CommentTarget::Post),
            ["Router post, mm.", "Second line."].map(|l| format!(" {l}"))
        );
        let target = if name.ends_with(".pp") { Target::Vectric } else { Target::VcPost };
        let again = String::from_utf8(postc_backends::convert(&back, target).expect("converts"))
            .expect("text")
            .replace("\r\n", "\n");
        let body = |t: &str| t.split_once('\n').map(|(_, rest)| rest.to_string()).unwrap_or_default();
        assert_eq!(body(&again), body(text), "{name} is not a fixed point");
    }
}

/// A CIMCO post with a native form of everything the lowering turns into
/// native IR (a `switch` that falls through, look-up tables read with keys
/// known only when the post runs and walked with `for ... in`, array
/// locals, compound assignments and `++`, `do ... while` and `continue`,
/// bitwise operators, `Math`, `typeof`, `toFixed`, text escapes) and
/// formats and variables made by implicit globals and in `onInit`
/// converts to itself: the converted post posts what the source posts,
/// converting it again gives the same text, and Node.js runs it as postc
/// does.
#[test]
fn cimco_native_forms_convert_to_themselves() {
    const POST: &str = r#"decimalMark = ".";
var linebreak = "\r\n";
xyzFormat = createFormat({decimals: 3, scale: 0.5, forceSign: true});
var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput;
var codes = {a: "G0", b: "G1", 2: "G2"};
var count = 0;
var nothing = null;
var label = "tab\there \"quoted\" \u00b0 end";
total = 0;

function onInit() {
    yOutput = createVariable({prefix: "Y", force: true}, createFormat({decimals: 2, width: 4, zeropad: true}));
}

function words(a, b) {
    var parts = [];
    parts.push(a);
    if (b != "") {
        parts.push(b);
    }
    return parts.join(" ") + "/" + parts.length;
}

function kind(m) {
    var out = "";
    switch (m) {
    case 0:
        out += "r";
    case 1:
        out += "f";
        break;
    default:
        out += "d";
    }
    return out;
}

function lookup(k) {
    var s = "";
    for (var key in codes) {
        s += key + "=" + codes[key] + ";";
    }
    return s + (codes[k] || "none") + "M" + codes[k];
}

function maths(x, y) {
    var n = 0;
    for (var i = 0; i < 3; i++) {
        n += i;
    }
    var r = Math.pow(x, 2) + Math.sqrt(Math.abs(y)) - -x * 2 / 3 % 5;
    r = r | 0;
    n++;
    n--;
    n *= 2;
    var t = typeof x + (~n) + (x >> 1) + (x >>> 2) + (x << 1) + (x ^ 3) + (x & 1);
    var z = -Infinity < x ? NaN : Infinity;
    return r + " " + n + " " + t + " " + isNaN(z) + " " + (0.1 + 0.2).toFixed(4) + parseInt("12x") + parseFloat("1.5e3") + Number("7") + String(x).substring(0, 2) + label.length;
}

function loop(n) {
    var i = 0;
    var s = "";
    do {
        i++;
        if (i == 2) {
            s += "two";
        } else {
            if (i == 3) {
                s += "three";
            }
        }
    } while (i < n);
    while (true) {
        i--;
        if (i < 0) {
            break;
        }
        if (i == 1) {
            continue;
        }
        s = s + i;
    }
    return s;
}

function onOpen(isClipboard) {
    count++;
    total = total + 1;
    return "(" + words("a", "") + " " + words("b", "c") + " " + kind(0) + kind(1) + kind(5) + ")" + linebreak
        + "(" + lookup("a") + lookup(2) + lookup("zz") + ")\n(" + maths(3, -16) + ")\n(" + loop(4) + ")\n" + label + "\n";
}

function onLinear(x, y, z, movement) {
    var sx = xOutput.getLast();
    return "G1" + xOutput.format(x) + yOutput.format(y) + xyzFormat.format(z - sx) + (nothing === null ? "" : "!") + "\n";
}

function onCircular(cx, cy, cz, ex, ey, ez, isCW, movement) {
    return "G" + (isCW ? 2 : 3) + xOutput.format(ex) + yOutput.format(ey) + "\n";
}

function onClose() {
    return "M30 " + count + " " + total + "\n";
}
"#;
    let scratch = tempfile::tempdir().expect("a scratch folder");
    let (Some(source), diags) = compile_bytes(Path::new("forms.js"), POST.as_bytes(), None) else {
        panic!("the post compiles")
    };
    assert!(diags.is_empty(), "{diags:?}");
    assert!(
        source.functions.iter().filter(|f| f.source.is_empty()).all(|f| matches!(f.body, postc_ir::Body::Native(_))),
        "every function the test means is native"
    );
    let converted = postc_backends::convert(&source, Target::Cimco).unwrap_or_else(|d| panic!("{d:?}"));
    let path = scratch.path().join("forms.js");
    std::fs::write(&path, &converted).expect("write the converted post");
    let (Some(back), back_diags) = compile_bytes(&path, &converted, None) else {
        panic!("the converted post compiles:\n{}", String::from_utf8_lossy(&converted))
    };
    assert!(back_diags.is_empty(), "{back_diags:?}");
    assert_eq!(postc_backends::convert(&back, Target::Cimco).ok(), Some(converted.clone()), "a fixed point");
    let toolpath = corpus().join("toolpaths/cimco/mill.ron");
    let (want, _) = post(&source, &toolpath);
    let (got, _) = post(&back, &toolpath);
    let want = want.expect("the source posts").concat();
    assert_eq!(want, got.expect("the converted post posts").concat());
    if support::cimco::node().is_some() {
        let jsonl = scratch.path().join("mill.jsonl");
        support::cimco::export_jsonl(&toolpath, &jsonl).expect("export the toolpath");
        let node = support::cimco::run_node(&path, &jsonl, &[]).expect("Node.js runs the converted post");
        assert_eq!(String::from_utf8_lossy(&node), String::from_utf8_lossy(&want));
    }
}

/// What a CIMCO post with code cannot print as is refused with a
/// diagnostic that names it, and nothing is written: handlers that are not
/// the ones the CIMCO frontend derives from the functions (a RON post
/// edited by hand), options no CNC-Calc setting sets, a script whose
/// JavaScript was not kept.
#[test]
fn cimco_posts_that_cannot_print_are_refused() {
    let path = corpus().join("posts/cimco/fanuc_mill.js");
    let bytes = std::fs::read(&path).expect("read the post");
    let (Some(source), _) = compile_bytes(Path::new("corpus/posts/cimco/fanuc_mill.js"), &bytes, None) else {
        panic!("the post compiles")
    };
    let refusal = |post: &Post| -> Vec<String> {
        match postc_backends::convert(post, Target::Cimco) {
            Ok(_) => panic!("converted"),
            Err(d) => d.iter().map(|d| format!("{} {}", d.code, d.message)).collect(),
        }
    };
    let mut edited = source.clone();
    let tool_change = edited
        .handlers
        .iter_mut()
        .find(|h| h.key == postc_ir::HandlerKey::Section(postc_ir::Section::ToolChange))
        .expect("a TOOLCHANGE handler");
    tool_change.body.clear();
    let d = refusal(&edited);
    assert!(d.iter().any(|d| d.starts_with("CV006") && d.contains("the handler of TOOLCHANGE")), "{d:?}");

    let mut edited = source.clone();
    edited.options.forget_modal_at_toolpath_start = true;
    edited.options.substitutions.push(postc_ir::post::Substitution { from: b"(".to_vec(), to: b"[".to_vec() });
    let d = refusal(&edited);
    assert!(d.iter().any(|d| d.starts_with("CV004") && d.contains("modal memory cleared")), "{d:?}");
    assert!(d.iter().any(|d| d.starts_with("CV004") && d.contains("substitutions")), "{d:?}");

    // A post that keeps a script (`isFinite` has no native form).
    let js = "var linebreak = \"\\n\";\nvar seen = {n: 0};\nfunction onLinear(x, y, z, m) { seen.n = x; return \"\"; }\nfunction finite(t) { return isFinite(t); }\n";
    let (Some(mut edited), _) = compile_bytes(Path::new("script.js"), js.as_bytes(), None) else {
        panic!("the post compiles")
    };
    let finite = edited.functions.iter_mut().find(|f| f.name == "finite").expect("function finite");
    assert!(matches!(finite.body, postc_ir::Body::Script(_)));
    finite.source.clear();
    let d = refusal(&edited);
    assert!(d.iter().any(|d| d.starts_with("CV002") && d.contains("`finite` runs as a script")), "{d:?}");
}

/// A CIMCO post with a regular expression converts to itself: the
/// literal prints as written (`postc-backends` checks the printing of the
/// IR's literal itself), compiles back to the same post, and posts the
/// same program.
#[test]
fn regular_expressions_print_back_in_cimco() {
    let (Some(source), _) = compile_bytes(Path::new("regex.js"), REGEX_JS.as_bytes(), None) else {
        panic!("the post compiles")
    };
    assert!(source.scripts.is_empty(), "the regular expression is native IR");
    let text = match postc_backends::convert(&source, Target::Cimco) {
        Ok(t) => String::from_utf8(t).expect("text"),
        Err(d) => panic!("refused: {d:?}"),
    };
    assert!(text.contains("t.replace(/[()]/g, \"\")"), "{text}");
    let (Some(back), diags) = compile_bytes(Path::new("back.js"), text.as_bytes(), None) else {
        panic!("the printed post compiles")
    };
    assert!(diags.is_empty(), "{diags:?}");
    let toolpath = corpus().join("toolpaths/cimco/drill.ron");
    let program = post(&source, &toolpath).0.expect("posts");
    assert!(String::from_utf8_lossy(&program.concat()).contains("G1\n"));
    assert_eq!(program, post(&back, &toolpath).0.expect("posts"));
}

const REGEX_JS: &str = "var linebreak = \"\\n\";\nfunction clean(t) {\n    return t.replace(/[()]/g, \"\");\n}\nfunction onLinear(x, y, z, m) { return clean(\"(G1)\") + linebreak; }\n";

/// Vectric and VcPost have no regular expressions: converting a post with
/// one is refused with CV002, which names it and points at it.
#[test]
fn regular_expressions_are_refused_by_dialects_without_them() {
    let mut sources = postc_report::source_map();
    // `clean` returns a local, as a VcPost Function does.
    let js = "var linebreak = \"\\n\";\nfunction clean(t) {\n    var r = t.replace(/[()]/g, \"\");\n    return r;\n}\nfunction onLinear(x, y, z, m) { return clean(\"(G1)\") + linebreak; }\n";
    let compiled = postc_driver::compile_post_bytes(Path::new("regex.js"), js.as_bytes(), None, &mut sources);
    assert!(!compiled.has_errors(), "{:?}", compiled.diagnostics);
    let post = compiled.post.expect("a post");
    for target in [Target::Vectric, Target::VcPostSections] {
        let d = match postc_backends::convert(&post, target) {
            Ok(_) => panic!("{target:?} converted a post with a regular expression"),
            Err(d) => d,
        };
        // Vectric refuses every post with code; VcPost names the literal.
        assert!(d.iter().any(|d| d.code == "CV002"), "{target:?}: {d:?}");
        if target == Target::VcPostSections {
            let d =
                d.iter().find(|d| d.message.contains("a regular expression")).unwrap_or_else(|| panic!("named: {d:?}"));
            let span = d.primary_span().expect("a span");
            assert_eq!(sources.line_column(span.file, span.start), Some((3, 23)), "{d:?}");
        }
    }
}
