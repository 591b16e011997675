//! Convergence in the stiffness: the exact-geometry model against the impulsive values for a
//! range of k, with least-squares slopes on log-log axes.

use super::{Contact, Geometry, Integrator, simulate};
use crate::error::Error;
use crate::scene::Scene;

/// One stiffness of a [`sweep_k`].
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// The spring stiffness k.
    pub k: f64,
    /// The contact duration T_c.
    pub contact_time: f64,
    /// The rod's turn during contact, omega T_c (radians).
    pub turn: f64,
    /// Relative errors of v, V, omega and |lateral velocity| / v0.
    pub errors: [f64; 4],
    /// Wall-clock seconds of the run.
    pub seconds: f64,
}

/// Simulates `scene` for each stiffness in `ks` with `integrator`, `steps` steps per contact
/// time T_c.
///
/// # Errors
/// Those of [`Contact::new`].
///
/// # Examples
/// ```
/// use rodimpact::contact::{Geometry, Integrator, sweep_k};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let rows = sweep_k(&scene, &[1e4, 1e6], Geometry::Exact, Integrator::EventRk4, 200)?;
/// assert!(rows[1].errors[2] < rows[0].errors[2] / 50.0); // omega: O(1/k)
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn sweep_k(
    scene: &Scene,
    ks: &[f64],
    geometry: Geometry,
    integrator: Integrator,
    steps: usize,
) -> Result<Vec<SweepRow>, Error> {
    ks.iter()
        .map(|&k| {
            let c = Contact::new(scene, k, geometry)?;
            let run = simulate(&c, integrator, c.contact_time() / steps as f64);
            let [ev, erv, eo] = run.errors;
            Ok(SweepRow {
                k,
                contact_time: c.contact_time(),
                turn: c.reference()[2] * c.contact_time(),
                errors: [ev, erv, eo, run.lateral.abs()],
                seconds: run.seconds,
            })
        })
        .collect()
}

/// The least-squares slope of log10(y) against log10(x); `None` with fewer than two points or
/// a non-positive value.
///
/// # Examples
/// ```
/// use rodimpact::contact::fit_slope;
/// let slope = fit_slope(&[1.0, 10.0, 100.0], &[2.0, 0.2, 0.02]).unwrap();
/// assert!((slope + 1.0).abs() < 1e-12);
/// ```
pub fn fit_slope(x: &[f64], y: &[f64]) -> Option<f64> {
    if x.len() < 2 || x.len() != y.len() || x.iter().chain(y).any(|v| v.is_nan() || *v <= 0.0) {
        return None;
    }
    let n = x.len() as f64;
    let lx: Vec<f64> = x.iter().map(|v| v.log10()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.log10()).collect();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}
