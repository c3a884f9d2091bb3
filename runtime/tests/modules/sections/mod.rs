//! Tape splitting, rotary-wrap and modal-memory behaviour of section dispatch.

use postc_ir::FormatId;
use postc_ir::event::{Event, FeedMove, Intent, Move};
use postc_ir::event::{Job, Tool, ToolpathStart, VecSource};
use postc_ir::post::TapeSplitting;
use postc_ir::{FileId, Handler, HandlerKey, NumberFormat, Piece, Post, Stmt, ValueSource, Variable};
use postc_ir::{Quantity, Section};
use postc_runtime::{Finished, Output, RunOptions};

/// A post that prints each section's name and, for moves, Z; split
/// into parts of at most `max` blocks, at a retract once a part has
/// `max - tolerance`.
fn tape_post(max_lines: u64, tolerance: u64) -> Post {
    let mut post = Post::default();
    post.formats.push(NumberFormat { decimals: 0, ..NumberFormat::default() });
    post.variables.push(Variable {
        name: "Z".into(),
        source: ValueSource::Quantity(Quantity::Z),
        prefix: b"Z".to_vec(),
        format: FormatId::new(0),
        modality: postc_ir::Modality::Always,
        span: None,
    });
    post.variables.push(Variable {
        name: "T".into(),
        source: ValueSource::Quantity(Quantity::Tool),
        prefix: b"T".to_vec(),
        format: FormatId::new(0),
        modality: postc_ir::Modality::Always,
        span: None,
    });
    let line = |text: &str, var: Option<u16>| {
        let mut pieces = vec![Piece::Text(text.as_bytes().to_vec())];
        pieces.extend(var.map(|v| Piece::Var(postc_ir::VarId::new(v))));
        Stmt::Line { pieces, span: None }
    };
    for (section, text, var) in [
        (Section::Header, "HEADER ", Some(1)),
        (Section::Footer, "FOOTER ", Some(1)),
        (Section::ToolChange, "TOOLCHANGE ", Some(1)),
        (Section::NewSegment, "NEW_SEGMENT", None),
        (Section::RapidMove, "RAPID ", Some(0)),
        (Section::FeedMove, "FEED ", Some(0)),
    ] {
        post.handlers.push(Handler { key: HandlerKey::Section(section), body: vec![line(text, var)], span: None });
    }
    post.options.tape_splitting = Some(TapeSplitting {
        max_lines,
        tolerance,
        name_format: "%s_%d.nc".into(),
        start_index: 1,
        index_on_first_file: true,
    });
    post
}

fn parts(post: &Post, events: Vec<Event>) -> Vec<String> {
    let mut source = VecSource::new(events, FileId(0));
    let report = postc_runtime::run(post, &mut source, Output::memory(), RunOptions::default())
        .unwrap_or_else(|d| panic!("{d:?}"));
    match report.output {
        Finished::Memory(parts) => parts.into_iter().map(|p| String::from_utf8(p).unwrap()).collect(),
        _ => unreachable!(),
    }
}

/// A pass away from home (so its first rapid is no retract) that ends
/// with a retract.
fn pass(x: f64) -> Vec<Event> {
    vec![
        Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
        Event::Feed(FeedMove { x, y: 0.0, z: -1.0, ..FeedMove::default() }),
        Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
    ]
}

fn tool(number: u32) -> Event {
    Event::Tool(Tool { number, ..Tool::default() })
}

#[test]
fn a_split_due_at_the_last_retract_makes_no_empty_part() {
    let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
    events.extend(pass(1.0));
    events.push(Event::ToolpathEnd);
    events.push(Event::End);
    assert_eq!(parts(&tape_post(4, 2), events), ["HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n"]);
}

#[test]
fn a_split_waits_for_the_next_move_and_restarts_with_the_header() {
    let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
    events.extend(pass(1.0));
    events.extend(pass(2.0));
    events.push(Event::End);
    assert_eq!(
        parts(&tape_post(4, 2), events),
        [
            "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
            "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
        ]
    );
}

#[test]
fn a_split_at_a_tool_change_starts_the_part_like_a_program() {
    let mut events = vec![Event::Job(Box::default()), tool(1), Event::ToolpathStart(ToolpathStart::default())];
    events.extend(pass(1.0));
    events.push(Event::ToolpathEnd);
    events.push(tool(2));
    events.push(Event::ToolpathStart(ToolpathStart::default()));
    events.extend(pass(1.0));
    events.push(Event::End);
    // The old part's footer still has tool 1; the new part's header
    // loads tool 2, with no TOOLCHANGE or NEW_SEGMENT.
    assert_eq!(
        parts(&tape_post(4, 2), events),
        [
            "HEADER T1\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T1\n",
            "HEADER T2\nRAPID Z5\nFEED Z-1\nRAPID Z5\nFOOTER T2\n",
        ]
    );
}

#[test]
fn a_part_ends_only_at_a_retract_that_reaches_safe_z() {
    let job = Job { safe_z: Some(5.0), ..Job::default() };
    let mut events = vec![Event::Job(Box::new(job)), tool(1), Event::ToolpathStart(ToolpathStart::default())];
    for x in [1.0, 2.0] {
        events.extend([
            Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
            Event::Feed(FeedMove { x, y: 0.0, z: -1.0, ..FeedMove::default() }),
            // A feed retract to just above the surface: no split here,
            // or the next part would start with the rapid up alone.
            Event::Feed(FeedMove { x, y: 0.0, z: 0.0, intent: Intent::Retract, ..FeedMove::default() }),
            Event::Rapid(Move { x, y: 0.0, z: 5.0, ..Move::default() }),
        ]);
    }
    events.push(Event::End);
    let pass = "RAPID Z5\nFEED Z-1\nFEED Z0\nRAPID Z5\n";
    assert_eq!(
        parts(&tape_post(6, 3), events),
        [format!("HEADER T1\n{pass}FOOTER T1\n"), format!("HEADER T1\n{pass}FOOTER T1\n")]
    );
}

#[test]
fn a_wrapped_post_warns_when_the_job_has_no_wrap_diameter() {
    let mut post = tape_post(100, 10);
    post.options.rotary_wrap =
        Some(postc_ir::post::RotaryWrap { axis: postc_ir::post::WrappedAxis::Y, letter: Some('A'), reversed: false });
    let run = |job: Job| {
        let events =
            vec![Event::Job(Box::new(job)), tool(1), Event::ToolpathStart(ToolpathStart::default()), Event::End];
        let mut source = VecSource::new(events, FileId(0));
        let report = postc_runtime::run(&post, &mut source, Output::memory(), RunOptions::default())
            .unwrap_or_else(|d| panic!("{d:?}"));
        report.warnings.iter().map(|w| w.code.to_string()).collect::<Vec<_>>()
    };
    assert_eq!(run(Job::default()), ["RT015"]);
    assert!(run(Job { wrap_diameter: Some(40.0), ..Job::default() }).is_empty());
}

/// A post whose moves print `[X]` and `[F]`, both on change, whole numbers.
fn modal_post(by_value: bool, rapid_forgets_feed: bool) -> Post {
    let mut post = Post::default();
    post.formats.push(NumberFormat { decimals: 0, ..NumberFormat::default() });
    for (name, q) in [("X", Quantity::X), ("F", Quantity::Feed)] {
        post.variables.push(Variable {
            name: name.into(),
            source: ValueSource::Quantity(q),
            prefix: name.as_bytes().to_vec(),
            format: FormatId::new(0),
            modality: postc_ir::Modality::OnChange,
            span: None,
        });
    }
    let var = |v: u16| Piece::Var(postc_ir::VarId::new(v));
    for (section, pieces) in [
        (Section::RapidMove, vec![Piece::Text(b"G0".to_vec()), var(0)]),
        (Section::FeedMove, vec![Piece::Text(b"G1".to_vec()), var(0), var(1)]),
    ] {
        post.handlers.push(Handler {
            key: HandlerKey::Section(section),
            body: vec![Stmt::Line { pieces, span: None }],
            span: None,
        });
    }
    post.options.on_change_by_value = by_value;
    post.options.rapid_forgets_feed = rapid_forgets_feed;
    post
}

fn modal_run(post: &Post) -> String {
    let feed = |x: f64| Event::Feed(FeedMove { x, y: 0.0, z: 0.0, feed: Some(100.0), ..FeedMove::default() });
    let events = vec![
        Event::Job(Box::default()),
        tool(1),
        Event::ToolpathStart(ToolpathStart::default()),
        feed(1.0),
        // 1.2 prints `1` as 1.0 does: the value changed, the text did not.
        feed(1.2),
        feed(1.2),
        Event::Rapid(Move { x: 5.0, y: 0.0, z: 0.0, ..Move::default() }),
        feed(6.0),
    ];
    parts(post, events).concat()
}

/// On change by value prints a word whose number changed though its text
/// did not (Vectric); by text it does not (CIMCO, VcPost). An unchanged
/// number prints nothing either way.
#[test]
fn on_change_compares_values_or_text() {
    assert_eq!(modal_run(&modal_post(true, false)), "G1X1F100\nG1X1\nG1\nG0X5\nG1X6\n");
    assert_eq!(modal_run(&modal_post(false, false)), "G1X1F100\nG1\nG1\nG0X5\nG1X6\n");
}

/// A rapid makes the feed forget what it printed when the post says so:
/// the feed move after it prints `F100` again.
#[test]
fn a_rapid_forgets_the_feed_when_asked() {
    assert_eq!(modal_run(&modal_post(true, true)), "G1X1F100\nG1X1\nG1\nG0X5\nG1X6F100\n");
}
