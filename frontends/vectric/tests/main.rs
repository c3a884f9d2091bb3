//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod corpus;
mod loader;
mod modules;
mod mutations;
mod snapshots;
