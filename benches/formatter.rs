//! The number formatter alone: typical coordinates, near-tie values that
//! need the exact tie rule, and the slow path's huge magnitudes.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use postc_ir::NumberFormat;
use postc_runtime::number::NumberWriter;

fn bench(c: &mut Criterion) {
    let three = NumberWriter::new(&NumberFormat { decimals: 3, ..NumberFormat::default() });
    let padded = NumberWriter::new(&NumberFormat {
        decimals: 3,
        width: 9,
        padding: postc_ir::Padding::Zero,
        sign: postc_ir::SignStyle::Always,
        decimal_mark: ',',
        ..NumberFormat::default()
    });
    let typical: Vec<f64> = (0..1000).map(|i| (i as f64) * 1.234_567 - 600.0).collect();
    let ties: Vec<f64> = (0..1000).map(|i| (i as f64) * 0.0005 + 0.0005).collect();
    let huge: Vec<f64> = (0..1000).map(|i| 1e15 + i as f64 * 0.125).collect();
    let mut out = Vec::with_capacity(1 << 16);
    let mut group = c.benchmark_group("formatter");
    group.throughput(Throughput::Elements(1000));
    for (name, writer, values) in [
        ("typical", &three, &typical),
        ("ties", &three, &ties),
        ("padded-comma-signed", &padded, &typical),
        ("huge-slow-path", &three, &huge),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                out.clear();
                for &v in values {
                    writer.write(v, &mut out);
                }
                out.len()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
