//! Vectric fidelity: a word whose value has no source prints
//! nothing, never a number the machine obeys, and arcs of a post that
//! wraps an axis around a cylinder are cut into feed moves (a G2/G3 cannot
//! turn a rotary axis). Real posts of `../shared/corpus/vectric` are used
//! where the corpus holds one; without the corpus those cases print
//! "skipped" and pass.

use crate::support;
use std::path::{Path, PathBuf};

use postc_ir::event::{Event, FeedMove, Intent, Job, Move, Power, Tool, ToolpathStart, VecSource};
use postc_ir::{FileId, Post};
use postc_runtime::{Finished, Output};

fn manifest() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `../shared/corpus/vectric/REL`, when the shared corpus is there.
fn real_post(rel: &str) -> Option<PathBuf> {
    let path = manifest().join("../shared/corpus/vectric").join(rel);
    path.is_file().then_some(path)
}

fn text(parts: Vec<Vec<u8>>) -> String {
    String::from_utf8_lossy(&parts.concat()).into_owned()
}

fn post_file(post: &Post, toolpath: &Path) -> String {
    let mut sources = postc_report::source_map();
    let mut source = postc_driver::open_toolpath(toolpath, &mut sources).expect("open the toolpath");
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => text(parts),
            _ => unreachable!("a memory run"),
        },
        Err(d) => panic!("posting failed: {d:?}"),
    }
}

fn post_events(post: &Post, events: Vec<Event>) -> String {
    let mut source = VecSource::new(events, FileId(0));
    match postc_runtime::run(post, &mut source, Output::memory(), postc_driver::run_options(post)) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => text(parts),
            _ => unreachable!("a memory run"),
        },
        Err(d) => panic!("posting failed: {d:?}"),
    }
}

/// Cutting blocks (G1-G3, or bare coordinates continuing one), block
/// number and blanks dropped.
fn motion_lines(program: &str) -> Vec<String> {
    program
        .lines()
        .map(|l| {
            let l = l.trim();
            let l = l
                .strip_prefix('N')
                .map_or(l, |rest| rest.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start());
            l.replace(' ', "")
        })
        .filter(|l| is_cut(l) || l.starts_with('X') || l.starts_with('Y') || l.starts_with('Z'))
        .collect()
}

/// Whether a block starts with G1, G2 or G3 (not G17, G20, G21, G28...).
fn is_cut(l: &str) -> bool {
    let b = l.as_bytes();
    b.len() >= 2 && b[0] == b'G' && matches!(b[1], b'1' | b'2' | b'3') && !b.get(2).is_some_and(u8::is_ascii_digit)
}

/// Whether a block carries the word `S0` (S followed by a zero value).
fn has_s0(line: &str) -> bool {
    line.match_indices('S').any(|(i, _)| {
        let value: String =
            line[i + 1..].chars().take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-').collect();
        !value.is_empty() && value.parse::<f64>().is_ok_and(|v| v == 0.0)
    })
}

/// Router/laser posts that print `[P]` (prefix `S`) in their cutting moves.
/// The standard job cuts three router toolpaths and one laser toolpath at
/// 80 % then 40 % power.
const POWER_IN_MOVES: &[(&str, &str)] = &[
    ("buildbotics__bbctrl-posts/Buildbotics_mm.pp", "S800"),
    ("blaghislain__onefinity-post-processors/Onefinity (MM).pp", "S800"),
    ("blaghislain__onefinity-post-processors/Onefinity Laser (MM).pp", "S800"),
    ("synthetos__g2/G2Core_mm.pp", "S800"),
    ("synthetos__g2/G2Core_Arcs_mm.pp", "S800"),
    ("neilferreri__V-Carve-PPs/Grbl_mm_TC_wLaser.pp", "S800"),
    ("MakeraInc__CarveraProfiles/Carvera Laser (mm) (!.cnc).pp", "S0.80"),
    ("garrettmc__snapmaker_cnc_post_process/Snapmaker_garrett_laser_mm.pp", ""),
];

#[test]
fn router_cuts_of_real_posts_print_no_power_word() {
    let standard = manifest().join("corpus/toolpaths/standard.ron");
    let mut checked = 0;
    for (rel, laser_word) in POWER_IN_MOVES {
        let Some(path) = real_post(rel) else {
            println!("skipped {rel}: ../shared/corpus not found");
            continue;
        };
        let program = post_file(&support::compile_file(&path), &standard);
        let motion = motion_lines(&program);
        assert!(!motion.is_empty(), "{rel}: no motion blocks in\n{program}");
        let bad: Vec<&String> = motion.iter().filter(|l| has_s0(l)).collect();
        assert!(bad.is_empty(), "{rel}: motion blocks print S0 (spindle speed 0 on the controller):\n{bad:#?}");
        if !laser_word.is_empty() {
            assert!(
                program.contains(laser_word),
                "{rel}: the laser toolpath's power {laser_word} is missing:\n{program}"
            );
        }
        checked += 1;
    }
    println!("{checked} real posts checked");
}

fn laser_post() -> Post {
    support::compile_file(&manifest().join("corpus/posts/vectric/laser_mm.pp"))
}

fn job() -> Event {
    Event::Job(Box::new(Job { home: Some(postc_ir::event::Point { x: 0.0, y: 0.0, z: 20.0 }), ..Job::default() }))
}

fn feed(x: f64) -> Event {
    Event::Feed(FeedMove { x, y: 0.0, z: -1.0, intent: Intent::Cut, ..FeedMove::default() })
}

/// The corpus laser post prints `M4[P]` in JET_TOOL_ON and `[P]` in
/// JET_TOOL_POWER: a jet tool with no power of its own is off (`M4S0`, "M4
/// S0 laser off" as the Snapmaker laser post writes it) until a Power event
/// sets one, never the spindle's last speed; then the power prints.
#[test]
fn a_jet_tool_without_power_prints_power_zero_until_one_is_set() {
    let laser = Tool { number: 3, jet: true, cut_feed: 1000.0, plunge_feed: 500.0, ..Tool::default() };
    let program = post_events(
        &laser_post(),
        vec![
            job(),
            Event::Tool(laser),
            Event::ToolpathStart(ToolpathStart {
                name: "Engrave".into(),
                notes: String::new(),
                ..ToolpathStart::default()
            }),
            Event::Rapid(Move { x: 0.0, y: 0.0, z: 0.0, ..Move::default() }),
            Event::JetOn,
            feed(10.0),
            Event::Power(Power { value: 50.0 }),
            Event::JetOn,
            feed(20.0),
            Event::JetOff,
            Event::End,
        ],
    );
    let lines: Vec<&str> = program.lines().collect();
    let on = lines
        .iter()
        .position(|l| *l == "M4S0")
        .unwrap_or_else(|| panic!("JET_TOOL_ON before any power prints M4S0:\n{program}"));
    // `[P]` is on-change (`C`): JET_TOOL_POWER prints S500, the JET_TOOL_ON after it M4.
    let power = lines
        .iter()
        .position(|l| *l == "S500")
        .unwrap_or_else(|| panic!("the Power event's S500 is missing:\n{program}"));
    assert!(on < power && lines[power + 1] == "M4", "{program}");
}

/// A Power event given while a spindle tool is loaded belongs to that
/// tool; the next spindle tool has no power again.
#[test]
fn power_is_forgotten_when_a_spindle_tool_is_loaded() {
    let Some(path) = real_post("buildbotics__bbctrl-posts/Buildbotics_mm.pp") else {
        println!("skipped: ../shared/corpus not found");
        return;
    };
    let laser = Tool { number: 3, jet: true, power: Some(80.0), cut_feed: 1000.0, ..Tool::default() };
    let mill = Tool { number: 1, spindle_speed: 18000.0, cut_feed: 1000.0, plunge_feed: 300.0, ..Tool::default() };
    let start = |name: &str| {
        Event::ToolpathStart(ToolpathStart { name: name.into(), notes: String::new(), ..ToolpathStart::default() })
    };
    let program = post_events(
        &support::compile_file(&path),
        vec![
            job(),
            Event::Tool(laser),
            start("Laser"),
            Event::Rapid(Move { x: 0.0, y: 0.0, z: 0.0, ..Move::default() }),
            feed(10.0),
            Event::Tool(mill),
            start("Pocket"),
            Event::Rapid(Move { x: 0.0, y: 0.0, z: 5.0, ..Move::default() }),
            feed(20.0),
            Event::End,
        ],
    );
    let motion = motion_lines(&program);
    assert!(motion.iter().any(|l| l.contains("S800")), "the laser cut prints its power:\n{program}");
    let after_change = program.split("T1").nth(1).expect("a tool change to T1");
    assert!(!after_change.contains("S800"), "the mill's cuts must not carry the laser's power:\n{after_change}");
    assert!(!motion.iter().any(|l| has_s0(l)), "no S0 in motion blocks:\n{program}");
}

/// `[A]` of a post that does not wrap an axis prints the A position the
/// toolpath gave, and nothing before it gives one (an `A0` would turn the
/// rotary axis back to zero).
#[test]
fn a_prints_nothing_before_the_toolpath_sets_it() {
    let post = support::compile_file(&manifest().join("corpus/posts/vectric/text_output_mm.pp"));
    let mill = Tool { number: 1, spindle_speed: 18000.0, cut_feed: 1000.0, plunge_feed: 300.0, ..Tool::default() };
    let program = post_events(
        &post,
        vec![
            job(),
            Event::Tool(mill),
            Event::ToolpathStart(ToolpathStart::default()),
            Event::Rapid(Move { x: 1.0, y: 0.0, z: 5.0, ..Move::default() }),
            Event::Rapid(Move { x: 2.0, y: 0.0, z: 5.0, a: Some(90.0), ..Move::default() }),
            Event::End,
        ],
    );
    let rapids: Vec<&str> = program.lines().filter(|l| l.contains("RAPID_MOVE")).collect();
    assert_eq!(rapids.len(), 2, "{program}");
    assert!(rapids[0].ends_with(" A "), "A before any A position: {:?}", rapids[0]);
    assert!(rapids[1].ends_with(" A 90.000"), "A after the toolpath set it: {:?}", rapids[1]);
}

/// `[UNITS]` prints the guides' words for the UNITS statement: MM or INCHES.
#[test]
fn units_print_mm_or_inches() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let pp = dir.path().join("units.pp");
    std::fs::write(
        &pp,
        "POST_NAME = \"units\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"INCHES\"\nbegin HEADER\n\"([UNITS])\"\n",
    )
    .unwrap();
    let program = post_events(&support::compile_file(&pp), vec![job(), Event::End]);
    assert_eq!(program.lines().next(), Some("(INCHES)"), "{program}");
}

/// A real wrapping post with arc sections (Carvera Wrap X2A: ROTARY_WRAP_Y
/// = "-A", G2/G3 sections): the standard job's arcs (wrap diameter 50) are
/// cut into G1 moves; no G2/G3 carries the A axis.
#[test]
fn wrapped_arcs_of_a_real_post_are_linearized() {
    let Some(path) = real_post("MakeraInc__CarveraProfiles/Carvera Wrap X2A ATC (mm) (!.cnc).pp") else {
        println!("skipped: ../shared/corpus not found");
        return;
    };
    let program = post_file(&support::compile_file(&path), &manifest().join("corpus/toolpaths/standard.ron"));
    let arcs: Vec<&str> = program.lines().filter(|l| is_cut(l) && !l.starts_with("G1")).collect();
    assert!(arcs.is_empty(), "wrapped arcs must be linearized, found:\n{}", arcs.join("\n"));
    assert!(
        program.lines().any(|l| l.contains('A') && (l.starts_with("G1") || l.starts_with('X') || l.starts_with('A'))),
        "{program}"
    );
}

/// The same with the corpus's own wrapping post given arc sections: every
/// chord of a linearized arc ends on the arc (the angle turned back into a
/// length on the cylinder).
#[test]
fn wrapped_arc_chords_lie_on_the_arc() {
    let source = std::fs::read_to_string(manifest().join("corpus/posts/vectric/rotary_wrap_mm.pp")).unwrap();
    let with_arcs = format!(
        "{source}\nVAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.3]\nVAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.3]\nbegin CW_ARC_MOVE\n\"G2[X][Y][I][J][FI]\"\nbegin CCW_ARC_MOVE\n\"G3[X][Y][I][J][FI]\"\n"
    );
    let dir = tempfile::tempdir().expect("a temporary folder");
    let pp = dir.path().join("wrap_arcs.pp");
    std::fs::write(&pp, with_arcs).unwrap();
    let post = support::compile_file(&pp);
    let diameter = 40.0;
    let events = vec![
        Event::Job(Box::new(Job {
            wrap_diameter: Some(diameter),
            home: Some(postc_ir::event::Point { x: 0.0, y: 0.0, z: 20.0 }),
            ..Job::default()
        })),
        Event::Tool(Tool { number: 1, spindle_speed: 10000.0, cut_feed: 600.0, plunge_feed: 200.0, ..Tool::default() }),
        Event::ToolpathStart(ToolpathStart::default()),
        Event::Rapid(Move { x: 20.0, y: 10.0, z: 1.0, ..Move::default() }),
        Event::Feed(FeedMove { x: 20.0, y: 10.0, z: -1.0, intent: Intent::Plunge, ..FeedMove::default() }),
        Event::Arc(postc_ir::event::ArcMove {
            dir: postc_ir::event::ArcDir::Ccw,
            x: 10.0,
            y: 20.0,
            z: -1.0,
            cx: 10.0,
            cy: 10.0,
            cz: -1.0,
            ..postc_ir::event::ArcMove::default()
        }),
        Event::End,
    ];
    let program = post_events(&post, events);
    assert!(!program.lines().any(|l| is_cut(l) && !l.starts_with("G1")), "{program}");
    // ROTARY_WRAP_Y = "-A": Y prints as A = -Y / (pi d) * 360.
    let mut chords = 0;
    for line in program.lines().filter(|l| l.starts_with("G1")) {
        let word = |letter: char| {
            line.find(letter).map(|i| {
                line[i + 1..]
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
                    .collect::<String>()
                    .parse::<f64>()
                    .unwrap()
            })
        };
        let (Some(x), Some(a)) = (word('X'), word('A')) else { continue };
        let y = -a / 360.0 * std::f64::consts::PI * diameter;
        let r = ((x - 10.0).powi(2) + (y - 10.0).powi(2)).sqrt();
        assert!((r - 10.0).abs() < 0.01, "chord end {x},{y} is off the arc (radius {r}): {line}");
        chords += 1;
    }
    assert!(chords > 4, "the quarter arc of radius 10 needs several chords:\n{program}");
}

/// A Vectric post with a Lua `SCRIPT` block posts, its Lua lines skipped
/// with RT003 (docs/vectric.md). Before the script host was chosen by the
/// scripts' language, the runtime compiled the Lua as Rhai and stopped
/// with RT022 ("a bug in postc").
#[test]
fn lua_scripts_are_kept_and_not_run() {
    let pp = "POST_NAME = \"lua\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nLINE_ENDING = \"[10]\"\n\
        VAR X_POSITION = [X|C|X|1.3]\nVAR Y_POSITION = [Y|C|Y|1.3]\nVAR Z_POSITION = [Z|C|Z|1.3]\n\
        begin HEADER\n\"%\"\n\"<!>Hello()\"\nbegin RAPID_MOVE\n\"G0[X][Y][Z]\"\nbegin FEED_MOVE\n\"G1[X][Y][Z]\"\n\
        begin FOOTER\n\"%\"\nSCRIPT\nfunction Hello()\n  return \"x\"\nend\nENDSCRIPT\n";
    let mut sources = postc_report::source_map();
    let compiled = postc_driver::compile_post_bytes(Path::new("lua.pp"), pp.as_bytes(), None, &mut sources);
    let post = compiled.post.expect("a compiled post");
    assert!(!post.scripts.is_empty() && postc_driver::script_host(&post).is_none());
    let toolpath = manifest().join("corpus/toolpaths/arcs_mm.ron");
    let mut source = postc_driver::open_toolpath(&toolpath, &mut sources).expect("open the toolpath");
    let report = postc_runtime::run(&post, &mut source, Output::memory(), postc_driver::run_options(&post))
        .expect("the post runs");
    assert!(report.warnings.iter().any(|w| w.code == "RT003"), "{:?}", report.warnings);
    let Finished::Memory(parts) = report.output else { unreachable!("a memory run") };
    assert!(text(parts).starts_with("%\n"));
}
