//! postc frontends: finds the dialect of a post or the format of a toolpath
//! and hands the file to the frontend crate that reads it.
//!
//! - `postc-front-vectric` (`frontends/vectric`): Vectric `.pp` posts;
//! - `postc-front-cimco` (`frontends/cimco`): CIMCO CNC-Calc JavaScript posts;
//! - `postc-front-vcpost` (`frontends/vcpost`): Vericut VcPost posts;
//! - `postc-front-apt` (`frontends/apt`): APT CL toolpaths;
//! - [`native`] (here): the native toolpath stream, RON or JSON Lines.

pub mod native;
