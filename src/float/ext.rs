//! [`Ext`]: a float with its binary exponent carried as an integer, so products and quotients
//! never overflow or underflow in the middle of a formula.
//!
//! `Ext { f, k }` stands for `f 2^k` with `0.5 <= |f| < 1` (or `f = 0`). Multiplication and
//! division round the mantissa once, exactly like the plain float operation would in range;
//! addition aligns the exponents exactly first. Only [`Ext::value`] returns to the float format,
//! with a single rounding.

use super::Real;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `f 2^k` with a normalised mantissa and an unbounded (i32) exponent.
///
/// # Examples
/// ```
/// use rodimpact::float::Ext;
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
    /// use rodimpact::float::Ext;
    /// assert_eq!(Ext::new(3.0f32).value(), 3.0);
    /// ```
    pub fn new(x: T) -> Ext<T> {
        let (f, k) = x.frexp();
        Ext { f, k }
    }

    /// `f 2^k` renormalised (exact), for any float `f` and exponent `k`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::float::Ext;
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
    /// use rodimpact::float::Ext;
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
    /// use rodimpact::float::Ext;
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
