//! The float formulas for the free rod, side by side: the paper's closed form ("naive"), the
//! exponent-carried stable form ("sq", the float route of `solve --backend`) and its compensated
//! variant ("scomp"). `docs/stability.md` describes them and their measured errors.

use super::{Ext, Real, compensated};
use crate::field::Q;
use crate::scene::{Groups, Motion};
use crate::scene::{Params, Scene, Support};
use crate::solve::fast::closed_form::closed_form;

/// A float formula for (v, V, omega) of a free rod.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FloatFormula {
    /// The paper's closed form `r = m/M`, `q = r + (m a/I) a`, `v = (q - e)/(1 + q) v0`
    /// ([`closed_form`]): intermediate products overflow or underflow on extreme scenes.
    Naive,
    /// The same formulas on [`Ext`] numbers (binary exponents carried as integers, exact
    /// power-of-two scaling): no intermediate overflow or underflow, one rounding at the end.
    /// The formula of `solve --backend f64/f32`.
    Sq,
    /// `Sq` with `q - e` from error-free transforms, so v stays accurate in the stop zone.
    Scomp,
}

impl FloatFormula {
    /// Every formula, cheapest first.
    pub const ALL: [FloatFormula; 3] = [FloatFormula::Naive, FloatFormula::Sq, FloatFormula::Scomp];

    /// Name in reports: `naive`, `sq`, `scomp`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::FloatFormula;
    /// assert_eq!(FloatFormula::Scomp.name(), "scomp");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            FloatFormula::Naive => "naive",
            FloatFormula::Sq => "sq",
            FloatFormula::Scomp => "scomp",
        }
    }

    /// (v, V, omega) after the impact of a free rod, in the float format `T`; `None` for a
    /// pivoted rod (the formulas cover the free rod). A naive division by zero gives NaN.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{solve::fast::float::FloatFormula, scene::Scene, field::q};
    /// // I = 10^-310 is subnormal: the naive m a/I overflows and v becomes NaN.
    /// let tiny = num_bigint::BigInt::from(10).pow(310);
    /// let s = Scene::builder(q(1, 1), q(1, 1))
    ///     .rod(rodimpact::scene::RodInertia::Moment(rodimpact::field::Q::new(1.into(), tiny)))
    ///     .build()?;
    /// let p = s.params::<f64>();
    /// assert!(FloatFormula::Naive.eval(&p).unwrap().v.is_nan());
    /// let stable = FloatFormula::Sq.eval(&p).unwrap();
    /// assert_eq!((stable.v, stable.omega), (1.0, 2.0));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn eval<T: Real>(self, p: &Params<T>) -> Option<Motion<T>> {
        if p.support != Support::Free {
            return None;
        }
        Some(match self {
            FloatFormula::Naive => closed_form(p).unwrap_or_else(|| {
                let nan = T::zero() / T::zero();
                Motion {
                    v: nan,
                    rod_v: nan,
                    omega: nan,
                }
            }),
            FloatFormula::Sq => plain(p)
                .or_else(|| scaled(p))
                .unwrap_or_else(|| stable(carried(p), false)),
            FloatFormula::Scomp => stable(carried(p), true),
        })
    }

    /// (v, V, omega) of a free-rod `scene`, from its exact rational inputs, in the float format
    /// `T`; `None` for a pivoted rod. The naive formula rounds each input to `T`, as a program
    /// reading them into `T` would (an input beyond the format's range becomes 0, a subnormal
    /// or infinity). The stable formulas rescale each input exactly by a power of two before
    /// rounding it ([`Ext::from_rational`]), so no input overflows or underflows: their answer
    /// is right wherever the output itself is a normal number of `T`. On scenes whose inputs
    /// are normal numbers of `T` both agree bit for bit with [`FloatFormula::eval`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{solve::fast::float::FloatFormula, scene::Scene, field::q, number::parse};
    /// // l = a = 10^-200: I = M l^2/3 = 10^-400/3 underflows f64 to 0.
    /// let l = parse("1e-200").expect("a number");
    /// let s = Scene::builder(q(1, 1), q(1, 1)).half_length(l.clone()).a(l).build()?;
    /// assert_eq!(s.params::<f64>().inertia, 0.0);
    /// assert!(FloatFormula::Sq.eval(&s.params::<f64>()).unwrap().omega.is_nan());
    /// // From the exact inputs: v = 3/5, V = 2/5, omega = 6/5 10^200.
    /// let x = FloatFormula::Sq.eval_scene::<f64>(&s).unwrap();
    /// assert_eq!((x.v, x.rod_v), (0.6, 0.4));
    /// assert!((x.omega / 1.2e200 - 1.0).abs() <= 2.0 * f64::EPSILON);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn eval_scene<T: Real>(self, scene: &Scene) -> Option<Motion<T>> {
        match self {
            FloatFormula::Naive => self.eval(&scene.params::<T>()),
            FloatFormula::Sq | FloatFormula::Scomp => {
                let p = scene.params::<Q>();
                if p.support != Support::Free {
                    return None;
                }
                let inputs = [&p.m, &p.rod_mass, &p.inertia, &p.a, &p.v0, &p.e];
                Some(stable(
                    inputs.map(Ext::from_rational),
                    self == FloatFormula::Scomp,
                ))
            }
        }
    }
}

/// The inputs (m, M, I, a, v0, e) with their exponents carried (exact).
fn carried<T: Real>(p: &Params<T>) -> [Ext<T>; 6] {
    [p.m, p.rod_mass, p.inertia, p.a, p.v0, p.e].map(Ext::new)
}

/// The operations of "sq" on plain floats, every intermediate kept (the fast paths check them).
struct Operations<T> {
    groups: Groups<T>,
    /// q - e.
    n: T,
    /// (1 + e)/d v0.
    gain: T,
    v: T,
    rod_v: T,
    omega: T,
}

impl<T: Real> Operations<T> {
    /// The operations of [`stable`] in this order, on the inputs (m, M, I, a, v0, e).
    fn of(m: T, rod_mass: T, inertia: T, a: T, v0: T, e: T) -> Operations<T> {
        let groups = Groups::of(&m, &rod_mass, &inertia, &a);
        let n = groups.q - e;
        let gain = (T::one() + e) / groups.d * v0;
        Operations {
            v: n / groups.d * v0,
            rod_v: gain * groups.r,
            omega: gain * groups.ma_over_i,
            groups,
            n,
            gain,
        }
    }
}

/// The widest binary exponent (as [`Real::frexp`] gives it) of the inputs for which every value
/// of "sq" is a normal number of `T` or an exact zero: (MAX_EXP - PRECISION - 11)/8, 120 for
/// f64 and 11 for f32.
///
/// With every input within 2^-(K+1) <= |x| < 2^K (a and e may also be 0): r = m/M and q = r +
/// m a^2/I lie above 2^(-2K-2), so q - e is 0 or at least one unit in the last place there,
/// 2^(-2K-1-PRECISION); d = 1 + q lies in [1, 2^(4K+6)); so v = (q - e)/d v0 is 0 or above
/// 2^(-7K-PRECISION-8), and every product and quotient (omega = (1 + e)/d v0 m a/I is the
/// largest) stays below 2^(5K+8). For K = 120 that is 2^-901 to 2^608, inside f64's normal
/// range 2^-1022 to 2^1024; for K = 11 (f32), 2^-109 to 2^63, inside 2^-126 to 2^128.
fn safe_exponent<T: Real>() -> i32 {
    (T::MAX_EXP - T::PRECISION as i32 - 11) / 8
}

/// The plain path of "sq": inputs within [`safe_exponent`] need no rescaling, since every value
/// is then normal (or an exact zero) and a power-of-two rescaling would change no rounding; so
/// the operations run on the inputs as they are, bit-identical to [`scaled`] and [`stable`].
/// `None` for inputs outside the range (the caller rescales).
fn plain<T: Real>(p: &Params<T>) -> Option<Motion<T>> {
    let k = safe_exponent::<T>();
    let within = |x: T| x.binade().is_some_and(|e| e.abs() <= k);
    let positive = [p.m, p.rod_mass, p.inertia, p.v0]
        .into_iter()
        .all(|x| x > T::zero() && within(x));
    let zero_or_within = [p.a, p.e].into_iter().all(|x| x.is_zero() || within(x));
    (positive && zero_or_within).then(|| {
        let o = Operations::of(p.m, p.rod_mass, p.inertia, p.a, p.v0, p.e);
        Motion {
            v: o.v,
            rod_v: o.rod_v,
            omega: o.omega,
        }
    })
}

/// The rescaling path of "sq": one exact power-of-two rescaling up front (masses
/// so that M is in [1/2, 1), lengths so that I/M is near 1), then the same operations as
/// [`stable`] in plain floats. While every intermediate is a normal number, each operation
/// rounds exactly like its [`Ext`] twin, so the result is bit-identical; otherwise `None` and
/// the caller takes the exponent-carried path (the limit branch).
fn scaled<T: Real>(p: &Params<T>) -> Option<Motion<T>> {
    let ok = |x: T| x.normal();
    let ok_or_zero = |x: T| x.normal() || x.is_zero();
    let mass_exponent = p.rod_mass.frexp().1;
    let half = (mass_exponent - p.inertia.frexp().1) / 2;
    let (mass_scale, length_scale) = (T::pow2(-mass_exponent), T::pow2(half));
    // I is scaled as a mass times an area in one exact product: scaled as a mass first, it
    // could pass through the subnormals and lose bits.
    let inertia_scale = T::pow2(2 * half - mass_exponent);
    let (m, rod_mass) = (p.m * mass_scale, p.rod_mass * mass_scale);
    let (inertia, a) = (p.inertia * inertia_scale, p.a * length_scale);
    let o = Operations::of(m, rod_mass, inertia, a, p.v0, p.e);
    let Groups {
        r,
        ma_over_i,
        s: arm,
        q,
        d,
    } = o.groups;
    let omega_out = o.omega * length_scale;
    let inputs = [
        mass_scale,
        length_scale,
        inertia_scale,
        m,
        rod_mass,
        inertia,
        p.v0,
    ];
    let normal = [r, q, d, o.gain, o.rod_v];
    let zero_with_a = [a, m * a, ma_over_i, arm, o.omega, omega_out];
    let fine = inputs.into_iter().chain(normal).all(ok)
        && (zero_with_a.into_iter().all(ok) || (p.a.is_zero() && omega_out.is_zero()))
        && (ok(o.v) || o.n.is_zero())
        && ok_or_zero(o.n);
    fine.then_some(Motion {
        v: o.v,
        rod_v: o.rod_v,
        omega: omega_out,
    })
}

/// The exponent-carried closed form of the inputs (m, M, I, a, v0, e); `compensated` takes
/// q - e from error-free transforms.
fn stable<T: Real>(inputs: [Ext<T>; 6], compensated: bool) -> Motion<T> {
    let [m, rod_mass, inertia, a, v0, e] = inputs;
    let one = Ext::new(T::one());
    let Groups {
        r, ma_over_i, q, d, ..
    } = Groups::of(&m, &rod_mass, &inertia, &a);
    let n = if compensated {
        compensated::numerator(m, rod_mass, inertia, a, e)
    } else {
        q - e
    };
    let gain = (one + e) / d * v0;
    Motion {
        v: (n / d * v0).value(),
        rod_v: (gain * r).value(),
        omega: (gain * ma_over_i).value(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stability::{suite, sweep};

    /// The fast path is bit-identical to the exponent-carried one wherever it answers, and it
    /// answers on the ordinary scenes (the point of having it).
    fn fast_path_matches<T: Real + std::fmt::Debug>(decades: i64) -> usize {
        let cases = suite()
            .into_iter()
            .chain(sweep(5, 300, decades))
            .chain(sweep(11, 300, decades));
        let mut taken = 0;
        for case in cases {
            let p = case.scene.params::<T>();
            if p.support != Support::Free {
                continue;
            }
            if let Some(fast) = scaled(&p) {
                let slow = stable(carried(&p), false);
                let same = |x: T, y: T| x == y && x.sign() == y.sign();
                assert!(
                    same(fast.v, slow.v) && same(fast.rod_v, slow.rod_v),
                    "{}: {fast:?} {slow:?} {:?}",
                    case.id,
                    (p.m, p.rod_mass, p.inertia, p.a, p.e)
                );
                assert!(
                    same(fast.omega, slow.omega),
                    "{} {:?} {:?} {:?}",
                    case.id,
                    fast.omega,
                    slow.omega,
                    (p.m, p.rod_mass, p.inertia, p.a, p.v0, p.e)
                );
                taken += 1;
            }
        }
        taken
    }

    /// On scenes whose inputs are normal numbers of the format, evaluating from the exact
    /// inputs (each rounded once, exponent carried) is bit-identical to evaluating the rounded
    /// inputs, for every formula; so the stability report measures the same floats either way.
    fn exact_inputs_change_nothing_in_range<T: Real + std::fmt::Debug>(decades: i64) -> usize {
        let cases = suite().into_iter().chain(sweep(11, 300, decades));
        let mut compared = 0;
        for case in cases.filter(|c| crate::stability::in_range::<T>(&c.scene)) {
            for formula in FloatFormula::ALL {
                let plain = formula.eval(&case.scene.params::<T>()).unwrap();
                let exact = formula.eval_scene::<T>(&case.scene).unwrap();
                let nan = |x: T| x.sign().is_none();
                let same = |x: T, y: T| (x == y && x.sign() == y.sign()) || (nan(x) && nan(y));
                assert!(
                    same(plain.v, exact.v)
                        && same(plain.rod_v, exact.rod_v)
                        && same(plain.omega, exact.omega),
                    "{} {}: {plain:?} {exact:?}",
                    case.id,
                    formula.name()
                );
            }
            compared += 1;
        }
        compared
    }

    #[test]
    fn evaluating_from_the_exact_inputs_is_bit_identical_in_range() {
        assert!(exact_inputs_change_nothing_in_range::<f64>(300) >= 100);
        assert!(exact_inputs_change_nothing_in_range::<f32>(36) >= 100);
    }

    /// Regression (issue 12): with a = 7.9e-343 the f64 input a underflowed to 0, so omega came
    /// out 0. From the exact inputs, every output that is a normal f64 is right: here the
    /// scene is scaled so that omega = 6/5 (a = l = 10^-400 with I = M l^2/3, v0 = 10^-400).
    #[test]
    fn outputs_in_range_are_right_whatever_the_inputs() {
        let tiny = crate::number::parse("1e-400").unwrap();
        let s = crate::scene::Scene::builder(crate::field::q(1, 1), crate::field::q(1, 1))
            .half_length(tiny.clone())
            .a(tiny.clone())
            .v0(tiny)
            .build()
            .unwrap();
        for formula in [FloatFormula::Sq, FloatFormula::Scomp] {
            let x = formula.eval_scene::<f64>(&s).unwrap();
            // v = 3/5 10^-400 and V = 2/5 10^-400 underflow to 0; omega = 6/5 exactly in Q.
            assert_eq!((x.v, x.rod_v), (0.0, 0.0), "{}", formula.name());
            assert!((x.omega - 1.2).abs() <= 2.0 * f64::EPSILON, "{}", x.omega);
        }
        let naive = FloatFormula::Naive.eval_scene::<f64>(&s).unwrap();
        assert!(naive.omega.is_nan(), "every input underflowed: 0/0");
    }

    /// Regression: the fast path scaled I by 2^-k(M) first and by the area scale after, so in
    /// f32 with M = 2^36 and I = 2^-88/3 (both normal) the intermediate I 2^-37 was subnormal
    /// and lost bits, and the outputs came out ulps away from the exponent-carried path (found
    /// by a seeded sweep). I is now scaled in one exact product.
    #[test]
    fn the_fast_path_never_scales_the_inertia_through_the_subnormals() {
        let two = |k: i32| {
            let p = num_bigint::BigInt::from(2).pow(k.unsigned_abs());
            if k >= 0 {
                Q::from_integer(p)
            } else {
                Q::new(1.into(), p)
            }
        };
        let inertia = two(-88) / Q::from_integer(3.into());
        let s = crate::scene::Scene::builder(crate::field::q(1, 1), two(36))
            .rod(crate::scene::RodInertia::Moment(inertia))
            .half_length(crate::field::q(1, 1))
            .a(-two(-45) / Q::from_integer(7.into()))
            .build()
            .unwrap();
        let p = s.params::<f32>();
        // frexp: M = 0.5 2^37, I = (2/3) 2^-89, so the area scale is 2^126 and I's is 2^89.
        let two_steps = p.inertia * f32::pow2(-37);
        assert!(!two_steps.normal());
        assert_ne!(two_steps * f32::pow2(126), p.inertia * f32::pow2(89));
        let fast = scaled(&p).expect("every scaled input is normal");
        assert_eq!(fast, stable(carried(&p), false));
    }

    proptest::proptest! {
        /// Inputs anywhere in the plain path's range (random exponents up to its edge, random
        /// mantissas, a and e sometimes 0): the plain path answers, and bit for bit as the
        /// exponent-carried path does; in f32 too.
        #[test]
        fn the_plain_path_is_bit_identical_in_its_range(
            exps in proptest::array::uniform6(-120i32..=120),
            mants in proptest::array::uniform6(0.5f64..1.0),
            zero_a in proptest::prelude::any::<bool>(),
            zero_e in proptest::prelude::any::<bool>(),
        ) {
            let x = |k: usize| mants[k] * f64::pow2(exps[k]);
            let p = Params {
                m: x(0),
                rod_mass: x(1),
                half_length: 1.0,
                inertia: x(2),
                a: if zero_a { 0.0 } else { -x(3) },
                v0: x(4),
                e: if zero_e { 0.0 } else { x(5) },
                support: Support::Free,
            };
            let fast = plain(&p).expect("inputs within the range");
            proptest::prop_assert_eq!(fast, stable(carried(&p), false));
            let small = |k: usize| (mants[k] * f64::pow2(exps[k] % 12)) as f32;
            let p32 = Params {
                m: small(0),
                rod_mass: small(1),
                half_length: 1.0f32,
                inertia: small(2),
                a: if zero_a { 0.0 } else { small(3) },
                v0: small(4),
                e: if zero_e { 0.0 } else { small(5) },
                support: Support::Free,
            };
            if let Some(fast) = plain(&p32) {
                proptest::prop_assert_eq!(fast, stable(carried(&p32), false));
            }
        }
    }

    #[test]
    fn the_scaled_fast_path_is_bit_identical_where_it_answers() {
        // Over +-300 (f64) and +-36 (f32) decades many scenes leave the range: the limit branch.
        let (wide64, wide32) = (fast_path_matches::<f64>(300), fast_path_matches::<f32>(36));
        assert!(wide64 >= 50 && wide32 >= 50, "{wide64} {wide32}");
        // Over +-30 (f64) and +-5 (f32) decades the fast path answers nearly always.
        let (near64, near32) = (fast_path_matches::<f64>(30), fast_path_matches::<f32>(5));
        assert!(near64 >= 300 && near32 >= 300, "{near64} {near32}");
        let paper = crate::scene::Scene::builder(crate::field::q(1, 1), crate::field::q(1, 1))
            .build()
            .unwrap();
        assert!(scaled(&paper.params::<f64>()).is_some());
    }
}
