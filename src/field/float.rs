//! [`Field`] for the IEEE floats `f64` and `f32`: the backends whose error the exact ones measure.
//!
//! `from_rational` rounds to nearest (through num-rational's `to_f64`, which rounds the exact
//! ratio, not its parts); `sign` is `None` for NaN.

use super::{Field, Q};
use num_traits::ToPrimitive;
use std::cmp::Ordering;

/// The exact value of a finite `x` as a reduced [`Q`] (a dyadic rational: an odd numerator
/// over a power of two, or an integer), built from its bits without a GCD; `None` for NaN and
/// the infinities. The same value as num-rational's `Ratio::from_float`, which reduces with a
/// big-integer GCD.
///
/// # Examples
/// ```
/// use rodimpact::field::{exact_float, q};
/// assert_eq!(exact_float(0.75), Some(q(3, 4)));
/// assert_eq!(exact_float(-6.0), Some(q(-6, 1)));
/// assert_eq!(exact_float(f64::NAN), None);
/// ```
pub fn exact_float(x: f64) -> Option<Q> {
    use num_bigint::{BigInt, BigUint};
    if x == 0.0 {
        return Some(Q::from_integer(BigInt::from(0)));
    }
    let (negative, odd, exponent) = float_parts(x)?;
    let magnitude = BigUint::from(odd);
    let sign = if negative {
        num_bigint::Sign::Minus
    } else {
        num_bigint::Sign::Plus
    };
    Some(if exponent >= 0 {
        Q::from_integer(BigInt::from_biguint(sign, magnitude << exponent as u64))
    } else {
        Q::new_raw(
            BigInt::from_biguint(sign, magnitude),
            BigInt::from(BigUint::from(1u8) << (-exponent) as u64),
        )
    })
}

/// A finite nonzero `x` as `(negative, odd, exponent)` with `|x| = odd * 2^exponent`, `odd` an
/// odd integer of at most 53 bits; `None` for zero, NaN and the infinities.
pub(crate) fn float_parts(x: f64) -> Option<(bool, u64, i64)> {
    if !x.is_finite() || x == 0.0 {
        return None;
    }
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let fraction = bits & ((1 << 52) - 1);
    // x = mantissa * 2^exponent, the mantissa an integer of at most 53 bits.
    let (mantissa, exponent) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | 1 << 52, biased - 1075)
    };
    let zeros = mantissa.trailing_zeros();
    Some((x < 0.0, mantissa >> zeros, exponent + i64::from(zeros)))
}

macro_rules! float_field {
    ($t:ty, $name:literal, $to:ident) => {
        impl Field for $t {
            const NAME: &'static str = $name;
            const EXACT: bool = false;

            fn from_rational(q: &Q) -> Self {
                q.$to().unwrap_or(<$t>::NAN)
            }

            fn sign(&self) -> Option<Ordering> {
                self.partial_cmp(&0.0)
            }

            fn nearest_f64(&self) -> f64 {
                f64::from(*self)
            }
        }
    };
}

float_field!(f64, "f64", to_f64);
float_field!(f32, "f32", to_f32);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};

    /// Within 8 ulps of the larger magnitude, absolute below 1 (cancellation in the laws).
    fn close_f64(a: &f64, b: &f64) -> bool {
        let scale = a.abs().max(b.abs()).max(1.0);
        (a - b).abs() <= 8.0 * f64::EPSILON * scale
    }

    fn close_f32(a: &f32, b: &f32) -> bool {
        let scale = a.abs().max(b.abs()).max(1.0);
        (a - b).abs() <= 8.0 * f32::EPSILON * scale
    }

    #[test]
    fn f64_field_laws_hold_to_eight_ulps() {
        let samples: Vec<f64> = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7)]
            .iter()
            .map(f64::from_rational)
            .chain([1e100, 1e-100])
            .collect();
        laws::check_field(&samples, close_f64);
    }

    #[test]
    fn f32_field_laws_hold_to_eight_ulps() {
        let samples: Vec<f32> = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7)]
            .iter()
            .map(f32::from_rational)
            .chain([1e12, 1e-12])
            .collect();
        laws::check_field(&samples, close_f32);
    }

    #[test]
    fn exact_float_is_num_rationals_value() {
        for x in [
            0.1,
            -0.59999996,
            1e300,
            -1.5e-310,
            f64::from_bits(1),
            f64::MAX,
            -0.0,
            3.0,
            1.0 / 3.0,
        ] {
            assert_eq!(exact_float(x), Q::from_float(x), "{x:e}");
        }
    }

    proptest::proptest! {
        /// Every finite f64 (random bit patterns: subnormals, integers, huge): the same value
        /// as num-rational's reduced one.
        #[test]
        fn exact_float_of_any_bits(bits in proptest::prelude::any::<u64>()) {
            let x = f64::from_bits(bits);
            proptest::prop_assert_eq!(exact_float(x), Q::from_float(x));
        }
    }

    #[test]
    fn from_rational_rounds_the_ratio_to_nearest() {
        assert_eq!(f64::from_rational(&q(1, 3)), 1.0 / 3.0);
        assert_eq!(f32::from_rational(&q(1, 10)), 0.1f32);
        assert_eq!(f64::NAN.sign(), None);
        assert_eq!((-0.5f64).sign(), Some(Ordering::Less));
    }
}
