//! The exact values the paper's figures draw, solved: the scene at rational impact points
//! along the rod (by the linear route), the optimum of each arm, a* as the mass ratio runs, and
//! the budget that bounds a figure's work. [`crate::report`]'s figures draw what these return.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt};
use crate::scene::{Scene, Support};
use crate::solve::Outcome;
use crate::solve::fast::linear;
use crate::solve::optimum::{Optimum, a_star_squared, optimum};
use num_traits::{One, ToPrimitive};

/// Sample points per half-length l.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::sampling::PER_L, 200);
/// ```
pub const PER_L: i64 = 200;

/// The most decimal digits the exact numbers of a sampled figure may hold together (numerators
/// and denominators of m, M, l, v0, e, the pivot and the rod's inertia): a figure solves its
/// scene exactly at hundreds of points, and every operation on numbers of d digits costs about
/// d^2 in num-bigint's reductions, so 700 digits is about five seconds at worst (a pivot at
/// 1e-600 took 4.4 s, at 1e-9000 minutes). Several curves share the bound: their squared digit
/// counts add up. `rodimpact solve` and `table` answer larger scenes exactly.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::sampling::MAX_SAMPLED_DIGITS, 700);
/// ```
pub const MAX_SAMPLED_DIGITS: u64 = 700;

/// Refuses scenes whose exact samples would cost more than [`MAX_SAMPLED_DIGITS`] allows, naming
/// the input with the most digits (`ratios` for a family of mass ratios).
///
/// # Errors
/// `field: the figure samples its scene exactly at hundreds of points, and its numbers hold N
/// digits, more than 700 (limit for figures); ...`.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::check_sampling_cost};
/// assert!(check_sampling_cost(&[Scene::builder(q(1, 1), q(1, 1)).build()?]).is_ok());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn check_sampling_cost(scenes: &[Scene]) -> Result<(), Error> {
    let digits = crate::field::int::decimal_digits;
    let mut work = 0u64;
    let mut heaviest = ("scene", 0u64);
    for scene in scenes {
        let pivot = match scene.support() {
            Support::Pivot(p) => Some(p.clone()),
            Support::Free => None,
        };
        let inputs = [
            ("m", Some(scene.m().clone())),
            (
                if scenes.len() > 1 { "ratios" } else { "M" },
                Some(scene.rod_mass().clone()),
            ),
            ("l", Some(scene.half_length().clone())),
            ("v0", Some(scene.v0().clone())),
            ("e", Some(scene.e().clone())),
            ("pivot", pivot),
            ("rod", Some(scene.inertia())),
        ];
        let mut total = 0u64;
        for (name, value) in inputs {
            let d = value.as_ref().map_or(0, digits);
            total += d;
            if d > heaviest.1 {
                heaviest = (name, d);
            }
        }
        work = work.saturating_add(total.saturating_mul(total));
    }
    if work > MAX_SAMPLED_DIGITS * MAX_SAMPLED_DIGITS {
        return Err(Error::out_of_range(
            heaviest.0,
            format!(
                "the figure solves its scene exactly at hundreds of points, and its numbers hold {} digits, more than {MAX_SAMPLED_DIGITS} (limit for figures); `rodimpact solve` answers the scene exactly",
                work.isqrt()
            ),
        ));
    }
    Ok(())
}

/// The nearest f64 of an exact value (only for drawing).
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::sampling::f(&rodimpact::field::q(1, 4)), 0.25);
/// ```
pub fn f(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// The impact point `k/PER_L` of l (exact).
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::point};
/// let s = Scene::builder(q(1, 1), q(1, 1)).half_length(q(2, 1)).build()?;
/// assert_eq!(point(&s, 100), q(1, 1));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn point(scene: &Scene, k: i64) -> Q {
    Q::new(k.into(), PER_L.into()) * scene.half_length()
}

/// The scene solved exactly, by the library's solver, for the projectile striking at `a`;
/// beyond the rod's ends (|a| > l) this is the formula continued, drawn dashed.
///
/// # Errors
/// Only if the impulse system were singular, which it never is for a valid scene.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::outcome_at};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build()?;
/// assert_eq!(outcome_at(&s, &q(1, 2))?.after.omega, q(12, 11));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn outcome_at(scene: &Scene, a: &Q) -> Result<Outcome<Q>, Error> {
    linear::solve_at(scene, a.clone()).ok_or_else(|| {
        Error::new(
            "a",
            ErrorKind::Invalid(format!("the impulse equations are singular at a = {a}")),
        )
    })
}

/// The scene's optimum: a* (or d* from a pivot), where it lies, and the largest omega; the
/// scene's rod is at rest before the impact.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::optimum_of};
/// assert_eq!(optimum_of(&Scene::builder(q(1, 1), q(1, 1)).build()?).squared, q(2, 3));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn optimum_of(scene: &Scene) -> Optimum {
    optimum(scene).expect("a rod at rest before the impact has an optimum")
}

/// a*^2 (or d*^2 from a pivot) of the scene's masses and inertia.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::a_star_squared_of};
/// assert_eq!(a_star_squared_of(&Scene::builder(q(1, 1), q(1, 1)).build()?), q(2, 3));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn a_star_squared_of(scene: &Scene) -> Q {
    a_star_squared(&scene.params::<Q>())
}

/// The optimum of one arm of the rod ([`arm_optima`]).
#[derive(Debug, Clone)]
pub struct ArmOptimum {
    /// +1 for the arm towards +l, -1 towards -l.
    pub side: i8,
    /// The optimum of that arm (a* or d* and the maximum of |omega|).
    pub optimum: Optimum,
    /// a* (free) or p ± d* (pivot): where the formula peaks, in units of l (may be off the rod).
    pub peak_at: f64,
    /// |omega| at that peak, exactly: (1 + e) v0 / (2 a*).
    pub peak: QSqrt,
}

/// The optimum of each arm with room on it: a > 0 for a free rod (the other is its mirror
/// image), both sides of the pivot for a pivoted rod.
///
/// # Errors
/// None for a valid scene (the scene struck at each end is valid).
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, sampling::arm_optima};
/// let pivoted = Scene::builder(q(1, 1), q(1, 1)).pivot(q(-1, 2)).build()?;
/// assert_eq!(arm_optima(&pivoted)?.len(), 2);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn arm_optima(scene: &Scene) -> Result<Vec<ArmOptimum>, Error> {
    let l = scene.half_length();
    let sides: &[i8] = match scene.support() {
        Support::Free => &[1],
        Support::Pivot(_) => &[1, -1],
    };
    let mut arms = Vec::new();
    for &side in sides {
        let end = l * Q::from_integer(side.into());
        if let Support::Pivot(p) = scene.support()
            && &end == p
        {
            continue; // the pivot is at this end: no arm on this side
        }
        let o = optimum_of(&scene.with_a(end)?);
        let root = QSqrt::sqrt_of(&o.squared);
        let axis = match scene.support() {
            Support::Free => 0.0,
            Support::Pivot(p) => f(p),
        };
        let peak_at = (axis + f64::from(side) * root.nearest_f64()) / f(l);
        let half = (Q::one() + scene.e()) * scene.v0() / Q::from_integer(2.into());
        let peak = QSqrt::sqrt_of(&(Q::one() / &o.squared)) * &QSqrt::rational(half);
        arms.push(ArmOptimum {
            side,
            optimum: o,
            peak_at,
            peak,
        });
    }
    Ok(arms)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    #[test]
    fn the_formula_continues_past_the_end() {
        // M = m uniform: omega(a) = 6a/(4/3 + ... ) -> at a = 6/5 (off the rod) the solver still
        // answers: omega = 2 a/(a*^2 + a^2) with a*^2 = 2/3: 12/5 / (2/3 + 36/25) = 90/79.
        let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
        assert_eq!(outcome_at(&s, &q(6, 5)).unwrap().after.omega, q(90, 79));
    }

    #[test]
    fn a_pivot_has_two_arms_a_door_one() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .pivot(q(-1, 2))
            .build()
            .unwrap();
        let arms = arm_optima(&s).unwrap();
        assert_eq!(arms.len(), 2);
        // I_p = 1/3 + 1/4 = 7/12 = d*^2 on both sides.
        assert!(arms.iter().all(|a| a.optimum.squared == q(7, 12)));
        let door = Scene::builder(q(1, 1), q(1, 1))
            .pivot(q(-1, 1))
            .build()
            .unwrap();
        assert_eq!(arm_optima(&door).unwrap().len(), 1);
        // The peak (1 + e) v0/(2 d*) = 1/sqrt(7/12) = sqrt(12/7).
        assert!((arms[0].peak.nearest_f64() - (12.0f64 / 7.0).sqrt()).abs() < 1e-15);
    }
}
