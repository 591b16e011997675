//! Where to strike for the fastest spin: the optimum a* and the maximum of omega, exactly.
//!
//! For a free rod omega depends on the impact distance a as
//! `omega(a) = (1 + e) v0 a / (a*^2 + a^2)` with `a*^2 = I (M + m)/(m M)`, so on a > 0 it peaks
//! at a = a* (the paper's Eq. (maximal-a-general)). For a rod on a pivot at p the same shape holds
//! in the distance d = |a - p| from the pivot, with `d*^2 = I_p / m`, `I_p = I + M p^2`.
//! On the rod, the maximum is at a* when a* lies on the rod and at the end otherwise.

use crate::field::{Field, Q, QSqrt, RatFn};
use crate::scene::{Params, Scene, Support};
use crate::solve::fast::linear::motion_after;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

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
    /// use rodimpact::solve::optimum::Argmax;
    /// assert_eq!(Argmax::End.as_str(), "end");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Argmax::AStar => "a_star",
            Argmax::End => "end",
        }
    }
}

/// Where a* lies relative to the end of the struck arm, decided exactly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Placement {
    /// a* < arm: the fastest spin comes from an interior point (the paper's surprise).
    Inside,
    /// a* = arm exactly (the uniform free rod at M = 2m).
    AtEnd,
    /// a* > arm: unphysical; omega increases all the way to the end.
    Beyond,
}

impl Placement {
    /// `inside`, `at the end` or `beyond the end`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::optimum::Placement;
    /// assert_eq!(Placement::AtEnd.as_str(), "at the end");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Placement::Inside => "inside",
            Placement::AtEnd => "at the end",
            Placement::Beyond => "beyond the end",
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
    /// a* against the end of the arm: inside, exactly at the end, or beyond it.
    pub placement: Placement,
    /// |omega| when the end of the arm is struck.
    pub omega_end: Q,
    /// The rod mass at which a* reaches the end, the mass distribution (I/M) and everything
    /// else fixed: a* is on the rod iff M <= this. `None` for a dumbbell-like free rod
    /// (r_G = l), whose a* is beyond the end for every mass.
    pub threshold_mass: Option<Q>,
    /// A pivoted rod's other arm, on the far side of the pivot from the impact, when it has a
    /// length: the same curve of omega in the distance from the pivot holds there, so the
    /// rod's largest |omega| may lie on it (`None` for a free rod, whose two halves mirror
    /// each other, and for a pivot at an end).
    pub other_arm: Option<ArmPeak>,
}

/// The largest |omega| over the impact points of one arm of a pivoted rod.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmPeak {
    /// The arm's length, from the pivot to its end.
    pub arm: Q,
    /// Where on the arm the maximum is reached.
    pub argmax: Argmax,
    /// The maximum, exactly.
    pub omega_max: QSqrt,
}

/// Which arm of a pivoted rod gives the rod's largest |omega|.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arm {
    /// The arm the projectile strikes (also when both arms give the same maximum).
    Struck,
    /// The arm on the far side of the pivot.
    Other,
}

impl Arm {
    /// The JSON spelling: `"struck"` or `"other"`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::optimum::Arm;
    /// assert_eq!(Arm::Other.as_str(), "other");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Arm::Struck => "struck",
            Arm::Other => "other",
        }
    }
}

impl Optimum {
    /// `omega(end)/omega_max`, exactly (1 when the maximum is at the end).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::optimum::optimum, field::q};
    /// let o = optimum(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap()).unwrap();
    /// assert_eq!(o.end_to_max().to_string(), "2*sqrt(6)/5");
    /// ```
    pub fn end_to_max(&self) -> QSqrt {
        QSqrt::rational(self.omega_end.clone()) / &self.omega_max
    }

    /// The gain from aiming at a* instead of the end: `omega_max/omega(end) - 1`, exactly.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::optimum::optimum, field::q};
    /// let o = optimum(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap()).unwrap();
    /// assert_eq!(o.gain().to_string(), "-1 + 5*sqrt(6)/12"); // about 2.06 %
    /// ```
    pub fn gain(&self) -> QSqrt {
        self.omega_max.clone() / &QSqrt::rational(self.omega_end.clone()) - &QSqrt::one()
    }

    /// The largest |omega| over the whole rod and the arm that gives it: the struck side's
    /// maximum for a free rod; for a pivoted rod the larger of the two arms' (decided exactly).
    ///
    /// # Examples
    /// A uniform rod (M = m, l = 1) on a pivot at p = 1/2 struck at a = 3/4: the struck arm
    /// (1/2 long) peaks at its end, 6/5; d* = sqrt(21)/6 lies on the other arm (3/2 long), where
    /// |omega| reaches v0/d* = 2 sqrt(21)/7.
    /// ```
    /// use rodimpact::{scene::Scene, solve::optimum::{optimum, Arm}, field::q};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).pivot(q(1, 2)).a(q(3, 4)).build()?;
    /// let o = optimum(&s).unwrap();
    /// assert_eq!(o.omega_max.to_string(), "6/5");
    /// let (max, arm) = o.rod_max();
    /// assert_eq!((max.to_string(), arm), ("2*sqrt(21)/7".to_string(), Arm::Other));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn rod_max(&self) -> (&QSqrt, Arm) {
        match &self.other_arm {
            Some(other) if other.omega_max.cmp_exact(&self.omega_max) == Ordering::Greater => {
                (&other.omega_max, Arm::Other)
            }
            _ => (&self.omega_max, Arm::Struck),
        }
    }
}

/// The paper's argument made explicit: `omega(x) = K f(x)` with `f(x) = x/(b^2 + c^2 x^2)`,
/// x the distance of the impact from the centre (free rod) or from the pivot, so the maximum
/// over x > 0 is at x = b/c = a*.
#[derive(Debug, Clone, PartialEq)]
pub struct PaperForm {
    /// The constant K = (1 + e) v0.
    pub k: Q,
    /// b^2 = I (1/m + 1/M) for a free rod, I_p/m for a pivoted one.
    pub b_squared: Q,
    /// c = 1.
    pub c: Q,
}

impl PaperForm {
    /// The form of `scene`'s omega.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::optimum::PaperForm, field::q};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
    /// let f = PaperForm::of(&s);
    /// assert_eq!((&f.k, &f.b_squared, &f.c), (&q(2, 1), &q(2, 3), &q(1, 1)));
    /// assert!(f.verify(&s));
    /// ```
    pub fn of(scene: &Scene) -> PaperForm {
        PaperForm {
            k: (Q::one() + scene.e()) * scene.v0(),
            b_squared: a_star_squared(&scene.params::<Q>()),
            c: Q::one(),
        }
    }

    /// Checks `omega(a) = K f(a - p)` as an identity in the impact point `a` (a symbol; every
    /// other parameter the scene's exact value), with omega from the generic solver over
    /// rational functions.
    pub fn verify(&self, scene: &Scene) -> bool {
        let lifted: Params<RatFn> = scene.params();
        let a = RatFn::symbol("a");
        let params = Params {
            a: a.clone(),
            ..lifted
        };
        let Some(after) = motion_after(&params) else {
            return false;
        };
        let x = a - &params.axis();
        let c = RatFn::from_rational(&self.c);
        let f = x.clone() / (RatFn::from_rational(&self.b_squared) + &(c.square() * &x * &x));
        (after.omega - &(RatFn::from_rational(&self.k) * &f)).is_identically_zero()
    }

    /// `b/c`, the argmax of f on x > 0, as an exact square root.
    pub fn argmax(&self) -> QSqrt {
        QSqrt::sqrt_of(&(&self.b_squared / (&self.c * &self.c)))
    }
}

/// a*^2 = I (M + m)/(m M) for a free rod (from the centre), d*^2 = I_p/m for a pivoted one
/// (from the pivot), over any field (numbers, or rational functions for symbolic checks).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::optimum::a_star_squared, field::{q, Q}};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// assert_eq!(a_star_squared(&s.params::<Q>()), q(2, 3));
/// ```
pub fn a_star_squared<F: Field>(p: &Params<F>) -> F {
    let (m, big_m) = (&p.m, &p.rod_mass);
    match &p.support {
        Support::Free => p.inertia.clone() * &(big_m.clone() + m) / (m.clone() * big_m),
        Support::Pivot(_) => p.inertia_about_axis() / m.clone(),
    }
}

/// Computes the optimum of `scene` exactly: no float, no approximate square root; `None` when
/// the rod turns before the impact (the approach speed v0 - (V0 + omega0 a) then depends on a,
/// and omega(a) is no longer the paper's curve). An oblique or frictional scene, or a rod
/// drifting without turning, has the optimum of its normal problem ([`Scene::normal_problem`]):
/// friction and drift leave a* unchanged (X27, X31) and scale omega_max with the approach speed.
///
/// # Examples
/// The paper's M = m uniform rod: a* = sqrt(2/3) l on the rod, omega_max = sqrt(3/2) v0/l.
/// ```
/// use rodimpact::{scene::Scene, solve::optimum::{optimum, Argmax}, field::q};
/// let o = optimum(&Scene::builder(q(1, 1), q(1, 1)).build()?).expect("the rod is at rest");
/// assert_eq!(o.squared, q(2, 3));
/// assert!(o.within_rod);
/// assert_eq!(o.argmax, Argmax::AStar);
/// assert_eq!(o.omega_max.to_string(), "sqrt(6)/2");
/// // A rod turning before the impact has no such optimum.
/// let turning = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).rod_before(q(0, 1), q(0, 1), q(1, 1)).build()?;
/// assert!(optimum(&turning).is_none());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn optimum(scene: &Scene) -> Option<Optimum> {
    if !scene.rod_before().omega.is_zero() {
        return None;
    }
    Some(match scene.oblique() {
        None => of_rod_at_rest(scene),
        Some(_) => of_rod_at_rest(&scene.normal_problem()),
    })
}

/// The square of the largest |omega| an impact on the struck side can give (the square of
/// [`Optimum::omega_max`]), without a square root, in any ordered exact field: (1 + e)^2 v0^2 /
/// (4 a*^2) when a* lies on the rod, else omega at the end squared; `None` when the rod turns
/// before the impact. What a bound on a claimed spin needs, at a rational's cost.
///
/// # Examples
/// The paper's M = m uniform rod: omega_max = sqrt(3/2) v0/l.
/// ```
/// use rodimpact::{scene::Scene, solve::optimum::omega_max_squared, field::{q, Q}};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build()?;
/// assert_eq!(omega_max_squared::<Q>(&s), Some(q(3, 2)));
/// // M = 3m: a* = sqrt(4/3) l lies beyond the end, so omega_max is omega at the end, 6/7.
/// let heavy = Scene::builder(q(1, 1), q(3, 1)).build()?;
/// assert_eq!(omega_max_squared::<Q>(&heavy), Some(q(36, 49)));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn omega_max_squared<F: Field>(scene: &Scene) -> Option<F> {
    if !scene.rod_before().omega.is_zero() {
        return None;
    }
    let normal;
    let scene = match scene.oblique() {
        None => scene,
        Some(_) => {
            normal = scene.normal_problem();
            &normal
        }
    };
    Some(omega_max_squared_of(&scene.params::<F>()))
}

/// [`omega_max_squared`] of a scene at rest given by its parameters in `F` (a rod at rest
/// before a normal impact): what a batch row's audit takes, in whatever exact field its
/// numbers are.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::optimum::omega_max_squared_of, field::{q, Q}};
/// let s = Scene::builder(q(1, 1), q(3, 1)).build()?;
/// assert_eq!(omega_max_squared_of(&s.params::<Q>()), q(36, 49));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn omega_max_squared_of<F: Field>(p: &Params<F>) -> F {
    let squared = a_star_squared(p);
    let arm = struck_arm(p);
    let peak = Peak::of(p, &squared, &arm);
    if peak.within_rod(&squared, &arm) {
        peak.half.square() / squared
    } else {
        peak.at_end.square()
    }
}

/// The rational parts of omega's peak over the struck side: half of (1 + e) v0, and omega at
/// the end of the arm.
struct Peak<F> {
    half: F,
    at_end: F,
}

impl<F: Field> Peak<F> {
    fn of(p: &Params<F>, squared: &F, arm: &F) -> Peak<F> {
        let scale = (F::one() + &p.e) * &p.v0;
        Peak {
            half: scale.clone() / F::from_i64(2),
            at_end: scale * arm / (squared.clone() + &arm.square()),
        }
    }

    /// a* <= arm, decided exactly.
    fn within_rod(&self, squared: &F, arm: &F) -> bool {
        (arm.square() - squared).sign() != Some(Ordering::Less)
    }
}

/// The arm struck: l for a free rod, the end on the struck side from the pivot for a pivoted one
/// (`l - p` toward `+l`, `l + p` toward `-l`).
fn struck_arm<F: Field>(params: &Params<F>) -> F {
    let l = params.half_length.clone();
    match &params.support {
        Support::Free => l,
        Support::Pivot(p) if struck_toward_plus(&params.a, p) => l - p,
        Support::Pivot(p) => l + p,
    }
}

/// Whether the end struck from the pivot `p` is `+l`: the side of `a`, or when the pivot itself
/// is struck the longer arm's (`+l` for `p <= 0`).
fn struck_toward_plus<F: Field>(a: &F, p: &F) -> bool {
    match (a.clone() - p).sign() {
        Some(Ordering::Equal) => p.sign() != Some(Ordering::Greater),
        side => side == Some(Ordering::Greater),
    }
}

/// The end of the rod on the struck side, `l` or `-l`: the paper's end `l` for a free rod; on a
/// pivot the end on the impact's side of it (the longer arm when the pivot itself is struck).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::optimum::struck_end, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).pivot(q(1, 2)).a(q(-1, 4)).build()?;
/// assert_eq!(struck_end(&s), q(-1, 1));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn struck_end(scene: &Scene) -> Q {
    let l = scene.half_length().clone();
    let Support::Pivot(p) = scene.support() else {
        return l;
    };
    if struck_toward_plus(scene.a(), p) {
        l
    } else {
        -l
    }
}

/// The optimum of a scene whose rod does not turn before the impact.
fn of_rod_at_rest(scene: &Scene) -> Optimum {
    let (m, big_m) = (scene.m(), scene.rod_mass());
    let l = scene.half_length();
    let params = scene.params::<Q>();
    let squared: Q = a_star_squared(&params);
    let gyration_squared = scene.inertia() / big_m;
    let arm = struck_arm(&params);
    let threshold_mass = match scene.support() {
        Support::Free => {
            let excess = l * l - &gyration_squared;
            excess.is_positive().then(|| m * excess / &gyration_squared)
        }
        Support::Pivot(p) => Some(m * &arm * &arm / (gyration_squared + p * p)),
    };
    let placement = match squared.cmp(&(&arm * &arm)) {
        Ordering::Less => Placement::Inside,
        Ordering::Equal => Placement::AtEnd,
        Ordering::Greater => Placement::Beyond,
    };
    let peak = Peak::of(&params, &squared, &arm);
    let within_rod = peak.within_rod(&squared, &arm);
    let struck = ArmPeak::of(&params, &squared, &arm);
    let other_arm = match scene.support() {
        Support::Free => None,
        Support::Pivot(_) => {
            let other = l.clone() + l - &arm;
            (!other.is_zero()).then(|| ArmPeak::of(&params, &squared, &other))
        }
    };
    Optimum {
        squared,
        arm,
        within_rod,
        argmax: struck.argmax,
        omega_max: struck.omega_max,
        placement,
        omega_end: peak.at_end,
        threshold_mass,
        other_arm,
    }
}

impl ArmPeak {
    /// The peak of omega over an arm of length `arm` (from the centre of a free rod, from the
    /// pivot of a pivoted one): at a* when a* lies on it, else at its end.
    fn of(params: &Params<Q>, squared: &Q, arm: &Q) -> ArmPeak {
        let peak = Peak::of(params, squared, arm);
        let (argmax, omega_max) = if peak.within_rod(squared, arm) {
            let inverse_root = QSqrt::sqrt_of(&(Q::one() / squared));
            (Argmax::AStar, inverse_root * &QSqrt::rational(peak.half))
        } else {
            (Argmax::End, QSqrt::rational(peak.at_end))
        };
        ArmPeak {
            arm: arm.clone(),
            argmax,
            omega_max,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Field, q};
    use crate::solve::fast::linear::solve;

    fn scene(m: Q, big_m: Q) -> crate::scene::SceneBuilder {
        Scene::builder(m, big_m)
    }

    #[test]
    fn paper_threshold_m_equals_2m_puts_a_star_at_the_end() {
        let o = optimum(&scene(q(1, 1), q(2, 1)).build().unwrap()).unwrap();
        assert_eq!(o.squared, q(1, 1));
        assert!(o.within_rod);
        // omega_max = v0/l at a* = l, and equals omega at the end from the solver.
        let at_end = solve(&scene(q(1, 1), q(2, 1)).build().unwrap().params::<Q>()).unwrap();
        assert_eq!(o.omega_max, QSqrt::rational(at_end.after.omega));
    }

    #[test]
    fn heavy_rod_peaks_at_the_end() {
        let s = scene(q(1, 1), q(3, 1)).build().unwrap();
        let o = optimum(&s).unwrap();
        assert_eq!(o.squared, q(4, 3));
        assert!(!o.within_rod);
        assert_eq!(o.argmax, Argmax::End);
        let at_end = solve(&s.params::<Q>()).unwrap();
        assert_eq!(o.omega_max, QSqrt::rational(at_end.after.omega));
    }

    #[test]
    fn optimum_beats_the_end_for_a_light_rod() {
        let s = scene(q(1, 1), q(1, 1)).build().unwrap();
        let o = optimum(&s).unwrap();
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
        let o = optimum(&s).unwrap();
        assert_eq!((o.squared.clone(), o.arm.clone()), (q(4, 1), q(2, 1)));
        assert!(o.within_rod); // d* = 2 = the whole rod: a door is best hit at its edge iff M >= 3m
        let s = scene(q(2, 1), q(3, 1)).pivot(q(-1, 1)).build().unwrap();
        assert_eq!(optimum(&s).unwrap().squared, q(2, 1));
    }

    #[test]
    fn thresholds_are_where_a_star_reaches_the_end() {
        // Uniform free rod: M = 2m; dumbbell: never inside; door (pivot at an end): M = 3m.
        let o = optimum(&scene(q(1, 1), q(5, 1)).build().unwrap()).unwrap();
        assert_eq!(o.threshold_mass, Some(q(2, 1)));
        let o = optimum(
            &scene(q(1, 1), q(5, 1))
                .rod(crate::scene::RodInertia::Dumbbell)
                .build()
                .unwrap(),
        )
        .unwrap();
        assert_eq!(o.threshold_mass, None);
        assert_eq!(o.placement, Placement::Beyond);
        let o = optimum(&scene(q(1, 1), q(5, 1)).pivot(q(-1, 1)).build().unwrap()).unwrap();
        assert_eq!(o.threshold_mass, Some(q(3, 1)));
        // At the threshold itself a* is exactly at the end.
        let o = optimum(&scene(q(1, 1), q(2, 1)).build().unwrap()).unwrap();
        assert_eq!(o.placement, Placement::AtEnd);
        assert_eq!(o.end_to_max(), QSqrt::one());
    }

    #[test]
    fn paper_form_matches_the_solver_for_every_kind_of_scene() {
        let scenes = [
            scene(q(1, 1), q(1, 1)).build().unwrap(),
            scene(q(2, 3), q(5, 7))
                .e(q(1, 3))
                .rod(crate::scene::RodInertia::Gyration(q(1, 2)))
                .build()
                .unwrap(),
            scene(q(1, 1), q(3, 1))
                .pivot(q(-1, 2))
                .e(q(0, 1))
                .build()
                .unwrap(),
        ];
        for s in scenes {
            let form = PaperForm::of(&s);
            assert!(form.verify(&s), "{s:?}");
            assert_eq!(form.argmax(), QSqrt::sqrt_of(&optimum(&s).unwrap().squared));
            let wrong = PaperForm {
                b_squared: &form.b_squared * q(2, 1),
                ..form
            };
            assert!(!wrong.verify(&s), "a wrong b must not verify");
        }
    }

    #[test]
    fn struck_side_decides_the_arm() {
        // The arm from the pivot p to the struck end, a and l as given.
        let struck_arm = |a: &Q, p: &Q, l: &Q| {
            struck_arm::<Q>(
                &scene(q(1, 1), q(1, 1))
                    .half_length(l.clone())
                    .a(a.clone())
                    .pivot(p.clone())
                    .build()
                    .unwrap()
                    .params(),
            )
        };
        assert_eq!(struck_arm(&q(1, 2), &q(-1, 2), &q(1, 1)), q(3, 2));
        assert_eq!(struck_arm(&q(-1, 1), &q(-1, 2), &q(1, 1)), q(1, 2));
        assert_eq!(struck_arm(&q(1, 2), &q(1, 2), &q(1, 1)), q(3, 2));
        assert_eq!(struck_arm(&q(0, 1), &q(0, 1), &q(1, 1)), q(1, 1));
    }
}
