//! Per scene, side by side: f64 closed form, the straightforward `BigRational` path (the generic
//! solver over Q) and the fast exact path (fixed width, then big integers), each solving and
//! checking the conservation laws, on the first 1000 scenes of both reference batches; and the
//! growth of the fast exact cost with the size of the inputs. Throughput is in scenes; the
//! ratios to f64 are the figures of docs/performance.md.

mod support;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use rodimpact::field::Q;
use rodimpact::samples::sized_scene;
use rodimpact::solve::fast::float::FloatFormula;
use rodimpact::solve::fast::fraction_free;
use rodimpact::solve::{
    fast::{closed_form::closed_form, linear::solve},
    outcome,
};
use rodimpact::stability::SplitMix64;
use std::hint::black_box;
use std::time::Duration;

const SCENES: usize = 1000;

fn per_scene(c: &mut Criterion) {
    for (label, file) in [("1e6", "bench-1e6.csv"), ("textbook", "bench-textbook.csv")] {
        let batch = support::reference(file, SCENES);
        let floats: Vec<_> = batch.iter().map(|s| s.params::<f64>()).collect();
        let exact: Vec<_> = batch.iter().map(|s| s.params::<Q>()).collect();
        let mut group = c.benchmark_group(format!("exact/{label}"));
        group.sample_size(10);
        group.warm_up_time(Duration::from_millis(500));
        group.measurement_time(Duration::from_secs(2));
        group.throughput(Throughput::Elements(SCENES as u64));
        group.bench_function("f64 closed form + laws", |b| {
            b.iter(|| {
                for p in &floats {
                    black_box(closed_form(black_box(p)).map(|m| outcome(p, m)));
                }
            })
        });
        group.bench_function("f64 stable (sq)", |b| {
            b.iter(|| {
                for p in &floats {
                    black_box(FloatFormula::Sq.eval(black_box(p)));
                }
            })
        });
        group.bench_function("BigRational straightforward", |b| {
            b.iter(|| {
                for p in &exact {
                    black_box(solve(black_box(p)));
                }
            })
        });
        group.bench_function("fast exact", |b| {
            b.iter(|| {
                for s in &batch {
                    black_box(fraction_free::solve(black_box(s)));
                }
            })
        });
        group.bench_function("fast exact, big integers only", |b| {
            b.iter(|| {
                for s in &batch {
                    black_box(fraction_free::solve_big(black_box(s)));
                }
            })
        });
        group.finish();
    }
}

/// Growth of the fast exact cost with the size of the inputs: random scenes whose numerators
/// and denominators have 10 to 10,000 bits (the example `exact_cost` goes to 100,000 and fits
/// the exponent).
fn growth(c: &mut Criterion) {
    let mut group = c.benchmark_group("exact/growth");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(300));
    group.measurement_time(Duration::from_secs(2));
    let mut rng = SplitMix64::new(20240611);
    for bits in [10u64, 32, 100, 1000, 10_000] {
        let count = (20_000 / bits).clamp(2, 100) as usize;
        let batch: Vec<_> = (0..count).map(|_| sized_scene(&mut rng, bits)).collect();
        group.throughput(Throughput::Elements(count as u64));
        group.bench_with_input(BenchmarkId::new("fast exact", bits), &batch, |b, batch| {
            b.iter(|| {
                for s in batch {
                    black_box(fraction_free::solve(black_box(s)));
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, per_scene, growth);
criterion_main!(benches);
