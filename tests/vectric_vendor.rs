//! What programs VCarve itself wrote show about its post engine, where
//! postc's earlier reading of the guides did otherwise (docs/vectric.md,
//! "What VCarve's own programs show"). Each test is one behaviour, on a
//! small post written for it; `tests/vcarve_real.rs` reproduces the real
//! programs of `../shared/vcarve-real/` as a whole.

use crate::support;

use postc_ir::event::{ArcDir, ArcMove, Event, FeedMove, Job, Material, Move, Point, Tool, ToolpathStart, VecSource};
use postc_ir::{FileId, Post, Units};
use postc_runtime::{Finished, Output, RunOptions};

fn run(post: &Post, events: Vec<Event>, options: RunOptions) -> String {
    let mut source = VecSource::new(events, FileId(0));
    match postc_runtime::run(post, &mut source, Output::memory(), options) {
        Ok(report) => match report.output {
            Finished::Memory(parts) => String::from_utf8(parts.concat()).expect("text"),
            _ => unreachable!("a memory run"),
        },
        Err(d) => panic!("posting failed: {d:?}"),
    }
}

fn post(post: &Post, events: Vec<Event>) -> String {
    run(post, events, postc_driver::run_options(post))
}

/// The ShopSabre post's variables and move sections (`../shared/vcarve-real/`).
const SHOPSABRE: &str = "POST_NAME = \"ShopSabre\"\nFILE_EXTENSION = \"tap\"\nUNITS = \"INCHES\"\n\
LINE_ENDING = \"[13][10]\"\n\
VAR FEED_RATE = [F|C|F|1.1]\nVAR X_POSITION = [X|C|X|1.4]\nVAR Y_POSITION = [Y|C|Y|1.4]\n\
VAR Z_POSITION = [Z|C|Z|1.4]\nVAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.4]\nVAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.4]\n\
begin HEADER\n\"G90\"\n[F]\n\
begin RAPID_MOVE\n\"G0 [X] [Y] [Z]\"\n\
begin FIRST_FEED_MOVE\n\"G1 [X] [Y] [Z] [F]\"\n\
begin FEED_MOVE\n\"G1 [X] [Y] [Z]\"\n\
begin FIRST_CW_ARC_MOVE\n\"G2 [X] [Y] [I] [J] [F]\"\n\
begin CW_ARC_MOVE\n\"G2 [X] [Y] [I] [J]\"\n\
begin FOOTER\n\"M5\"\n";

fn inch_job() -> Event {
    Event::Job(Box::new(Job { units: Units::Inch, ..Job::default() }))
}

fn tool(cut_feed: f64) -> Event {
    Event::Tool(Tool { number: 8, spindle_speed: 10_000.0, cut_feed, plunge_feed: 20.0, ..Tool::default() })
}

fn start() -> Event {
    Event::ToolpathStart(ToolpathStart::default())
}

fn rapid(x: f64, y: f64, z: f64) -> Event {
    Event::Rapid(Move { x, y, z, ..Move::default() })
}

fn feed(x: f64, y: f64, z: f64, f: f64) -> Event {
    Event::Feed(FeedMove { x, y, z, feed: Some(f), ..FeedMove::default() })
}

/// The program's lines, line endings kept.
fn lines(program: &str) -> Vec<&str> {
    program.split_inclusive('\n').collect()
}

/// The G0/G1/G2 lines of `moves` posted through the ShopSabre post, as one
/// toolpath of tool 8 in an inch job.
fn shopsabre_moves(moves: Vec<Event>) -> Vec<String> {
    let mut events = vec![inch_job(), tool(62.5), start()];
    events.extend(moves);
    events.push(Event::End);
    let program = post(&support::compile_text("shopsabre.pp", SHOPSABRE), events);
    lines(&program)
        .into_iter()
        .filter(|l| l.starts_with("G0") || l.starts_with("G1") || l.starts_with("G2"))
        .map(String::from)
        .collect()
}

/// `[F]` alone on a line of HEADER, without quotes: VCarve prints the
/// feed (`F62.5` in `LGC 50 Job 1 Board 1.tap`); postc used to ignore the
/// line with PP018.
#[test]
fn a_line_of_variables_without_quotes_prints() {
    let program =
        post(&support::compile_text("shopsabre.pp", SHOPSABRE), vec![inch_job(), tool(62.5), start(), Event::End]);
    assert_eq!(lines(&program)[..2], ["G90\r\n", "F62.5\r\n"], "{program}");
}

/// The first feed move after a rapid prints its feed even when it did not
/// change (`G1   Z-1.5000 F20.0` after every `G0` of the real programs);
/// a feed move after feed or arc moves at the same feed does not.
#[test]
fn the_feed_prints_again_after_a_rapid() {
    let arc = Event::Arc(ArcMove {
        dir: ArcDir::Cw,
        x: 2.0,
        y: 0.0,
        z: -1.5,
        cx: 1.5,
        cy: 0.0,
        feed: Some(60.0),
        ..ArcMove::default()
    });
    let moves = shopsabre_moves(vec![
        rapid(0.75, 4.1314, 0.8),
        feed(0.75, 4.1314, -1.5, 20.0),
        rapid(0.75, 4.1314, 0.8),
        rapid(1.0, 0.0, 0.8),
        feed(1.0, 0.0, -1.5, 20.0),
        feed(1.0, 0.0, -1.5, 60.0),
        arc,
        feed(3.0, 0.0, -1.5, 60.0),
    ]);
    assert_eq!(
        moves,
        [
            "G0 X0.7500 Y4.1314 Z0.8000\r\n",
            "G1   Z-1.5000 F20.0\r\n",
            "G0   Z0.8000\r\n",
            "G0 X1.0000 Y0.0000 \r\n",
            "G1   Z-1.5000 F20.0\r\n",
            "G1    F60.0\r\n",
            "G2 X2.0000  I0.5000 J0.0000 \r\n",
            "G1 X3.0000   \r\n",
        ]
    );
}

/// A `C` word prints when its value changes, not its text: VCarve's
/// drilling rapid `G0 X1.0002 Y19.0701` repeats `X1.0002` (two holes
/// 0.00005 apart), and its 3D rasters repeat words the same way. A value
/// that did not change is still left out.
#[test]
fn on_change_words_compare_values() {
    let moves = shopsabre_moves(vec![
        rapid(1.00019, 17.3513, 0.8),
        feed(1.00019, 17.3513, -0.6, 25.0),
        rapid(1.00019, 17.3513, 0.8),
        rapid(1.00024, 19.0701, 0.8),
        rapid(1.00024, 19.07014, 0.8),
        rapid(1.00024, 19.07014, 0.8),
    ]);
    let rapids: Vec<&String> = moves.iter().filter(|l| l.starts_with("G0")).collect();
    assert_eq!(
        rapids,
        [
            "G0 X1.0002 Y17.3513 Z0.8000\r\n",
            "G0   Z0.8000\r\n",
            "G0 X1.0002 Y19.0701 \r\n",
            "G0  Y19.0701 \r\n",
            "G0   \r\n",
        ]
    );
}

/// An undeclared material label prints with no prefix: VCarve's ShopBot
/// program reads `'Length of material in X = 24.000` (one blank, the
/// post's own); the 2012 Vectric post guide's default `[XMIN|A| |1.3]` gave two.
#[test]
fn undeclared_labels_have_no_prefix() {
    let pp = "POST_NAME = \"sbp\"\nFILE_EXTENSION = \"sbp\"\nUNITS = \"INCHES\"\n\
        begin HEADER\n\"'Length of material in X = [XLENGTH]\"\n\"'Minimum X = [XMIN]\"\n";
    let job = Event::Job(Box::new(Job {
        units: Units::Inch,
        material: Some(Material { min: Point { x: -1.5, y: 0.0, z: -0.75 }, max: Point { x: 22.5, y: 48.0, z: 0.0 } }),
        ..Job::default()
    }));
    let program = post(&support::compile_text("sbp.pp", pp), vec![job, Event::End]);
    assert_eq!(lines(&program)[..2], ["'Length of material in X = 24.000\r\n", "'Minimum X = -1.500\r\n"], "{program}");
}

/// `begin REVISION_COMMENT` (newer stock posts) prints first, before the
/// HEADER, wherever the file has it: `(VECTRIC POST REVISION)` and 32
/// hexadecimal digits, the hash of the post file. postc used to drop the
/// section with PP017.
#[test]
fn the_revision_comment_prints_first() {
    let pp = "POST_NAME = \"rev\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\n\
        begin HEADER\n\"G21\"\n\
        begin REVISION_COMMENT\n\"(VECTRIC POST REVISION)\"\n\"([REVISION])\"\n";
    let program = post(&support::compile_text("rev.pp", pp), vec![Event::Job(Box::default()), Event::End]);
    let hash = postc_front_vectric::revision::revision(pp.as_bytes());
    assert_eq!(hash.len(), 32);
    assert!(hash.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_lowercase()), "{hash}");
    assert_eq!(program, format!("(VECTRIC POST REVISION)\r\n({hash})\r\nG21\r\n"));
}

/// Under `ROTARY_WRAP_Y = "A"` the home position prints its wrapped axis
/// as A, as positions do: VCarve writes `G0X0.000A0.000`.
#[test]
fn the_home_position_of_a_wrapped_axis_prints_the_rotary_letter() {
    let pp = "POST_NAME = \"wrap\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nROTARY_WRAP_Y = \"A\"\n\
        VAR X_HOME_POSITION = [XH|A|X|1.3]\nVAR Y_HOME_POSITION = [YH|A|Y|1.3]\n\
        begin HEADER\n\"G0[XH][YH]\"\n";
    let job = |y: f64| {
        Event::Job(Box::new(Job {
            home: Some(Point { x: 0.0, y, z: 20.0 }),
            wrap_diameter: Some(100.0 / std::f64::consts::PI),
            ..Job::default()
        }))
    };
    let wrap = support::compile_text("wrap.pp", pp);
    assert_eq!(post(&wrap, vec![job(0.0), Event::End]), "G0X0.000A0.000\r\n");
    // A home off zero turns like a position: 25 mm on a 100 mm circumference is 90 degrees.
    assert_eq!(post(&wrap, vec![job(25.0), Event::End]), "G0X0.000A90.000\r\n");
}

/// A small negative value keeps its minus when it rounds to zero: VCarve
/// writes `Z-0.000` and `Y-0.000`; zero itself prints `0.000`.
#[test]
fn a_negative_value_that_rounds_to_zero_keeps_its_minus() {
    let pp = "POST_NAME = \"nz\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nLINE_ENDING = \"[10]\"\n\
        VAR X_POSITION = [X|A|X|1.3]\nVAR Y_POSITION = [Y|A|Y|1.3]\nVAR Z_POSITION = [Z|A|Z|1.3]\n\
        begin RAPID_MOVE\n\"G0[X][Y][Z]\"\n";
    let program = post(
        &support::compile_text("nz.pp", pp),
        vec![Event::Job(Box::default()), start(), rapid(0.0, -0.0004, -0.0001), rapid(-0.0, 0.0004, 0.0), Event::End],
    );
    assert_eq!(program, "G0X0.000Y-0.000Z-0.000\nG0X0.000Y0.000Z0.000\n");
}

/// `[DATE]` with no date from the job or the command line prints the long
/// form VCarve writes: `Tuesday, November 15, 2011`.
#[test]
fn the_date_prints_in_the_long_form() {
    let pp = "POST_NAME = \"date\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nbegin HEADER\n\"( [DATE] )\"\n";
    let post = support::compile_text("date.pp", pp);
    let options = RunOptions { now: Some(1_321_358_400), ..postc_driver::run_options(&post) };
    assert_eq!(run(&post, vec![Event::Job(Box::default()), Event::End], options), "( Tuesday, November 15, 2011 )\r\n");
}

/// A post file with LF line ends writes CR LF when it says nothing else
/// (and when it says `[13][10]`, as the ShopSabre post does): the real
/// programs are CR LF from an LF post.
#[test]
fn an_lf_post_writes_crlf() {
    assert!(!SHOPSABRE.contains('\r'));
    let plain = "POST_NAME = \"lf\"\nFILE_EXTENSION = \"nc\"\nUNITS = \"MM\"\nbegin HEADER\n\"G21\"\n\"G90\"\n";
    assert_eq!(
        post(&support::compile_text("lf.pp", plain), vec![Event::Job(Box::default()), Event::End]),
        "G21\r\nG90\r\n"
    );
}
