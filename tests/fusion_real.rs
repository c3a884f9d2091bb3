//! Autodesk's own post engine as the reference for Fusion posts:
//! `../shared/fusion-real/fanuc-debug-trace.nc` is the engine's
//! `--debugall` run of `fanuc.cps` (Autodesk/cam-posteditor, MIT): every
//! entry-point call with its arguments (`!DEBUG: command:{...}`)
//! interleaved with the program it wrote. This test rebuilds the toolpath
//! from the recorded calls (one toolpath per `onSection`, the tool from
//! its `operation:tool_*` parameters, moves from `onRapid`, `onLinear`
//! and the arc calls, cutter compensation from the moves' flags), posts
//! `fanuc.cps` over it with postc, and compares the program with the
//! engine's line by line. The block numbers are compared as a sequence
//! of their own (the post numbers in steps of 5); every other difference
//! is listed in [`KNOWN`] with its reason, and any other fails the test.

use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::support;

/// The parameter names of the trace carry CIMCO's namespace.
const NAMESPACE: &str = "http://www.cimco-software.com/namespace/nc/parameter/";

/// Differences between the engine's program (`-`) and postc's (`+`), block
/// numbers left out, with the reason each is not postc's fault or what
/// postc lacks.
const KNOWN: &[(&str, &str)] = &[(
    "-(T1 D=50.8 CR=0. - ZMIN=0. - FACE MILL)\n+(T1 D=50.8 CR=0. - ZMIN=0. - FLAT END MILL)",
    "the first tool's kind in the tool table of `onOpen`, a rebuilding artefact: postc's toolpaths carry no tool kind, and the host takes it from the tool's name (docs/fusion.md, choice 12), `myTool1` in the trace",
)];

fn real() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/fusion-real")
}

/// A number as RON reads it back exactly.
fn num(v: &Value) -> String {
    format!("{:?}", v.as_f64().expect("a number"))
}

fn point(p: &Value) -> String {
    format!("x:{},y:{},z:{}", num(&p["x"]), num(&p["y"]), num(&p["z"]))
}

fn text(v: &Value) -> String {
    serde_json::to_string(v.as_str().unwrap_or_default()).expect("a JSON string")
}

/// The toolpath of the recorded calls, as postc's RON events.
fn rebuild(trace: &str) -> String {
    let mut params = serde_json::Map::new();
    let mut events: Vec<String> = Vec::new();
    let (mut tool, mut comp, mut coolant) = (None, "Off", String::new());
    let mut stock = None;
    let mut pos = [0.0f64; 3];
    for line in trace.lines() {
        let Some(json) = line.strip_prefix("!DEBUG: command:") else { continue };
        let call: Value = serde_json::from_str(json).expect("a JSON command");
        let args = &call["args"];
        match call["name"].as_str().expect("a call name") {
            "onParameter" => {
                let name = args["name"].as_str().expect("a parameter name");
                params.insert(name.trim_start_matches(NAMESPACE).to_string(), args["value"].clone());
            }
            "onSection" => {
                if stock.is_none() {
                    let at = |k: &str| num(&params[k]);
                    stock = Some(format!(
                        "(min:(x:{},y:{},z:{}),max:(x:{},y:{},z:{}))",
                        at("stock-lower-x"),
                        at("stock-lower-y"),
                        at("stock-lower-z"),
                        at("stock-upper-x"),
                        at("stock-upper-y"),
                        at("stock-upper-z")
                    ));
                }
                let number = params["operation:tool_number"].as_u64().expect("a tool number");
                if tool != Some(number) {
                    tool = Some(number);
                    events.push(format!(
                        "Tool(number:{number},name:{},notes:{},diameter:{},spindle_speed:{},cut_feed:{},plunge_feed:{})",
                        text(&params["operation:tool_description"]),
                        text(&params["operation:tool_comment"]),
                        num(&params["operation:tool_diameter"]),
                        num(&params["operation:tool_spindleSpeed"]),
                        num(&params["operation:tool_feedCutting"]),
                        num(&params["operation:tool_feedPlunge"]),
                    ));
                }
                // The operation's notes, handed before the sections of operations that have them.
                let notes = params.remove("notes").unwrap_or_else(|| serde_json::Value::String(String::new()));
                events.push(format!(
                    "ToolpathStart(name:{},notes:{})",
                    text(&params["operation-comment"]),
                    text(&notes)
                ));
                let wanted = params["operation:tool_coolant"].as_str().unwrap_or("disabled").to_string();
                if wanted != coolant {
                    let kind = match wanted.as_str() {
                        "flood" => "Flood",
                        "mist" => "Mist",
                        "through tool" => "Through",
                        "air" => "Air",
                        _ => "Off",
                    };
                    events.push(format!("Coolant({kind})"));
                    coolant = wanted;
                }
            }
            name @ ("onRapid" | "onLinear" | "onCWArc" | "onCCWArc" | "onCCWCircle" | "onCWCircle" | "onCircular") => {
                let flags = args["flags"].as_u64().unwrap_or(0);
                // Bits 7 and 8 of a move's flags: compensation left, right.
                let side = if flags & 0x80 != 0 {
                    "Left"
                } else if flags & 0x100 != 0 {
                    "Right"
                } else {
                    "Off"
                };
                if side != comp && name != "onRapid" {
                    comp = side;
                    events.push(format!("CutterComp(side:{side})"));
                }
                // The high half of the flags is the movement: 10 plunge, 1 lead-in, 3 lead-out.
                let intent = match flags >> 16 {
                    10 => ",intent:Plunge",
                    1 => ",intent:LeadIn",
                    3 => ",intent:LeadOut",
                    _ => "",
                };
                let end = &args["end"];
                let end_at =
                    [end["x"].as_f64(), end["y"].as_f64(), end["z"].as_f64()].map(|v| v.expect("a coordinate"));
                match name {
                    "onRapid" => events.push(format!("Rapid({})", point(end))),
                    "onLinear" => events.push(format!("Feed({}{intent},feed:{})", point(end), num(&args["feedrate"]))),
                    _ => {
                        let normal = &args["normal"];
                        let axis = |k: &str| normal[k].as_f64().unwrap_or(0.0);
                        let (plane, sign) = if axis("z").abs() > 0.5 {
                            ("Xy", axis("z"))
                        } else if axis("y").abs() > 0.5 {
                            ("Zx", axis("y"))
                        } else {
                            ("Yz", axis("x"))
                        };
                        let sweep = args["sweep"].as_f64();
                        let mut cw = matches!(name, "onCWArc" | "onCWCircle") || sweep.is_some_and(|s| s < 0.0);
                        if sign < 0.0 {
                            cw = !cw;
                        }
                        let dir = if cw { "Cw" } else { "Ccw" };
                        let c = &args["center"];
                        // A helix of whole turns (`onCircular` with a sweep
                        // over 2 pi) is one event per turn.
                        let turns = sweep.map_or(1.0, |s| (s.abs() / std::f64::consts::TAU).round().max(1.0));
                        for k in 1..=turns as u32 {
                            let f = f64::from(k) / turns;
                            let z = pos[2] + (end_at[2] - pos[2]) * f;
                            events.push(format!(
                                "Arc(dir:{dir},x:{},y:{},z:{},cx:{},cy:{},cz:{},plane:{plane}{intent},feed:{})",
                                num(&end["x"]),
                                num(&end["y"]),
                                if turns > 1.0 { format!("{z:?}") } else { num(&end["z"]) },
                                num(&c["x"]),
                                num(&c["y"]),
                                num(&c["z"]),
                                num(&args["feedrate"]),
                            ));
                        }
                    }
                }
                pos = end_at;
            }
            "onSectionEnd" => events.push("ToolpathEnd".into()),
            "onClose" => events.push("End".into()),
            "onOpen" | "onContext" | "onTool" => {}
            other => panic!("the trace calls `{other}`, which this rebuilding does not know"),
        }
    }
    let stock = stock.expect("the trace has a section");
    format!("Job(units:Mm,material:{stock})\n{}\n", events.join("\n"))
}

/// A block's number and the rest of its line.
fn split_number(line: &str) -> (Option<u64>, &str) {
    if let Some(rest) = line.strip_prefix('N') {
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        if digits > 0 {
            let n = rest[..digits].parse().ok();
            return (n, rest[digits..].trim_start());
        }
    }
    (None, line)
}

/// The differences of two programs without their block numbers, as
/// groups of removed (`-`) and added (`+`) lines.
fn differences(want: &[&str], got: &[&str]) -> Vec<String> {
    let (n, m) = (want.len(), got.len());
    let mut lcs = vec![vec![0usize; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            lcs[i][j] = if want[i] == got[j] { lcs[i + 1][j + 1] + 1 } else { lcs[i + 1][j].max(lcs[i][j + 1]) };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut hunks = Vec::new();
    let mut hunk: Vec<String> = Vec::new();
    while i < n || j < m {
        if i < n && j < m && want[i] == got[j] {
            if !hunk.is_empty() {
                hunks.push(hunk.join("\n"));
                hunk.clear();
            }
            i += 1;
            j += 1;
        } else if j < m && (i == n || lcs[i][j + 1] >= lcs[i + 1][j]) {
            hunk.push(format!("+{}", got[j]));
            j += 1;
        } else {
            hunk.push(format!("-{}", want[i]));
            i += 1;
        }
    }
    if !hunk.is_empty() {
        hunks.push(hunk.join("\n"));
    }
    // A group's removed lines first, as the known list writes them.
    hunks
        .into_iter()
        .map(|h| {
            let (minus, plus): (Vec<&str>, Vec<&str>) = h.lines().partition(|l| l.starts_with('-'));
            minus.into_iter().chain(plus).collect::<Vec<_>>().join("\n")
        })
        .collect()
}

#[test]
fn fanuc_post_reproduces_autodesks_debug_trace_line_for_line() {
    let dir = real();
    if !dir.is_dir() {
        support::referee_missing("fusion_real", "../shared/fusion-real");
        return;
    }
    let trace = std::fs::read_to_string(dir.join("fanuc-debug-trace.nc")).expect("the trace");
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let toolpath = tmp.path().join("trace.ron");
    std::fs::write(&toolpath, rebuild(&trace)).expect("write the toolpath");
    // The program number is the output file's name (docs/fusion.md, choice 9).
    let program = tmp.path().join("0123.nc");
    let run = support::postc(&[
        "post",
        "-q",
        "--no-verify",
        dir.join("fanuc.cps").to_str().expect("UTF-8"),
        toolpath.to_str().expect("UTF-8"),
        "-o",
        program.to_str().expect("UTF-8"),
    ]);
    assert!(run.status.success(), "postc did not post the rebuilt toolpath: {}", support::said(&run));
    let got = std::fs::read_to_string(&program).expect("the program");
    let want: String = trace.lines().filter(|l| !l.starts_with("!DEBUG")).map(|l| format!("{l}\n")).collect();
    // Autodesk's engine ends lines with CR LF on Windows, as postc does.
    assert!(got.ends_with("\r\n"), "postc's program does not end its lines with CR LF");
    let (want, got): (Vec<&str>, Vec<&str>) = (want.lines().collect(), got.lines().collect());
    let numbers = |lines: &[&str]| lines.iter().filter_map(|l| split_number(l).0).collect::<Vec<_>>();
    for numbers in [numbers(&want), numbers(&got)] {
        assert!(numbers.windows(2).all(|w| w[1] == w[0] + 5), "block numbers do not count up by 5: {numbers:?}");
        assert_eq!(numbers.first(), Some(&10));
    }
    let strip = |lines: &[&str]| lines.iter().map(|l| split_number(l).1.to_string()).collect::<Vec<_>>();
    let (want, got) = (strip(&want), strip(&got));
    let (want, got): (Vec<&str>, Vec<&str>) =
        (want.iter().map(String::as_str).collect(), got.iter().map(String::as_str).collect());
    let found = differences(&want, &got);
    let unknown: Vec<&String> = found.iter().filter(|d| !KNOWN.iter().any(|(k, _)| k == d)).collect();
    let gone: Vec<&str> = KNOWN.iter().filter(|(k, _)| !found.iter().any(|d| d == k)).map(|(k, _)| *k).collect();
    assert!(
        unknown.is_empty() && gone.is_empty(),
        "differences from Autodesk's program not listed as known:\n{}\n\nknown differences that no longer occur (remove them from KNOWN):\n{}",
        unknown.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n--\n"),
        gone.join("\n--\n"),
    );
    println!(
        "{} lines of Autodesk's program; {} differ, each listed in KNOWN with its reason",
        want.len(),
        found.iter().map(|d| d.lines().filter(|l| l.starts_with('-')).count()).sum::<usize>()
    );
}
