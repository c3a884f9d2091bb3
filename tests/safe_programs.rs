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
    // Dem-target1.apt writes an INSERT before its LOAD/TOOL: the header
    // still loads tool 14 and starts the spindle at the CL file's speed.
    let boss = shared("apt/aamorim1913__AptPostProcessor/Dem-target1.apt");
    if !boss.is_file() {
        assert!(std::env::var_os("CI").is_none(), "../shared is missing under CI");
        return;
    }
    let carvera = shared("vectric/MakeraInc__CarveraProfiles/Carvera ATC (mm) (!.cnc).pp");
    // The Carvera's tool change goes home with `G0[ZH]`, which this job (no
    // home) leaves out (RT033): verify finds M6 with the tool down (VF038).
    // The Carvera's own M6 macro raises Z, a property of the machine the
    // user states by lowering the finding.
    let warn = [Path::new("--warn"), Path::new("VF038")];
    for (post, tool, spindle) in [(None, "T14 M6", "S12000 M3"), (Some(carvera.as_path()), "T14M6", "S12000M3")] {
        let out = match post {
            Some(p) => postc(&[p, &boss, warn[0], warn[1]]),
            None => postc(&[&boss]),
        };
        assert!(out.status.success(), "{}", text(&out.stderr));
        // The CL file's INSERTs do not read as G-code: warnings, as the toolpath's own text.
        assert!(text(&out.stderr).contains("warning[VF004]: this line is text the toolpath inserts"));
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
    let out = postc(&[&post, &job, Path::new("--no-verify")]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning[RT034]") && stderr.contains("address `T`"), "{stderr}");
    assert!(stderr.contains("t.pp:5:1"), "the warning names the post line: {stderr}");
    // Verified, as by default, the program (`G0 ZZ20.000 T`) is refused:
    // the warning is still printed at the post's line.
    let out = postc(&[&post, &job]);
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[VF004]") && stderr.contains("t.pp:5:1"), "{stderr}");
    assert!(out.stdout.is_empty());
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

/// Posts `toolpath` (through `post`, or the embedded default post) to
/// `out` and asserts that it is refused: exit 1, the `error[CODE]` with
/// `what` in its message, naming `at` (FILE:LINE:COLUMN of the toolpath
/// record or of the program line), and no file written.
fn assert_refused(post: Option<&Path>, toolpath: &Path, out: &Path, code: &str, what: &str, at: &str) {
    let o = match post {
        Some(p) => postc(&[p, toolpath, Path::new("-o"), out]),
        None => postc(&[toolpath, Path::new("-o"), out]),
    };
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{post:?}: {stderr}");
    assert!(stderr.contains(&format!("error[{code}]")) && stderr.contains(what), "{stderr}");
    assert!(stderr.contains(at), "the error names {at}: {stderr}");
    assert!(!out.exists());
}

/// A CL file's move that tilts the tool (boss.apt's second setup machines
/// from the side: `GOTO/120.,24.9625,-30.35,1.,0,0`, the tool along +X)
/// is refused at its record by a post that writes X, Y and Z: posted, the
/// upright tool went sideways into the part at Z-30.35.
#[test]
fn a_move_that_tilts_the_tool_is_refused_by_a_three_axis_post() {
    let dir = tempfile::tempdir().unwrap();
    let cl = dir.path().join("tilted.apt");
    std::fs::write(
        &cl,
        "PARTNO/TILT\nUNITS/MM\nLOADTL/1\nSPINDL/RPM,1000,CLW\nFEDRAT/500\nGOTO/0,0,10,0,0,1\nGOTO/0,0,0,0,0,1\nGOTO/10,0,0,0.5,0,0.8660254\nFINI\n",
    )
    .unwrap();
    let out_file = dir.path().join("tilted.nc");
    for post in [None, Some(root().join("corpus/posts/cimco/fanuc_mill.js"))] {
        assert_refused(post.as_deref(), &cl, &out_file, "RT040", "30.0 degrees", "tilted.apt:8:1");
    }
    // Upright to within a CL file's rounding is upright.
    std::fs::write(&cl, "PARTNO/UP\nUNITS/MM\nLOADTL/1\nSPINDL/RPM,1000,CLW\nFEDRAT/500\nGOTO/0,0,10,0,0,1\nGOTO/0,0,0,0.0000001,0,0.9999999999\nFINI\n").unwrap();
    let out = postc(&[&cl, Path::new("-o"), &out_file]);
    assert!(out.status.success(), "{}", text(&out.stderr));
}

/// A move that turns a rotary axis (`"a": 90` of a native move) through a
/// post that writes no A axis is refused at its line: posted, the part
/// stayed where it was and the rest of the move was cut as if it had
/// turned. A post that prints `[A]` takes it.
#[test]
fn a_move_that_turns_an_axis_the_post_does_not_write_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let job = dir.path().join("turns.jsonl");
    std::fs::write(
        &job,
        concat!(
            "{\"Tool\":{\"number\":1,\"spindle_speed\":10000.0,\"cut_feed\":1000.0,\"plunge_feed\":300.0}}\n",
            "{\"Rapid\":{\"x\":0.0,\"y\":0.0,\"z\":5.0}}\n",
            "{\"Feed\":{\"x\":0.0,\"y\":0.0,\"z\":-1.0}}\n",
            "{\"Feed\":{\"x\":10.0,\"y\":0.0,\"z\":-1.0,\"a\":0.0}}\n",
            "{\"Feed\":{\"x\":20.0,\"y\":0.0,\"z\":-1.0,\"a\":90.0}}\n",
            "{\"End\":null}\n"
        ),
    )
    .unwrap();
    let out_file = dir.path().join("turns.nc");
    for post in [root().join("corpus/posts/vectric/gcode_mm.pp"), root().join("corpus/posts/cimco/fanuc_mill.js")] {
        assert_refused(Some(&post), &job, &out_file, "RT041", "A axis to 90 degrees", "turns.jsonl:5:1");
    }
    let writes_a = root().join("corpus/posts/vectric/text_output_mm.pp");
    let out = postc(&[&writes_a, &job, Path::new("-o"), &out_file, Path::new("--no-verify")]);
    assert!(out.status.success(), "{}", text(&out.stderr));
}

/// A CL file that starts the spindle at 0 rpm (`SPINDL/RPM,0,CLW`) posts
/// `S0 M3` and cuts with a spindle that turns nothing: verify refuses it
/// (it passed, since M3 was read as the spindle running).
#[test]
fn a_cut_with_the_spindle_at_zero_rpm_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let cl = dir.path().join("s0.apt");
    std::fs::write(
        &cl,
        "PARTNO/S0\nUNITS/MM\nLOADTL/1\nSPINDL/RPM,0,CLW\nFEDRAT/300\nGOTO/0,0,10\nGOTO/0,0,0\nGOTO/10,0,0\nFINI\n",
    )
    .unwrap();
    assert_refused(None, &cl, &dir.path().join("s0.nc"), "VF035", "0 rpm", "s0.nc:8:1");
}

/// A CL file that changes its units after it moved (`UNITS/INCHES` then
/// `GOTO/1,0,0`) is refused: the change was ignored with a warning, and
/// the inch after it posted as a millimetre.
#[test]
fn a_cl_file_that_changes_units_after_it_moved_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let cl = dir.path().join("units.apt");
    std::fs::write(
        &cl,
        "PARTNO/UNITS\nUNITS/MM\nLOADTL/1\nSPINDL/RPM,1000,CLW\nFEDRAT/500\nGOTO/0,0,10\nGOTO/0,0,0\nUNITS/INCHES\nGOTO/1,0,0\nFINI\n",
    )
    .unwrap();
    assert_refused(None, &cl, &dir.path().join("units.nc"), "CL014", "UNITS after the first move", "units.apt:8:1");
}

/// A spindle stop the post has no section for, followed by moves (a CL
/// file's `SPINDL/OFF` before it moves on), is a warning at the record:
/// the spindle runs on. One before a tool change, a restart or the end is
/// not (the tool change and the footer stop the spindle themselves).
#[test]
fn a_spindle_stop_the_post_cannot_write_is_a_warning_when_moves_follow() {
    let dir = tempfile::tempdir().unwrap();
    let cl = |name: &str, tail: &str| {
        let path = dir.path().join(name);
        let head = "PARTNO/STOP\nUNITS/MM\nLOADTL/1\nSPINDL/RPM,1000,CLW\nFEDRAT/500\nGOTO/0,0,10\nGOTO/0,0,0\n";
        std::fs::write(&path, format!("{head}{tail}FINI\n")).unwrap();
        path
    };
    let moves_on = cl("moves_on.apt", "SPINDL/OFF\nGOTO/10,0,0\n");
    let out = postc(&[&moves_on, Path::new("-o"), &dir.path().join("moves_on.nc")]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("warning[RT035]") && stderr.contains("the spindle to stop"), "{stderr}");
    assert!(stderr.contains("moves_on.apt:8:1"), "the warning names the CL record: {stderr}");
    for (name, tail) in [
        ("tool_change.apt", "SPINDL/OFF\nLOADTL/2\nSPINDL/RPM,800,CLW\nGOTO/10,0,0\n"),
        ("restart.apt", "SPINDL/OFF\nSPINDL/RPM,800,CLW\nGOTO/10,0,0\n"),
        ("end.apt", "GOTO/10,0,0\nSPINDL/OFF\n"),
    ] {
        let path = cl(name, tail);
        let out = postc(&[&path, Path::new("-o"), &dir.path().join("x.nc")]);
        assert!(out.status.success(), "{name}: {}", text(&out.stderr));
        assert!(!text(&out.stderr).contains("RT035"), "{name}: {}", text(&out.stderr));
    }
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
