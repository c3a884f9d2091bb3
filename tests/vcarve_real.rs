//! Programs VCarve itself wrote (`../shared/vcarve-real/`), reproduced.
//!
//! Each program was posted by VCarve with the ShopSabre post beside it and
//! not edited. Its toolpath is not available, so it is rebuilt from the
//! program: every G0/G1/G2/G3 line becomes a rapid, feed or arc event (arc
//! centres from I/J), the feeds as printed, the tools and spindle speeds of
//! the HEADER and TOOLCHANGE lines, the first tool's cut feed from the
//! HEADER's `[F]` line. The rebuilt toolpath is posted through postc with
//! the same post and compared with the real program line by line, line
//! endings included. Every line that differs must be listed in
//! [`ARTEFACTS`] with the reason it is an artefact of the rebuilding, not
//! something postc does differently from VCarve.
//!
//! What the program says, and the rebuilding keeps:
//!
//! - A word left out means the value did not change: the rebuilt move keeps
//!   the previous value exactly.
//! - A modal (`C`) word printed with the same text as the word printed
//!   before it means the value changed by less than the last printed digit
//!   (VCarve compares values, docs/vectric.md): the rebuilt value is the
//!   printed one moved by a millionth of an inch, which prints the same.
//! - A G-code line is a move when it has the shape of the post's move
//!   sections (`"G0 [X] [Y] [Z]"` keeps its three blanks when a word prints
//!   nothing); the FOOTER's literal `"G0 Z2.0000"` is not.
//! - A rapid that prints X, Y and Z with Z as printed before starts a new
//!   toolpath (modal memory is cleared as a toolpath starts, so its first
//!   move prints every word); so does the first move after a TOOLCHANGE.
//!
//! When `../shared/vcarve-real` is not there the test fails under `CI=true`
//! and is skipped, with a message, elsewhere.

use crate::support;
use std::path::{Path, PathBuf};

use postc_ir::event::{ArcDir, ArcMove, Event, FeedMove, Job, Move, Tool, ToolpathStart, VecSource};
use postc_ir::{FileId, Post, Units};
use postc_runtime::{Finished, Output};

fn shared() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/vcarve-real")
}

/// The programs of `../shared/vcarve-real/`, all posted with this post.
const POST: &str = "ShopSabre_DC_ATC_speed_arc_inch.pp";
const PROGRAMS: &[&str] = &["XRT-50.tap", "LGC 50 Job 1 Board 1.tap", "lgc-72-board-7.reference.tap"];

/// Why a line of a real program can differ from postc's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reason {
    /// A pocket's link from one ring to the next, and the ring's first
    /// move: VCarve printed them through FIRST_FEED_MOVE
    /// (`"G1 [X] [Y] [Z] [F]"`: the line ends in one more blank than
    /// FEED_MOVE's `"G1 [X] [Y] [Z]"`, that of its empty `[F]`) in the
    /// middle of a run of feed moves at one feed, with no rapid and no feed
    /// change before them. VCarve starts a new run of feed moves where the
    /// pocket starts a ring; the program does not show where a ring starts,
    /// so the rebuilt toolpath is one run and postc prints FEED_MOVE, the
    /// same words.
    RingLink,
}

impl Reason {
    /// Whether the real line and postc's differ as the reason says.
    fn explains(self, real: &[u8], ours: &[u8]) -> bool {
        match self {
            Reason::RingLink => {
                let body = ours.strip_suffix(b"\r\n").unwrap_or(ours);
                real.strip_suffix(b"\r\n").is_some_and(|r| r.strip_suffix(b" ") == Some(body))
            }
        }
    }
}

/// The lines (1-based) of each program that differ from postc's output,
/// and why: the three pockets of lgc-72-board-7 (two at two depths), each
/// with three ring links.
const ARTEFACTS: &[(&str, &[(usize, Reason)])] = &[(
    "lgc-72-board-7.reference.tap",
    &[
        (81, Reason::RingLink),
        (82, Reason::RingLink),
        (86, Reason::RingLink),
        (87, Reason::RingLink),
        (91, Reason::RingLink),
        (92, Reason::RingLink),
        (103, Reason::RingLink),
        (104, Reason::RingLink),
        (108, Reason::RingLink),
        (109, Reason::RingLink),
        (113, Reason::RingLink),
        (114, Reason::RingLink),
        (125, Reason::RingLink),
        (126, Reason::RingLink),
        (130, Reason::RingLink),
        (131, Reason::RingLink),
        (135, Reason::RingLink),
        (136, Reason::RingLink),
        (147, Reason::RingLink),
        (148, Reason::RingLink),
        (152, Reason::RingLink),
        (153, Reason::RingLink),
        (157, Reason::RingLink),
        (158, Reason::RingLink),
    ],
)];

/// A program rebuilt into toolpath events.
struct Rebuilt {
    events: Vec<Event>,
    /// Words printed with the text printed before them (values moved).
    moved: usize,
    toolpaths: usize,
}

/// A number word of a line: `X1.2345` gives ('X', "1.2345").
fn words(line: &str) -> Vec<(char, &str)> {
    line.split_whitespace().filter_map(|w| Some((w.chars().next()?, w.get(1..)?))).collect()
}

fn number(text: &str, line: usize) -> f64 {
    text.parse().unwrap_or_else(|_| panic!("line {line}: `{text}` is not a number"))
}

/// Rebuilds the toolpath of a program the ShopSabre post wrote.
fn rebuild(program: &str) -> Rebuilt {
    const NUDGE: f64 = 1e-6;
    let mut events = vec![Event::Job(Box::new(Job { units: Units::Inch, ..Job::default() }))];
    let mut tool = Tool::default();
    let mut tool_pending = false;
    let mut started = false;
    let mut pos = [0.0f64; 3];
    let mut printed: [Option<String>; 3] = [None, None, None];
    let mut feed = 0.0;
    let (mut moved, mut toolpaths) = (0, 0);
    for (i, line) in program.lines().enumerate() {
        let n = i + 1;
        let ws = words(line);
        let Some(&(letter, code)) = ws.first() else { continue };
        match (letter, code) {
            ('T', t) if t.parse::<u32>().is_ok() => {
                tool = Tool { number: number(t, n) as u32, ..Tool::default() };
                tool_pending = true;
            }
            ('S', s) if ws.len() == 1 => tool.spindle_speed = number(s, n),
            // The HEADER's bare `[F]`: the first tool's cut feed.
            ('F', f) if ws.len() == 1 && !started => tool.cut_feed = number(f, n),
            // A move section's line: `G0 [X] [Y] [Z]` keeps its blanks when
            // a word prints nothing; the FOOTER's literal `G0 Z2.0000` has one.
            ('G', g @ ("0" | "1" | "2" | "3")) if line.split(' ').count() >= 4 => {
                let axes: Vec<(usize, &str)> = ws.iter().filter_map(|&(l, v)| "XYZ".find(l).map(|a| (a, v))).collect();
                let new_toolpath =
                    tool_pending || (g == "0" && axes.len() == 3 && printed[2].as_deref() == Some(axes[2].1));
                if new_toolpath {
                    if tool_pending {
                        events.push(Event::Tool(tool.clone()));
                        tool_pending = false;
                    }
                    events.push(Event::ToolpathStart(ToolpathStart {
                        name: format!("Toolpath {}", toolpaths + 1),
                        ..ToolpathStart::default()
                    }));
                    toolpaths += 1;
                    printed = [None, None, None];
                    started = true;
                }
                let start = pos;
                for (axis, text) in axes {
                    let value = number(text, n);
                    pos[axis] = if printed[axis].as_deref() == Some(text) {
                        moved += 1;
                        if pos[axis] == value + NUDGE { value + 2.0 * NUDGE } else { value + NUDGE }
                    } else {
                        value
                    };
                    printed[axis] = Some(text.to_string());
                }
                for &(l, v) in &ws[1..] {
                    if l == 'F' {
                        feed = number(v, n);
                    }
                }
                let [x, y, z] = pos;
                let word = |c: char| ws.iter().find(|w| w.0 == c).map(|w| number(w.1, n));
                events.push(match g {
                    "0" => Event::Rapid(Move { x, y, z, ..Move::default() }),
                    "1" => Event::Feed(FeedMove { x, y, z, feed: Some(feed), ..FeedMove::default() }),
                    _ => Event::Arc(ArcMove {
                        dir: if g == "2" { ArcDir::Cw } else { ArcDir::Ccw },
                        x,
                        y,
                        z,
                        cx: start[0] + word('I').unwrap_or(0.0),
                        cy: start[1] + word('J').unwrap_or(0.0),
                        feed: Some(feed),
                        ..ArcMove::default()
                    }),
                });
            }
            _ => {}
        }
    }
    events.push(Event::End);
    Rebuilt { events, moved, toolpaths }
}

fn post_events(post: &Post, events: Vec<Event>) -> Vec<u8> {
    let mut source = VecSource::new(events, FileId(0));
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => parts.concat(),
            _ => unreachable!("a memory run"),
        },
        Err(d) => panic!("posting failed: {d:?}"),
    }
}

fn lines(bytes: &[u8]) -> Vec<&[u8]> {
    bytes.split_inclusive(|&b| b == b'\n').collect()
}

fn show(line: &[u8]) -> String {
    String::from_utf8_lossy(line).replace('\r', "\\r").replace('\n', "\\n")
}

/// The runs of lines where two programs differ, found by a longest common
/// subsequence of lines: (first real line, real lines, first line of ours,
/// lines of ours), 0-based.
fn hunks(real: &[&[u8]], ours: &[&[u8]]) -> Vec<(usize, usize, usize, usize)> {
    let (n, m) = (real.len(), ours.len());
    // common[i][j]: the longest common subsequence of real[i..] and ours[j..].
    let mut common = vec![vec![0u32; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            common[i][j] =
                if real[i] == ours[j] { common[i + 1][j + 1] + 1 } else { common[i + 1][j].max(common[i][j + 1]) };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut out = Vec::new();
    while i < n || j < m {
        if i < n && j < m && real[i] == ours[j] {
            i += 1;
            j += 1;
            continue;
        }
        let (i0, j0) = (i, j);
        while (i < n || j < m) && !(i < n && j < m && real[i] == ours[j]) {
            if j == m || (i < n && common[i + 1][j] >= common[i][j + 1]) {
                i += 1;
            } else {
                j += 1;
            }
        }
        out.push((i0, i - i0, j0, j - j0));
    }
    out
}

#[test]
fn vcarve_programs_reproduce_line_for_line() {
    let dir = shared();
    if !dir.join(POST).is_file() {
        crate::support::referee_missing("vcarve_real", "../shared/vcarve-real");
        println!("skipped: ../shared/vcarve-real not found");
        return;
    }
    let post = support::compile_file(&dir.join(POST));
    let mut failures = Vec::new();
    let (mut total, mut differ) = (0, 0);
    for name in PROGRAMS {
        let real = std::fs::read(dir.join(name)).expect("read the program");
        let rebuilt = rebuild(&String::from_utf8_lossy(&real));
        let ours = post_events(&post, rebuilt.events);
        let listed: &[(usize, Reason)] = ARTEFACTS.iter().find(|(p, _)| p == name).map_or(&[], |(_, l)| *l);
        let (real_lines, our_lines) = (lines(&real), lines(&ours));
        let mut differing = Vec::new();
        for (r0, rn, o0, on) in hunks(&real_lines, &our_lines) {
            differing.extend(r0 + 1..=r0 + rn);
            let explained = rn == on
                && (0..rn).all(|k| {
                    listed
                        .iter()
                        .any(|&(l, reason)| l == r0 + k + 1 && reason.explains(real_lines[r0 + k], our_lines[o0 + k]))
                });
            if explained {
                continue;
            }
            let mut text = format!(
                "{name}:{}: {rn} real lines, {on} of postc's, not listed as artefacts of the rebuilding",
                r0 + 1
            );
            for line in &real_lines[r0..r0 + rn] {
                text += &format!("\n    real  {}", show(line));
            }
            for line in &our_lines[o0..o0 + on] {
                text += &format!("\n    postc {}", show(line));
            }
            failures.push(text);
        }
        total += real_lines.len();
        differ += differing.len();
        for (n, reason) in listed {
            if !differing.contains(n) {
                failures.push(format!("{name}:{n}: listed as {reason:?}, but postc prints the real line"));
            }
        }
        println!(
            "{name}: {} lines, {} differ ({} listed), {} toolpaths, {} words moved",
            real_lines.len(),
            differing.len(),
            listed.len(),
            rebuilt.toolpaths,
            rebuilt.moved
        );
    }
    println!("{} of {total} lines the same", total - differ);
    assert!(failures.is_empty(), "{} runs of lines differ:\n{}", failures.len(), failures.join("\n"));
}
