//! The `postc` command-line tool, as a library so that benchmarks and tests
//! can drive the same code the binary runs.
//!
//! - [`cli`]: argument parsing and one module per subcommand (`post`,
//!   `check`, `inspect`, `bench`, `toolpath gen`);
//! - [`synthetic`]: generated toolpaths of any length;
//! - [`postp`]: the APT CL post processor `postp` (`postc postp DIR`), reimplemented, and
//!   its eight controllers;
//! - [`default_post`]: the G-code post embedded in the binary, used when
//!   `postc post` is given only a toolpath.

pub mod cli;
pub mod default_post;
pub mod postp;
pub mod synthetic;
