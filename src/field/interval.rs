//! [`Interval`]: an outward-rounded `f64` interval, a [`Field`] backend whose enclosure always
//! contains the exact value of the same computation over Q.
//!
//! Every operation rounds its lower end down and its upper end up by one step
//! (`f64::next_down`/`next_up`) after round-to-nearest, which encloses the exact result because a
//! round-to-nearest error is at most half a step. Overflow widens to an infinite end, and a
//! division by an interval containing 0 gives the whole line: an enclosure is never lost, only
//! widened.

use super::{Field, Q};
use num_rational::Ratio;
use num_traits::{One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` of reals with `f64` ends (infinite ends allowed).
///
/// # Examples
/// ```
/// use rodimpact::field::{Field, Interval, q};
/// let third = Interval::from_rational(&q(1, 3));
/// assert!(third.contains(&q(1, 3)));
/// let x = third.clone() + &third + &third; // encloses 1
/// assert!(x.contains(&q(1, 1)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

impl Interval {
    /// The interval `[lo, hi]`; a NaN end becomes the infinite end on its side.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Interval;
    /// assert_eq!(Interval::new(f64::NAN, 1.0).lower(), f64::NEG_INFINITY);
    /// ```
    pub fn new(lo: f64, hi: f64) -> Interval {
        Interval {
            lo: if lo.is_nan() { f64::NEG_INFINITY } else { lo },
            hi: if hi.is_nan() { f64::INFINITY } else { hi },
        }
    }

    /// The interval of a round-to-nearest result `[lo, hi]`, widened by one step each side.
    fn outward(lo: f64, hi: f64) -> Interval {
        Interval::new(lo.next_down(), hi.next_up())
    }

    /// The lower end.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Interval;
    /// assert_eq!(Interval::new(1.0, 2.0).lower(), 1.0);
    /// ```
    pub fn lower(&self) -> f64 {
        self.lo
    }

    /// The upper end.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Interval;
    /// assert_eq!(Interval::new(1.0, 2.0).upper(), 2.0);
    /// ```
    pub fn upper(&self) -> f64 {
        self.hi
    }

    /// Whether the exact rational `x` lies in the interval (decided exactly).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Interval, q};
    /// assert!(Interval::new(0.0, 1.0).contains(&q(1, 3)));
    /// assert!(!Interval::new(0.5, 1.0).contains(&q(1, 3)));
    /// ```
    pub fn contains(&self, x: &Q) -> bool {
        // An infinite end has no rational value: -inf is below every x, +inf above.
        let above_lo = match Ratio::from_float(self.lo) {
            Some(lo) => lo <= *x,
            None => self.lo == f64::NEG_INFINITY,
        };
        let below_hi = match Ratio::from_float(self.hi) {
            Some(hi) => *x <= hi,
            None => self.hi == f64::INFINITY,
        };
        above_lo && below_hi
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{:e}, {:e}]", self.lo, self.hi)
    }
}

impl Zero for Interval {
    fn zero() -> Self {
        Interval::new(0.0, 0.0)
    }
    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }
}

impl One for Interval {
    fn one() -> Self {
        Interval::new(1.0, 1.0)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval::new(-self.hi, -self.lo)
    }
}

impl Add<&Interval> for Interval {
    type Output = Interval;
    fn add(self, rhs: &Interval) -> Interval {
        Interval::outward(self.lo + rhs.lo, self.hi + rhs.hi)
    }
}

impl Sub<&Interval> for Interval {
    type Output = Interval;
    fn sub(self, rhs: &Interval) -> Interval {
        Interval::outward(self.lo - rhs.hi, self.hi - rhs.lo)
    }
}

impl Mul<&Interval> for Interval {
    type Output = Interval;
    fn mul(self, rhs: &Interval) -> Interval {
        // 0 * inf between ends stands for 0 times a large finite number: 0.
        let product = |x: f64, y: f64| if x == 0.0 || y == 0.0 { 0.0 } else { x * y };
        let p = [
            product(self.lo, rhs.lo),
            product(self.lo, rhs.hi),
            product(self.hi, rhs.lo),
            product(self.hi, rhs.hi),
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::outward(lo, hi)
    }
}

impl Div<&Interval> for Interval {
    type Output = Interval;
    fn div(self, rhs: &Interval) -> Interval {
        if rhs.lo <= 0.0 && rhs.hi >= 0.0 {
            return Interval::new(f64::NEG_INFINITY, f64::INFINITY);
        }
        let inverse = Interval::outward(1.0 / rhs.hi, 1.0 / rhs.lo);
        self * inverse
    }
}

macro_rules! by_value {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for Interval {
            type Output = Interval;
            fn $f(self, rhs: Interval) -> Interval {
                self.$f(&rhs)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

impl Field for Interval {
    const NAME: &'static str = "interval";
    const EXACT: bool = false;

    /// The nearest `f64` when it equals `q`, else the two floats around `q`.
    fn from_rational(q: &Q) -> Self {
        let x = q.to_f64().unwrap_or(f64::NAN);
        match Ratio::from_float(x).map(|r| r.cmp(q)) {
            Some(Ordering::Equal) => Interval::new(x, x),
            Some(Ordering::Less) => Interval::new(x, x.next_up()),
            Some(Ordering::Greater) => Interval::new(x.next_down(), x),
            // Beyond the largest finite float on one side.
            None if q > &Q::zero() => Interval::new(f64::MAX, f64::INFINITY),
            None => Interval::new(f64::NEG_INFINITY, f64::MIN),
        }
    }

    /// Decided only when the interval does not straddle 0 (or is exactly `[0, 0]`).
    fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.is_zero() {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The midpoint (an infinite end gives that infinity).
    fn nearest_f64(&self) -> f64 {
        if self.lo == self.hi {
            self.lo
        } else {
            self.lo / 2.0 + self.hi / 2.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};

    #[test]
    fn field_laws_hold_up_to_overlap() {
        let samples: Vec<Interval> = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7)]
            .iter()
            .map(Interval::from_rational)
            .collect();
        // Interval arithmetic is not a field; the laws hold as "the two sides overlap".
        laws::check_field(&samples, |a, b| a.lo <= b.hi && b.lo <= a.hi);
    }

    #[test]
    fn rationals_are_enclosed_tightly() {
        let third = Interval::from_rational(&q(1, 3));
        assert!(third.contains(&q(1, 3)));
        assert_eq!(third.hi, third.lo.next_up());
        assert_eq!(Interval::from_rational(&q(1, 2)), Interval::new(0.5, 0.5));
        let huge = Q::from_integer(num_bigint::BigInt::from(10).pow(400));
        let h = Interval::from_rational(&huge);
        assert!(h.contains(&huge));
        assert_eq!(h.sign(), Some(Ordering::Greater));
    }

    #[test]
    fn division_by_an_interval_around_zero_is_the_whole_line() {
        let x = Interval::one() / Interval::new(-1.0, 1.0);
        assert_eq!(x.sign(), None);
        assert!(x.contains(&q(-7, 1)) && x.contains(&q(7, 1)));
    }
}
