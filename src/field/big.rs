//! Exact rationals on dashu ([`RBig`]): the same numbers as [`Q`], for the exact work that
//! meets numbers of thousands of digits.
//!
//! num-rational reduces every result with num-bigint's binary GCD, quadratic with a large
//! constant: twenty products and quotients of 10,000-digit fractions take 46 s. dashu reduces
//! with a Lehmer GCD and multiplies with Karatsuba and Toom-3: the same twenty take 0.26 s. The
//! public exact type stays [`Q`]; a computation that may meet big numbers lifts its inputs with
//! [`to_rbig`], runs over [`RBig`] (a [`Field`], so every generic solver and law runs on it), and
//! hands its answers back with [`to_q`], the same value and representation as `Q::new(n, d)`.
//! Conversions go through little-endian bytes (linear time).

use super::{Field, Q};
use dashu_int::{IBig, Sign as DashuSign, UBig};
use num_bigint::{BigInt, BigUint, Sign};
use std::cmp::Ordering;

pub use dashu_ratio::{RBig, Relaxed};

/// `x` as a dashu [`IBig`].
pub(crate) fn ibig_from_big(x: &BigInt) -> IBig {
    let magnitude = UBig::from_le_bytes(&x.magnitude().to_bytes_le());
    let sign = if x.sign() == Sign::Minus {
        DashuSign::Negative
    } else {
        DashuSign::Positive
    };
    IBig::from_parts(sign, magnitude)
}

/// `x` as a num-bigint [`BigUint`].
pub(crate) fn big_from_ubig(x: &UBig) -> BigUint {
    BigUint::from_bytes_le(&x.to_le_bytes())
}

/// `x` as a num-bigint [`BigInt`].
pub(crate) fn big_from_ibig(x: &IBig) -> BigInt {
    let (sign, magnitude) = x.clone().into_parts();
    let sign = if sign == DashuSign::Negative {
        Sign::Minus
    } else {
        Sign::Plus
    };
    BigInt::from_biguint(sign, big_from_ubig(&magnitude))
}

/// `q` as a dashu [`RBig`] (already reduced: no GCD is taken).
///
/// # Examples
/// ```
/// use rodimpact::field::{big::{to_q, to_rbig}, q};
/// assert_eq!(to_rbig(&q(-6, 4)).to_string(), "-3/2");
/// assert_eq!(to_q(&to_rbig(&q(-6, 4))), q(-3, 2));
/// ```
pub fn to_rbig(q: &Q) -> RBig {
    let (n, d) = dashu_parts(q);
    RBig::from_parts(n, d)
}

/// `q`'s numerator and (positive) denominator in dashu's integers.
fn dashu_parts(q: &Q) -> (IBig, UBig) {
    (
        ibig_from_big(q.numer()),
        UBig::from_le_bytes(&q.denom().magnitude().to_bytes_le()),
    )
}

/// `x` as a [`Q`]: the same value and representation (reduced, positive denominator).
///
/// # Examples
/// ```
/// use rodimpact::field::{big::{to_q, RBig}, q};
/// let x: RBig = "14/-21".parse().unwrap();
/// assert_eq!(to_q(&x), q(-2, 3));
/// ```
pub fn to_q(x: &RBig) -> Q {
    Q::new_raw(
        big_from_ibig(x.numerator()),
        BigInt::from_biguint(Sign::Plus, big_from_ubig(x.denominator())),
    )
}

/// A dashu number's order against zero, from whether it is zero and its sign.
fn order_of(zero: bool, sign: DashuSign) -> Ordering {
    match sign {
        _ if zero => Ordering::Equal,
        DashuSign::Negative => Ordering::Less,
        DashuSign::Positive => Ordering::Greater,
    }
}

impl Field for RBig {
    const NAME: &'static str = "Q (dashu)";
    const EXACT: bool = true;

    fn from_rational(q: &Q) -> Self {
        to_rbig(q)
    }

    fn sign(&self) -> Option<Ordering> {
        Some(order_of(self.is_zero(), self.numerator().sign()))
    }

    /// Correctly rounded, as [`Q`]'s.
    fn nearest_f64(&self) -> f64 {
        to_q(self).nearest_f64()
    }
}

/// `q` as a dashu [`Relaxed`]: a rational that is never reduced (but for common factors of
/// two), so a sum or product costs its multiplications and no GCD.
///
/// # Examples
/// ```
/// use rodimpact::field::{big::{relaxed_to_q, to_relaxed}, q};
/// let sum = to_relaxed(&q(1, 6)) + to_relaxed(&q(1, 3));
/// assert_eq!(relaxed_to_q(sum), q(1, 2));
/// ```
pub fn to_relaxed(q: &Q) -> Relaxed {
    let (n, d) = dashu_parts(q);
    Relaxed::from_parts(n, d)
}

/// `x` as a [`Q`], reduced (one GCD).
pub fn relaxed_to_q(x: Relaxed) -> Q {
    to_q(&x.canonicalize())
}

/// Exact rationals that compare by cross-multiplication and reduce only when converted back:
/// for exact work of bounded depth on big numbers, where a GCD after every operation (as
/// [`RBig`] takes) is most of the cost.
impl Field for Relaxed {
    const NAME: &'static str = "Q (dashu, unreduced)";
    const EXACT: bool = true;

    fn from_rational(q: &Q) -> Self {
        to_relaxed(q)
    }

    fn sign(&self) -> Option<Ordering> {
        Some(order_of(num_traits::Zero::is_zero(self), self.sign()))
    }

    /// Correctly rounded, as [`Q`]'s.
    fn nearest_f64(&self) -> f64 {
        relaxed_to_q(self.clone()).nearest_f64()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Zero;
    use proptest::prelude::*;

    fn rational() -> impl Strategy<Value = Q> {
        (
            proptest::collection::vec(any::<u32>(), 1..40),
            proptest::collection::vec(any::<u32>(), 1..40),
            any::<bool>(),
        )
            .prop_filter_map("nonzero denominator", |(n, d, negative)| {
                let n = BigInt::from_biguint(
                    if negative { Sign::Minus } else { Sign::Plus },
                    BigUint::new(n),
                );
                let d = BigInt::from(BigUint::new(d));
                (!d.is_zero()).then(|| Q::new(n, d))
            })
    }

    proptest! {
        /// Every operation over RBig gives Q's answer, in Q's representation.
        #[test]
        fn rbig_agrees_with_q(a in rational(), b in rational()) {
            let (x, y) = (to_rbig(&a), to_rbig(&b));
            prop_assert_eq!(to_q(&x), a.clone());
            prop_assert_eq!(to_q(&(x.clone() + &y)), &a + &b);
            prop_assert_eq!(to_q(&(x.clone() - &y)), &a - &b);
            prop_assert_eq!(to_q(&(x.clone() * &y)), &a * &b);
            if !b.is_zero() {
                prop_assert_eq!(to_q(&(x.clone() / &y)), &a / &b);
            }
            prop_assert_eq!(Field::sign(&x), Field::sign(&a));
            prop_assert_eq!(x.partial_cmp(&y), a.partial_cmp(&b));
            prop_assert_eq!(x.nearest_f64().to_bits(), a.nearest_f64().to_bits());
        }

        /// ... and over Relaxed, reduced at the end.
        #[test]
        fn relaxed_agrees_with_q(a in rational(), b in rational()) {
            let (x, y) = (to_relaxed(&a), to_relaxed(&b));
            prop_assert_eq!(relaxed_to_q(x.clone()), a.clone());
            prop_assert_eq!(relaxed_to_q(x.clone() + &y), &a + &b);
            prop_assert_eq!(relaxed_to_q(x.clone() - &y), &a - &b);
            prop_assert_eq!(relaxed_to_q(x.clone() * &y), &a * &b);
            if !b.is_zero() {
                prop_assert_eq!(relaxed_to_q(x.clone() / &y), &a / &b);
            }
            prop_assert_eq!(Field::sign(&x), Field::sign(&a));
            prop_assert_eq!(x.partial_cmp(&y), a.partial_cmp(&b));
            prop_assert_eq!(x == y, a == b);
            prop_assert_eq!(x.nearest_f64().to_bits(), a.nearest_f64().to_bits());
        }
    }
}
