//! Composites event files: the corpus files read against their posts, each
//! CP diagnostic at its line, the routines a post may leave out, and
//! mutated files that never panic.

use postc_report::Render as _;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use postc_front_vcpost::compile;
use postc_front_vcpost::composites::calls::{LayingCall, LinkHeader, Modals, PacketPoint, ProbingCall};
use postc_front_vcpost::composites::{self, CompositesReader, Syntax};
use postc_ir::{CallSource, CallValue, Diagnostic, FileId, Post, SubCall};
use proptest::prelude::*;

fn corpus() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../corpus")
}

fn post_from(text: &str) -> Post {
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(Path::new("t.VcPost"), text.as_bytes(), &mut sources);
    assert!(diagnostics.iter().all(|d| !d.is_error()), "{}", sources.render(&diagnostics, false));
    post
}

fn corpus_post(name: &str) -> Post {
    post_from(&std::fs::read_to_string(corpus().join("posts/vcpost").join(format!("{name}.VcPost"))).unwrap())
}

fn drain(mut reader: impl CallSource) -> (Vec<SubCall>, Vec<Diagnostic>) {
    let (mut calls, mut diagnostics) = (Vec::new(), Vec::new());
    while let Some(c) = reader.next_call(&mut diagnostics) {
        calls.push(c);
        assert!(calls.len() < 100_000, "the reader does not end");
    }
    (calls, diagnostics)
}

fn read(text: &str, post: &Post, primers: Vec<SubCall>) -> (Vec<SubCall>, Vec<Diagnostic>) {
    drain(CompositesReader::new(Cursor::new(text.as_bytes().to_vec()), None, FileId(1), post, primers))
}

/// Code and 1-based line of each diagnostic of a text.
fn lines_of(diagnostics: &[Diagnostic], text: &str) -> Vec<(String, usize)> {
    diagnostics
        .iter()
        .map(|d| {
            let at = d.primary_span().map_or(0, |s| s.start);
            (d.code.to_string(), text[..at.min(text.len())].matches('\n').count() + 1)
        })
        .collect()
}

fn json(call: &LayingCall) -> String {
    serde_json::to_string(call).unwrap()
}

/// A whole small ply as JSON lines.
fn ply() -> Vec<String> {
    let length = |n: f64| {
        json(&LayingCall::Length(postc_front_vcpost::composites::calls::Length {
            TowArea: 1.0,
            TowLen: 2.0,
            TowNum: n,
        }))
    };
    let link = |t: f64| json(&LayingCall::LinkHeader(LinkHeader { LinkType: t, Rotation: 0.0, TowWidth: None }));
    let goto = PacketPoint {
        AddCutA: "0110".into(),
        AddCutB: "0110".into(),
        AddCutI: 6.0,
        AddCutJ: 6.0,
        TowsInPacket: 4.0,
        ..Default::default()
    };
    vec![
        r#"{"VcpFile":{"kind":"Laying"}}"#.to_string(),
        json(&LayingCall::Modals(Box::<Modals>::default())),
        json(&LayingCall::Extent(Default::default())),
        length(1.0),
        length(0.0),
        json(&LayingCall::PlyHeader),
        link(-1.0),
        json(&LayingCall::TraverseHeader),
        json(&LayingCall::TraverseTo(Box::default())),
        json(&LayingCall::TraverseTrailer),
        json(&LayingCall::MoveTo(Box::default())),
        json(&LayingCall::LinkTrailer),
        json(&LayingCall::PacketHeader),
        json(&LayingCall::GoTo(Box::new(goto))),
        json(&LayingCall::PacketTrailer),
        link(1.0),
        json(&LayingCall::LinkTrailer),
        json(&LayingCall::PlyTrailer),
    ]
}

const SMALL_POST: &str = "Sub GoTo\n  Out \"<X>\"\nEnd Sub\nSub Note()\n  ' #Option\n  Out OptString1\nEnd Sub\nSub Plain()\n  Out \"x\"\nEnd Sub\n";

#[test]
fn corpus_files_read_cleanly() {
    for (file, post) in [
        ("afp_roller__wing_ply45.vcp.ron", "afp_roller"),
        ("afp_roller__spar_ply90.vcp.jsonl", "afp_roller"),
        ("afp_probe__wing_check.vcp.ron", "afp_probe"),
    ] {
        let path = corpus().join("composites").join(file);
        assert!(composites::is_composites_file(&path, &postc_report::FsLoader), "{file}");
        let post = corpus_post(post);
        let mut sources = postc_report::source_map();
        let (calls, diagnostics) = drain(composites::open(&path, &mut sources, &post, Vec::new()).unwrap());
        assert!(diagnostics.is_empty(), "{file}: {}", sources.render(&diagnostics, false));
        assert!(calls.len() > 15, "{file}");
    }
    let post = corpus_post("afp_roller");
    let text = std::fs::read_to_string(corpus().join("composites/afp_roller__wing_ply45.vcp.ron")).unwrap();
    let (calls, _) = read(&text, &post, Vec::new());
    assert_eq!(calls[0].sub, "S3_Vertical", "the header's primer runs first");
    assert_eq!(calls[1].sub, "Modals");
    let goto = calls.iter().find(|c| c.sub == "GoTo" && c.vars.iter().any(|(n, _)| n == "getNthLength1")).unwrap();
    assert!(goto.vars.iter().any(|(n, v)| n == "getNthLength1" && matches!(v, CallValue::List(l) if l.len() == 8)));
}

#[test]
fn routines_the_post_leaves_out() {
    let post = post_from(SMALL_POST);
    let (calls, diagnostics) = read(&ply().join("\n"), &post, Vec::new());
    assert!(diagnostics.is_empty(), "{diagnostics:?}");
    let subs: Vec<&str> = calls.iter().map(|c| c.sub.as_str()).collect();
    assert!(
        subs.contains(&"TraverseHeader") && !subs.contains(&"TraverseTo") && !subs.contains(&"TraverseTrailer"),
        "{subs:?}"
    );
    let modals = calls.iter().find(|c| c.sub == "Modals").unwrap();
    assert_eq!(modals.vars.len(), 70, "every Modals variable of Vericut's application notes");
}

#[test]
fn every_problem_is_reported_at_its_line() {
    let post = post_from(SMALL_POST);
    let good = ply();
    let with = |at: usize, line: &str, replace: bool| {
        let mut lines = good.clone();
        if replace {
            lines[at] = line.to_string();
        } else {
            lines.insert(at, line.to_string());
        }
        lines.join("\n")
    };
    let mut goto_bad = serde_json::to_value(LayingCall::GoTo(Box::default())).unwrap();
    goto_bad["GoTo"]["AddCutA"] = "01".into();
    goto_bad["GoTo"]["AddCutB"] = "01".into();
    goto_bad["GoTo"]["getNthLength1"] = serde_json::json!([1.0, 2.0]);
    let cases: Vec<(String, &str, usize)> = vec![
        (with(0, r#"{"Modals":{}}"#, true), "CP002", 1),
        (with(1, r#"{"Modals":{"AccDecDist":1}}"#, true), "CP001", 2),
        (with(2, r#"{"Extent":{"AMax":"x"}}"#, true), "CP001", 3),
        (with(13, r#"{"GoTo":{"Bogus":1}}"#, true), "CP001", 14),
        (with(5, &json(&LayingCall::GoTo(Box::default())), false), "CP003", 6),
        (good[..10].join("\n"), "CP004", 10),
        (with(13, r#"{"Option":{"name":"Missing"}}"#, false), "CP005", 14),
        (with(6, r#"{"LinkHeader":{"LinkType":-1,"Rotation":2}}"#, true), "CP006", 7),
        (with(13, r#"{"Option":{"name":"Plain"}}"#, false), "CP007", 14),
        (with(13, &goto_bad.to_string(), true), "CP008", 14),
        (with(13, &goto_bad.to_string(), true), "CP009", 14),
    ];
    for (text, code, line) in &cases {
        let (_, diagnostics) = read(text, &post, Vec::new());
        let found = lines_of(&diagnostics, text);
        assert!(
            found.iter().any(|(c, l)| c == code && l == line),
            "expected {code} at line {line}, got {found:?}\n{text}"
        );
    }
}

#[test]
fn primers_and_probing() {
    let post = corpus_post("afp_roller");
    let mut diagnostics = Vec::new();
    let primers = composites::primers(&post, &["S5_Horizontal".to_string(), "Nope".to_string()], &mut diagnostics);
    assert_eq!(primers.len(), 1);
    assert_eq!(diagnostics.iter().map(|d| d.code).collect::<Vec<_>>(), ["CP005"]);
    let probe = corpus_post("afp_probe");
    let lines = [
        r#"{"VcpFile":{"kind":"Probing"}}"#.to_string(),
        serde_json::to_string(&ProbingCall::Modals(Box::default())).unwrap(),
        serde_json::to_string(&ProbingCall::ProgramHeader).unwrap(),
        r#"{"MoveTo":{"X":1,"Y":2,"Z":3}}"#.to_string(),
    ];
    let text = lines.join("\n");
    let (_, diagnostics) = read(&text, &probe, Vec::new());
    let found = lines_of(&diagnostics, &text);
    assert!(found.contains(&("CP003".to_string(), 4)) && found.contains(&("CP004".to_string(), 4)), "{found:?}");
}

#[test]
fn recognised_by_name_or_header() {
    assert!(composites::looks_like_composites(b"// c\nVcpFile(kind: Laying)\n"));
    assert!(composites::looks_like_composites(b"{\"VcpFile\": {\"kind\": \"Probing\"}}\n"));
    assert!(!composites::looks_like_composites(b"Job(units: Mm)\n"));
    assert!(composites::is_composites_file(Path::new("/nonexistent/ply.VCP.JSONL"), &postc_report::FsLoader));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn mutated_files_never_panic(edits in prop::collection::vec((any::<prop::sample::Index>(), 0u8..4, any::<char>()), 0..10), ron in any::<bool>()) {
        let text = if ron {
            std::fs::read_to_string(corpus().join("composites/afp_roller__wing_ply45.vcp.ron")).unwrap()
        } else {
            ply().join("\n")
        };
        let mut bytes: Vec<char> = text.chars().collect();
        for (at, kind, ch) in edits {
            let i = at.index(bytes.len().max(1)).min(bytes.len());
            match kind {
                0 if i < bytes.len() => { bytes.remove(i); }
                1 => bytes.insert(i, ch),
                2 => bytes.insert(i, ['"', ',', '{', '}', '(', ')', '\n', ':'][ch as usize % 8]),
                _ if i < bytes.len() => bytes[i] = ch,
                _ => {}
            }
        }
        let text: String = bytes.into_iter().collect();
        let post = corpus_post("afp_roller");
        let syntax = if ron { Syntax::Ron } else { Syntax::JsonLines };
        let (calls, _) = drain(CompositesReader::new(Cursor::new(text.clone().into_bytes()), Some(syntax), FileId(1), &post, Vec::new()));
        prop_assert!(calls.len() <= text.lines().count() + 2);
    }
}
