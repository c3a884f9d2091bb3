//! `postc verify` reads the families real posts write besides plain ISO
//! words (docs/verify.md, "What it reads"): Fanuc/Haas/LinuxCNC `#`
//! parameters and `[ ]` expressions, Siemens Sinumerik (`;` comments,
//! R parameters, `X=` values, `CR=` arcs, `SUPA`, `MCALL CYCLE8x(...)`
//! drilling), Okuma's `VC` variables and Heidenhain ISO (centres, `G83
//! P01 ...` cycles called by `M99`). Hand-written programs in the style of the corpus posts'
//! verify clean against their toolpath; the same programs with a fault are
//! still caught; what verify does not replay is a warning (VF005) naming
//! the word, never an error; broken syntax stays an error (VF004). The
//! macro program is also read by LinuxCNC's `rs274`, the reference for `#`
//! and `[ ]`.

use postc_ir::Severity;
use postc_verify::{Controller, Settings};

use crate::support;
use crate::support::verifying::{self, Found, errors};

/// Verifies `program` against the native toolpath `toolpath`.
fn verify(program: &str, toolpath: &str) -> Vec<Found> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("job.ron");
    std::fs::write(&path, toolpath).unwrap();
    let settings = Settings { controller: Controller::Generic, ..Settings::default() };
    verifying::verify(program.as_bytes(), &path, &settings)
}

fn line_of(program: &str, text: &str) -> usize {
    program.lines().position(|l| l.contains(text)).map(|i| i + 1).expect("the program has the line")
}

/// A pocket of one tool: a plunge, a line, an arc, a line.
const MILL: &str = r#"Job(units:Mm,material:(min:(x:0.0,y:0.0,z:-10.0),max:(x:100.0,y:100.0,z:0.0)),safe_z:5.0)
Tool(number:1,name:"6 mm End Mill",diameter:6.0,spindle_speed:16000.0,cut_feed:1000.0,plunge_feed:300.0)
ToolpathStart(name:"One")
Rapid(x:10.0,y:10.0,z:5.0)
Feed(x:10.0,y:10.0,z:-2.0,intent:Plunge)
Feed(x:30.0,y:10.0,z:-2.0)
Arc(dir:Ccw,x:40.0,y:20.0,z:-2.0,cx:30.0,cy:20.0)
Feed(x:40.0,y:40.0,z:-2.0)
Rapid(x:40.0,y:40.0,z:5.0)
ToolpathEnd
End
"#;

/// Two holes drilled 7 deep from the top at Z0, clearance 5, reference plane 1.
const DRILL: &str = r#"Job(units:Mm,material:(min:(x:0.0,y:0.0,z:-20.0),max:(x:80.0,y:60.0,z:0.0)),safe_z:5.0)
Tool(number:4,name:"5 mm drill",diameter:5.0,spindle_speed:6000.0,cut_feed:120.0,plunge_feed:120.0)
ToolpathStart(name:"Holes")
DrillCycle(kind:Deep,retract_plane:5.0,reference_plane:1.0,depth:-7.0,feed:120.0,peck:2.0)
DrillPoint(x:20.0,y:20.0)
DrillPoint(x:40.0,y:20.0)
ToolpathEnd
End
"#;

/// MILL as a Fanuc/LinuxCNC macro program: numbered and named
/// parameters, bracket expressions in words, a machine parameter that
/// verify does not know (`#5183`, under G53), and the statements of macro
/// B and LinuxCNC's O-words that verify does not follow.
const MACRO: &str = "%
G21 G90 G17 G40 G80
#100 = 10.
#101 = [#100 * 3.]
#<_depth> = -2.
#102 = 1
G53 G0 Z[25.4 * #5183]
T1 M6
S16000 M3
G0 X#100 Y[#100] Z5.
G#102 Z#<_depth> F300.
X#101 F1000.
G3 X[#101 + 10.] Y[#100 * 2] I0 J10.
G1 Y[SQRT[1600.]]
G0 Z[#100 / 2]
M5
M30
%
";

#[test]
fn fanuc_and_linuxcnc_macro_programs_are_read_and_compared() {
    let found = verify(MACRO, MILL);
    assert!(found.is_empty(), "{found:#?}");
    // A computed value is compared as any number: one unit off is a cut off the toolpath.
    let wrong = MACRO.replace("X#101 F1000.", "X[#101 + 1.] F1000.");
    let found = verify(&wrong, MILL);
    let at = line_of(&wrong, "X[#101 + 1.]");
    assert!(errors(&found).iter().any(|f| f.code == "VF010" && f.line == at), "{found:#?}");
    // Broken brackets are an error, as before (a post that drops the closing `]`).
    let broken = MACRO.replace("G0 X#100 Y[#100] Z5.", "G0 X[#100 Y10. Z5.");
    let found = verify(&broken, MILL);
    let at = line_of(&broken, "X[#100 Y10.");
    assert!(errors(&found).iter().any(|f| f.code == "VF004" && f.line == at), "{found:#?}");
}

#[test]
fn what_verify_cannot_evaluate_or_follow_is_a_warning() {
    let program = MACRO
        .replace("#<_depth> = -2.", "#<_depth> = -2.\n#1 = #4001\nIF [#1 EQ 0] GOTO 10\nWHILE [#1 LT 3] DO1\nEND1\nDPRNT[TOOL*#1]\nN10 G0 X#500 Y10. Z5.\nF#1")
        .replace("G0 X#100 Y[#100] Z5.", "G0 X#100 Y[#100] Z5.\no100 if [#1 GT 0]\no100 endif");
    let found = verify(&program, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    for (text, what) in [
        ("#1 = #4001", "does not know the value"),
        ("IF [#1", "`IF`"),
        ("WHILE", "`WHILE`"),
        ("END1", "`END`"),
        ("N10 G0 X#500", "cannot compute"),
        ("F#1", "F word"),
        ("o100 if", "`IF`"),
        ("o100 endif", "`ENDIF`"),
    ] {
        let at = line_of(&program, text);
        assert!(
            found.iter().any(|f| f.code == "VF005" && f.line == at && f.message.contains(what)),
            "no VF005 `{what}` at line {at} ({text}): {found:#?}"
        );
    }
    // The output statement has no effect on motion: nothing is said of it.
    assert!(!found.iter().any(|f| f.line == line_of(&program, "DPRNT")), "{found:#?}");
}

/// LinuxCNC's rs274 reads the macro program too (the reference for `#`,
/// `#<name>` and `[ ]`), and moves where verify says it does.
#[test]
fn rs274_reads_the_macro_program() {
    let Some(rs274) = support::rs274::find() else {
        support::referee_missing("rs274_reads_the_macro_program", "rs274");
        return;
    };
    // rs274 starts with #5183 = 0; everything else is the program's.
    let motions = support::rs274::run(&rs274, MACRO).unwrap_or_else(|e| panic!("rs274 refuses the program: {e}"));
    let ends: Vec<[f64; 3]> = motions.iter().map(|m| m.end_mm()).collect();
    for want in [[10.0, 10.0, 5.0], [10.0, 10.0, -2.0], [30.0, 10.0, -2.0], [40.0, 20.0, -2.0], [40.0, 40.0, -2.0]] {
        assert!(
            ends.iter().any(|e| (0..3).all(|i| (e[i] - want[i]).abs() < 1e-6)),
            "rs274 does not move to {want:?}: {ends:?}"
        );
    }
}

/// MILL as `siemens-840d.cps` writes it, with R parameters, `X=` values
/// and the Sinumerik statements the corpus posts print.
const SINUMERIK_MILL: &str = "; %_N_1001_MPF
N10 ; T1 D=6 CR=0 - ZMIN=-2 - flat end mill
N11 WORKPIECE(,,,\"BOX\",112,0,-10,100,100,100,0,0)
N12 G90 G94
N13 G71
N14 G64
N15 G17
N16 G0 SUPA Z0 D0

N17 ; Pocket
N18 T=\"6 mm End Mill\" D1
N19 M6
N20 CYCLE832(0.01, _SEMIFIN, 1)
N21 MSG(\"Pocket\")
N22 S16000 M3
N23 G54
N24 R1=10 R2=R1*3
N25 G0 X=R1 Y10
N26 G0 Z5
N27 G1 Z-2 F300
N28 G1 X=R2 F1000
N29 G3 X40 Y20 Z-2 CR=10
N30 G1 Y40
N31 G0 Z5
N32 G0 SUPA Z0 D0
N33 M30
";

/// DRILL as the corpus Sinumerik posts write it: a modal CYCLE83 called
/// at each positioning block, then cancelled.
const SINUMERIK_DRILL: &str = "; %_N_1001_MPF
N10 G90 G94
N11 G71
N12 G17
N13 G0 SUPA Z0 D0
N14 T4 D1
N15 M6
N16 S6000 M3
N17 G54
N18 G0 X20 Y20
N19 G0 Z5
N20 F120
N21 MCALL CYCLE83(5, 1, 0, -7, , -2, , 0, , , 1, 1, , 3, 0, 0.5, 0)
N22 X20 Y20
N23 X40
N24 MCALL
N25 G0 SUPA Z0 D0
N26 M30
";

#[test]
fn sinumerik_programs_are_read_and_compared() {
    let found = verify(SINUMERIK_MILL, MILL);
    assert!(found.is_empty(), "{found:#?}");
    let found = verify(SINUMERIK_DRILL, DRILL);
    assert!(found.is_empty(), "{found:#?}");
    // The same holes called one at a time (no MCALL), and with the depth relative to the reference plane.
    let single = SINUMERIK_DRILL.replace(
        "N21 MCALL CYCLE83(5, 1, 0, -7, , -2, , 0, , , 1, 1, , 3, 0, 0.5, 0)\nN22 X20 Y20\nN23 X40\nN24 MCALL",
        "N22 CYCLE81(5, 1, 0, , 8)\nN23 X40\nN24 CYCLE81(5, 1, 0, -7)",
    );
    let found = verify(&single, DRILL);
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn sinumerik_faults_are_still_caught() {
    // An arc turning the wrong way.
    let wrong = SINUMERIK_MILL.replace("G3 X40 Y20 Z-2 CR=10", "G2 X40 Y20 Z-2 CR=10");
    let found = verify(&wrong, MILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF013" && f.line == line_of(&wrong, "N29")), "{found:#?}");
    // An R parameter one unit off.
    let wrong = SINUMERIK_MILL.replace("R2=R1*3", "R2=R1*3+1");
    let found = verify(&wrong, MILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF010" && f.line == line_of(&wrong, "N28")), "{found:#?}");
    // The reference plane and the depth swapped: the cycle rapids down to Z-7 and feeds up.
    let wrong = SINUMERIK_DRILL.replace("CYCLE83(5, 1, 0, -7,", "CYCLE83(5, -7, 0, 1,");
    let found = verify(&wrong, DRILL);
    assert!(!errors(&found).is_empty(), "{found:#?}");
    assert!(errors(&found).iter().all(|f| f.line >= line_of(&wrong, "N22")), "{found:#?}");
    // Too deep.
    let wrong = SINUMERIK_DRILL.replace("CYCLE83(5, 1, 0, -7,", "CYCLE83(5, 1, 0, -9,");
    let found = verify(&wrong, DRILL);
    assert!(errors(&found).iter().any(|f| f.line == line_of(&wrong, "N22")), "{found:#?}");
    // A cycle without its reference plane (RFP) is an error at the hole it drills.
    let wrong = SINUMERIK_DRILL.replace("CYCLE83(5, 1, 0, -7,", "CYCLE83(5, , 0, -7,");
    let found = verify(&wrong, DRILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF024" && f.line == line_of(&wrong, "N22")), "{found:#?}");
}

#[test]
fn sinumerik_statements_verify_does_not_replay_are_warnings_naming_them() {
    let program = SINUMERIK_MILL.replace("N23 G54", "N23 G54\nTRANS X0 Y0\nGOTOF LABEL1\nLABEL1:\nTRANS");
    let found = verify(&program, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    let trans = line_of(&program, "TRANS X0");
    assert!(found.iter().any(|f| f.code == "VF005" && f.line == trans && f.message.contains("`TRANS`")), "{found:#?}");
    let gotof = line_of(&program, "GOTOF");
    assert!(found.iter().any(|f| f.code == "VF005" && f.line == gotof && f.message.contains("`GOTOF`")), "{found:#?}");
    // TRANS alone (the frame reset) and the label say nothing.
    assert_eq!(found.len(), 2, "{found:#?}");
    // A work offset set in a system variable is not replayed (the moves are in work coordinates).
    let program = SINUMERIK_MILL.replace("N23 G54", "$P_UIFR[1,X,TR]=120.05\nN23 G54");
    let found = verify(&program, MILL);
    assert!(errors(&found).is_empty() && found.len() == 1 && found[0].code == "VF005", "{found:#?}");
    // A call of a block written after M30 (as `siemens-840d_2.cps` writes
    // its operations): verify says, as a note, that it compares nothing from
    // there, and nothing after it is an error.
    let program = SINUMERIK_MILL
        .replace("N27 G1 Z-2 F300", "CALL BLOCK LABEL1 TO LABEL0\nM30\nLABEL1:\nG1 Z-3 F300")
        .replace("N33 M30", "LABEL0:");
    let found = verify(&program, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    let call = line_of(&program, "CALL BLOCK");
    assert!(
        found.iter().any(|f| f.code == "VF044"
            && f.severity == Severity::Note
            && f.line == call
            && f.message.contains("`CALL`")),
        "{found:#?}"
    );
    // A move verify cannot compute (IC: incremental for one word) is not
    // compared; the toolpath moves it may make are not reported missing
    // as an error, and the moves after it are compared again.
    let program = SINUMERIK_MILL.replace("N28 G1 X=R2 F1000", "N28 G1 X=IC(20) F1000");
    let found = verify(&program, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF005" && f.line == line_of(&program, "N28")), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF011" && f.severity == Severity::Warning), "{found:#?}");
    // A word verify does not know is still an error.
    let program = SINUMERIK_MILL.replace("N23 G54", "N23 G54 FOOBAR");
    let found = verify(&program, MILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF004" && f.line == line_of(&program, "FOOBAR")), "{found:#?}");
}

/// MILL as Okuma OSP posts write it (`OKUMA_MB-5000H.cps`): common
/// variables `VC`, a work offset set in a system variable, `X=VC1`.
const OKUMA: &str = "%
O1001
N10 (TOMBSTONE SETUP B ANGLE)VC1=10.
N11 VZOFX[21]=0.
N12 VC2=VC1*3
N13 G40 G80 G90 G94 G17
N14 G21
N15 G15 H01
N16 T1 M06
N17 S16000 M03
N18 G00 X=VC1 Y=VC[1] Z5.
N19 G01 Z-2. F300.
N20 X=VC2 F1000.
N21 G03 X40. Y20. I0 J10.
N22 G01 Y40.
N23 G00 Z5.
N24 M02
%
";

#[test]
fn okuma_variables_are_read() {
    let found = verify(OKUMA, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    // The system variable is not replayed: a warning that names it, and nothing else.
    assert!(
        found.len() == 1 && found[0].code == "VF005" && found[0].line == 4 && found[0].message.contains("Okuma"),
        "{found:#?}"
    );
    let wrong = OKUMA.replace("VC2=VC1*3", "VC2=VC1*3.1");
    let found = verify(&wrong, MILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF010" && f.line == line_of(&wrong, "N20")), "{found:#?}");
}

/// MILL as `heidenhain_iso.cps` writes it: the `%1001 G71` program lines,
/// the blank (`G30`/`G31`), signed numbers, I J as the circle centre.
const HEIDENHAIN_ISO_MILL: &str = "N10 %1001 G71
(STANDARD TEST JOB)
N15 G30 G17 X+0. Y+0. Z-10.
N20 G31 G90 X+100. Y+100. Z+0.
N25 G94
N40 T1 G17 S16000
N45 S16000 M03
N55 G00 X+10. Y+10.
N60 Z+5.
N65 G01 Z-2. F300.
N70 X+30. F1000.
N75 I+30. J+20. G03 X+40. Y+20.
N80 G01 Y+40.
N85 G00 Z+5.
N90 M30
N95 %1001 G71
";

/// DRILL as `heidenhain_iso.cps` writes it: the cycle defined (`G83
/// P01` set-up clearance, `P02` depth from the surface) and called by
/// `M99` at each hole.
const HEIDENHAIN_ISO_DRILL: &str = "N10 %1001 G71
N15 G30 G17 X+0. Y+0. Z-20.
N20 G31 G90 X+80. Y+60. Z+0.
N40 T4 G17 S6000
N45 S6000 M03
N55 G00 X+20. Y+20.
N60 Z+5.
N70 G83 P01 -4. P02 -8. P03 +3. P04 0.5 P05 F120.
N75 M99
N80 X+40. M99
N85 M30
N90 %1001 G71
";

#[test]
fn heidenhain_iso_programs_are_read_and_compared() {
    let found = verify(HEIDENHAIN_ISO_MILL, MILL);
    assert!(found.is_empty(), "{found:#?}");
    let found = verify(HEIDENHAIN_ISO_DRILL, DRILL);
    assert!(found.is_empty(), "{found:#?}");
    // The centre read as an offset (as a Fanuc control would) is wrong.
    let wrong = HEIDENHAIN_ISO_MILL.replace("I+30. J+20.", "I+0. J+10.");
    let found = verify(&wrong, MILL);
    assert!(errors(&found).iter().any(|f| f.line == line_of(&wrong, "N75")), "{found:#?}");
    // Drilled too deep.
    let wrong = HEIDENHAIN_ISO_DRILL.replace("P02 -8.", "P02 -9.");
    let found = verify(&wrong, DRILL);
    assert!(errors(&found).iter().any(|f| f.line == line_of(&wrong, "N75")), "{found:#?}");
    // Without the `%1001 G71` line, it is not Heidenhain ISO: M99 is no cycle call
    // and the holes are never drilled.
    let other = HEIDENHAIN_ISO_DRILL.replace("N10 %1001 G71", "N10 G71");
    let found = verify(&other, DRILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF011" || f.code == "VF004"), "{found:#?}");
}

/// MILL as other controllers' programs write it, each with what marks
/// its family: Okuma's program name on the line after `%`, Hurco's `E`
/// after M2, OSAI's `DWT=` dwell, a Boxford file's `[GM HEADER]`, and
/// KinetiC-NC's `O1234:` subprogram label after the end.
const OTHER_CONTROLS_MILL: &str = "%
1001
G21 G90 G17
T1 M6
S16000 M3
G0 X10. Y10. Z5.
G1 Z-2. F300.
DWT=0.5
X30. F1000.
G3 X40. Y20. I0. J10.
G1 Y40.
G0 Z5.
M5
M2
E
";

#[test]
fn program_marks_and_statements_of_other_controls_are_read() {
    let found = verify(OTHER_CONTROLS_MILL, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    let boxford =
        format!("[GM HEADER]\ntype=mill\nunits=mm\nT1=32= T=1 P=1 D=6\n[PROGRAM]\n{}", &OTHER_CONTROLS_MILL[7..]);
    let found = verify(&boxford, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    // The program name only right after `%`, before any move; `E` only after the program's end.
    let late = OTHER_CONTROLS_MILL.replace("DWT=0.5", "2002");
    assert!(errors(&verify(&late, MILL)).iter().any(|f| f.code == "VF004" && f.line == line_of(&late, "2002")));
    let early = OTHER_CONTROLS_MILL.replace("DWT=0.5", "E");
    assert!(errors(&verify(&early, MILL)).iter().any(|f| f.code == "VF004"));
    // A subprogram after the end: its label reads, and M98 stops the comparison with a note.
    let sub = OTHER_CONTROLS_MILL.replace("T1 M6", "T1 M6\nM98 P1234").replace("E\n", "O1234:\nG53 G0 Z0.\nM99\n");
    let found = verify(&sub, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    assert!(found.iter().any(|f| f.code == "VF044" && f.line == line_of(&sub, "M98")), "{found:#?}");
    // Andronic's `G282 A1`: machine coordinates until `G282 A-1`; a rapid to
    // machine Z0 there is no rapid into the material.
    let andronic = OTHER_CONTROLS_MILL.replace("T1 M6", "G282 A1\nG0 Z0.\nG282 A-1\nT1 M6");
    let found = verify(&andronic, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    let without = OTHER_CONTROLS_MILL.replace("G0 X10. Y10. Z5.", "G0 X10. Y10. Z-5.");
    assert!(!errors(&verify(&without, MILL)).is_empty());
}

/// DRILL's holes in Fagor's cycle form (`G8x X Y Z I`: Z the reference
/// plane, I the depth), and in a controller's own form verify does not
/// read (Andronic's `G83 Z8 B4 K3 ... E120`), which is a note.
#[test]
fn fagor_cycles_are_read_and_other_cycle_forms_are_named() {
    let fagor = "G21 G90 G17\nT4 M6\nS6000 M3\nG0 X20. Y20. Z5.\nG98 G83 X20. Y20. Z1. I-7. K0 F120.\nX40.\nG80\nM30\n";
    let found = verify(fagor, DRILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    // Too deep is still caught.
    let deep = fagor.replace("I-7.", "I-8.");
    assert!(!errors(&verify(&deep, DRILL)).is_empty());
    let andronic = "G21 G90 G17\nT4 M6\nS6000 M3\nG0 X20. Y20. Z5.\nG83 Z8 Y0 B4 K3 I0 J0 X0.5 E120\nG80\nM30\n";
    let found = verify(andronic, DRILL);
    assert!(found.iter().any(|f| f.code == "VF044" && f.line == 5), "{found:#?}");
    assert!(errors(&found).is_empty(), "{found:#?}");
}

/// MILL as a Klipper post writes it (`MPCNC.cps`, "MPCNC Milling -
/// Klipper"): extended commands, a name and `NAME=VALUE` parameters
/// (Klipper's G-Codes reference: `SET_SERVO SERVO=myservo ANGLE=5.3`),
/// which run the firmware's command or a macro of the machine's
/// configuration.
const KLIPPER: &str = "G90
G21
START_PRINT X=-3,5 Y=-3,5 Z=-3,5 ; the macro
M3 S16000
G0 X10 Y10 Z5
G1 Z-2 F300
G1 X30 F1000
G3 X40 Y20 I0 J10
G1 Y40
G0 Z5
END_PRINT
";

#[test]
fn klipper_extended_commands_are_named_not_replayed() {
    let found = verify(KLIPPER, MILL);
    assert!(errors(&found).is_empty(), "{found:#?}");
    for (line, name) in [(3, "START_PRINT"), (11, "END_PRINT")] {
        assert!(
            found.iter().any(|f| f.code == "VF005"
                && f.severity == Severity::Warning
                && f.line == line
                && f.message.contains(name)
                && f.message.contains("Klipper")),
            "{found:#?}"
        );
    }
    // The moves after a command are still compared.
    let wrong = KLIPPER.replace("G1 X30 F1000", "G1 X31 F1000");
    assert!(!errors(&verify(&wrong, MILL)).is_empty());
    // A name after other words, or one followed by words that are not
    // `NAME=VALUE` parameters, is no Klipper command: still an error.
    for bad in ["G1 X30 F1000 START_PRINT", "START_PRINT X-3"] {
        let wrong = KLIPPER.replace("START_PRINT X=-3,5 Y=-3,5 Z=-3,5 ; the macro", bad);
        let found = verify(&wrong, MILL);
        assert!(errors(&found).iter().any(|f| f.code == "VF004"), "{bad}: {found:#?}");
    }
    // A program of another family whose lines read as named commands
    // (SCM's `XL2P X=49.992 Y=40.28`) and never move the tool is still no
    // G-code program (VF001).
    let foreign = format!("{}{}", "XG0 X=10 Y=10 Z=5\n".repeat(3), "XL2P X=30 Y=10 Z=-2\n".repeat(20));
    let found = verify(&foreign, MILL);
    assert!(errors(&found).iter().any(|f| f.code == "VF001"), "{found:#?}");
}
