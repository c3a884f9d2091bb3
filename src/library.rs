//! The posts embedded in the binary (docs/posts.md): the generic G-code
//! post `postc post TOOLPATH` uses when no post is named
//! (`corpus/posts/vectric/gcode_mm.pp`), and the library the project
//! writes itself for common controllers (`corpus/posts/library/`), which
//! `postc posts` lists and `postc post --post NAME` selects by name.

/// One embedded post: the file name diagnostics show (`<embedded>/FILE`)
/// and its text.
#[derive(Debug, Clone, Copy)]
pub struct Embedded {
    pub name: &'static str,
    pub text: &'static [u8],
}

macro_rules! embedded {
    ($file:literal, $path:literal) => {
        Embedded { name: concat!("<embedded>/", $file), text: include_bytes!(concat!("../corpus/posts/", $path)) }
    };
}

/// Every embedded post, the default first.
pub const EMBEDDED: &[Embedded] = &[
    embedded!("gcode_mm.pp", "vectric/gcode_mm.pp"),
    embedded!("linuxcnc.pp", "library/linuxcnc.pp"),
    embedded!("grbl.pp", "library/grbl.pp"),
    embedded!("mach3.pp", "library/mach3.pp"),
    embedded!("fanuc.js", "library/fanuc.js"),
    embedded!("haas.js", "library/haas.js"),
    embedded!("heidenhain.pp", "library/heidenhain.pp"),
    embedded!("sinumerik.pp", "library/sinumerik.pp"),
    embedded!("hpgl.pp", "library/hpgl.pp"),
];

/// The post `postc post TOOLPATH` uses when no post is named.
pub const DEFAULT: Embedded = EMBEDDED[0];
