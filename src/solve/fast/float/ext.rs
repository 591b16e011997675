//! [`Ext`]: a float with its binary exponent carried as an integer, so products and quotients
//! never overflow or underflow in the middle of a formula.
//!
//! `Ext { f, k }` stands for `f 2^k` with `0.5 <= |f| < 1` (or `f = 0`). Multiplication and
//! division round the mantissa once, exactly like the plain float operation would in range;
//! addition aligns the exponents exactly first. Only [`Ext::value`] returns to the float format,
//! with a single rounding.

use super::Real;
use crate::field::Q;
use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `f 2^k` with a normalised mantissa and an unbounded (i32) exponent.
///
/// # Examples
/// ```
/// use rodimpact::solve::fast::float::Ext;
/// let big = Ext::new(1e300f64);
/// let x = big * big / big; // 1e600 in the middle, never infinite
/// assert_eq!(x.value(), 1e300);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ext<T> {
    f: T,
    k: i32,
}

impl<T: Real> Ext<T> {
    /// `x` split into mantissa and exponent (exact).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Ext;
    /// assert_eq!(Ext::new(3.0f32).value(), 3.0);
    /// ```
    pub fn new(x: T) -> Ext<T> {
        let (f, k) = x.frexp();
        Ext { f, k }
    }

    /// The exact rational `x` rounded once, to nearest (ties to even), to the format's precision,
    /// its binary exponent carried as an integer: no overflow or underflow however large or
    /// small `x` is (the exponent saturates only beyond 2^31 bits). Where `x` is a normal number
    /// of the format this is exactly the float nearest to `x`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, solve::fast::float::Ext};
    /// assert_eq!(Ext::<f64>::from_rational(&q(1, 3)).value(), 1.0 / 3.0);
    /// assert_eq!(Ext::<f32>::from_rational(&q(-6, 1)).parts(), (-0.75, 3));
    /// // 10^-400 underflows f64, but not here: times 10^400 it is 1 to the last bit.
    /// let tiny = rodimpact::number::parse("1e-400")?;
    /// let huge = rodimpact::number::parse("1e400")?;
    /// let one = Ext::<f64>::from_rational(&tiny) * Ext::from_rational(&huge);
    /// assert!((one.value() - 1.0).abs() <= f64::EPSILON);
    /// # Ok::<(), rodimpact::ErrorKind>(())
    /// ```
    pub fn from_rational(x: &Q) -> Ext<T> {
        if x.is_zero() {
            return Ext { f: T::zero(), k: 0 };
        }
        let precision = T::PRECISION as i64;
        let (n, d) = (x.numer().magnitude(), x.denom().magnitude());
        // Scaled so that n/d 2^(precision - k) is an integer part of `precision` bits plus a
        // remainder: 2^(k-1) <= n/d < 2^k.
        let scaled = |k: i64| -> (BigUint, BigUint) {
            let shift = precision - k;
            if shift >= 0 {
                (n << shift as u64, d.clone())
            } else {
                (n.clone(), d << shift.unsigned_abs())
            }
        };
        let mut k = n.bits() as i64 - d.bits() as i64;
        let (mut num, mut den) = scaled(k);
        if num >= (&den << precision as u64) {
            k += 1;
            (num, den) = scaled(k);
        }
        let (quotient, remainder) = num.div_rem(&den);
        let twice = remainder << 1u8;
        let up = twice > den || (twice == den && quotient.bit(0));
        let mantissa = if up { quotient + 1u8 } else { quotient };
        // At most 2^precision: exact in the format, and exactly scaled into [1/2, 1].
        let f = T::from_rational(&Q::from_integer(BigInt::from(mantissa)));
        let f = f.ldexp(-(T::PRECISION as i32));
        let f = if x.is_negative() { -f } else { f };
        let k = i32::try_from(k).unwrap_or(if k < 0 { i32::MIN / 2 } else { i32::MAX / 2 });
        Ext::from_parts(f, k)
    }

    /// `f 2^k` renormalised (exact), for any float `f` and exponent `k`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Ext;
    /// assert_eq!(Ext::from_parts(3.0f64, -1).value(), 1.5);
    /// ```
    pub fn from_parts(f: T, k: i32) -> Ext<T> {
        let (f, j) = f.frexp();
        Ext { f, k: k + j }
    }

    /// The float nearest to the value: one rounding, to infinity or (gradually) to zero when
    /// out of the format's range.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Ext;
    /// let tiny = Ext::new(1e-30f32);
    /// assert_eq!((tiny * tiny).value(), 0.0);
    /// ```
    pub fn value(self) -> T {
        self.f.ldexp(self.k)
    }

    /// Mantissa and exponent, `(f, k)` with value `f 2^k`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Ext;
    /// assert_eq!(Ext::new(6.0f64).parts(), (0.75, 3));
    /// ```
    pub fn parts(self) -> (T, i32) {
        (self.f, self.k)
    }
}

impl<T: Real> Mul for Ext<T> {
    type Output = Ext<T>;
    fn mul(self, rhs: Ext<T>) -> Ext<T> {
        Ext::from_parts(self.f * rhs.f, self.k + rhs.k)
    }
}

impl<T: Real> Div for Ext<T> {
    type Output = Ext<T>;
    fn div(self, rhs: Ext<T>) -> Ext<T> {
        Ext::from_parts(self.f / rhs.f, self.k - rhs.k)
    }
}

impl<T: Real> Neg for Ext<T> {
    type Output = Ext<T>;
    fn neg(self) -> Ext<T> {
        Ext {
            f: -self.f,
            k: self.k,
        }
    }
}

impl<T: Real> Add for Ext<T> {
    type Output = Ext<T>;
    /// Exact alignment, then one rounding. A term more than PRECISION + 2 binades below the
    /// other is below half an ulp of the sum and is dropped (the sum rounds to the larger).
    fn add(self, rhs: Ext<T>) -> Ext<T> {
        if rhs.f.is_zero() || !self.f.finite() {
            return if self.f.is_zero() { rhs } else { self };
        }
        if self.f.is_zero() || !rhs.f.finite() {
            return rhs;
        }
        let (big, small) = if self.k >= rhs.k {
            (self, rhs)
        } else {
            (rhs, self)
        };
        let gap = big.k - small.k;
        if gap > T::PRECISION as i32 + 2 {
            return big;
        }
        Ext::from_parts(big.f + small.f.ldexp(-gap), big.k)
    }
}

impl<T: Real> Sub for Ext<T> {
    type Output = Ext<T>;
    fn sub(self, rhs: Ext<T>) -> Ext<T> {
        self + -rhs
    }
}

/// The by-reference right operands, as the generic formulas ([`crate::scene::Groups`])
/// write them: the same operations on a copy.
macro_rules! by_reference {
    ($($Trait:ident $method:ident),*) => {$(
        impl<T: Real> $Trait<&Ext<T>> for Ext<T> {
            type Output = Ext<T>;
            fn $method(self, rhs: &Ext<T>) -> Ext<T> {
                $Trait::$method(self, *rhs)
            }
        }
    )*};
}
by_reference!(Add add, Mul mul, Div div);

impl<T: Real> One for Ext<T> {
    fn one() -> Ext<T> {
        Ext::new(T::one())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_matches_the_float_in_range() {
        let (a, b) = (0.1f64, 3.7f64);
        let (x, y) = (Ext::new(a), Ext::new(b));
        assert_eq!((x * y).value(), a * b);
        assert_eq!((x / y).value(), a / b);
        assert_eq!((x + y).value(), a + b);
        assert_eq!((x - y).value(), a - b);
        assert_eq!((y - y).value(), 0.0);
        assert_eq!((Ext::new(0.0f64) + x).value(), a);
    }

    /// Regression: a float's `from_rational` goes through f64 (num-rational), so an f32 could
    /// be rounded twice. 1 + 2^-24 + 2^-60 lies just above the f32 tie 1 + 2^-24; f64 rounds it
    /// onto the tie, and the tie then rounds to even, 1. Rounded once it is 1 + 2^-23.
    #[test]
    fn from_rational_rounds_once() {
        let two = |k: u32| Q::new(1.into(), BigInt::from(2).pow(k));
        let above_tie = Q::from_integer(1.into()) + two(24) + two(60);
        assert_eq!(
            Ext::<f32>::from_rational(&above_tie).value(),
            1.0 + f32::EPSILON
        );
        assert_eq!(
            Ext::<f32>::from_rational(&(Q::from_integer(1.into()) + two(24))).value(),
            1.0
        );
        // Exactly 1/2 below and above a power of two; the largest f64 and the carry into 2^k.
        assert_eq!(Ext::<f64>::from_rational(&two(1)).parts(), (0.5, 0));
        let max = Q::from_float(f64::MAX).unwrap();
        assert_eq!(Ext::<f64>::from_rational(&max).value(), f64::MAX);
        let just_below_one = Q::from_integer(1.into()) - two(60);
        assert_eq!(Ext::<f64>::from_rational(&just_below_one).parts(), (0.5, 1));
    }

    /// Where the value is a normal number, rounding once with the exponent carried gives the
    /// float nearest to it (f64's `from_rational` is correctly rounded).
    #[test]
    fn from_rational_matches_the_nearest_float_in_range() {
        for (n, d) in [
            (1i64, 3i64),
            (-22, 7),
            (1, 10),
            (123456789, 1000),
            (7, 1 << 40),
        ] {
            let x = Q::new(n.into(), d.into());
            let nearest = <f64 as crate::field::Field>::from_rational(&x);
            assert_eq!(Ext::<f64>::from_rational(&x), Ext::new(nearest), "{x}");
        }
        // Beyond the range the exponent is carried: 3 2^-1100 and 3 2^1100.
        let big = Q::from_integer(BigInt::from(3) << 1100u32);
        assert_eq!(Ext::<f64>::from_rational(&big).parts(), (0.75, 1102));
        assert_eq!(
            Ext::<f64>::from_rational(&(Q::from_integer(1.into()) / big)).parts(),
            (2.0 / 3.0, -1101)
        );
    }

    #[test]
    fn exponents_are_carried_beyond_the_range() {
        let tiny = Ext::new(1e-200f64);
        let one = (tiny * tiny) / (tiny * tiny);
        assert_eq!(one.value(), 1.0);
        assert_eq!((tiny * tiny).value(), 0.0);
        assert_eq!(
            (Ext::new(1e200f64) * Ext::new(1e200)).value(),
            f64::INFINITY
        );
        // 1 + 2^-60 rounds to 1 (dropped term), 1 + 2^-53 ties to even: 1.
        assert_eq!((Ext::new(1.0f64) + Ext::new(2f64.powi(-60))).value(), 1.0);
        assert_eq!(
            (Ext::new(1.0f64) + Ext::new(2f64.powi(-52))).value(),
            1.0 + f64::EPSILON
        );
    }
}
