use postc_ir::Units;
use postc_ir::event::{ArcDir, Intent, Plane};
use postc_ir::{Diagnostic, FileId, Span};
use postc_verify::expect::Record;
use postc_verify::expect::RecordSource;
use postc_verify::testing::interp::*;
use postc_verify::{Controller, Move, Observer, Settings};
use proptest::prelude::*;

/// A toolpath handed over at once.
struct Path(Vec<(Record, Span)>);

impl RecordSource for Path {
    fn next_batch(&mut self, batch: &mut Vec<(Record, Span)>, _: &mut Vec<Diagnostic>) -> bool {
        *batch = std::mem::take(&mut self.0);
        !batch.is_empty()
    }
}

/// Every move replayed, as text.
struct Moves(Vec<String>);

impl Observer for Moves {
    fn motion(&mut self, m: &Move) {
        self.0.push(format!("{m:?}"));
    }
}

/// Everything a verification gives: its report and the moves replayed.
fn replayed(program: &str, settings: &Settings, fast: bool) -> String {
    let span = Span::new(FileId(1), 0, 1);
    let moves = [[0.0, 0.0, 5.0], [10.0, 0.0, 5.0], [10.0, 0.0, -1.0], [10.0, 20.0, -1.0], [0.5, 20.0, -1.0]];
    let mut records = vec![
        (
            Record::Job(Box::new(postc_verify::expect::JobRecord {
                units: Units::Mm,
                material: Some(([0.0, 0.0, -20.0], [300.0, 200.0, 0.0])),
                safe_z: Some(5.0),
            })),
            span,
        ),
        (
            Record::Tool { cut_feed: 1500.0, plunge_feed: 500.0, spindle_speed: 18000.0, jet: false, turning: false },
            span,
        ),
        (Record::Rapid { end: moves[0], rotary: false }, span),
    ];
    for end in &moves[1..] {
        records.push((Record::Feed { end: *end, intent: Intent::Cut, feed: None, rotary: false }, span));
    }
    records.push((
        Record::Arc {
            end: [0.5, 21.0, -1.0],
            centre: [0.5, 20.5, -1.0],
            dir: ArcDir::Cw,
            plane: Plane::Xy,
            intent: Intent::Cut,
            feed: None,
        },
        span,
    ));
    let mut moves = Moves(Vec::new());
    let mut reader = std::io::Cursor::new(program.as_bytes());
    let r = replay(&mut reader, FileId(0), &mut Path(records), settings, &mut moves, fast);
    format!("{:?}\n{:?}\n{:?}\n{} {} {:?}\n{:#?}", r.findings, r.at, r.lines, r.errors, r.warnings, r.stats, moves.0)
}

/// Program lines: mostly words as posts print them (the letters verify
/// reads, G and M codes, now and then a letter it does not know or a
/// word twice), blanks, and now and then a comment or bytes only the
/// general path reads.
fn line() -> impl Strategy<Value = String> {
    let letter = prop_oneof![
        8 => proptest::sample::select(b"GXYZFIJKRN".to_vec()),
        2 => proptest::sample::select(b"MSTPQLHDOUVWABCE".to_vec()),
        1 => proptest::sample::select(b"gxyzfmqe".to_vec()),
    ];
    let code = prop_oneof![
        4 => proptest::sample::select(vec!["0", "1", "2", "3", "01", "00"]),
        1 => proptest::sample::select(vec!["17", "18", "20", "21", "90", "91", "81", "80", "28", "53", "4", "6", "117", "117,5", "5", "99"]),
    ]
    .prop_map(String::from);
    let number = (any::<bool>(), 0u64..3_000_000_000, 0usize..5, any::<bool>()).prop_map(|(neg, m, d, comma)| {
        let digits = m.to_string();
        let sign = if neg { "-" } else { "" };
        match d {
            0 => format!("{sign}{digits}"),
            _ if d >= digits.len() => format!("{sign}.{digits}"),
            _ => {
                let (a, b) = digits.split_at(digits.len() - d);
                format!("{sign}{a}{}{b}", if comma { ',' } else { '.' })
            }
        }
    });
    let word = (letter, " {0,1}", prop_oneof![2 => code, 3 => number.clone()])
        .prop_map(|(l, b, n)| format!("{}{b}{n}", l as char));
    // Words of distinct letters with blanks between: lines of words only,
    // long enough for the controllers' block limits.
    let long = proptest::sample::subsequence(b"NGXYZIJKFRS".to_vec(), 1..11)
        .prop_flat_map(move |letters| {
            let n = letters.len();
            (Just(letters), proptest::collection::vec((number.clone(), " {0,25}"), n))
        })
        .prop_map(|(letters, words)| {
            letters.iter().zip(words).map(|(l, (n, b))| format!("{}{n}{b}", *l as char)).collect::<String>()
        });
    let piece = prop_oneof![
        12 => word,
        3 => " {1,2}|\\t|\\r".prop_map(String::from),
        1 => "\\([ -~]{0,6}\\)".prop_map(String::from),
        1 => "[%/:;#\\x00]".prop_map(String::from),
    ];
    // Now and then a line longer than grbl's and LinuxCNC's limits.
    prop_oneof![8 => proptest::collection::vec(piece, 0..7).prop_map(|p| p.concat()), 1 => long]
}

/// The program that makes the test's toolpath, line by line.
const MAKES: [&str; 9] = [
    "G21 G90 G17",
    "M3 S18000",
    "G0 X0 Y0 Z5",
    "G1 X10.0004 F1500",
    "G1 Z-1 F500",
    "N20 G1 Y20. F1500.",
    "g1 x0.500",
    "G2 X0.5 Y21 I0 J0.5",
    "G0 Z5",
];

/// A program: the lines that make the toolpath, in order, with other
/// lines among them.
fn program() -> impl Strategy<Value = String> {
    proptest::collection::vec(prop_oneof![1 => line().prop_map(Some), 1 => Just(None)], 0..30).prop_map(|lines| {
        let mut makes = MAKES.iter();
        let mut text = String::new();
        for line in lines {
            text += line.as_deref().or_else(|| makes.next().copied()).unwrap_or("");
            text.push('\n');
        }
        text
    })
}

fn controller() -> impl Strategy<Value = Controller> {
    proptest::sample::select(vec![Controller::Generic, Controller::Fanuc, Controller::Grbl, Controller::LinuxCnc])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    /// Lines of words read by the fast path replay as the general path
    /// replays them: the same findings, where and on which line, the
    /// same counts and the same moves.
    #[test]
    fn the_words_fast_path_replays_as_the_general_path(
        program in program(),
        controller in controller(),
        units in any::<bool>(),
        numbered in any::<bool>(),
        fine in any::<bool>(),
    ) {
        // A fine tolerance makes the program's own rounding count (the most decimals of its X Y Z words).
        let tolerance = if fine { 0.0001 } else { 0.01 };
        let mut settings = Settings { controller, tolerance, ..Settings::default() };
        if units {
            settings.units = Some(Units::Mm);
            settings.decimals = Some(3);
        }
        if numbered {
            settings.block_start = Some(10.0);
            settings.block_maximum = Some(9999.0);
        }
        prop_assert_eq!(replayed(&program, &settings, true), replayed(&program, &settings, false), "{:?}", program);
    }
}

#[test]
fn tenths_round_as_the_library_does() {
    for code in [0.0, 1.0, 2.0, 91.1, 38.25, 38.35, 0.04, 0.05, -0.05, -1.0, 1e30, -1e30, f64::NAN, 4e8, 4.3e8] {
        assert_eq!(tenths(code), (code * 10.0).round() as u32, "{code}");
    }
}

#[test]
fn lines_of_words_take_the_fast_path() {
    let mut block = Block::default();
    for line in ["G1 X-1.5 Y2. Z.25 F1200\n", "G0X1Y2\r\n", "x 1.0 g2 i.5 j0\n", "\n", "N10 G90 G17 G21\n"] {
        assert_eq!(words_line(line.as_bytes(), &mut block, None), Some(line.len() - 1), "{line:?}");
    }
    for line in ["G1 X1 (cut)\n", "M3 S1000\n", "G1 X1 X2\n", "G1 E5\n", "G1 X1", "/G0 X1\n", "G1 X\n"] {
        assert_eq!(words_line(line.as_bytes(), &mut block, None), None, "{line:?}");
    }
    assert_eq!(words_line(b"G1 X123456789\n", &mut block, Some(8)), None);
    assert_eq!(words_line(b"G1 X12345.678\n", &mut block, Some(8)), Some(13));
}
