//! The [`Field`] trait and its backends.
//!
//! The impulse solver is written once, generically over a commutative field. Running it on
//! different fields answers different questions:
//!
//! | backend | type | what it answers |
//! |---|---|---|
//! | exact rationals | [`Q`] (`BigRational`) | the exact answer for a rational scene |
//! | floats | `f64`, `f32` | what a float code computes, to measure its error |
//! | intervals | [`Interval`] | a guaranteed `f64` enclosure of the exact answer |
//! | quadratic field | [`QSqrt`] | exact values at the irrational optimum a* |
//! | rational functions | [`RatFn`] | identities for *all* parameter values, exact limits |
//!
//! Numbers enter a field only through [`Field::from_rational`]: no float ever reaches an exact
//! backend.

use num_rational::BigRational;
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::fmt::{Debug, Display};
use std::ops::{Add, Div, Mul, Neg, Sub};

pub mod big;
pub mod count;
pub mod decimal;
mod float;
pub mod int;
mod interval;
pub mod laws;
pub mod linear;
pub mod notation;
pub mod poly;
pub mod quadratic;
pub mod ratfunc;
mod rational;
pub(crate) mod shortest;

pub use float::exact_float;
pub(crate) use float::float_parts;
pub use interval::Interval;
pub use poly::{Poly, Sym};
pub use quadratic::QSqrt;
pub use ratfunc::RatFn;

/// Exact rational numbers: the reference backend.
pub type Q = BigRational;

/// A commutative field: all the impulse solver needs.
///
/// Owned and by-reference right-hand operands (num-traits `NumOps` + `NumRef` style), so exact
/// backends add and multiply without cloning both sides: write `a.clone() * &b` or `a * &b`.
///
/// # Examples
/// ```
/// use rodimpact::field::{Field, Q};
/// use num_traits::One;
/// fn half_sum<F: Field>(a: &F, b: &F) -> F {
///     (a.clone() + b) / F::from_i64(2)
/// }
/// let q: Q = half_sum(&Q::one(), &Q::from_i64(2));
/// assert_eq!(q.to_string(), "3/2");
/// assert_eq!(half_sum(&1.0f64, &2.0), 1.5);
/// ```
pub trait Field:
    Clone
    + PartialEq
    + Debug
    + Display
    + Zero
    + One
    + Sub<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
{
    /// Backend name in reports and tables: `"Q"`, `"Q(sqrt d)"`, `"Q(symbols)"`, `"f64"`.
    const NAME: &'static str;
    /// `true` when `==`, `is_zero` and `sign` decide; `false` when they only estimate.
    const EXACT: bool;

    /// The embedding Q -> F: the only door numbers enter by (exact, or the nearest float).
    fn from_rational(q: &Q) -> Self;

    /// The sign where the field can decide it: always for Q, Q(sqrt d) and non-NaN floats;
    /// `None` for NaN and for a rational function whose sign depends on its symbols.
    fn sign(&self) -> Option<Ordering>;

    /// The nearest `f64` (for printed estimates); NaN where no number is meant (a non-constant
    /// rational function).
    fn nearest_f64(&self) -> f64;

    /// The size of the number in bits, for the work budgets of iterated exact work
    /// ([`crate::impact::Work`]): numerator and denominator together for a rational; a
    /// machine word's 64 where numbers do not grow (floats, the default).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, q};
    /// assert_eq!(q(3, 4).size_bits(), 2 + 3);
    /// assert_eq!(0.75f64.size_bits(), 64);
    /// ```
    fn size_bits(&self) -> u64 {
        64
    }

    /// An integer, through [`Field::from_rational`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, Q};
    /// assert_eq!(Q::from_i64(-3).to_string(), "-3");
    /// ```
    fn from_i64(n: i64) -> Self {
        Self::from_rational(&Q::from_integer(n.into()))
    }

    /// `self / rhs`, or `None` when `rhs` is zero (a singular system) instead of a panic or NaN.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, Q};
    /// use num_traits::{One, Zero};
    /// assert!(Q::one().checked_div(&Q::zero()).is_none());
    /// assert_eq!(Q::one().checked_div(&Q::from_i64(4)).unwrap().to_string(), "1/4");
    /// ```
    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        (!rhs.is_zero()).then(|| self.clone() / rhs)
    }

    /// `self * self`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, Q};
    /// assert_eq!(Q::from_i64(-3).square().to_string(), "9");
    /// ```
    fn square(&self) -> Self {
        self.clone() * self
    }
}

/// `|x|` in any field whose sign is decided (`x` itself when the sign is not).
pub(crate) fn abs<F: Field>(x: F) -> F {
    if x.sign() == Some(Ordering::Less) {
        -x
    } else {
        x
    }
}

/// Square roots that exist in the field.
pub trait TrySqrt: Field {
    /// `Some(r)` with `r >= 0` and `r * r == self`; `None` when no such `r` lies in the field.
    fn try_sqrt(&self) -> Option<Self>;
}

/// Convenience: the rational `n/d` (panics only on `d == 0`, a programming error).
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// assert_eq!(q(6, 4).to_string(), "3/2");
/// ```
pub fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}
