//! The float formulas for the free rod, side by side: the paper's closed form ("naive"), the
//! exponent-carried stable form ("sq", the library's default float path) and its compensated
//! variant ("scomp"). STABILITY.md §2 defines them and measures their errors.

use super::{Ext, Real, compensated};
use crate::mechanics::Motion;
use crate::scene::{Params, Support};
use crate::solve::closed_form;

/// A float formula for (v, V, omega) of a free rod.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Formula {
    /// The paper's closed form `r = m/M`, `q = r + (m a/I) a`, `v = (q - e)/(1 + q) v0`
    /// ([`closed_form`]): intermediate products overflow or underflow on extreme scenes.
    Naive,
    /// The same formulas on [`Ext`] numbers (binary exponents carried as integers, exact
    /// power-of-two scaling): no intermediate overflow or underflow, one rounding at the end.
    Sq,
    /// `Sq` with `q - e` from error-free transforms, so v stays accurate in the stop zone.
    Scomp,
}

impl Formula {
    /// Every formula, cheapest first.
    pub const ALL: [Formula; 3] = [Formula::Naive, Formula::Sq, Formula::Scomp];

    /// The formula of the library's float path: [`Formula::Sq`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::float::Formula;
    /// assert_eq!(Formula::DEFAULT.name(), "sq");
    /// ```
    pub const DEFAULT: Formula = Formula::Sq;

    /// Name in reports: `naive`, `sq`, `scomp`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::float::Formula;
    /// assert_eq!(Formula::Scomp.name(), "scomp");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Formula::Naive => "naive",
            Formula::Sq => "sq",
            Formula::Scomp => "scomp",
        }
    }

    /// (v, V, omega) after the impact of a free rod, in the float format `T`; `None` for a
    /// pivoted rod (the formulas cover the free rod). A naive division by zero gives NaN.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{float::Formula, scene::Scene, field::q};
    /// // I = 10^-310 is subnormal: the naive m a/I overflows and v becomes NaN.
    /// let tiny = num_bigint::BigInt::from(10).pow(310);
    /// let s = Scene::builder(q(1, 1), q(1, 1))
    ///     .rod(rodimpact::scene::RodInertia::Moment(rodimpact::field::Q::new(1.into(), tiny)))
    ///     .build()?;
    /// let p = s.params::<f64>();
    /// assert!(Formula::Naive.eval(&p).unwrap().v.is_nan());
    /// let stable = Formula::Sq.eval(&p).unwrap();
    /// assert_eq!((stable.v, stable.omega), (1.0, 2.0));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn eval<T: Real>(self, p: &Params<T>) -> Option<Motion<T>> {
        if p.support != Support::Free {
            return None;
        }
        Some(match self {
            Formula::Naive => closed_form(p).unwrap_or_else(|| {
                let nan = T::zero() / T::zero();
                Motion {
                    v: nan,
                    rod_v: nan,
                    omega: nan,
                }
            }),
            Formula::Sq => scaled(p).unwrap_or_else(|| stable(p, false)),
            Formula::Scomp => stable(p, true),
        })
    }
}

/// The fast path of "sq" (STABILITY.md §2): one exact power-of-two rescaling up front (masses
/// so that M is in [1/2, 1), lengths so that I/M is near 1), then the same operations as
/// [`stable`] in plain floats. While every intermediate is a normal number, each operation
/// rounds exactly like its [`Ext`] twin, so the result is bit-identical; otherwise `None` and
/// the caller takes the exponent-carried path (the limit branch).
fn scaled<T: Real>(p: &Params<T>) -> Option<Motion<T>> {
    let ok = |x: T| x.normal();
    let ok_or_zero = |x: T| x.normal() || x.is_zero();
    let mass_scale = T::pow2(-p.rod_mass.frexp().1);
    let (m, rod_mass, inertia) = (
        p.m * mass_scale,
        p.rod_mass * mass_scale,
        p.inertia * mass_scale,
    );
    let half = (rod_mass.frexp().1 - inertia.frexp().1) / 2;
    let (length_scale, area_scale) = (T::pow2(half), T::pow2(2 * half));
    let (inertia, a) = (inertia * area_scale, p.a * length_scale);
    let one = T::one();
    let r = m / rod_mass;
    let ma_over_i = m * a / inertia;
    let arm = ma_over_i * a;
    let q = r + arm;
    let d = one + q;
    let n = q - p.e;
    let gain = (one + p.e) / d * p.v0;
    let (v, rod_v, omega) = (n / d * p.v0, gain * r, gain * ma_over_i);
    let omega_out = omega * length_scale;
    let inputs = [
        mass_scale,
        length_scale,
        area_scale,
        m,
        rod_mass,
        inertia,
        p.v0,
    ];
    let normal = [r, q, d, gain, rod_v];
    let zero_with_a = [a, m * a, ma_over_i, arm, omega, omega_out];
    let fine = inputs.into_iter().chain(normal).all(ok)
        && (zero_with_a.into_iter().all(ok) || (p.a.is_zero() && omega_out.is_zero()))
        && (ok(v) || n.is_zero())
        && ok_or_zero(n);
    fine.then_some(Motion {
        v,
        rod_v,
        omega: omega_out,
    })
}

/// The exponent-carried closed form; `compensated` takes q - e from error-free transforms.
fn stable<T: Real>(p: &Params<T>, compensated: bool) -> Motion<T> {
    let [m, rod_mass, inertia, a, v0, e] =
        [p.m, p.rod_mass, p.inertia, p.a, p.v0, p.e].map(Ext::new);
    let one = Ext::new(T::one());
    let r = m / rod_mass;
    let ma_over_i = m * a / inertia;
    let q = r + ma_over_i * a;
    let d = one + q;
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
        let cases = suite().into_iter().chain(sweep(5, 300, decades));
        let mut taken = 0;
        for case in cases {
            let p = case.scene.params::<T>();
            if p.support != Support::Free {
                continue;
            }
            if let Some(fast) = scaled(&p) {
                let slow = stable(&p, false);
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
