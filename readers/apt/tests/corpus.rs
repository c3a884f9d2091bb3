//! The shared corpus of real CL files: every text file reads without
//! errors, the binary APT360 file gives exactly one, and per file the
//! reader makes one linear move per motion GOTO, one arc per CIRCLE and one
//! drill point per GOTO inside a cycle, counted here by a separate, simple
//! scan of the records.

use postc_report::Render as _;
use std::path::Path;

/// Counts from a plain scan of the records: linear moves, arcs, holes.
#[derive(Debug, Default, PartialEq, Eq)]
struct Counts {
    linear: usize,
    arcs: usize,
    holes: usize,
}

/// Joins `$`-continued lines, drops `$$` comments (and their continuation
/// lines), and returns each record's major word and the text after it.
fn records(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut buffer = String::new();
    let mut comment = false;
    for line in text.lines() {
        let line = line.trim_end_matches(['\r', ' ', '\t']);
        let trimmed = line.trim_start();
        if comment {
            comment = trimmed.ends_with('$') && !trimmed.ends_with("$$");
            continue;
        }
        if buffer.is_empty() && trimmed.starts_with("$$") {
            comment = trimmed.len() > 2 && trimmed.ends_with('$') && !trimmed.ends_with("$$");
            continue;
        }
        if let Some(rest) = trimmed.strip_suffix('$').filter(|r| !r.ends_with('$')) {
            buffer.push_str(rest);
            continue;
        }
        buffer.push_str(trimmed);
        let record = std::mem::take(&mut buffer);
        let (head, rest) = record.split_once('/').unwrap_or((&record, ""));
        out.push((head.trim().to_ascii_uppercase(), rest.trim().to_ascii_uppercase()));
    }
    out
}

fn expected_counts(text: &str) -> Counts {
    let mut counts = Counts::default();
    let (mut in_cycle, mut circle) = (false, false);
    for (word, rest) in records(text) {
        match word.as_str() {
            "GOTO" if in_cycle => counts.holes += 1,
            "GOTO" if circle => {
                counts.arcs += 1;
                circle = false;
            }
            "GOTO" => counts.linear += 1,
            "GOHOME" | "GODLTA" if !rest.is_empty() => counts.linear += 1,
            "CIRCLE" => circle = true,
            "CYCLE" => {
                let kind = rest.split(',').next().unwrap_or("").trim().to_string();
                match kind.as_str() {
                    "OFF" => in_cycle = false,
                    "INIT" | "ON" => {}
                    _ => in_cycle = true,
                }
            }
            _ => {}
        }
    }
    counts
}

#[test]
fn every_corpus_file_reads_and_counts_match() {
    let files = crate::common::corpus_files();
    if files.is_empty() {
        return;
    }
    let mut checked = 0;
    for path in files {
        let bytes = std::fs::read(&path).expect("read corpus file");
        let name =
            path.strip_prefix(crate::common::corpus_dir().unwrap_or_default()).unwrap_or(&path).display().to_string();
        let mut read = crate::common::read_bytes(&name, &bytes);
        if path.ends_with(Path::new("smooker__aptos-apt360/cl.tap")) {
            assert_eq!(read.errors().len(), 1, "{name}: {:?}", read.diagnostics);
            assert_eq!(read.errors()[0].code, "CL001", "{name}");
            assert!(read.events.is_empty(), "{name}: events from a binary file");
            checked += 1;
            continue;
        }
        let errors: Vec<_> = read.diagnostics.iter().filter(|d| d.is_error()).cloned().collect();
        assert!(errors.is_empty(), "{name}: {}", read.sources.render(&errors, false));
        let expected = expected_counts(&String::from_utf8_lossy(&bytes));
        let actual = Counts {
            linear: read.count("Rapid") + read.count("Feed"),
            arcs: read.count("Arc"),
            holes: read.count("DrillPoint"),
        };
        assert_eq!(actual, expected, "{name}");
        assert_eq!(read.events.first().map(|e| e.0.name()), Some("Job"), "{name}");
        println!(
            "{name}: {} events, {} linear, {} arcs, {} holes, warnings {:?}",
            read.events.len(),
            actual.linear,
            actual.arcs,
            actual.holes,
            read.codes()
        );
        checked += 1;
    }
    assert_eq!(checked, 31, "the corpus has 31 files");
}

#[test]
fn every_corpus_file_is_recognised_by_content() {
    for path in crate::common::corpus_files() {
        let bytes = std::fs::read(&path).expect("read corpus file");
        let head = &bytes[..bytes.len().min(16 << 10)];
        assert!(postc_reader_apt::looks_like_cl(head), "{}", path.display());
    }
    for other in
        [&b"G0 X1 Y2\nG1 Z-1 F100\n"[..], b"POST_NAME = \"Mach3\"\n", b"{\"Job\":{}}\n", b"\x89PNG\r\n\x1a\n\0\0"]
    {
        assert!(!postc_reader_apt::looks_like_cl(other), "{}", String::from_utf8_lossy(other));
    }
}

#[test]
fn check_and_open_read_files_from_disk() {
    let files = crate::common::corpus_files();
    for path in files.iter().filter(|p| p.ends_with("bohren_1.ncl.8") || p.ends_with("cl.tap")) {
        let mut sources = postc_report::source_map();
        let diagnostics = postc_reader_apt::check(path, &mut sources);
        let errors = diagnostics.iter().filter(|d| d.is_error()).count();
        let expected = usize::from(path.ends_with("cl.tap"));
        assert_eq!(errors, expected, "{}: {diagnostics:?}", path.display());
        let rendered = sources.render(&diagnostics, false);
        if expected == 1 {
            assert!(rendered.contains("CL001") && rendered.contains("cl.tap"), "{rendered}");
        }
    }
    let mut sources = postc_report::source_map();
    let missing = postc_reader_apt::check(Path::new("/nonexistent/part.cl"), &mut sources);
    assert_eq!(missing.len(), 1);
    assert_eq!(missing[0].code, "CL021");
}

/// The sweep of an arc in the direction the reader gives it, in degrees,
/// from `start`.
fn sweep(start: [f64; 3], arc: &postc_ir::event::ArcMove) -> f64 {
    use postc_ir::event::{ArcDir, Plane};
    let (u, v) = match arc.plane {
        Plane::Xy => ([start[0] - arc.cx, start[1] - arc.cy], [arc.x - arc.cx, arc.y - arc.cy]),
        Plane::Zx => ([start[2] - arc.cz, start[0] - arc.cx], [arc.z - arc.cz, arc.x - arc.cx]),
        Plane::Yz => ([start[1] - arc.cy, start[2] - arc.cz], [arc.y - arc.cy, arc.z - arc.cz]),
    };
    let ccw = (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1]).to_degrees();
    let ccw = if ccw <= 1e-6 { ccw + 360.0 } else { ccw };
    if arc.dir == ArcDir::Ccw { ccw } else { 360.0 - ccw }
}

/// Most arcs of real toolpaths turn less than half a turn (pocket circles
/// that turn nearly all the way round aside); a reader that got a vendor's
/// direction wrong would make most of them turn more.
#[test]
fn corpus_arcs_mostly_turn_the_short_way() {
    use postc_ir::event::Event;
    for path in crate::common::corpus_files() {
        let bytes = std::fs::read(&path).expect("read corpus file");
        let read = crate::common::read_bytes("corpus", &bytes);
        let (mut short, mut long, mut nearly_full) = (0usize, 0usize, 0usize);
        let mut at = None;
        for (event, _) in &read.events {
            match event {
                Event::Rapid(m) => at = Some([m.x, m.y, m.z]),
                Event::Feed(m) => at = Some([m.x, m.y, m.z]),
                Event::Arc(a) => {
                    if let Some(s) = at {
                        match sweep(s, a) {
                            d if d <= 180.0 + 1e-6 => short += 1,
                            d if d >= 300.0 => nearly_full += 1,
                            _ => long += 1,
                        }
                    }
                    at = Some([a.x, a.y, a.z]);
                }
                _ => {}
            }
        }
        if short + long + nearly_full > 0 {
            println!(
                "{}: {short} arcs under half a turn, {nearly_full} nearly full circles, {long} between",
                path.display()
            );
            assert!(short >= 9 * long, "{}: {short} short, {long} long", path.display());
        }
    }
}

#[test]
fn corpus_events_come_in_contract_order() {
    for path in crate::common::corpus_files() {
        let bytes = std::fs::read(&path).expect("read corpus file");
        let read = crate::common::read_bytes("corpus", &bytes);
        crate::common::check_order(&path.display().to_string(), &read.events, false);
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let bytes = std::fs::read(entry.path()).expect("read fixture");
        let read = crate::common::read_bytes("fixture", &bytes);
        crate::common::check_order(&entry.path().display().to_string(), &read.events, false);
    }
}
