//! Units in the last place: the correctly rounded binary float of an exact rational, and the
//! distance between two floats counted in representable values (`batch --ulps N --float F`).

use crate::field::Q;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A binary floating-point format an engine computes in.
///
/// # Examples
/// ```
/// use rodimpact::batch::FloatFormat;
/// assert_eq!(FloatFormat::F32.name(), "f32");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FloatFormat {
    /// IEEE binary32.
    F32,
    /// IEEE binary64.
    F64,
}

impl FloatFormat {
    /// `f32` or `f64`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::FloatFormat;
    /// assert_eq!(FloatFormat::F64.name(), "f64");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            FloatFormat::F32 => "f32",
            FloatFormat::F64 => "f64",
        }
    }

    /// Significand bits (with the hidden bit), the smallest normal exponent, and the exponent
    /// bias of the largest finite value (its exponent, for a significand in [1, 2)).
    fn layout(self) -> (u32, i64, i64) {
        match self {
            FloatFormat::F32 => (24, -126, 127),
            FloatFormat::F64 => (53, -1022, 1023),
        }
    }

    /// The position of `x` in the ordered sequence of this format's values: consecutive
    /// floats have consecutive positions, +0 and -0 both 0, the largest finite value one below
    /// infinity. `x` is rounded to the nearest value of the format, ties to even; beyond the
    /// largest finite value it is infinity.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{batch::FloatFormat, field::q};
    /// let f = FloatFormat::F32;
    /// // 3/5 lies between two f32 values; 0.6f32 is the nearer one.
    /// assert_eq!(f.position(&q(3, 5)), i64::from(0.6f32.to_bits()));
    /// assert_eq!(f.position(&q(-3, 5)), -i64::from(0.6f32.to_bits()));
    /// assert_eq!(FloatFormat::F64.position(&q(1, 10)), 0.1f64.to_bits() as i64);
    /// ```
    pub fn position(self, x: &Q) -> i64 {
        let magnitude = self.magnitude_position(&x.abs());
        if x.is_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    /// [`FloatFormat::position`] of |x| (x >= 0): the bits of the rounded value.
    fn magnitude_position(self, x: &Q) -> i64 {
        if x.is_zero() {
            return 0;
        }
        let (precision, min_exponent, max_exponent) = self.layout();
        let significand_bits = i64::from(precision) - 1;
        let infinity = (max_exponent + 1 - min_exponent + 1) << significand_bits;
        // floor(log2 x), from the bit lengths, corrected by one comparison.
        let (n, d) = (x.numer(), x.denom());
        let mut exponent = n.bits() as i64 - d.bits() as i64;
        if Q::new(n.clone(), d.clone()) < power_of_two(exponent) {
            exponent -= 1;
        }
        if exponent > max_exponent {
            return infinity;
        }
        // The quantum: 2^(exponent - p + 1), or the subnormal quantum below the normal range.
        let quantum = exponent.max(min_exponent) - significand_bits;
        let scaled = x / power_of_two(quantum);
        let units = round_half_even(&scaled);
        // units counts quanta: below 2^(p-1) it is subnormal, 2^p means the rounding carried.
        let units = units.to_i64().unwrap_or(i64::MAX);
        let biased = quantum + significand_bits - min_exponent + 1;
        let position = if units < (1 << significand_bits) {
            units // subnormal (biased exponent 0) or the carry into the smallest normal
        } else {
            ((biased - 1) << significand_bits) + units
        };
        position.min(infinity)
    }
}

/// 2^k as an exact rational (k of either sign).
fn power_of_two(k: i64) -> Q {
    let p = BigInt::one() << k.unsigned_abs();
    if k >= 0 {
        Q::from_integer(p)
    } else {
        Q::new(BigInt::one(), p)
    }
}

/// The integer nearest to x >= 0, ties to even.
fn round_half_even(x: &Q) -> BigInt {
    let (q, r) = x.numer().div_rem(x.denom());
    let twice: BigInt = &r * 2;
    match twice.cmp(x.denom()) {
        std::cmp::Ordering::Less => q,
        std::cmp::Ordering::Greater => q + 1,
        std::cmp::Ordering::Equal if q.is_even() => q,
        std::cmp::Ordering::Equal => q + 1,
    }
}

/// The number of floats of `format` from the rounded `claim` to the rounded `exact`.
///
/// # Examples
/// ```
/// use rodimpact::{batch::{ulp_distance, FloatFormat}, field::{q, Q}};
/// let claim = Q::from_float(0.59999996f32).unwrap(); // the f32 just below 0.6f32
/// assert_eq!(ulp_distance(&claim, &q(3, 5), FloatFormat::F32), 1);
/// assert_eq!(ulp_distance(&q(3, 5), &q(3, 5), FloatFormat::F64), 0);
/// // Across zero: the subnormals in between are counted.
/// let tiny = Q::from_float(f64::from_bits(3)).unwrap();
/// assert_eq!(ulp_distance(&-tiny, &Q::from_float(f64::from_bits(2)).unwrap(), FloatFormat::F64), 5);
/// ```
pub fn ulp_distance(claim: &Q, exact: &Q, format: FloatFormat) -> u64 {
    format.position(claim).abs_diff(format.position(exact))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    fn f32_position(x: f32) -> i64 {
        let magnitude = i64::from(x.abs().to_bits());
        if x.is_sign_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    fn f64_position(x: f64) -> i64 {
        let magnitude = x.abs().to_bits() as i64;
        if x.is_sign_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    /// Every float is its own correctly rounded value, across the normal and subnormal ranges
    /// and the boundaries between them; Rust's decimal parsing (correctly rounded) agrees on
    /// the decimals in between.
    #[test]
    fn floats_round_to_themselves_and_decimals_as_rust_parses_them() {
        let f32s = [
            1.0f32,
            0.6,
            f32::MIN_POSITIVE,
            f32::from_bits(1),
            f32::from_bits(0x007f_ffff),
            f32::MAX,
            -2.5e-40,
            1e30,
        ];
        for x in f32s {
            let exact = Q::from_float(x).unwrap();
            assert_eq!(FloatFormat::F32.position(&exact), f32_position(x), "{x:e}");
        }
        let f64s = [
            1.0f64,
            0.1,
            f64::MIN_POSITIVE,
            f64::from_bits(1),
            f64::MAX,
            -3e-310,
        ];
        for x in f64s {
            let exact = Q::from_float(x).unwrap();
            assert_eq!(FloatFormat::F64.position(&exact), f64_position(x), "{x:e}");
        }
        for text in [
            "0.81818175",
            "3.2727275",
            "1e-45",
            "7e-46",
            "1.1754942e-38",
            "3.5e38",
        ] {
            let exact = crate::number::parse(text).unwrap();
            let parsed: f32 = text.parse().unwrap();
            assert_eq!(
                FloatFormat::F32.position(&exact),
                f32_position(parsed),
                "{text}"
            );
        }
        for text in [
            "0.8181818181818183",
            "2.2250738585072011e-308",
            "4.9e-324",
            "2e-324",
        ] {
            let exact = crate::number::parse(text).unwrap();
            let parsed: f64 = text.parse().unwrap();
            assert_eq!(
                FloatFormat::F64.position(&exact),
                f64_position(parsed),
                "{text}"
            );
        }
    }

    #[test]
    fn ties_go_to_even_and_overflow_to_infinity() {
        // 1 + 2^-24 is half-way between 1 and the next f32: ties to 1 (even significand).
        let tie = q(1, 1) + power_of_two(-24);
        assert_eq!(FloatFormat::F32.position(&tie), i64::from(1.0f32.to_bits()));
        let above = q(1, 1) + power_of_two(-24) * q(3, 2);
        assert_eq!(
            FloatFormat::F32.position(&above),
            i64::from(1.0f32.to_bits()) + 1
        );
        let huge = Q::from_integer(BigInt::from(10).pow(39));
        assert_eq!(
            FloatFormat::F32.position(&huge),
            i64::from(f32::INFINITY.to_bits())
        );
        // Half the smallest subnormal rounds to 0 (even), a bit more to the smallest subnormal.
        assert_eq!(FloatFormat::F64.position(&power_of_two(-1075)), 0);
        let more = power_of_two(-1075) * q(3, 2);
        assert_eq!(FloatFormat::F64.position(&more), 1);
    }
}
