//! Exact error measurement: a float result converted exactly (`Ratio::from_float`) and compared
//! with the exact answer for the same rational inputs. The arithmetic runs over dashu's
//! rationals ([`RBig`]): the stability sweep's exact answers have hundreds of digits, where
//! num-rational's binary GCD was most of the report's time.

use crate::field::big::{RBig, to_q, to_rbig};
use crate::field::{Interval, Q, abs};
use crate::solve::fast::float::Real;
use num_traits::{Signed, ToPrimitive, Zero};

/// What a float output is, judged against the exact value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// A finite number (possibly a correct zero).
    Number,
    /// NaN.
    Nan,
    /// An infinity (or an infinite interval end).
    Infinite,
    /// 0 where the exact value is not 0.
    SpuriousZero,
    /// Not 0 where the exact value is 0 (expected in the stop zone: only exact arithmetic
    /// decides v = 0).
    MissedZero,
}

/// The accuracy of one float output, measured exactly against its exact value.
#[derive(Debug, Clone, PartialEq)]
pub struct Accuracy {
    /// |float - exact|/|exact| exactly (0 when both are 0); `None` when undefined (NaN,
    /// infinite, or nonzero where the exact value is 0).
    pub rel_error: Option<Q>,
    /// `rel_error / (cond u)` in f64; `None` when either is undefined (cond infinite).
    pub ratio: Option<f64>,
    /// Kind of output.
    pub class: Class,
}

impl Accuracy {
    /// Measures the float `x` against `exact`, with condition number `cond` (`None`:
    /// infinite) and unit roundoff `u`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, solve::fast::float::Real, stability::{Class, Accuracy}};
    /// let m = Accuracy::of(1.0f64 / 3.0, &q(1, 3), Some(&q(1, 1)), &<f64 as Real>::unit_roundoff());
    /// assert_eq!(m.class, Class::Number);
    /// assert!(m.ratio.unwrap() <= 1.0); // correctly rounded: at most u
    /// ```
    pub fn of<T: Real>(x: T, exact: &Q, cond: Option<&Q>, u: &Q) -> Accuracy {
        let cond = cond.map(to_rbig);
        Accuracy::of_big(x, &to_rbig(exact), cond.as_ref(), &to_rbig(u))
    }

    /// [`Accuracy::of`] with the exact numbers over dashu.
    pub(crate) fn of_big<T: Real>(x: T, exact: &RBig, cond: Option<&RBig>, u: &RBig) -> Accuracy {
        match x.to_exact() {
            None if x.finite() => unreachable!("finite floats are rationals"),
            None if x.sign().is_none() => Accuracy::undefined(Class::Nan),
            None => Accuracy::undefined(Class::Infinite),
            Some(value) => {
                let value = to_rbig(&value);
                Accuracy::distance(abs(value.clone() - exact), exact, cond, u, &value)
            }
        }
    }

    /// Measures an interval by its worst point: the larger distance of an end from `exact`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::{q, Field, Interval}, solve::fast::float::Real, stability::Accuracy};
    /// let third = Interval::from_rational(&q(1, 3));
    /// let m = Accuracy::of_interval(&third, &q(1, 3), Some(&q(1, 1)), &<f64 as Real>::unit_roundoff());
    /// assert!(m.ratio.unwrap() <= 2.0); // one ulp wide
    /// ```
    pub fn of_interval(x: &Interval, exact: &Q, cond: Option<&Q>, u: &Q) -> Accuracy {
        let cond = cond.map(to_rbig);
        Accuracy::of_big_interval(x, &to_rbig(exact), cond.as_ref(), &to_rbig(u))
    }

    /// [`Accuracy::of_interval`] with the exact numbers over dashu.
    pub(crate) fn of_big_interval(
        x: &Interval,
        exact: &RBig,
        cond: Option<&RBig>,
        u: &RBig,
    ) -> Accuracy {
        match (x.lower().to_exact(), x.upper().to_exact()) {
            (Some(lo), Some(hi)) => {
                let (lo, hi) = (to_rbig(&lo), to_rbig(&hi));
                let far = abs(lo.clone() - exact).max(abs(hi.clone() - exact));
                let point = if lo.is_zero() && hi.is_zero() { lo } else { hi };
                Accuracy::distance(far, exact, cond, u, &point)
            }
            _ if x.lower().is_nan() || x.upper().is_nan() => Accuracy::undefined(Class::Nan),
            _ => Accuracy::undefined(Class::Infinite),
        }
    }

    /// Measures an exact result (its error is 0 unless the exact path is wrong).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, stability::Accuracy};
    /// assert_eq!(Accuracy::of_exact(&q(1, 3), &q(1, 3)).ratio, Some(0.0));
    /// ```
    pub fn of_exact(x: &Q, exact: &Q) -> Accuracy {
        let gap = (x - exact).abs();
        let rel = if exact.is_zero() {
            gap
        } else {
            gap / exact.abs()
        };
        Accuracy {
            ratio: rel.to_f64(),
            rel_error: Some(rel),
            class: Class::Number,
        }
    }

    fn undefined(class: Class) -> Accuracy {
        Accuracy {
            rel_error: None,
            ratio: None,
            class,
        }
    }

    fn distance(gap: RBig, exact: &RBig, cond: Option<&RBig>, u: &RBig, value: &RBig) -> Accuracy {
        if exact.is_zero() {
            return if gap.is_zero() {
                Accuracy {
                    rel_error: Some(Q::zero()),
                    ratio: Some(0.0),
                    class: Class::Number,
                }
            } else {
                Accuracy::undefined(Class::MissedZero)
            };
        }
        let rel = gap / abs(exact.clone());
        let ratio = cond.map(|c| {
            to_q(&(rel.clone() / (c.clone() * u)))
                .to_f64()
                .unwrap_or(f64::INFINITY)
        });
        Accuracy {
            rel_error: Some(to_q(&rel)),
            ratio,
            class: if value.is_zero() {
                Class::SpuriousZero
            } else {
                Class::Number
            },
        }
    }

    /// `cond u <= 1e-3`: well enough conditioned to trust a float (one of the conditions of
    /// `reliable` in `docs/stability.md`; [`super::judge`] checks the others).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, stability::Accuracy};
    /// let u = q(1, 1 << 20);
    /// assert!(Accuracy::well_conditioned(Some(&q(1, 1)), &u));
    /// assert!(!Accuracy::well_conditioned(Some(&q(10_000, 1)), &u));
    /// assert!(!Accuracy::well_conditioned(None, &u));
    /// ```
    pub fn well_conditioned(cond: Option<&Q>, u: &Q) -> bool {
        cond.is_some_and(|c| c * u <= Q::new(1.into(), 1000.into()))
    }
}
