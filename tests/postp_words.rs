//! One test per word of the APT post-processor guide (the APT `postp`), each checking the
//! documented output on FANUCM (lathe words on FANUCL) against a committed
//! snapshot in `tests/snapshots/postp/` (`POSTC_BLESS=1` rewrites them).
//! Every CL file starts `MACHIN/<controller>` and `UNITS/MM`.

use crate::support::postp;

use postp::{check, run};

/// A tool, a feed and a first position: the start of most tests.
const START: &str = "LOADTL/1\nFEDRAT/300,MMPM\nRAPID\nGOTO/0,0,10\n";

fn with_start(body: &str) -> String {
    format!("{START}{body}")
}

#[test]
fn auxfun_now_and_next() {
    let r = check("auxfun", "FANUCM", &with_start("AUXFUN/99,NOW\nAUXFUN/8\nAUXFUN/21,NEXT\nGOTO/5,0,10\n"));
    assert!(r.program.contains("M99\nM08\nG01 X5. F300. M21\n"), "{}", r.program);
}

#[test]
fn prefun_now_and_next() {
    let r = check("prefun", "FANUCM", &with_start("PREFUN/61\nPREFUN/64,NEXT\nGOTO/5,0,10\n"));
    assert!(r.program.contains("G61\nG01 G64 X5. F300.\n"), "{}", r.program);
}

#[test]
fn clearp_with_retrct() {
    let body = "CLEARP/XYPLAN,25\nGOTO/5,5,-2\nRETRCT\nCLEARP/(PLANE/0,0,2,30)\nRETRCT\nCLEARP/0,0,1,40\nRETRCT\nCLEARP/OFF\nRETRCT\n";
    let r = check("clearp_retrct", "FANUCM", &with_start(body));
    assert!(r.program.contains("G00 Z25.\nZ15.\nZ40.\nG91 G28 Z0.\nG90\n"), "{}", r.program);
}

#[test]
fn clearp_must_be_parallel_to_xy() {
    for bad in ["CLEARP/YZPLAN,3", "CLEARP/PL1", "CLEARP/0,1,1,3"] {
        let r = run("FANUCM", &with_start(&format!("{bad}\n")));
        assert!(!r.ok && r.has("PX016"), "{bad}: {:?}", r.diagnostics);
    }
}

#[test]
fn clrsrf_now_moves_along_the_normal() {
    let body = "GOTO/10,20,5\nCLRSRF/XYPLAN,30\nCLRSRF/NOW\nCLRSRF/YZPLAN,50\nCLRSRF/NOW\nCLRSRF/(PLANE/1,0,1,100)\nCLRSRF/NOW\n";
    let r = check("clrsrf", "FANUCM", &with_start(body));
    // (50,20,30) onto x + z = 100 (normal (1,0,1)/sqrt 2): (60,20,40).
    assert!(r.program.contains("G00 Z30.\nX50.\nX60. Z40.\n"), "{}", r.program);
}

#[test]
fn coolnt_default_now_and_next() {
    let body = "COOLNT/FLOOD\nGOTO/5,0,10\nGOTO/5,0,2\nCOOLNT/MIST,NOW\nCOOLNT/ON,NEXT\nGOTO/6,0,2\nCOOLNT/OFF\nGOTO/7,0,2\nCOOLNT/MIST\nGOTO/7,0,3\nCOOLNT/OFF,NOW\n";
    let r = check("coolnt", "FANUCM", &with_start(body));
    // FLOOD waits for the block with Z; OFF goes into the next block.
    assert!(r.program.contains("G01 X5. F300.\nZ2. M08\nM07\nX6. M08\nX7. M09\nZ3. M07\nM09\n"), "{}", r.program);
}

#[test]
fn cutcom_left_right_off_with_d() {
    let body =
        "CUTCOM/LEFT\nGOTO/5,0,10\nCUTCOM/OFF\nGOTO/6,0,10\nCUTCOM/RIGHT,12\nGOTO/7,0,10\nCUTCOM/OFF\nGOTO/8,0,10\n";
    let r = check("cutcom", "FANUCM", &with_start(body));
    assert!(
        r.program.contains("G41 X5.") && r.program.contains("G40 X6.") && r.program.contains("G42 D12 X7."),
        "{}",
        r.program
    );
}

#[test]
fn delay_and_dwell_in_seconds_and_revolutions() {
    let body = "DELAY/2.5\nDWELL/1\nSPINDL/600\nDELAY/REV,10\nDWELL/REV,3\n";
    let r = check("delay", "FANUCM", &with_start(body));
    assert!(r.program.contains("G04 P2500\nG04 P1000\nS600 M03\nG04 P1000\nG04 P300\n"), "{}", r.program);
}

#[test]
fn delete_and_opskip_skip_blocks() {
    let body = "DELETE/ON\nGOTO/5,0,10\nPPRINT OPTIONAL\nOPSKIP/OFF\nGOTO/6,0,10\nOPSKIP/ON\nOPSTOP\nDELETE/OFF\n";
    let r = check("delete_opskip", "FANUCM", &with_start(body));
    assert!(r.program.contains("/G01 X5. F300.\n/(OPTIONAL)\nX6.\n/M01\n"), "{}", r.program);
}

#[test]
fn end_rewind_reset_write_the_options() {
    let r = check("end_rewind_reset", "FANUCM", "RESET\nEND\nREWIND\n");
    assert_eq!(r.program, "G17 G21 G40 G49 G80 G90\nM02\nM30\n");
}

#[test]
fn fedrat_per_minute_and_per_revolution() {
    let body = "GOTO/5,0,10\nFEDRAT/150\nGOTO/6,0,10\nSPINDL/1000\nFEDRAT/0.1,MMPR\nGOTO/7,0,10\nFEDRAT/MMPM,400\nGOTO/8,0,10\n";
    let r = check("fedrat", "FANUCM", &with_start(body));
    assert!(r.program.contains("G01 X5. F300.\nX6. F150.\nS1000 M03\nG95 X7. F0.1\nG94 X8. F400.\n"), "{}", r.program);
}

#[test]
fn gohome_writes_the_options_and_forces_every_axis() {
    let r = check("gohome", "FANUCM", &with_start("GOHOME\nGOTO/0,0,10\n"));
    assert!(r.program.ends_with("G91 G28 Z0.\nG28 X0. Y0.\nG90\nG01 X0. Y0. Z10. F300.\n"), "{}", r.program);
}

#[test]
fn insert_is_verbatim_from_column_7() {
    // "INSERT G65 P9010": column 7 is the blank after the word, and it is kept.
    let r = check("insert", "FANUCM", "SEQNO/10,INCR,10\nINSERT G65 P9010 A1.\nDELETE/ON\nINSERT M08\n");
    assert_eq!(r.program, "N10  G65 P9010 A1.\n/N20  M08\n");
}

#[test]
fn letter_engraves_the_next_pprint() {
    let body = "LETTER/10,20,-0.2,6,0,0.2,0.2,5,1,200,100\nPPRINT HI\nGOTO/0,0,10\n";
    let r = check("letter", "FANUCM", &with_start(body));
    // H: three strokes, I: three, each a plunge at 100 and cuts at 200.
    assert_eq!(r.program.matches("G01 Z-0.2 F100.").count(), 6, "{}", r.program);
    assert!(
        r.program.contains("(HI)\nZ5.\nX10. Y20.\nZ1.\nG01 Z-0.2 F100.\nY25.08 F200.\nG00 Z5.\nX13.387 Y20.\n"),
        "{}",
        r.program
    );
}

#[test]
fn letter_honours_rotation_scale_and_spacing() {
    let body = "LETTER/0,0,-1,10,90,0.5,1,5,2,100,50\nPPRINT L.\n";
    let r = check("letter_rotated", "FANUCM", &with_start(body));
    // Turned 90 degrees: the L's upright (1 inch) runs along -X, its foot
    // (4 grid units of 0.5 x 25.4 / 6) along +Y; the dot sits at 10 along
    // the turned baseline plus 2 grid units.
    assert!(r.program.contains("X-25.4\nZ2.\nG01 Z-1. F50.\nX0. F100.\nY8.467\n"), "{}", r.program);
    assert!(r.program.ends_with("Y14.233\nZ2.\nG01 Z-1. F50.\nG00 Z5.\n"), "{}", r.program);
}

#[test]
fn loadtl_with_height_and_diameter_offsets() {
    let body = "FEDRAT/300\nLOADTL/3\nRAPID\nGOTO/0,0,50\nLOADTL/4,14\nRAPID\nGOTO/0,0,50\nLOADTL/5,15,25\nRAPID\nGOTO/1,1,1\nGOTO/1,1,50\n";
    let r = check("loadtl", "FANUCM", body);
    assert!(r.program.contains("T03 M06\nG00 X0. Y0. Z50.\nT04 M06\nG00 G43 H14 X0. Y0. Z50.\n"), "{}", r.program);
    assert!(r.program.contains("T05 M06\nG00 G43 H15 D25 X1. Y1. Z1.\n"), "{}", r.program);
}

#[test]
fn mode_absolute_and_incremental() {
    let body = "MODE/91\nGOTO/5,0,10\nGOTO/5,3,8\nMODE/90,NEXT\nGOTO/6,3,8\n";
    let r = check("mode", "FANUCM", &with_start(body));
    assert!(r.program.contains("G91\nG01 X5. F300.\nY3. Z-2.\nG01 G90 X6. Y3. Z8. F300.\n"), "{}", r.program);
}

#[test]
fn opstop_and_stop() {
    let r = check("opstop_stop", "FANUCM", "OPSTOP\nSTOP\n");
    assert_eq!(r.program, "M01\nM00\n");
}

#[test]
fn origin_default_now_next_and_extended() {
    let body = "ORIGIN/55\nGOTO/0,0,5\nGOTO/1,0,5\nORIGIN/54.3,NOW\nORIGIN/56,NEXT\nGOTO/2,0,5\n";
    let r = check("origin", "FANUCM", &with_start(body));
    // ORIGIN/55 waits for the first block with X or Y.
    assert!(r.program.contains("G01 Z5. F300.\nG55 X1.\nG54 P3\nG56 X2.\n"), "{}", r.program);
}

#[test]
fn partno_and_pprint_are_comments_as_written_without_numbers() {
    let r =
        check("partno_pprint", "FANUCM", "SEQNO/5,INCR,5\nPARTNO BRACKET (REV B)\nPPRINT check the clamps\nOPSTOP\n");
    assert_eq!(r.program, "(BRACKET [REV B])\n(check the clamps)\nN5 M01\n");
}

#[test]
fn rapid_is_for_the_next_move_only() {
    let r = check("rapid", "FANUCM", &with_start("RAPID\nGOTO/5,0,10\nGOTO/6,0,10\n"));
    assert!(r.program.ends_with("G00 X0. Y0. Z10.\nX5.\nG01 X6. F300.\n"), "{}", r.program);
}

#[test]
fn retrct_without_a_plane_goes_home() {
    let r = check("retrct", "FANUCM", &with_start("GOTO/5,0,2\nRETRCT\nGOTO/5,0,10\n"));
    assert!(r.program.ends_with("G91 G28 Z0.\nG90\nG01 X5. Y0. Z10. F300.\n"), "{}", r.program);
}

#[test]
fn rotabl_absolute_incremental_and_mapped() {
    let body = "ROTABL/AAXIS,ATANGL,90\nROTABL/AAXIS,INCR,30,CCLW,NEXT\nGOTO/0,10,10\nROTABL/LINEAR,AAXIS,RADIUS,10\nGOTO/15.70796,10,10\nROTABL/LINEAR,NOMORE\nGOTO/5,10,10\nFINI\n";
    let r = postp::run_with(&format!("MACHIN/FANUCM,1\nUNITS/MM\n{START}{body}"), None, None);
    postp::snapshot("rotabl.FANUCM", &r.text());
    // 15.708 mm on a 10 mm radius is 90 degrees more than the 60 where the mapping began.
    assert!(r.program.ends_with("G00 A90.\nG01 A60. Y10. F300.\nA150.\nX5.\n"), "{}", r.program);
}

#[test]
fn selctl_and_toolno_select_a_tool() {
    let r = check("selctl_toolno", "FANUCM", &with_start("SELCTL/4\nTOOLNO/5,NOW\nSELCTL/6,NEXT\nGOTO/5,0,10\n"));
    assert!(r.program.contains("T04\nT05\nG01 X5. F300. T06\n"), "{}", r.program);
}

#[test]
fn seqno_numbers_blocks_but_not_comments_marks_or_the_program_number() {
    let r = check("seqno", "FANUCM", "TMARK\nSEQNO/1000,INCR,10,9100\nPPRINT NOTE\nOPSTOP\nSTOP\nTMARK\n");
    assert_eq!(r.program, "%\nO9100\n(NOTE)\nN1000 M01\nN1010 M00\n%\n");
}

#[test]
fn spindl_forms() {
    let body = "SPINDL/1200\nSPINDL/1500,RPM,CCLW\nSPINDL/OFF\nSPINDL/ON\n";
    let r = check("spindl", "FANUCM", body);
    assert_eq!(r.program, "S1200 M03\nS1500 M04\nM05\nS1500 M04\n");
}

#[test]
fn spindl_on_a_lathe_with_surface_speed_and_maxrpm() {
    let body = "TURRET/1\nSPINDL/200,SFM,CLW,MAXRPM,2500\nSPINDL/150,SFM,CCLW\nSPINDL/800,RPM\n";
    let r = check("spindl", "FANUCL", body);
    // Without MAXRPM the options' maxspeed (3000) limits the spindle.
    assert_eq!(r.program, "T0101\nG50 S2500\nG96 S200 M03\nG50 S3000\nG96 S150 M04\nG97 S800 M03\n");
}

#[test]
fn thread_is_a_g76_cycle_on_the_lathe() {
    let body = "TURRET/3\nSPINDL/300,RPM\nRAPID\nGOTO/6,0,2\nTHREAD/1.5,9.2,-20,0.3,0.05,0.05,1.5,0,60,2\n";
    let r = check("thread", "FANUCL", body);
    assert!(r.program.ends_with("G76 P021060 Q50 R0.05\nG76 X9.2 Z-20. R0. P900 Q300 F1.5\n"), "{}", r.program);
}

#[test]
fn tmark_default_and_by_code() {
    let r = check("tmark", "FANUCM", "TMARK\nTMARK/61\n");
    assert_eq!(r.program, "%\n=\n");
}

#[test]
fn trans_replaces_the_translation() {
    let body = "TRANS/10,20,0\nGOTO/1,1,10\nTRANS/0,0,5\nGOTO/1,1,10\nTRANS/0,0,0\nGOTO/1,1,10\n";
    let r = check("trans", "FANUCM", &with_start(body));
    assert!(r.program.contains("G01 X11. Y21. F300.\nX1. Y1. Z15.\nZ10.\n"), "{}", r.program);
}

#[test]
fn turret_on_the_lathe_and_moves_in_diameter() {
    let body = "TURRET/2\nTURRET/4,14\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/20,0,2\nGOTO/20,0,-30\nMODE/91\nGOTO/22,0,-30\nGOTO/22,0,-25\nMODE/90\nCUTCOM/RIGHT,24\nGOTO/25,0,-25\n";
    let r = check("turret", "FANUCL", body);
    // Lathes start in feed per revolution (G99), so MMPR writes no mode.
    assert!(r.program.contains("T0202\nT0414\nG00 X40. Z2.\nG01 Z-30. F0.2\nG01 U4. F0.2\nW5.\n"), "{}", r.program);
    assert!(r.program.ends_with("G01 G42 T0424 X50. Z-25. F0.2\n"), "{}", r.program);
}
