//! `postc check` over a CL file with many bad records (issue 14, fault 9):
//! reading it, and giving every diagnostic its line and column as
//! `check --format json` does. Each diagnostic must cost the same wherever
//! it is in the file, so the time per MB is the same at both sizes.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use postc_ir::SourceMap;

/// A CL file of about `bytes` bytes where every other GOTO is bad.
fn bad_cl(bytes: usize) -> String {
    let mut text = String::from("PARTNO/MANY ERRORS\nUNITS/MM\nLOADTL/1\nCUTTER/6.\nRAPID\nGOTO/0,0,25.\n");
    let mut i = 0u32;
    while text.len() < bytes {
        let x = f64::from(i) * 0.01;
        if i.is_multiple_of(2) {
            text.push_str(&format!("GOTO  /   {x:.4},Q    1.7270,    3.1466, 0.0000000, 0.0000000, 1.0000000\n"));
        } else {
            text.push_str(&format!("GOTO  /   {x:.4},    0.7247,    2.2967, 0.0085511,-0.0050286, 0.9999508\n"));
        }
        i += 1;
    }
    text.push_str("FINI\n");
    text
}

fn check_json(path: &Path) -> usize {
    let mut sources = SourceMap::new();
    let diagnostics = postc_frontends::check_toolpath(path, &mut sources);
    let name = path.display().to_string();
    diagnostics.iter().map(|d| sources.to_json(d, &name)).filter_map(|j| j.line).count()
}

fn bench(c: &mut Criterion) {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let mut group = c.benchmark_group("check_many_errors");
    group.sample_size(10);
    for mb in [1usize, 4] {
        let path = dir.path().join(format!("bad{mb}.cl"));
        let text = bad_cl(mb << 20);
        std::fs::write(&path, &text).expect("the bench file is written");
        group.throughput(Throughput::Bytes(text.len() as u64));
        group.bench_function(format!("{mb}MB"), |b| b.iter(|| black_box(check_json(&path))));
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
