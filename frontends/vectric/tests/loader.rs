//! `POST_BASE` files come through the source map's loader: a post and its
//! base held in memory compile as they do from disk, and a base the loader
//! does not have is the same PP019 warning as a missing file.

use std::path::Path;
use std::sync::Arc;

use postc_ir::{MemoryLoader, SourceMap};

const BASE: &str = "POST_NAME = \"Base (mm) (*.nc)\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nbegin FOOTER\n\"M30\"\n";
const DERIVED: &str = "POST_NAME = \"Derived\"\nPOST_BASE = \"BASE.PP\"\nbegin HEADER\n\"(derived)\"\n";

fn compile(sources: &mut SourceMap) -> (postc_ir::Post, Vec<postc_ir::Diagnostic>) {
    postc_front_vectric::compile(Path::new("posts/derived.pp"), DERIVED.as_bytes(), sources)
}

#[test]
fn a_base_in_memory_is_read_through_the_loader() {
    let mut files = MemoryLoader::new();
    // The name differs in case from POST_BASE's: found as on Windows.
    files.insert("posts/base.pp", BASE);
    let mut sources = SourceMap::with_loader(Arc::new(files));
    let (post, diagnostics) = compile(&mut sources);
    assert!(diagnostics.is_empty(), "{diagnostics:?}");
    assert_eq!(post.info.file_extension, "nc");
    assert!(sources.len() == 2 && sources.name(postc_ir::FileId(1)) == "posts/base.pp");
}

#[test]
fn a_base_the_loader_lacks_is_pp019() {
    for mut sources in [SourceMap::new(), SourceMap::with_loader(Arc::new(MemoryLoader::new()))] {
        let (_, diagnostics) = compile(&mut sources);
        let [d] = diagnostics.as_slice() else { panic!("{diagnostics:?}") };
        assert_eq!(d.code, "PP019");
        assert_eq!(d.message, "cannot read the POST_BASE file posts/BASE.PP: there is no such file");
    }
}

/// A base is read only when it is a regular file of at most 16 MiB: a
/// name that points at a folder (or a device such as `/dev/urandom`,
/// which would be read without end) or at a file too large to be a post
/// is PP019, and nothing of it is read.
#[test]
fn a_base_that_is_no_regular_file_or_too_large_is_pp019() {
    let mut folder = MemoryLoader::new();
    folder.insert("posts/BASE.PP/inside.pp", BASE);
    let mut large = MemoryLoader::new();
    large.insert("posts/BASE.PP", vec![b'+'; (16 << 20) + 1]);
    for (files, why) in [
        (folder, "it is not a regular file (a folder, a device or a pipe), so it is not read"),
        (large, "it is larger than 16 MiB, more than any post"),
    ] {
        let mut sources = SourceMap::with_loader(Arc::new(files));
        let (_, diagnostics) = compile(&mut sources);
        let [d] = diagnostics.as_slice() else { panic!("{diagnostics:?}") };
        assert_eq!(d.code, "PP019");
        assert_eq!(d.message, format!("cannot read the POST_BASE file posts/BASE.PP: {why}"));
        assert_eq!(sources.len(), 1, "the base was not registered");
    }
}
