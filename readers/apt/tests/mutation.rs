//! Mutated CL text never makes the reader panic or hang: byte flips,
//! deletions, insertions of random lines and truncation of real and
//! hand-written CL files, read to the end every time.

use std::path::Path;

use proptest::prelude::*;

/// Seeds: the hand-written fixtures and a slice of two corpus files.
fn seeds() -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let mut seeds: Vec<Vec<u8>> =
        std::fs::read_dir(dir).into_iter().flatten().flatten().filter_map(|e| std::fs::read(e.path()).ok()).collect();
    if let Some(corpus) = crate::common::corpus_dir() {
        for name in [
            "MichaHofft__CreoPost/profilfraesen_2.ncl.2",
            "HumMan__CLSFProcessor/cutcom.clsf",
            "aamorim1913__AptPostProcessor/Interface-glue.clt",
        ] {
            if let Ok(bytes) = std::fs::read(corpus.join(name)) {
                seeds.push(bytes[..bytes.len().min(6000)].to_vec());
            }
        }
    }
    seeds.sort();
    seeds
}

/// One edit of a CL text.
#[derive(Clone, Debug)]
enum Edit {
    Flip { at: usize, byte: u8 },
    Delete { at: usize, len: usize },
    InsertLine { at: usize, line: String },
    Truncate { at: usize },
}

fn edit() -> impl Strategy<Value = Edit> {
    let cl_bytes = prop::sample::select(b"$/,()=. -+0123456789EDGOTCIRLFAPXYZ\t\r\n\0\xff".to_vec());
    let line = "[A-Z]{1,8}(/| )?[-0-9.,A-Z ()$=*]{0,40}";
    prop_oneof![
        (any::<usize>(), prop_oneof![cl_bytes, any::<u8>()]).prop_map(|(at, byte)| Edit::Flip { at, byte }),
        (any::<usize>(), 1usize..64).prop_map(|(at, len)| Edit::Delete { at, len }),
        (any::<usize>(), line).prop_map(|(at, line)| Edit::InsertLine { at, line }),
        any::<usize>().prop_map(|at| Edit::Truncate { at }),
    ]
}

fn apply(text: &mut Vec<u8>, edit: &Edit) {
    let pick = |at: usize, len: usize| if len == 0 { 0 } else { at % (len + 1) };
    match edit {
        Edit::Flip { at, byte } => {
            if !text.is_empty() {
                let i = at % text.len();
                text[i] = *byte;
            }
        }
        Edit::Delete { at, len } => {
            let i = pick(*at, text.len());
            let end = (i + len).min(text.len());
            text.drain(i..end);
        }
        Edit::InsertLine { at, line } => {
            let i = pick(*at, text.len());
            let mut bytes = line.clone().into_bytes();
            bytes.push(b'\n');
            text.splice(i..i, bytes);
        }
        Edit::Truncate { at } => {
            let i = pick(*at, text.len());
            text.truncate(i);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(512)))]

    #[test]
    fn mutated_cl_never_panics_or_hangs(seed in any::<prop::sample::Index>(), edits in prop::collection::vec(edit(), 1..12)) {
        let seeds = seeds();
        let mut text = seeds[seed.index(seeds.len())].clone();
        for e in &edits {
            apply(&mut text, e);
        }
        let read = crate::common::read_bytes("mutated.cl", &text);
        // Every event comes from a record; a tilted arc makes at most 10000 moves.
        prop_assert!(read.events.len() <= 10_001 * (text.len() + 2));
        for d in &read.diagnostics {
            prop_assert!(!d.code.is_empty());
            if let Some(span) = d.primary_span() {
                prop_assert!(span.start <= span.end && span.end <= text.len() + 1, "{:?} outside the text", d);
            }
        }
        for (_, span) in &read.events {
            prop_assert!(span.end <= text.len() + 1);
        }
        crate::common::check_order("mutated", &read.events, read.codes().contains(&"CL002"));
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..2000)) {
        let _ = crate::common::read_bytes("random.cl", &bytes);
    }

    #[test]
    fn random_records_never_panic(lines in prop::collection::vec("(GOTO|CIRCLE|CYCLE|RAPID|END-OF-PATH|TOOL PATH|LOADTL|[A-Z]{1,6})(/[-0-9.,A-Z ()$]{0,30})?", 0..40)) {
        let text = lines.join("\n");
        let read = crate::common::read_text(&text);
        crate::common::check_order("random", &read.events, read.codes().contains(&"CL002"));
    }
}
