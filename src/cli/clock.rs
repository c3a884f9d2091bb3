//! The clock, read at the edge: the runtime takes "now" as an input
//! ([`postc_runtime::RunOptions::now`]) and never reads it itself; the
//! reading is `postc_driver::settings::now`, shared with the Python package.

pub use postc_driver::settings::now;

/// Run options with "now" read from the clock.
pub fn run_options() -> postc_runtime::RunOptions {
    postc_runtime::RunOptions { now: Some(now()), ..postc_runtime::RunOptions::default() }
}
