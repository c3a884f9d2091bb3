//! The `postp` controllers side by side, and everything around the words:
//! the embedded posts and options, the same job on each controller
//! (snapshots), wrong-machine words, missing or bad MACHIN, cl.tap and
//! options files, the `postc postp DIR` and `postp DIR` command lines, and
//! the demo CL file read back by LinuxCNC's rs274.

use crate::support::postp;

use std::process::Command;

use postc_postp::{Controller, Settings};
use postp::{check, interpret, root, rs274, run, run_with};

#[test]
fn every_embedded_post_compiles_without_a_diagnostic() {
    for c in Controller::ALL {
        let mut sources = postc_report::source_map();
        let compiled =
            postc_driver::compile_post_bytes(std::path::Path::new(&c.post_name()), c.post_source(), None, &mut sources);
        assert!(compiled.diagnostics.is_empty(), "{c}: {:?}", compiled.diagnostics);
    }
}

/// A milling job that shows where the controllers differ.
const MILL_JOB: &str = "TMARK
SEQNO/10,INCR,10,1234
PARTNO Mill job
RESET
LOADTL/7,7
SPINDL/2000,RPM,CLW
ORIGIN/54.2
COOLNT/FLOOD
FEDRAT/250,MMPM
RAPID
GOTO/10,10,20
GOTO/10,10,2
CUTCOM/LEFT,7
GOTO/10,20,2
CUTCOM/OFF
DELAY/0.5
RAPID
GOTO/10,20,20
CYCLE/DRILL,RAPTO,2,FEDTO,5,MMPM,100,DWELL,1
GOTO/30,30,0
CYCLE/OFF
CYCLE/DRILL,DEEP,RAPTO,2,FEDTO,12,INCR,3,MMPM,120
GOTO/40,30,0
GOTO/50,30,0
CYCLE/OFF
OPSTOP
GOHOME
END
TMARK
FINI
";

#[test]
fn mills_differ_in_codes_comments_offsets_and_dwells() {
    let fanuc = check("mill_job", "FANUCM", MILL_JOB);
    let haas = check("mill_job", "HAASM", MILL_JOB);
    let tormach = check("mill_job", "TORMM", MILL_JOB);
    let acorn = check("mill_job", "ACORNM", MILL_JOB);
    assert!(
        fanuc.program.contains("O1234\n(Mill job)\nN10 G17 G21") && fanuc.program.contains("T07 M06"),
        "{}",
        fanuc.program
    );
    assert!(fanuc.program.contains("G04 P500") && fanuc.program.contains("G54 P2 G43 H07 X10."), "{}", fanuc.program);
    assert!(
        haas.program.contains("O01234\n(Mill job)\nN10 G00 G17") && haas.program.contains("T7 M06"),
        "{}",
        haas.program
    );
    assert!(haas.program.contains("G04 P0.5") && haas.program.contains("G154 P2 G43 H07 X10."), "{}", haas.program);
    assert!(
        tormach.program.contains("(O1234)\n(Mill job)") && tormach.program.contains("T7 M6\n"),
        "{}",
        tormach.program
    );
    assert!(
        tormach.program.contains("G4 P0.5") && tormach.program.contains("G54.1 P2 G43 H7 X10."),
        "{}",
        tormach.program
    );
    assert!(acorn.program.contains("O01234\n; Mill job") && acorn.program.contains("G41 D7 Y20."), "{}", acorn.program);
}

#[test]
fn mill_programs_read_in_rs274() {
    let Some(rs274) = rs274() else {
        println!("skipped: rs274 not found on PATH");
        return;
    };
    // Extended offsets (G54 P2, G154 P2) are not LinuxCNC's, so plain G55
    // here; and rs274's tool table has 6 inch cutters, too big for the
    // short compensated move.
    let job = MILL_JOB.replace("ORIGIN/54.2", "ORIGIN/55").replace("CUTCOM/LEFT,7\n", "").replace("CUTCOM/OFF\n", "");
    for m in ["FANUCM", "HAASM", "TORMM", "ACORNM"] {
        let r = run(m, &job);
        let (complaints, moves) = interpret(&rs274, &r.program);
        assert!(complaints.is_empty(), "{m}: {complaints:?}\n{}", r.program);
        assert!(moves > 5, "{m}");
    }
}

/// A turning job for the four lathes.
const LATHE_JOB: &str = "TMARK
SEQNO/10,INCR,10,20
PARTNO Shaft
RESET
TURRET/1
SPINDL/180,SFM,CLW
COOLNT/FLOOD
FEDRAT/0.25,MMPR
RAPID
GOTO/15,0,2
GOTO/12.5,0,0
GOTO/12.5,0,-25
CIRCLE/18.5,0,-25,0,1,0,6
GOTO/18.5,0,-31
MODE/91
GOTO/20,0,-31
MODE/90
DELAY/1
TURRET/4,14
SPINDL/500,RPM
RAPID
GOTO/7,0,3
THREAD/1.5,10.2,-18,0.3,0.05,0.05,1.5,0,60,2
COOLNT/OFF
SPINDL/OFF
GOHOME
REWIND
TMARK
FINI
";

#[test]
fn lathes_differ_in_spindle_limits_incremental_words_and_threading() {
    let fanuc = check("lathe_job", "FANUCL", LATHE_JOB);
    let haas = check("lathe_job", "HAASL", LATHE_JOB);
    let tormach = check("lathe_job", "TORML", LATHE_JOB);
    let acorn = check("lathe_job", "ACORNL", LATHE_JOB);
    assert!(
        fanuc.program.contains("G50 S3000\nN40 G96 S180 M03") && fanuc.program.contains("G01 U3. F0.25"),
        "{}",
        fanuc.program
    );
    assert!(
        fanuc.program.contains("G76 P021060 Q50 R0.05\nN") && fanuc.program.contains("G04 U1."),
        "{}",
        fanuc.program
    );
    assert!(
        haas.program.contains("G76 X10.2 Z-18. K0.9 D0.3 F1.5 A60") && haas.program.contains("G04 P1."),
        "{}",
        haas.program
    );
    assert!(tormach.program.contains("G96 D2000 S180 M3") && tormach.program.contains("G91\n"), "{}", tormach.program);
    assert!(tormach.program.contains("G76 P1.5 Z-18. I-1. J0.3 K0.9 Q30. H2 E1.5 L2"), "{}", tormach.program);
    assert!(acorn.program.contains("; Shaft") && acorn.program.contains("G4 P1."), "{}", acorn.program);
}

#[test]
fn words_on_the_wrong_machine_are_errors() {
    let cases = [
        ("FANUCM", "THREAD/1,2,3,4,5,6,7,8,9,10", "PX010"),
        ("HAASM", "TURRET/1", "PX010"),
        ("TORMM", "SPINDL/200,SFM", "PX010"),
        ("FANUCL", "LOADTL/1", "PX011"),
        ("HAASL", "LETTER/0,0,0,1,0,1,1,1,1,1,1", "PX011"),
        ("TORML", "RETRCT", "PX011"),
        ("ACORNL", "ROTABL/AAXIS,ATANGL,90", "PX011"),
        ("FANUCL", "CYCLE/DRILL,5,MMPM,100,2,20\nGOTO/0,0,0\nCYCLE/OFF", "PX011"),
        ("FANUCM", "ROTABL/AAXIS,ATANGL,90", "PX020"),
    ];
    for (m, body, code) in cases {
        let r = run(m, &format!("{body}\n"));
        assert!(!r.ok && r.has(code), "{m} {body}: {:?}", r.diagnostics);
        assert!(r.program.is_empty());
    }
}

#[test]
fn bad_arguments_have_a_code() {
    for body in
        ["AUXFUN/NOW", "MODE/92", "ORIGIN/61", "SEQNO/10,10", "TMARK/300", "TRANS/A", "ROTABL/AAXIS,90", "DELETE/MAYBE"]
    {
        let r = run_with(&format!("MACHIN/FANUCM,1\n{body}\n"), None, None);
        assert!(!r.ok && r.has("PX012"), "{body}: {:?}", r.diagnostics);
    }
}

#[test]
fn machin_is_required_known_and_first() {
    let r = run_with("PARTNO NONE\nGOTO/1,1,1\n", None, None);
    assert!(!r.ok && r.has("PX002"), "{:?}", r.diagnostics);
    let r = run_with("MACHIN/OKUMA\nGOTO/1,1,1\n", None, None);
    assert!(!r.ok && r.has("PX003"), "{:?}", r.diagnostics);
    let r = run_with("MACHIN/FANUCL,1\nGOTO/1,1,1\n", None, None);
    assert!(!r.ok && r.has("PX004"), "{:?}", r.diagnostics);
    let r = run_with("PARTNO LATE\nMACHIN/fanucm\nFEDRAT/100\nGOTO/1,1,1\n", None, None);
    assert!(r.ok && r.has("PX013"), "{:?}", r.diagnostics);
    let r = postp::run_file(std::path::Path::new("/nonexistent/cl.tap"), Settings::default());
    assert!(!r.ok && r.has("PX001"), "{:?}", r.diagnostics);
}

#[test]
fn an_options_file_replaces_the_fields_it_gives() {
    let options = "(end: \"M30\\nM99\", sequence: On(start: 100, increment: 5), retractz: At(50), decimals: 2)";
    let cl = "MACHIN/FANUCM\nUNITS/MM\nFEDRAT/100\nGOTO/1.2345,0,1\nRETRCT\nEND\n";
    let r = run_with(cl, Some(options), None);
    assert_eq!(r.program, "N100 G01 X1.23 Y0. Z1. F100.\nN105 G00 Z50.\nN110 M30\nN115 M99\n");
    let r = run_with(cl, Some("(ends: \"M30\")"), None);
    assert!(!r.ok && r.has("PX005"), "{:?}", r.diagnostics);
}

#[test]
fn the_machine_can_be_forced() {
    let path = root().join("corpus/toolpaths/apt/postp_demo.apt");
    let r = postp::run_file(&path, Settings { machine: Some(Controller::TormM), ..Settings::default() });
    assert!(r.ok && r.program.contains("T1 M6"), "{:?}", r.diagnostics);
}

fn demo_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(root().join("corpus/toolpaths/apt/postp_demo.apt"), dir.path().join("cl.tap")).unwrap();
    dir
}

#[test]
fn postc_postp_dir_prints_the_demo_as_a_fanuc_program_that_rs274_reads() {
    let dir = demo_dir();
    let out = Command::new(env!("CARGO_BIN_EXE_postc")).arg("postp").arg(dir.path()).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let program = String::from_utf8(out.stdout).unwrap();
    assert!(program.starts_with("%\nO1001\n(POSTP DEMO PLATE)\nN10 G17 G21 G40 G49 G80 G90\n"), "{program}");
    assert!(program.ends_with("M30\n%\n"), "{program}");
    match rs274() {
        Some(rs274) => {
            let (complaints, moves) = interpret(&rs274, &program);
            assert!(complaints.is_empty(), "{complaints:?}");
            assert!(moves > 50);
        }
        None => println!("skipped the rs274 check: rs274 not found on PATH"),
    }
}

#[test]
fn postc_postp_o_writes_what_it_prints_and_says_so() {
    let dir = demo_dir();
    let printed = Command::new(env!("CARGO_BIN_EXE_postc")).arg("postp").arg(dir.path()).output().unwrap();
    let out = dir.path().join("demo.nc");
    let wrote =
        Command::new(env!("CARGO_BIN_EXE_postc")).arg("postp").arg(dir.path()).arg("-o").arg(&out).output().unwrap();
    let said = String::from_utf8_lossy(&wrote.stderr);
    assert!(wrote.status.success() && wrote.stdout.is_empty(), "{said}");
    assert!(said.starts_with(&format!("postc: wrote {} (", out.display())), "{said}");
    assert_eq!(std::fs::read(&out).unwrap(), printed.stdout);
    // The CL file is an input: `-o` naming it is refused and it is kept.
    let cl = dir.path().join("cl.tap");
    let before = std::fs::read(&cl).unwrap();
    let refused =
        Command::new(env!("CARGO_BIN_EXE_postc")).arg("postp").arg(dir.path()).arg("-o").arg(&cl).output().unwrap();
    assert_eq!(refused.status.code(), Some(1), "{}", String::from_utf8_lossy(&refused.stderr));
    assert_eq!(std::fs::read(&cl).unwrap(), before);
}

#[test]
fn invoked_as_postp_the_binary_takes_dir_alone() {
    let dir = demo_dir();
    let bin = tempfile::tempdir().unwrap();
    let postp = bin.path().join(if cfg!(windows) { "postp.exe" } else { "postp" });
    // A symlink, not a copy: executing a just-written copy races with other
    // tests' forks (ETXTBSY).
    #[cfg(unix)]
    std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_postc"), &postp).unwrap();
    #[cfg(not(unix))]
    std::fs::copy(env!("CARGO_BIN_EXE_postc"), &postp).unwrap();
    let out = Command::new(&postp).arg(dir.path()).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("%\nO1001\n"));
    // A folder without cl.tap: a diagnostic with its code, nothing on stdout, exit 1.
    let empty = tempfile::tempdir().unwrap();
    let out = Command::new(&postp).arg(empty.path()).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("PX001"));
}

#[test]
fn the_options_example_in_docs_apt_md_reads() {
    let doc = std::fs::read_to_string(root().join("docs/apt.md")).unwrap();
    let start = doc.find("```ron\n").expect("an options example") + 7;
    let end = start + doc[start..].find("```").unwrap();
    let patch = postc_postp::Patch::parse(&doc[start..end]).unwrap();
    assert!(patch.is_complete());
    let fanuc = postc_postp::Patch::parse(Controller::FanucM.default_options()).unwrap();
    assert_eq!(patch, fanuc, "the example is FANUCM's file");
}
