use postc_ir::source::*;
use std::ffi::OsString;
use std::io::{self};
use std::path::Path;

#[test]
fn memory_files() {
    let mut m = MemoryLoader::new();
    m.insert("posts/a.pp", b"abcdef".to_vec());
    assert_eq!(m.read(Path::new("posts/a.pp")).unwrap(), b"abcdef");
    assert_eq!(m.read_at(Path::new("posts/a.pp"), 2, 3).unwrap(), b"cde");
    assert_eq!(m.read_at(Path::new("posts/a.pp"), 5, 9).unwrap(), b"f");
    assert!(m.exists(Path::new("posts")));
    assert_eq!(m.read_dir(Path::new("posts")).unwrap(), [OsString::from("a.pp")]);
    assert_eq!(m.read(Path::new("b.pp")).unwrap_err().kind(), io::ErrorKind::NotFound);
    assert!(!NoFiles.exists(Path::new("posts/a.pp")));
}
