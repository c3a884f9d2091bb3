//! The crate's integration tests: one test binary, each file of `tests/` a module of it.

mod js_values;
mod modules;
mod seed_listing;
