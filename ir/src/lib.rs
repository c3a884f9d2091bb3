//! # The postc IR
//!
//! postc reads post processors written in three vendor dialects (Vectric
//! `.pp`, CIMCO CNC-Calc JavaScript, Vericut VcPost) and toolpaths in two
//! families (APT CL files, the native RON / JSON Lines stream). Every
//! frontend lowers into the types of this crate; the runtime and every
//! backend read only these types. Nothing downstream of a frontend ever sees
//! a dialect's syntax tree.
//!
//! ## Posts
//!
//! A [`Post`] is what one post file compiles to. It holds:
//!
//! - [`PostInfo`]: name, dialect of origin, output file extension and
//!   units, and the [`Dispatch`] model that says how events reach handlers;
//! - [`OutputOptions`]: the shape of the output that is not code: the line
//!   ending, block numbering (start, increment, maximum), character
//!   substitution in variable text, tape splitting, spindle-speed ranges,
//!   rotary wrapping, arc radius limits, inverse-time feed, the chord
//!   tolerance of linearized arcs, exact arc words, the step budget that
//!   stops runaway loops;
//! - [`NumberFormat`]s: how numbers print (see below);
//! - [`Variable`]s: named outputs that tie a value source to a prefix, a
//!   format and a [`Modality`];
//! - [`Global`]s and [`Function`]s for the dialects that have code;
//! - `init`: statements run once before the first event;
//! - [`Handler`]s: what the post does for each kind of event;
//! - [`Script`]s: code the IR does not express, kept with a span map back
//!   into the post file so that every error in it points at the post.
//!
//! ## Handlers
//!
//! A handler is a list of [`Stmt`]s keyed by a [`HandlerKey`]. Under
//! [`Dispatch::Sections`] the key is a [`Section`], named after the Vectric
//! sections (`HEADER`, `RAPID_MOVE`, `FIRST_FEED_MOVE`, `CW_ARC_MOVE`, ...)
//! plus the events Vectric has no section for (coolant, drilling cycles,
//! cutter compensation). The runtime picks the section for each event and
//! falls back when a post lacks it: a missing `FIRST_FEED_MOVE` uses
//! `FEED_MOVE`, a missing arc section linearizes the arc into feed moves, a
//! missing `DWELL_MOVE` skips the dwell. Under [`Dispatch::AptWords`] each
//! event becomes APT records and the key is the record's major word
//! (`GOTO`, `FEDRAT`, `LOADTL`), which is how VcPost milling posts work.
//!
//! A Vectric section body is a list of [`Stmt::Line`]s, each a list of
//! [`Piece`]s: literal bytes and variables. That is the whole hot path:
//! for a move, the runtime finds the section, and for each line writes the
//! literal bytes and formats each variable into the output buffer, with no
//! allocation. The other dialects use the rest of the statement language
//! (assignments, `if`, loops, calls, returns over numbers, text and
//! booleans); code that does not lower runs as a script.
//!
//! ## Number formats
//!
//! One [`NumberFormat`] describes how a number prints in every dialect:
//! decimals, minimum width (counted over the whole text as Vectric does, or
//! over the integer digits as CIMCO does), blank or zero padding, left or
//! right justification, forced sign, the decimal mark (`.` or `,`), when the
//! mark is written, trailing-zero trimming, the leading zero, a multiplier
//! applied before rounding, and a prefix. Rounding is half away from zero on
//! the decimal value of the number, so 2.675 prints 2.68 at two decimals;
//! a value that rounds to zero prints without a sign.
//!
//! ## Variables and modal state
//!
//! A [`Variable`] prints its value with its prefix and format. A
//! [`Modality::OnChange`] variable prints only when its formatted text
//! differs from the text it printed last; an `Always` variable prints every
//! time. All modal memory is cleared when a toolpath starts, so the first
//! move of each toolpath prints every word. Values come from a
//! [`Quantity`] (the runtime's current position, arc geometry, feeds, tool
//! and job data, converted to the post's units) or are assigned by the
//! post's code (CIMCO output variables, VcPost registers), which also keeps
//! the previous value (`.Previous`, `getLast()`).
//!
//! ## Toolpath events
//!
//! A toolpath is a stream of [`Event`]s: job data, tools, toolpath starts
//! and ends, rapid, feed and arc moves with their intent, dwells, spindle,
//! jet, coolant, cutter compensation, drilling cycles, comments, inserts and
//! pass-through post commands. [`EventSource`] is what every reader
//! implements; the runtime pulls events one at a time, so memory stays flat
//! whatever the toolpath's length.
//!
//! ## Sub calls
//!
//! VcPost's probe-cycle tables and composites event files are not toolpaths:
//! each record names a Sub and the variables to set before calling it. Their
//! readers produce [`SubCall`]s through a [`CallSource`] (module [`calls`]).
//!
//! ## Diagnostics
//!
//! [`Diagnostic`] is the one error type of the project: a code, a severity,
//! a message, labels over byte [`Span`]s of files in a [`SourceMap`], notes
//! and help. The IR only holds it: the command line renders it (for people,
//! and as JSON) through `postc_report`. Files
//! beyond the bytes a frontend is given are read through the map's
//! [`SourceLoader`] (module [`source`]), which the caller provides.

pub mod calls;
pub mod code;
pub mod codes;
pub mod diagnostic;
pub mod event;
pub mod format;
pub mod id;
pub mod js;
pub mod limits;
pub mod outline;
pub mod post;
pub mod quantity;
pub mod source;
pub mod units;
pub mod validate;
pub mod visit;

pub use calls::{CallSource, CallValue, MissingSub, SubCall, SubParam, SubSignature, SubTip};
pub use code::{BinaryOp, Builtin, Expr, OutputRef, Piece, Place, Site, Stmt, UnaryOp};
pub use diagnostic::{Diagnostic, FileId, Label, Severity, SourceMap, Span};
pub use event::{Event, EventSource};
pub use format::{Justify, NumberFormat, Padding, PointStyle, Rounding, SignStyle, WidthOf};
pub use id::{FormatId, FunctionId, GlobalId, LocalId, ScriptId, VarId};
pub use post::{
    Body, CallList, Comment, CommentTarget, Dialect, Dispatch, Function, Global, Handler, HandlerKey, Modality,
    OutputOptions, Post, PostInfo, Script, ScriptLanguage, ScriptReason, Section, SourceText, TextEncoding,
    ValueSource, Variable,
};
pub use quantity::{Dimension, Quantity};
pub use source::{MemoryLoader, NoFiles, SourceLoader};
pub use units::Units;
