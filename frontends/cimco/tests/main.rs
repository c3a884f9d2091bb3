//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod grammar;
mod lowering;
mod modules;
mod robustness;
mod roundtrip;
mod snapshots;
