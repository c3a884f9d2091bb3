//! The post's units decide the output units in every dialect
//! (docs/units.md): a toolpath in inches posted by a millimetre post, and
//! one in millimetres posted by an inch post, move the tool where the
//! toolpath goes. LinuxCNC's `rs274` is the referee: it reads each program
//! (G20/G21 included) and the moves it reports, in millimetres, must hold
//! the toolpath's moves in millimetres, in order.
//!
//! The dialects: Vectric (`UNITS`), CIMCO JavaScript (a post that states no
//! units and writes `G21`, as `haas_field.js` does: the case), VcPost
//! (`Postc.Units`, and a post whose `Metric` picks G20 or G21), and `postp`
//! (the CL file's units).

use std::path::{Path, PathBuf};

use postc_ir::{Event, EventSource, Post, Units};

use crate::support;

use crate::support::rs274;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The end points of the toolpath's moves, in millimetres.
fn toolpath_mm(toolpath: &Path) -> Vec<[f64; 3]> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).unwrap();
    let (mut diags, mut ends, mut mm) = (Vec::new(), Vec::new(), 1.0);
    while let Some((event, _)) = source.next_event(&mut diags) {
        match event {
            Event::Job(job) => mm = job.units.mm_per_unit(),
            Event::Rapid(m) => ends.push([m.x * mm, m.y * mm, m.z * mm]),
            Event::Feed(m) => ends.push([m.x * mm, m.y * mm, m.z * mm]),
            Event::Arc(a) => ends.push([a.x * mm, a.y * mm, a.z * mm]),
            _ => {}
        }
    }
    assert!(!postc_ir::diagnostic::has_errors(&diags), "{}: {diags:?}", toolpath.display());
    ends
}

fn compile(path: &Path, text: &str) -> Post {
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(path, text.as_bytes(), None, &mut sources);
    assert!(!compiled.has_errors(), "{}: {:?}", path.display(), compiled.diagnostics);
    compiled.post.unwrap()
}

fn post(post: &Post, toolpath: &Path) -> String {
    String::from_utf8(support::post_parts(post, toolpath).unwrap().concat()).unwrap()
}

/// rs274 reads `program` with the toolpath's motion in millimetres, in
/// `units`. A tool table of zero diameters: rs274 standalone reads a
/// table's diameters in inches whatever the program says.
fn moves_as_the_toolpath(label: &str, rs274: &Path, program: &str, toolpath: &Path, units: Units) {
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("zero.tbl");
    let rows: String = (1..=20).map(|t| format!("T{t} P{t} D0 Z+0.000 ;tool {t}\n")).collect();
    std::fs::write(&table, rows).unwrap();
    let actual = rs274::run_with_table(rs274, program, &table).unwrap_or_else(|e| panic!("{label}: {e}\n{program}"));
    assert!(
        actual.iter().all(|m| m.inch == (units == Units::Inch)),
        "{label}: rs274 did not read the program in {units:?}\n{program}"
    );
    let mut at = 0;
    for (i, e) in toolpath_mm(toolpath).iter().enumerate() {
        let near = |m: &rs274::Motion| m.end_mm().iter().zip(e).all(|(a, b)| (a - b).abs() <= 0.02);
        // A move to where the last one ended (the Creo file's 0.00003 mm
        // steps) prints no new position: the last move made it.
        if at > 0 && near(&actual[at - 1]) {
            continue;
        }
        match actual[at..].iter().position(near) {
            Some(k) => at += k + 1,
            None => panic!(
                "{label}: move {i} of the toolpath, {e:?} mm, is not among rs274's moves after #{at}: {:?}\n{program}",
                actual[at..].iter().take(4).map(rs274::Motion::end_mm).collect::<Vec<_>>()
            ),
        }
    }
}

/// A small job in inches.
const INCH_JOB: &str = "Job(units: Inch, safe_z: 0.5)
Tool(number: 1, name: \"Quarter inch end mill\", diameter: 0.25, spindle_speed: 12000, cut_feed: 40, plunge_feed: 10)
ToolpathStart(name: \"Pocket\")
Rapid(x: 1, y: 1, z: 0.5)
Feed(x: 1, y: 1, z: -0.125, intent: Plunge)
Feed(x: 5, y: 1, z: -0.125)
Arc(dir: Ccw, x: 5, y: 3, z: -0.125, cx: 5, cy: 2)
Feed(x: 1, y: 3, z: -0.125, feed: 30)
Rapid(x: 1, y: 3, z: 0.5)
ToolpathEnd
End
";

fn find_rs274() -> Option<PathBuf> {
    let found = rs274::find();
    if found.is_none() {
        println!("skipped: rs274 not found on PATH (bash .ci/run installs it from Debian's linuxcnc-uspace)");
    }
    found
}

/// The case: `haas_field.js` states no units and writes `G21`;
/// an inch CL file posted through it wrote G21 and inch numbers. Now its
/// output is in millimetres, as its `G21` says.
#[test]
fn a_cimco_post_that_writes_g21_writes_millimetres() {
    let Some(rs274) = find_rs274() else { return };
    let path = root().join("corpus/posts/cimco/haas_field.js");
    let haas = compile(&path, &std::fs::read_to_string(&path).unwrap());
    assert_eq!((haas.info.units, haas.output_units()), (None, Some(Units::Mm)));
    // The corpus's inch job names a tool "Laser (5 W)", which this post
    // writes inside a comment unfiltered: rs274 refuses the nested
    // parenthesis. This inch job has a line, an arc and a plunge.
    let dir = tempfile::tempdir().unwrap();
    let inch = dir.path().join("inch.ron");
    std::fs::write(&inch, INCH_JOB).unwrap();
    let mut toolpaths = vec![inch];
    let creo = root().join("../shared/corpus/apt/mbourque__creo_nc_tools/Haas_Machine__mworks.ncl");
    if creo.is_file() {
        toolpaths.push(creo);
    } else {
        println!("../shared/corpus not found: the inch CL file of the issue is not posted");
    }
    for toolpath in &toolpaths {
        let program = post(&haas, toolpath);
        assert!(program.contains("G21"), "{program}");
        moves_as_the_toolpath(
            &format!("haas_field.js over {}", toolpath.display()),
            &rs274,
            &program,
            toolpath,
            Units::Mm,
        );
    }
    if toolpaths.len() == 2 {
        let program = post(&haas, &toolpaths[1]);
        assert!(program.contains("N50 G0 X177.8000 Y-73.8187 Z82.4230\n"), "{program}");
        assert!(program.contains(" F30319.0\n"), "1193.663081 IPM is 30319.0 mm/min: {program}");
    }
}

/// `siemens_840d.js` writes ` G17 G90 G94 G71 G40` and `absolute_centre.js`
/// `G90G17G71G90.1`: `G71`, the millimetre word of Siemens and Heidenhain
/// ISO, is their statement (they write no `G21` or `G20`). Over an inch
/// job they wrote the inch numbers under `G71` before, which verify
/// refused (VF030); now they write millimetres and verify finds nothing.
#[test]
fn cimco_posts_that_write_g71_write_millimetres() {
    let dir = tempfile::tempdir().unwrap();
    let inch = dir.path().join("inch.ron");
    std::fs::write(&inch, INCH_JOB).unwrap();
    for name in ["siemens_840d.js", "absolute_centre.js"] {
        let path = root().join("corpus/posts/cimco").join(name);
        let cimco = compile(&path, &std::fs::read_to_string(&path).unwrap());
        assert_eq!((cimco.info.units, cimco.output_units()), (None, Some(Units::Mm)), "{name}");
        let program = post(&cimco, &inch);
        // X5 inches is X127 millimetres.
        assert!(program.contains("X127"), "{name}: {program}");
        let settings = postc_verify::Settings::from_post(&cimco, postc_verify::Controller::Generic, 0.01);
        let found = crate::support::verifying::verify(program.as_bytes(), &inch, &settings);
        let errors = crate::support::verifying::errors(&found);
        assert!(errors.is_empty(), "{name}: {errors:?}\n{program}");
    }
}

/// A Fusion post writes the job's units with the formats it made for them
/// at its top level: `linuxcnc_mill.cps` over the Creo inch CL file writes
/// `G20` and four decimals (`xyzFormat`'s `unit == MM ? 3 : 4`), and
/// LinuxCNC's `rs274` reads it in inches with the toolpath's motion. The
/// host set `unit` only at `onOpen` before: three decimals, and arcs cut
/// into chords by a tolerance read as inches.
#[test]
fn a_fusion_post_writes_an_inch_job_in_inches_with_its_inch_formats() {
    let Some(rs274) = find_rs274() else { return };
    let path = root().join("../shared/corpus/fusion/85vmh__LinuxCNCFusionPosts/linuxcnc_mill.cps");
    let creo = root().join("../shared/corpus/apt/mbourque__creo_nc_tools/sketched-tools-inch__mworks.ncl");
    if !path.is_file() || !creo.is_file() {
        support::referee_missing("units", "../shared/corpus");
        return;
    }
    let linuxcnc = compile(&path, &std::fs::read_to_string(&path).unwrap());
    let program = post(&linuxcnc, &creo);
    assert!(program.contains("G20"), "{program}");
    // GOTO / 2.4782263819, 4.2940606520, 1.4375: four decimals, and the
    // first arc as G3 with its centre, not chords.
    assert!(program.contains("G0 X2.4782 Y4.2941\r\n"), "{program}");
    assert!(program.contains("G3 X2.5011 Y3.6441 I0.1427 J0.009"), "{program}");
    moves_as_the_toolpath("linuxcnc_mill.cps over the Creo inch CL file", &rs274, &program, &creo, Units::Inch);
}

/// Vectric: `UNITS` decides; a post without it that writes `G21` writes
/// millimetres; an inch post writes a millimetre toolpath in inches.
#[test]
fn vectric_posts_write_their_units() {
    let Some(rs274) = find_rs274() else { return };
    let inch_job = root().join("corpus/toolpaths/tools_inch.ron");
    let mm_job = root().join("corpus/toolpaths/standard.ron");
    let mm_text = std::fs::read_to_string(root().join("corpus/posts/vectric/gcode_mm.pp")).unwrap();
    let no_units = mm_text.replace("UNITS = \"MM\"", "");
    assert_ne!(no_units, mm_text);
    let inch_text = std::fs::read_to_string(root().join("corpus/posts/vectric/gcode_inch.pp")).unwrap();
    for (name, text, toolpath, units) in [
        ("gcode_mm.pp", &mm_text, &inch_job, Units::Mm),
        ("gcode_mm.pp without UNITS", &no_units, &inch_job, Units::Mm),
        ("gcode_inch.pp", &inch_text, &mm_job, Units::Inch),
    ] {
        let p = compile(Path::new("post.pp"), text);
        let program = post(&p, toolpath);
        moves_as_the_toolpath(&format!("{name} over {}", toolpath.display()), &rs274, &program, toolpath, units);
    }
}

/// VcPost: `Postc.Units` decides; without it `fanuc_mill.VcPost` writes
/// the toolpath's units, and its `Metric` writes the G20 or G21 that says
/// so.
#[test]
fn vcpost_posts_write_their_units() {
    let Some(rs274) = find_rs274() else { return };
    let inch_job = root().join("corpus/toolpaths/tools_inch.ron");
    let text = std::fs::read_to_string(root().join("corpus/posts/vcpost/fanuc_mill.VcPost")).unwrap();
    let stated = format!("Postc.Units = \"MM\"\n{text}");
    for (name, text, units) in
        [("fanuc_mill.VcPost", &text, Units::Inch), ("with Postc.Units = MM", &stated, Units::Mm)]
    {
        let p = compile(Path::new("fanuc_mill.VcPost"), text);
        let program = post(&p, &inch_job);
        moves_as_the_toolpath(name, &rs274, &program, &inch_job, units);
    }
}

/// postp: the controllers write the CL file's units.
#[test]
fn postp_writes_the_cl_files_units() {
    let Some(rs274) = find_rs274() else { return };
    let dir = tempfile::tempdir().unwrap();
    let cl = dir.path().join("cl.tap");
    std::fs::write(
        &cl,
        "MACHIN/FANUCM\nUNITS/INCHES\nRESET\nLOADTL/1\nSPINDL/RPM,3000,CLW\nRAPID\nGOTO/1,2,0.5\nFEDRAT/20,IPM\nGOTO/1,2,-0.1\nGOTO/3,2,-0.1\nGOTO/3,4,-0.1\nRAPID\nGOTO/3,4,0.5\nEND\nFINI\n",
    )
    .unwrap();
    let run = support::postp::run_file(&cl, postc_postp::Settings::default());
    assert!(run.ok && run.program.contains("G20"), "{:?}\n{}", run.diagnostics, run.program);
    moves_as_the_toolpath("FANUCM over an inch CL file", &rs274, &run.program, &cl, Units::Inch);
}
