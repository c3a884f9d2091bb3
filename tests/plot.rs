//! `postc plot`: the corpus post `corpus/posts/vectric/gcode_mm.pp` over
//! `corpus/toolpaths/seed_job.ron`, posted in memory and drawn; the SVG is
//! parsed (by usvg, the parser resvg renders with) and its parts counted;
//! a seeded fault (I and J swapped) is marked and numbered; the command
//! writes SVG and PNG whole, and refuses bad inputs with diagnostics and
//! no file.

use std::io::Cursor;
use std::path::PathBuf;
use std::process::{Command, Output};

use postc_ir::Post;
use postc_runtime::Finished;
use postc_verify::Settings;

use crate::support;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn postc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_postc")).current_dir(root()).args(args).output().unwrap()
}

const POST: &str = "corpus/posts/vectric/gcode_mm.pp";
const JOB: &str = "corpus/toolpaths/seed_job.ron";

fn post(post: &Post) -> String {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(&root().join(JOB), &mut sources).unwrap();
    match postc_runtime::run(post, &mut source, postc_runtime::Output::memory(), postc_driver::run_options(post)) {
        Ok(r) => match r.output {
            Finished::Memory(parts) => String::from_utf8(parts.concat()).unwrap(),
            _ => unreachable!(),
        },
        Err(d) => panic!("{d:?}"),
    }
}

/// Posts the seed job with `text` as the post, then plots it: the SVG and the number of findings.
fn plot(text: &str) -> (String, usize) {
    let post_ir = support::compile_text("gcode_mm.pp", text);
    let program = post(&post_ir);
    let mut sources = postc_report::source_map();
    let file = sources.add("seed.tap", program.clone());
    let mut drawn = postc_driver::open_toolpath(&root().join(JOB), &mut sources).unwrap();
    let mut again = postc_driver::open_toolpath(&root().join(JOB), &mut sources).unwrap();
    let settings = Settings::from_post(&post_ir, postc_verify::Controller::Generic, 0.01);
    let (plot, report) = postc_verify::plot::draw(
        &mut Cursor::new(program.as_bytes()),
        file,
        &mut drawn,
        &mut again,
        &settings,
        &sources,
    );
    (plot.svg(), report.findings.len())
}

fn good_post() -> String {
    std::fs::read_to_string(root().join(POST)).unwrap()
}

/// Parses the SVG as resvg does (roxmltree underneath): well-formed XML and valid path data.
fn parses(svg: &str) {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default());
    assert!(tree.is_ok(), "{:?}", tree.err());
    let size = tree.unwrap().size();
    assert!(size.width() >= 1000.0 && size.height() > 400.0, "{size:?}");
}

#[test]
fn the_seed_job_is_drawn_in_two_views_with_arcs_dashed_rapids_and_a_legend() {
    let (svg, findings) = plot(&good_post());
    assert_eq!(findings, 0, "{svg}");
    parses(&svg);
    assert!(svg.starts_with("<svg "), "{svg}");
    assert!(svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<svg").count(), 1);
    assert_eq!(svg.matches("<g").count(), svg.matches("</g>").count());
    // Two views, each with the toolpath's and the program's feeds and rapids.
    assert!(svg.contains(r#"id="view-xy""#) && svg.contains(r#"id="view-xz""#));
    for class in ["toolpath-feed", "toolpath-rapid", "program-feed", "program-rapid"] {
        // Once per view and once in the legend.
        assert_eq!(svg.matches(&format!(r#"<path class="{class}""#)).count(), 3, "{class}");
    }
    // The seed job's circles are arcs: eight G2/G3 moves, each a quarter, in both the toolpath and the program layers of the top view.
    let arcs = svg.matches("A ").count();
    assert_eq!(arcs, 16, "{svg}");
    // Rapids are dashed, feeds are not.
    for line in svg.lines().filter(|l| l.contains("-rapid\"")) {
        assert!(line.contains("stroke-dasharray"), "{line}");
    }
    for line in svg.lines().filter(|l| l.contains("-feed\"")) {
        assert!(!line.contains("stroke-dasharray"), "{line}");
    }
    // The legend and the axes.
    for text in [
        "toolpath feed",
        "toolpath rapid",
        "program feed / arc",
        "program rapid",
        "X (mm)",
        "Y (mm)",
        "Z (mm)",
        "No findings",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    assert!(!svg.contains("class=\"finding\""));
}

#[test]
fn swapped_i_and_j_are_marked_and_numbered() {
    let text = good_post().replace("[I|A|I|1.4]", "[J|A|I|1.4]").replace("[J|A|J|1.4]", "[I|A|J|1.4]");
    assert_ne!(text, good_post());
    let (svg, findings) = plot(&text);
    assert!(findings > 0);
    parses(&svg);
    // Each finding is marked in both views (it has X, Y and Z) and listed once, numbered from 1.
    assert_eq!(svg.matches(r#"<g class="finding">"#).count(), 2 * findings, "{svg}");
    for n in 1..=findings {
        assert!(svg.contains(&format!(">{n}</text></g>")), "marker {n}");
        assert!(svg.contains(&format!(">{n}. VF0")), "list entry {n}");
    }
    assert!(svg.contains("VF013"), "{svg}");
    assert!(svg.contains(&format!("{findings} finding(s)")));
    // The list gives the program line of each.
    assert!(svg.contains(" line 13: ") || svg.contains(" line 1"), "{svg}");
}

fn temp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

#[test]
fn plot_writes_svg_and_png() {
    let dir = temp();
    let program = dir.path().join("seed.tap");
    let out = postc(&["post", POST, JOB, "-o", program.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = dir.path().join("plot.svg");
    let out =
        postc(&["plot", program.to_str().unwrap(), "--toolpath", JOB, "--post", POST, "-o", svg.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    parses(&text);
    assert!(text.contains("seed.tap over seed_job.ron"));

    let png = dir.path().join("plot.png");
    let out = postc(&[
        "plot",
        program.to_str().unwrap(),
        "--toolpath",
        JOB,
        "--post",
        POST,
        "-o",
        png.to_str().unwrap(),
        "--controller",
        "linuxcnc",
        "--tolerance",
        "0.02",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&bytes[12..16], b"IHDR");
    let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    let size = resvg::usvg::Tree::from_str(&text, &resvg::usvg::Options::default()).unwrap().size().to_int_size();
    assert_eq!((width, height), (size.width(), size.height()));
    assert!(bytes.len() > 10_000, "{} bytes", bytes.len());
}

#[test]
fn a_faulty_program_is_plotted_and_its_findings_printed() {
    let dir = temp();
    let program = dir.path().join("bad.tap");
    std::fs::write(&program, "G21 G90 G17\nG0 X0 Y0 Z5\nS1000 M3\nG1 Z-1 F300\nG2 X20 Y0 I0 J10 F1000\nG0 Z5\nM30\n")
        .unwrap();
    let job = dir.path().join("job.ron");
    std::fs::write(
        &job,
        "Job(units:Mm,safe_z:5.0)\nTool(number:1,name:\"T\",diameter:6.0,spindle_speed:1000.0,cut_feed:1000.0,plunge_feed:300.0)\nToolpathStart(name:\"A\")\nRapid(x:0.0,y:0.0,z:5.0)\nFeed(x:0.0,y:0.0,z:-1.0,intent:Plunge)\nArc(dir:Cw,x:20.0,y:0.0,z:-1.0,cx:10.0,cy:0.0)\nRapid(x:20.0,y:0.0,z:5.0)\nToolpathEnd\nEnd\n",
    )
    .unwrap();
    let svg = dir.path().join("bad.svg");
    let out =
        postc(&["plot", program.to_str().unwrap(), "--toolpath", job.to_str().unwrap(), "-o", svg.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    // Findings do not fail the plot; they are printed as verify prints them.
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("VF0"), "{stderr}");
    let text = std::fs::read_to_string(&svg).unwrap();
    parses(&text);
    assert!(text.contains(r#"<g class="finding">"#), "{text}");
    assert!(text.contains(">1. VF0"), "{text}");
}

#[test]
fn bad_inputs_give_diagnostics_and_no_file() {
    let dir = temp();
    let program = dir.path().join("seed.tap");
    assert!(postc(&["post", POST, JOB, "-o", program.to_str().unwrap()]).status.success());
    let p = program.to_str().unwrap();
    let cases: Vec<(Vec<String>, &str, PathBuf)> = vec![
        (vec!["-o".into(), dir.path().join("plot.pdf").display().to_string()], "IO007", dir.path().join("plot.pdf")),
        (
            vec!["-o".into(), dir.path().join("no/such/dir/plot.svg").display().to_string()],
            "IO003",
            dir.path().join("no/such/dir/plot.svg"),
        ),
        (
            vec!["-o".into(), dir.path().join("t.svg").display().to_string(), "--tolerance".into(), "0".into()],
            "IO007",
            dir.path().join("t.svg"),
        ),
        (
            vec!["-o".into(), dir.path().join("m.svg").display().to_string(), "--post".into(), "no-such.pp".into()],
            "IO001",
            dir.path().join("m.svg"),
        ),
    ];
    for (extra, code, path) in cases {
        let mut args = vec!["plot".to_string(), p.to_string(), "--toolpath".into(), JOB.into()];
        args.extend(extra);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = postc(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains(code), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!path.exists(), "{args:?} wrote {}", path.display());
    }
    // A program that is not there, a toolpath that is not there, binary data.
    let out = postc(&["plot", "no-such.tap", "--toolpath", JOB, "-o", dir.path().join("a.svg").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("IO001"));
    let out = postc(&["plot", p, "--toolpath", "no-such.ron", "-o", dir.path().join("b.svg").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("IO001"), "{}", String::from_utf8_lossy(&out.stderr));
    let binary = dir.path().join("bin.tap");
    std::fs::write(&binary, [0u8, 1, 2, 3, 0, 255]).unwrap();
    let out =
        postc(&["plot", binary.to_str().unwrap(), "--toolpath", JOB, "-o", dir.path().join("c.svg").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("VF002"));
    // Nothing was left behind, not even a temporary file.
    let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left.len(), 2, "{left:?}");
}

/// The README's plot (docs/img/seed_job.svg) is what `postc plot` draws
/// today: a byte-exact golden of `tests/support` (`POSTC_BLESS=1` writes it
/// again).
#[test]
fn the_readme_plot_is_current() {
    let dir = temp();
    let program = dir.path().join("seed.tap");
    assert!(postc(&["post", POST, JOB, "-o", program.to_str().unwrap()]).status.success());
    let svg = dir.path().join("seed_job.svg");
    let out =
        postc(&["plot", program.to_str().unwrap(), "--toolpath", JOB, "--post", POST, "-o", svg.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let drawn = std::fs::read(&svg).unwrap();
    if let Err(e) = support::check_golden(&root().join("docs/img/seed_job.svg"), &drawn) {
        panic!("docs/img/seed_job.svg is out of date: {e}\n{}", support::bless_hint("plot"));
    }
}

/// Without any font the PNG is still drawn (resvg leaves the text out): what docs/plot.md promises.
#[test]
fn a_png_without_fonts_is_still_drawn() {
    let text = good_post().replace("[I|A|I|1.4]", "[J|A|I|1.4]").replace("[J|A|J|1.4]", "[I|A|J|1.4]");
    let (svg, _) = plot(&text);
    let options = resvg::usvg::Options::default();
    assert_eq!(options.fontdb.len(), 0);
    let tree = resvg::usvg::Tree::from_str(&svg, &options).unwrap();
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(&tree, resvg::tiny_skia::Transform::default(), &mut pixmap.as_mut());
    // The findings' red discs are there.
    let red =
        pixmap.pixels().iter().filter(|p| p.red() > 200 && p.green() < 80 && p.blue() < 80 && p.alpha() == 255).count();
    assert!(red > 500, "{red} red pixels");
    assert!(pixmap.encode_png().unwrap().starts_with(b"\x89PNG"));
}
