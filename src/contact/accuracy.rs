//! How far a run is from the exact impulsive values, how far it may be, and the verdict.

use super::{Contact, Ending, Integrator};
use std::fmt;

/// The largest tolerance at which a run still cross-checks the impulse: 10 %.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::contact::LOOSEST, 0.1);
/// ```
pub const LOOSEST: f64 = 0.1;

/// The error a run may have, by source, and how errors are measured.
///
/// The errors are relative: |sim - exact| / scale, with scale |exact| for V, omega and the
/// pivot impulse P, max(|v|, |v0 - v|) for v (never below v0/2, so the projectile's stop point
/// v = 0 is measured too), max(|P|, J) for P (J = m (v0 - v) > 0, the contact impulse), and v0
/// (V) or v0/l (omega) where the exact value is 0.
///
/// The tolerance is the sum of three parts, each an upper bound measured with margin over a grid
/// of scenes (mass ratios 1e-3 to 1e3, impact points from the centre to 0.99 l, e from 0 to 1,
/// uniform, dumbbell and r_G = l/10 rods, free and pivoted, k from 1e2 to 1e10):
///
/// - the model floor (exact geometry only; the frozen oscillator is exact for every k):
///   10 theta_c^2 with theta_c = max(|omega|, v0/l) T_c, the rod's turn (or, for a slowly
///   turning rod, the projectile's travel over l) during the contact; it falls as 1/k;
/// - the integrator's error at x = h Omega: x/5 + x^2/5 for Verlet and RK4, x/2 + x^2/5 for
///   the implicit midpoint rule (second order for an elastic contact, first order once the
///   dashpot's force jumps at the onset), 2x for backward Euler, x^4/50 for event-driven RK4;
/// - rounding: 1e-12 plus 1e-15 per step.
///
/// Explicit methods beyond their stability limit (h Omega >= 2 for Verlet, 2.78 for RK4, the
/// smaller of its limits on the real and imaginary axes) miss whatever their errors, and so does
/// a run whose tolerance exceeds [`LOOSEST`]: it could not tell a right impulse from a wrong one.
///
/// # Examples
/// ```
/// use rodimpact::contact::{Contact, Geometry, Integrator, Tolerance};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = Contact::new(&scene, 1e6, Geometry::Frozen)?;
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
    /// use rodimpact::contact::{Contact, Geometry, Integrator, Tolerance};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let c = Contact::new(&scene, 1e6, Geometry::Exact)?;
    /// let t = Tolerance::of(&c, Integrator::EventRk4, c.contact_time() / 100.0, 100);
    /// let turn = 12.0 / 11.0 * c.contact_time(); // max(omega = 12/11, v0/l = 1) T_c
    /// assert!((t.model / (10.0 * turn * turn) - 1.0).abs() < 1e-12);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(c: &Contact, integrator: Integrator, h: f64, steps: usize) -> Tolerance {
        let model = match c.geometry {
            super::Geometry::Frozen => 0.0,
            super::Geometry::Exact => {
                let rate = c.reference()[2].abs().max(c.v0 / c.half_length);
                10.0 * (rate * c.contact_time()).powi(2)
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
    /// use rodimpact::contact::Tolerance;
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
    /// use rodimpact::contact::Miss;
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

/// The stability limit of an explicit method in h Omega; `None` for the implicit ones.
fn stability_limit(integrator: Integrator) -> Option<f64> {
    match integrator {
        Integrator::Verlet => Some(2.0),
        Integrator::Rk4 | Integrator::EventRk4 => Some(2.78),
        Integrator::Midpoint | Integrator::BackwardEuler => None,
    }
}

/// The errors of (v, V, omega) and of the pivot impulse, as the module documentation defines
/// them.
pub(super) fn errors(
    c: &Contact,
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
    integrator: Integrator,
    h_omega: f64,
    ending: Ending,
    errors: &[f64; 3],
    pivot_error: Option<f64>,
    tolerance: &Tolerance,
) -> Option<Miss> {
    if let Some(limit) = stability_limit(integrator).filter(|limit| h_omega >= *limit) {
        return Some(Miss::Unstable { h_omega, limit });
    }
    match ending {
        Ending::SlidOff => return Some(Miss::SlidOff),
        Ending::StillInContact => return Some(Miss::StillInContact),
        Ending::Separated | Ending::Settled => {}
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
