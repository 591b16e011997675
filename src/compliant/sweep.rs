//! Convergence in the stiffness: the exact-geometry model against the impulsive values for a
//! range of k, with least-squares slopes on log-log axes.

use super::{CompliantContact, Geometry, Integrator, Run, simulate};
use crate::error::Error;
use crate::scene::Scene;

/// One stiffness of a [`sweep_k`]: the model and its run.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// The model at this stiffness (its k, T_c and exact values).
    pub contact: CompliantContact,
    /// The run at this stiffness.
    pub run: Run,
}

impl SweepRow {
    /// The rod's turn during the contact, |omega| T_c (radians), omega the exact value.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{Geometry, Integrator, sweep_k};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let row = &sweep_k(&scene, &[1e6], Geometry::Exact, Integrator::EventRk4, 100)?[0];
    /// assert!((row.turn() - 12.0 / 11.0 * row.contact.contact_time()).abs() < 1e-18);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn turn(&self) -> f64 {
        self.contact.reference()[2].abs() * self.contact.contact_time()
    }
}

/// Least-squares slopes of log10(error) against log10(k) over a sweep: the convergence orders.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slopes {
    /// Slopes for the errors of v, V and omega (`None` where an error is 0 or not finite).
    pub errors: [Option<f64>; 3],
    /// Slope for the pivot impulse's error; `None` for a free rod.
    pub pivot: Option<f64>,
    /// Slope for |lateral velocity| / v0.
    pub lateral: Option<f64>,
}

impl Slopes {
    /// The slopes of `rows`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{Geometry, Integrator, Slopes, sweep_k};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let rows = sweep_k(&scene, &[1e4, 1e6, 1e8], Geometry::Exact, Integrator::EventRk4, 400)?;
    /// let slopes = Slopes::of(&rows);
    /// assert!((slopes.errors[2].unwrap() + 1.0).abs() < 0.01); // omega: O(1/k)
    /// assert!((slopes.lateral.unwrap() + 0.5).abs() < 0.01); // lateral: O(k^-1/2)
    /// assert_eq!(slopes.pivot, None);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(rows: &[SweepRow]) -> Slopes {
        let ks: Vec<f64> = rows.iter().map(|r| r.contact.stiffness()).collect();
        let fit = |value: &dyn Fn(&Run) -> f64| {
            let ys: Vec<f64> = rows.iter().map(|r| value(&r.run)).collect();
            fit_slope(&ks, &ys)
        };
        let pivoted = rows.iter().all(|r| r.run.pivot_error.is_some()) && !rows.is_empty();
        Slopes {
            errors: std::array::from_fn(|i| fit(&|run: &Run| run.errors[i])),
            pivot: if pivoted {
                fit(&|run: &Run| run.pivot_error.unwrap_or(f64::NAN))
            } else {
                None
            },
            lateral: fit(&|run: &Run| run.lateral.abs()),
        }
    }
}

/// Simulates `scene` for each stiffness in `ks` with `integrator`, `steps` steps per contact
/// time T_c.
///
/// # Errors
/// Those of [`CompliantContact::new`] and [`simulate`].
///
/// # Examples
/// ```
/// use rodimpact::compliant::{Geometry, Integrator, sweep_k};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let rows = sweep_k(&scene, &[1e4, 1e6], Geometry::Exact, Integrator::EventRk4, 200)?;
/// assert!(rows[1].run.errors[2] < rows[0].run.errors[2] / 50.0); // omega: O(1/k)
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
            let contact = CompliantContact::new(scene, k, geometry)?;
            let run = simulate(&contact, integrator, contact.contact_time() / steps as f64)?;
            Ok(SweepRow { contact, run })
        })
        .collect()
}

/// The least-squares slope of log10(y) against log10(x); `None` with fewer than two points or
/// a non-positive value.
///
/// # Examples
/// ```
/// use rodimpact::compliant::fit_slope;
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
