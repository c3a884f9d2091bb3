//! `postp` never panics: the demo CL file with lines dropped, duplicated,
//! cut short or replaced by postp words with random arguments posts or
//! fails with diagnostics, on every controller.

use crate::support::postp;

use postc_postp::Controller;
use proptest::prelude::*;

const WORDS: &[&str] = &[
    "AUXFUN", "CLEARP", "CLRSRF", "COOLNT", "CUTCOM", "DELAY", "DELETE", "END", "FEDRAT", "GOHOME", "GOTO", "CIRCLE",
    "LETTER", "LOADTL", "MODE", "OPSKIP", "ORIGIN", "PPRINT", "PREFUN", "RAPID", "RETRCT", "ROTABL", "SEQNO", "SPINDL",
    "THREAD", "TMARK", "TRANS", "TURRET", "CYCLE", "MACHIN",
];
const ARGS: &[&str] = &[
    "0",
    "-1",
    "1e9",
    "54.3",
    "91",
    "NOW",
    "NEXT",
    "ON",
    "OFF",
    "LINEAR",
    "AAXIS",
    "INCR",
    "ATANGL",
    "XYPLAN",
    "RADIUS",
    "SFM",
    "MAXRPM",
    "IPR",
    "REV",
    "(PLANE/0,0,1,2)",
    "NOMORE",
    "CLW",
    "",
];

fn demo() -> Vec<String> {
    let text = std::fs::read_to_string(postp::root().join("corpus/toolpaths/apt/postp_demo.apt")).unwrap();
    text.lines().map(String::from).collect()
}

#[derive(Clone, Debug)]
enum Edit {
    Drop(usize),
    Repeat(usize),
    Cut(usize, usize),
    Word(usize, usize, Vec<usize>),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        any::<usize>().prop_map(Edit::Drop),
        any::<usize>().prop_map(Edit::Repeat),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Edit::Cut(a, b)),
        (any::<usize>(), any::<usize>(), prop::collection::vec(any::<usize>(), 0..12))
            .prop_map(|(a, b, c)| Edit::Word(a, b, c)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn mutated_cl_files_never_panic(edits in prop::collection::vec(edit(), 1..6), machine in 0usize..8) {
        let mut lines = demo();
        for e in edits {
            let n = lines.len().max(1);
            match e {
                Edit::Drop(i) if !lines.is_empty() => { lines.remove(i % n); }
                Edit::Repeat(i) if !lines.is_empty() => { let l = lines[i % n].clone(); lines.insert(i % n, l); }
                Edit::Cut(i, k) if !lines.is_empty() => {
                    let l = &mut lines[i % n];
                    let at = (k % (l.len() + 1)).min(l.len());
                    if l.is_char_boundary(at) { l.truncate(at); }
                }
                Edit::Word(i, w, args) => {
                    let args: Vec<&str> = args.iter().map(|a| ARGS[a % ARGS.len()]).collect();
                    lines.insert(i % (lines.len() + 1), format!("{}/{}", WORDS[w % WORDS.len()], args.join(",")));
                }
                _ => {}
            }
        }
        let cl = lines.join("\n");
        let r = postp::run_with(&cl, None, Some(Controller::ALL[machine]));
        prop_assert!(r.ok || !r.diagnostics.is_empty());
    }
}

/// MAXRPM given on a mill is ignored with a warning of the registry's
/// warning code for ignored words (a mutant once reported it under the
/// lathe-word error code as a warning, and the diagnostic panicked).
#[test]
fn maxrpm_on_a_mill_is_an_ignored_word() {
    for machine in Controller::ALL.into_iter().filter(|c| c.kind() == postc_postp::Kind::Mill) {
        let mut lines = demo();
        lines.insert(1, "SPINDL/1000,RPM,CLW,MAXRPM,2500".to_string());
        let r = postp::run_with(&lines.join("\n"), None, Some(machine));
        assert!(
            r.diagnostics.iter().any(|d| d.contains("PX014") && d.contains("MAXRPM")),
            "{machine:?}: {:?}",
            r.diagnostics
        );
    }
}
