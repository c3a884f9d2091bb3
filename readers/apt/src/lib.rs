//! # postc-reader-apt: the APT CL reader
//!
//! Reads APT CL text files (Siemens NX CLSF, PTC Creo Pro/CLfile,
//! SolidWorks CAM `.apt`, CLT exports, NCL `.as`, classic APT CL) as a
//! stream of toolpath [`Event`](postc_ir::Event)s. See `docs/apt.md` for the
//! full description; this is the summary a maintainer needs.
//!
//! ## Reading
//!
//! [`AptReader`] reads line by line through one reused buffer: a 1 GB file
//! is never held. A statement record is assembled from its lines by the
//! lexer (`$` continuation, `$$` comments, CRLF, trailing blanks) and parsed
//! by a chumsky grammar (`grammar.rs`); text records (`PPRINT`, `PARTNO`,
//! `INSERT`, `REMARK`, `OPFEATSTART`, `OPFEATEND`) are taken as text.
//! Every problem becomes a [`Diagnostic`] with the span of the record (or of
//! the argument) and reading goes on at the next record, so [`check`]
//! reports them all. No input makes the reader panic.
//!
//! ## Records and events
//!
//! | record | event |
//! |---|---|
//! | (start) | `Job`: units from `UNITS`/`UNIT` or the first feed unit, part from `PARTNO`, home from `FROM`, product from Creo's `$$*` line |
//! | `LOADTL/t[,h[,d]]`, `LOAD/TOOL,t[,ADJUST,h]` | `Tool` (diameter from `CUTTER`/`TLDATA`/`$$-> CUTTER`, name from `TOOL PATH/..,TOOL,name`, speed from the next `SPINDL`; `load` keeps the offset registers as written) |
//! | `CUTTER`, `TLDATA` (without a load) | `Tool` when the cutter changes |
//! | `TOOL PATH/name`, `OPFEATSTART/name` | `ToolpathStart` |
//! | `END-OF-PATH`, `OPFEATEND` | `ToolpathEnd` |
//! | moves outside any toolpath | a synthesized `ToolpathStart` (and `ToolpathEnd` at the next tool load or the end) |
//! | `GOTO/x,y,z[,i,j,k]` | `Rapid` after `RAPID`, else `Feed` (Plunge when only Z goes down) |
//! | `CIRCLE/...` + `GOTO` | `Arc` (see `circle.rs` for the vendor conventions) |
//! | `TLON,GOFWD/(CIRCLE/..),ON,(LINE/..)` after `INDIRV` (also `ON,2,INTOF`, and `GOFWD` alone) | `Arc` |
//! | `GODLTA/d` or `/dx,dy,dz` | `Rapid`/`Feed` relative to the current position |
//! | `GOHOME/x,y,z` | `Rapid`; bare `GOHOME` is a `Command` |
//! | `FROM/x,y,z` | sets the position; `Command` |
//! | `RAPID` | the next move only is rapid |
//! | `FEDRAT/f[,unit]`, `FEDRAT/unit,f` | the feed of the following moves (MMPM, IPM, MMPR, IPR), and a `FeedRate` event with the value and unit as written (posts never see it; `postp` reads it) |
//! | `SPINDL/...` | `SpindleOn` / `SpindleOff` |
//! | `COOLNT/...` | `Coolant`, with its placement when `NOW` or `NEXT` is written |
//! | `CUTCOM/LEFT\|RIGHT\|OFF[,n]` | `CutterComp` (`CUTCOM/ON` alone: none) |
//! | `CYCLE/kind,...` + `GOTO`s + `CYCLE/OFF` | `DrillCycle`, `DrillPoint`s, `DrillEnd` |
//! | `DELAY`, `DWELL` | `Dwell` |
//! | `PPRINT`, `REMARK` | `Comment` |
//! | `INSERT` | `Insert` |
//! | `PARTNO` | `Command { word: "PARTNO", args: [Text] }` |
//! | `FINI` | `End`; a file that ends without it (and not right after END-OF-PATH, as NX CLSF files do) may be cut short: warning CL024 |
//! | other post words (`AUXFUN`, `OPSTOP`, `MACHIN`, `PAINT`, ...) | `Command { word, args }` |
//! | unknown words | warning CL005, skipped |
//! | `$$` comments | none (Creo's `$$-> CUTTER / d` gives the tool diameter, `$$*` the product) |
//!
//! Moves carry the feed of the last `FEDRAT` (converted to the job's units
//! per minute; per revolution times the spindle speed) and the last tool
//! axis given (NX writes i,j,k only when it changes; the axis is forgotten
//! at a tool load, `CSYS`/`MSYS`/`TRNTYP` and `MULTAX/OFF`). Events are held
//! in a small window until the header is settled, so that `Job` comes
//! first and a `Tool` before the `ToolpathStart` it belongs to (see
//! `window.rs`).
//!
//! Every event is checked against the ranges of `postc_ir::limits` as it
//! leaves the reader (in the job's units): one out of range is error CL023
//! at its record, which refuses the toolpath.
//!
//! ## What is not CL text
//!
//! A binary CL file (a NUL byte in the head; APT360's 32-bit record
//! layout is named) and an APT part program (an assignment `NAME=WORD/...`,
//! `GO/...`, a motion naming geometry such as `GOTO/PT1`) give exactly one
//! error and no events; see `detect.rs`. [`sniff`] and [`looks_like_cl`]
//! tell them apart from the head of a file.
//!
//! ## Diagnostic codes
//!
//! Its diagnostic codes are declared in the registry `postc_ir::codes`
//! (rendered as docs/diagnostics.md; `postc explain CODE`).

mod circle;
mod cycle;
mod detect;
mod diagnostics;
mod dispatch;
mod grammar;
mod lexer;
mod lines;
mod machine_records;
mod motion;
mod number;
mod reader;
mod state;
mod window;
mod words;

use std::io::BufReader;
use std::path::Path;

use postc_ir::diagnostic::{Diagnostic, SourceMap};
use postc_ir::event::EventSource;
use postc_ir::source::SourceReader;

pub use detect::{Content, sniff};
pub use reader::AptReader;

/// A CL file streamed through the source map's loader.
pub type FileReader = AptReader<BufReader<SourceReader>>;

/// Opens a CL file for streaming (through the source map's loader); spans
/// point into it through `sources`.
pub fn open(path: &Path, sources: &mut SourceMap) -> Result<FileReader, Diagnostic> {
    let file = sources.loader().open(path).map_err(|e| {
        Diagnostic::error(diagnostics::IO, format!("cannot open the CL file {}: {e}", path.display()))
            .help("check the path and that the file can be read")
    })?;
    let id = sources.add_streamed(path.display().to_string());
    Ok(AptReader::new(BufReader::with_capacity(1 << 16, file), id))
}

/// Reads a whole CL file and returns every diagnostic.
pub fn check(path: &Path, sources: &mut SourceMap) -> Vec<Diagnostic> {
    let mut diagnostics = Vec::new();
    match open(path, sources) {
        Ok(mut reader) => while reader.next_event(&mut diagnostics).is_some() {},
        Err(d) => diagnostics.push(d),
    }
    diagnostics
}

/// Whether the APT reader is the reader for a file whose head (its first
/// few KiB) is `head`: CL text, or a binary APT CL file or an APT part
/// program, which the reader refuses with one clear error.
pub fn looks_like_cl(head: &[u8]) -> bool {
    match sniff(head) {
        Content::ClText | Content::PartProgram(..) => true,
        Content::Binary(kind) => kind.contains("APT360"),
        Content::Other => false,
    }
}

/// What the tests of this crate's modules (`tests/modules/`) reach that is
/// not its interface: nothing else uses these.
#[doc(hidden)]
pub mod testing {
    pub mod circle {
        pub use crate::circle::{ArcOutcome, CircleSpec, Convention, V3, build_arc, norm, rotate, unit};
    }
    pub mod grammar {
        pub use crate::grammar::{ItemKind, Shape, record};
    }
    pub mod lexer {
        pub use crate::lexer::{Lexer, RawKind};
    }
    pub mod lines {
        pub use crate::lines::{Lines, find_newline};
    }
    pub mod number {
        pub use crate::number::parse_number;
    }
}
