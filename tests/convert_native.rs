//! Native CNC-Calc posts judged by Node.js: every Vectric post of the
//! corpus (`corpus/posts/vectric/`), the real Vectric posts of
//! `../shared/corpus/vectric/` and the posts below (as Vectric posts and
//! as VcPost section posts) is converted with
//! `postc convert --to cimco` (the CNC-Calc manual's entry points, docs/convert.md,
//! "Native CNC-Calc posts"); each that converts runs under the Node.js
//! CNC-Calc host (`tests/node_host/`) over every toolpath it applies to and
//! must print, byte for byte, what `postc post` prints for the SOURCE post
//! (and so must postc's own CNC-Calc host running the converted post).
//! A toolpath applies when it holds only what the CNC-Calc manual hands a post (one
//! toolpath, no tool change, dwell or arc outside XY) in the
//! post's units. The test prints the counts docs/convert.md records.
//! Without Node.js the comparison is skipped, with a message, and fails
//! under `CI=true`.

use std::path::{Path, PathBuf};

use crate::support::cimco::{export_jsonl, node_or_skip, post_toolpath, run_node};
use crate::support::converting::{Tally, convert_counted, real_vectric_posts};
use crate::support::{compile_warned, corpus, diff, files, postc, said, stem};
use postc_backends::Target;
use postc_ir::{Post, Units};

/// Posts that exercise each rule a native post carries: FIRST_ sections
/// after rapids and feed changes, plunge and retract sections, helix
/// fallbacks (through an arc section that prints [Z], and cut into feed
/// moves where none does), arcs cut into feed moves, block numbers,
/// FEED_RATE_CHANGE, modal words, a CR LF line ending, and number formats
/// (signs, zero and blank padding, a decimal comma, multipliers) and every
/// arc word (start, mid point, sweep, K).
pub(crate) const POSTS: &[(&str, &str)] = &[
    (
        "first_sections.pp",
        r#"POST_NAME = "first sections (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[13][10]"
LINE_NUMBER_START = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM = 100
VAR LINE_NUMBER = [N|A|N|1.0]
VAR FEED_RATE = [F|C|F|1.1]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.4]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.4]
begin HEADER
"%"
"[N]G21 G90 G17"
begin SPINDLE_ON
"M3"
begin TOOLCHANGE
"M6"
begin NEW_SEGMENT
"(next)"
begin RAPID_MOVE
"[N]G0[X][Y][Z]"
begin FIRST_FEED_MOVE
"[N]G1[X][Y][Z][F]"
begin FEED_MOVE
"[N]G1[X][Y][Z]"
begin PLUNGE_MOVE
"[N]G1[Z][F] (plunge)"
begin FIRST_CW_ARC_MOVE
"[N]G2[X][Y][Z][I][J][F]"
begin CW_ARC_MOVE
"[N]G2[X][Y][Z][I][J]"
begin FIRST_CCW_ARC_MOVE
"[N]G3[X][Y][Z][I][J][F]"
begin CCW_ARC_MOVE
"[N]G3[X][Y][Z][I][J]"
begin FOOTER
"M5"
"M30"
"%"
"#,
    ),
    (
        "plain_sections.pp",
        r#"POST_NAME = "plain sections (*.tap)"
FILE_EXTENSION = "tap"
UNITS = "MM"
VAR FEED_RATE = [F|A|F|1.0]
VAR X_POSITION = [X|A| X|1.4]
VAR Y_POSITION = [Y|A| Y|1.4]
VAR Z_POSITION = [Z|A| Z|1.4]
VAR ARC_CENTRE_I_ABS_POSITION = [IA|A| I|1.3]
VAR ARC_CENTRE_J_ABS_POSITION = [JA|A| J|1.3]
VAR ARC_RADIUS = [Radius|A| R|1.3]
begin HEADER
"G90"
begin INITIAL_RAPID_MOVE
"G0 (first)[X][Y][Z]"
begin RAPID_MOVE
"G0[X][Y][Z]"
begin RETRACT_MOVE
"G0 (up)[Z]"
begin FEED_RATE_CHANGE
"(feed)[F]"
begin FEED_MOVE
"G1[X][Y][Z]"
begin FIRST_PLUNGE_MOVE
"G1 (first plunge)[Z][F]"
begin PLUNGE_MOVE
"G1 (plunge)[Z]"
begin CW_ARC_MOVE
"G2[X][Y][IA][JA][Radius]"
begin CCW_ARC_MOVE
"G3[X][Y][IA][JA][Radius]"
begin FOOTER
"M30"
"#,
    ),
    (
        "no_arcs.pp",
        r#"POST_NAME = "no arcs (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
VAR FEED_RATE = [F|C|F|1.0]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|+1.3]
begin HEADER
"G21"
begin RAPID_MOVE
"G0[X][Y][Z]"
begin FIRST_FEED_MOVE
"G1[X][Y][Z][F]"
begin FEED_MOVE
"G1[X][Y][Z]"
begin FOOTER
"M2"
"#,
    ),
    (
        "helix.pp",
        r#"POST_NAME = "helix (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
VAR FEED_RATE = [F|C|F|1.1]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.3]
begin HEADER
"G21"
begin RAPID_MOVE
"G0[X][Y][Z]"
begin FEED_MOVE
"G1[X][Y][Z][F]"
begin FIRST_CW_ARC_MOVE
"G2[X][Y][I][J][F]"
begin CW_ARC_MOVE
"G2[X][Y][Z][I][J]"
begin CCW_ARC_MOVE
"G3[X][Y][I][J][F]"
begin CCW_HELICAL_ARC_MOVE
"G3 (helix)[X][Y][Z][I][J][F]"
begin FOOTER
"M30"
"#,
    ),
    (
        "formats.pp",
        r#"POST_NAME = "formats (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
VAR FEED_RATE = [F|C| F|#1.0|0.5]
VAR X_POSITION = [X|C| X|+1.3]
VAR Y_POSITION = [Y|C| Y|08.2]
VAR Z_POSITION = [Z|C| Z|-9,3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A| I|+010.4|2]
VAR ARC_CENTRE_J_INC_POSITION = [J|A| J|0.1]
VAR ARC_RADIUS = [Radius|A| R|1.5]
begin HEADER
"(formats)"
begin RAPID_MOVE
"G0[X][Y][Z]"
begin FEED_MOVE
"G1[X][Y][Z][F]|"
begin CW_ARC_MOVE
"G2[X][Y][I][J][Radius][F]"
begin CCW_ARC_MOVE
"G3[X][Y][I][J][Radius][F]"
begin FOOTER
"M30"
"#,
    ),
    (
        "arc_words.pp",
        r#"POST_NAME = "arc words (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR FEED_RATE = [F|C|F|1.0]
begin HEADER
"(arc words)"
begin RAPID_MOVE
"G0[X][Y][Z]"
begin FEED_MOVE
"G1[X][Y][Z][F]"
begin CW_ARC_MOVE
"G2[X][Y][Z] S[ArcStartX],[ArcStartY] M[ArcMidX],[ArcMidY] D[ArcMidXI],[ArcMidYI] A[Angle] K[K] KA[KA] I[IA] J[JA][F]"
begin CCW_ARC_MOVE
"G3[X][Y][Z] S[ArcStartX],[ArcStartY] M[ArcMidX],[ArcMidY] D[ArcMidXI],[ArcMidYI] A[Angle] K[K] KA[KA] I[IA] J[JA][F]"
begin FOOTER
"M30"
"#,
    ),
];

/// Real Vectric posts that convert to native CNC-Calc posts whose every
/// program Node.js prints as postc posts the source (docs/convert.md).
const REAL_NATIVE_AT_LEAST: usize = 1;

/// The toolpaths a native post is judged over: those holding only what
/// the CNC-Calc manual hands a post, in the post's units.
fn toolpaths(post: &Post) -> Vec<PathBuf> {
    let units = post.info.units.unwrap_or(Units::Mm);
    let mut all = files(&corpus().join("toolpaths"), "ron");
    all.extend(files(&corpus().join("toolpaths/native"), "ron"));
    all.into_iter()
        .filter(|t| {
            let text = std::fs::read_to_string(t).unwrap_or_default();
            let events: Vec<&str> = text.lines().filter(|l| !l.trim_start().starts_with("//")).collect();
            let count = |name: &str| events.iter().filter(|l| l.trim_start().starts_with(name)).count();
            let in_units = match units {
                Units::Mm => text.contains("units: Mm") || text.contains("units:Mm"),
                Units::Inch => text.contains("units: Inch") || text.contains("units:Inch"),
            };
            in_units
                && count("ToolpathStart") <= 1
                && count("Tool(") <= 1
                && count("Dwell") == 0
                && !["plane: Zx", "plane: Yz", "plane:Zx", "plane:Yz"].iter().any(|p| text.contains(p))
                && count("Jet") == 0
                && count("Power") == 0
        })
        .collect()
}

/// Converts and judges each post; returns the tally and the failures.
fn judge(posts: &[PathBuf], dir: &Path, failures: &mut Vec<String>) -> Tally {
    let mut tally = Tally::default();
    for (n, path) in posts.iter().enumerate() {
        // A source not read whole stops `convert` (docs/convert.md).
        let Some((post, converted)) = convert_counted(path, n, Target::Cimco, "js", dir, &mut tally) else { continue };
        let failed_before = failures.len();
        // postc's own CNC-Calc host runs the converted post too, natively
        // (no function left to a script).
        let again = match compile_warned(&converted) {
            Ok(p)
                if !p.scripts.is_empty()
                    || p.functions.iter().any(|f| !matches!(f.body, postc_ir::Body::Native(_))) =>
            {
                failures.push(format!("{}: the converted post does not lower to native IR whole", path.display()));
                Some(p)
            }
            Ok(p) => Some(p),
            Err(e) => {
                failures.push(format!("{}: postc does not compile the converted post: {e}", path.display()));
                None
            }
        };
        for toolpath in toolpaths(&post) {
            let pair = format!("{}__{}", path.display(), stem(&toolpath));
            let jsonl = dir.join(format!("{}.jsonl", stem(&toolpath)));
            if let Err(e) = export_jsonl(&toolpath, &jsonl) {
                failures.push(format!("{pair}: cannot export the toolpath: {e}"));
                continue;
            }
            let ours = match post_toolpath(&post, &toolpath) {
                Ok(o) => o,
                Err(e) => {
                    failures.push(format!("{pair}: postc: {e}"));
                    continue;
                }
            };
            if let Some(again) = &again {
                match post_toolpath(again, &toolpath) {
                    Ok(o) if o == ours => {}
                    Ok(o) => failures.push(format!(
                        "{pair}: postc posting the converted post (-) and the source (+) differ\n{}",
                        diff(&o, &ours)
                    )),
                    Err(e) => failures.push(format!("{pair}: postc posting the converted post: {e}")),
                }
            }
            match run_node(&converted, &jsonl, &[]) {
                Ok(theirs) if theirs == ours => tally.compared += 1,
                Ok(theirs) => failures.push(format!(
                    "{pair}: Node.js running the converted post (-) and postc posting the source (+) differ\n{}",
                    diff(&theirs, &ours)
                )),
                Err(e) => failures.push(format!("{pair}: {e}")),
            }
        }
        if failures.len() == failed_before {
            tally.identical_posts += 1;
        }
    }
    tally
}

#[test]
fn node_runs_native_posts_as_postc_posts_their_sources() {
    if node_or_skip("convert_native").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut failures = Vec::new();
    let mut own = Vec::new();
    for (name, text) in POSTS {
        let path = dir.path().join(name);
        std::fs::write(&path, text).expect("write the post");
        own.push(path);
    }
    let tests = judge(&own, dir.path(), &mut failures);
    eprintln!("{}", tests.show("this test's posts", own.len()));
    assert_eq!(tests.converted, POSTS.len(), "every post of this test converts: {}", failures.join("\n\n"));
    assert!(tests.compared >= POSTS.len(), "only {} programs were compared", tests.compared);
    // The same posts as VcPost section posts (`--to vcpost --postc-extension`), converted on.
    let mut vcpost = Vec::new();
    for path in &own {
        let post = compile_warned(path).expect("the test's post compiles");
        let text = postc_backends::convert(&post, Target::VcPostSections).expect("a section post converts to VcPost");
        let to = path.with_extension("VcPost");
        std::fs::write(&to, text).expect("write the VcPost post");
        vcpost.push(to);
    }
    let v = judge(&vcpost, dir.path(), &mut failures);
    eprintln!("{}", v.show("this test's posts as VcPost section posts", vcpost.len()));
    assert_eq!(v.converted, POSTS.len(), "every VcPost section post converts: {}", failures.join("\n\n"));
    let corpus_posts = files(&corpus().join("posts/vectric"), "pp");
    let c = judge(&corpus_posts, dir.path(), &mut failures);
    eprintln!("{}", c.show("corpus/posts/vectric", corpus_posts.len()));
    let real = real_vectric_posts("convert_native");
    if !real.is_empty() {
        let r = judge(&real, dir.path(), &mut failures);
        eprintln!("{}", r.show("../shared/corpus/vectric", real.len()));
        assert!(r.identical_posts >= REAL_NATIVE_AT_LEAST, "{}", r.show("../shared/corpus/vectric", real.len()));
    }
    assert!(failures.is_empty(), "{} failures:\n\n{}", failures.len(), failures.join("\n\n"));
}

/// The command line: a native post by default, with the warnings of what
/// it leaves out at their lines; a refusal names the line and column and
/// writes nothing; a section post only with `--postc-extension`.
#[test]
fn convert_writes_native_posts_and_section_posts_only_when_asked() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let (name, text) = POSTS[0];
    let pp = dir.path().join(name);
    std::fs::write(&pp, text).expect("write the post");
    let js = dir.path().join("native.js");
    let o = postc(&["convert", &pp.display().to_string(), "--to", "cimco", "-o", &js.display().to_string()]);
    assert!(o.status.success(), "{}", said(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    let line = text.lines().position(|l| l == "begin TOOLCHANGE").expect("a TOOLCHANGE section") + 1;
    let at = format!("{name}:{line}:1");
    assert!(err.contains("warning[CV008]") && err.contains("TOOLCHANGE is left out") && err.contains(&at), "{err}");
    let native = std::fs::read_to_string(&js).expect("the converted post");
    for entry in
        ["function onOpen(", "function onLinear(vx, vy, vz, movement)", "function onCircular(", "function onClose("]
    {
        assert!(native.contains(entry), "{entry}\n{native}");
    }
    assert!(!native.contains("function HEADER(") && !native.contains("postcOptions"), "{native}");
    let sections = dir.path().join("sections.js");
    let o = postc(&[
        "convert",
        &pp.display().to_string(),
        "--to",
        "cimco",
        "--postc-extension",
        "-o",
        &sections.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", said(&o));
    assert!(std::fs::read_to_string(&sections).expect("the section post").contains("function HEADER("));
    // A value CNC-Calc never hands: refused at its line and column, nothing written.
    let refused = dir.path().join("refused.js");
    let o =
        postc(&["convert", "corpus/posts/vectric/gcode_mm.pp", "--to", "cimco", "-o", &refused.display().to_string()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("error[CV007]") && err.contains("`[T]` in HEADER") && err.contains("gcode_mm.pp:50:"),
        "{err}"
    );
    assert!(!refused.exists(), "a refused conversion writes nothing");
}

/// A feed printed finer than the tenth getFeedrate hands is warned of at
/// its line; a coarser one (a multiplier to feeds per second) is not.
#[test]
fn feeds_finer_than_the_engine_hands_are_warned_of() {
    for (format, warned) in [("1.2", true), ("1.1", false), ("1.2|0.0166667", false), ("1.0", false)] {
        let text = format!(
            "POST_NAME = \"feeds (*.nc)\"\nUNITS = \"MM\"\nVAR FEED_RATE = [F|C|F|{format}]\nbegin HEADER\n\"G21\"\nbegin FEED_MOVE\n\"G1[X][Y][F]\"\n"
        );
        let post = crate::support::compile_text("feeds.pp", &text);
        let (_, warnings) = postc_backends::convert_warned(&post, Target::Cimco).expect("converts");
        let found = warnings.iter().any(|d| d.code == "CV011");
        assert_eq!(found, warned, "{format}: {warnings:?}");
    }
}

/// A Vectric post whose POST_BASE file is missing stops `convert`, as an
/// error, in every target, and nothing is written.
#[test]
fn a_missing_post_base_stops_convert_in_every_target() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post = dir.path().join("child.pp");
    std::fs::write(&post, "POST_NAME = \"child (*.nc)\"\nPOST_BASE = \"missing_base.pp\"\nbegin FOOTER\n\"M30\"\n")
        .expect("write the post");
    for (target, extension) in
        [("vectric", false), ("vcpost", false), ("vcpost", true), ("cimco", false), ("cimco", true), ("ron", false)]
    {
        let out = dir.path().join(format!("out-{target}-{extension}"));
        let mut args = vec!["convert".to_string(), post.display().to_string(), "--to".into(), target.into()];
        if extension {
            args.push("--postc-extension".into());
        }
        args.extend(["-o".to_string(), out.display().to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = postc(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{target}: {err}");
        assert!(err.contains("error[PP019]") && err.contains("child.pp:2:13"), "{target}: {err}");
        assert!(!out.exists(), "{target}: nothing is written");
    }
    // `post` and `check` still read the post without its base, with a warning.
    let o = postc(&["check", &post.display().to_string()]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("warning[PP019]"), "{}", said(&o));
}

/// Numbers near every rounding edge (ties at the last decimal, values
/// that round to a negative zero, tiny and large magnitudes, JavaScript's
/// exponent forms) print through the converted posts' number formats
/// under Node.js as the source posts print them.
#[test]
fn native_number_formats_print_as_vectric_formats_under_node() {
    if node_or_skip("convert_native").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut ron = String::from(
        "Job(units: Mm)\nTool(number: 1, name: \"T\", diameter: 6, spindle_speed: 1000, cut_feed: 1000, plunge_feed: 200)\nToolpathStart(name: \"edges\")\nRapid(x: 0, y: 0, z: 5)\n",
    );
    let mut values = Vec::new();
    for i in 0..400i32 {
        let k = f64::from(i);
        values.push(k * 0.0005 - 0.1);
        values.push(-(k * 1.0005e-3));
        values.push(k * 1e-7);
        values.push(123_456.0 + k * 0.00125);
        values.push(2.675 + k * 0.005);
        values.push(-0.00049 * k);
        values.push(-999_999.0 + k * 0.0015);
    }
    for w in values.chunks(3) {
        let (x, y, z) = (w[0], w.get(1).copied().unwrap_or(0.0), w.get(2).copied().unwrap_or(0.0));
        ron.push_str(&format!("Feed(x: {x:?}, y: {y:?}, z: {z:?})\n"));
    }
    ron.push_str("ToolpathEnd\nEnd\n");
    let toolpath = dir.path().join("edges.ron");
    std::fs::write(&toolpath, ron).expect("write the toolpath");
    let jsonl = dir.path().join("edges.jsonl");
    export_jsonl(&toolpath, &jsonl).expect("export the toolpath");
    let mut compared = 0;
    for (name, text) in POSTS.iter().filter(|(n, _)| ["formats.pp", "first_sections.pp"].contains(n)) {
        let pp = dir.path().join(name);
        std::fs::write(&pp, text).expect("write the post");
        let post = compile_warned(&pp).expect("compiles");
        let js = postc_backends::convert(&post, Target::Cimco).expect("converts");
        let converted = pp.with_extension("js");
        std::fs::write(&converted, js).expect("write the converted post");
        let ours = post_toolpath(&post, &toolpath).expect("postc posts the source");
        let theirs = run_node(&converted, &jsonl, &[]).expect("Node.js posts the converted post");
        assert!(theirs == ours, "{name}: Node.js (-) and postc (+) differ\n{}", diff(&theirs, &ours));
        compared += 1;
    }
    assert_eq!(compared, 2);
}

/// Vericut runs no section post: `--to vcpost` refuses a Vectric post
/// (CV001, at its first section, naming the flag) and writes nothing;
/// `--postc-extension` writes the section post, which says what it is.
#[test]
fn a_vectric_post_is_a_vcpost_section_post_only_when_asked() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post = corpus().join("posts/vectric/gcode_mm.pp");
    let out = dir.path().join("gcode_mm.VcPost");
    let (post_arg, out_arg) = (post.display().to_string(), out.display().to_string());
    let o = postc(&["convert", &post_arg, "--to", "vcpost", "-o", &out_arg]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[CV001]") && err.contains("gcode_mm.pp:42:1"), "{err}");
    assert!(err.contains("--postc-extension"), "the refusal names the flag: {err}");
    assert!(!out.exists(), "nothing is written");
    let o = postc(&["convert", &post_arg, "--to", "vcpost", "--postc-extension", "-o", &out_arg]);
    assert!(o.status.success(), "{}", said(&o));
    let text = std::fs::read_to_string(&out).expect("the section post");
    assert!(text.contains("Sub FEED_MOVE"), "{text}");
}
