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
            Formula::Sq => stable(p, false),
            Formula::Scomp => stable(p, true),
        })
    }
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
