//! The tests of this crate's modules, one file per module of `src/`: `tests/modules/PATH` holds the tests of `src/PATH` (`mod.rs` those of `lib.rs` or of a folder's `mod.rs`).

mod composites;
mod csv;
mod diagnostics;
mod keywords;
mod lexer;
mod lower;
mod parser;
mod registers;
