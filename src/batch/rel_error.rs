//! A claim's relative error |claim - value| / |value|, exact and kept as its row computed it:
//! a fraction of machine words (the word, f64 and engine rows) or a rational (the general row),
//! never reduced until somebody asks for the value. A row needs only its nearest f64 (for the
//! f64 tolerance and the summary) and its three-digit text, both of which the words give
//! directly. Building a big rational per claim, then taking it back to words for its text and
//! its nearest f64 twice, was about 4,000 of the 25,000 instructions of an f64 row with three
//! claims.

use crate::field::decimal::{decimal, push_decimal_words};
use crate::field::int::{FixedInt, Int, U256, Wide};
use crate::field::{Field, Q};
use num_traits::Zero;
use std::cmp::Ordering;

/// An exact, nonnegative relative error.
#[derive(Debug, Clone)]
pub(crate) enum RelError {
    /// `n/d` on machine words, `d > 0`, not necessarily reduced.
    Words(U256, U256),
    /// A rational, not necessarily reduced.
    Rational(Q),
}

impl RelError {
    /// Zero: the claim is the value.
    pub(crate) const ZERO: RelError = RelError::Words(U256::ZERO, U256::ONE);

    /// Whether the claim is the value.
    pub(crate) fn is_zero(&self) -> bool {
        match self {
            RelError::Words(n, _) => *n == U256::ZERO,
            RelError::Rational(q) => q.is_zero(),
        }
    }

    /// The value in lowest terms.
    pub(crate) fn value(&self) -> Q {
        match self {
            RelError::Words(n, d) => U256::ratio(false, *n, *d),
            RelError::Rational(q) => Q::new(q.numer().clone(), q.denom().clone()),
        }
    }

    /// The value as a [`Q`] as it stands (not reduced): for comparisons, which [`Q`] makes by
    /// value.
    pub(crate) fn unreduced(&self) -> Q {
        match self {
            RelError::Words(n, d) => U256::unreduced(*n, *d),
            RelError::Rational(q) => q.clone(),
        }
    }

    /// The nearest f64, correctly rounded.
    pub(crate) fn nearest_f64(&self) -> f64 {
        match self {
            RelError::Words(n, _) if *n == U256::ZERO => 0.0,
            RelError::Words(n, d) => {
                U256::nearest_f64(*n, *d).unwrap_or_else(|| self.unreduced().nearest_f64())
            }
            RelError::Rational(q) => q.nearest_f64(),
        }
    }

    /// Appends three significant digits, as [`decimal`] prints the value (`0.0167`,
    /// `5.39e-17`, `0`); `near` must be its nearest f64 (correctly rounded), which decides
    /// most digits without the words.
    pub(crate) fn push_text(&self, out: &mut String, near: f64) {
        match self {
            RelError::Words(n, d) => push_decimal_words(out, false, *n, *d, 3, Some(near)),
            RelError::Rational(q) => out.push_str(&decimal(q, 3)),
        }
    }

    /// The order of the error and a nonnegative rational, by value (a zero error without big
    /// integers: an exact batch compares its zeros row after row). By cross-multiplication:
    /// num-rational's order walks a continued fraction, one big division a step, which cost
    /// 50,000 instructions a comparison on an engine's 400-bit errors.
    pub(crate) fn cmp_value(&self, other: &Q) -> Ordering {
        if self.is_zero() {
            return other.sign().map_or(Ordering::Equal, Ordering::reverse);
        }
        let mine = self.unreduced();
        if mine.denom() == other.denom() {
            return mine.numer().cmp(other.numer());
        }
        (mine.numer() * other.denom()).cmp(&(other.numer() * mine.denom()))
    }
}

impl RelError {
    /// The order of two errors by value: on words when both are (the same fraction, which a
    /// run of one scene's rows often repeats, without a product; else by cross-multiplication
    /// in 512 bits), by [`RelError::cmp_value`] otherwise. The summary's ties took 480
    /// instructions of an engine's row through big integers.
    pub(crate) fn cmp_error(&self, other: &RelError) -> Ordering {
        if let (RelError::Words(a, b), RelError::Words(c, d)) = (self, other) {
            if (a, b) == (c, d) {
                return Ordering::Equal;
            }
            let wide = |x: &U256| Wide::of_words(false, *x);
            let product = |x: &U256, y: &U256| wide(x)?.mul(&wide(y)?);
            if let (Some(left), Some(right)) = (product(a, d), product(c, b)) {
                return left.cmp_signed(&right);
            }
        }
        self.cmp_value(&other.unreduced())
    }
}

/// Equal when the values are, however each is held.
impl PartialEq for RelError {
    fn eq(&self, other: &RelError) -> bool {
        self.unreduced() == other.unreduced()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use num_bigint::BigInt;

    #[test]
    fn words_and_rationals_of_one_value_agree_on_everything() {
        let words = RelError::Words(U256 { hi: 0, lo: 10 }, U256 { hi: 0, lo: 600 });
        let rational = RelError::Rational(Q::new_raw(10.into(), 600.into()));
        for e in [&words, &rational] {
            assert_eq!(e.value(), q(1, 60));
            assert_eq!(e.value().denom().to_string(), "60");
            assert_eq!(e.nearest_f64(), 1.0 / 60.0);
            let text = |near| {
                let mut out = String::from("x");
                e.push_text(&mut out, near);
                out
            };
            assert_eq!(text(1.0 / 60.0), "x0.0167");
            assert!(!e.is_zero());
            assert_eq!(e.cmp_value(&q(1, 61)), Ordering::Greater);
        }
        assert_eq!(words, rational);
        assert!(RelError::ZERO.is_zero());
        // Unreduced 400-bit errors (an engine's claim of 1e-100 against 3e-100), ordered by
        // value against a reduced one.
        let tens = crate::field::decimal::ten_to(120);
        let big = RelError::Rational(Q::new_raw(BigInt::from(2) * &tens, BigInt::from(3) * &tens));
        assert_eq!(big.cmp_value(&q(2, 3)), Ordering::Equal);
        assert_eq!(big.cmp_value(&q(667, 1000)), Ordering::Less);
        assert_eq!(big.cmp_value(&q(666, 1000)), Ordering::Greater);
        let mut zero = String::new();
        RelError::ZERO.push_text(&mut zero, 0.0);
        assert_eq!(zero, "0");
        assert_eq!(RelError::ZERO.nearest_f64(), 0.0);
        assert_ne!(RelError::ZERO, words);
        assert_eq!(RelError::ZERO.cmp_value(&q(0, 1)), Ordering::Equal);
        assert_eq!(RelError::ZERO.cmp_value(&q(1, 9)), Ordering::Less);
        assert_eq!(words.cmp_value(&q(1, 60)), Ordering::Equal);
    }

    /// Two errors ordered by value however each is held: the same words, equal fractions in
    /// other terms, 256-bit parts whose products pass 256 bits, a rational beside words.
    #[test]
    fn errors_are_ordered_by_value() {
        let w = |n: u128, d: u128| RelError::Words(U256 { hi: 0, lo: n }, U256 { hi: 0, lo: d });
        let r = |n: i64, d: i64| RelError::Rational(Q::new_raw(n.into(), d.into()));
        assert_eq!(w(1, 60).cmp_error(&w(1, 60)), Ordering::Equal);
        assert_eq!(w(1, 60).cmp_error(&w(10, 600)), Ordering::Equal);
        assert_eq!(w(1, 60).cmp_error(&w(1, 61)), Ordering::Greater);
        assert_eq!(w(1, 61).cmp_error(&w(1, 60)), Ordering::Less);
        assert_eq!(RelError::ZERO.cmp_error(&w(0, 7)), Ordering::Equal);
        assert_eq!(RelError::ZERO.cmp_error(&w(1, 7)), Ordering::Less);
        // (2^255 + 1) / (2^255) against (2^255) / (2^255 - 1): the second is larger.
        let top = U256 {
            hi: 1 << 127,
            lo: 0,
        };
        let big = |n: U256, d: U256| RelError::Words(n, d);
        let one = U256::ONE;
        let above = big(
            U256 {
                hi: 1 << 127,
                lo: 1,
            },
            top,
        );
        let further = big(top, top.minus(one));
        assert_eq!(above.cmp_error(&further), Ordering::Less);
        assert_eq!(further.cmp_error(&above), Ordering::Greater);
        assert_eq!(w(2, 3).cmp_error(&r(4, 6)), Ordering::Equal);
        assert_eq!(r(4, 6).cmp_error(&w(1, 2)), Ordering::Greater);
        assert_eq!(r(1, 3).cmp_error(&r(1, 2)), Ordering::Less);
    }
}
