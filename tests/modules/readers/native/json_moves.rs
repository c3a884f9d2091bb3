use postc_ir::Event;
use postc_ir::event::{ArcDir, ArcMove, FeedMove, Intent, Move, Plane};
use postc_reader_native::testing::json_moves::*;

fn serde(line: &str) -> Option<Event> {
    serde_json::from_str::<Event>(line).ok()
}

#[test]
fn reads_what_the_writer_writes() {
    let events = [
        Event::Rapid(Move { x: 1.5, y: -2.0, z: 3.25, a: Some(90.0), ..Move::default() }),
        Event::Feed(FeedMove {
            x: 0.1,
            y: 0.2,
            z: -1.0,
            intent: Intent::Plunge,
            feed: Some(500.0),
            ..FeedMove::default()
        }),
        Event::Feed(FeedMove { x: 46.882499999999936, y: 0.12349999999999985, z: -1.075, ..FeedMove::default() }),
        Event::Arc(ArcMove {
            dir: ArcDir::Ccw,
            x: 1.0,
            y: 2.0,
            z: -0.5,
            cx: 0.5,
            cy: 1.0,
            cz: 0.0,
            plane: Plane::Zx,
            intent: Intent::LeadIn,
            feed: Some(1200.0),
        }),
    ];
    for e in events {
        let mut line = String::new();
        postc_reader_native::write_event(&e, postc_reader_native::Syntax::JsonLines, &mut line);
        let line = line.trim_end();
        assert_eq!(read_move(line.as_bytes()), Some(e), "{line}");
    }
}

#[test]
fn leaves_to_serde_what_it_does_not_read_plainly() {
    for line in [
        r#"{"Rapid":{"x":1,"y":2}}"#,
        r#"{"Rapid":{"x":1,"y":2,"z":3,"x":4}}"#,
        r#"{"Rapid":{"x":1,"y":2,"z":3,"w":4}}"#,
        r#"{"Rapid": {"x":1,"y":2,"z":3}}"#,
        r#"{"Rapid":{"x":01,"y":2,"z":3}}"#,
        r#"{"Rapid":{"x":1.,"y":2,"z":3}}"#,
        r#"{"Rapid":{"x":1e999,"y":2,"z":3}}"#,
        r#"{"Rapid":{"x":1,"y":2,"z":3}} "#,
        r#"{"Rapid":{"x":1,"y":2,"z":3,"tool_axis":[0,0,1]}}"#,
        r#"{"Feed":{"x":1,"y":2,"z":3,"intent":"Sideways"}}"#,
        r#"{"Arc":{"x":1,"y":2,"z":3,"cx":0,"cy":0}}"#,
        r#"{"R\u0061pid":{"x":1,"y":2,"z":3}}"#,
        r#"{"Dwell":{"seconds":1}}"#,
        r#""ToolpathEnd""#,
    ] {
        assert_eq!(read_move(line.as_bytes()), None, "{line}");
    }
}

fn number_text() -> impl proptest::strategy::Strategy<Value = String> {
    use proptest::prelude::*;
    prop_oneof![
        4 => any::<f64>().prop_filter("finite", |x| x.is_finite()).prop_map(|x| format!("{x:?}")),
        2 => any::<i64>().prop_map(|x| x.to_string()),
        1 => any::<u64>().prop_map(|x| x.to_string()),
        3 => "-?(0|[1-9][0-9]{0,25})(\\.[0-9]{1,25})?([eE][+-]?[0-9]{1,3})?",
        // Coordinates as CAM systems write them, and at the edges of exact
        // reading: 19 digits, 2^53 and past it, 22 and 23 decimals.
        4 => "-?(0|[1-9][0-9]{0,5})(\\.[0-9]{1,6})?",
        2 => "-?(0|[1-9][0-9]{0,18})(\\.[0-9]{1,22})?",
        1 => "-?0\\.[0-9]{20,24}",
        1 => prop_oneof![Just("9007199254740992".to_string()), Just("9007199254740993".to_string()), Just("900719925474099.3".to_string()), Just("0.9007199254740993".to_string())],
        1 => Just("-0".to_string()),
        1 => Just("null".to_string()),
        1 => "[-+.0-9eE]{1,8}",
    ]
}

/// The fields of a move line: its required keys, some of its optional
/// ones, now and then an unknown key, a missing or a repeated one.
fn move_line() -> impl proptest::strategy::Strategy<Value = String> {
    use proptest::prelude::*;
    const TAGS: [(&str, &[&str], &[&str]); 3] = [
        ("Rapid", &["x", "y", "z"], &["a", "b", "c", "q"]),
        ("Feed", &["x", "y", "z"], &["intent", "feed", "a", "b", "c", "q"]),
        ("Arc", &["dir", "x", "y", "z", "cx", "cy"], &["cz", "plane", "intent", "feed", "q"]),
    ];
    (0..TAGS.len())
        .prop_flat_map(|t| {
            let (tag, required, optional) = TAGS[t];
            (
                Just(tag),
                Just(required),
                proptest::sample::subsequence(optional, 0..=optional.len()),
                proptest::option::weighted(0.1, 0usize..6),
                proptest::option::weighted(0.1, 0usize..6),
                proptest::collection::vec(number_text(), 12),
                proptest::collection::vec(0usize..4, 12),
                any::<u64>(),
            )
        })
        .prop_map(|(tag, required, optional, missing, repeated, numbers, names, order)| {
            let mut keys: Vec<&str> = required.iter().chain(optional.iter()).copied().collect();
            if let Some(at) = missing.filter(|&at| at < keys.len()) {
                keys.remove(at);
            }
            if let Some(at) = repeated.filter(|&at| at < keys.len()) {
                keys.push(keys[at]);
            }
            // A shuffle from the seed: the serializer's order is not the only one.
            let n = keys.len();
            for i in (1..n).rev() {
                keys.swap(i, (order.rotate_left(i as u32 * 7) % (i as u64 + 1)) as usize);
            }
            let fields: Vec<String> = keys
                .iter()
                .enumerate()
                .map(|(i, &k)| {
                    let value = match k {
                        "intent" => ["\"Cut\"", "\"Plunge\"", "\"LeadOut\"", "1"][names[i]].to_string(),
                        "dir" => ["\"Cw\"", "\"Ccw\"", "\"Cw\"", "\"Up\""][names[i]].to_string(),
                        "plane" => ["\"Xy\"", "\"Zx\"", "\"Yz\"", "null"][names[i]].to_string(),
                        _ => numbers[i].clone(),
                    };
                    format!("\"{k}\":{value}")
                })
                .collect();
            format!("{{\"{tag}\":{{{}}}}}", fields.join(","))
        })
}

proptest::proptest! {
    /// On move lines with keys in any order and any number texts (valid
    /// or not), the fast path reads what serde_json reads, bit for bit,
    /// or leaves the line to it.
    #[test]
    fn agrees_with_serde_json(line in move_line()) {
        if let Some(fast) = read_move(line.as_bytes()) {
            proptest::prop_assert_eq!(format!("{:?}", Some(fast)), format!("{:?}", serde(&line)), "{}", line);
        }
    }
}
