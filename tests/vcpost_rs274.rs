//! The VcPost milling post read by a real interpreter: LinuxCNC's `rs274`.
//!
//! `corpus/posts/vcpost/fanuc_mill.VcPost` posts every APT CL file of
//! `../shared/corpus/apt/` (the files the APT reader reads without error)
//! and every native corpus toolpath; `rs274 -g -t corpus/tool.tbl` must
//! read each program without an error, and every GOTO and CIRCLE of the
//! toolpath (its Rapid, Feed and Arc events) must be among the moves rs274
//! reports, in order, at the same end point (arcs also with the same centre
//! and turning direction, in XY, ZX and YZ planes) within the printed
//! precision. Extra moves (tool changes, the split of a rapid into Z and
//! XY, expanded drilling cycles) may come between them, and a move to where
//! the tool already is prints nothing, so it is not looked for.
//!
//! Without rs274 on PATH the test says it is skipped; without
//! `../shared/corpus` only the native toolpaths are checked.

use std::path::{Path, PathBuf};

use postc_ir::event::{ArcDir, Event, Plane};
use postc_ir::{EventSource, Post};
use postc_runtime::{Finished, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

use crate::support::rs274;

use rs274::{Kind, Motion, axes};

/// A move: kind (0 traverse, 1 feed, 2 arc), end point, arc centre in plane
/// coordinates, arc rotation (+1 counter-clockwise), plane.
#[derive(Debug, Clone, Copy)]
struct Move {
    kind: u8,
    end: [f64; 3],
    centre: [f64; 2],
    rotation: i32,
    plane: Plane,
}

impl From<&Motion> for Move {
    fn from(m: &Motion) -> Move {
        let end = [m.end[0], m.end[1], m.end[2]];
        match m.kind {
            Kind::Traverse => Move { kind: 0, end, centre: [0.0; 2], rotation: 0, plane: m.plane },
            Kind::Feed => Move { kind: 1, end, centre: [0.0; 2], rotation: 0, plane: m.plane },
            Kind::Arc { centre, rotation } => Move { kind: 2, end, centre, rotation, plane: m.plane },
        }
    }
}

/// The toolpath's moves, leaving out moves to where the tool already is;
/// `None` when the file does not read without errors.
fn expected(toolpath: &Path, tol: f64) -> Option<Vec<Move>> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).ok()?;
    let (mut diags, mut moves, mut at) = (Vec::new(), Vec::new(), [f64::NAN; 3]);
    while let Some((event, _)) = source.next_event(&mut diags) {
        let (kind, end, centre, rotation, plane) = match event {
            Event::Rapid(m) => (0, [m.x, m.y, m.z], [0.0; 2], 0, Plane::Xy),
            Event::Feed(m) => (1, [m.x, m.y, m.z], [0.0; 2], 0, Plane::Xy),
            Event::Arc(a) => {
                let c = [a.cx, a.cy, a.cz];
                let [u, v, _] = axes(a.plane);
                (2, [a.x, a.y, a.z], [c[u], c[v]], if a.dir == ArcDir::Ccw { 1 } else { -1 }, a.plane)
            }
            Event::DrillPoint(p) => {
                at = [p.x, p.y, f64::NAN];
                continue;
            }
            _ => continue,
        };
        if kind < 2 && close(end, at, tol) {
            continue;
        }
        at = end;
        moves.push(Move { kind, end, centre, rotation, plane });
    }
    (!postc_ir::diagnostic::has_errors(&diags)).then_some(moves)
}

fn close<const N: usize>(a: [f64; N], b: [f64; N], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

fn matches(e: &Move, c: &Move, tol: f64) -> bool {
    e.kind == c.kind
        && close(e.end, c.end, tol)
        && (e.kind < 2 || (e.plane == c.plane && e.rotation == c.rotation && close(e.centre, c.centre, 2.0 * tol)))
}

fn post_program(post: &Post, toolpath: &Path) -> Result<Vec<u8>, String> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).map_err(|d| d.message)?;
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(r) => match r.output {
            Finished::Memory(mut parts) if parts.len() == 1 => Ok(parts.remove(0)),
            _ => Err("not one program in memory".into()),
        },
        Err(d) => Err(format!("posting failed: {:?}", d.iter().map(|d| &d.message).collect::<Vec<_>>())),
    }
}

fn toolpaths() -> Vec<PathBuf> {
    let mut out = Vec::new();
    let list = |dir: PathBuf, out: &mut Vec<PathBuf>| {
        let Ok(entries) = std::fs::read_dir(&dir) else { return };
        out.extend(entries.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_file()));
    };
    for dir in ["corpus/toolpaths", "corpus/toolpaths/vcpost"] {
        list(root().join(dir), &mut out);
    }
    if let Ok(vendors) = std::fs::read_dir(root().join("../shared/corpus/apt")) {
        for vendor in vendors.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.is_dir()) {
            list(vendor, &mut out);
        }
    }
    out.retain(|p| postc_driver::is_toolpath(p, &postc_report::FsLoader));
    out.sort();
    out
}

#[test]
fn fanuc_mill_reads_in_rs274_with_every_goto_and_circle() {
    let Some(rs274) = rs274::find() else {
        println!("skipped: rs274 not found on PATH (bash .ci/run installs it)");
        return;
    };
    let mut sources = postc_report::source_map();
    let compiled =
        postc_driver::compile_post(&root().join("corpus/posts/vcpost/fanuc_mill.VcPost"), None, &mut sources);
    assert!(compiled.diagnostics.is_empty(), "{:?}", compiled.diagnostics);
    let post = compiled.post.unwrap();
    let tol = 1e-4 + 1e-4;
    let (mut checked, mut failures) = (0, Vec::new());
    for toolpath in toolpaths() {
        let label = toolpath.file_name().unwrap().to_string_lossy().into_owned();
        let Some(expected) = expected(&toolpath, tol) else { continue };
        let program = match post_program(&post, &toolpath) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!("{label}: {e}"));
                continue;
            }
        };
        let actual: Vec<Move> = match rs274::run(&rs274, &String::from_utf8_lossy(&program)) {
            Ok(m) => m.iter().map(Move::from).collect(),
            Err(e) => {
                failures.push(format!("{label}: {e}"));
                continue;
            }
        };
        let mut at = 0;
        for (i, e) in expected.iter().enumerate() {
            match actual[at..].iter().position(|c| matches(e, c, tol)) {
                Some(k) => at += k + 1,
                None => {
                    failures.push(format!("{label}: move {i} ({e:?}) is not among rs274's moves after #{at}"));
                    break;
                }
            }
        }
        checked += 1;
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(checked >= 8, "only {checked} programs were checked");
    println!("rs274 read {checked} fanuc_mill programs with every move of their toolpaths");
}
