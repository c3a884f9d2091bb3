//! The `postc verify` command line, and `postc post` verifying what it
//! writes (by default; `--no-verify`): exit status, human and JSON
//! findings, severities the user sets, refusal of other output families.

use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

use crate::support::{postc, said as text};

#[test]
fn a_golden_program_verifies_against_its_toolpath() {
    let o = postc(&[
        "verify",
        "corpus/expected/vectric/gcode_mm__standard.ngc",
        "--toolpath",
        "corpus/toolpaths/standard.ron",
        "--post",
        "corpus/posts/vectric/gcode_mm.pp",
        "--controller",
        "linuxcnc",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("0 error(s), 0 warning(s)"), "{}", text(&o));
}

#[test]
fn a_wrong_program_exits_1_with_json_findings_at_their_line() {
    let dir = tempfile::tempdir().unwrap();
    let program = std::fs::read_to_string(root().join("corpus/expected/vectric/gcode_mm__standard.ngc")).unwrap();
    // The first arc turns the other way.
    let wrong = program.replacen("G3X80.000", "G2X80.000", 1);
    let line = wrong.lines().position(|l| l.starts_with("G2X80.000")).unwrap() + 1;
    let path = dir.path().join("wrong.ngc");
    std::fs::write(&path, wrong).unwrap();
    let o =
        postc(&["verify", path.to_str().unwrap(), "--toolpath", "corpus/toolpaths/standard.ron", "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let findings: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let arc = findings.as_array().unwrap().iter().find(|f| f["code"] == "VF013").expect("a VF013 finding");
    assert_eq!(arc["line"], line);
    assert_eq!(arc["column"], 1);
    assert_eq!(arc["severity"], "error");
}

#[test]
fn other_families_are_refused_with_the_families_verify_reads() {
    for (program, toolpath) in [
        ("corpus/expected/vectric/hpgl_arcs__standard.plt", "corpus/toolpaths/standard.ron"),
        ("corpus/expected/vectric/shopbot_inch__standard.sbp", "corpus/toolpaths/standard.ron"),
        ("corpus/expected/vectric/heidenhain_mm__standard.h", "corpus/toolpaths/standard.ron"),
    ] {
        let o = postc(&["verify", program, "--toolpath", toolpath]);
        assert_eq!(o.status.code(), Some(1), "{}", text(&o));
        assert!(text(&o).contains("VF001") && text(&o).contains("verify reads G-code"), "{}", text(&o));
    }
    // By the post, too.
    let o = postc(&[
        "verify",
        "corpus/expected/vectric/gcode_mm__standard.ngc",
        "--toolpath",
        "corpus/toolpaths/standard.ron",
        "--post",
        "corpus/posts/vectric/hpgl_arcs.pp",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("VF001"), "{}", text(&o));
    // Rotary-wrapped posts are refused.
    let o = postc(&[
        "verify",
        "corpus/expected/vectric/gcode_mm__standard.ngc",
        "--toolpath",
        "corpus/toolpaths/standard.ron",
        "--post",
        "corpus/posts/vectric/rotary_wrap_mm.pp",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("VF006"), "{}", text(&o));
}

#[test]
fn binary_and_missing_programs_are_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("blob.ngc");
    std::fs::write(&path, [0u8, 159, 146, 150, 0, 1, 2, 3].repeat(100)).unwrap();
    let o = postc(&["verify", path.to_str().unwrap(), "--toolpath", "corpus/toolpaths/standard.ron"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("VF002"), "{}", text(&o));
    let o = postc(&["verify", "no/such.ngc", "--toolpath", "corpus/toolpaths/standard.ron"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("IO001"), "{}", text(&o));
}

/// A drilling fault: the canned cycle of `fanuc_mill.js` with its Z and R
/// words swapped, so each hole is drilled to the R plane and the tool
/// rapids down to the hole's bottom. `postc post` verifies the program it
/// writes by default, finds the rapids into the material (VF012, VF037)
/// and writes nothing.
fn drilling_fault(dir: &std::path::Path) -> PathBuf {
    let post = std::fs::read_to_string(root().join("corpus/posts/cimco/fanuc_mill.js")).unwrap();
    let right = r#"+ " Z" + xyzFormat.format(holeBottom()) + " R" + xyzFormat.format(rPlane());"#;
    let swapped = r#"+ " Z" + xyzFormat.format(rPlane()) + " R" + xyzFormat.format(holeBottom());"#;
    assert!(post.contains(right), "the cycle block of fanuc_mill.js changed");
    let path = dir.join("swapped_zr.js");
    std::fs::write(&path, post.replace(right, swapped)).unwrap();
    path
}

const DRILL: &str = "corpus/toolpaths/cimco/drill.ron";

/// A folder holding the drilling fault's post, that post and the program's path there.
fn faulty_job() -> (tempfile::TempDir, String, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let post = drilling_fault(dir.path()).to_str().unwrap().to_string();
    let out = dir.path().join("holes.nc");
    (dir, post, out)
}

fn errors_of(o: &std::process::Output) -> Vec<String> {
    let stderr = String::from_utf8_lossy(&o.stderr);
    let mut codes: Vec<String> = stderr
        .lines()
        .filter_map(|l| l.strip_prefix("error["))
        .filter_map(|l| l.split(']').next())
        .map(String::from)
        .collect();
    codes.sort();
    codes.dedup();
    codes
}

#[test]
fn post_verifies_by_default_and_writes_nothing_when_verify_finds_an_error() {
    let (_dir, post, out) = faulty_job();
    let (post, out_s) = (post.as_str(), out.to_str().unwrap());
    // The unmodified post verifies clean: nothing printed, the file written.
    let o = postc(&["post", "corpus/posts/cimco/fanuc_mill.js", DRILL, "-o", out_s]);
    assert!(o.status.success(), "{}", text(&o));
    // `[VF`: a finding as rendered (`error[VF012]`), not the letters in a temporary folder's name.
    assert!(!text(&o).contains("[VF"), "{}", text(&o));
    assert!(out.is_file());
    std::fs::write(&out, "before").unwrap();

    let o = postc(&["post", post, DRILL, "-o", out_s]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert_eq!(errors_of(&o), ["VF012", "VF037"], "{}", text(&o));
    assert!(text(&o).contains("the program was not written"), "{}", text(&o));
    assert!(text(&o).contains("--no-verify"), "{}", text(&o));
    assert_eq!(std::fs::read(&out).unwrap(), b"before", "the file there before is left as it was");
    // The findings name the program's lines and show them, read back from
    // the staged file (the verify thread keeps none of the program).
    assert!(text(&o).contains("holes.nc:7:1"), "{}", text(&o));
    assert!(text(&o).contains("N50 G98 G81 X20.000 Y15.000 Z2.000 R-3.000"), "{}", text(&o));
    // To standard output: nothing at all; the lines shown from what is held back.
    let o = postc(&["post", post, DRILL]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert!(o.stdout.is_empty());
    assert!(text(&o).contains("<standard output>:7:1"), "{}", text(&o));
    assert!(text(&o).contains("N50 G98 G81 X20.000 Y15.000 Z2.000 R-3.000"), "{}", text(&o));
}

#[test]
fn no_verify_writes_the_program_and_warn_lowers_the_findings() {
    let (dir, post, out) = faulty_job();
    let (post, out_s) = (post.as_str(), out.to_str().unwrap());
    let o = postc(&["post", post, DRILL, "-o", out_s, "--no-verify"]);
    assert!(o.status.success(), "{}", text(&o));
    // `[VF`: a finding as rendered (`error[VF012]`), not the letters in a temporary folder's name.
    assert!(!text(&o).contains("[VF"), "{}", text(&o));
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(written.contains("G98 G81"), "{written}");
    // `postc verify` finds in it what `postc post` found.
    let v = postc(&["verify", out_s, "--toolpath", DRILL, "--post", post]);
    assert_eq!(v.status.code(), Some(1));
    assert_eq!(errors_of(&v), ["VF012", "VF037"], "{}", text(&v));
    std::fs::remove_file(&out).unwrap();

    // --warn lowers the findings to warnings: printed, and the program written.
    let o = postc(&["post", post, DRILL, "-o", out_s, "--warn", "VF012", "--warn", "VF037"]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("warning[VF012]") && text(&o).contains("warning[VF037]"), "{}", text(&o));
    assert!(out.is_file());
    std::fs::remove_file(&out).unwrap();
    // One lowered, the other still an error.
    let o = postc(&["post", post, DRILL, "-o", out_s, "--warn", "VF012"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert_eq!(errors_of(&o), ["VF037"], "{}", text(&o));
    assert!(!out.exists());
    // --allow hides them.
    let o = postc(&["post", post, DRILL, "-o", out_s, "--allow", "VF"]);
    assert!(o.status.success(), "{}", text(&o));
    // `[VF`: a finding as rendered (`error[VF012]`), not the letters in a temporary folder's name.
    assert!(!text(&o).contains("[VF"), "{}", text(&o));
    std::fs::remove_file(&out).unwrap();
    // postc.toml beside the post: a documented property of the post.
    std::fs::write(dir.path().join("postc.toml"), "[diagnostics]\nwarn = [\"VF012\", \"VF037\"]\n").unwrap();
    let o = postc(&["post", post, DRILL, "-o", out_s]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("warning[VF037]"), "{}", text(&o));
}

#[test]
fn deny_makes_a_verification_warning_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("laser.ngc");
    let out_s = out.to_str().unwrap();
    // A milling post with no JET_TOOL_ON section over the job's laser
    // toolpath: the jet cuts are a warning (the post cannot switch a jet on).
    let args = ["post", "corpus/posts/vectric/gcode_noarcs_mm.pp", "corpus/toolpaths/standard.ron", "-o", out_s];
    let o = postc(&args);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("warning[VF035]") && text(&o).contains("no JET_TOOL_ON section"), "{}", text(&o));
    std::fs::remove_file(&out).unwrap();
    for deny in ["VF035", "VF", "all"] {
        let o = postc(&[&args[..], &["--deny", deny]].concat());
        assert_eq!(o.status.code(), Some(1), "--deny {deny}: {}", text(&o));
        assert!(text(&o).contains("error[VF035]"), "{}", text(&o));
        assert!(!out.exists());
    }
    // --verify adds verify's summary line.
    let o = postc(&[&args[..], &["--verify"]].concat());
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("postc verify: `") && text(&o).contains("1 warning(s)"), "{}", text(&o));
    let o = postc(&[&args[..], &["--verify", "--no-verify"]].concat());
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
}

#[test]
fn what_post_cannot_verify_it_says_in_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&[&str], &str); 5] = [
        (&["corpus/posts/vectric/hpgl_arcs.pp", "corpus/toolpaths/standard.ron"], "HPGL"),
        (&["corpus/posts/vectric/shopbot_inch.pp", "corpus/toolpaths/standard.ron"], "ShopBot"),
        (&["corpus/posts/cimco/heidenhain.js", DRILL], "Heidenhain conversational"),
        (&["corpus/posts/vectric/rotary_wrap_mm.pp", "corpus/toolpaths/rotary_mm.ron"], "rotary"),
        (&["corpus/posts/vcpost/siemens_probe.VcPost", "corpus/probe/siemens_probe__housing.csv"], "probe table"),
    ];
    for (i, (inputs, why)) in cases.iter().enumerate() {
        let out = dir.path().join(format!("out{i}.txt"));
        let args = [&["post"], *inputs, &["-o", out.to_str().unwrap()]].concat();
        let o = postc(&args);
        assert!(o.status.success(), "{inputs:?}: {}", text(&o));
        assert!(text(&o).contains("note[VF044]") && text(&o).contains("was not verified"), "{inputs:?}: {}", text(&o));
        assert!(text(&o).contains(why), "{inputs:?}: {}", text(&o));
        assert!(out.is_file(), "{inputs:?}");
        // --no-verify: no note.
        let o = postc(&[&args[..], &["--no-verify"]].concat());
        assert!(o.status.success() && !text(&o).contains("VF044"), "{inputs:?}: {}", text(&o));
    }
    // Text output that is not a G-code program, found by reading it.
    let out = dir.path().join("text.txt");
    let o = postc(&[
        "post",
        "corpus/posts/vectric/text_output_mm.pp",
        "corpus/toolpaths/standard.ron",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("note[VF044]") && text(&o).contains("do not read as G-code"), "{}", text(&o));
    // --deny VF044: a program that cannot be verified is not written.
    std::fs::remove_file(&out).unwrap();
    let o = postc(&[
        "post",
        "corpus/posts/vectric/hpgl_arcs.pp",
        "corpus/toolpaths/standard.ron",
        "-o",
        out.to_str().unwrap(),
        "--deny",
        "VF044",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert!(text(&o).contains("error[VF044]"), "{}", text(&o));
    assert!(!out.exists());
}

/// A post that writes nothing for the toolpath's moves: verification does
/// not keep the events waiting for program text without end; it stops,
/// and the program, which makes none of those moves, is not written.
#[test]
fn a_post_that_writes_nothing_for_its_moves_stops_verification() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("silent.pp");
    std::fs::write(&post, "POST_NAME = \"silent\"\nUNITS = \"MM\"\nbegin HEADER\n\"G21 G90\"\nbegin FOOTER\n\"M30\"\n")
        .unwrap();
    let toolpath = dir.path().join("moves.jsonl");
    let o = postc(&["toolpath", "gen", "--moves", "80000", "-o", toolpath.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o));
    let out = dir.path().join("silent.nc");
    let o = postc(&["post", post.to_str().unwrap(), toolpath.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert!(
        text(&o).contains("error[VF011]") && text(&o).contains("wrote nothing for 65536 toolpath events"),
        "{}",
        text(&o)
    );
    assert!(!out.exists());
}

/// Every post of the project's corpus posts every toolpath its goldens
/// are made from with `postc post` as a user runs it, verification on:
/// none is refused but the programs [`REFUSED`] lists with their reason.
/// Programs verify refuses, each for a fault of the program: the guide's
/// 25-line "G-Code Arcs (inch)" post prints the spindle speed only in its
/// header, which a job that starts with a laser (`tools_inch.ron`) prints
/// as `S0 M3`: the end mill of the next toolpath then cuts at 0 rpm
/// (VF035); the post has no TOOLCHANGE section to start it at 14000.
const REFUSED: &[(&str, &str, &str)] =
    &[("corpus/posts/vectric/gcode_arcs_inch.pp", "corpus/toolpaths/tools_inch.ron", "error[VF035]")];

#[test]
fn every_corpus_post_still_posts_its_toolpaths_with_verification() {
    let dir = tempfile::tempdir().unwrap();
    let files = |dir: &str, ext: &str| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|e| e == ext))
            .map(|p| p.strip_prefix(root()).unwrap().display().to_string())
            .collect();
        v.sort();
        v
    };
    let vectric = files("corpus/toolpaths", "ron");
    let cimco: Vec<String> =
        ["cimco/mill.ron", "cimco/drill.ron", "standard.ron"].iter().map(|t| format!("corpus/toolpaths/{t}")).collect();
    let mut vcpost = vectric.clone();
    vcpost.extend(files("corpus/toolpaths/vcpost", "ron"));
    let mut jobs: Vec<(String, &Vec<String>)> = Vec::new();
    jobs.extend(files("corpus/posts/vectric", "pp").into_iter().map(|p| (p, &vectric)));
    jobs.extend(files("corpus/posts/cimco", "js").into_iter().map(|p| (p, &cimco)));
    jobs.extend(files("corpus/posts/cimco-styles", "js").into_iter().map(|p| (p, &cimco)));
    jobs.push(("corpus/posts/vcpost/fanuc_mill.VcPost".into(), &vcpost));
    let (mut runs, mut warned, mut not_posted, mut failures) = (0, 0, 0, Vec::new());
    for (post, toolpaths) in &jobs {
        for toolpath in toolpaths.iter() {
            let run = dir.path().join(format!("run{runs}"));
            std::fs::create_dir(&run).unwrap();
            let out = run.join("out.nc");
            let args = ["post", post.as_str(), toolpath.as_str(), "-o", out.to_str().unwrap()];
            let o = postc(&args);
            runs += 1;
            // What postc does not post (yet) whatever verify finds is not counted.
            if !o.status.success() && !postc(&[&args[..], &["--no-verify"]].concat()).status.success() {
                not_posted += 1;
                continue;
            }
            // The program is written: as `out.nc`, or as its tape-split parts.
            let written = std::fs::read_dir(&run).unwrap().count();
            let refused = REFUSED.iter().any(|(p, t, code)| p == post && t == toolpath && text(&o).contains(code));
            if (!o.status.success() || written == 0) && !refused {
                failures.push(format!("{post} over {toolpath}:\n{}", text(&o)));
            }
            warned += usize::from(text(&o).contains("warning[VF"));
        }
    }
    println!("{runs} posts, {warned} with verification warnings, {not_posted} postc does not post");
    assert!(runs - not_posted >= 140, "only {} runs posted", runs - not_posted);
    assert!(failures.is_empty(), "{} refused:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn postp_programs_verify_against_their_cl_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(root().join("corpus/toolpaths/apt/postp_demo.apt"), dir.path().join("cl.tap")).unwrap();
    let o = postc(&["postp", dir.path().to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o));
    let program = dir.path().join("out.nc");
    std::fs::write(&program, &o.stdout).unwrap();
    let cl = dir.path().join("cl.tap");
    let o = postc(&[
        "verify",
        program.to_str().unwrap(),
        "--toolpath",
        cl.to_str().unwrap(),
        "--postp",
        "--controller",
        "fanuc",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("0 error(s)"), "{}", text(&o));
}
