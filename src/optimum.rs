//! Where to strike for the fastest spin: the optimum a* and the maximum of omega, exactly.
//!
//! For a free rod omega depends on the impact distance a as
//! `omega(a) = (1 + e) v0 a / (a*^2 + a^2)` with `a*^2 = I (M + m)/(m M)`, so on a > 0 it peaks
//! at a = a* (the paper's Eq. (maximal-a-general)). For a rod on a pivot at p the same shape holds
//! in the distance d = |a - p| from the pivot, with `d*^2 = I_p / m`, `I_p = I + M p^2`.
//! On the rod, the maximum is at a* when a* lies on the rod and at the end otherwise.

use crate::field::{Q, QSqrt};
use crate::scene::{Scene, Support};
use num_traits::{One, Signed, Zero};

/// Where omega is largest over the impact points on the struck side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Argmax {
    /// At the interior optimum a* (or exactly at the end when a* = l).
    AStar,
    /// At the end of the rod: a* lies beyond it.
    End,
}

impl Argmax {
    /// The JSON spelling: `"a_star"` or `"end"`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::optimum::Argmax;
    /// assert_eq!(Argmax::End.as_str(), "end");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Argmax::AStar => "a_star",
            Argmax::End => "end",
        }
    }
}

/// The optimum of a scene: a*^2, whether a* is on the rod, and the exact maximum of omega.
#[derive(Debug, Clone, PartialEq)]
pub struct Optimum {
    /// a*^2 (free rod, measured from the centre) or d*^2 (pivot, measured from the pivot).
    pub squared: Q,
    /// The room on the struck side: l for a free rod, the distance from the pivot to the end
    /// on the side of the impact for a pivoted one.
    pub arm: Q,
    /// `a* <= arm`, decided exactly (a*^2 <= arm^2).
    pub within_rod: bool,
    /// Where the maximum of |omega| over the struck side is reached.
    pub argmax: Argmax,
    /// That maximum, exactly: `(1 + e) v0 / (2 a*)` at a*, or omega at the end.
    pub omega_max: QSqrt,
}

/// Computes the optimum of `scene` exactly: no float, no approximate square root.
///
/// # Examples
/// The paper's M = m uniform rod: a* = sqrt(2/3) l on the rod, omega_max = sqrt(3/2) v0/l.
/// ```
/// use rodimpact::{scene::Scene, optimum::{optimum, Argmax}, field::q};
/// let o = optimum(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap());
/// assert_eq!(o.squared, q(2, 3));
/// assert!(o.within_rod);
/// assert_eq!(o.argmax, Argmax::AStar);
/// assert_eq!(o.omega_max.to_string(), "1/2*sqrt(6)");
/// ```
pub fn optimum(scene: &Scene) -> Optimum {
    let m = scene.m();
    let big_m = scene.rod_mass();
    let l = scene.half_length();
    let inertia = scene.inertia();
    let (squared, arm) = match scene.support() {
        Support::Free => (&inertia * (big_m + m) / (m * big_m), l.clone()),
        Support::Pivot(p) => {
            let inertia_p = &inertia + big_m * p * p;
            (inertia_p / m, struck_arm(scene.a(), p, l))
        }
    };
    let within_rod = squared <= &arm * &arm;
    let scale = (Q::one() + scene.e()) * scene.v0();
    let (argmax, omega_max) = if within_rod {
        let half = &scale / Q::from_integer(2.into());
        let inverse_root = QSqrt::sqrt_of(&(Q::one() / &squared));
        (Argmax::AStar, inverse_root * &QSqrt::rational(half))
    } else {
        let at_end = scale * &arm / (&squared + &arm * &arm);
        (Argmax::End, QSqrt::rational(at_end))
    };
    Optimum {
        squared,
        arm,
        within_rod,
        argmax,
        omega_max,
    }
}

/// Distance from the pivot to the rod's end on the struck side (the longer arm when the
/// projectile hits the pivot itself).
fn struck_arm(a: &Q, p: &Q, l: &Q) -> Q {
    let side_positive = match (a - p).signum() {
        s if s.is_zero() => !p.is_positive(),
        s => s.is_positive(),
    };
    if side_positive { l - p } else { l + p }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Field, q};
    use crate::solve::solve;

    fn scene(m: Q, big_m: Q) -> crate::scene::SceneBuilder {
        Scene::builder(m, big_m)
    }

    #[test]
    fn paper_threshold_m_equals_2m_puts_a_star_at_the_end() {
        let o = optimum(&scene(q(1, 1), q(2, 1)).build().unwrap());
        assert_eq!(o.squared, q(1, 1));
        assert!(o.within_rod);
        // omega_max = v0/l at a* = l, and equals omega at the end from the solver.
        let at_end = solve(&scene(q(1, 1), q(2, 1)).build().unwrap().params::<Q>()).unwrap();
        assert_eq!(o.omega_max, QSqrt::rational(at_end.after.omega));
    }

    #[test]
    fn heavy_rod_peaks_at_the_end() {
        let s = scene(q(1, 1), q(3, 1)).build().unwrap();
        let o = optimum(&s);
        assert_eq!(o.squared, q(4, 3));
        assert!(!o.within_rod);
        assert_eq!(o.argmax, Argmax::End);
        let at_end = solve(&s.params::<Q>()).unwrap();
        assert_eq!(o.omega_max, QSqrt::rational(at_end.after.omega));
    }

    #[test]
    fn optimum_beats_the_end_for_a_light_rod() {
        let s = scene(q(1, 1), q(1, 1)).build().unwrap();
        let o = optimum(&s);
        let at_end = QSqrt::rational(solve(&s.params::<Q>()).unwrap().after.omega);
        assert_eq!(
            (o.omega_max.clone() - at_end).sign(),
            Some(std::cmp::Ordering::Greater)
        );
    }

    #[test]
    fn pivot_optimum_is_measured_from_the_pivot() {
        // Uniform rod M = 3, l = 1, pivot at the end p = -1: I_p = 1 + 3 = 4, d*^2 = 4/m.
        let s = scene(q(1, 1), q(3, 1)).pivot(q(-1, 1)).build().unwrap();
        let o = optimum(&s);
        assert_eq!((o.squared.clone(), o.arm.clone()), (q(4, 1), q(2, 1)));
        assert!(o.within_rod); // d* = 2 = the whole rod: a door is best hit at its edge iff M >= 3m
        let s = scene(q(2, 1), q(3, 1)).pivot(q(-1, 1)).build().unwrap();
        assert_eq!(optimum(&s).squared, q(2, 1));
    }

    #[test]
    fn struck_side_decides_the_arm() {
        assert_eq!(struck_arm(&q(1, 2), &q(-1, 2), &q(1, 1)), q(3, 2));
        assert_eq!(struck_arm(&q(-1, 1), &q(-1, 2), &q(1, 1)), q(1, 2));
        assert_eq!(struck_arm(&q(1, 2), &q(1, 2), &q(1, 1)), q(3, 2));
        assert_eq!(struck_arm(&q(0, 1), &q(0, 1), &q(1, 1)), q(1, 1));
    }
}
