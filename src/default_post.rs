//! The post `postc post TOOLPATH` uses when no post is named: a generic
//! G-code post in millimetres (`corpus/posts/vectric/gcode_mm.pp`), embedded
//! in the binary so a fresh install can post a toolpath straight away.

/// The file name diagnostics show for the embedded post.
pub const NAME: &str = "<embedded>/gcode_mm.pp";

/// The embedded post's text.
pub const TEXT: &[u8] = include_bytes!("../corpus/posts/vectric/gcode_mm.pp");
