//! [`Field`] for exact rationals ([`Q`] = `BigRational`).

use super::int::U256;
use super::{Field, Q, TrySqrt};
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

impl Field for Q {
    const NAME: &'static str = "Q";
    const EXACT: bool = true;

    fn size_bits(&self) -> u64 {
        self.numer().bits() + self.denom().bits()
    }

    fn from_rational(q: &Q) -> Self {
        q.clone()
    }

    fn sign(&self) -> Option<Ordering> {
        Some(if self.is_zero() {
            Ordering::Equal
        } else if self.is_positive() {
            Ordering::Greater
        } else {
            Ordering::Less
        })
    }

    /// Correctly rounded: on machine words when both parts fit (see `U256::nearest_f64`),
    /// else by num-rational (also correctly rounded, on heap digits).
    fn nearest_f64(&self) -> f64 {
        let words = || {
            let (negative, n, d) = U256::parts_of(self)?;
            if n == U256::ZERO {
                return Some(0.0);
            }
            let x = U256::nearest_f64(n, d)?;
            Some(if negative { -x } else { x })
        };
        words().unwrap_or_else(|| self.to_f64().unwrap_or(f64::NAN))
    }
}

impl TrySqrt for Q {
    /// The rational square root when both the reduced numerator and denominator are squares.
    fn try_sqrt(&self) -> Option<Self> {
        if self.is_negative() {
            return None;
        }
        let (n, d) = (self.numer(), self.denom());
        let (rn, rd) = (n.sqrt(), d.sqrt());
        (&rn * &rn == *n && &rd * &rd == *d).then(|| Q::new(rn, rd))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};

    #[test]
    fn field_laws_hold_exactly() {
        let huge = Q::from_integer(num_bigint::BigInt::from(10u32).pow(400));
        let tiny = Q::new(1.into(), num_bigint::BigInt::from(7u32).pow(300));
        let samples = [q(0, 1), q(1, 1), q(-1, 1), q(1, 3), q(-22, 7), huge, tiny];
        laws::check_field(&samples, |a, b| a == b);
    }

    #[test]
    fn square_roots_exist_only_for_rational_squares() {
        assert_eq!(q(4, 9).try_sqrt(), Some(q(2, 3)));
        assert_eq!(q(2, 3).try_sqrt(), None);
        assert_eq!(q(-4, 9).try_sqrt(), None);
        assert_eq!(q(0, 1).try_sqrt(), Some(q(0, 1)));
    }

    proptest::proptest! {
        /// The nearest f64, on words or on heap digits, is num-rational's correctly rounded
        /// value (both signs, parts of 1 to 300 bits: across the 256-bit word limit).
        #[test]
        fn nearest_f64_is_correctly_rounded(
            n in proptest::collection::vec(proptest::prelude::any::<u32>(), 0..10),
            d in proptest::collection::vec(proptest::prelude::any::<u32>(), 1..10),
            negative: bool,
        ) {
            use num_bigint::{BigInt, BigUint};
            let d = BigUint::new(d) + 1u8;
            let n = BigInt::from(BigUint::new(n));
            let x = Q::new(if negative { -n } else { n }, d.into());
            proptest::prop_assert_eq!(x.nearest_f64().to_bits(), x.to_f64().unwrap().to_bits());
        }
    }

    #[test]
    fn sign_is_decided() {
        assert_eq!(q(-1, 3).sign(), Some(Ordering::Less));
        assert_eq!(q(0, 3).sign(), Some(Ordering::Equal));
        assert_eq!(q(1, 3).sign(), Some(Ordering::Greater));
    }
}
