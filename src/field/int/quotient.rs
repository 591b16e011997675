//! Quotients of 256-bit integers on machine words, for the numbers a batch row compares and
//! prints: `n / d` when the quotient is small, the f64 nearest to `n / d`, and the products
//! and powers of ten the decimal printer needs. Each is the value num-bigint and num-rational
//! give (`Ratio::to_f64` is correctly rounded too), without their heap digits.

use super::U256;
use super::words::POWERS_OF_TEN;

impl U256 {
    /// The bit length (0 for 0).
    pub(crate) fn bits(self) -> u32 {
        if self.hi != 0 {
            256 - self.hi.leading_zeros()
        } else {
            128 - self.lo.leading_zeros()
        }
    }

    /// `self * o`, or `None` at 2^256 or more.
    #[inline(always)]
    pub(crate) fn checked_mul_wide(self, o: U256) -> Option<U256> {
        match (self.hi, o.hi) {
            // Both below 2^128 (an audit's usual operands): one product, which never overflows.
            (0, 0) => Some(U256::product(self.lo, o.lo)),
            (_, 0) => self.checked_mul(o.lo),
            (0, _) => o.checked_mul(self.lo),
            _ => None, // both at least 2^128
        }
    }

    /// `10^k`, or `None` past 10^76.
    pub(crate) fn pow10(k: u32) -> Option<U256> {
        let ten = |k: u32| u128::from(POWERS_OF_TEN[k as usize]);
        match k {
            0..=19 => Some(U256 { hi: 0, lo: ten(k) }),
            // 10^38 < 2^127: one product of words.
            20..=38 => Some(U256 {
                hi: 0,
                lo: ten(19) * ten(k - 19),
            }),
            39..=76 => U256::pow10(38)?.checked_mul(U256::pow10(k - 38)?.lo),
            _ => None,
        }
    }

    /// `(self / d, self mod d)` for `d > 0` when the quotient is below 2^63.
    ///
    /// The quotient is estimated from the top 64 bits of `d` (rounded up) and the bits of
    /// `self` above the same place, which never overshoots and falls short by at most two;
    /// the remainder then corrects it.
    ///
    /// # Panics
    /// If `d` is zero or the quotient is 2^63 or more.
    pub(crate) fn div_small(self, d: U256) -> (u64, U256) {
        const LIMIT: u128 = 1 << 63;
        assert!(d != U256::ZERO, "division by zero");
        let too_big = "the quotient is below 2^63";
        if self.hi == 0 && d.hi == 0 {
            let quotient = self.lo / d.lo;
            assert!(quotient < LIMIT, "{too_big}");
            let rest = U256 {
                hi: 0,
                lo: self.lo - quotient * d.lo,
            };
            return (quotient as u64, rest);
        }
        let shift = d.bits().saturating_sub(64);
        let (n_top, d_top) = (self.shr(shift), d.shr(shift).lo);
        // self < 2^63 d < 2^(63 + bits(d)), so the bits of self from `shift` up fit 127.
        assert!(n_top.hi == 0, "{too_big}");
        let mut quotient = if shift == 0 {
            n_top.lo / d_top
        } else {
            n_top.lo / (d_top + 1)
        };
        assert!(quotient < LIMIT, "{too_big}");
        let below = d.checked_mul(quotient).expect("at most self");
        let mut rest = self.minus(below);
        while rest >= d {
            rest = rest.minus(d);
            quotient += 1;
        }
        assert!(quotient < LIMIT, "{too_big}");
        (quotient as u64, rest)
    }

    /// [`U256::div_small`] from a guess of the quotient: checked by one product and corrected
    /// by up to two steps either way; `None` when the guess is further off.
    pub(crate) fn div_small_guessed(self, d: U256, guess: u64) -> Option<(u64, U256)> {
        let mut quotient = guess;
        let mut below = d.checked_mul(guess.into())?;
        for _ in 0..2 {
            if below <= self {
                break;
            }
            quotient = quotient.checked_sub(1)?;
            below = below.minus(d);
        }
        let mut rest = (below <= self).then(|| self.minus(below))?;
        for _ in 0..2 {
            if rest < d {
                break;
            }
            rest = rest.minus(d);
            quotient += 1;
        }
        (rest < d).then_some((quotient, rest))
    }

    /// The f64 nearest to `n / d` (ties to even), for nonzero `n` and `d`; `None` when the
    /// scaled operands would pass 2^256 (`n` or `d` of more than 202 bits).
    pub(crate) fn nearest_f64(n: U256, d: U256) -> Option<f64> {
        const EXACT_IN_F64: u128 = 1 << 53;
        if n.hi == 0 && d.hi == 0 && n.lo < EXACT_IN_F64 && d.lo < EXACT_IN_F64 {
            // Both operands are f64s exactly, and IEEE division rounds their quotient
            // correctly, ties to even.
            assert!(n.lo > 0 && d.lo > 0, "nonzero operands");
            // (Through u64: the hardware converts those; u128 takes a software routine.)
            return Some(n.lo as u64 as f64 / d.lo as u64 as f64);
        }
        let (bits_n, bits_d) = (n.bits() as i32, d.bits() as i32);
        assert!(bits_n > 0 && bits_d > 0, "nonzero operands");
        // Scaled by 2^k, the quotient lies in [2^53, 2^55): 53 bits and one or two more.
        let k = 54 + bits_d - bits_n;
        let (num, den) = if k >= 0 {
            (bits_n + k <= 256).then(|| (n.shl(k as u32), d))?
        } else {
            (bits_d - k <= 256).then(|| (n, d.shl(-k as u32)))?
        };
        let (q, inexact) = if num.hi == 0 && den.hi == 0 {
            // The batch's f64 inputs: a division of two words.
            let q = num.lo / den.lo;
            (q as u64, q * den.lo != num.lo)
        } else {
            let (q, rest) = num.div_small(den);
            (q, rest != U256::ZERO)
        };
        let extra = (64 - q.leading_zeros()) - 53; // 1 or 2 bits below the mantissa
        let mantissa = q >> extra;
        let below = q & ((1 << extra) - 1);
        let half = 1 << (extra - 1);
        let up = below > half || (below == half && (inexact || mantissa & 1 == 1));
        let mantissa = mantissa + u64::from(up); // 2^53 at most: exact in f64
        // 2^(extra - k) is within 2^-310..2^204: a normal power of two, so the product is exact.
        let exponent = extra as i32 - k;
        let scale = f64::from_bits(((exponent + 1023) as u64) << 52);
        Some(mantissa as f64 * scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;
    use num_bigint::{BigInt, BigUint};
    use num_integer::Integer;
    use num_traits::ToPrimitive;
    use proptest::prelude::*;

    #[test]
    fn powers_of_ten_up_to_the_width() {
        for k in 0..=76u32 {
            let want = num_traits::pow(BigUint::from(10u8), k as usize);
            assert_eq!(U256::pow10(k).map(U256::to_big), Some(want), "10^{k}");
        }
        assert_eq!(U256::pow10(77), None); // beyond 10^76 by contract
    }

    /// A value of up to `bits` bits from four random words, cut to a random length.
    fn word_value(limbs: [u64; 4], len: u32) -> U256 {
        let x = U256 {
            hi: u128::from(limbs[3]) << 64 | u128::from(limbs[2]),
            lo: u128::from(limbs[1]) << 64 | u128::from(limbs[0]),
        };
        if len >= 256 { x } else { x.shr(256 - len) }
    }

    #[test]
    fn powers_of_ten_and_wide_products() {
        let big = |x: U256| BigInt::from(x.to_big());
        for k in 0..=76 {
            assert_eq!(big(U256::pow10(k).unwrap()), BigInt::from(10u8).pow(k));
        }
        assert_eq!(U256::pow10(77), None);
        let half = U256::ONE.shl(128);
        assert_eq!(half.checked_mul_wide(half), None);
        assert_eq!(
            half.checked_mul_wide(U256::pow10(3).unwrap()).map(big),
            Some(big(half) * 1000)
        );
        assert_eq!(
            (U256::ZERO.bits(), U256::ONE.bits(), half.bits()),
            (0, 1, 129)
        );
    }

    #[test]
    fn nearest_f64_rounds_ties_to_even_and_reaches_the_extremes() {
        let w = |x: u128| U256 { hi: 0, lo: x };
        // 2^53 + 1 is halfway between two floats: down to the even one; 2^53 + 3 up.
        assert_eq!(
            U256::nearest_f64(w((1 << 53) + 1), w(1)),
            Some(9007199254740992.0)
        );
        assert_eq!(
            U256::nearest_f64(w((1 << 53) + 3), w(1)),
            Some(9007199254740996.0)
        );
        let max = U256 {
            hi: u128::MAX,
            lo: u128::MAX,
        };
        assert_eq!(U256::nearest_f64(max, w(1)), Some(2f64.powi(256)));
        assert_eq!(U256::nearest_f64(w(1), max.shr(54)), Some(2f64.powi(-202)));
        assert_eq!(U256::nearest_f64(w(1), max), None);
    }

    proptest! {
        /// The small quotient and its remainder are num-bigint's, and the nearest f64 is
        /// num-rational's correctly rounded one, over every size of operand.
        #[test]
        fn quotients_match_big_integers(
            a in any::<[u64; 4]>(), la in 1u32..=256,
            b in any::<[u64; 4]>(), lb in 1u32..=256,
            q in any::<u64>(),
        ) {
            let (n, d) = (word_value(a, la), word_value(b, lb));
            prop_assume!(n != U256::ZERO && d != U256::ZERO);
            let want = Q::new(n.to_big().into(), d.to_big().into()).to_f64().unwrap();
            match U256::nearest_f64(n, d) {
                Some(x) => prop_assert_eq!(x, want),
                None => prop_assert!(n.bits() > 202 || d.bits() > 202),
            }
            // A dividend with a quotient below 2^63: d * q + a remainder below d.
            let q = q >> 1;
            if let Some(product) = d.checked_mul(q.into()) {
                let r = word_value(a, lb).shr(1);
                let r = if r >= d { U256::ZERO } else { r };
                let dividend = product.checked_add(r);
                prop_assume!(dividend.is_some());
                let dividend = dividend.unwrap();
                let (bq, br) = dividend.to_big().div_rem(&d.to_big());
                let (wq, wr) = dividend.div_small(d);
                prop_assert_eq!((BigUint::from(wq), wr.to_big()), (bq, br));
            }
        }
    }
}
