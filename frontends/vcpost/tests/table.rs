//! Probe-cycle tables: the calls a table makes, every PT diagnostic at the
//! row and column it names, the template read back, and mutated tables
//! that never panic.

use postc_front_vcpost::{compile, table};
use postc_ir::{CallValue, Diagnostic, FileId, Post, SourceMap, SubCall};
use postc_report::Render as _;
use proptest::prelude::*;

const POST: &str = r#"
Sub Initialize()
  ' #Init Offset Clearance
  Out "<N> G17"
End Sub
Sub Terminate()
  ' #End
  Out "M30"
End Sub
Sub Rapid()
  ' #Rapid !X !Y !Z
  Out "<N> G0<X><Y><Z>"
End Sub
Sub Approach()
  ' #Approach !X !Y !Z FeedRate
  Out "<N> G1<X><Y><Z>"
End Sub
Sub Retract()
  ' #Retract Clearance
  Out "<N> G1 Z" & Clearance
End Sub
Sub WallThick()
  ' #Cycle !X !Y !Width Angle
  Out "<N> CYCLE979"
End Sub
Sub Bore()
  ' #Cycle !Diameter Note
  Out "<N> CYCLE977"
End Sub
Sub Store()
  ' #Save
  Out "<N> SAVE"
End Sub
Sub GOTO
  Out "<N><X>"
End Sub
"#;

fn post() -> (Post, SourceMap) {
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = compile(std::path::Path::new("probe.VcPost"), POST.as_bytes(), &mut sources);
    assert!(diagnostics.is_empty(), "{}", sources.render(&diagnostics, false));
    (post, sources)
}

fn read(text: &str) -> (Vec<SubCall>, Vec<Diagnostic>, SourceMap) {
    let (post, mut sources) = post();
    let file = sources.add("table.csv", text.to_string());
    let (calls, diagnostics) = table::read(text, file, &post);
    (calls, diagnostics, sources)
}

fn names(calls: &[SubCall]) -> Vec<&str> {
    calls.iter().map(|c| c.sub.as_str()).collect()
}

/// Code, line and column of each diagnostic.
fn located(diagnostics: &[Diagnostic], sources: &SourceMap) -> Vec<(String, usize, usize)> {
    diagnostics
        .iter()
        .map(|d| {
            let (line, col) = d.primary_span().and_then(|s| sources.line_column(s.file, s.start)).unwrap_or((0, 0));
            (d.code.to_string(), line, col)
        })
        .collect()
}

#[test]
fn calls_follow_the_seed_order() {
    let text = "# a comment\nInitialize,,5\nRapid,0,0,100\nApproach,10,20,-5\nWallThick,10,20,Width=12.5\nStore\nRetract,3\n\nApproach,0,0,0\nBore,42,\"front bore\"\nTerminate\n";
    let (calls, diagnostics, _) = read(text);
    assert!(diagnostics.iter().all(|d| !d.is_error()), "{diagnostics:?}");
    assert_eq!(
        names(&calls),
        [
            "Initialize",
            "Rapid",
            "Approach",
            "WallThick",
            "Store",
            "Retract",
            "Approach",
            "Bore",
            "Retract",
            "Terminate"
        ]
    );
    assert_eq!(calls[0].vars, vec![("Clearance".to_string(), CallValue::Number(5.0))]);
    assert_eq!(calls[3].vars[2], ("Width".to_string(), CallValue::Number(12.5)));
    assert_eq!(calls[7].vars[1], ("Note".to_string(), CallValue::Text("front bore".into())));
    // The second feature has no Retract row: its Retract runs with no values.
    assert!(calls[8].vars.is_empty());
}

#[test]
fn init_and_end_run_without_their_rows() {
    let (calls, diagnostics, _) = read("Rapid,1,2,3\n");
    assert!(diagnostics.is_empty(), "{diagnostics:?}");
    assert_eq!(names(&calls), ["Initialize", "Rapid", "Terminate"]);
}

#[test]
fn every_problem_is_reported_where_it_is() {
    let cases: &[(&str, &str, usize, usize)] = &[
        ("Rapid,1,\"2\n", "PT001", 1, 9),
        ("Rapidd,1,2,3\n", "PT002", 1, 1),
        ("GOTO,1\n", "PT003", 1, 1),
        ("Rapid,X=1,2,3\n", "PT004", 1, 11),
        ("Rapid,1,2,3,4\n", "PT005", 1, 13),
        ("Rapid,1,2,3,W=4\n", "PT006", 1, 13),
        ("Rapid,1,2,3,X=4\n", "PT007", 1, 13),
        ("Rapid,1,,3\n", "PT008", 1, 9),
        ("Rapid,1,2\n", "PT008", 1, 10),
        ("Rapid,1,!Y,3\n", "PT008", 1, 9),
        ("Rapid,1,two,3\n", "PT009", 1, 9),
        ("Rapid,1,2,3\nInitialize\n", "PT010", 2, 1),
        ("Terminate\nRapid,1,2,3\n", "PT011", 1, 1),
        ("Approach,1,2,3\nRapid,1,2,3\n", "PT012", 1, 1),
        ("Rapid,1,2,3\nStore\n", "PT013", 2, 1),
        ("Rapid,1,2,3\nRetract\n", "PT014", 2, 1),
        ("WallThick,1,2,3\n", "PT008", 1, 1),
    ];
    for (text, code, line, col) in cases {
        let (_, diagnostics, sources) = read(text);
        let found = located(&diagnostics, &sources);
        assert!(
            found.iter().any(|(c, l, k)| c == code && l == line && k == col),
            "{text:?}: expected {code} at {line}:{col}, got {found:?}"
        );
    }
    let (_, diagnostics, _) = read("# nothing\n");
    assert_eq!(diagnostics.iter().map(|d| d.code).collect::<Vec<_>>(), ["PT015"]);
}

#[test]
fn the_template_reads_back_with_only_its_mandatory_cells_missing() {
    let (post, _) = post();
    let template = table::template(&post).unwrap();
    assert!(template.contains("Rapid,!X,!Y,!Z\n"), "{template}");
    let cycles: Vec<&str> = template.lines().filter(|l| l.starts_with("Bore") || l.starts_with("WallThick")).collect();
    assert_eq!(cycles, ["Bore,!Diameter,Note", "WallThick,!X,!Y,!Width,Angle"], "cycles are sorted by name");
    let (_, diagnostics, _) = read(&template);
    assert!(!diagnostics.is_empty());
    assert!(diagnostics.iter().all(|d| d.code == "PT008"), "{diagnostics:?}");
    let mut sources = postc_report::source_map();
    let (milling, _) = compile(std::path::Path::new("m.VcPost"), b"Sub GOTO\n Out \"<X>\"\nEnd Sub\n", &mut sources);
    assert!(table::template(&milling).is_none());
}

/// A valid table, to mutate.
const GOOD: &str = "Initialize,1,5\nRapid,0,0,100\nApproach,X=10,Y=20,Z=-5,FeedRate=900\nWallThick,10,20,12.5,\"30\"\nStore\nRetract,3\nTerminate\n";

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn mutated_tables_never_panic(edits in prop::collection::vec((any::<prop::sample::Index>(), 0u8..4, any::<char>()), 0..8)) {
        let mut text: Vec<char> = GOOD.chars().collect();
        for (at, kind, ch) in edits {
            let i = at.index(text.len().max(1)).min(text.len());
            match kind {
                0 if i < text.len() => { text.remove(i); }
                1 => text.insert(i, ch),
                2 => text.insert(i, ['"', ',', '=', '\n', '!', '#', ' '][ch as usize % 7]),
                _ if i < text.len() => text[i] = ch,
                _ => {}
            }
        }
        let text: String = text.into_iter().collect();
        let (post, _) = post();
        let (calls, diagnostics) = table::read(&text, FileId(1), &post);
        for d in &diagnostics {
            if let Some(s) = d.primary_span() {
                prop_assert!(s.start <= s.end && s.end <= text.len(), "{d:?} out of {}", text.len());
            }
        }
        prop_assert!(calls.len() <= 3 * text.lines().count() + 2);
    }

    #[test]
    fn any_text_never_panics(text in "\\PC{0,200}") {
        let (post, _) = post();
        let _ = table::read(&text, FileId(1), &post);
    }
}
