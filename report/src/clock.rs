//! The clock, read at the edge: the runtime takes "now" as an input
//! (`postc_runtime::RunOptions::now`) and never reads it itself; the
//! command line and the Python package read it here.

use std::time::{SystemTime, UNIX_EPOCH};

/// Now as a Unix time in seconds, or the time `SOURCE_DATE_EPOCH` names
/// when it is set (the reproducible-builds convention): what `[DATE]` and
/// `[TIME]` print when neither the job nor a setting gives them.
pub fn now() -> i64 {
    std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.trim().parse::<i64>().ok())
        .unwrap_or_else(|| SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs() as i64))
}
