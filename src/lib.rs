//! The `postc` command-line tool, as a library so that benchmarks and tests
//! can drive the same code the binary runs.
//!
//! - [`cli`]: argument parsing and one module per subcommand (`post`,
//!   `check`, `inspect`, `bench`, `toolpath gen`);
//! - [`default_post`]: the G-code post embedded in the binary, used when
//!   `postc post` is given only a toolpath.

pub mod cli;
pub mod default_post;
