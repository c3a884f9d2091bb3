//! Every real CL file of `../shared/corpus/apt/` (a failure under `CI=true`,
//! and skipped with a message elsewhere, when `../shared` is not beside the
//! repository): it reads with no errors (the APT360 binary `cl.tap` gives
//! exactly one), it posts through the
//! default post (the embedded Vectric G-code post of `postc post FILE`),
//! LinuxCNC's `rs274` reads the program with no complaint, and the motions
//! in the program add up to the file's GOTO and CIRCLE records.
//!
//! How the counts are made to agree, and what legitimately differs:
//!
//! 1. Records to events. Each `CIRCLE` with its `GOTO` is one arc; every
//!    other `GOTO`, each `GODLTA` and each `GOHOME/x,y,z` is one straight
//!    move (a rapid, a feed, or a hole of a drilling cycle). A CIRCLE with
//!    no GOTO after it is dropped (CL010); an arc in a tilted plane is cut
//!    into as many feed moves as its CL012 warning says. The corpus has
//!    neither, but the count allows for them.
//! 2. Events to motions. rs274 reports every traverse, feed and arc. The
//!    post adds its own `G53 G0 Z0` retracts (header, tool changes,
//!    footer), counted from the program. Every move is a block with its G
//!    word, and rs274 makes a motion of each, also of a move that goes
//!    nowhere. A Vectric post writes arcs in the XY plane only: the runtime
//!    cuts the others (Creo's and SolidWorks' arcs about X or Y) into
//!    chords at its tolerance. Each hole of a drilling cycle becomes the
//!    moves the runtime cuts it into (up to the clearance plane, over the
//!    hole, down to the R plane, each peck with its retract and return, the
//!    bottom, back up). `Expected` follows these rules.
//! 3. Two things in these files are not G-code and are changed before
//!    posting, and said here: SolidWorks writes tool-holder notes as
//!    `INSERT` records, which a post writes verbatim, so they become
//!    comments; the NCL samples carry no FEDRAT at all, so the post would
//!    print F0 and rs274 refuses a G1 at zero feed; their feed moves are
//!    given 100 per minute.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use postc_ir::event::{DrillCycle, DrillKind, Event, Plane, Text};
use postc_ir::{Diagnostic, EventSource, Post, SourceMap, Span};
use postc_runtime::geometry::ArcGeometry;
use postc_runtime::{Finished, Output};

use crate::support::postp;

fn corpus() -> Option<Vec<PathBuf>> {
    let dir = postp::root().join("../shared/corpus/apt");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .ok()?
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir())
        .flat_map(|d| std::fs::read_dir(d.path()).into_iter().flatten().filter_map(|e| e.ok()).map(|e| e.path()))
        .filter(|p| p.extension().is_none_or(|e| e != "md"))
        .collect();
    files.sort();
    Some(files)
}

fn is_binary(path: &Path) -> bool {
    path.ends_with("smooker__aptos-apt360/cl.tap")
}

/// Record heads counted from the text: continuation lines (after `$`) and
/// `$$` comments are not records.
fn count_records(text: &str) -> HashMap<String, usize> {
    let mut counts = HashMap::new();
    let mut continued = false;
    for line in text.lines() {
        let code = line.split("$$").next().unwrap_or("").trim_end();
        let was_continued = continued;
        continued = line.trim_end().ends_with('$');
        let trimmed = code.trim_start();
        if was_continued || trimmed.is_empty() {
            continue;
        }
        let head = trimmed.split(['/', ' ', '\t', ',']).next().unwrap_or("").to_ascii_uppercase();
        let with_args = trimmed.contains('/');
        let key = if head == "GOHOME" && !with_args { "GOHOME-BARE".to_string() } else { head };
        *counts.entry(key).or_insert(0) += 1;
    }
    counts
}

/// The reader's events, with the changes of point 3 of the module doc.
struct Adapted<S> {
    inner: S,
    feed: Option<f64>,
}

impl<S: EventSource> EventSource for Adapted<S> {
    fn next_event(&mut self, d: &mut Vec<Diagnostic>) -> Option<(Event, Span)> {
        let (event, span) = self.inner.next_event(d)?;
        let event = match event {
            Event::Insert(Text { text }) => Event::Comment(Text { text }),
            Event::Feed(mut m) if m.feed.is_none() => {
                m.feed = self.feed;
                Event::Feed(m)
            }
            Event::Arc(mut a) if a.feed.is_none() => {
                a.feed = self.feed;
                Event::Arc(a)
            }
            other => other,
        };
        Some((event, span))
    }
}

/// Motions the program should hold for these events (point 2).
struct Expected {
    motions: usize,
    cycle: Option<DrillCycle>,
    /// Where the tool is, in the file's units.
    pos: [f64; 3],
    /// The file's units to the post's (millimetres).
    factor: f64,
    /// The post's chord tolerance, mm.
    tolerance: f64,
}

impl Expected {
    fn to(&mut self, p: [f64; 3]) {
        self.motions += 1;
        self.pos = p;
    }

    fn event(&mut self, e: &Event) {
        match e {
            Event::Rapid(m) => self.to([m.x, m.y, m.z]),
            Event::Feed(m) => self.to([m.x, m.y, m.z]),
            Event::Job(j) => self.factor = j.units.factor_to(postc_ir::Units::Mm),
            // The default post writes arcs in the XY plane; the runtime cuts
            // the others into chords, as many as its tolerance needs.
            Event::Arc(a) if a.plane != Plane::Xy => {
                let mm = |p: [f64; 3]| p.map(|v| v * self.factor);
                let g = ArcGeometry::new(mm(self.pos), mm([a.x, a.y, a.z]), mm([a.cx, a.cy, a.cz]), a.dir, a.plane);
                self.motions += g.segments(self.tolerance).min(10_000) as usize - 1;
                self.to([a.x, a.y, a.z]);
            }
            Event::Arc(a) => self.to([a.x, a.y, a.z]),
            Event::DrillCycle(c) => self.cycle = Some(c.clone()),
            Event::DrillEnd => self.cycle = None,
            Event::DrillPoint(h) => {
                let Some(c) = self.cycle.clone() else { return };
                let (clear, r, depth) = (c.retract_plane, c.reference_plane, c.depth);
                if self.pos[2] < clear {
                    self.to([self.pos[0], self.pos[1], clear]);
                }
                self.to([h.x, h.y, clear]);
                if r < clear {
                    self.to([h.x, h.y, r]);
                }
                let peck = c.peck.filter(|p| *p > 0.0 && matches!(c.kind, DrillKind::Deep | DrillKind::ChipBreak));
                let mut z = r;
                while let Some(step) = peck.filter(|_| z - depth > 1e-9) {
                    z = (z - step).max(depth);
                    self.to([h.x, h.y, z]);
                    if z > depth {
                        let back = if c.kind == DrillKind::Deep { r } else { z + step.min(0.5 * step) };
                        self.to([h.x, h.y, back]);
                        self.to([h.x, h.y, z]);
                    }
                }
                if peck.is_none() {
                    self.to([h.x, h.y, depth]);
                }
                self.to([h.x, h.y, clear]);
            }
            _ => {}
        }
    }
}

fn default_post(sources: &mut SourceMap) -> Post {
    let name = Path::new(postc::library::DEFAULT.name);
    postc_driver::compile_post_bytes(name, postc::library::DEFAULT.text, None, sources).post.unwrap()
}

/// Reads, posts and checks one file; returns what went wrong.
/// What [`check_file`] says of a file whose moves tilt the tool.
const TILTED: &str = "a move tilts the tool";

fn check_file(path: &Path, rs274: Option<&Path>) -> Result<String, String> {
    let mut sources = postc_report::source_map();
    let diags = postc_driver::check_toolpath(path, &mut sources);
    let errors: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
    if is_binary(path) {
        return match errors.as_slice() {
            [e] if e.code == "CL001" => Ok("binary CL file: one CL001 error, as it should".into()),
            _ => Err(format!("the binary CL file should give exactly one CL001 error: {errors:?}")),
        };
    }
    if !errors.is_empty() {
        return Err(format!("read with errors: {errors:?}"));
    }
    let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
    let records = count_records(&text);
    let n = |k: &str| records.get(k).copied().unwrap_or(0);
    let feed = (n("FEDRAT") == 0).then_some(100.0);
    // Events, counted, and what the program should hold.
    let mut reader = postc_driver::open_toolpath(path, &mut sources).unwrap();
    let mut d = Vec::new();
    let post = default_post(&mut sources);
    let tolerance = post.options.arc_tolerance;
    let mut expected = Expected { motions: 0, cycle: None, pos: [0.0; 3], factor: 1.0, tolerance };
    let (mut arcs, mut linear) = (0, 0);
    // A move that tilts the tool (RT040 for a post that writes X, Y and Z).
    let mut tilts = false;
    while let Some((event, _)) = reader.next_event(&mut d) {
        if let Event::Rapid(postc_ir::event::Move { tool_axis: Some([_, _, k]), .. })
        | Event::Feed(postc_ir::event::FeedMove { tool_axis: Some([_, _, k]), .. }) = &event
        {
            tilts |= 1.0 - k > 1e-6;
        }
        match &event {
            Event::Arc(_) => arcs += 1,
            Event::Rapid(_) | Event::Feed(_) | Event::DrillPoint(_) => linear += 1,
            _ => {}
        }
        expected.event(&event);
    }
    let dropped = d.iter().filter(|d| d.code == "CL010").count();
    let tilted = d.iter().filter(|d| d.code == "CL012").count();
    let chords: usize = d
        .iter()
        .filter(|d| d.code == "CL012")
        .filter_map(|d| d.message.split("cut as ").nth(1)?.split(' ').next()?.parse::<usize>().ok())
        .sum();
    let paired = n("CIRCLE") - dropped;
    let linear_records = n("GOTO") - paired + n("GODLTA") + n("GOHOME");
    if arcs != paired - tilted || linear != linear_records + chords {
        return Err(format!(
            "records and events disagree: {} GOTO, {} CIRCLE ({dropped} dropped, {tilted} tilted into {chords} moves), {} GODLTA, {} GOHOME/x,y,z; events: {arcs} arcs, {linear} straight moves",
            n("GOTO"),
            n("CIRCLE"),
            n("GODLTA"),
            n("GOHOME")
        ));
    }
    // Post through the default post.
    let reader = postc_driver::open_toolpath(path, &mut sources).unwrap();
    let mut source = Adapted { inner: reader, feed };
    let program = match postc_runtime::run(&post, &mut source, Output::memory(), postc_driver::run_options(&post)) {
        Ok(r) => match r.output {
            Finished::Memory(parts) => String::from_utf8_lossy(&parts.concat()).into_owned(),
            _ => unreachable!(),
        },
        Err(d) if tilts && d.iter().find(|d| d.is_error()).is_some_and(|d| d.code == "RT040") => {
            return Ok(format!("{TILTED}: refused with RT040"));
        }
        Err(d) => return Err(format!("posting failed: {d:?}")),
    };
    if tilts {
        return Err("a move tilts the tool, and the default post wrote a program".into());
    }
    let Some(rs274) = rs274 else {
        return Ok(format!("{arcs} arcs, {linear} straight moves (rs274 not on PATH)"));
    };
    let (complaints, motions) = postp::interpret(rs274, &program);
    if !complaints.is_empty() {
        return Err(format!("rs274: {complaints:?}"));
    }
    let own = program.lines().filter(|l| l.starts_with("G53")).count();
    if motions != expected.motions + own {
        return Err(format!(
            "rs274 made {motions} motions; expected {} from the events and {own} G53 retracts",
            expected.motions
        ));
    }
    Ok(format!(
        "{} GOTO, {} CIRCLE: {arcs} arcs, {linear} straight moves; {motions} motions in rs274",
        n("GOTO"),
        n("CIRCLE")
    ))
}

#[test]
fn every_corpus_cl_file_reads_posts_and_reads_back_in_rs274() {
    let Some(files) = corpus() else {
        crate::support::referee_missing("apt_corpus", "../shared/corpus/apt");
        println!("skipped: ../shared/corpus/apt is not there");
        return;
    };
    let rs274 = postp::rs274();
    if rs274.is_none() {
        println!("rs274 not found on PATH: the programs are posted but not read back");
    }
    let mut failures = Vec::new();
    let mut tilted = 0;
    for f in &files {
        match check_file(f, rs274.as_deref()) {
            Ok(summary) => {
                tilted += usize::from(summary.starts_with(TILTED));
                println!("{}: {summary}", f.display());
            }
            Err(e) => failures.push(format!("{}: {e}", f.display())),
        }
    }
    assert!(files.len() >= 31, "the corpus has {} files", files.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // Multi-axis operations and setups from below or the side (docs/apt.md).
    assert_eq!(tilted, 10, "CL files whose moves tilt the tool");
}

#[test]
fn the_acceptance_file_posts_and_reads_in_rs274() {
    let path = postp::root().join("../shared/corpus/apt/HumMan__CLSFProcessor/_3_PAZ_125_N2.cls");
    if !path.exists() {
        crate::support::referee_missing("apt_corpus", "../shared/corpus/apt");
        println!("skipped: ../shared/corpus/apt is not there");
        return;
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_postc")).arg("post").arg(&path).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    if let Some(rs274) = postp::rs274() {
        let (complaints, motions) = postp::interpret(&rs274, &String::from_utf8_lossy(&out.stdout));
        assert!(complaints.is_empty(), "{complaints:?}");
        assert!(motions > 0);
    }
}
