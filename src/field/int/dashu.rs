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
use dashu_int::ops::Gcd;
use dashu_int::{IBig, Sign as DashuSign, UBig};
use num_bigint::{BigInt, BigUint, Sign};

/// `x` as a dashu [`IBig`].
fn ibig_from_big(x: &BigInt) -> IBig {
    let magnitude = UBig::from_le_bytes(&x.magnitude().to_bytes_le());
    let sign = if x.sign() == Sign::Minus {
        DashuSign::Negative
    } else {
        DashuSign::Positive
    };
    IBig::from_parts(sign, magnitude)
}

/// `x` as a num-bigint [`BigUint`].
fn big_from_ubig(x: &UBig) -> BigUint {
    BigUint::from_bytes_le(&x.to_le_bytes())
}

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
    use num_traits::One;
    use proptest::prelude::*;

    /// `x` as a num-bigint [`BigInt`].
    fn big_from_ibig(x: IBig) -> BigInt {
        let (sign, magnitude) = x.into_parts();
        let sign = if sign == DashuSign::Negative {
            Sign::Minus
        } else {
            Sign::Plus
        };
        BigInt::from_biguint(sign, big_from_ubig(&magnitude))
    }

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
            prop_assert_eq!(big_from_ibig(x.clone()), a.clone());
            prop_assert_eq!(big_from_ibig(x.mul(&y).unwrap()), &a * &b);
            prop_assert_eq!(big_from_ibig(x.sub(&y).unwrap()), &a - &b);
            let d = b.magnitude() + BigUint::one();
            let q = IBig::ratio(x, ibig_from_big(&BigInt::from(d.clone())));
            prop_assert_eq!(q, Q::new(a, BigInt::from(d)));
        }
    }
}
