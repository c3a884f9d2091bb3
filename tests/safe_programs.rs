//! Safe programs, end to end through the command line: what `postc post`
//! writes for a job that lacks values a post prints (no tool, no home, no
//! material), and what it says about toolpath events the post cannot
//! write. The programs are read by LinuxCNC's `rs274` where it is
//! installed.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::rs274;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn shared(rel: &str) -> PathBuf {
    root().join("../shared/corpus").join(rel)
}

fn postc(args: &[&Path]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_postc"))
        .arg("post")
        .args(args)
        .env("SOURCE_DATE_EPOCH", "0")
        .output()
        .expect("postc runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The program's lines that hold an address letter with no number after it
/// (`T M6`, `G43 H`, `TM6`), comments left aside.
fn bare_addresses(program: &str) -> Vec<String> {
    program
        .lines()
        .filter(|line| {
            let code = line.split(['(', ';']).next().unwrap_or("").as_bytes();
            code.iter().enumerate().any(|(i, b)| {
                b.is_ascii_alphabetic() && !code.get(i + 1).is_some_and(|n| n.is_ascii_digit() || b"+-.".contains(n))
            })
        })
        .map(str::to_string)
        .collect()
}

/// rs274 reads the program with no error (when it is installed).
fn rs274_reads(program: &str) {
    if let Some(rs274) = rs274::find() {
        rs274::run(&rs274, program).unwrap_or_else(|e| panic!("rs274 refuses the program: {e}\n{program}"));
    }
}

#[test]
fn the_default_post_writes_a_correct_program_for_a_job_with_no_tool() {
    let dir = tempfile::tempdir().unwrap();
    let empty = dir.path().join("empty.apt");
    std::fs::write(&empty, "").unwrap();
    let out = postc(&[&empty]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let program = text(&out.stdout);
    assert_eq!(bare_addresses(&program), Vec::<String>::new(), "{program}");
    assert!(!program.contains("(  )") && !program.contains("( tools:  )"), "empty header comments:\n{program}");
    rs274_reads(&program);
    // The tool lines left out are named, each at its post line.
    let stderr = text(&out.stderr);
    assert!(stderr.contains("RT033") && stderr.contains("\"T[T] M6\"") && stderr.contains("\"G43 H[T]\""), "{stderr}");
}

#[test]
fn the_header_waits_for_the_first_tool_of_a_cl_file() {
    // boss.apt writes an INSERT before its LOAD/TOOL: the header still
    // loads tool 1 and starts the spindle at the CL file's speed.
    let boss = shared("apt/aamorim1913__AptPostProcessor/boss.apt");
    if !boss.is_file() {
        assert!(std::env::var_os("CI").is_none(), "../shared is missing under CI");
        return;
    }
    let carvera = shared("vectric/MakeraInc__CarveraProfiles/Carvera ATC (mm) (!.cnc).pp");
    for (post, tool, spindle) in [(None, "T1 M6", "S12000 M3"), (Some(carvera.as_path()), "T1M6", "S12000M3")] {
        let out = match post {
            Some(p) => postc(&[p, &boss]),
            None => postc(&[&boss]),
        };
        assert!(out.status.success(), "{}", text(&out.stderr));
        let program = text(&out.stdout);
        let first_move = program.lines().position(|l| l.starts_with("G0X")).expect("a move");
        let head: Vec<&str> = program.lines().take(first_move).collect();
        assert!(head.contains(&tool) && head.contains(&spindle), "{post:?}:\n{program}");
        assert!(!program.lines().any(|l| l == "T M6" || l == "TM6" || l.starts_with("S0")), "{program}");
        // The CL file's INSERTs are its own verbatim text, not G-code.
        let gcode: Vec<&str> =
            program.lines().filter(|l| !l.starts_with("[HOLDER=") && !l.starts_with("Stock Size")).collect();
        rs274_reads(&gcode.join("\n"));
    }
}

#[test]
fn a_letter_printed_with_no_value_is_a_warning_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("t.pp");
    std::fs::write(
        &post,
        "UNITS = \"MM\"\nVAR TOOL_NUMBER = [T|A||1.0]\nVAR Z_HOME_POSITION = [ZH|A|Z|1.3]\nbegin HEADER\n\"G0 Z[ZH] T[T]\"\nbegin RAPID_MOVE\n\"G0 X[X] Y[Y] Z[Z]\"\nbegin FOOTER\n\"M30\"\n",
    )
    .unwrap();
    let job = dir.path().join("j.ron");
    std::fs::write(
        &job,
        "Job(units: Mm, home: (x: 0.0, y: 0.0, z: 20.0))\nToolpathStart()\nRapid(x: 1.0, y: 2.0, z: 5.0)\nEnd\n",
    )
    .unwrap();
    let out = postc(&[&post, &job]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning[RT034]") && stderr.contains("address `T`"), "{stderr}");
    assert!(stderr.contains("t.pp:5:1"), "the warning names the post line: {stderr}");
}

#[test]
fn events_the_post_cannot_write_are_warnings_at_the_toolpath_line() {
    // haas_field.js has no onCompensation; mill.ron turns compensation on
    // at its line 13: the machine would cut one radius off the part.
    let post = root().join("corpus/posts/cimco/haas_field.js");
    let toolpath = root().join("corpus/toolpaths/cimco/mill.ron");
    let out = postc(&[&post, &toolpath]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning[RT035]") && stderr.contains("cutter compensation"), "{stderr}");
    assert!(stderr.contains("mill.ron:13:1"), "the warning names the toolpath line: {stderr}");
    // A post that writes it says nothing.
    let fanuc = root().join("corpus/posts/cimco/fanuc_mill.js");
    let out = postc(&[&fanuc, &toolpath]);
    assert!(!text(&out.stderr).contains("RT035"), "{}", text(&out.stderr));
}

#[test]
fn formatting_nan_writes_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("codes.js");
    std::fs::write(
        &post,
        "var linebreak = \"\\n\";\nvar g = createVariable({prefix: \"G\"}, createFormat({decimals: 0}));\nvar codes = {\"Drilling (G81)\": 81};\nfunction onOpen() { return \"\"; }\nfunction onLinear(x, y, z, m) { return \"\"; }\nfunction onDrillingHeader(name) {\n    return g.format(codes[name]) + \"\\n\";\n}\nfunction onDrillingPoint(x, y) { return \"\"; }\n",
    )
    .unwrap();
    let toolpath = root().join("corpus/toolpaths/drill_mm.ron");
    let program = dir.path().join("out.nc");
    let out = postc(&[&post, &toolpath, Path::new("-o"), &program]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success() && stderr.contains("error[RT032]"), "{stderr}");
    assert!(stderr.contains("codes.js:7:"), "{stderr}");
    assert!(!program.exists(), "no output is written");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1, "nothing left behind");
}
