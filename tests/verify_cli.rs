//! The `postc verify` command line and `postc post --verify`: exit status,
//! human and JSON findings, refusal of other output families.

use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

use crate::support::{postc, said as text};

#[test]
fn a_golden_program_verifies_against_its_toolpath() {
    let o = postc(&[
        "verify",
        "corpus/expected/gcode_mm__standard.ngc",
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
    let program = std::fs::read_to_string(root().join("corpus/expected/gcode_mm__standard.ngc")).unwrap();
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
        ("corpus/expected/hpgl_arcs__standard.plt", "corpus/toolpaths/standard.ron"),
        ("corpus/expected/shopbot_inch__standard.sbp", "corpus/toolpaths/standard.ron"),
        ("corpus/expected/heidenhain_mm__standard.h", "corpus/toolpaths/standard.ron"),
    ] {
        let o = postc(&["verify", program, "--toolpath", toolpath]);
        assert_eq!(o.status.code(), Some(1), "{}", text(&o));
        assert!(text(&o).contains("VF001") && text(&o).contains("verify reads G-code"), "{}", text(&o));
    }
    // By the post, too.
    let o = postc(&[
        "verify",
        "corpus/expected/gcode_mm__standard.ngc",
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
        "corpus/expected/gcode_mm__standard.ngc",
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

#[test]
fn post_with_verify_checks_what_it_wrote() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.ngc");
    let o = postc(&[
        "post",
        "corpus/posts/vectric/gcode_mm.pp",
        "corpus/toolpaths/standard.ron",
        "-o",
        out.to_str().unwrap(),
        "--verify",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("postc verify"), "{}", text(&o));
    // A post that drops the spindle: the program is written, verify fails.
    let bad = std::fs::read_to_string(root().join("corpus/posts/vectric/gcode_noarcs_mm.pp")).unwrap();
    let post = dir.path().join("noarcs.pp");
    std::fs::write(&post, bad).unwrap();
    let o = postc(&[
        "post",
        post.to_str().unwrap(),
        "corpus/toolpaths/standard.ron",
        "-o",
        out.to_str().unwrap(),
        "--verify",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert!(text(&o).contains("VF035"), "{}", text(&o));
    // --verify needs -o.
    let o = postc(&["post", "corpus/posts/vectric/gcode_mm.pp", "corpus/toolpaths/standard.ron", "--verify"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("IO007"), "{}", text(&o));
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
