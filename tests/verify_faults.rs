//! `postc verify` finds seeded faults: deliberately wrong variants of the
//! corpus post `corpus/posts/vectric/gcode_mm.pp` (arc direction swapped,
//! I and J swapped, arc words with too few decimals, inch numbers under
//! G21, no feed on the first cut, the spindle started after the first cut,
//! Z not raised before a tool change), each caught with its code at the
//! program line that shows the fault; and hand-written programs for the
//! checks a post variant cannot reach. The unmodified post verifies clean
//! over the same toolpaths, so every finding is the fault's.
//!
//! Bad programs (truncated, binary, unknown words, a 10 MB line, random
//! bytes) give findings, never a panic.

use std::path::{Path, PathBuf};

use postc_ir::{Post, Severity};
use postc_runtime::{Finished, Output};
use postc_verify::{Controller, Settings};

use crate::support;
use crate::support::verifying::{Found, errors, verify};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A job of two tools: a plunge, a line, an arc whose centre offset
/// (J10.35) needs decimals, and a first toolpath that ends down in the
/// material (no retract), so the post must raise Z before the tool change.
const JOB: &str = r#"Job(units:Mm,material:(min:(x:0.0,y:0.0,z:-10.0),max:(x:100.0,y:100.0,z:0.0)),safe_z:5.0)
Tool(number:1,name:"6 mm End Mill",diameter:6.0,spindle_speed:16000.0,cut_feed:1000.0,plunge_feed:300.0)
ToolpathStart(name:"One")
Rapid(x:10.0,y:10.0,z:5.0)
Feed(x:10.0,y:10.0,z:-2.0,intent:Plunge)
Feed(x:30.0,y:10.0,z:-2.0)
Arc(dir:Ccw,x:40.35,y:20.35,z:-2.0,cx:30.0,cy:20.35)
Feed(x:40.35,y:40.0,z:-2.0)
ToolpathEnd
Tool(number:2,name:"3 mm End Mill",diameter:3.0,spindle_speed:18000.0,cut_feed:800.0,plunge_feed:200.0)
ToolpathStart(name:"Two")
Rapid(x:60.0,y:60.0,z:5.0)
Feed(x:60.0,y:60.0,z:-1.0,intent:Plunge)
Feed(x:80.0,y:60.0,z:-1.0)
Rapid(x:80.0,y:60.0,z:5.0)
ToolpathEnd
End
"#;

fn job_file(dir: &Path) -> PathBuf {
    let path = dir.join("job.ron");
    std::fs::write(&path, JOB).unwrap();
    path
}

fn good_post() -> String {
    std::fs::read_to_string(root().join("corpus/posts/vectric/gcode_mm.pp")).unwrap()
}

fn post(post: &Post, toolpath: &Path) -> String {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(r) => match r.output {
            Finished::Memory(parts) => String::from_utf8(parts.concat()).unwrap(),
            _ => unreachable!(),
        },
        Err(d) => panic!("{d:?}"),
    }
}

/// The 1-based number of the first program line that satisfies `pred`.
fn line_of(program: &str, pred: impl Fn(&str) -> bool) -> usize {
    program.lines().position(pred).map(|i| i + 1).expect("the program has the line")
}

/// Posts JOB through the post text and verifies it, with the post known.
fn seeded(text: &str) -> (String, Vec<Found>) {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = job_file(dir.path());
    let p = support::compile_text("seeded.pp", text);
    let program = post(&p, &toolpath);
    let found = verify(program.as_bytes(), &toolpath, &Settings::from_post(&p, Controller::LinuxCnc, 0.01));
    (program, found)
}

fn assert_caught(program: &str, found: &[Found], code: &str, line: usize) {
    let errs = errors(found);
    assert!(
        errs.iter().any(|f| f.code == code && f.line == line),
        "expected {code} at line {line}; found {errs:#?}\nprogram:\n{program}"
    );
}

#[test]
fn the_unmodified_post_verifies_clean() {
    let (program, found) = seeded(&good_post());
    assert!(found.is_empty(), "{found:#?}\n{program}");
    // And over the corpus's standard job.
    let p = support::compile_text("seeded.pp", &good_post());
    let standard = root().join("corpus/toolpaths/standard.ron");
    let program = post(&p, &standard);
    let found = verify(program.as_bytes(), &standard, &Settings::from_post(&p, Controller::LinuxCnc, 0.01));
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn arc_direction_swapped() {
    let text = good_post().replace("\"G2[X]", "\"GX2[X]").replace("\"G3[X]", "\"G2[X]").replace("\"GX2[X]", "\"G3[X]");
    let (program, found) = seeded(&text);
    // The toolpath's arc turns counter-clockwise; the seeded post prints it as G2.
    let line = line_of(&program, |l| l.starts_with("G2X"));
    assert_caught(&program, &found, "VF013", line);
    assert!(found.iter().any(|f| f.message.contains("turns G2")));
}

#[test]
fn i_and_j_swapped() {
    let text = good_post().replace("[I|A|I|1.4]", "[J|A|I|1.4]").replace("[J|A|J|1.4]", "[I|A|J|1.4]");
    let (program, found) = seeded(&text);
    let line = line_of(&program, |l| l.starts_with("G3"));
    let errs = errors(&found);
    assert!(errs.iter().any(|f| (f.code == "VF013" || f.code == "VF020") && f.line == line), "{errs:#?}\n{program}");
}

#[test]
fn arc_words_with_too_few_decimals() {
    let text = good_post().replace("[I|A|I|1.4]", "[I|A|I|1.0]").replace("[J|A|J|1.4]", "[J|A|J|1.0]");
    let (program, found) = seeded(&text);
    let line = line_of(&program, |l| l.starts_with("G3"));
    assert_caught(&program, &found, "VF020", line);
    // grbl's limit catches it too.
    let dir = tempfile::tempdir().unwrap();
    let toolpath = job_file(dir.path());
    let p = support::compile_text("seeded.pp", &text);
    let found = verify(program.as_bytes(), &toolpath, &Settings::from_post(&p, Controller::Grbl, 0.01));
    assert_caught(&program, &found, "VF020", line);
}

#[test]
fn inch_numbers_in_a_g21_program() {
    let text = good_post().replace("UNITS = \"MM\"", "UNITS = \"INCH\"");
    let (program, found) = seeded(&text);
    // With the post known: its G21 contradicts its inch numbers.
    let line = line_of(&program, |l| l.starts_with("G21"));
    assert_caught(&program, &found, "VF031", line);
    // Without the post: the numbers are read as millimetres and are 25.4 times too small.
    let dir = tempfile::tempdir().unwrap();
    let toolpath = job_file(dir.path());
    let found = verify(program.as_bytes(), &toolpath, &Settings::default());
    let first_move = line_of(&program, |l| l.starts_with("G0X"));
    assert_caught(&program, &found, "VF030", first_move);
}

#[test]
fn feed_missing_on_the_first_cut() {
    let text = good_post().replace("\"G1[X][Y][Z][F]\"", "\"G1[X][Y][Z]\"");
    let (program, found) = seeded(&text);
    let line = line_of(&program, |l| l.starts_with("G1"));
    assert_caught(&program, &found, "VF034", line);
}

#[test]
fn spindle_started_after_the_first_cut() {
    let text = good_post()
        .replace("begin SPINDLE_ON\n\"[S] M3\"", "begin SPINDLE_ON\n")
        .replace("begin SPINDLE_ON\r\n\"[S] M3\"", "begin SPINDLE_ON\r\n")
        .replace(
            "begin FIRST_CCW_ARC_MOVE\n\"G3[X][Y][Z][I][J][F]\"",
            "begin FIRST_CCW_ARC_MOVE\n\"G3[X][Y][Z][I][J][F]\"\n\"[S] M3\"",
        );
    assert!(!text.contains("begin SPINDLE_ON\n\"[S] M3\""), "the seeded post still starts the spindle");
    let (program, found) = seeded(&text);
    let first_cut = line_of(&program, |l| l.starts_with("G1"));
    assert!(program.lines().position(|l| l.ends_with("M3")).unwrap() + 1 > first_cut, "{program}");
    assert_caught(&program, &found, "VF035", first_cut);
}

#[test]
fn z_not_raised_before_a_tool_change() {
    let text = good_post().replace("begin TOOLCHANGE\n\"M5\"\n\"G53 G0 Z0\"", "begin TOOLCHANGE\n\"M5\"");
    assert!(!text.contains("begin TOOLCHANGE\n\"M5\"\n\"G53"), "the seeded post still raises Z");
    let (program, found) = seeded(&text);
    let line = line_of(&program, |l| l.starts_with("T2 M6"));
    assert_caught(&program, &found, "VF038", line);
}

/// A post that never starts the spindle (nothing in SPINDLE_ON, no M3 or
/// M4 outside its jet sections: a spindle switched on by hand) cuts with
/// the spindle off by design: VF035 is a warning, and no error is left.
#[test]
fn a_post_for_a_spindle_started_by_hand_warns() {
    let text = good_post()
        .replace("begin SPINDLE_ON\n\"[S] M3\"", "begin SPINDLE_ON\n")
        .replace("begin SPINDLE_ON\r\n\"[S] M3\"", "begin SPINDLE_ON\r\n");
    assert!(!text.contains("\"[S] M3\""), "the seeded post still starts the spindle");
    let (program, found) = seeded(&text);
    assert!(errors(&found).is_empty(), "{found:#?}\n{program}");
    let first_cut = line_of(&program, |l| l.starts_with("G1"));
    assert!(
        found.iter().any(|f| f.code == "VF035" && f.severity == Severity::Warning && f.line == first_cut),
        "{found:#?}"
    );
}

/// Verifies `program` against a native toolpath given as text.
fn check_against(program: &str, toolpath: &str, settings: &Settings) -> Vec<Found> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("job.ron");
    std::fs::write(&path, toolpath).unwrap();
    verify(program.as_bytes(), &path, settings)
}

/// A job whose tool has no spindle speed, and that never switches the
/// spindle on, asks for none: a program without M3 makes it as it is (an
/// APT CL file with no SPINDL record posts this way).
#[test]
fn a_tool_without_a_speed_asks_for_no_spindle() {
    let job = "Job(units:Mm,safe_z:5.0)\nTool(number:1,cut_feed:1000.0,plunge_feed:300.0)\nToolpathStart()\nRapid(x:10.0,y:10.0,z:5.0)\nFeed(x:10.0,y:10.0,z:-2.0,intent:Plunge)\nFeed(x:30.0,y:10.0,z:-2.0)\nEnd\n";
    let program = "G21 G90\nT1 M6\nG0 X10 Y10 Z5\nG1 Z-2 F300\nX30 F1000\nM30\n";
    let found = check_against(program, job, &Settings::default());
    assert!(found.is_empty(), "{found:#?}");
    // With a speed, the runtime starts the spindle: the same program is wrong.
    let job = job.replace("Tool(number:1,", "Tool(number:1,spindle_speed:12000.0,");
    let found = check_against(program, &job, &Settings::default());
    assert!(errors(&found).iter().any(|f| f.code == "VF035" && f.line == 4), "{found:#?}");
    // An APT-word post (VcPost) is given no spindle record for it: a warning.
    let found = check_against(program, &job, &Settings { apt_words: true, ..Settings::default() });
    assert!(errors(&found).is_empty(), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF035" && f.message.contains("SPINDL")), "{found:#?}");
}

/// Text the toolpath inserts as it is (an APT INSERT) is the toolpath's,
/// not the post's: a line of it that does not read as G-code is a warning;
/// the same line with no insert behind it is an error.
#[test]
fn inserted_text_that_is_not_gcode_warns() {
    let job = "Job(units:Mm,safe_z:5.0)\nTool(number:1,spindle_speed:12000.0,cut_feed:1000.0,plunge_feed:300.0)\nToolpathStart()\nInsert(text:\"[HOLDER=C40] 6MM CRB\")\nRapid(x:10.0,y:10.0,z:5.0)\nFeed(x:10.0,y:10.0,z:-2.0,intent:Plunge)\nEnd\n";
    let program = "G21 G90\nT1 M6\nS12000 M3\n[HOLDER=C40] 6MM CRB\nG0 X10 Y10 Z5\nG1 Z-2 F300\nM30\n";
    let found = check_against(program, job, &Settings::default());
    assert!(errors(&found).is_empty(), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF004" && f.severity == Severity::Warning && f.line == 4), "{found:#?}");
    let other = program.replace("[HOLDER=C40] 6MM CRB", "[HOLDER=C41] 6MM CRB");
    let found = check_against(&other, job, &Settings::default());
    assert!(errors(&found).iter().any(|f| f.code == "VF004" && f.line == 4), "{found:#?}");
}

/// Verifies a hand-written program against JOB (mm, generic controller unless given).
fn check(program: &str, controller: Controller) -> Vec<Found> {
    let dir = tempfile::tempdir().unwrap();
    let toolpath = job_file(dir.path());
    verify(program.as_bytes(), &toolpath, &Settings { controller, ..Settings::default() })
}

/// JOB as a correct hand-written program, each line replaceable.
const PROGRAM: &[&str] = &[
    "%",
    "N10 G21 G90 G17 (JOB)",
    "N20 G53 G0 Z0",
    "N30 T1 M6",
    "N40 S16000 M3",
    "N50 G0 X10 Y10 Z5",
    "N60 G1 Z-2 F300",
    "N70 X30 F1000",
    "N80 G3 X40.35 Y20.35 I0 J10.35",
    "N90 G1 Y40",
    "N100 M5",
    "N110 G53 G0 Z0",
    "N120 T2 M6",
    "N130 S18000 M3",
    "N140 G0 X60 Y60 Z5",
    "N150 G1 Z-1 F200",
    "N160 X80 F800",
    "N170 G0 Z5",
    "N180 M30",
    "%",
];

fn program_with(replace: &[(usize, &str)]) -> String {
    let mut lines: Vec<String> = PROGRAM.iter().map(|s| s.to_string()).collect();
    for (i, text) in replace {
        lines[*i] = text.to_string();
    }
    lines.join("\n") + "\n"
}

#[test]
fn the_hand_written_program_verifies_clean() {
    let found = check(&program_with(&[]), Controller::LinuxCnc);
    assert!(found.is_empty(), "{found:#?}");
}

/// Under G95 a feed is per spindle revolution: F times S is the feed a
/// minute the toolpath gives (F0.01875 at S16000 is 300 mm/min).
#[test]
fn feeds_per_revolution_are_read_with_the_spindle_speed() {
    let per_rev = [
        (1, "N10 G21 G95 G90 G17 (JOB)"),
        (6, "N60 G1 Z-2 F0.01875"),
        (7, "N70 X30 F0.0625"),
        (15, "N150 G1 Z-1 F0.01111"),
        (16, "N160 X80 F0.04444"),
    ];
    let found = check(&program_with(&per_rev), Controller::LinuxCnc);
    assert!(found.is_empty(), "{found:#?}");
    // The per-minute number under G95 is 16,000 times too fast.
    let mut wrong = per_rev.to_vec();
    wrong[2] = (7, "N70 X30 F1000");
    caught(&program_with(&wrong), Controller::LinuxCnc, "VF033", 8);
}

fn caught(program: &str, controller: Controller, code: &str, line: usize) {
    let found = check(program, controller);
    assert_caught(program, &found, code, line);
}

#[test]
fn hand_written_faults_are_caught_at_their_line() {
    // R arc over 180 degrees needs a negative R: this one is the 90 degree arc's R form with R negative.
    caught(&program_with(&[(8, "N80 G3 X40.35 Y20.35 R-10.35")]), Controller::LinuxCnc, "VF022", 9);
    // K in the XY plane.
    caught(&program_with(&[(8, "N80 G3 X40.35 Y20.35 I0 J10.35 K0")]), Controller::LinuxCnc, "VF021", 9);
    // Block numbers that go back, and over the controller's maximum.
    caught(&program_with(&[(9, "N75 G1 Y40")]), Controller::LinuxCnc, "VF040", 10);
    caught(&program_with(&[(9, "N100000 G1 Y40")]), Controller::Fanuc, "VF041", 10);
    // A nested parenthesis in a comment; a `%` in a Fanuc comment.
    caught(&program_with(&[(1, "N10 G21 G90 G17 (JOB (1))")]), Controller::LinuxCnc, "VF042", 2);
    caught(&program_with(&[(1, "N10 G21 G90 G17 (JOB 100%)")]), Controller::Fanuc, "VF042", 2);
    // A rapid where the toolpath cuts.
    caught(&program_with(&[(9, "N90 G0 Y40")]), Controller::LinuxCnc, "VF012", 10);
    // A rapid over a cut and on past its end.
    caught(&program_with(&[(9, "N90 G0 Y45")]), Controller::LinuxCnc, "VF012", 10);
    // A rapid down into the material that the toolpath does not make.
    caught(&program_with(&[(13, "N130 S18000 M3 G0 X60 Y60 Z-3")]), Controller::LinuxCnc, "VF037", 14);
    // A cut off the toolpath.
    caught(&program_with(&[(7, "N70 X31 F1000")]), Controller::LinuxCnc, "VF010", 8);
    // A wrong feed.
    caught(&program_with(&[(7, "N70 X30 F1500")]), Controller::LinuxCnc, "VF033", 8);
    // Truncated after N90: the second toolpath is never cut.
    let truncated: String = PROGRAM[..10].join("\n");
    let found = check(&truncated, Controller::LinuxCnc);
    assert!(errors(&found).iter().any(|f| f.code == "VF011"), "{found:#?}");
    // The arc linearized into one chord, 3 mm from the arc: over the chord tolerance.
    caught(&program_with(&[(8, "N80 G1 X40.35 Y20.35")]), Controller::LinuxCnc, "VF014", 9);
    // Linearized into chords within 0.01 mm of the arc, it verifies.
    let chords: Vec<String> = (1..=40)
        .map(|k| {
            let a = -std::f64::consts::FRAC_PI_2 + std::f64::consts::FRAC_PI_2 * f64::from(k) / 40.0;
            format!("X{:.4} Y{:.4}", 30.0 + 10.35 * a.cos(), 20.35 + 10.35 * a.sin())
        })
        .collect();
    let program = program_with(&[(8, &format!("N80 G1 {}", chords.join("\nG1 ")))]);
    assert!(errors(&check(&program, Controller::LinuxCnc)).is_empty(), "{program}");
    // An R full circle.
    caught(&program_with(&[(8, "N80 G3 X30 Y10 R5")]), Controller::LinuxCnc, "VF023", 9);
}

/// Words and blocks longer than the controller reads (VF043): a
/// coordinate of 309 digits (what `GOTO/1e308,5,0` posted as) under every
/// controller; Fanuc's 8 digits a word; LinuxCNC's 252 characters a line,
/// past which its own interpreter (`rs274`) says "Command too long"; grbl's
/// 80 characters besides blanks and comments.
#[test]
fn words_and_blocks_longer_than_the_controller_reads() {
    let huge = format!("N70 X1{} F1000", "0".repeat(308));
    for controller in [Controller::Generic, Controller::LinuxCnc, Controller::Fanuc, Controller::Haas, Controller::Grbl]
    {
        caught(&program_with(&[(7, &huge)]), controller, "VF043", 8);
    }
    let vf043 = |program: &str, controller| check(program, controller).iter().filter(|f| f.code == "VF043").count();
    // Fanuc and Haas: 8 digits are read, 9 are not.
    assert_eq!(vf043(&program_with(&[(7, "N70 X30.000000 F1000")]), Controller::Fanuc), 0);
    caught(&program_with(&[(7, "N70 X30.0000000 F1000")]), Controller::Fanuc, "VF043", 8);
    caught(&program_with(&[(7, "N70 X30.0000000 F1000")]), Controller::Haas, "VF043", 8);
    assert_eq!(vf043(&program_with(&[(7, "N70 X30.0000000 F1000")]), Controller::LinuxCnc), 0);
    // LinuxCNC: a line of 252 characters is read, one of 253 is not; a
    // carriage return before the line feed counts.
    let line = |n: usize| format!("N70 X30 F1000 ({})", "c".repeat(n - 16));
    assert_eq!(line(253).len(), 253);
    assert_eq!(vf043(&program_with(&[(7, &line(252))]), Controller::LinuxCnc), 0);
    caught(&program_with(&[(7, &line(253))]), Controller::LinuxCnc, "VF043", 8);
    let crlf = |text: &str| program_with(&[(7, text)]).replace('\n', "\r\n");
    assert_eq!(vf043(&crlf(&line(251)), Controller::LinuxCnc), 0);
    caught(&crlf(&line(252)), Controller::LinuxCnc, "VF043", 8);
    if let Some(rs274) = support::rs274::find() {
        let run = |text: &str, end: &str| {
            support::rs274::run(&rs274, &format!("G21 G90{end}G1 X0 F100{end}{text}{end}M2{end}"))
        };
        assert!(run(&line(252), "\n").is_ok(), "rs274 reads 252 characters: {:?}", run(&line(252), "\n"));
        assert!(run(&line(251), "\r\n").is_ok(), "rs274 reads 251 characters and a CR");
        for (text, end) in [(line(253), "\n"), (line(252), "\r\n")] {
            let refused = run(&text, end).expect_err("rs274 refuses the line");
            assert!(refused.contains("Command too long"), "{refused}");
        }
    } else {
        println!("rs274 not found: the LinuxCNC limit is not cross-checked");
    }
    // grbl: the comment does not count; 81 other characters do.
    assert_eq!(vf043(&program_with(&[(7, &line(253))]), Controller::Grbl), 0);
    let long = format!("N70 X30 F1000 G1 {}", "Y40 ".repeat(25));
    caught(&program_with(&[(7, &long)]), Controller::Grbl, "VF043", 8);
}

#[test]
fn bad_programs_give_findings_never_a_panic() {
    // Unknown words and letters.
    let found =
        check(&program_with(&[(7, "N70 X30 F1000 E5"), (8, "N80 G3 X40.35 Y20.35 I0 J10.35 G7.7")]), Controller::Grbl);
    assert!(found.iter().any(|f| f.code == "VF005" && f.line == 8), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF005" && f.line == 9), "{found:#?}");
    // Parameters and expressions are read (tests/verify_families.rs): one
    // the program never set leaves the move uncompared, a warning; an
    // unclosed bracket is an error.
    let found = check(&program_with(&[(7, "N70 X[#1+2] F1000")]), Controller::LinuxCnc);
    assert!(found.iter().any(|f| f.code == "VF005" && f.severity == Severity::Warning && f.line == 8), "{found:#?}");
    let found = check(&program_with(&[(7, "N70 X[#1+2 F1000")]), Controller::LinuxCnc);
    assert!(found.iter().any(|f| f.code == "VF004" && f.line == 8), "{found:#?}");
    // Binary data in a line.
    let mut bytes = program_with(&[]).into_bytes();
    bytes.splice(40..40, [0u8, 1, 2, 0xFF, 0xFE, b'\n']);
    let dir = tempfile::tempdir().unwrap();
    let toolpath = job_file(dir.path());
    let found = verify(&bytes, &toolpath, &Settings::default());
    assert!(found.iter().any(|f| f.code == "VF002"), "{found:#?}");
    // A 10 MB line.
    let mut big = program_with(&[]);
    big.insert_str(big.find("N90").unwrap(), &format!("({})\n", "A".repeat(10 << 20)));
    let found = verify(big.as_bytes(), &toolpath, &Settings::default());
    assert!(found.iter().any(|f| f.code == "VF003" && f.line == 10), "{found:#?}");
    // Not G-code at all.
    let text: String = (0..50).map(|i| format!("{i},{i},0\n")).collect();
    let found = verify(text.as_bytes(), &toolpath, &Settings::default());
    assert!(found.iter().any(|f| f.code == "VF001"), "{found:#?}");
    // Random mutations of a real program: findings, never a panic.
    let p = support::compile_text("seeded.pp", &good_post());
    let standard = root().join("corpus/toolpaths/standard.ron");
    let program = post(&p, &standard).into_bytes();
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for _ in 0..300 {
        let mut mutated = program.clone();
        for _ in 0..(next() % 8 + 1) {
            let at = (next() as usize) % mutated.len();
            match next() % 4 {
                0 => mutated[at] = next() as u8,
                1 => {
                    mutated.remove(at);
                }
                2 => {
                    let alphabet = b"GXYZIJKRFNM-.%()/;:0123456789 \n\r";
                    mutated.insert(at, alphabet[(next() as usize) % alphabet.len()]);
                }
                _ => mutated.truncate(at),
            }
            if mutated.is_empty() {
                break;
            }
        }
        let _ = verify(&mutated, &standard, &Settings::from_post(&p, Controller::LinuxCnc, 0.01));
        let _ = verify(&mutated, &standard, &Settings::default());
    }
}

/// The spot holes of `drill_mm.ron` as Autodesk's `fanuc.cps` writes them:
/// a canned cycle, G80, then a rapid with no G0 (a Fanuc control moves
/// it in the G0 of before the cycle), a plunge, a dwell, another cycle.
const SPOT_HOLES: &[&str] = &[
    "%",
    "N10 G90 G94 G17 G21",
    "N30 T4 M06",
    "N35 S6000 M03",
    "N45 G00 X20. Y20. Z5.",
    "N50 G98 G83 X20. Y20. Z-7. R1. Q3. F120.",
    "N55 X40.",
    "N60 G80",
    "N160 G00 X20. Y40.",
    "N170 G98 G82 X20. Y40. Z-2. R2. P1250 F150.",
    "N175 G80",
    "N180 X30. Z5.",
    "N185 G01 Z-1. F150.",
    "N190 G04 P2000",
    "N195 G00 Z5.",
    "N200 X40.",
    "N205 G82 X40. Y40. Z-2. R2. P1250 F150.",
    "N210 G80",
    "N240 M30",
    "%",
];

#[test]
fn axis_words_after_a_cycles_g80_move_in_the_motion_mode_of_before_the_cycle() {
    let toolpath = root().join("corpus/toolpaths/drill_mm.ron");
    let settings = Settings { controller: Controller::Fanuc, ..Settings::default() };
    let program = SPOT_HOLES.join("\n") + "\n";
    let found = verify(program.as_bytes(), &toolpath, &settings);
    let errors: Vec<_> = found.iter().filter(|f| f.severity == Severity::Error).collect();
    assert!(errors.is_empty(), "{found:#?}");
    // LinuxCNC refuses the block: a warning at it, naming both readings.
    let warned = found.iter().find(|f| f.code == "VF005" && f.line == 12).expect("a VF005 warning at N180");
    assert!(warned.message.contains("Fanuc") && warned.message.contains("LinuxCNC"), "{}", warned.message);
    // The move is compared: to the wrong place, it is caught.
    let wrong = program.replace("N180 X30. Z5.", "N180 X35. Z5.");
    let found = verify(wrong.as_bytes(), &toolpath, &settings);
    assert!(found.iter().any(|f| f.severity == Severity::Error && f.code.starts_with("VF01")), "{found:#?}");
}
