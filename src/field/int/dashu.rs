//! The big-integer fallback on dashu's [`IBig`] (the default; MIT/Apache-2.0).
//!
//! Beyond the 512-bit width the fraction-free route needs unbounded integers. num-bigint's
//! multiplication is schoolbook and its GCD a quadratic binary GCD with a large constant;
//! dashu multiplies with Karatsuba and Toom-3 and reduces with a Lehmer GCD, 4-6 times faster
//! from 32 to 10,000 bits. The scene is lifted into dashu once, the solve runs there, and each
//! output is reduced there and handed back as num-bigint's [`Q`], the same value and
//! representation as `Q::new(n, d)`: the public exact types do not change. malachite (feature
//! `malachite`) replaces it for huge inputs, where its half-GCD pulls ahead.
//!
//! Conversions go through little-endian bytes (linear time, the same on every word size).

use super::Int;
use crate::field::Q;
use crate::field::big::{big_from_ubig, ibig_from_big};
use dashu_int::ops::Gcd;
use dashu_int::{IBig, Sign as DashuSign};
use num_bigint::{BigInt, Sign};

impl Int for IBig {
    fn lift(x: &BigInt) -> Option<Self> {
        Some(ibig_from_big(x))
    }
    fn small(x: u8) -> Self {
        IBig::from(x)
    }
    unbounded_arithmetic!();
    fn ratio(n: Self, d: Self) -> Q {
        // d > 0, so g >= 1; n/g and d/g are exact. With g = 1 nothing is divided.
        let (sign, n) = n.into_parts();
        let d = d.into_parts().1;
        let g = (&n).gcd(&d);
        let (n, d) = if g.is_one() { (n, d) } else { (n / &g, d / g) };
        let sign = if sign == DashuSign::Negative {
            Sign::Minus
        } else {
            Sign::Plus
        };
        Q::new_raw(
            BigInt::from_biguint(sign, big_from_ubig(&n)),
            BigInt::from_biguint(Sign::Plus, big_from_ubig(&d)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::big::big_from_ibig;
    use num_bigint::BigUint;
    use num_traits::One;
    use proptest::prelude::*;

    fn big() -> impl Strategy<Value = BigInt> {
        (
            proptest::collection::vec(any::<u32>(), 0..80),
            any::<bool>(),
        )
            .prop_map(|(digits, negative)| {
                let x = BigInt::from(BigUint::new(digits));
                if negative { -x } else { x }
            })
    }

    proptest! {
        /// Values of up to 2,560 bits, both signs and zero, go through dashu and back
        /// unchanged, its arithmetic agrees with num-bigint's, and a fraction reduced in dashu
        /// is num-rational's.
        #[test]
        fn dashu_agrees_with_num_bigint(a in big(), b in big()) {
            let (x, y) = (ibig_from_big(&a), ibig_from_big(&b));
            prop_assert_eq!(big_from_ibig(&x), a.clone());
            prop_assert_eq!(big_from_ibig(&x.mul(&y).unwrap()), &a * &b);
            prop_assert_eq!(big_from_ibig(&x.sub(&y).unwrap()), &a - &b);
            let d = b.magnitude() + BigUint::one();
            let q = IBig::ratio(x, ibig_from_big(&BigInt::from(d.clone())));
            prop_assert_eq!(q, Q::new(a, BigInt::from(d)));
        }
    }

    /// G1 (docs/upstream-dashu-gcd.md): dashu-int 0.4.3's gcd panicked ("not enough memory
    /// allocated") on these 91-word operands, the smallest of their shape, and on the
    /// reduction of `solve --m 1 --M 1 --pivot 1e-622`. Fixed upstream in 0.5.1; rodimpact
    /// requires 0.6. The reduction must give num-rational's value.
    #[test]
    fn the_operands_that_made_dashu_0_4_panic_reduce() {
        let two = BigInt::from(2u8);
        let w = two.pow(3648) + 1;
        let v = two.pow(2112) * &w + 1;
        let u = &v + &w;
        for (n, d) in [(&u, &v), (&v, &u)] {
            let reduced = IBig::ratio(ibig_from_big(n), ibig_from_big(d));
            prop_assert_eq_plain(reduced, Q::new(n.clone(), d.clone()));
        }
        // The scene's own pair: 2P^3(P-3) over 2P^2(2P^2-3P+3), P = 10^622.
        let p = BigInt::from(10u8).pow(622);
        let n = 2 * p.pow(3) * (&p - 3);
        let d = 2 * p.pow(2) * (2 * p.pow(2) - 3 * &p + 3);
        prop_assert_eq_plain(
            IBig::ratio(ibig_from_big(&n), ibig_from_big(&d)),
            Q::new(n, d),
        );
    }

    fn prop_assert_eq_plain(a: Q, b: Q) {
        assert_eq!((a.numer(), a.denom()), (b.numer(), b.denom()));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Lopsided pairs `(Q R + 1 + R, Q R + 1)` of 20-220 words, the family on which
        /// dashu-int 0.4.3's gcd panicked 1,850 times in 2,747 (a Lehmer step dividing a long
        /// remainder by a much shorter one): reduced as num-rational reduces them.
        #[test]
        fn lopsided_gcds_reduce(r_words in 20usize..220, q_words in 20usize..140, seed in any::<u64>()) {
            let mut state = seed | 1;
            let mut word = || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state
            };
            let mut random = |words: usize| {
                BigInt::from(BigUint::new((0..2 * words).map(|_| word() as u32).collect()))
            };
            let (r, q) = (random(r_words) + 1, random(q_words) + 1);
            let v = &q * &r + 1;
            let u = &v + &r;
            let reduced = IBig::ratio(ibig_from_big(&u), ibig_from_big(&v));
            let expected = Q::new(u, v);
            prop_assert_eq!((reduced.numer(), reduced.denom()), (expected.numer(), expected.denom()));
        }
    }
}
