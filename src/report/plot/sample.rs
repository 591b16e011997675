//! The exact values a figure draws: the library's solver at rational impact points, and the
//! optimum of each arm.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt};
use crate::scene::{Params, Scene, Support};
use crate::solve::Outcome;
use crate::solve::fast::linear::solve;
use crate::solve::optimum::{Optimum, optimum};
use num_traits::{One, ToPrimitive};

/// Sample points per half-length l.
pub(crate) const PER_L: i64 = 200;

/// The most decimal digits the exact numbers of a sampled figure may hold together (numerators
/// and denominators of m, M, l, v0, e, the pivot and the rod's inertia): a figure solves its
/// scene exactly at hundreds of points, and every operation on numbers of d digits costs about
/// d^2 in num-bigint's reductions, so 700 digits is about five seconds at worst (a pivot at
/// 1e-600 took 4.4 s, at 1e-9000 minutes). Several curves share the bound: their squared digit
/// counts add up. `rodimpact solve` and `table` answer larger scenes exactly.
pub(crate) const MAX_SAMPLED_DIGITS: u64 = 700;

/// Refuses scenes whose exact samples would cost more than [`MAX_SAMPLED_DIGITS`] allows, naming
/// the input with the most digits (`ratios` for a family of mass ratios).
///
/// # Errors
/// `field: the figure samples its scene exactly at hundreds of points, and its numbers hold N
/// digits, more than 700 (limit for figures); ...`.
pub(crate) fn check_sampling_cost(scenes: &[Scene]) -> Result<(), Error> {
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
pub(crate) fn f(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// The impact point `k/PER_L` of l (exact).
pub(crate) fn point(scene: &Scene, k: i64) -> Q {
    Q::new(k.into(), PER_L.into()) * scene.half_length()
}

/// The scene solved exactly, by the library's solver, for the projectile striking at `a`;
/// beyond the rod's ends (|a| > l) this is the formula continued, drawn dashed.
///
/// # Errors
/// Only if the impulse system were singular, which it never is for a valid scene.
pub(crate) fn solve_at(scene: &Scene, a: &Q) -> Result<Outcome<Q>, Error> {
    let params = Params {
        a: a.clone(),
        ..scene.params::<Q>()
    };
    solve(&params).ok_or_else(|| {
        Error::new(
            "a",
            ErrorKind::Invalid(format!("the impulse equations are singular at a = {a}")),
        )
    })
}

/// The best impact point of one arm of the rod, in units of l from the centre.
#[derive(Debug, Clone)]
pub(crate) struct ArmOptimum {
    /// +1 for the arm towards +l, -1 towards -l.
    pub(crate) side: i8,
    /// The optimum of that arm (a* or d* and the maximum of |omega|).
    pub(crate) optimum: Optimum,
    /// a* (free) or p ± d* (pivot): where the formula peaks, in units of l (may be off the rod).
    pub(crate) peak_at: f64,
    /// |omega| at that peak, exactly: (1 + e) v0 / (2 a*).
    pub(crate) peak: QSqrt,
}

/// The optimum of each arm with room on it: a > 0 for a free rod (the other is its mirror
/// image), both sides of the pivot for a pivoted rod.
pub(crate) fn arm_optima(scene: &Scene) -> Result<Vec<ArmOptimum>, Error> {
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
        let o =
            optimum(&scene.with_a(end)?).expect("a rod at rest before the impact has an optimum");
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
        assert_eq!(solve_at(&s, &q(6, 5)).unwrap().after.omega, q(90, 79));
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
