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
