//! Hand-written fixtures, one per lexing rule, CIRCLE convention, CYCLE
//! form and diagnostic, with their events and diagnostics kept as
//! `insta` snapshots in `tests/snapshots/` (`cargo insta review` accepts new output).

use std::path::Path;

use postc_ir::event::{ArcDir, Event, Plane};

fn fixture(name: &str) -> Vec<u8> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures").join(name);
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn snapshot(name: &str) -> crate::common::Read {
    let read = crate::common::read_bytes(name, &fixture(name));
    let stem = name.split('.').next().unwrap_or(name);
    crate::common::assert_snapshot(stem, &crate::common::render(&read));
    read
}

fn arcs(read: &crate::common::Read) -> Vec<(ArcDir, Plane)> {
    read.events
        .iter()
        .filter_map(|(e, _)| match e {
            Event::Arc(a) => Some((a.dir, a.plane)),
            _ => None,
        })
        .collect()
}

#[test]
fn lexing_rules() {
    let read = snapshot("lexing.cl");
    assert!(read.errors().is_empty());
    assert_eq!(read.codes(), ["CL007"], "only the line of numbers without `$` is reported");
    assert_eq!(read.count("Feed"), 5);
    // The same file with CRLF line ends reads to the same events.
    let text = String::from_utf8(fixture("lexing.cl")).unwrap_or_default();
    let crlf = crate::common::read_text(&text.replace('\n', "\r\n"));
    let events = |r: &crate::common::Read| r.events.iter().map(|(e, _)| e.clone()).collect::<Vec<_>>();
    assert_eq!(events(&crlf), events(&read));
    assert_eq!(crlf.codes(), read.codes());
}

#[test]
fn nx_toolpaths_tools_and_moves() {
    let read = snapshot("toolpaths_nx.cls");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(read.count("ToolpathStart"), 3);
    assert_eq!(read.count("ToolpathEnd"), 3);
    assert_eq!(read.count("Tool"), 2, "the second toolpath keeps its tool");
    let names: Vec<&str> = read.events.iter().map(|(e, _)| e.name()).take(3).collect();
    assert_eq!(names, ["Job", "Tool", "ToolpathStart"]);
}

#[test]
fn circle_solidworks_turns_counter_clockwise_about_its_axis() {
    let read = snapshot("circle_solidworks.apt");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(
        arcs(&read),
        [
            (ArcDir::Ccw, Plane::Xy),
            (ArcDir::Ccw, Plane::Xy),
            (ArcDir::Cw, Plane::Xy),
            (ArcDir::Cw, Plane::Yz),
            (ArcDir::Ccw, Plane::Xy)
        ]
    );
}

#[test]
fn circle_creo_turns_counter_clockwise_about_its_axis() {
    let read = snapshot("circle_creo.ncl");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(arcs(&read), [(ArcDir::Cw, Plane::Xy), (ArcDir::Ccw, Plane::Xy)]);
}

#[test]
fn circle_nx_turns_clockwise_about_its_axis() {
    let read = snapshot("circle_nx.cls");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(arcs(&read), [(ArcDir::Ccw, Plane::Xy), (ArcDir::Cw, Plane::Xy)]);
}

#[test]
fn circle_clt_follows_its_direction_word() {
    let read = snapshot("circle_clt.clt");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(arcs(&read), [(ArcDir::Ccw, Plane::Xy), (ArcDir::Cw, Plane::Xy)]);
}

#[test]
fn circle_catia_follows_indirv() {
    let read = snapshot("circle_catia.aptsource");
    assert_eq!(read.codes(), ["CL022"]);
    assert_eq!(arcs(&read), [(ArcDir::Ccw, Plane::Xy), (ArcDir::Cw, Plane::Xy), (ArcDir::Ccw, Plane::Xy)]);
}

#[test]
fn circle_in_a_tilted_plane_is_cut_into_feed_moves() {
    let read = snapshot("circle_tilted.cl");
    assert_eq!(read.codes(), ["CL012"]);
    assert_eq!(read.count("Arc"), 0);
    assert!(read.count("Feed") > 10);
}

#[test]
fn cycles_of_every_vendor() {
    for name in ["cycle_solidworks.apt", "cycle_nx.clsf", "cycle_creo.ncl", "cycle_classic.cl"] {
        let read = snapshot(name);
        assert!(read.diagnostics.is_empty(), "{name}: {:?}", read.diagnostics);
        assert!(read.count("DrillCycle") >= 1, "{name}");
    }
    let read = snapshot("cycle_clt.clt");
    assert_eq!(read.codes(), ["CL006", "CL006"]);
    assert_eq!(read.count("DrillPoint"), 2);
    let read = snapshot("cycle_open.cl");
    assert_eq!(read.codes(), ["CL013", "CL013", "CL024"], "the file ends without FINI too");
    assert_eq!(read.count("DrillEnd"), 2);
}

#[test]
fn seed_words_read_without_problems() {
    let read = snapshot("seed_words.cl");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert!(read.count("Command") > 30);
}

#[test]
fn every_error_is_reported_and_reading_goes_on() {
    let read = snapshot("errors.cl");
    let codes = read.codes();
    for code in
        ["CL003", "CL004", "CL005", "CL006", "CL008", "CL009", "CL010", "CL014", "CL015", "CL016", "CL017", "CL019"]
    {
        assert!(codes.contains(&code), "{code} missing from {codes:?}");
    }
    assert_eq!(read.events.last().map(|e| e.0.name()), Some("End"));
    let read = snapshot("eof_continuation.cl");
    assert_eq!(read.codes(), ["CL018", "CL004", "CL024"], "the incomplete GOTO and the missing FINI are reported too");
    assert_eq!(read.count("Feed"), 0, "{:?}", read.events);
}

#[test]
fn part_programs_give_one_error() {
    for name in ["part_program.apt", "part_program_motion.apt"] {
        let read = snapshot(name);
        assert_eq!(read.codes(), ["CL002"], "{name}");
    }
    // An assignment found while reading (the head check only sees `NAME=WORD/`).
    let read = crate::common::read_text("FEDRAT/100\nGOTO/1,2,3\nP(1) = 4\nGOTO/4,5,6\n");
    assert_eq!(read.codes(), ["CL002"]);
    // An `=` inside a record's arguments is a syntax error, not a part program.
    let read = crate::common::read_text("FEDRAT/100\nGOTO/1,2,3\nOPERATION/NAME=ROUGH\nGOTO/4,5,6\nFINI\n");
    assert_eq!(read.codes(), ["CL003"]);
    assert_eq!(read.count("Feed"), 2);
    // CATIA's drive arc without its tool-position word still reads.
    let read = crate::common::read_text(
        "FEDRAT/100\nGOTO/10,0,0\nINDIRV/0,1,0\nGOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,10,0)\nFINI\n",
    );
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(read.count("Arc"), 1);
}

#[test]
fn binary_files_give_one_error() {
    let mut apt360 = vec![1, 0, 0, 0, 2, 0, 0, 0, 0xe8, 3, 0, 0, 1, 0, 0, 0];
    apt360.extend_from_slice(b"\0\0\0\0\0\0\0\0        \n GOTO/1,2,3\n");
    let read = crate::common::read_bytes("cl.tap", &apt360);
    assert_eq!(read.codes(), ["CL001"]);
    assert!(read.diagnostics[0].message.contains("APT360"));
    assert!(read.events.is_empty());
    let utf16: Vec<u8> = "\u{feff}GOTO/1,2,3\n".encode_utf16().flat_map(u16::to_le_bytes).collect();
    let read = crate::common::read_bytes("utf16.cl", &utf16);
    assert_eq!(read.codes(), ["CL001"]);
    assert!(read.diagnostics[0].message.contains("UTF-16"));
}

#[test]
fn a_line_longer_than_a_mebibyte_is_skipped() {
    let mut text = b"FEDRAT/100\nRAPID\nGOTO/0,0,0\nPPRINT ".to_vec();
    text.extend(std::iter::repeat_n(b'x', 3 << 20));
    text.extend_from_slice(b"\nGOTO/1,0,0\nFINI\n");
    let read = crate::common::read_bytes("long.cl", &text);
    assert_eq!(read.codes(), ["CL020"]);
    assert_eq!(read.count("Rapid") + read.count("Feed"), 2);
}

#[test]
fn a_record_continued_past_a_mebibyte_is_skipped() {
    let mut text = b"FEDRAT/100\nRAPID\nGOTO/0,0,0\nGOTO/1,$\n".to_vec();
    for _ in 0..200_000 {
        text.extend_from_slice(b"1.5,2.5,3.5,$\n");
    }
    text.extend_from_slice(b"3\nGOTO/1,0,0\nFINI\n");
    let read = crate::common::read_bytes("long.cl", &text);
    assert_eq!(read.codes(), ["CL020"]);
    assert_eq!(read.count("Rapid") + read.count("Feed"), 2);
}

#[test]
fn a_utf8_byte_order_mark_is_skipped() {
    let read = crate::common::read_bytes("bom.cl", b"\xEF\xBB\xBFFEDRAT/100\nGOTO/1,2,3\nFINI\n");
    assert!(read.diagnostics.is_empty(), "{:?}", read.diagnostics);
    assert_eq!(read.count("Feed"), 1);
}

/// Coordinates, feeds and speeds no machine can reach are refused, with an
/// error at the record (CL023): `GOTO/1e308,5,0` would post as a 309-digit
/// X. The limits are in the file's units; a feed every later move carries
/// is reported once, at its first move.
#[test]
fn values_out_of_range_are_refused_at_their_record() {
    let read = crate::common::read_text("UNITS/MM\nLOADTL/1\nFEDRAT/100,MMPM\nGOTO/1e308,5,0\nGOTO/1,2,3\nFINI\n");
    assert_eq!(read.codes(), ["CL023"]);
    let json = postc_report::Render::to_json(&read.sources, &read.diagnostics[0], "test.cl");
    assert_eq!((json.line, json.column), (Some(4), Some(1)));
    assert!(
        read.diagnostics[0].message.starts_with("Feed x is 1e308: a coordinate or length must be within ±1000000 mm")
    );
    assert_eq!(read.count("Feed"), 2, "the events keep their order; the error refuses the toolpath");
    let read = crate::common::read_text("UNITS/INCHES\nFEDRAT/10\nGOTO/0,0,0\nGOTO/40000,0,0\nGOTO/39000,0,0\nFINI\n");
    assert_eq!(read.codes(), ["CL023"], "40,000 inches is over 1 km; 39,000 is not");
    let read = crate::common::read_text(
        "UNITS/MM\nFEDRAT/5e7,MMPM\nGOTO/0,0,0\nGOTO/1,0,0\nGOTO/2,0,0\nSPINDL/RPM,2e6\nFINI\n",
    );
    let lines: Vec<_> = read
        .diagnostics
        .iter()
        .map(|d| postc_report::Render::to_json(&read.sources, d, "test.cl").line.unwrap_or(0))
        .collect();
    assert_eq!(read.codes(), ["CL023", "CL023", "CL023"], "{:?}", read.diagnostics);
    assert_eq!(lines, [2, 3, 6], "the FEDRAT, the first move that carries it, the spindle speed");
    // A drilling cycle out of range is an error, and its holes stay inside it.
    let cl = "UNITS/MM\nTOOL PATH/D,TOOL,T1\nCYCLE/DRILL,RAPTO,3.0,FEDTO,5e9,MMPM,100.0\nGOTO/0,0,0\nGOTO/10,0,0\nCYCLE/OFF\nEND-OF-PATH\nFINI\n";
    let read = crate::common::read_text(cl);
    assert_eq!(read.codes(), ["CL023"], "{:?}", read.diagnostics);
    crate::common::check_order("cycle out of range", &read.events, false);
    assert_eq!((read.count("DrillCycle"), read.count("DrillPoint"), read.count("DrillEnd")), (1, 2, 1));
}

/// A CL file that ends without FINI may be cut short (CL024): a copy that
/// stopped inside a GOTO posts as a whole program otherwise. An NX CLSF
/// file, which ends with END-OF-PATH and writes no FINI (the nine of the
/// corpus's `HumMan__CLSFProcessor`), is whole.
#[test]
fn a_file_without_fini_may_be_cut_short() {
    // Cut inside the last number of a GOTO: the record still reads.
    let read = crate::common::read_text("UNITS/MM\nFEDRAT/100\nGOTO/0,0,0\nGOTO/7.0000000000, -2.9062500000, 3.24");
    assert_eq!(read.codes(), ["CL024"]);
    let json = postc_report::Render::to_json(&read.sources, &read.diagnostics[0], "test.cl");
    assert_eq!(json.line, Some(4));
    assert!(crate::common::read_text("UNITS/MM\nFEDRAT/100\nGOTO/0,0,0\nFINI\n").diagnostics.is_empty());
    let nx = "TOOL PATH/A,TOOL,T1\nFEDRAT/100\nGOTO/0,0,0\nEND-OF-PATH\n$$ end\n";
    assert!(crate::common::read_text(nx).diagnostics.is_empty());
    let cut = "TOOL PATH/A,TOOL,T1\nFEDRAT/100\nGOTO/0,0,0\nEND-OF-PATH\nTOOL PATH/B,TOOL,T1\nGOTO/1,0,0\n";
    assert_eq!(crate::common::read_text(cut).codes(), ["CL024"]);
}

/// A cutting move before any FEDRAT has no feed rate (CL025), said once at
/// the first: NCL's `pmill_test1_4.as` of the corpus cuts its whole path
/// with none, and the program posted from it cut with no F (VF034, blamed
/// on the post); rapids need none.
#[test]
fn a_cutting_move_before_any_feed_rate_is_reported_once() {
    let read = crate::common::read_text(
        "UNITS/MM\nRAPID\nGOTO/0,0,5\nGOTO/0,0,-1\nGOTO/5,0,-1\nFEDRAT/100\nGOTO/9,0,-1\nFINI\n",
    );
    assert_eq!(read.codes(), ["CL025"]);
    let json = postc_report::Render::to_json(&read.sources, &read.diagnostics[0], "test.cl");
    assert_eq!(json.line, Some(4));
    assert!(crate::common::read_text("UNITS/MM\nRAPID\nGOTO/0,0,5\nFINI\n").diagnostics.is_empty());
}
