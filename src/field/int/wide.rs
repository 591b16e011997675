//! Signed integers of a fixed number of 64-bit limbs with checked arithmetic (`Limbs<N>`): the
//! 512-bit `Wide`, the second fixed width of the fast path, and the 1024-bit `Wider` and
//! 2560-bit `Widest` of an engine row's audit.
//!
//! Scenes with numbers of about 10^6 (20 bits) give fraction-free values of about 120 bits and
//! law identities of up to about 330 bits: too wide for `i128`, far below what needs heap
//! digits. An engine's claim of 5e-107 for a zero (a 356-bit power of ten) squared in the
//! audit's energies needs about 800 bits. Sign and magnitude (limbs least significant first);
//! the loops run over the limbs in use only, so small values cost little more than machine
//! words.

use super::Int;
use super::words::U256;
use crate::field::Q;
use num_bigint::{BigInt, BigUint, Sign};
use std::cmp::Ordering;

/// A signed integer of at most `64 N` bits (`N >= 4`: a 256-bit word fits); zero is never
/// negative.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Limbs<const N: usize> {
    negative: bool,
    mag: [u64; N],
}

/// A signed integer of at most 512 bits.
pub(crate) type Wide = Limbs<8>;

/// A signed integer of at most 1024 bits.
pub(crate) type Wider = Limbs<16>;

/// A signed integer of at most 2560 bits: the square of the smallest f64 written out in
/// decimal (`4.9406564584124654e-324`, 17 digits over 10^340, 1130 bits) with room to spare.
pub(crate) type Widest = Limbs<40>;

impl<const N: usize> Limbs<N> {
    const ZERO: Limbs<N> = Limbs {
        negative: false,
        mag: [0; N],
    };

    /// Whether the representation holds its invariant: zero is never negative (so the derived
    /// `==` is equality of numbers). Asserted by the property tests of every operation.
    #[cfg(test)]
    fn is_valid(&self) -> bool {
        !(self.negative && self.is_zero())
    }

    /// The number of limbs in use (0 for zero).
    fn len(&self) -> usize {
        self.mag.iter().rposition(|&x| x != 0).map_or(0, |i| i + 1)
    }

    pub(crate) fn is_zero(&self) -> bool {
        // An OR over the limbs: comparing the arrays calls memcmp, which took 19 % of the path's
        // time.
        self.mag.iter().fold(0, |acc, &x| acc | x) == 0
    }

    fn signed(negative: bool, mag: [u64; N]) -> Self {
        let mut w = Limbs { negative, mag };
        if w.is_zero() {
            w.negative = false;
        }
        w
    }

    fn compare_magnitudes(a: &[u64; N], b: &[u64; N]) -> Ordering {
        a.iter().rev().cmp(b.iter().rev())
    }

    fn add_magnitudes(a: &[u64; N], b: &[u64; N]) -> Option<[u64; N]> {
        let mut out = [0; N];
        let mut carry = false;
        for i in 0..N {
            let (s, c1) = a[i].overflowing_add(b[i]);
            let (s, c2) = s.overflowing_add(u64::from(carry));
            out[i] = s;
            carry = c1 || c2;
        }
        (!carry).then_some(out)
    }

    /// `a - b` for `a >= b`.
    fn sub_magnitudes(a: &[u64; N], b: &[u64; N]) -> [u64; N] {
        let mut out = [0; N];
        let mut borrow = false;
        for i in 0..N {
            let (d, b1) = a[i].overflowing_sub(b[i]);
            let (d, b2) = d.overflowing_sub(u64::from(borrow));
            out[i] = d;
            borrow = b1 || b2;
        }
        out
    }

    pub(crate) fn checked_add(&self, o: &Self) -> Option<Self> {
        if self.negative == o.negative {
            return Some(Self::signed(
                self.negative,
                Self::add_magnitudes(&self.mag, &o.mag)?,
            ));
        }
        Some(match Self::compare_magnitudes(&self.mag, &o.mag) {
            Ordering::Less => Self::signed(o.negative, Self::sub_magnitudes(&o.mag, &self.mag)),
            _ => Self::signed(self.negative, Self::sub_magnitudes(&self.mag, &o.mag)),
        })
    }

    pub(crate) fn negated(&self) -> Self {
        Self::signed(!self.negative, self.mag)
    }

    pub(crate) fn checked_mul(&self, o: &Self) -> Option<Self> {
        let (la, lb) = (self.len(), o.len());
        if la == 0 || lb == 0 {
            return Some(Self::ZERO);
        }
        let negative = self.negative != o.negative;
        if la <= 2 && lb <= 2 {
            // Both below 2^128 (most of an audit's products): one 128 x 128-bit product.
            let word = |w: &Self| u128::from(w.mag[0]) | u128::from(w.mag[1]) << 64;
            let product = U256 {
                hi: 0,
                lo: word(self),
            }
            .checked_mul(word(o))
            .expect("a 128 x 128-bit product fits 256 bits");
            return Some(Self::from_u256(negative, product));
        }
        // The product has la + lb - 1 or la + lb limbs: every partial product lands below
        // limb N, and only a last carry can reach it.
        if la + lb - 1 > N {
            return None;
        }
        let mut out = [0u64; N];
        for i in 0..la {
            let mut carry = 0u128;
            for j in 0..lb {
                let t =
                    u128::from(self.mag[i]) * u128::from(o.mag[j]) + u128::from(out[i + j]) + carry;
                out[i + j] = t as u64;
                carry = t >> 64;
            }
            match out.get_mut(i + lb) {
                Some(slot) => *slot = carry as u64,
                None if carry != 0 => return None,
                None => {}
            }
        }
        Some(Self::signed(negative, out))
    }

    /// `-n` (when `negative`) or `n`.
    pub(crate) fn from_u256(negative: bool, n: U256) -> Self {
        const { assert!(N >= 4, "a 256-bit word fits") };
        let mut mag = [0; N];
        mag[0] = n.lo as u64;
        mag[1] = (n.lo >> 64) as u64;
        mag[2] = n.hi as u64;
        mag[3] = (n.hi >> 64) as u64;
        Self::signed(negative, mag)
    }

    /// The sign: less than, equal to or greater than zero.
    pub(crate) fn sign(&self) -> Ordering {
        match (self.negative, self.is_zero()) {
            (true, _) => Ordering::Less,
            (false, true) => Ordering::Equal,
            (false, false) => Ordering::Greater,
        }
    }

    /// The order of the signed values.
    pub(crate) fn cmp_signed(&self, o: &Self) -> Ordering {
        match (self.negative, o.negative) {
            (false, true) => Ordering::Greater,
            (true, false) => Ordering::Less,
            (false, false) => Self::compare_magnitudes(&self.mag, &o.mag),
            (true, true) => Self::compare_magnitudes(&o.mag, &self.mag),
        }
    }

    fn from_big(x: &BigInt) -> Option<Self> {
        if x.bits() > 64 * N as u64 {
            return None;
        }
        let mut mag = [0; N];
        for (slot, digit) in mag.iter_mut().zip(x.magnitude().iter_u64_digits()) {
            *slot = digit;
        }
        Some(Self::signed(x.sign() == Sign::Minus, mag))
    }

    fn magnitude_to_big(mag: &[u64]) -> BigUint {
        let digits: Vec<u32> = mag
            .iter()
            .flat_map(|&x| [x as u32, (x >> 32) as u32])
            .collect();
        BigUint::new(digits)
    }

    pub(crate) fn to_big(self) -> BigInt {
        let sign = if self.negative {
            Sign::Minus
        } else {
            Sign::Plus
        };
        let magnitude = match self.len() {
            0..=2 => BigUint::from(u128::from(self.mag[0]) | u128::from(self.mag[1]) << 64),
            len => Self::magnitude_to_big(&self.mag[..len]),
        };
        BigInt::from_biguint(sign, magnitude)
    }

    /// The magnitude as a [`U256`] when it fits.
    fn to_u256(self) -> Option<U256> {
        (self.len() <= 4).then(|| U256 {
            lo: u128::from(self.mag[0]) | u128::from(self.mag[1]) << 64,
            hi: u128::from(self.mag[2]) | u128::from(self.mag[3]) << 64,
        })
    }
}

impl<const N: usize> super::FixedInt for Limbs<N> {
    const BITS: u32 = 64 * N as u32;
    fn of_words(negative: bool, x: U256) -> Option<Self> {
        Some(Self::from_u256(negative, x))
    }
    fn to_words(&self) -> Option<(bool, U256)> {
        Some((self.negative, self.to_u256()?))
    }
    fn to_big(&self) -> BigInt {
        Limbs::to_big(*self)
    }
}

impl<const N: usize> Int for Limbs<N> {
    fn lift(x: &BigInt) -> Option<Self> {
        Self::from_big(x)
    }
    fn small(x: u8) -> Self {
        let mut mag = [0; N];
        mag[0] = x.into();
        Self::signed(false, mag)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        self.checked_add(o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        self.checked_add(&o.negated())
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        self.checked_mul(o)
    }
    fn squares_balance(lhs: [(&Self, &Self); 3], (c, x): (&Self, &Self)) -> Option<bool> {
        let mut sum = Self::ZERO;
        for (c, x) in lhs {
            sum = sum.checked_add(&c.checked_mul(&x.checked_mul(x)?)?)?;
        }
        Some(sum == c.checked_mul(&x.checked_mul(x)?)?)
    }
    fn ratio(n: Self, d: Self) -> Q {
        match (n.to_u256(), d.to_u256()) {
            (Some(a), Some(b)) => U256::ratio(n.negative, a, b),
            _ => Q::new(n.to_big(), d.to_big()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn big(s: &str) -> BigInt {
        s.parse().unwrap()
    }

    #[test]
    fn limits_of_the_width() {
        let top = (BigInt::from(1) << 512u32) - 1;
        let w = Wide::from_big(&top).unwrap();
        assert_eq!(w.to_big(), top);
        assert_eq!(Wide::from_big(&(top.clone() + 1)), None);
        assert_eq!(w.add(&Wide::small(1)), None);
        assert_eq!(w.negated().sub(&Wide::small(1)), None);
        assert_eq!(w.sub(&w), Some(Wide::ZERO));
        let half = Wide::from_big(&(BigInt::from(1) << 256u32)).unwrap();
        assert_eq!(half.mul(&half), None);
        let just = Wide::from_big(&(BigInt::from(1) << 255u32)).unwrap();
        assert_eq!(just.mul(&half).unwrap().to_big(), BigInt::from(1) << 511u32);
        assert_eq!(Wide::small(0).negated(), Wide::ZERO);
    }

    #[test]
    fn ratio_reduces_like_num_rational() {
        let cases = [
            ("-84", "36"),
            (
                "605266953260872505155079183529643000000",
                "42781701118546417863969985673251741000000",
            ),
            ("0", "17"),
            (
                "115792089237316195423570985008687907853269984665640564039457584007913129639936",
                "6",
            ),
        ];
        for (n, d) in cases {
            let (wn, wd) = (
                Wide::from_big(&big(n)).unwrap(),
                Wide::from_big(&big(d)).unwrap(),
            );
            assert_eq!(Wide::ratio(wn, wd), Q::new(big(n), big(d)), "{n}/{d}");
        }
    }

    /// A signed integer of up to `32 words` bits.
    fn int(words: usize) -> impl Strategy<Value = BigInt> {
        (
            any::<bool>(),
            proptest::collection::vec(any::<u32>(), 0..words),
        )
            .prop_map(|(negative, digits)| {
                let m = BigInt::from(BigUint::new(digits));
                if negative { -m } else { m }
            })
    }

    /// Whether every operation of `Limbs<N>` on `a` and `b` agrees with big integers, or
    /// reports overflow exactly when the result needs more than `64 N` bits.
    fn agrees<const N: usize>(a: &BigInt, b: &BigInt) -> bool {
        let (wa, wb) = (
            Limbs::<N>::from_big(a).unwrap(),
            Limbs::<N>::from_big(b).unwrap(),
        );
        let fits = |x: &BigInt| x.bits() <= 64 * N as u64;
        let check = |got: Option<Limbs<N>>, want: BigInt| match got {
            Some(w) => w.is_valid() && w.to_big() == want,
            None => !fits(&want),
        };
        check(wa.add(&wb), a + b)
            && check(wa.sub(&wb), a - b)
            && check(wa.mul(&wb), a * b)
            && check(wa.mul(&wa), a * a)
            && wa.is_valid()
            && wb.is_valid()
    }

    proptest! {
        /// Law: every operation of the 512-bit width agrees with big integers, or reports
        /// overflow exactly when the result needs more than 512 bits.
        #[test]
        fn agrees_with_big_integers(a in int(10), b in int(10)) {
            prop_assert!(agrees::<8>(&a, &b));
        }

        /// Law: the same of the 1024-bit width, on operands of up to 600 bits.
        #[test]
        fn the_wider_width_agrees_with_big_integers(a in int(19), b in int(19)) {
            prop_assert!(agrees::<16>(&a, &b));
        }
    }

    #[test]
    fn a_negative_zero_is_invalid_and_never_made() {
        let negative_zero = Wide {
            negative: true,
            mag: [0; 8],
        };
        assert!(!negative_zero.is_valid());
        let one = Wide::from_big(&BigInt::from(1)).unwrap();
        let minus_one = Wide::from_big(&BigInt::from(-1)).unwrap();
        assert!(one.add(&minus_one).unwrap().is_valid());
        assert!(minus_one.sub(&minus_one).unwrap().is_valid());
    }
}
