//! Robustness: mutated and random posts never panic or hang, and every
//! diagnostic points inside the file. Pathological inputs (deep nesting,
//! very long lines, huge files of one construct) are refused with a
//! diagnostic, not a stack overflow.

use postc_report::Render as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use postc_front_vcpost::compile;
use proptest::prelude::*;

fn fixture_texts() -> Vec<String> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let mut texts = Vec::new();
    for kind in ["valid", "invalid"] {
        let mut files: Vec<PathBuf> =
            std::fs::read_dir(root.join(kind)).unwrap().filter_map(|e| e.ok().map(|e| e.path())).collect();
        files.sort();
        texts.extend(files.iter().map(|p| std::fs::read_to_string(p).unwrap()));
    }
    texts
}

/// Compiles and checks that every span is inside the text and that the
/// diagnostics render.
fn compile_checked(bytes: &[u8]) -> Duration {
    let started = Instant::now();
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(Path::new("fuzz.VcPost"), bytes, &mut sources);
    let elapsed = started.elapsed();
    let len = sources.text(postc_ir::FileId(0)).map_or(0, str::len);
    for d in &diagnostics {
        assert!(d.code.starts_with("VC"), "{d:?}");
        for l in &d.labels {
            assert!(l.span.start <= l.span.end && l.span.end <= len, "span out of the file: {d:?}");
        }
    }
    let _ = sources.render(&diagnostics[..diagnostics.len().min(40)], false);
    let _ = format!("{post:?}");
    elapsed
}

/// Pieces the mutator inserts: the language's own words and symbols, the
/// characters that trouble lexers, and block lines.
const PIECES: &[&str] = &[
    "Sub ",
    "End Sub\n",
    "If ",
    " Then",
    "Else",
    "ElseIf ",
    "End If\n",
    "For I = 1 To ",
    "Next\n",
    "While ",
    "Wend\n",
    "Do\n",
    "Loop\n",
    "Select Case ",
    "Case ",
    "End Select\n",
    "Out \"",
    "<N>",
    "<X",
    ">",
    "\"",
    "\"\"",
    "(",
    ")",
    ")(",
    " _\n",
    "'",
    "Rem ",
    "' #Cycle !X",
    " !",
    "#",
    ":",
    ",",
    ".",
    ".Previous",
    ".Format = ",
    "=",
    "<>",
    "&",
    "^",
    "\\",
    "Mod",
    "Not ",
    " And ",
    "Xor",
    "Exit For\n",
    "Exit Sub\n",
    "Call ",
    "Dim ",
    "Const ",
    "Function F(A)\n",
    "End Function\n",
    "[End]",
    "[",
    "]",
    "é",
    "\u{0}",
    "\r",
    "\r\n",
    "\n",
    "1.5E-3",
    ".5",
    "99999999999999999999",
    "Abs(",
    "Mid(",
    "IIf(",
    "N.Start = ",
    "X.Modal = True\n",
];

#[derive(Clone, Debug)]
enum Mutation {
    Delete { at: usize, len: usize },
    Insert { at: usize, piece: usize },
    DuplicateLine { at: usize },
    Truncate { at: usize },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), 1usize..40).prop_map(|(at, len)| Mutation::Delete { at, len }),
        (any::<usize>(), 0..PIECES.len()).prop_map(|(at, piece)| Mutation::Insert { at, piece }),
        any::<usize>().prop_map(|at| Mutation::DuplicateLine { at }),
        any::<usize>().prop_map(|at| Mutation::Truncate { at }),
    ]
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let n = text.len().max(1);
    match *m {
        Mutation::Delete { at, len } => {
            let at = at % n;
            let end = (at + len).min(text.len());
            if at < end {
                text.drain(at..end);
            }
        }
        Mutation::Insert { at, piece } => {
            let at = at % (text.len() + 1);
            let bytes = PIECES[piece].as_bytes();
            text.splice(at..at, bytes.iter().copied());
        }
        Mutation::DuplicateLine { at } => {
            let at = at % n;
            let start = text[..at.min(text.len())].iter().rposition(|b| *b == b'\n').map_or(0, |p| p + 1);
            let end = text[start..].iter().position(|b| *b == b'\n').map_or(text.len(), |p| start + p + 1);
            let line: Vec<u8> = text[start..end].to_vec();
            text.splice(end..end, line);
        }
        Mutation::Truncate { at } => {
            let at = at % n;
            text.truncate(at);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn mutated_posts_never_panic_or_hang(which in any::<usize>(), mutations in prop::collection::vec(mutation(), 1..12)) {
        let texts = fixture_texts();
        let mut text = texts[which % texts.len()].clone().into_bytes();
        for m in &mutations {
            apply(&mut text, m);
        }
        let elapsed = compile_checked(&text);
        prop_assert!(elapsed < Duration::from_secs(10), "took {elapsed:?}");
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..1500)) {
        compile_checked(&bytes);
    }

    #[test]
    fn random_token_soup_never_panics(pieces in prop::collection::vec(0..PIECES.len(), 0..300)) {
        let text: String = pieces.iter().map(|i| PIECES[*i]).collect();
        compile_checked(text.as_bytes());
    }
}

fn run_big_stack<F: FnOnce() + Send + 'static>(f: F) {
    // The default test thread stack (2 MiB) is what a caller gets; keep it.
    std::thread::Builder::new().stack_size(2 << 20).spawn(f).unwrap().join().unwrap();
}

#[test]
fn pathological_inputs_are_refused_not_overflowed() {
    let cases: Vec<String> = vec![
        format!("X = {}1{}", "(".repeat(10_000), ")".repeat(10_000)),
        format!("X = {}1", "-".repeat(10_000)),
        format!("X = {}1", "Not ".repeat(10_000)),
        format!("X = 1{}", " + 1".repeat(10_000)),
        format!("Sub A\n{}Out \"x\"\n{}End Sub\n", "If 1 Then\n".repeat(10_000), "End If\n".repeat(10_000)),
        format!("Sub A\n{}End Sub\n", "For I = 1 To 2\n".repeat(10_000)),
        format!("{}X = 1\n", "If 1 Then ".repeat(240)),
        format!("X = {}1{}", "Abs(".repeat(30), ")".repeat(30)),
        "Sub A\n".repeat(5_000),
        "End If\n".repeat(5_000),
        format!("Out \"{}\"", "<X>".repeat(50_000)),
        format!("' #Cycle {}\nSub A\nEnd Sub", "!P ".repeat(10_000)),
        format!("Sub A\n' #Cycle {}\nEnd Sub", "!P ".repeat(10_000)),
        "\"".repeat(10_000),
        " _\n".repeat(10_000),
    ];
    for (i, case) in cases.into_iter().enumerate() {
        run_big_stack(move || {
            let elapsed = compile_checked(case.as_bytes());
            if std::env::var_os("VCPOST_TIMING").is_some() {
                eprintln!("case {i}: {elapsed:?}");
            }
            assert!(elapsed < Duration::from_secs(20), "case {i} took {elapsed:?}");
        });
    }
}

#[test]
fn windows_1252_text_is_read_and_written_back() {
    let bytes = b"Sub PPRINT\r\n  Out \"(L\xE4nge 90\xB0)\"\r\nEnd Sub\r\n";
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(Path::new("legacy.VcPost"), bytes, &mut sources);
    assert!(diagnostics.is_empty(), "{diagnostics:?}");
    let postc_ir::Body::Native(body) = &post.functions[0].body else { panic!() };
    let postc_ir::Stmt::Line { pieces, .. } = &body[0] else { panic!() };
    assert_eq!(pieces, &vec![postc_ir::Piece::Text(b"(L\xE4nge 90\xB0)".to_vec())]);
}
