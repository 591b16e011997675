//! How long `prove` takes for every claim: build the symbolic computations and re-check every
//! certificate. Goal (docs/performance.md): all claims in at most 1 s on a 2-core machine.

use criterion::{Criterion, criterion_group, criterion_main};
use rodimpact::claims::{Paper, decide_all};
use std::hint::black_box;

fn prove_all(c: &mut Criterion) {
    let paper = Paper::as_printed();
    let mut group = c.benchmark_group("prove");
    group.sample_size(10);
    group.bench_function("all claims", |b| {
        b.iter(|| {
            let decided = decide_all(black_box(&paper));
            assert!(decided.iter().all(|d| d.verdict.is_ok()));
            decided
        })
    });
    group.finish();
}

criterion_group!(benches, prove_all);
criterion_main!(benches);
