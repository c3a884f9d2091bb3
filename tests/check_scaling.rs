//! `postc check` costs the same per diagnostic wherever it is in the file:
//! a CL file of many bad records checks in linear time (issue 14, fault 9).
//! Each diagnostic's line and column come from a line index built once per
//! file, not from reading the file again from its start.

use postc_report::Render as _;
use std::path::Path;
use std::time::{Duration, Instant};

mod many_errors;
use many_errors::bad_cl;

/// Checks a file as `postc check` does, both output forms: the JSON array
/// (every diagnostic's line and column) and the rendering for people.
fn check(path: &Path) -> (usize, Duration) {
    let start = Instant::now();
    let mut sources = postc_report::source_map();
    let diagnostics = postc_frontends::check_toolpath(path, &mut sources);
    let name = path.display().to_string();
    let json: Vec<_> = diagnostics.iter().map(|d| sources.to_json(d, &name)).collect();
    assert!(json.iter().all(|d| d.line.is_some() && d.column.is_some()));
    let rendered = sources.render(&diagnostics, false);
    assert!(!rendered.is_empty());
    (diagnostics.len(), start.elapsed())
}

#[test]
fn many_bad_records_check_in_linear_time() {
    let dir = tempfile::tempdir().unwrap();
    let small = dir.path().join("small.cl");
    let large = dir.path().join("large.cl");
    std::fs::write(&small, bad_cl(1 << 20)).unwrap();
    std::fs::write(&large, bad_cl(4 << 20)).unwrap();
    check(&small); // warm the page cache and the allocator
    let (n_small, t_small) = check(&small);
    let (n_large, t_large) = check(&large);
    assert!(n_small > 10_000 && n_large > 3 * n_small, "{n_small} and {n_large} diagnostics");
    let ratio = t_large.as_secs_f64() / t_small.as_secs_f64().max(1e-6);
    eprintln!("{n_small} diagnostics in {t_small:?}, {n_large} in {t_large:?}: ratio {ratio:.2} for 4x the size");
    // Linear work makes this about 4; work that grows with the square of the
    // diagnostics makes it about 16. The bound is generous against noise.
    assert!(ratio < 8.0, "4x the bad records took {ratio:.1}x the time ({t_small:?} -> {t_large:?})");
}

#[test]
fn streamed_positions_match_the_held_text() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("positions.cl");
    let text = "GOTO/1,2,3\n$$ é à ü\nGOTO/4,Q5,6\r\n\nFINI";
    std::fs::write(&path, text).unwrap();
    let mut held = postc_report::source_map();
    let held_id = held.add("positions.cl", text);
    let mut streamed = postc_report::source_map();
    let streamed_id = streamed.add_streamed(path.display().to_string());
    for offset in 0..=text.len() + 3 {
        if !text.is_char_boundary(offset.min(text.len())) {
            continue;
        }
        assert_eq!(streamed.line_column(streamed_id, offset), held.line_column(held_id, offset), "offset {offset}");
    }
}
