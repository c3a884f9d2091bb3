mod json_moves;

use postc_ir::event::{FeedMove, Move};
use postc_ir::{Diagnostic, Event, EventSource, FileId, SourceMap};
use postc_reader_native::*;
use std::io::BufReader;

/// The events of `text` as read, before ranges and the end are checked:
/// these tests read fragments of toolpaths, and doubles of any size.
fn read(text: &str, syntax: Option<Syntax>) -> (Vec<Event>, Vec<Diagnostic>) {
    let mut sources = SourceMap::new();
    let id = sources.add("t", text);
    let mut reader = NativeReader::new(text.as_bytes(), syntax, id);
    let mut diags = Vec::new();
    let mut events = Vec::new();
    while let Some((e, _)) = reader.next_read(&mut diags) {
        events.push(e);
    }
    (events, diags)
}

/// The events of `text` as a reader gives them out, with their checks.
fn read_checked(text: &str) -> (Vec<Event>, Vec<(&'static str, usize)>) {
    let mut reader = NativeReader::new(text.as_bytes(), None, FileId(0));
    let (mut events, mut diags) = (Vec::new(), Vec::new());
    while let Some((e, _)) = reader.next_event(&mut diags) {
        events.push(e);
    }
    let line = |d: &Diagnostic| {
        let at = d.primary_span().map_or(0, |s| s.start);
        text[..at].matches('\n').count() + 1
    };
    (events, diags.iter().map(|d| (d.code, line(d))).collect())
}

/// Coordinates, feeds and speeds no machine can reach are refused at
/// their line (TP004), in the job's units, in both syntaxes; a feed
/// repeated unchanged is reported once.
#[test]
fn values_out_of_range_are_refused_at_their_line() {
    let ron = "Job(units: Mm)\nRapid(x: 1e308, y: 5, z: 0)\nFeed(x: 1, y: 2, z: 3, feed: -1)\nFeed(x: 2, y: 2, z: 3, feed: -1)\nSpindleOn(speed: 2e6)\nRapid(x: 1, y: 2, z: 3)\nEnd\n";
    let (events, diags) = read_checked(ron);
    assert_eq!(diags, [("TP004", 2), ("TP004", 3), ("TP004", 5)]);
    assert_eq!(events.len(), 7, "the events keep their order; the errors refuse the toolpath");
    let json = "{\"Job\":{\"units\":\"Inch\"}}\n{\"Rapid\":{\"x\":39000,\"y\":0,\"z\":0}}\n{\"Rapid\":{\"x\":40000,\"y\":0,\"z\":0}}\n\"End\"\n";
    let (events, diags) = read_checked(json);
    assert_eq!(diags, [("TP004", 3)], "40,000 inches is over 1 km; 39,000 is not");
    assert_eq!(events.len(), 4);
}

/// A toolpath without its `End` may be cut short (TP005), at its end;
/// one with it is whole.
#[test]
fn a_toolpath_without_end_may_be_cut_short() {
    let whole = "{\"Job\":{}}\n{\"Rapid\":{\"x\":0,\"y\":0,\"z\":5}}\n\"End\"\n";
    assert_eq!(read_checked(whole).1, []);
    let cut = "{\"Job\":{}}\n{\"Rapid\":{\"x\":0,\"y\":0,\"z\":5}}\n{\"Feed\":{\"x\":1,\"y\":0,\"z\":5}}\n";
    assert_eq!(read_checked(cut).1, [("TP005", 4)]);
    assert_eq!(read_checked("Job()\nRapid(x: 0, y: 0, z: 5)").1, [("TP005", 2)]);
}

#[test]
fn ron_and_json_read_the_same_events() {
    let ron = "// a job\nJob(units: Inch)\n\nRapid(x: 1, y: 2, z: 3)\nFeed(x: 1, y: 2, z: -1, intent: Plunge, feed: 5)\nToolpathEnd\n";
    let json = "{\"Job\":{\"units\":\"Inch\"}}\n{\"Rapid\":{\"x\":1,\"y\":2,\"z\":3}}\n{\"Feed\":{\"x\":1,\"y\":2,\"z\":-1,\"intent\":\"Plunge\",\"feed\":5}}\n\"ToolpathEnd\"\n";
    let (a, da) = read(ron, None);
    let (b, db) = read(json, None);
    assert!(da.is_empty() && db.is_empty(), "{da:?} {db:?}");
    assert_eq!(a, b);
    assert_eq!(a[1], Event::Rapid(Move { x: 1.0, y: 2.0, z: 3.0, ..Move::default() }));
    assert!(matches!(a[2], Event::Feed(FeedMove { intent: postc_ir::event::Intent::Plunge, feed: Some(5.0), .. })));
}

/// Move lines read in the input's buffer or copied out of it (a line
/// across the buffer's end, the last line without a newline) read the
/// same events with the same spans.
#[test]
fn lines_across_the_buffer_read_the_same() {
    let text = "{\"Rapid\":{\"x\":1,\"y\":2,\"z\":3}}\r\n  {\"Feed\":{\"x\":1.5,\"y\":2,\"z\":-1,\"intent\":\"Plunge\"}}\n\n{\"Feed\":{\"x\":1,\"y\":2}}\n\"ToolpathEnd\"\n{\"Arc\":{\"dir\":\"Ccw\",\"x\":0,\"y\":0,\"z\":0,\"cx\":1,\"cy\":1}}";
    let read_with = |capacity: usize| {
        let mut reader = NativeReader::new(BufReader::with_capacity(capacity, text.as_bytes()), None, FileId(0));
        let (mut found, mut diags) = (Vec::new(), Vec::new());
        while let Some(e) = reader.next_read(&mut diags) {
            found.push(e);
        }
        (found, diags.iter().map(|d| (d.code, d.labels.first().map(|l| l.span))).collect::<Vec<_>>())
    };
    let whole = read_with(1 << 16);
    assert_eq!(whole.0.len(), 4, "{whole:?}");
    assert_eq!(whole.1.len(), 1, "{whole:?}");
    for capacity in [1, 7, 16, 40, 64] {
        assert_eq!(read_with(capacity), whole, "buffer of {capacity} bytes");
    }
}

#[test]
fn bad_lines_are_reported_and_skipped() {
    let (events, diags) =
        read("Rapid(x: 1, y: 2, z: 3)\nRapid(x: 1, y: 2\nFeed(x: 1, y: 2, z: 0, speed: 3)\nEnd\n", None);
    assert_eq!(events.len(), 2);
    assert_eq!(diags.len(), 2);
    assert!(diags.iter().all(|d| d.code == "TP001"));
}

#[test]
fn written_events_read_back() {
    let events =
        vec![Event::Rapid(Move { x: 1.5, y: -2.0, z: 3.0, a: Some(90.0), ..Move::default() }), Event::ToolpathEnd];
    for syntax in [Syntax::Ron, Syntax::JsonLines] {
        let mut text = String::new();
        for e in &events {
            write_event(e, syntax, &mut text);
        }
        let (back, diags) = read(&text, Some(syntax));
        assert!(diags.is_empty(), "{text}: {diags:?}");
        assert_eq!(back, events, "{text}");
    }
}

/// What a toolpath wrote: `FeedRate`, a placed `Coolant` and a
/// `Tool`'s `load` read in both syntaxes, in the forms
/// docs/toolpath-format.md gives, and write back the same; a bare
/// `Coolant(Flood)` and a `Tool` without `load` write as they always did.
#[test]
fn written_feed_coolant_placement_and_tool_load() {
    use postc_ir::event::{Coolant, CoolantAt, CoolantChange, FeedRate, FeedUnit, Tool, ToolLoad};
    let ron = "FeedRate(value: 0.1, unit: Ipr)\nCoolant(coolant: Flood, at: Now)\nCoolant(Mist)\nTool(number: 3, load: (length_offset: 3))\n";
    let json = "{\"FeedRate\":{\"value\":0.1,\"unit\":\"Ipr\"}}\n{\"Coolant\":{\"coolant\":\"Flood\",\"at\":\"Now\"}}\n{\"Coolant\":\"Mist\"}\n{\"Tool\":{\"number\":3,\"load\":{\"length_offset\":3}}}\n";
    let expected = vec![
        Event::FeedRate(FeedRate { value: 0.1, unit: Some(FeedUnit::Ipr) }),
        Event::Coolant(CoolantChange { coolant: Coolant::Flood, at: Some(CoolantAt::Now) }),
        Event::Coolant(Coolant::Mist.into()),
        Event::Tool(Tool {
            number: 3,
            load: Some(Box::new(ToolLoad { length_offset: Some(3), diameter_offset: None })),
            ..Tool::default()
        }),
    ];
    for (text, syntax) in [(ron, Syntax::Ron), (json, Syntax::JsonLines)] {
        let (events, diags) = read(text, Some(syntax));
        assert!(diags.is_empty(), "{text}: {diags:?}");
        assert_eq!(events, expected, "{text}");
        let mut again = String::new();
        for e in &events {
            write_event(e, syntax, &mut again);
        }
        let (back, diags) = read(&again, Some(syntax));
        assert!(diags.is_empty(), "{again}: {diags:?}");
        assert_eq!(back, expected, "{again}");
    }
    let mut bare = String::new();
    write_event(&Event::Coolant(Coolant::Flood.into()), Syntax::JsonLines, &mut bare);
    write_event(&Event::Tool(Tool { number: 1, ..Tool::default() }), Syntax::JsonLines, &mut bare);
    assert!(bare.starts_with("{\"Coolant\":\"Flood\"}\n") && !bare.contains("load"), "{bare}");
}

/// A lathe's turning tool (`turning: true`) reads in both syntaxes and
/// writes back the same; a tool that does not say is not one, and writes
/// as it always did, without the field.
#[test]
fn a_turning_tool_reads_and_an_old_tool_writes_as_before() {
    use postc_ir::event::Tool;
    let ron = "Tool(number: 2, diameter: 0.8, turning: true)\nTool(number: 3)\n";
    let json = "{\"Tool\":{\"number\":2,\"diameter\":0.8,\"turning\":true}}\n{\"Tool\":{\"number\":3}}\n";
    let expected = vec![
        Event::Tool(Tool { number: 2, diameter: 0.8, turning: true, ..Tool::default() }),
        Event::Tool(Tool { number: 3, ..Tool::default() }),
    ];
    for (text, syntax) in [(ron, Syntax::Ron), (json, Syntax::JsonLines)] {
        let (events, diags) = read(text, Some(syntax));
        assert!(diags.is_empty(), "{text}: {diags:?}");
        assert_eq!(events, expected, "{text}");
        let mut again = String::new();
        for e in &events {
            write_event(e, syntax, &mut again);
        }
        assert_eq!(again.matches("turning").count(), 1, "{again}");
        let (back, diags) = read(&again, Some(syntax));
        assert!(diags.is_empty() && back == expected, "{again}: {diags:?}");
    }
}

/// A JSON number is read as the double nearest to
/// its decimal text, as RON and Rust read it, not the next one.
#[test]
fn json_numbers_are_read_correctly_rounded() {
    let (json, dj) = read("{\"Rapid\":{\"x\":36.207499999999996,\"y\":0,\"z\":0}}\n", None);
    let (ron, dr) = read("Rapid(x: 36.207499999999996, y: 0, z: 0)\n", None);
    assert!(dj.is_empty() && dr.is_empty());
    let x = |e: &Event| match e {
        Event::Rapid(m) => m.x,
        _ => panic!("{e:?}"),
    };
    assert_eq!(x(&json[0]).to_bits(), 36.207499999999996f64.to_bits());
    assert_eq!(x(&json[0]).to_bits(), x(&ron[0]).to_bits());
    assert!(x(&json[0]) < 36.2075);
}

proptest::proptest! {
    /// Any finite double, written as JSON by the writer or as a long
    /// decimal or exponent text, reads back as the same bits as
    /// Rust's own correctly rounded parse of that text.
    #[test]
    fn json_doubles_read_back_exactly(bits in proptest::num::u64::ANY, digits in 0usize..30) {
        let x = f64::from_bits(bits);
        proptest::prop_assume!(x.is_finite());
        let event = Event::Rapid(Move { x, ..Move::default() });
        let mut line = String::new();
        write_event(&event, Syntax::JsonLines, &mut line);
        let (back, diags) = read(&line, Some(Syntax::JsonLines));
        proptest::prop_assert!(diags.is_empty(), "{line}: {diags:?}");
        proptest::prop_assert_eq!(back.len(), 1);
        match &back[0] {
            Event::Rapid(m) => proptest::prop_assert_eq!(m.x.to_bits(), x.to_bits(), "{}", line),
            e => proptest::prop_assert!(false, "{e:?}"),
        }
        for text in [format!("{x:.digits$e}"), format!("{:.digits$}", x.abs().clamp(1e-30, 1e30) * x.signum())] {
            let expected: f64 = text.parse().unwrap();
            let line = format!("{{\"Rapid\":{{\"x\":{text},\"y\":0,\"z\":0}}}}\n");
            let (back, diags) = read(&line, Some(Syntax::JsonLines));
            proptest::prop_assert!(diags.is_empty(), "{line}: {diags:?}");
            match &back[0] {
                Event::Rapid(m) => proptest::prop_assert_eq!(m.x.to_bits(), expected.to_bits(), "{}", line),
                e => proptest::prop_assert!(false, "{e:?}"),
            }
        }
    }
}
