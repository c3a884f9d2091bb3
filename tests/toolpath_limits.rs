//! What the command line does with toolpaths a machine cannot run or that
//! were cut short: `GOTO/1e308,5,0` is refused at its line (it posted as a
//! 309-digit X word), `postc verify` flags such a word, and a toolpath
//! without its end record (FINI, End) posts with a warning that it may be
//! cut short, which `postc check` gives too.

use crate::support::{postc, said as text};

#[test]
fn a_coordinate_no_machine_reaches_is_refused_at_its_record() {
    let dir = tempfile::tempdir().unwrap();
    let cl = dir.path().join("far.cl");
    std::fs::write(&cl, "UNITS/MM\nLOADTL/1\nFEDRAT/100,MMPM\nGOTO/1e308,5,0\nFINI\n").unwrap();
    let out = dir.path().join("far.nc");
    for post in ["corpus/posts/cimco/haas_field.js", "corpus/posts/vectric/gcode_mm.pp"] {
        let o = postc(&["post", post, cl.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(1), "{post}: {}", text(&o));
        assert!(text(&o).contains("error[CL023]") && text(&o).contains("far.cl:4:1"), "{post}: {}", text(&o));
        assert!(!out.exists(), "{post}: a program was written");
    }
    let o = postc(&["check", cl.to_str().unwrap(), "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let found: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let d = found.as_array().unwrap().iter().find(|d| d["code"] == "CL023").expect("CL023");
    assert_eq!((d["line"].as_u64(), d["severity"].as_str()), (Some(4), Some("error")));
}

/// The program `GOTO/1e308,5,0` posted as before the readers refused it:
/// verify flags the word, for the generic controller too.
#[test]
fn verify_flags_the_309_digit_word() {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = dir.path().join("near.cl");
    std::fs::write(&toolpath, "UNITS/MM\nLOADTL/1\nFEDRAT/100,MMPM\nGOTO/1,5,0\nFINI\n").unwrap();
    let program = dir.path().join("far.nc");
    std::fs::write(&program, format!("G21 G90\nT1 M6\nS1000 M3\nG1 X1{} Y5. Z0. F100.\nM30\n", "0".repeat(308)))
        .unwrap();
    for controller in ["generic", "linuxcnc", "fanuc", "haas", "grbl"] {
        let o = postc(&[
            "verify",
            program.to_str().unwrap(),
            "--toolpath",
            toolpath.to_str().unwrap(),
            "--controller",
            controller,
            "--format",
            "json",
        ]);
        assert_eq!(o.status.code(), Some(1), "{controller}: {}", text(&o));
        let found: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let d = found.as_array().unwrap().iter().find(|d| d["code"] == "VF043");
        assert_eq!(d.and_then(|d| d["line"].as_u64()), Some(4), "{controller}: {}", text(&o));
    }
}

/// The first 50 lines of a long JSON Lines toolpath, and a CL file cut
/// inside a GOTO: each posts (a warning does not stop it) with the warning
/// that it may be cut short, and `postc check` says so.
#[test]
fn a_toolpath_without_its_end_record_may_be_cut_short() {
    let dir = tempfile::tempdir().unwrap();
    let long = dir.path().join("long.jsonl");
    let o = postc(&["toolpath", "gen", "--pattern", "mixed", "--moves", "100000", "-o", long.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o));
    let whole = std::fs::read_to_string(&long).unwrap();
    assert!(whole.lines().count() > 100_000, "a long toolpath");
    let head: String = whole.lines().take(50).map(|l| format!("{l}\n")).collect();
    let cut = dir.path().join("cut.jsonl");
    std::fs::write(&cut, head).unwrap();
    let cl = dir.path().join("cut.cl");
    std::fs::write(&cl, "UNITS/MM\nLOADTL/1\nFEDRAT/100,MMPM\nGOTO/0,0,5\nGOTO/7.0000000000, -2.9062500000, 3.24")
        .unwrap();
    for (toolpath, code, line) in [(&cut, "TP005", "cut.jsonl:51:1"), (&cl, "CL024", "cut.cl:5:")] {
        let out = dir.path().join("out.nc");
        let o = postc(&[
            "post",
            "corpus/posts/vectric/gcode_mm.pp",
            toolpath.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", text(&o));
        let said = text(&o);
        assert!(said.contains(&format!("warning[{code}]")) && said.contains("may be cut short"), "{said}");
        assert!(said.contains(line), "{said}");
        let o = postc(&["check", toolpath.to_str().unwrap()]);
        assert!(text(&o).contains(&format!("warning[{code}]")), "{}", text(&o));
    }
    // The whole file has its End: no warning.
    let o = postc(&["check", long.to_str().unwrap()]);
    assert!(o.status.success() && !text(&o).contains("TP005"), "{}", text(&o));
}
