//! What postc adds to every compiled CIMCO post, by name: the functions
//! that are not the post's own (its start-up code, the bridges that hand
//! an entry point the host's data, `getFeedrate` when the post has none,
//! the forms of a function for each number of arguments, named
//! `name/N`) and the output variables of that `getFeedrate`. The lowering
//! makes them under these names;
//! the CIMCO backend leaves them out of the JavaScript it prints, since
//! compiling that JavaScript makes them again.

/// The post's top-level code, run once at start.
pub const INIT: &str = "__postc_init";
/// The bridge to `onCompensation`.
pub const COMPENSATION: &str = "__postc_compensation";
/// The bridge to `onDrillingHeader`.
pub const DRILL_HEADER: &str = "__postc_drilling_header";
/// The bridge to `onDrilling`.
pub const TURN_DRILL: &str = "__postc_drilling";
/// The host's `getFeedrate`, which postc adds when the post has none.
pub const FEEDRATE: &str = crate::host_names::GET_FEEDRATE;
/// The output variables postc's `getFeedrate` formats through (per minute,
/// per revolution).
pub use crate::host_names::{FEED_REV_VAR, FEED_VAR};

/// The name of the form of function `name` for calls with `arity` arguments.
pub fn specialization(name: &str, arity: usize) -> String {
    format!("{name}/{arity}")
}

/// The post function a function postc made is a form of: `writeBlock` for
/// `writeBlock/5`; `None` for a name without a number of arguments.
pub fn specialized(name: &str) -> Option<&str> {
    let (base, arity) = name.rsplit_once('/')?;
    (!arity.is_empty() && arity.bytes().all(|b| b.is_ascii_digit())).then_some(base)
}
