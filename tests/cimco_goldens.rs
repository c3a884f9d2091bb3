//! CIMCO corpus goldens: posts every CIMCO post of `corpus/posts/cimco/`
//! over its toolpaths (milling posts: `corpus/toolpaths/cimco/mill.ron`,
//! `drill.ron` and `standard.ron`; lathe posts: `cimco/lathe.ron`) and
//! compares the program, byte for byte, with the committed file
//! `corpus/expected/cimco/POST__TOOLPATH.nc`.
//!
//! Every post must compile with no diagnostic at all (the corpus must
//! `postc check` clean), and the acceptance post `fanuc_mill.js` must run
//! `onLinear` and `onCircular` natively.
//!
//! `POSTC_BLESS=1 cargo test --test suite cimco_goldens` rewrites the expected
//! files from the current output and deletes the ones no pair makes.

use crate::support::cimco::*;
use crate::support::prepared::*;
use crate::support::{Goldens, all_files};
use postc_ir::Body;

#[test]
fn cimco_posts_match_their_goldens() {
    let expected_dir = corpus().join("expected/cimco");
    let posts = posts();
    assert!(posts.len() >= 7, "the corpus has {} CIMCO posts", posts.len());
    let mut goldens = Goldens::new();
    for post_path in &posts {
        let post = match compile(post_path) {
            Ok(p) => p,
            Err(e) => {
                goldens.fail(e);
                continue;
            }
        };
        for toolpath in toolpaths(&post) {
            let pair = format!("{}__{}", stem(post_path), stem(&toolpath));
            let program = match post_toolpath(&post, &toolpath) {
                Ok(p) => p,
                Err(e) => {
                    goldens.fail(format!("{pair}: {e}"));
                    continue;
                }
            };
            goldens.check(&expected_dir.join(format!("{pair}.{}", post.info.file_extension)), &program);
        }
    }
    goldens.sweep(all_files(&expected_dir), "no post and toolpath make this file any more");
    goldens.finish("CIMCO goldens", "cimco_goldens");
}

#[test]
fn fanuc_moves_are_native() {
    let post = compile(&corpus().join("posts/cimco/fanuc_mill.js")).expect("fanuc_mill.js compiles");
    for name in ["onLinear", "onCircular", "writeBlock", "getCompensation", "feedWord"] {
        let f = post.functions.iter().find(|f| f.name == name).unwrap_or_else(|| panic!("no {name}"));
        assert!(matches!(f.body, Body::Native(_)), "{name} is not native");
    }
    // The IR says what a move handler means: it writes what its entry
    // point returns. The runtime's preparation builds that text in the
    // output instead: no `Write` left, no string allocated per move.
    let code = postc_runtime::prepare::prepare(&post);
    for (h, prepared) in post.handlers.iter().zip(&code.handlers) {
        if let postc_ir::HandlerKey::Section(
            s @ (postc_ir::Section::FeedMove | postc_ir::Section::RapidMove | postc_ir::Section::CwArcMove),
        ) = h.key
        {
            assert!(
                matches!(h.body.first(), Some(postc_ir::Stmt::Write(postc_ir::Expr::Call(..)))),
                "{s:?} in the IR: {:?}",
                h.body
            );
            let writes = count_stmts(prepared, &|s| matches!(s, XStmt::Write(_)));
            assert_eq!(writes, 0, "{s:?} still writes a returned string: {prepared:?}");
            assert!(count_stmts(prepared, &|s| matches!(s, XStmt::Emit(_))) > 0, "{s:?} does not emit");
        }
    }
}
