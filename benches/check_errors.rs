//! `postc check` over a CL file with many bad records:
//! reading it, and giving every diagnostic its line and column as
//! `check --format json` does. Each diagnostic must cost the same wherever
//! it is in the file, so the time per MB is the same at both sizes.

use postc_report::Render as _;
use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};

#[path = "../tests/many_errors/mod.rs"]
mod many_errors;
use many_errors::bad_cl;

fn check_json(path: &Path) -> usize {
    let mut sources = postc_report::source_map();
    let diagnostics = postc_driver::check_toolpath(path, &mut sources);
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
