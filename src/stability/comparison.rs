//! The comparison behind `rodimpact stability`: every backend on the suite and a seeded sweep,
//! error in units of cond u against median run time, measured side by side in the same run
//! (rendered by `crate::report::stability_markdown` and `stability_json`).

use super::{Backend, Case, Class, Reference, median_nanos, suite, sweep};
use crate::field::{Interval, Q};
use crate::solve::fast::closed_form::closed_form;

/// One backend's statistics over the suite and the sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct BackendStats {
    /// The backend.
    pub backend: Backend,
    /// Scenes in range for its format (suite + sweep).
    pub scenes: usize,
    /// Max of error/(cond u) over the outputs where both are defined.
    pub max: f64,
    /// Median of error/(cond u).
    pub median: f64,
    /// NaN outputs.
    pub nan: usize,
    /// Infinite outputs.
    pub inf: usize,
    /// Zeros where the exact output is not zero.
    pub spurious_zero: usize,
    /// Interval enclosures that miss the exact value (must be 0).
    pub not_enclosed: usize,
    /// Median over the suite scenes of the median time per evaluation, in ns.
    pub nanos: f64,
}

/// Runs every backend on the suite plus `count` sweep scenes per format (f64 +-300 decades,
/// f32 +-36, seeds 1 and 2). Statistics cover the scenes in range for each format.
///
/// # Examples
/// ```
/// let rows = rodimpact::stability::compare_backends(10);
/// let sq = rows.iter().find(|r| r.backend.name() == "f64/sq").unwrap();
/// assert_eq!(sq.nan + sq.inf, 0);
/// assert!(sq.max <= 4.0);
/// ```
pub fn compare_backends(count: usize) -> Vec<BackendStats> {
    let cases = suite();
    // Each scene's exact reference is computed once and shared by every backend.
    let referenced = |pool: Vec<Case>| -> Vec<(Case, Reference)> {
        pool.into_iter()
            .map(|case| {
                let reference = Reference::of(&case.scene).expect("the suite's rods are free");
                (case, reference)
            })
            .collect()
    };
    let wide = referenced(cases.iter().cloned().chain(sweep(1, count, 300)).collect());
    let narrow = referenced(cases.iter().cloned().chain(sweep(2, count, 36)).collect());
    Backend::ALL
        .iter()
        .map(|&backend| {
            let pool = if matches!(backend, Backend::F32(_)) {
                &narrow
            } else {
                &wide
            };
            stats(backend, pool, &cases)
        })
        .collect()
}

fn stats(backend: Backend, pool: &[(Case, Reference)], timed: &[Case]) -> BackendStats {
    let fits = |(_, reference): &&(Case, Reference)| match backend {
        Backend::F32(_) => reference.in_range::<f32>(),
        Backend::Exact => true,
        _ => reference.in_range::<f64>(),
    };
    let mut ratios = Vec::new();
    let (mut nan, mut inf, mut zero, mut missed, mut scenes) = (0, 0, 0, 0, 0);
    for (case, reference) in pool.iter().filter(fits) {
        scenes += 1;
        let (m, encloses) = backend.measure(&case.scene, reference).expect("free rod");
        missed += usize::from(!encloses);
        for x in [m.v, m.rod_v, m.omega] {
            match x.class {
                Class::Nan => nan += 1,
                Class::Infinite => inf += 1,
                Class::SpuriousZero => zero += 1,
                _ => {}
            }
            ratios.extend(x.ratio);
        }
    }
    ratios.sort_by(f64::total_cmp);
    let mut times: Vec<f64> = timed.iter().map(|c| time(backend, c)).collect();
    times.sort_by(f64::total_cmp);
    BackendStats {
        backend,
        scenes,
        max: ratios.last().copied().unwrap_or(0.0),
        median: ratios.get(ratios.len() / 2).copied().unwrap_or(0.0),
        nan,
        inf,
        spurious_zero: zero,
        not_enclosed: missed,
        nanos: times[times.len() / 2],
    }
}

/// Median time of one evaluation of `case` in `backend`, inputs already in the format.
fn time(backend: Backend, case: &Case) -> f64 {
    let s = &case.scene;
    match backend {
        Backend::F64(f) => {
            let p = s.params::<f64>();
            median_nanos(|| f.eval(std::hint::black_box(&p)))
        }
        Backend::F32(f) => {
            let p = s.params::<f32>();
            median_nanos(|| f.eval(std::hint::black_box(&p)))
        }
        Backend::Interval => {
            let p = s.params::<Interval>();
            median_nanos(|| closed_form(std::hint::black_box(&p)))
        }
        Backend::Exact => {
            let p = s.params::<Q>();
            median_nanos(|| closed_form(std::hint::black_box(&p)))
        }
    }
}
