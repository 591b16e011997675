//! The big-integer fallback on malachite's [`Integer`] (feature `malachite`, off by default).
//!
//! num-bigint's GCD is a quadratic binary GCD, so the final reductions make the fast path's cost
//! grow like bits^1.9 on large inputs; malachite-nz multiplies subquadratically (Toom-Cook, FFT)
//! and its GCD is a subquadratic half-GCD, so the cost grows like multiplication. The scene is
//! lifted into malachite once, the fraction-free solve runs there, and each output is reduced
//! there and handed back as num-bigint's [`Q`], the same value and representation as
//! `Q::new(n, d)`: the public exact types do not change.
//!
//! Conversions go through 64-bit limbs (linear time, never through decimal strings).
//!
//! License: malachite-nz and malachite-base are LGPL-3.0-only. This module and those crates are
//! compiled only with the feature; the default build uses only MIT/Apache-2.0 dependencies.

use super::Int;
use crate::field::Q;
use malachite_base::num::arithmetic::traits::{DivExact, Gcd, UnsignedAbs};
use malachite_nz::integer::Integer;
use malachite_nz::natural::Natural;
use num_bigint::{BigInt, BigUint, Sign};

/// `x` as a malachite [`Natural`], through its 64-bit limbs (the type checks that malachite's
/// limbs are 64 bits, as they are on every 64-bit target unless `32_bit_limbs` is enabled).
fn natural_from_big(x: &BigUint) -> Natural {
    Natural::from_owned_limbs_asc(x.iter_u64_digits().collect())
}

/// `x` as a malachite [`Integer`], through the limbs of its magnitude.
fn integer_from_big(x: &BigInt) -> Integer {
    Integer::from_sign_and_abs(x.sign() != Sign::Minus, natural_from_big(x.magnitude()))
}

/// `x` as a num-bigint [`BigUint`]: each 64-bit limb is split into the two 32-bit digits that
/// `BigUint::new` takes (which packs them back into 64-bit digits on 64-bit targets).
fn big_from_natural(x: Natural) -> BigUint {
    let limbs = x.into_limbs_asc();
    let mut digits = Vec::with_capacity(2 * limbs.len());
    for limb in limbs {
        digits.push(limb as u32);
        digits.push((limb >> 32) as u32);
    }
    BigUint::new(digits)
}

impl Int for Integer {
    fn lift(x: &BigInt) -> Option<Self> {
        Some(integer_from_big(x))
    }
    fn small(x: u8) -> Self {
        Integer::from(x)
    }
    unbounded_arithmetic!();
    fn ratio(n: Self, d: Self) -> Q {
        // d > 0, so g >= 1; n/g and d/g are exact. With g = 1 nothing is divided.
        let negative = n < 0;
        let (n, d) = (n.unsigned_abs(), d.unsigned_abs());
        let g = (&n).gcd(&d);
        let (n, d) = if g == 1u32 {
            (n, d)
        } else {
            (n.div_exact(&g), d.div_exact(g))
        };
        let sign = if negative { Sign::Minus } else { Sign::Plus };
        Q::new_raw(
            BigInt::from_biguint(sign, big_from_natural(n)),
            BigInt::from_biguint(Sign::Plus, big_from_natural(d)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::{One, Zero};

    /// `x` as a num-bigint [`BigInt`] (zero has no sign in both).
    fn big_from_integer(x: Integer) -> BigInt {
        let sign = if x < 0 { Sign::Minus } else { Sign::Plus };
        BigInt::from_biguint(sign, big_from_natural(x.unsigned_abs()))
    }

    /// Values around the limb and width boundaries, both signs: zero, one word, two words,
    /// past 512 bits (the `Wide` width), and a few thousand bits.
    fn samples() -> Vec<BigInt> {
        let one = BigInt::one();
        let mut xs = vec![
            BigInt::zero(),
            one.clone(),
            BigInt::from(u32::MAX),
            BigInt::from(u32::MAX) + 1,
            BigInt::from(u64::MAX),
            BigInt::from(u64::MAX) + 1,
            (&one << 127) - 1,
            &one << 512,
            (&one << 513) - 1,
            BigInt::from(3).pow(2000),
            BigInt::from(-7).pow(1001) + BigInt::from(u64::MAX),
        ];
        let negatives: Vec<BigInt> = xs.iter().map(|x| -x).collect();
        xs.extend(negatives);
        xs
    }

    #[test]
    fn integers_round_trip_through_limbs() {
        for x in samples() {
            let m = integer_from_big(&x);
            // The same value: malachite's decimal print agrees with num-bigint's.
            assert_eq!(m.to_string(), x.to_string());
            assert_eq!(big_from_integer(m), x);
        }
    }

    #[test]
    fn naturals_round_trip_through_limbs() {
        for x in samples() {
            let x = x.magnitude();
            assert_eq!(big_from_natural(natural_from_big(x)), *x);
        }
        assert_eq!(natural_from_big(&BigUint::zero()), 0u32);
    }

    #[test]
    fn ratio_is_q_new() {
        let big = BigInt::from(3).pow(700) * BigInt::from(2).pow(300);
        let cases = [
            (BigInt::from(0), BigInt::from(5)),
            (BigInt::from(-84), BigInt::from(36)),
            (BigInt::from(84), BigInt::from(1)),
            (BigInt::from(7), BigInt::from(7)),
            (BigInt::from(-1), BigInt::from(u64::MAX)),
            (-&big * 35, &big * 14),
            (&big * 11 + 1, big.clone()),
            (big.clone(), BigInt::from(6).pow(300)),
            (-BigInt::from(6).pow(300), big.clone()),
        ];
        for (n, d) in cases {
            let want = Q::new(n.clone(), d.clone());
            let got = Integer::ratio(integer_from_big(&n), integer_from_big(&d));
            // The representation too: `==` on Q compares values, not numerator and denominator.
            assert_eq!(
                (got.numer(), got.denom()),
                (want.numer(), want.denom()),
                "{n}/{d}"
            );
        }
    }

    #[test]
    fn squares_balance_agrees_with_num_bigint() {
        // 2 x^2 + 3 y^2 + 0 z^2 against c x^2, with x and y past 512 bits: c = 5 balances when
        // y = x or y = -x; one off in c or in y does not.
        let x = BigInt::from(5).pow(400);
        let z = BigInt::from(9);
        for (y, c, want) in [
            (x.clone(), BigInt::from(5), true),
            (-&x, BigInt::from(5), true),
            (x.clone(), BigInt::from(6), false),
            (&x + 1, BigInt::from(5), false),
        ] {
            let w = x.clone();
            let (two, three, zero) = (BigInt::from(2), BigInt::from(3), BigInt::zero());
            // The same balance in num-bigint's plain arithmetic.
            let big = Some(&two * &x * &x + &three * &y * &y + &zero * &z * &z == &c * &w * &w);
            let m = |v: &BigInt| integer_from_big(v);
            let (two_m, three_m, zero_m) = (m(&two), m(&three), m(&zero));
            let (xm, ym, zm, cm, wm) = (m(&x), m(&y), m(&z), m(&c), m(&w));
            let got = Integer::squares_balance(
                [(&two_m, &xm), (&three_m, &ym), (&zero_m, &zm)],
                (&cm, &wm),
            );
            assert_eq!((got, big), (Some(want), Some(want)));
        }
    }
}
