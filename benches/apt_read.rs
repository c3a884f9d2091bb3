//! APT CL read throughput: the reader over a large synthetic CL file built
//! in memory by repeating the corpus's largest SolidWorks file (`boss.apt`,
//! 9814 GOTO, 1026 CIRCLE) and NX's `ust_a2.cls` (5-axis, 20057 GOTO), or
//! a generated CL text when the shared corpus is absent. The target is
//! 100 MB/s or more on one core (release).
//!
//! Needs `postc-reader-apt` in the root `[dev-dependencies]`.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use postc_ir::diagnostic::FileId;
use postc_ir::event::EventSource;
use postc_reader_apt::AptReader;

/// About this many bytes of CL text per benchmark input.
const TARGET_BYTES: usize = 64 << 20;

/// A generated stand-in for a real file: moves, arcs and feed changes.
fn generated() -> Vec<u8> {
    let mut text =
        String::from("PARTNO/BENCH\nUNITS/MM\nLOADTL/1\nCUTTER/6.\nSPINDL/12000,RPM,CLW\nRAPID\nGOTO/0,0,25.\n");
    for i in 0..10_000 {
        let x = f64::from(i) * 0.01;
        text.push_str(&format!(
            "FEDRAT/1645.92,MMPM\nGOTO/{x:.6},33.799705,-3.\nGOTO/{:.6},5.7625,-3.,0,0,1.\n",
            x + 1.0
        ));
        text.push_str(&format!("CIRCLE/{:.6},5.7625,-3.,0,0,-1.\nGOTO/{:.6},3.0,-3.\n", x + 1.0, x + 3.7625));
    }
    text.into_bytes()
}

/// One repetition's worth of CL text, without its FINI.
fn unit(name: &str) -> Vec<u8> {
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/apt");
    match std::fs::read(corpus.join(name)) {
        Ok(bytes) => {
            let text = String::from_utf8_lossy(&bytes);
            text.lines()
                .filter(|l| !l.trim_start().starts_with("FINI"))
                .flat_map(|l| [l, "\n"])
                .collect::<String>()
                .into_bytes()
        }
        Err(_) => generated(),
    }
}

fn repeated(unit: &[u8]) -> Vec<u8> {
    let mut text = Vec::with_capacity(TARGET_BYTES + unit.len());
    while text.len() < TARGET_BYTES {
        text.extend_from_slice(unit);
    }
    text.extend_from_slice(b"FINI\n");
    text
}

fn read_all(bytes: &[u8]) -> usize {
    let mut reader = AptReader::new(bytes, FileId(0));
    let mut diagnostics = Vec::new();
    let mut events = 0;
    while let Some(event) = reader.next_event(&mut diagnostics) {
        black_box(&event);
        events += 1;
    }
    events
}

fn apt_read(c: &mut Criterion) {
    let mut group = c.benchmark_group("apt_read");
    group.sample_size(10);
    for (label, name) in [
        ("solidworks_boss", "aamorim1913__AptPostProcessor/boss.apt"),
        ("nx_ust_a2", "HumMan__CLSFProcessor/ust_a2.cls"),
    ] {
        let input = repeated(&unit(name));
        group.throughput(Throughput::Bytes(input.len() as u64));
        group.bench_function(label, |b| b.iter(|| read_all(black_box(&input))));
    }
    group.finish();
}

criterion_group!(benches, apt_read);
criterion_main!(benches);
