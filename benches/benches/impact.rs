//! One impact solved by the general planar solver against the paper's route on the same scene
//! (the ratio says what generality costs), and the general solver on coupled scenes, where the
//! three laws part: `cargo bench -p rodimpact-benches --bench impact`. Instructions per scene: docs/performance.md.

use criterion::{Criterion, criterion_group, criterion_main};
use rodimpact::field::{Q, QSqrt, q};
use rodimpact::impact::{Law, Model, solve_contact, solve_exact, solve_several};
use rodimpact::model::parse_toml;
use rodimpact::scene::Scene;
use rodimpact::solve::{self, Answer, Route};
use std::hint::black_box;

fn scene_file(name: &str) -> rodimpact::model::System {
    let path = format!(
        "{}/../examples/impacts/{name}.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    parse_toml(name, &std::fs::read_to_string(path).expect("bench scene")).expect("valid")
}

fn paper_against_general(c: &mut Criterion) {
    let paper = Scene::builder(q(1, 1), q(1, 1))
        .a(q(1, 2))
        .build()
        .expect("valid");
    let system = paper.system();
    c.bench_function("impact/paper/fraction-free route", |b| {
        b.iter(|| solve::with::<Q>(black_box(&paper), Route::FractionFree))
    });
    c.bench_function("impact/paper/front door (Answer::of)", |b| {
        b.iter(|| Answer::of(black_box(&paper)))
    });
    c.bench_function("impact/paper/general solver, Newton", |b| {
        b.iter(|| solve_contact::<QSqrt>(black_box(&system), Law::Newton))
    });
    c.bench_function("impact/paper/general solver in Q, Newton", |b| {
        b.iter(|| solve_contact::<Q>(black_box(&system), Law::Newton))
    });
    for (name, law) in [
        ("tilted-rod-rough-floor", Law::Newton),
        ("tilted-rod-rough-floor", Law::Energetic),
        ("box-corner", Law::Poisson),
    ] {
        let system = scene_file(name);
        c.bench_function(&format!("impact/{name}/{}", law.name()), |b| {
            b.iter(|| solve_exact(black_box(&system), law))
        });
    }
    for (name, model) in [
        ("cradle-5", Model::SimultaneousNewton),
        ("box-lands-flat-friction", Model::SimultaneousPoisson),
    ] {
        let system = scene_file(name);
        c.bench_function(&format!("impact/{name}/{model}"), |b| {
            b.iter(|| solve_several::<Q>(black_box(&system), &model))
        });
    }
}

criterion_group!(benches, paper_against_general);
criterion_main!(benches);
