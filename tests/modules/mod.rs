//! The tests of the library crates without a test binary of their own, one file per module of their `src/`: `tests/modules/CRATE/PATH` holds the tests of `CRATE/src/PATH` (`mod.rs` those of `lib.rs` or `mod.rs`); `tests/modules/cli/` those of the command line's `src/cli/`.

mod backends;
mod cli;
mod driver;
mod fuzz;
mod ir;
mod lint;
mod postp;
mod readers;
mod report;
mod verify;
