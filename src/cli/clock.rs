//! The clock, read at the edge: the runtime takes "now" as an input
//! ([`postc_runtime::RunOptions::now`]) and never reads it itself; the
//! reading (`SOURCE_DATE_EPOCH` or the system clock) is `postc_report::now`,
//! shared with the Python package.

pub use postc_report::now;

/// Run options with "now" read from the clock.
pub fn run_options() -> postc_runtime::RunOptions {
    postc_runtime::RunOptions { now: Some(now()), ..postc_runtime::RunOptions::default() }
}
