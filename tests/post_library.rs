//! The post library (docs/posts.md): the embedded posts of
//! `corpus/posts/library/` and the default post check clean, post the
//! corpus toolpaths to their goldens (`corpus/expected/library/`), and
//! write G-code that `postc verify` replays without an error or a warning
//! beyond the expected one (every G-code post, Fanuc, Haas and Sinumerik
//! included, each with its controller). LinuxCNC's `rs274` reads the
//! programs of the LinuxCNC, grbl and Mach posts with every corpus
//! toolpath's motion in `tests/rs274.rs`. Heidenhain conversational and
//! HPGL are read by neither: their goldens, and a replay of their positions
//! here, are their check.
//!
//! `postc posts` lists every embedded post, as a table and as JSON, and
//! the posts of user folders (arguments, `[posts] dirs` of `postc.toml`,
//! `POSTC_POSTS`), a broken one with its error; `postc post --post NAME`
//! posts with any of them, answers a near miss with "did you mean" (IO013)
//! and two posts of one name with both paths (IO014).
//!
//! `POSTC_BLESS=1 cargo test --test suite post_library` rewrites the
//! goldens; read them before committing.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use postc::library::EMBEDDED;
use postc_driver::library::Described;
use postc_ir::Post;
use postc_verify::{Controller, Settings};

use crate::support::{Goldens, all_files, corpus, post_parts, said, stem, verifying};

/// The toolpaths every embedded post posts to its goldens.
const TOOLPATHS: &[&str] = &["standard.ron", "drill_mm.ron", "helix_mm.ron", "tools_inch.ron", "cimco/drill.ron"];

/// An embedded post compiled; it must compile with no diagnostic at all.
fn compile(i: usize) -> Post {
    let e = EMBEDDED[i];
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(Path::new(e.name), e.text, None, &mut sources);
    let said: Vec<String> = compiled.diagnostics.iter().map(|d| format!("{} {}", d.code, d.message)).collect();
    assert!(said.is_empty(), "{}: {said:?}", e.name);
    compiled.post.unwrap()
}

/// The embedded file's stem (`linuxcnc` for `<embedded>/linuxcnc.pp`).
fn embedded_stem(i: usize) -> String {
    stem(Path::new(EMBEDDED[i].name))
}

/// How `postc verify` replays what the post writes, by the controller
/// the post is for; `None` for the families verify does not read.
fn controller(i: usize) -> Option<Controller> {
    match embedded_stem(i).as_str() {
        "linuxcnc" | "mach3" => Some(Controller::LinuxCnc),
        "grbl" => Some(Controller::Grbl),
        "fanuc" => Some(Controller::Fanuc),
        "haas" => Some(Controller::Haas),
        "sinumerik" | "gcode_mm" => Some(Controller::Generic),
        "heidenhain" | "hpgl" => None,
        other => panic!("{other}: say how its output is checked"),
    }
}

#[test]
fn the_library_posts_are_the_embedded_ones() {
    let dir = corpus().join("posts/library");
    let files: Vec<String> =
        all_files(&dir).iter().map(|p| format!("<embedded>/{}", p.file_name().unwrap().to_string_lossy())).collect();
    for f in &files {
        assert!(EMBEDDED.iter().any(|e| e.name == f), "{f} of corpus/posts/library is not embedded (src/library.rs)");
    }
    assert_eq!(EMBEDDED.len(), files.len() + 1, "the default post and the library");
    assert_eq!(postc::library::DEFAULT.name, "<embedded>/gcode_mm.pp");
}

#[test]
fn every_embedded_post_checks_clean() {
    let dir = corpus().join("posts/library");
    let mut args = vec!["check".to_string(), "--format".into(), "json".into()];
    args.extend(all_files(&dir).iter().map(|p| p.display().to_string()));
    args.push("corpus/posts/vectric/gcode_mm.pp".into());
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = crate::support::postc(&args);
    assert!(out.status.success(), "{}", said(&out));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "[]", "{}", said(&out));
    for i in 0..EMBEDDED.len() {
        compile(i);
    }
}

#[test]
fn embedded_posts_match_their_goldens() {
    let root = corpus();
    let expected = root.join("expected/library");
    let mut goldens = Goldens::new();
    for i in 0..EMBEDDED.len() {
        let post = compile(i);
        let ext = post.info.file_extension.trim_start_matches('.').to_string();
        for toolpath in TOOLPATHS {
            let path = root.join("toolpaths").join(toolpath);
            let pair = format!("{}__{}", embedded_stem(i), stem(&path));
            match post_parts(&post, &path) {
                Ok(parts) => {
                    assert_eq!(parts.len(), 1, "{pair}: one part");
                    goldens.check(&expected.join(format!("{pair}.{ext}")), &parts[0]);
                }
                Err(e) => goldens.fail(format!("{pair}: {e}")),
            }
        }
    }
    goldens.sweep(all_files(&expected), "no embedded post and toolpath make this file any more");
    goldens.finish("library goldens", "post_library");
}

/// The one warning verify may give a library post's program: a jet
/// toolpath (the laser of `standard.ron` and `tools_inch.ron`) through a
/// post with no jet sections (VF035), which is true of every post here but
/// grbl's and the default's.
const EXPECTED_WARNINGS: &[&str] = &["VF035"];

#[test]
fn embedded_gcode_verifies_against_its_toolpath() {
    let mut failures = Vec::new();
    for (i, e) in EMBEDDED.iter().enumerate() {
        let Some(controller) = controller(i) else { continue };
        let post = compile(i);
        let settings = Settings::from_post(&post, controller, 0.01);
        for toolpath in TOOLPATHS {
            let path = corpus().join("toolpaths").join(toolpath);
            let program = post_parts(&post, &path).unwrap().concat();
            let found = verifying::verify(&program, &path, &settings);
            for f in found.iter().filter(|f| !EXPECTED_WARNINGS.contains(&f.code)) {
                failures.push(format!("{} over {toolpath}: {} line {}: {}", e.name, f.code, f.line, f.message));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The toolpath's move end points (rapid, feed, arc), in mm.
fn toolpath_ends(toolpath: &Path) -> Vec<[f64; 3]> {
    use postc_ir::event::Event;
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
    let (mut diags, mut factor, mut ends) = (Vec::new(), 1.0, Vec::new());
    while let Some((event, _)) = source.next_event(&mut diags) {
        match event {
            Event::Job(job) => factor = job.units.factor_to(postc_ir::Units::Mm),
            Event::Rapid(m) => ends.push([m.x * factor, m.y * factor, m.z * factor]),
            Event::Feed(m) => ends.push([m.x * factor, m.y * factor, m.z * factor]),
            Event::Arc(a) => ends.push([a.x * factor, a.y * factor, a.z * factor]),
            _ => {}
        }
    }
    ends
}

/// The number after `letter` in a Heidenhain block (`X+12.500`).
fn word(block: &str, letter: char) -> Option<f64> {
    block.split_whitespace().find_map(|w| w.strip_prefix(letter)?.parse().ok())
}

/// The positions a Heidenhain conversational program moves through (L
/// and C blocks, in order), checking on the way that each C block ends on
/// the circle of its CC centre through its start.
fn heidenhain_positions(program: &str, failures: &mut Vec<String>, label: &str) -> Vec<[f64; 3]> {
    let (mut at, mut centre, mut out) = ([f64::NAN; 3], [f64::NAN; 2], Vec::new());
    for line in program.lines() {
        let block = line.split_once(' ').map_or("", |(_, b)| b);
        let axes = |at: &mut [f64; 3]| {
            for (k, letter) in ['X', 'Y', 'Z'].into_iter().enumerate() {
                if let Some(v) = word(block, letter) {
                    at[k] = v;
                }
            }
        };
        if block.starts_with("CC ") {
            centre = [word(block, 'X').unwrap(), word(block, 'Y').unwrap()];
        } else if block.starts_with("C ") {
            let r0 = (at[0] - centre[0]).hypot(at[1] - centre[1]);
            axes(&mut at);
            let r1 = (at[0] - centre[0]).hypot(at[1] - centre[1]);
            if (r0 - r1).abs() > 0.002 {
                failures.push(format!("{label}: `{line}` ends {r1:.4} from CC, starts {r0:.4} from it"));
            }
            out.push(at);
        } else if block.starts_with("L ") && !block.contains("M91") {
            axes(&mut at);
            out.push(at);
        }
    }
    out
}

/// The positions an HPGL program moves the pen through (PU, PD, the ends
/// of AA arcs), in mm; NaN for Z, which HPGL does not have.
fn hpgl_positions(program: &str) -> Vec<[f64; 3]> {
    let (mut at, mut out) = ([f64::NAN; 3], Vec::new());
    for command in program.split(';').map(str::trim) {
        let numbers = |args: &str| args.split(',').filter_map(|a| a.trim().parse::<f64>().ok()).collect::<Vec<_>>();
        let (name, args) = command.split_at(command.len().min(2));
        match (name, numbers(args).as_slice()) {
            ("PU" | "PD", [x, y]) => at = [x / 40.0, y / 40.0, f64::NAN],
            ("AA", [cx, cy, sweep]) => {
                let (cx, cy) = (cx / 40.0, cy / 40.0);
                let (sin, cos) = sweep.to_radians().sin_cos();
                let (dx, dy) = (at[0] - cx, at[1] - cy);
                at = [cx + dx * cos - dy * sin, cy + dx * sin + dy * cos, f64::NAN];
            }
            _ => continue,
        }
        out.push(at);
    }
    out
}

/// Heidenhain conversational and HPGL are read by neither verify nor
/// rs274: a replay of their positions here finds every toolpath move's end
/// among them, in order (HPGL in X and Y only, to its 0.025 mm step), and
/// every Heidenhain arc on its circle.
#[test]
fn heidenhain_and_hpgl_programs_go_where_the_toolpath_goes() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for (i, e) in EMBEDDED.iter().enumerate() {
        let stem = embedded_stem(i);
        if stem != "heidenhain" && stem != "hpgl" {
            continue;
        }
        let post = compile(i);
        for toolpath in TOOLPATHS {
            let path = corpus().join("toolpaths").join(toolpath);
            let label = format!("{} over {toolpath}", e.name);
            let program = String::from_utf8(post_parts(&post, &path).unwrap().concat()).unwrap();
            let (positions, tol) = if stem == "hpgl" {
                (hpgl_positions(&program), 0.03)
            } else {
                (heidenhain_positions(&program, &mut failures, &label), 0.0015)
            };
            let close = |a: &[f64; 3], b: &[f64; 3]| a.iter().zip(b).all(|(p, q)| p.is_nan() || (p - q).abs() <= tol);
            let mut from = 0;
            for (n, end) in toolpath_ends(&path).iter().enumerate() {
                match positions[from..].iter().position(|p| close(p, end)) {
                    Some(k) => from += k + 1,
                    None => {
                        failures.push(format!(
                            "{label}: move {n} to {end:?} is not among the program's positions after #{from}"
                        ));
                        break;
                    }
                }
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 2 * TOOLPATHS.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The library's CIMCO posts (Fanuc, Haas) run under Node.js with the
/// referee host of `tests/node_host/` (written from docs/cimco.md, sharing
/// no code with postc) and print, byte for byte, what postc prints over the
/// CIMCO corpus's milling toolpaths.
#[test]
fn node_prints_what_postc_prints_for_the_cimco_posts() {
    use crate::support::cimco;
    if cimco::node_or_skip("post_library").is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (mut failures, mut compared) = (Vec::new(), 0);
    for (i, e) in EMBEDDED.iter().enumerate().filter(|(_, e)| e.name.ends_with(".js")) {
        let post = compile(i);
        let js = dir.path().join(format!("{}.js", embedded_stem(i)));
        std::fs::write(&js, e.text).unwrap();
        for toolpath in cimco::toolpaths(&post) {
            let jsonl = dir.path().join(format!("{}.jsonl", stem(&toolpath)));
            cimco::export_jsonl(&toolpath, &jsonl).unwrap();
            let ours = cimco::post_toolpath(&post, &toolpath).unwrap();
            let label = format!("{} over {}", e.name, stem(&toolpath));
            match cimco::run_node(&js, &jsonl, &[]) {
                Ok(theirs) if theirs == ours => compared += 1,
                Ok(theirs) => {
                    failures.push(format!("{label}: Node.js (-) and postc (+) differ\n{}", cimco::diff(&theirs, &ours)))
                }
                Err(err) => failures.push(format!("{label}: {err}")),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert_eq!(compared, 6, "two posts over three toolpaths");
}

/// Runs `postc` in `dir` with `POSTC_POSTS` set as given (and no other).
fn postc_in(dir: &Path, posts: Option<&str>, args: &[&str]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_postc"));
    c.current_dir(dir).args(args).env_remove("POSTC_POSTS");
    if let Some(p) = posts {
        c.env("POSTC_POSTS", p);
    }
    c.output().unwrap()
}

fn names() -> Vec<String> {
    (0..EMBEDDED.len()).map(|i| Described::of(&compile(i)).name).collect()
}

#[test]
fn posts_lists_every_embedded_post() {
    let dir = tempfile::tempdir().unwrap();
    let out = postc_in(dir.path(), None, &["posts"]);
    assert!(out.status.success(), "{}", said(&out));
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.starts_with("NAME "), "{table}");
    for (i, name) in names().iter().enumerate() {
        let row = table.lines().find(|l| l.ends_with(EMBEDDED[i].name)).unwrap_or_else(|| panic!("{table}"));
        assert!(row.starts_with(name.as_str()), "{row}");
    }
    let out = postc_in(dir.path(), None, &["posts", "--format", "json"]);
    let listed: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let listed = listed.as_array().unwrap();
    assert_eq!(listed.len(), EMBEDDED.len());
    let linuxcnc = listed.iter().find(|p| p["path"] == "<embedded>/linuxcnc.pp").unwrap();
    assert_eq!(linuxcnc["name"], "LinuxCNC (mm) (*.ngc)");
    assert_eq!(linuxcnc["dialect"], "vectric");
    assert_eq!(linuxcnc["units"], "mm");
    assert_eq!(linuxcnc["extension"], "ngc");
    assert_eq!(linuxcnc["embedded"], true);
    assert!(linuxcnc["error"].is_null());
    let fanuc = listed.iter().find(|p| p["path"] == "<embedded>/fanuc.js").unwrap();
    assert_eq!(fanuc["dialect"], "cimco");
    assert_eq!(fanuc["units"], "mm", "it writes G21 (docs/units.md)");
}

#[test]
fn post_by_name_posts_with_every_embedded_post() {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = corpus().join("toolpaths/standard.ron");
    for (i, name) in names().iter().enumerate() {
        let out = postc_in(dir.path(), None, &["post", "--post", name, toolpath.to_str().unwrap(), "--no-verify"]);
        assert!(out.status.success(), "{name}: {}", said(&out));
        let expected = post_parts(&compile(i), &toolpath).unwrap().concat();
        assert_eq!(out.stdout, expected, "{name}");
    }
    // Case and blanks do not matter; a Vectric name's `(*.ext)` may be left out.
    let out = postc_in(dir.path(), None, &["post", "--post", "  linuxcnc   (MM) ", toolpath.to_str().unwrap()]);
    assert!(out.status.success(), "{}", said(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("G64 P0.01"));
}

#[test]
fn a_near_miss_is_answered_with_did_you_mean() {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = corpus().join("toolpaths/standard.ron");
    let out = postc_in(dir.path(), None, &["post", "--post", "Linuxcnc (nm)", toolpath.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let text = said(&out);
    assert!(text.contains("IO013") && text.contains("did you mean `LinuxCNC (mm) (*.ngc)`"), "{text}");
    assert!(out.stdout.is_empty());
    let out = postc_in(dir.path(), None, &["post", "--post", "haas", toolpath.to_str().unwrap()]);
    assert!(said(&out).contains("did you mean `Haas VF mill (mm)`"), "{}", said(&out));
    // --post and a post path together are a bad command line.
    let out = postc_in(
        dir.path(),
        None,
        &["post", "--post", "grbl (mm)", "corpus/posts/vectric/gcode_mm.pp", toolpath.to_str().unwrap()],
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(said(&out).contains("IO006"), "{}", said(&out));
}

/// A user folder with a post of its own, a broken one and a copy named as
/// an embedded post.
fn user_folder(dir: &Path) -> PathBuf {
    let posts = dir.join("my posts");
    std::fs::create_dir(&posts).unwrap();
    let mine = std::fs::read_to_string(corpus().join("posts/library/linuxcnc.pp"))
        .unwrap()
        .replace("POST_NAME = \"LinuxCNC (mm) (*.ngc)\"", "POST_NAME = \"Shop mill (*.ngc)\"");
    std::fs::write(posts.join("shop.pp"), mine).unwrap();
    std::fs::write(posts.join("broken.pp"), "POST_NAME = \"Broken\"\nbegin RAPID_MOVE\n\"G0[X\"\n").unwrap();
    std::fs::write(posts.join("notes.txt"), "not a post").unwrap();
    // A VcPost post with no `Postc.Name`: named by its header comment.
    std::fs::copy(corpus().join("posts/vcpost/fanuc_mill.VcPost"), posts.join("fanuc_mill.VcPost")).unwrap();
    posts
}

#[test]
fn user_folders_are_listed_and_selected() {
    let dir = tempfile::tempdir().unwrap();
    let posts = user_folder(dir.path());
    let toolpath = corpus().join("toolpaths/standard.ron");
    // From POSTC_POSTS.
    let out = postc_in(dir.path(), Some(posts.to_str().unwrap()), &["posts", "--format", "json"]);
    assert!(out.status.success(), "{}", said(&out));
    let listed: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let listed = listed.as_array().unwrap();
    assert_eq!(listed.len(), EMBEDDED.len() + 3, "{listed:?}");
    let vcpost = listed.iter().find(|p| p["dialect"] == "vcpost").unwrap();
    assert_eq!(vcpost["name"], "Fanuc 0i/31i 3-axis milling post for postc (Vericut VcPost language)");
    let out = postc_in(
        dir.path(),
        Some(posts.to_str().unwrap()),
        &[
            "post",
            "--post",
            "fanuc 0i/31i 3-axis milling post for postc (vericut vcpost language)",
            toolpath.to_str().unwrap(),
        ],
    );
    assert!(out.status.success(), "{}", said(&out));
    let broken = listed.iter().find(|p| p["path"].as_str().unwrap().ends_with("broken.pp")).unwrap();
    assert_eq!(broken["name"], "broken");
    assert!(broken["error"].as_str().unwrap().starts_with("PP"), "{broken}");
    let shop = listed.iter().find(|p| p["name"] == "Shop mill (*.ngc)").unwrap();
    assert_eq!(shop["embedded"], false);
    let out = postc_in(
        dir.path(),
        Some(posts.to_str().unwrap()),
        &["post", "--post", "shop mill", toolpath.to_str().unwrap()],
    );
    assert!(out.status.success(), "{}", said(&out));
    // From `[posts] dirs` of postc.toml, relative to its folder; and as an argument.
    std::fs::write(dir.path().join("postc.toml"), "[posts]\ndirs = [\"my posts\"]\n").unwrap();
    let out = postc_in(dir.path(), None, &["posts"]);
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains("Shop mill (*.ngc)") && table.contains("  error: PP"), "{table}");
    std::fs::remove_file(dir.path().join("postc.toml")).unwrap();
    let out = postc_in(dir.path(), None, &["posts", posts.to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("Shop mill (*.ngc)"), "{}", said(&out));
    // A folder that does not exist is said, after the listing.
    let out = postc_in(dir.path(), None, &["posts", "no such folder"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(said(&out).contains("IO001") && said(&out).contains("LinuxCNC (mm)"), "{}", said(&out));
}

/// A folder of real posts lists whole and clean: the corpus's Vectric
/// posts, one of which reads the post beside it (`POST_BASE`), and its
/// CIMCO posts, each named by `PostInfo.title` or its file.
#[test]
fn the_corpus_folders_list_clean() {
    let dir = tempfile::tempdir().unwrap();
    for (folder, ext) in [("vectric", "pp"), ("cimco", "js"), ("vcpost", "VcPost")] {
        let path = corpus().join("posts").join(folder);
        let out = postc_in(dir.path(), None, &["posts", "--format", "json", path.to_str().unwrap()]);
        assert!(out.status.success(), "{}", said(&out));
        let listed: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let users: Vec<&serde_json::Value> =
            listed.as_array().unwrap().iter().filter(|p| p["embedded"] == false).collect();
        assert_eq!(users.len(), crate::support::files(&path, ext).len(), "{folder}");
        for p in users {
            assert!(p["error"].is_null() && p["dialect"].is_string(), "{p}");
        }
    }
}

/// Fusion posts are named by their `description` and write their
/// `extension` (docs/fusion.md, choice 23): real posts of the shared corpus.
#[test]
fn fusion_posts_are_named_by_their_description() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/fusion/85vmh__LinuxCNCFusionPosts");
    if !folder.is_dir() {
        crate::support::referee_missing("fusion_posts_are_named_by_their_description", "../shared/corpus/fusion");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = postc_in(dir.path(), None, &["posts", "--format", "json", folder.to_str().unwrap()]);
    assert!(out.status.success(), "{}", said(&out));
    let listed: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mill = listed.as_array().unwrap().iter().find(|p| p["path"].as_str().unwrap().ends_with("linuxcnc_mill.cps"));
    let mill = mill.unwrap();
    assert_eq!(mill["name"], "LinuxCNC - with optional 4th axis");
    assert_eq!(mill["dialect"], "fusion");
    assert_eq!(mill["extension"], "ngc");
    assert_eq!(mill["units"], "toolpath's", "a Fusion post writes the toolpath's units");
}

#[test]
fn two_posts_of_one_name_are_an_error_with_both_paths() {
    let dir = tempfile::tempdir().unwrap();
    let posts = user_folder(dir.path());
    std::fs::copy(corpus().join("posts/library/grbl.pp"), posts.join("my_grbl.pp")).unwrap();
    let toolpath = corpus().join("toolpaths/standard.ron");
    let out = postc_in(
        dir.path(),
        Some(posts.to_str().unwrap()),
        &["post", "--post", "grbl (mm)", toolpath.to_str().unwrap()],
    );
    assert_eq!(out.status.code(), Some(1));
    let text = said(&out);
    assert!(text.contains("IO014") && text.contains("<embedded>/grbl.pp") && text.contains("my_grbl.pp"), "{text}");
}
