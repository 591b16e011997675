//! [`Field`] for exact rationals ([`Q`] = `BigRational`).

use super::{Field, Q, TrySqrt};
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

impl Field for Q {
    const NAME: &'static str = "Q";
    const EXACT: bool = true;

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

    fn nearest_f64(&self) -> f64 {
        self.to_f64().unwrap_or(f64::NAN)
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

    #[test]
    fn sign_is_decided() {
        assert_eq!(q(-1, 3).sign(), Some(Ordering::Less));
        assert_eq!(q(0, 3).sign(), Some(Ordering::Equal));
        assert_eq!(q(1, 3).sign(), Some(Ordering::Greater));
    }
}
