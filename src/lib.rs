//! The `postc` command-line tool, as a library so that benchmarks and tests
//! can drive the same code the binary runs.
//!
//! - [`cli`]: argument parsing and one module per subcommand (`post`,
//!   `check`, `inspect`, `bench`, `toolpath gen`);
//! - [`library`]: the posts embedded in the binary: the G-code post
//!   `postc post` uses when given only a toolpath, and the post library.

pub mod cli;
pub mod library;
