//! G-code output checked by a real interpreter: LinuxCNC's `rs274`.
//!
//! Every G-code post of the corpus (and of the embedded library,
//! `corpus/posts/library/`) posts every corpus toolpath; `rs274 -g -t
//! corpus/tool.tbl` must read the program without an error, and the moves it
//! reports (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED) must contain every
//! move of the toolpath, in order, at the toolpath's end points (and arc
//! centres and turning directions) within the post's printed precision.
//! Extra moves (the header's and footer's, linearized arcs' intermediate
//! chords, expanded drilling cycles) are allowed between them.
//!
//! Posts that wrap an axis around a cylinder (ROTARY_WRAP) must cut every
//! arc into straight feed moves (a G2/G3 cannot turn a rotary axis): in
//! their programs each of the arc's moves is a STRAIGHT_FEED whose end,
//! unrolled from the rotary angle back onto the plane, lies on the arc.
//! Besides the project's posts, the real wrapping posts with arc sections
//! of `../shared/corpus/vectric` are checked when that corpus is there.
//!
//! `.ci/run` installs rs274; without it the test says it is skipped (and fails under `CI=true`).

use std::path::{Path, PathBuf};

use postc_ir::event::{ArcDir, Event};
use postc_ir::{EventSource, Post, Quantity, ValueSource};
use postc_runtime::{Finished, Output};

/// Output extensions of posts that write G-code (HPGL, Heidenhain and
/// ShopBot posts write other languages).
const GCODE_EXTENSIONS: &[&str] = &["ngc", "nc", "tap", "gcode", "cnc"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

use crate::support;

use crate::support::rs274;

use rs274::{Kind, Motion};

/// A move the toolpath asks for.
#[derive(Debug, Clone, Copy)]
enum Expected {
    /// X Y Z A B C; NaN where nothing is to be compared.
    Traverse([f64; 6]),
    Feed([f64; 6]),
    Arc([f64; 6], [f64; 2], ArcDir),
    /// An arc of a wrapped post: its end as rs274 sees it, and the circle
    /// (centre and radius) in the unrolled plane.
    WrappedArc([f64; 6], [f64; 2], f64),
}

/// How a wrapped post prints an axis: the axis index that turns into A, the
/// cylinder diameter and the direction.
#[derive(Clone, Copy)]
struct Wrap {
    axis: usize,
    /// Where the angle goes: 3, 4, 5 for A, B, C (the wrapped axis itself when the post keeps its letter).
    rotary: usize,
    diameter: f64,
    sign: f64,
}

impl Wrap {
    /// A point as rs274 sees it: X Y Z A B C, with the wrapped axis moved
    /// to its rotary letter; NaN marks what is not compared.
    fn apply(wrap: &Option<Wrap>, p: [f64; 3]) -> [f64; 6] {
        let mut q = [p[0], p[1], p[2], f64::NAN, f64::NAN, f64::NAN];
        if let Some(w) = wrap {
            let value = if w.diameter > 0.0 {
                w.sign * p[w.axis] / (std::f64::consts::PI * w.diameter) * 360.0
            } else {
                p[w.axis]
            };
            q[w.axis] = f64::NAN;
            q[w.rotary] = value;
        }
        q
    }

    /// The plane point (X, Y) of an rs274 end point: the rotary angle
    /// unrolled back into a length.
    fn unroll(&self, end: [f64; 6]) -> [f64; 2] {
        let mut xy = [end[0], end[1]];
        let v = end[self.rotary];
        xy[self.axis] =
            if self.diameter > 0.0 { self.sign * v / 360.0 * std::f64::consts::PI * self.diameter } else { v };
        xy
    }
}

/// The toolpath's moves in the post's units, and the post's wrap.
fn expected_moves(toolpath: &Path, post: &Post) -> (Vec<Expected>, Option<Wrap>) {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
    let mut diags = Vec::new();
    let mut factor = 1.0;
    let mut wrap = None;
    let mut moves = Vec::new();
    while let Some((event, _)) = source.next_event(&mut diags) {
        let p = |x: f64, y: f64, z: f64| Wrap::apply(&wrap, [x * factor, y * factor, z * factor]);
        match event {
            Event::Job(job) => {
                factor = job.units.factor_to(post.output_units().unwrap_or(job.units));
                if let Some(w) = post.options.rotary_wrap {
                    // Without a wrap diameter the runtime prints the distance unwrapped (RT015).
                    let diameter = job.wrap_diameter.filter(|d| *d > 0.0);
                    let axis = if w.axis == postc_ir::post::WrappedAxis::X { 0 } else { 1 };
                    wrap = Some(Wrap {
                        axis,
                        rotary: match w.letter.map(|l| l.to_ascii_uppercase()) {
                            Some('A') => 3,
                            Some('B') => 4,
                            Some('C') => 5,
                            _ => axis,
                        },
                        diameter: diameter.map_or(0.0, |d| d * factor),
                        sign: if w.reversed && diameter.is_some() { -1.0 } else { 1.0 },
                    });
                }
            }
            Event::Rapid(m) => moves.push(Expected::Traverse(p(m.x, m.y, m.z))),
            Event::Feed(m) => moves.push(Expected::Feed(p(m.x, m.y, m.z))),
            Event::Arc(a) if a.plane == postc_ir::event::Plane::Xy && wrap.is_some() => {
                let radius = (a.x - a.cx).hypot(a.y - a.cy) * factor;
                moves.push(Expected::WrappedArc(p(a.x, a.y, a.z), [a.cx * factor, a.cy * factor], radius))
            }
            Event::Arc(a) => {
                let centre = if wrap.is_some() { [f64::NAN; 2] } else { [a.cx * factor, a.cy * factor] };
                moves.push(Expected::Arc(p(a.x, a.y, a.z), centre, a.dir))
            }
            _ => {}
        }
    }
    assert!(diags.is_empty(), "{}: {diags:?}", toolpath.display());
    (moves, wrap)
}

fn close<const N: usize>(a: [f64; N], b: [f64; N], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| x.is_nan() || (x - y).abs() <= tol)
}

/// Whether an rs274 move is the expected one.
fn matches(e: &Expected, c: &Motion, tol: f64) -> bool {
    match (e, c.kind) {
        (Expected::Traverse(p), Kind::Traverse)
        | (Expected::Feed(p), Kind::Feed)
        | (Expected::Arc(p, _, _), Kind::Feed)
        | (Expected::WrappedArc(p, _, _), Kind::Feed) => close(*p, c.end, tol),
        (Expected::Arc(p, centre, dir), Kind::Arc { centre: cq, rotation }) => {
            let turn = if *dir == ArcDir::Ccw { 1 } else { -1 };
            close(*p, c.end, tol) && (!centre[0].is_finite() || close(*centre, cq, 2.0 * tol)) && rotation == turn
        }
        _ => false,
    }
}

/// The precision a post prints positions with.
fn tolerance(post: &Post) -> f64 {
    let decimals = post
        .variables
        .iter()
        .find(|v| v.source == ValueSource::Quantity(Quantity::X))
        .map_or(3, |v| post.formats[v.format.index()].decimals);
    10f64.powi(-(decimals as i32)) + 1e-4
}

/// Real posts (`../shared/corpus/vectric`) that wrap an axis and have arc
/// sections: their arcs must come out as chords.
const REAL_WRAPPING_POSTS: &[&str] = &[
    "MakeraInc__CarveraProfiles/Carvera Wrap X2A ATC (mm) (!.cnc).pp",
    "neilferreri__V-Carve-PPs/Grbl_mm_TC_Rotary.pp",
];

#[test]
fn gcode_posts_read_in_rs274_with_the_toolpaths_motion() {
    let Some(rs274) = rs274::find() else {
        println!("skipped: rs274 not found on PATH (bash .ci/run installs it from Debian's linuxcnc-uspace)");
        return;
    };
    let toolpaths = support::files(&root().join("corpus/toolpaths"), "ron");
    let mut checked = 0;
    let mut failures = Vec::new();
    let mut posts = support::files(&root().join("corpus/posts/vectric"), "pp");
    // The embedded library's Vectric posts (docs/posts.md): LinuxCNC, grbl, Mach3/4.
    posts.extend(support::files(&root().join("corpus/posts/library"), "pp"));
    posts.extend(
        REAL_WRAPPING_POSTS.iter().map(|rel| root().join("../shared/corpus/vectric").join(rel)).filter(|p| p.is_file()),
    );
    for post_path in &posts {
        let name = post_path.file_name().unwrap().to_string_lossy();
        let mut sources = postc_report::source_map();
        let compiled = postc_driver::compile_post(post_path, None, &mut sources);
        assert!(!compiled.has_errors(), "{name}: {:?}", compiled.diagnostics);
        let post = compiled.post.unwrap();
        if !GCODE_EXTENSIONS.contains(&post.info.file_extension.to_ascii_lowercase().as_str()) {
            continue;
        }
        for toolpath in &toolpaths {
            let label = format!("{name} over {}", toolpath.file_name().unwrap().to_string_lossy());
            let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
            let program =
                match postc_runtime::run(&post, &mut source, Output::memory(), postc_driver::run_options(&post)) {
                    Ok(r) => match r.output {
                        Finished::Memory(parts) => parts,
                        _ => unreachable!(),
                    },
                    Err(d) => {
                        failures.push(format!("{label}: posting failed: {d:?}"));
                        continue;
                    }
                };
            if program.len() != 1 {
                continue; // tape-split programs are checked part by part elsewhere
            }
            let actual = match rs274::run(&rs274, &String::from_utf8_lossy(&program[0])) {
                Ok(m) => m,
                Err(e) => {
                    failures.push(format!("{label}: {e}"));
                    continue;
                }
            };
            check_motion(&label, toolpath, &post, &actual, &mut failures);
            checked += 1;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(checked > 0, "no program was checked");
    println!("rs274 read {checked} programs with the toolpaths' motion");
}

/// Whether rs274's moves contain the toolpath's, in order (and, for a
/// wrapped post, every chord of an arc on the unrolled arc).
fn check_motion(label: &str, toolpath: &Path, post: &Post, actual: &[Motion], failures: &mut Vec<String>) {
    let tol = tolerance(post);
    let (expected, wrap) = expected_moves(toolpath, post);
    if wrap.is_some()
        && let Some(arc) = actual.iter().find(|c| matches!(c.kind, Kind::Arc { .. }))
    {
        failures.push(format!("{label}: a wrapped post printed an arc (G2/G3 cannot turn the rotary axis): {arc:?}"));
        return;
    }
    let mut at = 0;
    for (i, e) in expected.iter().enumerate() {
        match actual[at..].iter().position(|c| matches(e, c, tol)) {
            Some(k) => {
                if let (Expected::WrappedArc(_, centre, radius), Some(w)) = (e, &wrap) {
                    // Every chord of the arc ends on it, once unrolled.
                    for c in &actual[at..=at + k] {
                        let [x, y] = w.unroll(c.end);
                        let off = ((x - centre[0]).hypot(y - centre[1]) - radius).abs();
                        if c.kind != Kind::Feed || off > 2.0 * tol {
                            failures.push(format!("{label}: move {i} (a wrapped arc): {c:?} is not a feed move ending on the arc (off by {off:.4})"));
                        }
                    }
                }
                at += k + 1;
            }
            None => {
                failures
                    .push(format!("{label}: move {i} of the toolpath ({e:?}) is not among rs274's moves after #{at}"));
                return;
            }
        }
    }
}

/// A tool table of tools 1 to 20, every diameter zero, in `dir`.
fn zero_diameter_table(dir: &Path) -> PathBuf {
    let table = dir.join("zero.tbl");
    let rows: String = (1..=20).map(|t| format!("T{t} P{t} D0 Z+0.000 ;tool {t}\n")).collect();
    std::fs::write(&table, rows).expect("the tool table");
    table
}

/// The CIMCO corpus posts written for LinuxCNC-dialect controllers.
const CIMCO_RS274_POSTS: &[&str] = &["linuxcnc_field.js", "mach3_field.js"];

/// The CIMCO posts for LinuxCNC and Mach3 post their toolpaths (as their
/// goldens do) into programs rs274 reads with the toolpaths' motion. The
/// tool table gives every tool a zero diameter: rs274 standalone reads the
/// table's diameters in inches whatever G20/G21 says (corpus/tool.tbl's 6
/// would be a 152 mm cutter, longer than every compensation entry move of
/// `cimco/mill.ron`), and with no radius the compensated path is the
/// programmed one, which is what is compared. G41/G42/G40 are still
/// interpreted and checked (entry and exit moves, plane).
#[test]
fn cimco_linuxcnc_posts_read_in_rs274_with_the_toolpaths_motion() {
    let Some(rs274) = rs274::find() else {
        println!("skipped: rs274 not found on PATH (bash .ci/run installs it from Debian's linuxcnc-uspace)");
        return;
    };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let table = zero_diameter_table(dir.path());
    let (mut checked, mut failures) = (0, Vec::new());
    for name in CIMCO_RS274_POSTS {
        let post_path = root().join("corpus/posts/cimco").join(name);
        let post = support::cimco::compile(&post_path).expect("the post compiles");
        for toolpath in support::cimco::toolpaths(&post) {
            let label = format!("{name} over {}", toolpath.file_name().unwrap().to_string_lossy());
            let program = match support::cimco::post_toolpath(&post, &toolpath) {
                Ok(p) => p,
                Err(e) => {
                    failures.push(format!("{label}: posting failed: {e}"));
                    continue;
                }
            };
            match rs274::run_with_table(&rs274, &String::from_utf8_lossy(&program), &table) {
                Ok(actual) => check_motion(&label, &toolpath, &post, &actual, &mut failures),
                Err(e) => failures.push(format!("{label}: {e}")),
            }
            checked += 1;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert_eq!(checked, 3 * CIMCO_RS274_POSTS.len(), "every post and toolpath");
    println!("rs274 read {checked} CIMCO programs with the toolpaths' motion");
}

/// The field-style CIMCO posts (`corpus/posts/cimco-styles/`, one Fanuc
/// mill written six ways) as Node.js prints them: rs274 reads their
/// goldens (postc does not print them all yet, `tests/cimco_styles.rs`)
/// with the toolpaths' motion, cutter compensation read with the
/// zero-diameter table of the test above. No postc post is involved: the
/// programs are in the toolpaths' millimetres with three decimals, which
/// is what an empty post says to `check_motion`.
#[test]
fn cimco_field_style_goldens_read_in_rs274_with_the_toolpaths_motion() {
    let Some(rs274) = rs274::find() else {
        println!("skipped: rs274 not found on PATH (bash .ci/run installs it from Debian's linuxcnc-uspace)");
        return;
    };
    let dir = tempfile::tempdir().expect("a temporary folder");
    let table = zero_diameter_table(dir.path());
    let (mut checked, mut failures) = (0, Vec::new());
    for (golden, toolpath) in support::cimco::style_goldens() {
        let name = golden.file_name().unwrap().to_string_lossy().into_owned();
        let program = match std::fs::read_to_string(&golden) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        match rs274::run_with_table(&rs274, &program, &table) {
            Ok(actual) => check_motion(&name, &toolpath, &Post::default(), &actual, &mut failures),
            Err(e) => failures.push(format!("{name}: {e}")),
        }
        checked += 1;
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(checked >= 18, "only {checked} field-style goldens");
    println!("rs274 read {checked} field-style CIMCO programs with the toolpaths' motion");
}
