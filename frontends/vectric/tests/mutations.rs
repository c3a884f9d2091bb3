//! Robustness: random mutations of valid posts (byte flips, deletions,
//! insertions, truncations) never panic, always return, and every
//! diagnostic renders.

use postc_report::Render as _;
use std::path::Path;

use proptest::prelude::*;
use proptest::sample::Index;

const POSTS: &[&[u8]] = &[
    include_bytes!("fixtures/valid/seed_gcode_atc_arcs_inch.pp"),
    include_bytes!("fixtures/valid/sections.pp"),
    include_bytes!("fixtures/valid/formats.pp"),
    include_bytes!("fixtures/valid/all_globals.pp"),
    include_bytes!("fixtures/valid/lua_script.pp"),
    include_bytes!("fixtures/valid/windows_1252.pp"),
];

/// Bytes that matter to the grammar, inserted more often than chance would.
const INTERESTING: &[&[u8]] = &[
    b"[",
    b"]",
    b"|",
    b"\"",
    b"=",
    b"+",
    b"\r",
    b"\n",
    b"\r\n",
    b"\t",
    b" ",
    b"VAR ",
    b"begin ",
    b"SCRIPT\n",
    b"ENDSCRIPT",
    b"<!>",
    b"[300]",
    b"[13]",
    b"POST_BASE = \"x.pp\"\n",
    b"\xef\xbb\xbf",
    b"\xe4",
    b"\xc3\xa4",
    b"\xff",
];

#[derive(Clone, Debug)]
enum Mutation {
    Flip(Index, u8),
    Delete(Index, usize),
    Insert(Index, Vec<u8>),
    Truncate(Index),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<Index>(), 0u8..8).prop_map(|(i, bit)| Mutation::Flip(i, bit)),
        (any::<Index>(), 1usize..40).prop_map(|(i, n)| Mutation::Delete(i, n)),
        (any::<Index>(), prop::sample::select(INTERESTING)).prop_map(|(i, b)| Mutation::Insert(i, b.to_vec())),
        (any::<Index>(), prop::collection::vec(any::<u8>(), 1..8)).prop_map(|(i, b)| Mutation::Insert(i, b)),
        any::<Index>().prop_map(Mutation::Truncate),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    let len = bytes.len();
    match m {
        Mutation::Flip(i, bit) if len > 0 => bytes[i.index(len)] ^= 1 << bit,
        Mutation::Delete(i, n) if len > 0 => {
            let at = i.index(len);
            bytes.drain(at..(at + n).min(len));
        }
        Mutation::Insert(i, b) => {
            let at = i.index(len + 1);
            bytes.splice(at..at, b.iter().copied());
        }
        Mutation::Truncate(i) => bytes.truncate(i.index(len + 1)),
        _ => {}
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn mutated_posts_never_panic(post in 0..POSTS.len(), mutations in prop::collection::vec(mutation(), 1..10)) {
        let mut bytes = POSTS[post].to_vec();
        for m in &mutations {
            apply(&mut bytes, m);
        }
        let mut sources = postc_report::source_map();
        let (_post, diagnostics) =
            postc_front_vectric::compile(Path::new("tests/fixtures/valid/mutant.pp"), &bytes, &mut sources);
        let _ = sources.render(&diagnostics, false);
        for d in &diagnostics {
            prop_assert!(!d.labels.is_empty(), "diagnostic without a span: {d:?}");
            let _ = sources.to_json(d, "mutant.pp");
        }
        let _ = postc_front_vectric::looks_like_vectric(&bytes);
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[\\PC\\r\\n\\t\\[\\]|\"=+%]{0,300}") {
        let mut sources = postc_report::source_map();
        let file = sources.add("arbitrary.pp", text.clone());
        let (_ast, diagnostics) = postc_front_vectric::parse(&text, file);
        let _ = sources.render(&diagnostics, false);
    }
}
