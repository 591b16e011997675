//! A 256-bit signed integer with checked arithmetic (`I256`, sign and [`U256`] magnitude): the
//! narrowest width of [`super::Unreduced`] that holds an engine's 17-digit cells squared against a
//! tolerance, at two machine words' cost instead of the eight of `Wide`.

use super::Int;
use super::unreduced::UnreducedInt;
use super::words::U256;
use crate::field::Q;
use num_bigint::{BigInt, Sign};
use std::cmp::Ordering;

/// A signed integer of at most 256 bits; zero is never negative.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct I256 {
    negative: bool,
    mag: U256,
}

impl I256 {
    #[inline(always)]
    fn signed(negative: bool, mag: U256) -> I256 {
        I256 {
            negative: negative && mag != U256::ZERO,
            mag,
        }
    }
}

impl Int for I256 {
    fn lift(x: &BigInt) -> Option<Self> {
        Some(I256::signed(
            x.sign() == Sign::Minus,
            U256::from_big(x.magnitude())?,
        ))
    }
    fn small(x: u8) -> Self {
        I256::signed(
            false,
            U256 {
                hi: 0,
                lo: x.into(),
            },
        )
    }
    #[inline(always)]
    fn add(&self, o: &Self) -> Option<Self> {
        if self.negative == o.negative {
            return Some(I256::signed(self.negative, self.mag.checked_add(o.mag)?));
        }
        Some(match self.mag.cmp(&o.mag) {
            Ordering::Less => I256::signed(o.negative, o.mag.minus(self.mag)),
            _ => I256::signed(self.negative, self.mag.minus(o.mag)),
        })
    }
    #[inline(always)]
    fn sub(&self, o: &Self) -> Option<Self> {
        self.add(&I256::signed(!o.negative, o.mag))
    }
    #[inline(always)]
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(I256::signed(
            self.negative != o.negative,
            self.mag.checked_mul_wide(o.mag)?,
        ))
    }
    fn squares_balance(lhs: [(&Self, &Self); 3], (c, x): (&Self, &Self)) -> Option<bool> {
        let mut sum = I256::small(0);
        for (c, x) in lhs {
            sum = sum.add(&c.mul(&x.mul(x)?)?)?;
        }
        Some(sum == c.mul(&x.mul(x)?)?)
    }
    fn ratio(n: Self, d: Self) -> Q {
        U256::ratio(n.negative, n.mag, d.mag)
    }
}

impl super::FixedInt for I256 {
    const BITS: u32 = 256;
    fn of_words(negative: bool, x: U256) -> Option<Self> {
        Some(I256::signed(negative, x))
    }
    fn to_words(&self) -> Option<(bool, U256)> {
        Some((self.negative, self.mag))
    }
    fn to_big(&self) -> BigInt {
        let magnitude = BigInt::from(self.mag.to_big());
        if self.negative { -magnitude } else { magnitude }
    }
}

impl UnreducedInt for I256 {
    fn sign(&self) -> Ordering {
        match (self.negative, self.mag == U256::ZERO) {
            (true, _) => Ordering::Less,
            (false, true) => Ordering::Equal,
            (false, false) => Ordering::Greater,
        }
    }
    #[inline(always)]
    fn order(&self, o: &Self) -> Ordering {
        match (self.negative, o.negative) {
            (false, true) => Ordering::Greater,
            (true, false) => Ordering::Less,
            (false, false) => self.mag.cmp(&o.mag),
            (true, true) => o.mag.cmp(&self.mag),
        }
    }
    #[inline]
    fn negated(&self) -> Option<Self> {
        Some(I256::signed(!self.negative, self.mag))
    }
    fn exact_quotient(&self, d: &Self) -> Option<Self> {
        // Cheap only below 2^128 (a decimal's power of ten, a scene's small denominator).
        if self.mag.hi != 0 || d.mag.hi != 0 || d.mag.lo == 0 {
            return None;
        }
        self.mag.lo.is_multiple_of(d.mag.lo).then(|| {
            I256::signed(
                self.negative != d.negative,
                U256 {
                    hi: 0,
                    lo: self.mag.lo / d.mag.lo,
                },
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn int() -> impl Strategy<Value = BigInt> {
        (any::<bool>(), proptest::collection::vec(any::<u32>(), 0..9)).prop_map(
            |(negative, digits)| {
                let m = BigInt::from(num_bigint::BigUint::new(digits));
                if negative { -m } else { m }
            },
        )
    }

    fn big(x: I256) -> BigInt {
        let m = BigInt::from(x.mag.to_big());
        if x.negative { -m } else { m }
    }

    proptest! {
        /// Law: every operation is the big-integer one where it fits 256 bits, `None` beyond;
        /// the order and the sign are the big integers'.
        #[test]
        fn agrees_with_big_integers(a in int(), b in int()) {
            let (Some(x), Some(y)) = (I256::lift(&a), I256::lift(&b)) else {
                prop_assert!(a.bits() > 256 || b.bits() > 256);
                return Ok(());
            };
            let fits = |r: &BigInt| r.bits() <= 256;
            for (got, want) in [(x.add(&y), &a + &b), (x.sub(&y), &a - &b), (x.mul(&y), &a * &b)] {
                match got {
                    Some(r) => prop_assert_eq!(big(r), want),
                    None => prop_assert!(!fits(&want)),
                }
            }
            prop_assert_eq!(x.order(&y), a.cmp(&b));
            prop_assert_eq!(x.sign(), a.cmp(&BigInt::from(0)));
            if b.bits() <= 128 && a.bits() <= 128 && b != BigInt::from(0) {
                let want = (&a % &b == BigInt::from(0)).then(|| &a / &b);
                prop_assert_eq!(x.exact_quotient(&y).map(big), want);
            }
        }
    }
}
