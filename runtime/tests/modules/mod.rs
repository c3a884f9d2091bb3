//! The tests of this crate's modules, one file per module of `src/`: `tests/modules/PATH` holds the tests of `src/PATH` (`mod.rs` those of `lib.rs` or of a folder's `mod.rs`).

mod clock;
mod geometry;
mod interp;
mod js;
mod machine;
mod number;
mod output;
mod prepare;
mod regex;
mod sections;
mod units;
mod value;
