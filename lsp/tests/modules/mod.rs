//! The tests of this crate's modules, one file per module of `src/`: `tests/modules/PATH` holds the tests of `src/PATH` (`mod.rs` those of `lib.rs` or of a folder's `mod.rs`).

mod analysis;
mod text;
mod vocab;

use postc_ir::Dialect;
use postc_lsp::testing::dialect_of;
use postc_lsp::*;
use std::path::PathBuf;

#[test]
fn file_uris_become_paths() {
    assert_eq!(path_of("file:///home/a/Pi%C3%A8ce%201.pp"), PathBuf::from("/home/a/Pièce 1.pp"));
    assert_eq!(path_of("file:///C:/posts/x.pp"), PathBuf::from("C:/posts/x.pp"));
    assert_eq!(path_of("untitled:Untitled-1"), PathBuf::from("untitled:Untitled-1"));
    assert_eq!(path_of("file:///a%2"), PathBuf::from("/a%2"));
}

#[test]
fn dialects_from_extensions() {
    assert_eq!(dialect_of("file:///a/b.PP"), Some(Dialect::Vectric));
    assert_eq!(dialect_of("file:///a/b.VcPost"), Some(Dialect::VcPost));
    assert_eq!(dialect_of("file:///a/b.js"), Some(Dialect::Cimco));
    assert_eq!(dialect_of("file:///a/haas.CPS"), Some(Dialect::Fusion));
    assert_eq!(dialect_of("file:///a.d/b"), None);
}
