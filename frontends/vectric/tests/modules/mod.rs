//! The tests of this crate's modules, one file per module of `src/`: `tests/modules/PATH` holds the tests of `src/PATH` (`mod.rs` those of `lib.rs` or of a folder's `mod.rs`).

mod decode;
mod defaults;
mod detect;
mod diagnostics;
mod format_spec;
mod parser;
mod revision;
