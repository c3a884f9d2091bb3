//! Fusion posts judged by Node.js: every Vectric post of the corpus
//! (`corpus/posts/vectric/`), the real Vectric posts of
//! `../shared/corpus/vectric/` and the posts below is converted with
//! `postc convert --to fusion` (docs/convert.md, "Fusion posts"); each
//! that converts runs under the Node.js Fusion host
//! (`tests/node_host/fusion.js`) over every toolpath it applies to and
//! must print, byte for byte, what `postc post` prints for the SOURCE
//! post; postc running the converted post must print the same bytes too.
//! A toolpath applies when it holds no jet tool and no arc outside XY
//! (the Node.js host does not cut those), in either unit; a
//! toolpath with a jet toolpath is judged without it. The test prints the
//! counts docs/convert.md records. Without Node.js the comparison is
//! skipped, with a message, and fails under `CI=true`.

use std::path::{Path, PathBuf};

use crate::support::cimco::{export_jsonl, node_command, node_or_skip, post_toolpath};
use crate::support::converting::{Tally, convert_counted, real_vectric_posts};
use crate::support::{self, compile_warned, corpus, diff, files, postc, said, stem};
use postc_backends::Target;
use postc_ir::event::{Event, ZOrigin};
use postc_ir::{Dialect, EventSource, Piece, Post, Quantity, Stmt, ValueSource};
use postc_runtime::{Finished, Output, RunOptions};

/// A post that prints what Fusion hands at each section: the tool, its
/// name and diameter, the spindle speed (and its SPINDLE_SPEED_RANGE
/// step), the toolpath's name, the stock, through TOOLCHANGE and
/// NEW_SEGMENT, with a substitution in text words.
const SECTIONS: &str = r#"POST_NAME = "sections (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[13][10]"
SUBSTITUTE = "([)]"
SPINDLE_SPEED_RANGE = 1 15 4500 18000
LINE_NUMBER_START = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM = 100
VAR LINE_NUMBER = [N|A|N|1.0]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR TOOL_NUMBER = [T|A|T|1.0]
VAR TOOL_DIAMETER = [TDIA|A||1.2]
VAR TOOL_NAME = [TOOLNAME|A||1.0]
VAR TOOLPATH_NAME = [TOOLPATH_NAME|A||1.0]
VAR X_LENGTH = [XLENGTH|A||1.1]
VAR Z_MIN = [ZMIN|A||1.1]
VAR FEED_RATE = [F|C|F|1.1]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.4]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.4]
VAR DWELL_TIME = [DWELL|A|P|1.2]
begin HEADER
"%"
"([TOOLNAME] [TOOLPATH_NAME] [XLENGTH] [ZMIN])"
"[N]G21 G90 G17 T[T] D[TDIA]"
begin SPINDLE_ON
"M3[S] (step)"
begin TOOLCHANGE
"M5"
"M6[T] ([TOOLNAME])"
begin NEW_SEGMENT
"(next [TOOLPATH_NAME])"
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
begin DWELL_MOVE
"G4[DWELL]"
begin FOOTER
"M5"
"M30"
"%"
"#;

/// Real Vectric posts that convert to `.cps` posts whose every program
/// Node.js prints as postc posts the source (docs/convert.md).
const REAL_FUSION_AT_LEAST: usize = 110;

/// A toolpath's text without the toolpaths of its jet tools (from a jet
/// `Tool` to the next `Tool` or `End`), or `None` when it has none. The
/// job's lists of tools and toolpaths (`[TOOLS_USED]`,
/// `[TOOLPATHS_OUTPUT]`) no longer name what was left out.
fn without_jets(text: &str) -> Option<String> {
    let mut out = String::new();
    let mut skipping = false;
    let mut dropped_tools = Vec::new();
    let mut dropped_paths = Vec::new();
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("Tool(") {
            skipping = t.replace(' ', "").contains("jet:true");
            if skipping {
                dropped_tools.extend(text_field(t, "name"));
            }
        } else if t.starts_with("End") && !t.starts_with("EndOf") {
            skipping = false;
        } else if skipping && t.starts_with("ToolpathStart(") {
            dropped_paths.extend(text_field(t, "name"));
        }
        if !skipping {
            out.push_str(line);
            out.push('\n');
        }
    }
    if dropped_tools.is_empty() {
        return None;
    }
    let kept_tools: Vec<String> = out
        .lines()
        .map(str::trim_start)
        .filter(|t| t.starts_with("Tool("))
        .filter_map(|t| text_field(t, "name"))
        .collect();
    dropped_tools.retain(|n| !kept_tools.contains(n));
    let out = out
        .lines()
        .map(|line| {
            if line.trim_start().starts_with("Job(") {
                let line = drop_names(line, "tools", &dropped_tools);
                drop_names(&line, "toolpaths", &dropped_paths)
            } else {
                line.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    Some(out + "\n")
}

/// The byte range of the RON string that starts at `at` (a `"`), its
/// text unescaped.
fn ron_string(line: &str, at: usize) -> Option<(usize, String)> {
    let mut text = String::new();
    let mut chars = line[at + 1..].char_indices();
    while let Some((i, c)) = chars.next() {
        match c {
            '\\' => text.extend(chars.next().map(|(_, c)| c)),
            '"' => return Some((at + 1 + i + 1, text)),
            c => text.push(c),
        }
    }
    None
}

/// Where the value of field `name` starts in a RON event line.
fn field_value(line: &str, name: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(i) = line[from..].find(name).map(|i| i + from) {
        let before = line[..i].trim_end().chars().last();
        let rest = line[i + name.len()..].trim_start();
        if matches!(before, Some('(' | ',')) && rest.starts_with(':') {
            let after_colon = line.len() - rest.len() + 1;
            return Some(after_colon + (line[after_colon..].len() - line[after_colon..].trim_start().len()));
        }
        from = i + name.len();
    }
    None
}

/// A text field of a RON event line (`name: "Pocket"`).
fn text_field(line: &str, name: &str) -> Option<String> {
    let at = field_value(line, name)?;
    line[at..].starts_with('"').then(|| ron_string(line, at).map(|(_, t)| t)).flatten()
}

/// A RON line with the texts `names` left out of its list field `field`.
fn drop_names(line: &str, field: &str, names: &[String]) -> String {
    let Some(at) = field_value(line, field).filter(|&at| line[at..].starts_with('[')) else {
        return line.to_string();
    };
    let mut kept = Vec::new();
    let mut i = at + 1;
    loop {
        let rest = &line[i..];
        let skip = rest.len() - rest.trim_start_matches([' ', ',']).len();
        i += skip;
        if line[i..].starts_with(']') {
            break;
        }
        let Some((end, text)) = ron_string(line, i) else { return line.to_string() };
        if !names.contains(&text) {
            kept.push(line[i..end].to_string());
        }
        i = end;
    }
    format!("{}[{}]{}", &line[..at], kept.join(", "), &line[i + 1..])
}

/// A RON line without its text field `name` (and the comma after it).
fn drop_field(line: &str, name: &str) -> String {
    let Some(at) = field_value(line, name).filter(|&at| line[at..].starts_with('"')) else {
        return line.to_string();
    };
    let Some((end, _)) = ron_string(line, at) else { return line.to_string() };
    let start = line[..at].rfind(name).unwrap_or(at);
    let rest = line[end..].trim_start();
    let rest = rest.strip_prefix(',').map_or(rest, str::trim_start);
    format!("{}{}", &line[..start], rest)
}

/// A toolpath's text whose job gives no date and no time, or `None` when
/// it gives neither: posted at the same instant by postc and Node.js (the
/// converted post prints Fusion's clock, `new Date()`, where a Vectric
/// post prints a date the job writes as it is written).
fn without_date(text: &str) -> Option<String> {
    let mut changed = false;
    let out: Vec<String> = text
        .lines()
        .map(|line| {
            if line.trim_start().starts_with("Job(") {
                let plain = drop_field(&drop_field(line, "date"), "time");
                changed |= plain != line;
                plain
            } else {
                line.to_string()
            }
        })
        .collect();
    changed.then(|| out.join("\n") + "\n")
}

/// A toolpath the converted posts are judged over.
struct Job {
    path: PathBuf,
    text: String,
    /// Made from a toolpath whose job writes its date or time.
    dateless: bool,
    /// The job writes a date or a time.
    dated: bool,
}

/// The toolpaths the converted posts are judged over: the corpus's, the
/// native ones, those with a jet toolpath without it, and each whose job
/// writes a date or time without them.
fn all_toolpaths(dir: &Path) -> Vec<Job> {
    let mut all = files(&corpus().join("toolpaths"), "ron");
    all.extend(files(&corpus().join("toolpaths/native"), "ron"));
    let mut texts = Vec::new();
    for t in all {
        let text = std::fs::read_to_string(&t).unwrap_or_default();
        if let Some(rest) = without_jets(&text).filter(|r| r.contains("Tool(")) {
            let to = dir.join(format!("{}_without_jets.ron", stem(&t)));
            std::fs::write(&to, &rest).expect("write the toolpath");
            texts.push((to, rest));
        }
        texts.push((t, text));
    }
    let mut out = Vec::new();
    for (path, text) in texts {
        if let Some(plain) = without_date(&text) {
            let to = dir.join(format!("{}_without_date.ron", stem(&path)));
            std::fs::write(&to, &plain).expect("write the toolpath");
            out.push(Job { path: to, text: plain, dateless: true, dated: false });
            out.push(Job { path, text, dateless: false, dated: true });
        } else {
            out.push(Job { path, text, dateless: false, dated: false });
        }
    }
    out
}

/// A number field of a RON event line (`z: 5` in `Rapid(x: 0, y: 0, z: 5)`).
fn field(line: &str, name: &str) -> Option<f64> {
    let squeezed = line.replace(' ', "");
    let at = squeezed.find(&format!("{name}:"))? + name.len() + 1;
    let rest = &squeezed[at..];
    let end = rest.find([',', ')']).unwrap_or(rest.len());
    rest[..end].parse().ok()
}

/// Whether Fusion hands a converted post other moves than Vectric makes
/// for this toolpath (docs/convert.md, "Fusion posts"): a drilling cycle
/// that starts within a toolpath with the tool above its clearance
/// plane, which Fusion's linking moves reach over the first hole at the
/// tool's height and then straight down, where Vectric's rapid goes there
/// at once.
fn fusion_links_differ(text: &str) -> bool {
    let mut z: Option<f64> = None;
    let mut clearance: Option<f64> = None;
    for line in text.lines().map(str::trim_start) {
        if line.starts_with("ToolpathStart") {
            z = None;
        } else if line.starts_with("Rapid(") || line.starts_with("Feed(") || line.starts_with("Arc(") {
            z = field(line, "z").or(z);
        } else if line.starts_with("DrillCycle(") {
            clearance = field(line, "retract_plane");
            if let (Some(z), Some(clear)) = (z, clearance)
                && z > clear
            {
                return true;
            }
        } else if line.starts_with("DrillEnd") {
            // A cycle leaves the tool at its clearance plane.
            z = clearance.or(z);
        }
    }
    false
}

/// Whether a section of the post prints one of these quantities.
fn prints(post: &Post, quantities: &[Quantity]) -> bool {
    post.handlers.iter().any(|h| {
        h.body.iter().any(|s| {
            matches!(s, Stmt::Line { pieces, .. } if pieces.iter().any(|p| matches!(p, Piece::Var(v)
                if matches!(post.variables[v.index()].source, ValueSource::Quantity(q) if quantities.contains(&q)))))
        })
    })
}

/// Whether the job's origin texts say where its material lies about the
/// origin, as a Fusion stock does in its work coordinates: "Bottom Left"
/// where the material's least X and Y are 0, "Centre" where it is
/// centred on 0, ..., an empty text where 0 is no corner and not the
/// centre; Z zero the material's top (`MaterialSurface`) or its bottom
/// (`Table`). A job without an origin says Vectric's defaults (an empty
/// XY text, the material surface); one without material says them too
/// (a Fusion document without stock places no origin).
fn origin_agrees(toolpath: &Path) -> bool {
    let mut sources = postc_report::source_map();
    let Ok(mut events) = postc_driver::open_toolpath(toolpath, &mut sources) else { return false };
    let mut diags = Vec::new();
    let Some((Event::Job(job), _)) = events.next_event(&mut diags) else { return true };
    let (said_xy, said_z) = match job.origin {
        Some(o) => (o.xy, o.z),
        None => (String::new(), ZOrigin::MaterialSurface),
    };
    let Some(m) = job.material else { return said_xy.is_empty() && said_z == ZOrigin::MaterialSurface };
    let zero = |v: f64| v.abs() <= 1e-9;
    let side = |lower: f64, upper: f64, low: &'static str, high: &'static str| {
        if zero(lower) {
            low
        } else if zero(upper) {
            high
        } else if zero(lower + upper) {
            "centre"
        } else {
            ""
        }
    };
    let x = side(m.min.x, m.max.x, "Left", "Right");
    let y = side(m.min.y, m.max.y, "Bottom", "Top");
    let xy = match (x, y) {
        ("centre", "centre") => "Centre".to_string(),
        ("" | "centre", _) | (_, "" | "centre") => String::new(),
        _ => format!("{y} {x}"),
    };
    let table = zero(m.min.z) && !zero(m.max.z);
    said_xy == xy && (said_z == ZOrigin::Table) == table
}

/// The toolpaths a post applies to: no jet, no arc outside XY but for a
/// CIMCO post (in any units: the converted post prints lengths in its source's units, as
/// Vectric's runtime converts them). A post that prints `[DATE]` or
/// `[TIME]` is judged over the toolpaths whose job writes no date and no
/// time (copies of those that do, without them: the converted post
/// prints Fusion's clock, and a date a job writes is not an instant); one
/// that prints the origin texts over those whose origin texts say where
/// their material lies.
fn toolpaths(all: &[Job], post: &Post) -> Vec<PathBuf> {
    // A CNC-Calc post converted to Fusion cuts arcs outside XY as postc's
    // runtime does (`cncChords`); an APT-word post has CIRCLE's `Plane`.
    let every_plane = post.info.dialect == Dialect::Cimco || post.info.dispatch == postc_ir::post::Dispatch::AptWords;
    let clock = prints(post, &[Quantity::Date, Quantity::Time]);
    let origin = prints(post, &[Quantity::XyOriginText, Quantity::ZOriginText]);
    all.iter()
        .filter(|j| if clock { !j.dated } else { !j.dateless })
        .filter(|j| !fusion_links_differ(&j.text))
        .filter(|j| {
            let squeezed = j.text.replace(' ', "");
            !squeezed.contains("jet:true")
                && !squeezed.contains("JetOn")
                && !squeezed.contains("Power(")
                && (every_plane || !squeezed.contains("plane:Zx") && !squeezed.contains("plane:Yz"))
        })
        .filter(|j| !origin || origin_agrees(&j.path))
        .map(|j| j.path.clone())
        .collect()
}

/// Node.js running a `.cps` post over a JSON Lines toolpath, with post
/// properties set.
fn run_fusion_node(post: &Path, jsonl: &Path, properties: &[(String, String)]) -> Result<Vec<u8>, String> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/fusion.js");
    let mut command = node_command();
    command.arg(script).arg(post).arg(jsonl);
    for (name, value) in properties {
        command.arg("--property").arg(format!("{name}={value}"));
    }
    let out = command.output().map_err(|e| format!("cannot run node: {e}"))?;
    if !out.status.success() {
        return Err(format!("node failed:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    Ok(out.stdout)
}

/// The post properties a user sets for a converted post that reads the
/// job's home position and wrap diameter from them (docs/convert.md,
/// "Fusion posts"): the toolpath's, in the source's units (the
/// program's), for each such property the converted post declares.
fn dialog_properties(source: &Post, converted: &str, toolpath: &Path) -> Vec<(String, String)> {
    let mut sources = postc_report::source_map();
    let Ok(mut events) = postc_driver::open_toolpath(toolpath, &mut sources) else { return Vec::new() };
    let mut diags = Vec::new();
    let Some((Event::Job(job), _)) = events.next_event(&mut diags) else { return Vec::new() };
    let factor = source.output_units().map_or(1.0, |u| job.units.factor_to(u));
    let home = job.home.map(|h| [h.x, h.y, h.z]);
    [
        ("homePositionX", home.map(|h| h[0])),
        ("homePositionY", home.map(|h| h[1])),
        ("homePositionZ", home.map(|h| h[2])),
        ("wrapDiameter", job.wrap_diameter),
        ("originOffsetX", job.origin.as_ref().map(|o| o.x)),
        ("originOffsetY", job.origin.as_ref().map(|o| o.y)),
    ]
    .into_iter()
    .filter(|(name, _)| converted.contains(&format!("  {name}: {{")))
    .filter_map(|(name, v)| Some((name.to_string(), format!("{}", v? * factor))))
    .collect()
}

/// postc posting a post over a toolpath with post properties set (`--set
/// property.NAME=VALUE`).
fn post_with_properties(post: &Post, toolpath: &Path, properties: &[(String, String)]) -> Result<Vec<u8>, String> {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources)
        .map_err(|d| format!("cannot open {}: {} {}", toolpath.display(), d.code, d.message))?;
    let options = RunOptions { properties: properties.to_vec(), ..postc_driver::run_options(post) };
    match postc_runtime::run(post, &mut source, Output::memory(), options) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => Ok(parts.concat()),
            _ => Err("a memory run did not finish in memory".into()),
        },
        Err(diagnostics) => {
            let list: Vec<String> = diagnostics.iter().map(|d| format!("  {} {}", d.code, d.message)).collect();
            Err(format!("posting failed:\n{}", list.join("\n")))
        }
    }
}

/// Converts and judges each post, on worker threads; returns the tally
/// and the failures.
fn judge(posts: &[PathBuf], dir: &Path, all: &[Job], failures: &mut Vec<String>) -> Tally {
    // The toolpaths as JSON Lines for Node.js, each written once, before
    // the workers read them.
    let mut unexported = std::collections::BTreeMap::new();
    for job in all {
        let jsonl = dir.join(format!("{}.jsonl", stem(&job.path)));
        if !jsonl.exists()
            && let Err(e) = export_jsonl(&job.path, &jsonl)
        {
            unexported.insert(job.path.clone(), e);
        }
    }
    let numbered: Vec<(usize, &PathBuf)> = posts.iter().enumerate().collect();
    let judged = support::in_workers(&numbered, |&(n, path)| vec![judge_one(n, path, dir, all, &unexported)]);
    let mut tally = Tally::default();
    for (one, mut failed) in judged {
        tally.add(one);
        failures.append(&mut failed);
    }
    failures.sort();
    tally
}

/// Converts the `n`th post and judges it over every toolpath that applies:
/// its tally and its failures.
fn judge_one(
    n: usize,
    path: &Path,
    dir: &Path,
    all: &[Job],
    unexported: &std::collections::BTreeMap<PathBuf, String>,
) -> (Tally, Vec<String>) {
    let mut tally = Tally::default();
    let mut failures = Vec::new();
    let Some((post, converted)) = convert_counted(path, n, Target::Fusion, "cps", dir, &mut tally) else {
        return (tally, failures);
    };
    let again = match compile_warned(&converted) {
        Ok(p) => Some(p),
        Err(e) => {
            failures.push(format!("{}: postc does not compile the converted post: {e}", path.display()));
            None
        }
    };
    let text = std::fs::read_to_string(&converted).unwrap_or_default();
    let mut identical = true;
    for toolpath in toolpaths(all, &post) {
        let properties = dialog_properties(&post, &text, &toolpath);
        let pair = format!("{}__{}", path.display(), stem(&toolpath));
        if let Some(e) = unexported.get(&toolpath) {
            failures.push(format!("{pair}: cannot export the toolpath: {e}"));
            continue;
        }
        let jsonl = dir.join(format!("{}.jsonl", stem(&toolpath)));
        let ours = match post_toolpath(&post, &toolpath) {
            Ok(o) => o,
            // A CNC-Calc post stops on a toolpath it does not take (a
            // cycle it has no code for): the converted post must stop too.
            Err(e) if post.info.dialect == Dialect::Cimco => {
                if run_fusion_node(&converted, &jsonl, &properties).is_ok() {
                    failures
                        .push(format!("{pair}: postc refuses the source ({e}) but Node.js runs the converted post"));
                }
                continue;
            }
            Err(e) => {
                failures.push(format!("{pair}: postc: {e}"));
                continue;
            }
        };
        if let Some(again) = &again {
            match post_with_properties(again, &toolpath, &properties) {
                Ok(o) if o == ours => {}
                Ok(o) => {
                    identical = false;
                    failures.push(format!(
                        "{pair}: postc posting the converted post (-) and the source (+) differ\n{}",
                        diff(&o, &ours)
                    ));
                }
                Err(e) => failures.push(format!("{pair}: postc posting the converted post: {e}")),
            }
        }
        match run_fusion_node(&converted, &jsonl, &properties) {
            Ok(theirs) if theirs == ours => tally.compared += 1,
            Ok(theirs) => {
                identical = false;
                failures.push(format!(
                    "{pair}: Node.js running the converted post (-) and postc posting the source (+) differ\n{}",
                    diff(&theirs, &ours)
                ));
            }
            Err(e) => {
                identical = false;
                failures.push(format!("{pair}: {e}"));
            }
        }
    }
    if identical {
        tally.identical_posts += 1;
    }
    (tally, failures)
}

/// The posts of this test (the sections post with CR LF and with LF line
/// ends) and of `convert_native` (those with CR LF line ends, Fusion's:
/// the others are given CR LF).
fn own_posts(dir: &Path) -> Vec<PathBuf> {
    let mut own = Vec::new();
    // The sections post again with LF line ends (the converted post's
    // `setEOL`).
    let lf = SECTIONS.replace("LINE_ENDING = \"[13][10]\"", "LINE_ENDING = \"[10]\"");
    let mut texts = vec![("sections.pp".to_string(), SECTIONS.to_string()), ("sections_lf.pp".to_string(), lf)];
    for (name, text) in crate::convert_native::POSTS {
        let text = if text.contains("LINE_ENDING") {
            text.to_string()
        } else {
            text.replacen('\n', "\nLINE_ENDING = \"[13][10]\"\n", 1)
        };
        texts.push((name.to_string(), text));
    }
    for (name, text) in texts {
        let path = dir.join(name);
        std::fs::write(&path, text).expect("write the post");
        own.push(path);
    }
    own
}

#[test]
fn node_runs_fusion_posts_as_postc_posts_their_sources() {
    if node_or_skip("convert_fusion").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let all = all_toolpaths(dir.path());
    let mut failures = Vec::new();
    let own = own_posts(dir.path());
    let tests = judge(&own, dir.path(), &all, &mut failures);
    eprintln!("{}", tests.show("this test's posts", own.len()));
    // plain_sections.pp cuts helices into chords and has plunge sections:
    // the chords of a helical ramp (`MOVEMENT_RAMP_HELIX`) print through them.
    assert_eq!(tests.converted, own.len(), "every post of this test converts: {}", failures.join("\n\n"));
    assert!(tests.compared >= 3 * tests.converted, "only {} programs were compared", tests.compared);
    let corpus_posts = files(&corpus().join("posts/vectric"), "pp");
    let c = judge(&corpus_posts, dir.path(), &all, &mut failures);
    eprintln!("{}", c.show("corpus/posts/vectric", corpus_posts.len()));
    let real = real_vectric_posts("convert_fusion");
    if !real.is_empty() {
        let r = judge(&real, dir.path(), &all, &mut failures);
        eprintln!("{}", r.show("../shared/corpus/vectric", real.len()));
        assert!(r.identical_posts >= REAL_FUSION_AT_LEAST, "{}", r.show("../shared/corpus/vectric", real.len()));
    }
    assert!(failures.is_empty(), "{} failures:\n\n{}", failures.len(), failures.join("\n\n"));
}

/// The CIMCO toolpaths a CNC-Calc post converted to Fusion is judged over
/// besides the corpus's: `cimco/mill.ron`, and `cimco/drill.ron` without
/// its cycles' names (Fusion hands a cycle's type, not a CNC-Calc name:
/// CV013, docs/convert.md, "CIMCO posts as Fusion posts").
fn cimco_toolpaths(dir: &Path) -> Vec<Job> {
    let cimco = corpus().join("toolpaths/cimco");
    let mill = cimco.join("mill.ron");
    let mut out = vec![Job {
        text: std::fs::read_to_string(&mill).unwrap_or_default(),
        path: mill,
        dateless: false,
        dated: false,
    }];
    let drill = std::fs::read_to_string(cimco.join("drill.ron")).unwrap_or_default();
    let unnamed: String = drill
        .lines()
        .map(|l| match (l.find(", name: \""), l.starts_with("DrillCycle(")) {
            (Some(at), true) => {
                let end = l[at + 9..].find('"').map_or(l.len(), |e| at + 9 + e + 1);
                format!("{}{}\n", &l[..at], &l[end..])
            }
            _ => format!("{l}\n"),
        })
        .collect();
    assert!(!unnamed.contains("name: \"Drilling"), "the names are gone: {unnamed}");
    let path = dir.join("drill_unnamed.ron");
    std::fs::write(&path, &unnamed).expect("write the toolpath");
    out.push(Job { path, text: unnamed, dateless: false, dated: false });
    out
}

/// The posts, then each one's IR as RON (`--to ron`), written in `dir`.
fn with_their_ron(mut posts: Vec<PathBuf>, dir: &Path) -> Vec<PathBuf> {
    let rons: Vec<PathBuf> = posts
        .iter()
        .map(|p| {
            let ron = postc_backends::convert(&support::compile_file(p), Target::Ron).expect("RON holds every post");
            let to = dir.join(format!("{}.ron", stem(p)));
            std::fs::write(&to, ron).expect("write the RON post");
            to
        })
        .collect();
    posts.extend(rons);
    posts
}

/// Whether Fusion hands a converted CNC-Calc post a move CNC-Calc does
/// not: a drilling cycle within a toolpath that starts with the tool
/// elsewhere than over its first hole at the clearance plane, where
/// Fusion's linking moves take it (docs/convert.md, "CIMCO posts as
/// Fusion posts").
fn links_before_cycles(text: &str) -> bool {
    let mut at: Option<[Option<f64>; 3]> = None;
    let mut lines = text.lines().map(str::trim_start);
    while let Some(line) = lines.next() {
        if line.starts_with("ToolpathStart") {
            at = None;
        } else if line.starts_with("Rapid(") || line.starts_with("Feed(") || line.starts_with("Arc(") {
            let was = at.unwrap_or([None; 3]);
            at = Some([field(line, "x").or(was[0]), field(line, "y").or(was[1]), field(line, "z").or(was[2])]);
        } else if line.starts_with("DrillCycle(") {
            let clearance = field(line, "retract_plane");
            let holes: Vec<&str> = lines
                .clone()
                .take_while(|l| !l.starts_with("DrillEnd"))
                .filter(|l| l.starts_with("DrillPoint("))
                .collect();
            let over = |p: &&str| [field(p, "x"), field(p, "y"), clearance];
            if let (Some(now), Some(first)) = (at, holes.first().map(over))
                && now != first
            {
                return true;
            }
            // The cycle leaves the tool over its last hole at the clearance plane.
            at = holes.last().map(over).or(at);
        }
    }
    false
}

/// CIMCO posts converted to Fusion (`cnc_calc.js`: the CNC-Calc post as
/// written, in a scope of its own, called by Fusion's entry points in
/// CNC-Calc's order), judged as the Vectric ones are: Node.js with the
/// Fusion host running the converted post, and postc running it, print
/// what postc prints posting the CIMCO source, over every toolpath that
/// applies; each post's RON (its IR) converts and posts the same. The
/// lathe post is refused (CV004).
#[test]
fn node_runs_cimco_posts_converted_to_fusion_as_postc_posts_their_sources() {
    if node_or_skip("convert_fusion").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut all = all_toolpaths(dir.path());
    all.extend(cimco_toolpaths(dir.path()));
    all.retain(|j| !links_before_cycles(&j.text));
    let mut failures = Vec::new();
    let mut posts = files(&corpus().join("posts/cimco"), "js");
    posts.extend(files(&corpus().join("posts/cimco-styles"), "js"));
    // Each as its IR in RON too, which converts as the JavaScript does.
    let posts = with_their_ron(posts, dir.path());
    let tally = judge(&posts, dir.path(), &all, &mut failures);
    eprintln!("{}", tally.show("corpus/posts/cimco and cimco-styles, as JavaScript and as RON", posts.len()));
    assert_eq!(tally.converted, posts.len() - 2, "every milling post converts: {}", tally.show("CIMCO", posts.len()));
    assert_eq!(tally.refused.get("CV004"), Some(&2), "the lathe post is refused: {}", tally.show("CIMCO", posts.len()));
    assert!(failures.is_empty(), "{} failures:\n\n{}", failures.len(), failures.join("\n\n"));
    assert_eq!(tally.identical_posts, tally.converted, "{}", tally.show("CIMCO", posts.len()));
    assert!(tally.compared >= 5 * tally.converted, "only {} programs were compared", tally.compared);
}

/// A job of every record a converted APT-word post makes from Fusion's
/// calls, each as Fusion hands it: spindle (once counter-clockwise) and
/// coolant at each tool, a comment before a section's first move, cutter
/// compensation on and off, an arc, a dwell, coolant off within a
/// section, and drilling
/// cycles of each kind, each starting its own toolpath over its first
/// hole with the hole's top the surface (Fusion's `cycle.stock`).
const APT_RECORDS_JOB: &str = r#"Job(units: Mm, material: (min: (x: 0, y: 0, z: -20), max: (x: 100, y: 60, z: 0)), home: (x: 0, y: 0, z: 50), safe_z: 5, file: (name: "apt_records", dir: "/jobs", extension: "nc"), notes: "APT records", product: "postc test")
Tool(number: 3, name: "10 mm End Mill", notes: "", diameter: 10, spindle_speed: 8000, cut_feed: 900, plunge_feed: 300)
ToolpathStart(name: "Profile", notes: "")
SpindleOn(speed: 8000)
Coolant(Flood)
Comment(text: "Check (part) datum")
Rapid(x: 0, y: 0, z: 25)
Rapid(x: 10, y: 0, z: 5)
Feed(x: 10, y: 0, z: -2, intent: Plunge)
CutterComp(side: Left)
Feed(x: 30, y: 0, z: -2)
Arc(dir: Ccw, x: 40, y: 10, z: -2, cx: 30, cy: 10, cz: -2)
Feed(x: 40, y: 30, z: -2, feed: 600)
CutterComp(side: Off)
Feed(x: 50, y: 30, z: -2)
Dwell(seconds: 1.5)
Comment(text: "Profile done")
Rapid(x: 50, y: 30, z: 25)
ToolpathEnd
Tool(number: 5, name: "6.8 mm Drill", notes: "", diameter: 6.8, spindle_speed: 2400, cut_feed: 250, plunge_feed: 120)
ToolpathStart(name: "Spot", notes: "")
SpindleOn(speed: 2400, ccw: true)
Coolant(Mist)
DrillCycle(kind: Drill, retract_plane: 10, reference_plane: 2, surface: 0, depth: -8, feed: 120, dwell: 0.5)
DrillPoint(x: 10, y: 40)
DrillPoint(x: 20, y: 40)
DrillEnd
ToolpathEnd
ToolpathStart(name: "Peck", notes: "")
DrillCycle(kind: Deep, retract_plane: 10, reference_plane: 2, surface: 0, depth: -18, feed: 100, peck: 4)
DrillPoint(x: 30, y: 40)
DrillPoint(x: 40, y: 50)
DrillEnd
ToolpathEnd
ToolpathStart(name: "Chip break", notes: "")
DrillCycle(kind: ChipBreak, retract_plane: 10, reference_plane: 2, surface: 0, depth: -12, feed: 100, peck: 2)
DrillPoint(x: 50, y: 40)
DrillEnd
ToolpathEnd
ToolpathStart(name: "Bore", notes: "")
DrillCycle(kind: Bore, retract_plane: 10, reference_plane: 2, surface: 0, depth: -15, feed: 80)
DrillPoint(x: 70, y: 40)
DrillPoint(x: 80, y: 40)
DrillEnd
Coolant(Off)
ToolpathEnd
End
"#;

/// Each job as the APT records of a Fusion job have it (docs/convert.md,
/// "VcPost posts as Fusion posts"): a `SpindleOn` at the tool's speed
/// after the `ToolpathStart` of each toolpath that follows a tool change,
/// where the toolpath has none (the runtime calls an APT-word post's
/// SPINDL only at spindle records; Fusion hands every section its speed,
/// and the converted post makes the SPINDL record of each loaded tool),
/// and the centre of an arc in XY at its start's Z where the toolpath
/// gives none (Fusion's arcs have it there). Jobs whose sections Fusion
/// hands otherwise are left out ([`sections_differ_from_records`],
/// [`links_before_cycles`]).
fn with_spindle_records(all: Vec<Job>, dir: &Path) -> Vec<Job> {
    all.into_iter()
        .filter(|job| !sections_differ_from_records(&job.text) && !links_before_cycles(&job.text))
        .map(|job| {
            if job.text.contains("SpindleOn") || job.text.contains("SpindleOff") {
                return job;
            }
            let mut text = String::new();
            let mut speed: Option<f64> = None;
            let mut z: Option<f64> = None;
            for line in job.text.lines() {
                let t = line.trim_start();
                let squeezed = t.replace(' ', "");
                // An arc in XY with no centre Z has it at its start, as
                // Fusion's arcs and APT's CIRCLE records have it.
                let xy = !squeezed.contains("plane:Zx") && !squeezed.contains("plane:Yz");
                match (t.strip_prefix("Arc(").and_then(|a| a.trim_end().strip_suffix(')')), z) {
                    (Some(fields), Some(start)) if xy && !squeezed.contains("cz:") => {
                        text.push_str(&format!("Arc({fields}, cz: {start})\n"));
                    }
                    _ => {
                        text.push_str(line);
                        text.push('\n');
                    }
                }
                if t.starts_with("Rapid(") || t.starts_with("Feed(") || t.starts_with("Arc(") {
                    z = field(t, "z").or(z);
                }
                if t.starts_with("Tool(") {
                    speed = field(t, "spindle_speed").filter(|s| *s > 0.0);
                } else if t.starts_with("ToolpathStart")
                    && let Some(s) = speed.take()
                {
                    text.push_str(&format!("SpindleOn(speed: {s})\n"));
                }
            }
            let path = dir.join(format!("{}_spindle.ron", stem(&job.path)));
            std::fs::write(&path, &text).expect("write the toolpath");
            Job { path, text, ..job }
        })
        .collect()
}

/// Whether postc's Fusion host, which the section rules drive, hands a
/// job otherwise than its APT records say (docs/convert.md, "VcPost posts
/// as Fusion posts"): a `Tool` of the tool already loaded (a LOADTL record
/// that Fusion, whose sections only change tools, never makes), or a feed
/// straight down that the toolpath does not mark as a plunge (the section
/// rules feed it at the plunge feed; the APT records at the cutting feed).
fn sections_differ_from_records(text: &str) -> bool {
    let mut tool: Option<f64> = None;
    let mut at: [Option<f64>; 3] = [None; 3];
    for line in text.lines().map(str::trim_start) {
        if line.starts_with("Tool(") {
            let number = field(line, "number");
            if number.is_some() && number == tool {
                return true;
            }
            tool = number;
        } else if line.starts_with("Rapid(") || line.starts_with("Feed(") || line.starts_with("Arc(") {
            let to = [field(line, "x").or(at[0]), field(line, "y").or(at[1]), field(line, "z").or(at[2])];
            let down = to[0] == at[0] && to[1] == at[1] && matches!((to[2], at[2]), (Some(a), Some(b)) if a < b);
            let squeezed = line.replace(' ', "");
            if line.starts_with("Feed(") && down && !squeezed.contains("intent:Plunge") {
                return true;
            }
            at = to;
        }
    }
    false
}

/// VcPost milling posts (one Sub per APT word) and the `postp`
/// controllers as VcPost text, and each as its IR in RON, converted to
/// Fusion: the probing and composites posts are refused (CV001); every
/// other converts, and Node.js running it prints what postc prints for
/// the source over every job, each with its spindle records.
#[test]
fn node_runs_vcpost_posts_converted_to_fusion_as_postc_posts_their_sources() {
    if node_or_skip("convert_fusion").is_none() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut all = with_spindle_records(all_toolpaths(dir.path()), dir.path());
    let records = dir.path().join("apt_records.ron");
    std::fs::write(&records, APT_RECORDS_JOB).expect("write the job");
    all.push(Job { path: records, text: APT_RECORDS_JOB.to_string(), dateless: false, dated: false });
    let mut failures = Vec::new();
    let mut posts = files(&corpus().join("posts/vcpost"), "VcPost");
    posts.extend(files(&corpus().join("posts/postp"), "VcPost"));
    let posts = with_their_ron(posts, dir.path());
    let tally = judge(&posts, dir.path(), &all, &mut failures);
    eprintln!("{}", tally.show("corpus/posts/vcpost and postp, as VcPost and as RON", posts.len()));
    assert_eq!(
        tally.refused.get("CV001"),
        Some(&8),
        "the probing and composites posts: {}",
        tally.show("VcPost", posts.len())
    );
    assert_eq!(tally.converted, posts.len() - 8, "{}", tally.show("VcPost", posts.len()));
    assert!(failures.is_empty(), "{} failures:\n\n{}", failures.len(), failures.join("\n\n"));
    assert_eq!(tally.identical_posts, tally.converted, "{}", tally.show("VcPost", posts.len()));
    assert!(tally.compared >= 5 * tally.converted, "only {} programs were compared", tally.compared);
}

/// The command line: `--to fusion` writes a `.cps` post with Fusion's
/// entry points; a value Fusion never hands is refused at its line and
/// column and nothing is written; a post of another dialect is refused.
/// The home position is the converted post's properties, which `postc
/// post --set property.NAME=VALUE` sets; a property the post does not
/// have is refused, naming those it has.
#[test]
fn convert_writes_fusion_posts_and_refuses_what_fusion_never_hands() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let pp = dir.path().join("sections.pp");
    std::fs::write(&pp, SECTIONS).expect("write the post");
    let cps = dir.path().join("sections.cps");
    let o = postc(&["convert", &pp.display().to_string(), "--to", "fusion", "-o", &cps.display().to_string()]);
    assert!(o.status.success(), "{}", said(&o));
    let text = std::fs::read_to_string(&cps).expect("the converted post");
    for entry in [
        "description = \"sections (*.nc)\";",
        "extension = \"nc\";",
        "capabilities = CAPABILITY_MILLING;",
        "function onSection()",
        "function onRapid(",
        "function onLinear(",
        "function onCircular(",
        "function onDwell(",
        "function onClose()",
        "writeln(",
    ] {
        assert!(text.contains(entry), "{entry}\n{text}");
    }
    let refused = dir.path().join("refused.cps");
    let o = postc(&[
        "convert",
        "corpus/posts/vectric/text_output_mm.pp",
        "--to",
        "fusion",
        "-o",
        &refused.display().to_string(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[CV007]") && err.contains("`[FI]` in FEED_MOVE: Fusion never hands"), "{err}");
    assert!(!refused.exists(), "a refused conversion writes nothing");
    // The origin offsets: properties the user sets, as the home position.
    let shopbot = dir.path().join("shopbot.cps");
    let o = postc(&[
        "convert",
        "corpus/posts/vectric/shopbot_inch.pp",
        "--to",
        "fusion",
        "-o",
        &shopbot.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", said(&o));
    let text = std::fs::read_to_string(&shopbot).expect("the converted post");
    assert!(text.contains("  originOffsetX: {") && text.contains("getProperty(\"originOffsetY\")"), "{text}");
    let program = dir.path().join("shopbot.sbp");
    let o = postc(&[
        "post",
        &shopbot.display().to_string(),
        "corpus/toolpaths/native/one_toolpath_inch.ron",
        "-o",
        &program.display().to_string(),
        "--no-verify",
        "--set",
        "property.originOffsetX=1.25",
        "--set",
        "property.originOffsetY=-0.5",
    ]);
    assert!(o.status.success(), "{}", said(&o));
    let sbp = std::fs::read_to_string(&program).expect("the program");
    assert!(sbp.contains(" at 1.25"), "{sbp}");
    // The home position: properties the user sets.
    let homed = dir.path().join("homed.cps");
    let o = postc(&[
        "convert",
        "corpus/posts/vectric/gcode_arcs_inch.pp",
        "--to",
        "fusion",
        "-o",
        &homed.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", said(&o));
    let text = std::fs::read_to_string(&homed).expect("the converted post");
    assert!(text.contains("  homePositionZ: {") && text.contains("getProperty(\"homePositionZ\")"), "{text}");
    let job = "corpus/toolpaths/native/one_toolpath_inch.ron";
    let program = dir.path().join("homed.nc");
    let o = postc(&[
        "post",
        &homed.display().to_string(),
        job,
        "-o",
        &program.display().to_string(),
        // verify reads a `.cps` program in millimetres until it says G20,
        // and this post moves home first.
        "--no-verify",
        "--set",
        "property.homePositionX=1.5",
        "--set",
        "property.homePositionY=2",
        "--set",
        "property.homePositionZ=3.25",
    ]);
    assert!(o.status.success(), "{}", said(&o));
    let nc = std::fs::read_to_string(&program).expect("the program");
    assert!(nc.contains("G0Z3.2500\r\n") && nc.contains("G0X1.5000Y2.0000"), "{nc}");
    let o = postc(&["post", &homed.display().to_string(), job, "--set", "property.homeX=1"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[IO007]: The post has no property \"homeX\""), "{err}");
    // The command line's error: no frame of the host, no toolpath record.
    assert!(!err.contains("postc fusion host") && !err.contains("while posting"), "{err}");
    // ... with the names it has, so that a mistyped one is found.
    assert!(err.contains("its properties are homePositionX, homePositionY, homePositionZ"), "{err}");
    // A property given without `property.` is named as typed, with the
    // form that sets it.
    let o = postc(&["post", &homed.display().to_string(), job, "--set", "homePositionX=1"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("`--set homePositionX` is not a setting") && err.contains("`--set property.homePositionX=1`"),
        "{err}"
    );
    // A VcPost section post (postc's extension) has no Fusion form yet.
    let o = postc(&["convert", "corpus/converted/vcpost/vectric/gcode_mm.VcPost", "--to", "fusion"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[CV012]") && err.contains("driven by sections"), "{err}");
    // A VcPost milling post converts: its Subs in a scope of their own,
    // called through the APT records by Fusion's entry points; the Subs
    // of records Fusion never makes are left out with a warning.
    let fanuc = dir.path().join("fanuc_mill.cps");
    let o = postc(&[
        "convert",
        "corpus/posts/vcpost/fanuc_mill.VcPost",
        "--to",
        "fusion",
        "-o",
        &fanuc.display().to_string(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("warning[CV008]") && err.contains("`Sub INSERT` is left out: Fusion calls no function"),
        "{err}"
    );
    let text = std::fs::read_to_string(&fanuc).expect("the converted post");
    for entry in ["var vcPost = (function () {", "function GOTO() {", "function onSection() {", "vcPost.loadtl("] {
        assert!(text.contains(entry), "{entry}\n{text}");
    }
    // A probing post is refused at each table row, and nothing is written.
    let probe = dir.path().join("probe.cps");
    let o = postc(&[
        "convert",
        "corpus/posts/vcpost/renishaw_probe.VcPost",
        "--to",
        "fusion",
        "-o",
        &probe.display().to_string(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[CV001]") && err.contains("which Fusion has no call for"), "{err}");
    assert!(!probe.exists(), "a refused conversion writes nothing");
}
