//! The diagnostics of the APT CL reader: one constructor per code, so that
//! every message, severity and help text lives in one place. The table of
//! codes is in the crate documentation.

use postc_ir::codes;
use postc_ir::diagnostic::{Diagnostic, Span};

pub(crate) const BINARY: &str = codes::CL001.code;
pub(crate) const PART_PROGRAM: &str = codes::CL002.code;
pub(crate) const SYNTAX: &str = codes::CL003.code;
pub(crate) const BAD_ARGS: &str = codes::CL004.code;
pub(crate) const UNKNOWN_WORD: &str = codes::CL005.code;
pub(crate) const MISSING_COMMA: &str = codes::CL006.code;
pub(crate) const JOINED_LINE: &str = codes::CL007.code;
pub(crate) const ORPHAN_NUMBERS: &str = codes::CL008.code;
pub(crate) const IGNORED_WORD: &str = codes::CL009.code;
pub(crate) const CIRCLE_WITHOUT_GOTO: &str = codes::CL010.code;
pub(crate) const ARC_OFF_CIRCLE: &str = codes::CL011.code;
pub(crate) const TILTED_ARC: &str = codes::CL012.code;
pub(crate) const OPEN_CYCLE: &str = codes::CL013.code;
pub(crate) const LATE_UNITS: &str = codes::CL014.code;
pub(crate) const STRAY_END_OF_PATH: &str = codes::CL015.code;
pub(crate) const AFTER_FINI: &str = codes::CL016.code;
pub(crate) const NURBS: &str = codes::CL017.code;
pub(crate) const EOF_CONTINUATION: &str = codes::CL018.code;
pub(crate) const FEED_PER_REV: &str = codes::CL019.code;
pub(crate) const LONG_LINE: &str = codes::CL020.code;
pub(crate) const IO: &str = codes::CL021.code;
pub(crate) const NO_INDIRV: &str = codes::CL022.code;
pub(crate) const OUT_OF_RANGE: &str = codes::CL023.code;
pub(crate) const NO_FINI: &str = codes::CL024.code;
pub(crate) const NO_FEED: &str = codes::CL025.code;

pub(crate) fn binary(span: Span, what: &str) -> Diagnostic {
    Diagnostic::error(BINARY, format!("this is a binary file ({what}), not a text CL file"))
        .at(span, "binary data here")
        .note("postc reads CL data as text: APT CL records such as `GOTO/1.5,2,0` one per line")
        .help("export the toolpath from the CAM system as a text CL file (NX: CLSF, Creo: Pro/CLfile ASCII, NCL: APT source `.as`) and post that file")
}

pub(crate) fn part_program(span: Span, why: &str) -> Diagnostic {
    Diagnostic::error(PART_PROGRAM, "this is an APT part program (source code), not CL data")
        .at(span, why.to_string())
        .note("an APT part program defines geometry (`PL1=PLANE/...`, `C1=CIRCLE/...`) and describes motion against it (`GO/TO,...`, `TLLFT,GOLFT/L1`); CL data lists the tool positions an APT processor computed from it")
        .help("run the part program through an APT processor (APT360, NCL, ...) and post the CL file it writes")
}

pub(crate) fn syntax(span: Span, message: String, help: &str) -> Diagnostic {
    Diagnostic::error(SYNTAX, message).at(span, "here").help(help.to_string())
}

pub(crate) fn bad_args(span: Span, message: String, help: &str) -> Diagnostic {
    Diagnostic::error(BAD_ARGS, message).at(span, "this record is skipped").help(help.to_string())
}

pub(crate) fn unknown_word(span: Span, word: &str) -> Diagnostic {
    Diagnostic::warning(UNKNOWN_WORD, format!("unknown CL word `{word}`: the record is skipped"))
        .at(span, "not a CL or post-processor word postc knows")
        .help("if a post needs this word, tell the postc maintainers which CAM system writes it")
}

pub(crate) fn missing_comma(span: Span) -> Diagnostic {
    Diagnostic::warning(MISSING_COMMA, "two values stand side by side without a comma; they are read as two values")
        .at(span, "a comma is missing here")
}

pub(crate) fn joined_line(span: Span) -> Diagnostic {
    Diagnostic::warning(JOINED_LINE, "a line of numbers continues the record above, whose line has no `$`")
        .at(span, "joined to the record above")
        .help("end a line with `$` when the record goes on at the next line")
}

pub(crate) fn orphan_numbers(span: Span) -> Diagnostic {
    Diagnostic::error(ORPHAN_NUMBERS, "this line has numbers but no CL word (such as GOTO) before them")
        .at(span, "this line is skipped")
        .help("a CL record starts with its word: `GOTO/1,2,3`; a record continued over lines ends each line but the last with `$`")
}

pub(crate) fn ignored_word(span: Span, word: &str, record: &str) -> Diagnostic {
    Diagnostic::warning(IGNORED_WORD, format!("`{word}` is not understood in a {record} record and is ignored"))
        .at(span, "ignored")
}

pub(crate) fn circle_without_goto(span: Span, next: Option<Span>) -> Diagnostic {
    let d = Diagnostic::warning(
        CIRCLE_WITHOUT_GOTO,
        "CIRCLE is not followed by the GOTO that ends the arc; the circle is dropped",
    )
    .at(span, "this circle has no end point");
    match next {
        Some(next) => d.also(next, "the next record is not a GOTO"),
        None => d,
    }
}

pub(crate) fn arc_off_circle(span: Span, start_radius: f64, end_radius: f64) -> Diagnostic {
    Diagnostic::warning(
        ARC_OFF_CIRCLE,
        format!("the arc starts {start_radius:.4} and ends {end_radius:.4} from its centre; the end point is not on the circle"),
    )
    .at(span, "arc end point")
    .note("the arc is kept; a controller with a tight radius check may reject it")
}

pub(crate) fn tilted_arc(span: Span, segments: usize) -> Diagnostic {
    Diagnostic::warning(
        TILTED_ARC,
        format!("this arc lies in a tilted plane (not XY, ZX or YZ); it is cut as {segments} straight feed moves"),
    )
    .at(span, "tilted arc")
}

pub(crate) fn open_cycle(span: Span, closed_by: Option<Span>) -> Diagnostic {
    let d = Diagnostic::warning(OPEN_CYCLE, "a drilling cycle is not ended by CYCLE/OFF; it ends here")
        .at(span, "cycle started here");
    match closed_by {
        Some(at) => d.also(at, "the cycle is ended before this record"),
        None => d.note("the file ends inside the cycle"),
    }
}

pub(crate) fn late_units(span: Span) -> Diagnostic {
    Diagnostic::error(
        LATE_UNITS,
        "UNITS after the first move changes the units of the lengths after it, and postc reads a toolpath in one unit",
    )
    .at(span, "the units change here")
    .help("write the whole file in one unit, with UNITS before the first move")
}

pub(crate) fn stray_end_of_path(span: Span) -> Diagnostic {
    Diagnostic::warning(STRAY_END_OF_PATH, "END-OF-PATH without a TOOL PATH before it is ignored").at(span, "ignored")
}

pub(crate) fn out_of_range(span: Span, bad: &postc_ir::limits::OutOfRange, event: &str) -> Diagnostic {
    Diagnostic::error(OUT_OF_RANGE, format!("{}; the toolpath is refused", bad.message(event)))
        .at(span, "this record")
        .note("postc refuses numbers no machine can reach, so that no program carries a word no controller reads (docs/toolpath-format.md, \"Ranges\")")
        .help("correct the record; check the CAM system's units and the operation that wrote it")
}

pub(crate) fn no_fini(span: Span) -> Diagnostic {
    Diagnostic::warning(NO_FINI, "the CL file ends without FINI: it may be cut short, and the program would end early")
        .at(span, "the file ends here")
        .help("post the whole CL file; if it is whole, end it with FINI")
}

pub(crate) fn after_fini(span: Span) -> Diagnostic {
    Diagnostic::warning(AFTER_FINI, "records after FINI are ignored").at(span, "first record after FINI")
}

pub(crate) fn nurbs(span: Span) -> Diagnostic {
    Diagnostic::warning(
        NURBS,
        "NURBS spline motion is not supported: the tool moves straight to the next GOTO instead of along the spline",
    )
    .at(span, "spline")
    .note("the spline records (NURBS, KNOT, CNTRL) pass through as commands; only this first one is reported")
    .help("output the operation as GOTO points (NX: turn off NURBS output in the operation's machine control)")
}

pub(crate) fn eof_continuation(span: Span) -> Diagnostic {
    Diagnostic::warning(EOF_CONTINUATION, "the file ends after a `$`: the last record is read as it stands")
        .at(span, "continued record")
}

pub(crate) fn feed_per_rev(span: Span) -> Diagnostic {
    Diagnostic::warning(
        FEED_PER_REV,
        "a feed per revolution is used before any spindle speed is known; it is passed on as a feed per minute",
    )
    .at(span, "feed per revolution")
}

pub(crate) fn no_feed(span: Span) -> Diagnostic {
    Diagnostic::warning(
        NO_FEED,
        "this cutting move comes before any FEDRAT: the CL file gives it no feed rate, so the program has none for it",
    )
    .at(span, "cuts with no feed rate")
    .help("export the toolpath with its feeds, or add FEDRAT before the first cutting move")
}

pub(crate) fn long_line(span: Span) -> Diagnostic {
    Diagnostic::error(LONG_LINE, "this line (or record continued over lines) is longer than 1 MiB and is skipped")
        .at(span, "it starts here")
}

pub(crate) fn io(span: Span, error: &std::io::Error) -> Diagnostic {
    Diagnostic::error(IO, format!("the CL file cannot be read: {error}")).at(span, "reading stopped here")
}

pub(crate) fn no_indirv(span: Span) -> Diagnostic {
    Diagnostic::warning(
        NO_INDIRV,
        "an arc given with TLON,GOFWD has no INDIRV before it; it is taken as counter-clockwise",
    )
    .at(span, "direction unknown")
}
