//! How far a run is from the exact impulsive values, how far it may be, and the verdict.

use super::{CompliantContact, Integrator, RunEnd};
use std::fmt;

/// The largest tolerance at which a run still cross-checks the impulse: 10 %.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::compliant::LOOSEST, 0.1);
/// ```
pub const LOOSEST: f64 = 0.1;

/// The error a run may have, by source, and how errors are measured.
///
/// The errors are relative: |sim - exact| / scale, with scale |exact| for V, omega and the
/// pivot impulse P, max(|v|, |v0 - v|) for v (never below v0/2, so the projectile's stop point
/// v = 0 is measured too), max(|P|, J) for P (J = m (v0 - v) > 0, the contact impulse), and v0
/// (V) or v0/l (omega) where the exact value is 0.
///
/// The tolerance is the sum of three parts, each an upper bound measured with margin (the
/// largest error seen was 0.64 of it) over 8,000 random scenes (mass ratios 1e-3 to 1e3,
/// impact points across the rod, e from 0 through 1e-300 to 1, uniform, dumbbell and r_G rods,
/// free and pivoted, k from 1e3 to 1e10, every integrator) wherever the tolerance is at most
/// [`LOOSEST`]; softer runs turn the rod so far that the O(1/k) bound no longer applies, and
/// they are flagged regardless:
///
/// - the model floor (exact geometry only; the frozen oscillator is exact for every k):
///   10 theta_c^2 with theta_c = max(|omega|, v0/l) T, the rod's turn (or, for a slowly
///   turning rod, the projectile's travel over l) during the contact; T is the contact time
///   T_c, or the settle time T_s where that is shorter (sticking, or a restitution so small
///   that the contact is nearly critically damped); it falls as 1/k;
/// - the integrator's error at x = h Omega: x/5 + x^2/5 for Verlet and RK4, x/2 + x^2/5 for
///   the implicit midpoint rule (second order for an elastic contact, first order once the
///   dashpot's force jumps at the onset), 2x for backward Euler, x^4/50 for event-driven RK4;
/// - rounding: 1e-12 plus 1e-15 per step.
///
/// Explicit methods beyond their [`stability_limit`] (h Omega = 2 for undamped Verlet, 2.83 for
/// undamped RK4, less with a dashpot) miss whatever their errors, and so does
/// a run whose tolerance exceeds [`LOOSEST`]: it could not tell a right impulse from a wrong one.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, Tolerance};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Frozen)?;
/// let t = Tolerance::of(&c, Integrator::BackwardEuler, 0.01 / c.frequency(), 1000);
/// assert_eq!(t.model, 0.0); // the frozen oscillator is exact for every k
/// assert!((t.integrator - 0.02).abs() < 1e-15);
/// assert!((t.total() - 0.02).abs() < 1e-11);
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// The compliant model's own distance from the impulsive limit, O(1/k).
    pub model: f64,
    /// The integrator's error at this step.
    pub integrator: f64,
    /// Floating-point rounding.
    pub rounding: f64,
}

impl Tolerance {
    /// The tolerance of a run of `integrator` with step `h` taking `steps` steps.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, Tolerance};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
    /// let t = Tolerance::of(&c, Integrator::EventRk4, c.contact_time() / 100.0, 100);
    /// let turn = 12.0 / 11.0 * c.contact_time(); // max(omega = 12/11, v0/l = 1) T_c
    /// assert!((t.model / (10.0 * turn * turn) - 1.0).abs() < 1e-12);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(c: &CompliantContact, integrator: Integrator, h: f64, steps: usize) -> Tolerance {
        let model = match c.geometry {
            super::Geometry::Frozen => 0.0,
            super::Geometry::Exact => {
                let rate = c.reference()[2].abs().max(c.v0 / c.half_length);
                10.0 * (rate * c.active_time()).powi(2)
            }
        };
        let x = h * c.frequency();
        let integrator = match integrator {
            Integrator::Verlet | Integrator::Rk4 => x / 5.0 + x * x / 5.0,
            Integrator::Midpoint => x / 2.0 + x * x / 5.0,
            Integrator::BackwardEuler => 2.0 * x,
            Integrator::EventRk4 => x.powi(4) / 50.0,
        };
        Tolerance {
            model,
            integrator,
            rounding: 1e-12 + 1e-15 * steps as f64,
        }
    }

    /// The sum of the three parts.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::Tolerance;
    /// let t = Tolerance { model: 1e-6, integrator: 1e-3, rounding: 1e-12 };
    /// assert_eq!(t.total(), 1e-6 + 1e-3 + 1e-12);
    /// ```
    pub fn total(&self) -> f64 {
        self.model + self.integrator + self.rounding
    }
}

/// Why a run does not reproduce the exact impulsive values.
#[derive(Debug, Clone, PartialEq)]
pub enum Miss {
    /// The point slid past the rod's end during the contact.
    SlidOff,
    /// The contact had not ended when the run did.
    StillInContact,
    /// An explicit method beyond its stability limit in h Omega.
    Unstable {
        /// h Omega of the run.
        h_omega: f64,
        /// The method's limit.
        limit: f64,
    },
    /// The tolerance exceeds [`LOOSEST`]: the model floor (k too small) or the integrator's
    /// error (step too large) is too loose for the run to check anything.
    TooLoose {
        /// The run's tolerance.
        tolerance: Tolerance,
    },
    /// A quantity's error exceeds the tolerance (or is not finite).
    Error {
        /// `v`, `V`, `omega` or `P`.
        quantity: &'static str,
        /// Its relative error.
        error: f64,
        /// The run's total tolerance.
        tolerance: f64,
    },
}

impl fmt::Display for Miss {
    /// One line saying what went wrong and what to do.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::Miss;
    /// let miss = Miss::Error { quantity: "v", error: 0.5, tolerance: 1e-3 };
    /// assert_eq!(miss.to_string(), "the error of v, 5.0e-1, exceeds the tolerance 1.0e-3");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Miss::SlidOff => write!(
                f,
                "the point slid past the rod's end during the contact (the impact is too close \
                 to the end for this k: hit farther in, or raise --stiffness)"
            ),
            Miss::StillInContact => write!(f, "the contact had not ended when the run did"),
            Miss::Unstable { h_omega, limit } => write!(
                f,
                "h Omega = {h_omega:.3} is beyond the method's stability limit {limit}: use more \
                 --steps or a smaller --dt"
            ),
            Miss::TooLoose { tolerance } => {
                let (part, advice) = if tolerance.model >= tolerance.integrator {
                    ("the model's distance from the impulse", "raise --stiffness")
                } else {
                    (
                        "the integrator's error",
                        "use more --steps or a smaller --dt",
                    )
                };
                write!(
                    f,
                    "the tolerance {:.1e} ({part}) is above {LOOSEST}, too loose to check the \
                     impulse: {advice}",
                    tolerance.total()
                )
            }
            Miss::Error {
                quantity,
                error,
                tolerance,
            } => write!(
                f,
                "the error of {quantity}, {error:.1e}, exceeds the tolerance {tolerance:.1e}"
            ),
        }
    }
}

/// The stability limit in h Omega of an explicit method on the contact's oscillator, whose
/// eigenvalues are Omega (-zeta +- i sqrt(1 - zeta^2)); `None` for the implicit methods.
///
/// Verlet with its explicit dashpot: 2 (sqrt(1 + zeta^2) - zeta), the central-difference
/// limit (2 undamped, 0.83 critically damped). RK4: where the ray of the eigenvalues leaves
/// the stability region |1 + z + z^2/2 + z^3/6 + z^4/24| <= 1 (2.83 undamped, 2.62 at its
/// narrowest near zeta = 1/2, 2.79 critically damped).
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, stability_limit};
/// use rodimpact::{field::q, scene::Scene};
/// let elastic = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&elastic, 1e6, Geometry::Frozen)?;
/// assert_eq!(stability_limit(&c, Integrator::Verlet), Some(2.0));
/// assert!((stability_limit(&c, Integrator::Rk4).unwrap() - 2.828).abs() < 1e-3);
/// assert_eq!(stability_limit(&c, Integrator::Midpoint), None);
/// let glued = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).e(q(0, 1)).build()?;
/// let c = CompliantContact::new(&glued, 1e6, Geometry::Frozen)?;
/// assert!((stability_limit(&c, Integrator::Verlet).unwrap() - 0.828).abs() < 1e-3);
/// assert!((stability_limit(&c, Integrator::EventRk4).unwrap() - 2.785).abs() < 1e-3);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn stability_limit(c: &CompliantContact, integrator: Integrator) -> Option<f64> {
    let zeta = c.zeta;
    match integrator {
        Integrator::Verlet => Some(2.0 * ((1.0 + zeta * zeta).sqrt() - zeta)),
        Integrator::Rk4 | Integrator::EventRk4 => Some(rk4_limit(zeta)),
        Integrator::Midpoint | Integrator::BackwardEuler => None,
    }
}

/// The first r (to 1e-4) at which z = r (-zeta + i sqrt(1 - zeta^2)) leaves RK4's stability
/// region.
fn rk4_limit(zeta: f64) -> f64 {
    let direction = (-zeta, (1.0 - zeta * zeta).max(0.0).sqrt());
    let growth = |r: f64| {
        let z = (r * direction.0, r * direction.1);
        let mul = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
        // Horner: 1 + z (1 + z/2 (1 + z/3 (1 + z/4))).
        let mut acc = (1.0, 0.0);
        for k in [4.0, 3.0, 2.0, 1.0] {
            let t = mul(z, acc);
            acc = (1.0 + t.0 / k, t.1 / k);
        }
        acc.0.hypot(acc.1)
    };
    let mut r = 0.0;
    while growth(r + 1e-4) <= 1.0 + 1e-12 && r < 4.0 {
        r += 1e-4;
    }
    r
}

/// The errors of (v, V, omega) and of the pivot impulse, as the module documentation defines
/// them.
pub(super) fn errors(
    c: &CompliantContact,
    velocities: &[f64; 3],
    pivot_impulse: Option<f64>,
) -> ([f64; 3], Option<f64>) {
    let [v, rod_v, omega] = c.reference();
    let scales = [
        v.abs().max((c.v0 - v).abs()),
        if rod_v == 0.0 { c.v0 } else { rod_v.abs() },
        if omega == 0.0 {
            c.v0 / c.half_length
        } else {
            omega.abs()
        },
    ];
    let reference = c.reference();
    let errors = std::array::from_fn(|i| (velocities[i] - reference[i]).abs() / scales[i]);
    let contact_impulse = c.m * (c.v0 - v);
    let pivot_error = pivot_impulse
        .zip(c.reference_pivot_impulse())
        .map(|(sim, exact)| (sim - exact).abs() / exact.abs().max(contact_impulse));
    (errors, pivot_error)
}

/// The first reason the run misses, if any.
pub(super) fn judge(
    c: &CompliantContact,
    integrator: Integrator,
    h_omega: f64,
    ending: RunEnd,
    errors: &[f64; 3],
    pivot_error: Option<f64>,
    tolerance: &Tolerance,
) -> Option<Miss> {
    if let Some(limit) = stability_limit(c, integrator).filter(|limit| h_omega >= *limit) {
        return Some(Miss::Unstable { h_omega, limit });
    }
    match ending {
        RunEnd::SlidOff => return Some(Miss::SlidOff),
        RunEnd::StillInContact => return Some(Miss::StillInContact),
        RunEnd::Separated | RunEnd::Settled => {}
    }
    let named = ["v", "V", "omega"].into_iter().zip(errors.iter().copied());
    let pivot = pivot_error.map(|e| ("P", e));
    let beyond = named
        .chain(pivot)
        .find(|(_, error)| error.is_nan() || *error > tolerance.total())
        .map(|(quantity, error)| Miss::Error {
            quantity,
            error,
            tolerance: tolerance.total(),
        });
    beyond.or_else(|| {
        (tolerance.total() > LOOSEST).then_some(Miss::TooLoose {
            tolerance: *tolerance,
        })
    })
}
