//! One scene solved with the generic solver over each backend, side by side on the same scene
//! (the paper's M = m end hit, and a reference-batch scene with 10^6-sized inputs).

use criterion::{Criterion, criterion_group, criterion_main};
use rodimpact::field::{Field, Q, RatFn};
use rodimpact::scene::{Params, Scene, Support};
use rodimpact::solve::fast::linear::solve;
use std::hint::black_box;

fn scene(fields: [&str; 5]) -> Scene {
    let [m, big_m, l, a, v0] = fields.map(|t| rodimpact::number::parse(t).expect("bench data"));
    Scene::builder(m, big_m)
        .half_length(l)
        .a(a)
        .v0(v0)
        .build()
        .expect("valid bench scene")
}

fn bench_backend<F: Field>(c: &mut Criterion, label: &str, s: &Scene) {
    let params = s.params::<F>();
    c.bench_function(&format!("solve/{label}/{}", F::NAME), |b| {
        b.iter(|| solve(black_box(&params)))
    });
}

fn solve_backends(c: &mut Criterion) {
    let paper = scene(["1", "1", "1", "1", "1"]);
    let big = scene([
        "851747/375605",
        "93531/184198",
        "104159/300644",
        "-38267/525005",
        "5333/252521",
    ]);
    for (label, s) in [("paper", &paper), ("1e6", &big)] {
        bench_backend::<f64>(c, label, s);
        bench_backend::<f32>(c, label, s);
        bench_backend::<Q>(c, label, s);
    }
    let sym = RatFn::symbol;
    let symbolic = Params {
        m: sym("m"),
        rod_mass: sym("M"),
        half_length: sym("l"),
        inertia: sym("I"),
        a: sym("a"),
        v0: sym("v0"),
        e: RatFn::from(1),
        support: Support::Free,
    };
    c.bench_function("solve/symbolic/Q(symbols)", |b| {
        b.iter(|| solve(black_box(&symbolic)))
    });
}

criterion_group!(benches, solve_backends);
criterion_main!(benches);
