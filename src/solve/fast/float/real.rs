//! [`Real`]: the IEEE binary formats `f64` and `f32` seen through their bits, so the float
//! formulas can split a number into mantissa and binary exponent and scale by powers of two
//! exactly.

use crate::field::{Field, Q};
use num_rational::Ratio;
use num_traits::{One, Zero};

/// An IEEE binary float format (`f64` or `f32`) with exact power-of-two scaling.
///
/// # Examples
/// ```
/// use rodimpact::solve::fast::float::Real;
/// assert_eq!(Real::frexp(12.0f64), (0.75, 4));
/// assert_eq!(Real::ldexp(0.75f32, 4), 12.0);
/// assert_eq!(<f64 as Real>::PRECISION, 53);
/// ```
pub trait Real: Field + Copy + PartialOrd {
    /// Significand bits including the hidden bit: 53 or 24; the unit roundoff is 2^-PRECISION.
    const PRECISION: u32;

    /// One more than the largest binary exponent of a finite number: 1024 or 128 (the largest
    /// finite number is just below 2^MAX_EXP; the smallest normal is 2^(3 - MAX_EXP)).
    const MAX_EXP: i32;

    /// `(f, k)` with `self = f 2^k` and `0.5 <= |f| < 1`; zero, infinities and NaN give
    /// `(self, 0)`. Exact, subnormals included.
    fn frexp(self) -> (Self, i32);

    /// `self 2^k`, correctly rounded (a single rounding, also into the subnormal range).
    fn ldexp(self, k: i32) -> Self;

    /// The exponent k of a normal number, `self = f 2^k` with `0.5 <= |f| < 1` (as
    /// [`Real::frexp`] gives it), read off its bits; `None` for zero, a subnormal, an infinity
    /// or NaN.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Real;
    /// assert_eq!(Real::binade(12.0f64), Some(4));
    /// assert_eq!(Real::binade(f64::MIN_POSITIVE / 2.0), None);
    /// ```
    fn binade(self) -> Option<i32>;

    /// `2^k`, exact, for `k` in the normal exponent range; outside it as [`Real::ldexp`] rounds
    /// (a subnormal, 0 or infinity).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Real;
    /// assert_eq!(<f64 as Real>::pow2(-3), 0.125);
    /// assert_eq!(<f32 as Real>::pow2(200), f32::INFINITY);
    /// ```
    fn pow2(k: i32) -> Self;

    /// `self * a + b` with one rounding.
    fn mul_add(self, a: Self, b: Self) -> Self;

    /// Finite (neither infinite nor NaN).
    fn finite(self) -> bool;

    /// The exact rational value, or `None` for NaN and infinities.
    fn to_exact(self) -> Option<Q>;

    /// A normal number of the format (not zero, subnormal, infinite or NaN).
    fn normal(self) -> bool;

    /// The unit roundoff `u = 2^-PRECISION`, exactly.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Real;
    /// assert_eq!(<f32 as Real>::unit_roundoff().to_string(), "1/16777216");
    /// ```
    fn unit_roundoff() -> Q {
        Q::new(One::one(), num_bigint::BigInt::from(2).pow(Self::PRECISION))
    }

    /// The shortest decimal that reads back as `self`: positional for magnitudes in
    /// [1e-5, 1e16), scientific otherwise.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::fast::float::Real;
    /// assert_eq!(Real::shortest(0.1f64), "0.1");
    /// assert_eq!(Real::shortest(1e-300f64), "1e-300");
    /// assert_eq!(Real::shortest(3.0e20f32), "3e20");
    /// ```
    fn shortest(self) -> String;
}

macro_rules! real {
    ($t:ty, $bits:ty, $precision:literal, $bias:literal) => {
        impl Real for $t {
            const PRECISION: u32 = $precision;
            const MAX_EXP: i32 = <$t>::MAX_EXP;

            fn frexp(self) -> (Self, i32) {
                const MANT: u32 = $precision - 1;
                const EXP_MASK: $bits = (1 << (<$bits>::BITS - 1 - MANT)) - 1;
                if self.is_zero() || !self.is_finite() {
                    return (self, 0);
                }
                let bits = self.to_bits();
                let biased = ((bits >> MANT) & EXP_MASK) as i32;
                if biased == 0 {
                    // Subnormal: scale into the normal range first (exact).
                    let (f, k) = (self * <$t>::from_bits((($bias + 64) as $bits) << MANT)).frexp();
                    return (f, k - 64);
                }
                let cleared = bits & !(EXP_MASK << MANT);
                let f = <$t>::from_bits(cleared | ((($bias - 1) as $bits) << MANT));
                (f, biased - ($bias - 1))
            }

            fn binade(self) -> Option<i32> {
                const MANT: u32 = $precision - 1;
                const EXP_MASK: $bits = (1 << (<$bits>::BITS - 1 - MANT)) - 1;
                let biased = ((self.to_bits() >> MANT) & EXP_MASK) as i32;
                (biased != 0 && biased != EXP_MASK as i32).then_some(biased - ($bias - 1))
            }

            fn ldexp(self, k: i32) -> Self {
                const MANT: u32 = $precision - 1;
                let (f, e) = self.frexp();
                if f.is_zero() || !f.is_finite() {
                    return self;
                }
                // 2^j for j in the normal exponent range, exactly.
                let pow2 = |j: i32| <$t>::from_bits(((j + $bias) as $bits) << MANT);
                let target = e.saturating_add(k); // self 2^k = f 2^target, f in [0.5, 1)
                let min_normal = 2 - $bias; // exponent of the smallest normal, as f 2^target
                if target > $bias + 1 {
                    f * <$t>::INFINITY
                } else if target >= min_normal {
                    // f 2 is in [1, 2): the product stays normal, even at the lowest binade.
                    f * 2.0 * pow2(target - 1)
                } else if target < min_normal - ($precision + 1) {
                    f * 0.0
                } else {
                    // Exact into the smallest normal binade, then one rounding into subnormals.
                    let drop = min_normal - target; // 1 ..= PRECISION + 1
                    (f * 2.0 * pow2(min_normal - 1)) * pow2(-drop)
                }
            }

            fn pow2(k: i32) -> Self {
                const MANT: u32 = $precision - 1;
                if (1 - $bias..=$bias).contains(&k) {
                    <$t>::from_bits(((k + $bias) as $bits) << MANT)
                } else {
                    (1.0 as $t).ldexp(k)
                }
            }

            fn mul_add(self, a: Self, b: Self) -> Self {
                <$t>::mul_add(self, a, b)
            }

            fn finite(self) -> bool {
                self.is_finite()
            }

            fn to_exact(self) -> Option<Q> {
                Ratio::from_float(self)
            }

            fn normal(self) -> bool {
                self.is_normal()
            }

            fn shortest(self) -> String {
                let x = self.abs();
                if x == 0.0 || (1e-5..1e16).contains(&x) || !x.is_finite() {
                    format!("{self}")
                } else {
                    format!("{self:e}")
                }
            }
        }
    };
}

real!(f64, u64, 53, 1023);
real!(f32, u32, 24, 127);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ldexp_is_exact_into_the_lowest_normal_binade() {
        // Regression: f 2^-1 2^target once went through the subnormal range and lost the last bit.
        let x = 1.0f32 + f32::EPSILON;
        assert_eq!(x.ldexp(-126), f32::MIN_POSITIVE * x);
        let y = 1.0f64 + f64::EPSILON;
        assert_eq!(y.ldexp(-1022), f64::MIN_POSITIVE * y);
    }

    #[test]
    fn binade_is_frexps_exponent_for_normals_only() {
        for x in [1.0f64, -0.75, 3e300, f64::MIN_POSITIVE, f64::MAX, 1e-300] {
            assert_eq!(x.binade(), Some(x.frexp().1), "{x:e}");
        }
        for x in [
            0.0f64,
            -0.0,
            f64::MIN_POSITIVE / 2.0,
            f64::INFINITY,
            f64::NAN,
        ] {
            assert_eq!(x.binade(), None, "{x:e}");
        }
        assert_eq!(3.0f32.binade(), Some(2));
        assert_eq!(f32::from_bits(1).binade(), None);
    }

    #[test]
    fn frexp_splits_normals_and_subnormals_exactly() {
        assert_eq!(1.0f64.frexp(), (0.5, 1));
        assert_eq!((-3.0f64).frexp(), (-0.75, 2));
        assert_eq!(f64::from_bits(1).frexp(), (0.5, -1073));
        assert_eq!(f32::from_bits(1).frexp(), (0.5, -148));
        assert_eq!(f64::MAX.frexp().1, 1024);
        assert_eq!(0.0f64.frexp(), (0.0, 0));
        assert!(f64::NAN.frexp().0.is_nan());
    }

    #[test]
    fn ldexp_scales_with_one_rounding() {
        assert_eq!(0.5f64.ldexp(1025), f64::INFINITY);
        assert_eq!(0.5f64.ldexp(1024), 2f64.powi(1023));
        assert_eq!(0.5f64.ldexp(-1073), f64::from_bits(1));
        assert_eq!(0.5f64.ldexp(-1074), 0.0); // a tie rounds to even: 0
        assert_eq!(0.75f64.ldexp(-1074), f64::from_bits(1)); // above the tie
        assert_eq!(0.5f32.ldexp(-148), f32::from_bits(1));
        assert_eq!(3.0f32.ldexp(-2), 0.75);
        // Every subnormal step: scaling down and back up is exact.
        let x = 0.8125f64.ldexp(-1060);
        assert_eq!(x.ldexp(1060), 0.8125);
    }
}
