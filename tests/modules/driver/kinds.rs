//! What a file given to `post`, `check` or `lint` is taken for: a post's
//! extension names its dialect whatever its lines look like.

use postc_driver::{dialect_of_extension, is_toolpath, toolpath_format};
use postc_ir::Dialect;
use std::path::Path;

/// A Fusion post whose statements read like APT geometry definitions
/// (`SM = stockToLeave / 3;`, as konkers' `roeders_rms6.cps` and DATRON's
/// posts have) is a post, not an APT part program.
#[test]
fn a_post_extension_names_a_post_whatever_its_lines_look_like() {
    let dir = tempfile::tempdir().unwrap();
    let text = "description = \"Roeders\";\nvar SM;\nfunction onOpen() {\n    SM = stockToLeave / 3;\n    P1 = POINT / 1, 2, 3;\n}\n";
    // Read by its lines alone, it is an APT file.
    assert!(toolpath_format(Path::new("roeders"), text.as_bytes()).is_some());
    for name in ["roeders.cps", "ROEDERS.CPS", "post.js", "post.pp", "post.vcpost"] {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        assert!(!is_toolpath(&path, &postc_report::FsLoader), "{name} taken for a toolpath");
    }
    let cl = dir.path().join("part.apt");
    std::fs::write(&cl, "PARTNO/X\nGOTO/1,2,3\nFINI\n").unwrap();
    assert!(is_toolpath(&cl, &postc_report::FsLoader));
}

#[test]
fn each_post_extension_names_one_dialect() {
    let of = |p: &str| dialect_of_extension(Path::new(p));
    assert_eq!(of("a.cps"), Some(Dialect::Fusion));
    assert_eq!(of("a.CPS"), Some(Dialect::Fusion));
    assert_eq!(of("a.pp"), Some(Dialect::Vectric));
    assert_eq!(of("a.js"), Some(Dialect::Cimco));
    assert_eq!(of("a.VcPost"), Some(Dialect::VcPost));
    assert_eq!(of("a.ron"), Some(Dialect::Ron));
    assert_eq!(of("a.apt"), None);
    assert_eq!(of("cps"), None);
}

/// A folder given as the toolpath is said to be one.
#[test]
fn a_folder_is_no_toolpath() {
    let dir = tempfile::tempdir().unwrap();
    let mut sources = postc_report::source_map();
    let Err(d) = postc_driver::open_toolpath(dir.path(), &mut sources) else { panic!("a folder opened as a toolpath") };
    assert_eq!(d.code, "IO001");
    assert!(d.message.contains("is a folder"), "{}", d.message);
}
