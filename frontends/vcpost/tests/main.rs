//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod composites;
mod lowering;
mod modules;
mod robustness;
mod snapshots;
mod table;
