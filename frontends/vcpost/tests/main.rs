//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod composites;
mod lowering;
mod robustness;
mod snapshots;
mod table;
