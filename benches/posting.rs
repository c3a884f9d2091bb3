//! End-to-end posting throughput: postc running a Vectric G-code post over
//! a synthetic toolpath, against a hand-written Rust formatter that prints
//! the same text (checked byte for byte before anything is timed).
//!
//! The quality bar: 10 million moves per second or more on one core, and at
//! least 0.8 of the hand-written formatter's speed.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use postc_ir::event::{Event, Intent};
use postc_ir::{EventSource, Post};
use postc_reader_synthetic::Synthetic;
use postc_runtime::{Finished, Output, run};

/// The post both sides print: G0/G1 moves, modal X Y Z and F.
const POST: &str = r#"
POST_NAME = "bench G-code (mm)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[10]"
VAR FEED_RATE = [F|C|F|1.1]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
begin RAPID_MOVE
"G0[X][Y][Z]"
begin FIRST_FEED_MOVE
"G1[X][Y][Z][F]"
begin FEED_MOVE
"G1[X][Y][Z]"
"#;

fn post() -> Post {
    let mut sources = postc_report::source_map();
    let (post, diagnostics) =
        postc_front_vectric::compile(std::path::Path::new("bench.pp"), POST.as_bytes(), &mut sources);
    assert!(!postc_ir::diagnostic::has_errors(&diagnostics), "{diagnostics:?}");
    post
}

fn postc_text(post: &Post, moves: u64, out: Output) -> Option<Vec<u8>> {
    let mut source = Synthetic::new("zigzag", moves).unwrap();
    match run(post, &mut source, out, postc_driver::run_options(post)).ok()?.output {
        Finished::Memory(parts) => Some(parts.concat()),
        _ => None,
    }
}

/// The hand-written formatter: what a programmer would write to print this
/// one post's text as fast as possible, with the same exact rounding.
mod hand {
    use super::*;

    fn round(v: f64, scale: f64) -> (bool, u64) {
        let a = v.abs() * scale;
        let floor = a as u64;
        let frac = a - floor as f64;
        let up = if (frac - 0.5).abs() > 8.0 * f64::EPSILON * a.max(1.0) {
            frac > 0.5
        } else {
            v.abs() >= (2 * floor + 1) as f64 / (2.0 * scale)
        };
        let m = floor + u64::from(up);
        // Vectric keeps the minus of a negative value that rounds to zero.
        (v < 0.0, m)
    }

    fn put(out: &mut Vec<u8>, letter: u8, (neg, m): (bool, u64), decimals: usize) {
        let mut buf = [0u8; 32];
        let mut i = buf.len();
        let mut m = m;
        for _ in 0..decimals {
            i -= 1;
            buf[i] = b'0' + (m % 10) as u8;
            m /= 10;
        }
        i -= 1;
        buf[i] = b'.';
        loop {
            i -= 1;
            buf[i] = b'0' + (m % 10) as u8;
            m /= 10;
            if m == 0 {
                break;
            }
        }
        if neg {
            i -= 1;
            buf[i] = b'-';
        }
        i -= 1;
        buf[i] = letter;
        out.extend_from_slice(&buf[i..]);
    }

    /// Prints the moves of the synthetic toolpath as the bench post does,
    /// under Vectric's rules (docs/vectric.md): a modal word prints when
    /// its value changes, and the feed prints again after a rapid.
    pub fn print(moves: u64, out: &mut Vec<u8>, sink: &mut impl FnMut(&mut Vec<u8>)) {
        let mut source = Synthetic::new("zigzag", moves).unwrap();
        let mut diags = Vec::new();
        // The value each word printed last; NaN: none since it was forgotten.
        let mut last = [f64::NAN; 4];
        let (mut cut, mut plunge) = (0.0, 0.0);
        let mut last_feed = f64::NAN;
        let mut feed_run = false;
        let mut pos = [0.0f64; 3];
        while let Some((event, _)) = source.next_event(&mut diags) {
            let (target, rapid, feed) = match event {
                Event::Tool(t) => {
                    cut = t.cut_feed;
                    plunge = t.plunge_feed;
                    continue;
                }
                Event::ToolpathStart(_) => {
                    last = [f64::NAN; 4];
                    last_feed = f64::NAN;
                    feed_run = false;
                    continue;
                }
                Event::Rapid(m) => ([m.x, m.y, m.z], true, 0.0),
                Event::Feed(m) => {
                    let plunging = m.intent == Intent::Plunge || (m.x == pos[0] && m.y == pos[1] && m.z < pos[2]);
                    ([m.x, m.y, m.z], false, m.feed.unwrap_or(if plunging { plunge } else { cut }))
                }
                _ => continue,
            };
            pos = target;
            let first = !rapid && (!feed_run || feed != last_feed);
            out.extend_from_slice(if rapid { b"G0" } else { b"G1" });
            for (axis, letter) in [b'X', b'Y', b'Z'].into_iter().enumerate() {
                if last[axis] != target[axis] {
                    last[axis] = target[axis];
                    put(out, letter, round(target[axis], 1000.0), 3);
                }
            }
            if first && last[3] != feed {
                last[3] = feed;
                put(out, b'F', round(feed, 10.0), 1);
            }
            out.push(b'\n');
            if rapid {
                feed_run = false;
                last[3] = f64::NAN;
            } else {
                feed_run = true;
                last_feed = feed;
            }
            if out.len() >= 1 << 16 {
                sink(out);
                out.clear();
            }
        }
        sink(out);
    }
}

fn same_text() {
    let post = post();
    let ours = postc_text(&post, 20_000, Output::memory()).expect("postc posts the bench toolpath");
    let mut theirs = Vec::new();
    let mut all = Vec::new();
    hand::print(20_000, &mut theirs, &mut |b: &mut Vec<u8>| all.extend_from_slice(b));
    assert!(ours == all, "postc and the hand-written formatter print different text");
}

fn bench(c: &mut Criterion) {
    same_text();
    let post = post();
    let moves = 1_000_000u64;
    let mut group = c.benchmark_group("posting");
    group.sample_size(10);
    group.throughput(Throughput::Elements(moves));
    group.bench_with_input(BenchmarkId::new("postc", moves), &moves, |b, &n| {
        b.iter(|| postc_text(&post, n, Output::discard()));
    });
    group.bench_with_input(BenchmarkId::new("hand-written", moves), &moves, |b, &n| {
        b.iter(|| {
            let mut buf = Vec::with_capacity(1 << 17);
            let mut bytes = 0usize;
            hand::print(n, &mut buf, &mut |b: &mut Vec<u8>| bytes += b.len());
            bytes
        });
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
