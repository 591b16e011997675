//! Fixed-width integers that wrap: the ring Z/2^(64N) in two's complement, N 64-bit limbs.
//!
//! The word-level batch row ([`crate::batch`]) sizes N from the bit lengths of a row's inputs
//! before it computes anything, so that every exact value it forms lies in
//! `(-2^(64N-1), 2^(64N-1))`. In that range the ring is the integers: a sum or product that wraps
//! cannot happen, equality in the ring is equality of integers, and no operation needs a check
//! (the checked 512-bit `Wide` pays for an `Option` and a length scan on every step).

/// An integer modulo 2^(64N), two's complement, least significant limb first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Ring<const N: usize>(pub(crate) [u64; N]);

impl<const N: usize> Ring<N> {
    /// `magnitude`, negated when `negative`.
    pub(crate) fn signed(negative: bool, magnitude: u64) -> Self {
        let mut limbs = [0; N];
        limbs[0] = magnitude;
        let x = Ring(limbs);
        if negative { x.neg() } else { x }
    }

    /// A non-negative value below 2^127 (N >= 2).
    pub(crate) fn from_u128(x: u128) -> Self {
        let mut limbs = [0; N];
        limbs[0] = x as u64;
        limbs[1] = (x >> 64) as u64;
        Ring(limbs)
    }

    /// Whether the value, read as a signed integer, is below zero.
    pub(crate) fn is_negative(&self) -> bool {
        self.0[N - 1] >> 63 == 1
    }

    /// `-self`.
    pub(crate) fn neg(self) -> Self {
        let mut out = [0; N];
        let mut carry = 1u64;
        for (o, x) in out.iter_mut().zip(self.0) {
            let (sum, c) = (!x).overflowing_add(carry);
            *o = sum;
            carry = u64::from(c);
        }
        Ring(out)
    }

    /// `self + o`, wrapping.
    pub(crate) fn add(self, o: Self) -> Self {
        let mut out = [0; N];
        let mut carry = false;
        for ((out, x), y) in out.iter_mut().zip(self.0).zip(o.0) {
            let (s, c1) = x.overflowing_add(y);
            let (s, c2) = s.overflowing_add(u64::from(carry));
            *out = s;
            carry = c1 | c2;
        }
        Ring(out)
    }

    /// `self - o`, wrapping.
    pub(crate) fn sub(self, o: Self) -> Self {
        let mut out = [0; N];
        let mut borrow = false;
        for ((out, x), y) in out.iter_mut().zip(self.0).zip(o.0) {
            let (d, b1) = x.overflowing_sub(y);
            let (d, b2) = d.overflowing_sub(u64::from(borrow));
            *out = d;
            borrow = b1 | b2;
        }
        Ring(out)
    }

    /// `self * o`, wrapping: the low N limbs of the product (schoolbook, the limb products
    /// below the diagonal only; a zero limb of `self` is skipped).
    pub(crate) fn mul(self, o: Self) -> Self {
        let mut out = [0; N];
        for i in 0..N {
            let x = self.0[i];
            if x == 0 {
                continue;
            }
            let mut carry = 0u128;
            for j in 0..N - i {
                let t = u128::from(x) * u128::from(o.0[j]) + u128::from(out[i + j]) + carry;
                out[i + j] = t as u64;
                carry = t >> 64;
            }
        }
        Ring(out)
    }

    /// The same integer in M limbs: sign-extended when M > N, truncated when M < N (the
    /// caller knows it lies in M limbs' signed range).
    pub(crate) fn resize<const M: usize>(self) -> Ring<M> {
        let fill = if self.is_negative() { u64::MAX } else { 0 };
        let mut out = [fill; M];
        let kept = N.min(M);
        out[..kept].copy_from_slice(&self.0[..kept]);
        Ring(out)
    }

    /// The sign and the magnitude as 128-bit halves `(hi, lo)` (N <= 4; the value's magnitude
    /// below 2^256).
    pub(crate) fn sign_magnitude(self) -> (bool, u128, u128) {
        let negative = self.is_negative();
        let m = if negative { self.neg() } else { self };
        let limb = |k: usize| u128::from(m.0.get(k).copied().unwrap_or(0));
        (negative, limb(3) << 64 | limb(2), limb(1) << 64 | limb(0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use proptest::prelude::*;

    fn to_big<const N: usize>(x: Ring<N>) -> BigInt {
        let mut value = BigInt::from(0);
        for limb in x.0.iter().rev() {
            value = (value << 64) + BigInt::from(*limb);
        }
        if x.is_negative() {
            value - (BigInt::from(1) << (64 * N))
        } else {
            value
        }
    }

    fn from_i128<const N: usize>(x: i128) -> Ring<N> {
        Ring::<2>([x as u64, (x >> 64) as u64]).resize()
    }

    proptest! {
        /// In 4 limbs the products of two 126-bit values are exact: the ring agrees with the
        /// integers on every operation, and the signed magnitude reads back.
        #[test]
        fn the_ring_is_the_integers_in_range(a in -(1i128 << 125)..(1i128 << 125), b in -(1i128 << 125)..(1i128 << 125), m in any::<u64>(), neg in any::<bool>()) {
            let (x, y) = (from_i128::<4>(a), from_i128::<4>(b));
            let (ba, bb) = (BigInt::from(a), BigInt::from(b));
            prop_assert_eq!(to_big(x.mul(y)), &ba * &bb);
            prop_assert_eq!(to_big(x.add(y)), &ba + &bb);
            prop_assert_eq!(to_big(x.sub(y)), &ba - &bb);
            prop_assert_eq!(to_big(x.neg()), -&ba);
            prop_assert_eq!(to_big(x.mul(y).resize::<6>()), &ba * &bb);
            prop_assert_eq!(to_big(x.resize::<2>()), ba.clone());
            let s = Ring::<3>::signed(neg, m);
            prop_assert_eq!(to_big(Ring::<3>::from_u128(a.unsigned_abs())), BigInt::from(a.unsigned_abs()));
            prop_assert_eq!(to_big(s), if neg { -BigInt::from(m) } else { BigInt::from(m) });
            let (negative, hi, lo) = x.mul(y).sign_magnitude();
            let magnitude: BigInt = (BigInt::from(hi) << 128) + BigInt::from(lo);
            prop_assert_eq!(if negative { -magnitude } else { magnitude }, &ba * &bb);
        }
    }
}
