//! Real Fusion `.cps` posts: every post of `../shared/corpus/fusion/`
//! (public posts from 57 repositories, never copied into this one) posts
//! the four jobs of the corpus bar through `postc post`, whose
//! verification replays the program against the toolpath: the standard
//! job's milling toolpaths (`corpus/toolpaths/standard.ron` without its
//! laser toolpath), the arcs job, the drilling job, and a real APT CL file
//! (`../shared/corpus/apt/MichaHofft__CreoPost/profilfraesen_2.ncl.2`:
//! Creo's profile milling, its tool's centre line, arcs, no compensation
//! in the control); a fifth job, reported beside the bar's four, is the CL
//! file `aamorim1913__AptPostProcessor/Top-light-cover.apt` (a deep
//! drilling cycle, pockets of arcs, cutter compensation in the control,
//! inserted text). Each post either writes programs that verify, or writes programs
//! in a dialect verify says (VF044) it does not read, or is refused with a
//! diagnostic and writes nothing; none panics. The test prints the count
//! by outcome (the table of docs/fusion.md: a post counts under the first
//! job it does not post) and holds the number that post and verify all
//! four at or above [`AT_LEAST`], and the number that post all four at or
//! above [`POSTING_AT_LEAST`]. A second test posts the jet job
//! (`corpus/toolpaths/jet_mm.ron`) through every post the same way, and a
//! third the turning job (`corpus/toolpaths/turning/turning_mm.ron`) through the
//! turning and mill-turn posts.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::support;

/// Posts that post all four jobs and whose every program verify reads and
/// passes today, but for findings docs/fusion.md lists as the post's own
/// ([`OWN`]).
const AT_LEAST: usize = 93;

/// Posts that post all four jobs today, verified (as [`AT_LEAST`] counts
/// them) or in a dialect verify does not read.
const POSTING_AT_LEAST: usize = 132;

/// Of the 156 milling-kind posts (SOURCES.md's kinds, [`kinds`]), those
/// that post all four jobs and verify, and those that post them, verified
/// or in a dialect verify does not read.
const MILLING_AT_LEAST: usize = 91;
const MILLING_POSTING_AT_LEAST: usize = 126;

/// The outcome of a post whose programs pass verify but for findings
/// docs/fusion.md lists as that post's own property ([`OWN`]): it counts
/// with the posts that verify, as the bar says.
const OWN_FINDINGS: &str = "posts and verifies, but for findings that are the post's own (docs/fusion.md)";

/// Verify's findings that are a post's own property, each read in the
/// post and listed with its evidence in docs/fusion.md ("Findings that
/// are the post's own"): the post, the job (every job when empty), and
/// the codes. The post is
/// posted for that job with those codes as warnings; every other check
/// still applies. A post that writes no move (its finding VF011 over
/// every job) is not listed: with nothing compared, it has not posted the
/// job.
const OWN: &[(&str, &str, &[&str])] = &[
    // `allowedCircularPlanes = undefined` ("allow any circular motion"),
    // but `onCircular` prints G17 and then the ZX arc's X Z I K without G18.
    ("AntonTroskin__posts/siemens-840d.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("AntonTroskin__posts/siemens-840d_2.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("AntonTroskin__posts/siemens-810d.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("AntonTroskin__posts/HYDRO_-_DMG-MORI-DMU-50.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("AntonTroskin__posts/siemens-840d_probe_20180717.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("konkers__Mill-Post-Processors/siemens-840d.cps", "arcs", &["VF013", "VF021", "VF020"]),
    ("konkers__Mill-Post-Processors/siemens-810d.cps", "arcs", &["VF013", "VF021", "VF020"]),
    // Feeds per revolution (G95) computed for the tool's 16,000 rpm, and the
    // spindle capped at 15,000 (`S15000`, the speed printed beside the
    // tool's `( S16000 )`): every cut runs at 15/16 of the toolpath's feed.
    ("AntonTroskin__posts/A_haas.cps", "", &["VF033"]),
    // `hFormat` has no `H` prefix: `G43 Z5. 1`.
    ("Lawmate__Posts/hurco_Lorro_v4.cps", "", &["VF004"]),
    // A Marlin post with no spindle command at all (`onRapid` and
    // `onLinear` only), and one whose default mode is FDM (`marlinMode: 0`),
    // which writes `M3` only in its CNC mode (`marlinMode === 1`).
    ("rflulling__Marlin_CNC-Laser_CPS_for_Fusion360/marlin_magic_speed.cps", "", &["VF035"]),
    ("rflulling__Marlin_CNC-Laser_CPS_for_Fusion360/marlin_mode_minimal.cps", "", &["VF035"]),
    // `onRapid` turns a rapid from above Z0 to below it into `G1` at its
    // property `rLab_negZRapidPlungeRate: 5`: the drilling job's pecks.
    ("Gavatastic__260-VMC-post-processor/260VMC.cps", "drilling", &["VF033"]),
    // `onCycleEnd` leaves the cycle with no `G80` ("make it output G0 next
    // move, and don't use G80") and never resets `gCycleModal`: the next
    // cycle's first hole prints without its `G82`, a rapid into the hole.
    ("jfbell__CAMPosts/MotusCNC_5-Axis_G43.4.cps", "drilling", &["VF012"]),
    // `var kOutput = createReferenceVariable({prefix:"K"}, xFormat);`: an
    // arc's K is printed with X's diameter format (`scale:2`), twice the
    // centre's offset along Z.
    ("nmnarz__MACHINE-POSTS/DMG_MORI_NLX_4000B-750_180818.cps", "turning", &["VF013", "VF020"]),
    // `sOutput.format(tool.surfaceSpeed * ((unit == MM) ? 1 : 1/12.0))`:
    // the tool's surface speed (millimetres a minute) printed as metres a
    // minute unconverted, `G96 S200000` for 200 m/min.
    ("skidsolo__Lathe-Post-Processors-2-Axis/haas_turning.cps", "turning", &["VF036"]),
    ("skidsolo__Lathe-Post-Processors-2-Axis/fanuc_turning.cps", "turning", &["VF036"]),
    ("nmnarz__Sauer-Machine-Posts/fanuc_turning_G71_beta.cps", "turning", &["VF036"]),
];

/// The outcome of a post whose programs all post but whose dialect verify
/// does not read (VF044, a note): it posts, unverified.
const UNREAD: &str = "posts, but verify does not read its dialect (VF044)";

/// The outcome of a post whose capabilities take no jet operation.
const REFUSES_JET: &str = "refuses jet operations (its capabilities)";

/// The outcome of a post whose capabilities take no turning operation.
const REFUSES_TURNING: &str = "refuses turning operations (its capabilities)";

/// Of the turning and mill-turn posts ([`kinds`]), those that post the
/// turning job and whose program verify reads and passes (but for
/// findings listed as the post's own), and those that post it, verified
/// or in a dialect verify does not read.
const TURNING_AT_LEAST: usize = 11;
const TURNING_POSTING_AT_LEAST: usize = 11;

/// Posts that post the jet job (with one of the three jet tools) today,
/// and of those the ones whose program verify reads and passes.
const JET_POSTING_AT_LEAST: usize = 9;
const JET_AT_LEAST: usize = 7;

/// The Fusion corpus beside the checkout.
pub fn shared() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/fusion")
}

/// Every `.cps` under the corpus folder, sorted.
pub fn posts(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).expect("list the Fusion corpus") {
            let path = entry.expect("directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("cps")) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The kind of each corpus post (milling, turning, mill-turn, jet,
/// mill+jet, other), by its path relative to [`shared`], read from the
/// table of `SOURCES.md`. The file states the kinds' counts ("Kinds in
/// this part: milling 156, ...") and that they are "a heuristic from
/// capabilities / names", but names no kind per post; this rule gives
/// each post one and reproduces every stated count, which the caller
/// checks against [`stated_kinds`] (docs/fusion.md, "Kinds"):
///
/// - by `capabilities`: milling and turning a mill-turn post, milling and
///   jet a mill+jet post, jet alone a jet post, turning alone a turning
///   post, setup sheet or intermediate an "other", milling a milling post;
/// - a post that sets no `capabilities` (a 2014-era library post, which
///   Fusion takes as milling) by its `description`: `turning` a turning
///   post; a sheet, dumper, redirect, XML, APT or CSV exporter an "other";
///   a laser, plasma or jet a jet post; otherwise milling.
pub fn kinds(dir: &Path) -> BTreeMap<String, &'static str> {
    let text = std::fs::read_to_string(dir.join("SOURCES.md")).expect("the corpus's SOURCES.md");
    let mut out = BTreeMap::new();
    for row in text.lines().filter(|l| l.starts_with("| ") && !l.starts_with("| local path")) {
        // `\|` is a bar inside a cell (`CAPABILITY_MILLING \| CAPABILITY_JET`).
        let row = row.replace("\\|", "+");
        let cells: Vec<&str> = row.trim().trim_matches('|').split('|').map(str::trim).collect();
        let [path, .., description, _vendor, capabilities] = cells.as_slice() else { continue };
        let has = |c: &str| capabilities.contains(c);
        let words = description.to_ascii_lowercase();
        let said =
            |w: &[&str]| words.split(|c: char| !c.is_ascii_alphanumeric()).any(|t| w.iter().any(|w| t.starts_with(w)));
        let (milling, turning, jet) = (has("CAPABILITY_MILLING"), has("CAPABILITY_TURNING"), has("CAPABILITY_JET"));
        let kind = if milling && turning {
            "mill-turn"
        } else if milling && jet {
            "mill+jet"
        } else if jet {
            "jet"
        } else if turning {
            "turning"
        } else if has("CAPABILITY_SETUP_SHEET") || has("CAPABILITY_INTERMEDIATE") {
            "other"
        } else if milling {
            "milling"
        } else if said(&["turning"]) {
            "turning"
        } else if said(&["sheet", "dump", "redirect", "xml", "apt", "csv"]) {
            "other"
        } else if said(&["laser", "plasma", "jet", "waterjet"]) {
            "jet"
        } else {
            "milling"
        };
        out.insert(path.to_string(), kind);
    }
    out
}

/// The counts of each kind `SOURCES.md` states ("Kinds in this part:
/// milling 156, jet 16, ...").
pub fn stated_kinds(dir: &Path) -> BTreeMap<String, usize> {
    let text = std::fs::read_to_string(dir.join("SOURCES.md")).expect("the corpus's SOURCES.md");
    let line = text.lines().find_map(|l| l.strip_prefix("Kinds in this part:")).expect("the stated kinds");
    line.split(['.', ','])
        .filter_map(|part| {
            let (kind, n) = part.trim().rsplit_once(' ')?;
            (!kind.ends_with(':')).then_some(())?;
            Some((kind.to_string(), n.parse().ok()?))
        })
        .collect()
}

/// The standard job without its jet toolpath: the events from the jet
/// tool's `Tool` up to the `ToolpathEnd` of its toolpath are left out.
pub fn milling_job(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(support::corpus().join("toolpaths/standard.ron")).expect("standard.ron");
    let mut out = String::new();
    let mut jet = false;
    for line in text.lines() {
        if line.starts_with("Tool(") {
            jet = line.contains("jet:true");
        }
        if !jet {
            out.push_str(line);
            out.push('\n');
        }
        if jet && line.starts_with("ToolpathEnd") {
            jet = false;
        }
    }
    let path = dir.join("standard_milling.ron");
    std::fs::write(&path, out).expect("write the milling job");
    path
}

/// The outcome of one post over one job, as the table counts it.
fn outcome(said: &str, status: Option<i32>) -> String {
    if status == Some(0) {
        return if said.contains("note[VF044]") { UNREAD } else { "posts and verifies" }.into();
    }
    let first = said.lines().find(|l| l.starts_with("error[")).unwrap_or("no error printed");
    let code = first.get(6..11).unwrap_or("?");
    if first.contains("does not support milling operations") {
        return "refuses milling (its capabilities)".into();
    }
    if first.contains("does not support jet operations") {
        return REFUSES_JET.into();
    }
    if first.contains("does not support turning operations") {
        return REFUSES_TURNING.into();
    }
    code.to_string()
}

/// The jobs of the bar: the milling job first (a post that refuses it is
/// not run over the others).
fn jobs(tmp: &Path) -> Vec<(&'static str, PathBuf)> {
    let toolpaths = support::corpus().join("toolpaths");
    let apt = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/apt");
    vec![
        ("milling", milling_job(tmp)),
        ("arcs", toolpaths.join("arcs_mm.ron")),
        ("drilling", toolpaths.join("drill_mm.ron")),
        ("APT CL file", apt.join("MichaHofft__CreoPost/profilfraesen_2.ncl.2")),
        (TOP_LIGHT_COVER, apt.join("aamorim1913__AptPostProcessor/Top-light-cover.apt")),
    ]
}

/// The fifth job, reported but not part of the bar: a CL file whose
/// contours ask for cutter compensation in the control (`CUTCOM/LEFT`),
/// which posts for controls without it refuse (docs/fusion.md).
const TOP_LIGHT_COVER: &str = "Top-light-cover.apt";

/// Runs `run(post, name, output file)` for every post, on as many threads
/// as the machine has cores (at most 8), each thread writing into a file
/// of its own: each post's name and what `run` gave.
fn each_post<T: Send>(
    posts: &[PathBuf],
    dir: &Path,
    tmp: &Path,
    run: impl Fn(&Path, &str, &Path) -> T + Sync,
) -> Vec<(String, T)> {
    let next = std::sync::atomic::AtomicUsize::new(0);
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).min(8);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                let (next, run) = (&next, &run);
                scope.spawn(move || {
                    let mut done = Vec::new();
                    let out = tmp.join(format!("program-{w}.nc"));
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some(post) = posts.get(i) else { break };
                        let name = post.strip_prefix(dir).unwrap_or(post).display().to_string();
                        let got = run(post, &name, &out);
                        done.push((name, got));
                    }
                    done
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("a worker")).collect()
    })
}

/// Posts `job` with `post` into `out`: the outcome, as the tables count
/// it. A panic, a crash or an output left behind by a failed run is
/// added to `broken`, under `what`.
fn post_one(post: &Path, job: &Path, out: &Path, what: &str, broken: &mut Vec<String>) -> String {
    post_warning(post, job, out, &[], what, broken)
}

/// [`post_one`], with verify's findings of `codes` made warnings
/// (`--warn CODE`): the program is written when only those are found, and
/// every other check still applies.
fn post_warning(post: &Path, job: &Path, out: &Path, codes: &[&str], what: &str, broken: &mut Vec<String>) -> String {
    let _ = std::fs::remove_file(out);
    let mut args = vec![
        "post",
        "-q",
        post.to_str().expect("a UTF-8 path"),
        job.to_str().expect("a UTF-8 path"),
        "-o",
        out.to_str().expect("a UTF-8 path"),
    ];
    for code in codes {
        args.extend(["--warn", code]);
    }
    let run = support::postc(&args);
    let said = support::said(&run);
    let status = run.status.code();
    if said.contains("panicked") || status.is_none_or(|c| c > 1) {
        broken.push(format!("{what}: exit {status:?}: {said}"));
    }
    if !run.status.success() && out.exists() {
        broken.push(format!("{what}: failed and left its output behind"));
    }
    outcome(&said, status)
}

#[test]
fn corpus_fusion_posts_post_the_milling_jobs_or_say_why_not() {
    let dir = shared();
    if !dir.is_dir() {
        support::referee_missing("corpus_fusion_posts", "../shared/corpus/fusion");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("postc-fusion-corpus-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temporary folder");
    let jobs = jobs(&tmp);
    let posts = posts(&dir);
    // Each post over each job in turn, into a file of its own, until a job fails.
    let runs = each_post(&posts, &dir, &tmp, |post, name, out| {
        let mut broken = Vec::new();
        let mut result = "posts and verifies".to_string();
        let mut own = false;
        for (job, path) in &jobs {
            let what = format!("{name} ({job})");
            let mut got = post_one(post, path, out, &what, &mut broken);
            // Findings docs/fusion.md lists as the post's own property.
            if let Some((.., codes)) = OWN.iter().find(|(p, j, codes)| {
                name.replace(std::path::MAIN_SEPARATOR, "/") == *p
                    && (j.is_empty() || j == job)
                    && codes.contains(&got.as_str())
            }) {
                got = post_warning(post, path, out, codes, &what, &mut broken);
                own |= got == "posts and verifies" || got == UNREAD;
            }
            if got == UNREAD {
                result = got;
            } else if got != "posts and verifies" && *job == TOP_LIGHT_COVER {
                // The four jobs of the bar posted: this one is reported beside them.
                result = format!("{result}; {TOP_LIGHT_COVER}: {got}");
            } else if got != "posts and verifies" {
                result = if *job == "milling" { got } else { format!("{got} ({job})") };
                break;
            }
        }
        if own && result == "posts and verifies" {
            result = OWN_FINDINGS.to_string();
        } else if own && let Some(rest) = result.strip_prefix("posts and verifies; ") {
            result = format!("{OWN_FINDINGS}; {rest}");
        }
        (result, broken)
    });
    let _ = std::fs::remove_dir_all(&tmp);
    // The kinds of SOURCES.md: the bar counts the milling posts.
    let kinds = kinds(&dir);
    let mut counted: BTreeMap<String, usize> = BTreeMap::new();
    for kind in kinds.values() {
        *counted.entry(kind.to_string()).or_default() += 1;
    }
    assert_eq!(counted, stated_kinds(&dir), "the kinds read from SOURCES.md are not the counts it states");
    let mut table: BTreeMap<String, (Vec<String>, Vec<String>)> = BTreeMap::new();
    let mut broken = Vec::new();
    for (name, (result, mut wrong)) in runs {
        broken.append(&mut wrong);
        let entry = table.entry(result).or_default();
        let kind = kinds.get(&name.replace(std::path::MAIN_SEPARATOR, "/")).copied();
        assert!(kind.is_some(), "{name} is not in SOURCES.md");
        if kind == Some("milling") {
            entry.1.push(name.clone());
        }
        entry.0.push(name);
    }
    // All posts, then the milling-kind ones; the milling posts of each
    // outcome but the good ones named.
    let mut summary = String::from(" all  milling\n");
    for (what, (all, milling)) in &table {
        summary.push_str(&format!("{:>4}  {:>4}  {what}\n", all.len(), milling.len()));
        if what != "posts and verifies" && !what.starts_with("refuses milling") {
            for n in milling {
                summary.push_str(&format!("              {n}\n"));
            }
        }
    }
    println!("{summary}");
    assert!(broken.is_empty(), "posts that panic or leave output behind:\n{}", broken.join("\n"));
    // The bar's four jobs posted, whatever Top-light-cover.apt gave.
    let count = |what: &str| {
        table
            .iter()
            .filter(|(k, _)| *k == what || k.strip_prefix(what).is_some_and(|r| r.starts_with("; ")))
            .fold((0, 0), |(a, m), (_, (all, milling))| (a + all.len(), m + milling.len()))
    };
    let (verified, milling_verified) = count("posts and verifies");
    let (own, milling_own) = count(OWN_FINDINGS);
    let (good, milling_good) = (verified + own, milling_verified + milling_own);
    let (unread, milling_unread) = count(UNREAD);
    for (n, floor, what) in [
        (good, AT_LEAST, "corpus Fusion posts post and verify"),
        (good + unread, POSTING_AT_LEAST, "corpus Fusion posts post"),
        (milling_good, MILLING_AT_LEAST, "milling-kind corpus Fusion posts post and verify"),
        (milling_good + milling_unread, MILLING_POSTING_AT_LEAST, "milling-kind corpus Fusion posts post"),
    ] {
        assert!(n >= floor, "{n} {what} the four jobs, fewer than {floor}:\n{summary}");
    }
}

/// A Fusion post's IR nests deeply (the host's and the post's JavaScript):
/// `convert --to ron` writes it, and postc reads that RON back and posts
/// the same program as the `.cps`.
#[test]
fn a_fusion_post_as_ron_reads_back_and_posts_the_same() {
    let post = shared().join("OpenPostProject__haas/haas.cps");
    if !post.is_file() {
        support::referee_missing("fusion_corpus", "../shared/corpus/fusion");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("postc-fusion-ron-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temporary folder");
    let (ron, from_ron, from_cps) = (tmp.join("haas.ron"), tmp.join("ron.nc"), tmp.join("cps.nc"));
    let job = support::corpus().join("toolpaths/arcs_mm.ron");
    let s = |p: &Path| p.to_str().expect("a UTF-8 path").to_string();
    let convert = support::postc(&["convert", "-q", &s(&post), "--to", "ron", "-o", &s(&ron)]);
    assert!(convert.status.success(), "{}", support::said(&convert));
    for (from, out) in [(&ron, &from_ron), (&post, &from_cps)] {
        let run = support::postc(&["post", "-q", &s(from), &s(&job), "-o", &s(out)]);
        assert!(run.status.success(), "{}: {}", from.display(), support::said(&run));
    }
    let (a, b) =
        (std::fs::read(&from_cps).expect("the .cps program"), std::fs::read(&from_ron).expect("the RON program"));
    let _ = std::fs::remove_dir_all(&tmp);
    assert!(a == b, "{}", support::diff(&a, &b));
}

/// A post that calls host API postc defines but does not run yet (here
/// `redirectToFile` and `new TextFile`) is named by `postc check` at each
/// call (JS110, a warning: the post runs while a job does not reach the
/// call), and stops with an error naming it when a job does.
#[test]
fn check_names_host_api_postc_does_not_run_yet() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let post = dir.path().join("stub.cps");
    std::fs::write(
        &post,
        "description = \"stub\";\ncapabilities = CAPABILITY_MILLING;\nfunction onOpen() {\n  if (programName == \"none\") {\n    redirectToFile(\"x.txt\");\n    var f = new TextFile(\"y.txt\", true, \"ansi\");\n  }\n}\nfunction onClose() {\n  redirectToFile(\"z.txt\");\n}\n",
    )
    .expect("write the post");
    let run = support::postc(&["check", post.to_str().expect("UTF-8")]);
    let said = support::said(&run);
    assert!(run.status.success(), "{said}");
    for (name, line) in [("redirectToFile", 5), ("TextFile", 6), ("redirectToFile", 10)] {
        let at = format!("stub.cps:{line}:");
        assert!(
            said.lines().any(|l| l.contains(&at))
                && said.contains(&format!("warning[JS110]: this post calls `{name}`")),
            "no JS110 for `{name}` at line {line}:\n{said}"
        );
    }
    let job = dir.path().join("job.ron");
    std::fs::write(&job, "Job(units:Mm)\nTool(number:1,diameter:6.0,spindle_speed:1000.0)\nToolpathStart(name:\"a\")\nRapid(x:0.0,y:0.0,z:5.0)\nToolpathEnd\nEnd\n").expect("write the job");
    let out = dir.path().join("out.nc");
    let run = support::postc(&[
        "post",
        "-q",
        post.to_str().expect("UTF-8"),
        job.to_str().expect("UTF-8"),
        "-o",
        out.to_str().expect("UTF-8"),
    ]);
    let said = support::said(&run);
    assert!(!run.status.success() && said.contains("`redirectToFile`") && !out.exists(), "{said}");
    // The error is in the host's JavaScript; it is also placed at the
    // post's statement that called it.
    assert!(said.contains("stub.cps:10:3") && said.contains("the post's statement that led there"), "{said}");
}

/// The jet job (`corpus/toolpaths/jet_mm.ron`: a plasma torch cuts a hole
/// and a profile) with its tool named for each jet process: Fusion's
/// host takes the tool's kind (plasma cutter, laser cutter, water jet)
/// from its name, and a post for one process refuses the others, as a
/// machine's post does in Fusion. A post counts under its best outcome
/// over the three.
fn jet_jobs(dir: &Path) -> Vec<(&'static str, PathBuf)> {
    let text = std::fs::read_to_string(support::corpus().join("toolpaths/jet_mm.ron")).expect("jet_mm.ron");
    [("plasma", "Plasma torch"), ("laser", "Laser"), ("water jet", "Water jet")]
        .into_iter()
        .map(|(kind, name)| {
            let path = dir.join(format!("jet_{}.ron", kind.replace(' ', "_")));
            std::fs::write(&path, text.replace("\"Plasma torch\"", &format!("\"{name}\""))).expect("write a jet job");
            (kind, path)
        })
        .collect()
}

/// Every corpus post over the jet job: the posts whose capabilities take
/// jet operations post it (and verify reads the program, or says it does
/// not read the dialect), or are refused with a diagnostic; none panics
/// or leaves a file behind. The count by outcome is docs/fusion.md's jet
/// table.
#[test]
fn corpus_fusion_posts_post_the_jet_job_or_say_why_not() {
    let dir = shared();
    if !dir.is_dir() {
        support::referee_missing("corpus_fusion_posts", "../shared/corpus/fusion");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("postc-fusion-jet-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temporary folder");
    let jobs = jet_jobs(&tmp);
    let posts = posts(&dir);
    let runs = each_post(&posts, &dir, &tmp, |post, name, out| {
        let mut broken = Vec::new();
        // The best outcome over the three processes: verified, then
        // posted unverified, then posted with verify's findings, then the
        // first process's refusal.
        let rank = |r: &str| match r {
            "posts and verifies" => 0,
            UNREAD => 1,
            r if r.starts_with("VF") => 2,
            _ => 3,
        };
        let mut best: Option<String> = None;
        for (kind, path) in &jobs {
            let got = post_one(post, path, out, &format!("{name} ({kind})"), &mut broken);
            let stop = got == REFUSES_JET || rank(&got) == 0;
            if best.as_deref().is_none_or(|b| rank(&got) < rank(b)) {
                best = Some(got);
            }
            if stop {
                break;
            }
        }
        (best.unwrap_or_default(), broken)
    });
    let _ = std::fs::remove_dir_all(&tmp);
    let mut table: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut broken = Vec::new();
    for (name, (result, mut wrong)) in runs {
        broken.append(&mut wrong);
        table.entry(result).or_default().push(name);
    }
    let mut summary = String::new();
    for (what, names) in &table {
        summary.push_str(&format!("{:>4}  {what}\n", names.len()));
        if what != REFUSES_JET && what != "refuses milling (its capabilities)" {
            for n in names {
                summary.push_str(&format!("        {n}\n"));
            }
        }
    }
    println!("{summary}");
    assert!(broken.is_empty(), "posts that panic or leave output behind:\n{}", broken.join("\n"));
    let good = table.get("posts and verifies").map_or(0, Vec::len);
    let posting = good + table.get(UNREAD).map_or(0, Vec::len);
    assert!(
        good >= JET_AT_LEAST,
        "{good} corpus Fusion posts post and verify the jet job, fewer than {JET_AT_LEAST}:\n{summary}"
    );
    assert!(
        posting >= JET_POSTING_AT_LEAST,
        "{posting} corpus Fusion posts post the jet job, fewer than {JET_POSTING_AT_LEAST}:\n{summary}"
    );
}

/// The turning job (`corpus/toolpaths/turning/turning_mm.ron`: face, rough and
/// finish a stepped shaft, cut a groove; feeds per revolution, constant
/// surface speed) through the corpus's turning and mill-turn posts (by
/// [`kinds`]): each posts it and verify reads and passes the program (but
/// for findings docs/fusion.md lists as the post's own, [`OWN`]), or says
/// it does not read the dialect, or the post is refused with a diagnostic;
/// none panics or leaves a file behind. The count by outcome is
/// docs/fusion.md's turning table.
#[test]
fn corpus_fusion_turning_posts_post_the_turning_job_or_say_why_not() {
    let dir = shared();
    if !dir.is_dir() {
        support::referee_missing("corpus_fusion_posts", "../shared/corpus/fusion");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("postc-fusion-turning-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temporary folder");
    let job = support::corpus().join("toolpaths/turning/turning_mm.ron");
    let kinds = kinds(&dir);
    let turning: Vec<PathBuf> = posts(&dir)
        .into_iter()
        .filter(|p| {
            let name = p.strip_prefix(&dir).unwrap_or(p).display().to_string().replace(std::path::MAIN_SEPARATOR, "/");
            matches!(kinds.get(&name).copied(), Some("turning" | "mill-turn"))
        })
        .collect();
    let stated = stated_kinds(&dir);
    assert_eq!(
        turning.len(),
        stated.get("turning").copied().unwrap_or(0) + stated.get("mill-turn").copied().unwrap_or(0),
        "the turning and mill-turn posts are not the counts SOURCES.md states"
    );
    let runs = each_post(&turning, &dir, &tmp, |post, name, out| {
        let mut broken = Vec::new();
        let what = format!("{name} (turning)");
        let mut got = post_one(post, &job, out, &what, &mut broken);
        if let Some((.., codes)) = OWN.iter().find(|(p, j, codes)| {
            name.replace(std::path::MAIN_SEPARATOR, "/") == *p && *j == "turning" && codes.contains(&got.as_str())
        }) {
            got = post_warning(post, &job, out, codes, &what, &mut broken);
            if got == "posts and verifies" {
                got = OWN_FINDINGS.to_string();
            }
        }
        (got, broken)
    });
    let _ = std::fs::remove_dir_all(&tmp);
    let mut table: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut broken = Vec::new();
    for (name, (result, mut wrong)) in runs {
        broken.append(&mut wrong);
        table.entry(result).or_default().push(name);
    }
    let mut summary = String::new();
    for (what, names) in &mut table {
        names.sort();
        summary.push_str(&format!("{:>4}  {what}\n", names.len()));
        for n in names.iter() {
            summary.push_str(&format!("        {n}\n"));
        }
    }
    println!("{summary}");
    assert!(broken.is_empty(), "posts that panic or leave output behind:\n{}", broken.join("\n"));
    let count = |what: &str| table.get(what).map_or(0, Vec::len);
    let good = count("posts and verifies") + count(OWN_FINDINGS);
    let posting = good + count(UNREAD);
    assert!(
        good >= TURNING_AT_LEAST,
        "{good} corpus Fusion turning posts post and verify the turning job, fewer than {TURNING_AT_LEAST}:\n{summary}"
    );
    assert!(
        posting >= TURNING_POSTING_AT_LEAST,
        "{posting} corpus Fusion turning posts post the turning job, fewer than {TURNING_POSTING_AT_LEAST}:\n{summary}"
    );
}

/// LinuxCNC's own interpreter is the referee of verify's lathe reading
/// (docs/verify.md, "Lathe programs"): the program `linuxcnc_lathe.cps`
/// writes for the turning job (`G7` diameters, `G18`, `G95`, `G96`) read
/// by `rs274` makes every cut of the toolpath, in order, at the toolpath's
/// radii and Z, its arcs around the toolpath's centres and turning its
/// way; and `postc post` verified the same program.
#[test]
fn rs274_reads_the_linuxcnc_lathe_program_of_the_turning_job_as_the_toolpath() {
    use postc_ir::EventSource;
    use postc_ir::event::{ArcDir, Event};
    use support::rs274::Kind;
    let post = shared().join("85vmh__LinuxCNCFusionPosts/linuxcnc_lathe.cps");
    if !post.is_file() {
        support::referee_missing("fusion_corpus", "../shared/corpus/fusion");
        return;
    }
    let Some(rs274) = support::rs274::find() else { return };
    let job = support::corpus().join("toolpaths/turning/turning_mm.ron");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let out = dir.path().join("turning.ngc");
    let s = |p: &Path| p.to_str().expect("a UTF-8 path").to_string();
    let run = support::postc(&["post", "-q", &s(&post), &s(&job), "-o", &s(&out)]);
    assert!(run.status.success(), "{}", support::said(&run));
    let program = std::fs::read_to_string(&out).expect("the program");
    let moves = support::rs274::run(&rs274, &program).unwrap_or_else(|e| panic!("rs274 refuses the program: {e}"));
    // The toolpath's cuts: end (x radius, z), and for arcs the centre and
    // the turn as rs274 reports it in the XZ plane (+1 counter-clockwise).
    let mut sources = postc_report::source_map();
    let mut events = postc_driver::open_toolpath(&job, &mut sources).expect("the turning job opens");
    let mut cuts = Vec::new();
    let mut diagnostics = Vec::new();
    while let Some((event, _)) = events.next_event(&mut diagnostics) {
        match event {
            Event::Feed(f) => cuts.push(([f.x, f.y, f.z], None)),
            Event::Arc(a) => {
                cuts.push(([a.x, a.y, a.z], Some(([a.cz, a.cx], if a.dir == ArcDir::Ccw { 1 } else { -1 }))))
            }
            _ => {}
        }
    }
    assert!(diagnostics.is_empty() && cuts.len() > 20, "{diagnostics:?}");
    let near = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-3);
    let mut at = 0;
    for (end, arc) in &cuts {
        let found = moves[at..].iter().position(|m| {
            let cut = match (&m.kind, arc) {
                (Kind::Feed, None) => true,
                (Kind::Arc { centre, rotation }, Some((c, r))) => {
                    (centre[0] - c[0]).abs() < 1e-3 && (centre[1] - c[1]).abs() < 1e-3 && rotation == r
                }
                _ => false,
            };
            cut && near(m.end_mm(), *end)
        });
        let Some(i) = found else {
            panic!("rs274 does not make the toolpath's cut to {end:?} ({arc:?}) after its move {at}:\n{program}")
        };
        at += i + 1;
    }
}

/// Verify's lathe reading finds what a wrong lathe program does: the
/// program `linuxcnc_lathe.cps` writes for the turning job verifies, and
/// each fault seeded into it is found with its code: radius mode (`G8`
/// for `G7`: every X half as far out, VF010), a surface speed ten times
/// the toolpath's (VF036), a rough feed per revolution doubled (VF033),
/// an arc turned the other way (VF013).
#[test]
fn verify_finds_faults_seeded_into_a_lathe_program() {
    let post = shared().join("85vmh__LinuxCNCFusionPosts/linuxcnc_lathe.cps");
    if !post.is_file() {
        support::referee_missing("fusion_corpus", "../shared/corpus/fusion");
        return;
    }
    let job = support::corpus().join("toolpaths/turning/turning_mm.ron");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let out = dir.path().join("turning.ngc");
    let s = |p: &Path| p.to_str().expect("a UTF-8 path").to_string();
    let run = support::postc(&["post", "-q", &s(&post), &s(&job), "-o", &s(&out)]);
    assert!(run.status.success(), "{}", support::said(&run));
    let program = std::fs::read_to_string(&out).expect("the program");
    let verify = |text: &str| {
        let path = dir.path().join("seeded.ngc");
        std::fs::write(&path, text).expect("write the program");
        let run = support::postc(&["verify", &s(&path), "--toolpath", &s(&job), "--post", &s(&post)]);
        (run.status.success(), support::said(&run))
    };
    let (ok, said) = verify(&program);
    assert!(ok, "{said}");
    for (fault, from, to, code) in [
        ("radius mode", " G7", " G8", "VF010"),
        ("ten times the surface speed", "G96 D3000 S200 ", "G96 D3000 S2000 ", "VF036"),
        ("the rough feed doubled", "G1 Z-41.5 F0.25", "G1 Z-41.5 F0.5", "VF033"),
        ("an arc turned the other way", "G3 X20. Z-2.", "G2 X20. Z-2.", "VF013"),
    ] {
        assert!(program.contains(from), "{fault}: `{from}` is not in the program:\n{program}");
        let (ok, said) = verify(&program.replacen(from, to, 1));
        assert!(!ok && said.contains(&format!("error[{code}]")), "{fault}: no {code}:\n{said}");
    }
}
