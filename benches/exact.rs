//! Per scene, side by side: f64 closed form, the straightforward `BigRational` path (the generic
//! solver over Q) and the fast exact path (fixed width, then big integers), each solving and
//! checking the conservation laws, on the first 1000 scenes of both reference batches.
//! Throughput is in scenes; the ratios to f64 are the figures of the README.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rodimpact::batch::{Backend, Batch};
use rodimpact::fast;
use rodimpact::field::Q;
use rodimpact::float::Formula;
use rodimpact::scene::Scene;
use rodimpact::solve::{closed_form, outcome, solve};
use std::hint::black_box;
use std::time::Duration;

const SCENES: usize = 1000;

fn scenes(file: &str) -> Vec<Scene> {
    let path = format!("{}/../shared/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("shared/data beside the project");
    let mut lines = text.lines();
    let batch = Batch::new(lines.next().expect("a header"), Backend::Exact).expect("the header");
    lines
        .take(SCENES)
        .enumerate()
        .map(|(i, line)| batch.scene(i + 1, line).expect("valid reference scene").0)
        .collect()
}

fn per_scene(c: &mut Criterion) {
    for (label, file) in [("1e6", "bench-1e6.csv"), ("textbook", "bench-textbook.csv")] {
        let batch = scenes(file);
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
                    black_box(Formula::Sq.eval(black_box(p)));
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
                    black_box(fast::solve(black_box(s)));
                }
            })
        });
        group.bench_function("fast exact, big integers only", |b| {
            b.iter(|| {
                for s in &batch {
                    black_box(fast::solve_big(black_box(s)));
                }
            })
        });
        group.finish();
    }
}

criterion_group!(benches, per_scene);
criterion_main!(benches);
