//! Each float formula per format on the same scenes (paper scene, stop zone, extreme masses),
//! with the interval and exact closed forms as references. Sized small for a 2-core machine.

use criterion::{Criterion, criterion_group, criterion_main};
use rodimpact::field::{Interval, Q};
use rodimpact::solve::fast::closed_form::closed_form;
use rodimpact::solve::fast::float::FloatFormula;
use rodimpact::stability::suite;
use std::hint::black_box;
use std::time::Duration;

fn float_formulas(c: &mut Criterion) {
    let cases = suite();
    for id in ["1", "5", "8"] {
        let scene = &cases
            .iter()
            .find(|case| case.id == id)
            .expect("suite id")
            .scene;
        let (p64, p32) = (scene.params::<f64>(), scene.params::<f32>());
        for formula in FloatFormula::ALL {
            c.bench_function(&format!("scene {id}/f64/{}", formula.name()), |b| {
                b.iter(|| formula.eval(black_box(&p64)))
            });
            c.bench_function(&format!("scene {id}/f32/{}", formula.name()), |b| {
                b.iter(|| formula.eval(black_box(&p32)))
            });
        }
        let pi = scene.params::<Interval>();
        c.bench_function(&format!("scene {id}/interval"), |b| {
            b.iter(|| closed_form(black_box(&pi)))
        });
        let pq = scene.params::<Q>();
        c.bench_function(&format!("scene {id}/exact"), |b| {
            b.iter(|| closed_form(black_box(&pq)))
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(500));
    targets = float_formulas
}
criterion_main!(benches);
