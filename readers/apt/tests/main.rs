//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod common;
mod corpus;
mod dump;
mod fixtures;
mod modules;
mod mutation;
