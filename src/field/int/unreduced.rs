//! Fractions of fixed-width integers that are never reduced ([`Unreduced`], on `i128` or the
//! 512-bit `Wide`): a [`Field`] for the exact work of a batch row whose numbers are short (an
//! engine's 17-digit decimals, a scene's small fractions), where reducing after every
//! operation (a GCD each) cost far more than the arithmetic.
//!
//! Values are compared by cross-multiplication, so every decision (`==`, `<`, the sign) is
//! exact, the same as over [`Q`]. A sum over denominators of which one divides the other (the
//! powers of ten of decimals) takes the larger one, not their product. The width is checked,
//! not assumed: an operation whose result would leave it flags the computation, and
//! [`within`] then answers `None`, so the caller redoes the work in a wider integer or over
//! unbounded rationals. A flagged value is garbage, never a panic.

use super::wide::{Limbs, Wide};
use super::{FixedInt, Int, U256};
use crate::field::{Field, Q};
use num_traits::{One, Zero};
use std::cell::Cell;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

thread_local! {
    /// Set by an operation that left the width, since the last [`within`] began.
    static OVERFLOWED: Cell<bool> = const { Cell::new(false) };
}

/// Runs `work` (exact work over [`Unreduced`]) and returns its result, or `None` when a value left
/// its integers' width on the way (the result is then meaningless). Not reentrant: `work` must
/// not call `within` itself. Every [`Unreduced`] of the work must be made inside `work` (lifting a
/// value can overflow too, and the flag is cleared as `within` starts).
pub(crate) fn within<R>(work: impl FnOnce() -> R) -> Option<R> {
    OVERFLOWED.with(|flag| flag.set(false));
    let result = work();
    (!OVERFLOWED.with(|flag| flag.replace(false))).then_some(result)
}

/// A checked result, or 1 with the overflow flagged (1 keeps every denominator nonzero).
fn checked<T: UnreducedInt>(x: Option<T>) -> T {
    x.unwrap_or_else(|| {
        OVERFLOWED.with(|flag| flag.set(true));
        T::small(1)
    })
}

/// What a [`Unreduced`] needs of its integers beyond [`Int`].
pub(crate) trait UnreducedInt: Int + Copy + fmt::Debug {
    /// The sign.
    fn sign(&self) -> Ordering;
    /// The order of the values.
    fn order(&self, o: &Self) -> Ordering;
    /// `-self`, if it fits.
    fn negated(&self) -> Option<Self>;
    /// `self / d` when `d > 0` divides `self` exactly (and it is cheap to tell), else `None`.
    fn exact_quotient(&self, d: &Self) -> Option<Self>;
}

impl UnreducedInt for i128 {
    fn sign(&self) -> Ordering {
        self.cmp(&0)
    }
    fn order(&self, o: &Self) -> Ordering {
        self.cmp(o)
    }
    fn negated(&self) -> Option<Self> {
        self.checked_neg()
    }
    fn exact_quotient(&self, d: &Self) -> Option<Self> {
        // A magnitude below d's is a multiple only when zero: no division, which is a call
        // of its own on 128 bits (half of the sums of two denominators end here).
        if self.unsigned_abs() < d.unsigned_abs() {
            return (*self == 0).then_some(0);
        }
        // One division, checked by a product, where `%` then `/` were two.
        let quotient = self / d;
        (quotient * d == *self).then_some(quotient)
    }
}

impl<const N: usize> UnreducedInt for Limbs<N> {
    fn sign(&self) -> Ordering {
        Limbs::sign(self)
    }
    fn order(&self, o: &Self) -> Ordering {
        self.cmp_signed(o)
    }
    fn negated(&self) -> Option<Self> {
        Some(Limbs::negated(self))
    }
    fn exact_quotient(&self, _: &Self) -> Option<Self> {
        None
    }
}

/// `n/d` with `d > 0`, never reduced. See the module documentation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Unreduced<T = Wide> {
    n: T,
    d: T,
}

impl<T: UnreducedInt> Unreduced<T> {
    /// `n/d` as it stands, not reduced; `d` must be positive.
    pub(crate) fn of_parts(n: T, d: T) -> Unreduced<T> {
        debug_assert_eq!(d.sign(), Ordering::Greater, "a positive denominator");
        Unreduced { n, d }
    }

    /// The value reduced, as a [`Q`] (one GCD, on machine words up to 256 bits).
    pub(crate) fn to_q(self) -> Q {
        T::ratio(self.n, self.d)
    }

    fn new_checked(n: Option<T>, d: T) -> Unreduced<T> {
        Unreduced { n: checked(n), d }
    }

    /// `self * o` on both sides: `(self.n o.d) cmp (o.n self.d)`.
    fn cross(&self, o: &Unreduced<T>) -> Ordering {
        if self.d == o.d {
            return self.n.order(&o.n);
        }
        let left = checked(self.n.mul(&o.d));
        let right = checked(o.n.mul(&self.d));
        left.order(&right)
    }

    fn sum(&self, o: &Unreduced<T>) -> Unreduced<T> {
        // A zero term (a body at rest, a point without spin) adds nothing: no products.
        if o.n.sign() == Ordering::Equal {
            return *self;
        }
        if self.n.sign() == Ordering::Equal {
            return *o;
        }
        let (n, d) = if self.d == o.d {
            (self.n.add(&o.n), self.d)
        } else if let Some(k) = o.d.exact_quotient(&self.d) {
            (checked(self.n.mul(&k)).add(&o.n), o.d)
        } else if let Some(k) = self.d.exact_quotient(&o.d) {
            (checked(o.n.mul(&k)).add(&self.n), self.d)
        } else {
            let n = checked(self.n.mul(&o.d)).add(&checked(o.n.mul(&self.d)));
            (n, checked(self.d.mul(&o.d)))
        };
        Unreduced::new_checked(n, d)
    }

    fn product(&self, o: &Unreduced<T>) -> Unreduced<T> {
        if self.n.sign() == Ordering::Equal || o.n.sign() == Ordering::Equal {
            return Unreduced::zero();
        }
        Unreduced {
            n: checked(self.n.mul(&o.n)),
            d: checked(self.d.mul(&o.d)),
        }
    }

    fn quotient(&self, o: &Unreduced<T>) -> Unreduced<T> {
        let (n, d) = match o.n.sign() {
            // Division by zero: flagged, like an overflow (the caller falls back).
            Ordering::Equal => return Unreduced::new_checked(None, T::small(1)),
            _ if self.n.sign() == Ordering::Equal => return Unreduced::zero(),
            Ordering::Less => (checked(self.n.negated()), checked(o.n.negated())),
            Ordering::Greater => (self.n, o.n),
        };
        Unreduced {
            n: checked(n.mul(&o.d)),
            d: checked(self.d.mul(&d)),
        }
    }
}

impl<T: FixedInt> Unreduced<T> {
    /// The value reduced on words ([`reduced_words`](super::reduced_words)).
    pub(crate) fn reduced_words(self) -> Option<(bool, U256, U256)> {
        super::reduced_words(&self.n, &self.d)
    }
}

impl<T: UnreducedInt> PartialEq for Unreduced<T> {
    fn eq(&self, o: &Unreduced<T>) -> bool {
        self.cross(o) == Ordering::Equal
    }
}

impl<T: UnreducedInt> PartialOrd for Unreduced<T> {
    fn partial_cmp(&self, o: &Unreduced<T>) -> Option<Ordering> {
        Some(self.cross(o))
    }
}

impl<T: UnreducedInt> fmt::Display for Unreduced<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.to_q())
    }
}

/// `impl $trait<Unreduced>` and `impl $trait<&Unreduced>` for `Unreduced` by the method `$by`.
macro_rules! operator {
    ($trait:ident, $method:ident, $by:ident) => {
        impl<T: UnreducedInt> $trait<Unreduced<T>> for Unreduced<T> {
            type Output = Unreduced<T>;
            fn $method(self, o: Unreduced<T>) -> Unreduced<T> {
                self.$by(&o)
            }
        }
        impl<'a, T: UnreducedInt> $trait<&'a Unreduced<T>> for Unreduced<T> {
            type Output = Unreduced<T>;
            fn $method(self, o: &'a Unreduced<T>) -> Unreduced<T> {
                self.$by(o)
            }
        }
    };
}

operator!(Add, add, sum);
operator!(Mul, mul, product);
operator!(Div, div, quotient);

impl<T: UnreducedInt> Neg for Unreduced<T> {
    type Output = Unreduced<T>;
    fn neg(self) -> Unreduced<T> {
        Unreduced::new_checked(self.n.negated(), self.d)
    }
}

impl<T: UnreducedInt> Sub<Unreduced<T>> for Unreduced<T> {
    type Output = Unreduced<T>;
    fn sub(self, o: Unreduced<T>) -> Unreduced<T> {
        self.sum(&-o)
    }
}

impl<'a, T: UnreducedInt> Sub<&'a Unreduced<T>> for Unreduced<T> {
    type Output = Unreduced<T>;
    fn sub(self, o: &'a Unreduced<T>) -> Unreduced<T> {
        self.sum(&-*o)
    }
}

impl<T: UnreducedInt> Zero for Unreduced<T> {
    fn zero() -> Unreduced<T> {
        Unreduced {
            n: T::small(0),
            d: T::small(1),
        }
    }
    fn is_zero(&self) -> bool {
        self.n.sign() == Ordering::Equal
    }
}

impl<T: UnreducedInt> One for Unreduced<T> {
    fn one() -> Unreduced<T> {
        Unreduced {
            n: T::small(1),
            d: T::small(1),
        }
    }
}

impl<T: UnreducedInt> Field for Unreduced<T> {
    const NAME: &'static str = "Q (unreduced, fixed width)";
    const EXACT: bool = true;

    fn from_rational(q: &Q) -> Unreduced<T> {
        Unreduced {
            n: checked(T::lift(q.numer())),
            d: checked(T::lift(q.denom())),
        }
    }

    fn sign(&self) -> Option<Ordering> {
        Some(self.n.sign())
    }

    fn nearest_f64(&self) -> f64 {
        self.to_q().nearest_f64()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::int::I256;
    use crate::field::{laws, q};

    #[test]
    fn unreduced_fractions_are_a_field() {
        let rationals = [
            q(0, 1),
            q(1, 1),
            q(-1, 1),
            q(1, 3),
            q(-6, 4),
            q(7, 5),
            q(3, 10),
        ];
        let words: Vec<Unreduced<i128>> = rationals.iter().map(Unreduced::from_rational).collect();
        assert!(within(|| laws::check_field(&words, |a, b| a == b)).is_some());
        let wide: Vec<Unreduced<Wide>> = rationals.iter().map(Unreduced::from_rational).collect();
        assert!(within(|| laws::check_field(&wide, |a, b| a == b)).is_some());
    }

    /// A 128-bit quotient is taken only when exact: zero, a multiple, not a smaller
    /// magnitude or a near multiple, whatever the signs.
    #[test]
    fn exact_quotients_of_128_bits() {
        let cases = [
            (0i128, 7i128, Some(0i128)),
            (21, 7, Some(3)),
            (-21, 7, Some(-3)),
            (7, 7, Some(1)),
            (6, 7, None),
            (-6, 7, None),
            (22, 7, None),
            (i128::MAX, 1, Some(i128::MAX)),
            (i128::MIN, 2, Some(i128::MIN / 2)),
        ];
        for (x, d, want) in cases {
            assert_eq!(x.exact_quotient(&d), want, "{x} / {d}");
        }
    }

    /// The same fraction reduced on words: its sign (a zero is not negative), numerator and
    /// denominator, in each width.
    #[test]
    fn fractions_reduce_on_words() {
        let (n, d) = (
            Unreduced::<i128>::from_rational(&q(-6, 4)),
            U256 { hi: 0, lo: 2 },
        );
        assert_eq!(n.reduced_words(), Some((true, U256 { hi: 0, lo: 3 }, d)));
        let zero = within(|| {
            Unreduced::<Wide>::from_rational(&q(-1, 3)) + Unreduced::from_rational(&q(1, 3))
        });
        assert_eq!(
            zero.unwrap().reduced_words(),
            Some((false, U256::ZERO, U256::ONE))
        );
        let unreduced = within(|| {
            Unreduced::<I256>::from_rational(&q(5, 6)) * Unreduced::from_rational(&q(6, 10))
        });
        assert_eq!(
            unreduced.unwrap().reduced_words(),
            Some((false, U256::ONE, d))
        );
    }

    #[test]
    fn values_compare_and_reduce_as_rationals() {
        let got = within(|| {
            let x =
                Unreduced::<i128>::from_rational(&q(2, 6)) + Unreduced::from_rational(&q(-1, 4));
            (x.to_q(), x > Unreduced::zero(), x.sign())
        });
        assert_eq!(got, Some((q(1, 12), true, Some(Ordering::Greater))));
    }

    #[test]
    fn leaving_the_width_is_reported_not_wrapped() {
        let big =
            Unreduced::<Wide>::from_rational(&Q::from_integer(num_bigint::BigInt::from(1) << 300));
        assert!(within(|| big * big).is_none());
        let word = Unreduced::<i128>::from_rational(&Q::from_integer(num_bigint::BigInt::from(
            1u128 << 70,
        )));
        assert!(within(|| word * word).is_none());
        // A decimal's power of ten takes the larger denominator: 1/100 + 1/1000 = 11/1000.
        let (a, b) = (
            Unreduced::<i128>::from_rational(&q(1, 100)),
            Unreduced::from_rational(&q(1, 1000)),
        );
        assert_eq!(
            within(|| {
                let s = a + b;
                (s.n, s.d)
            }),
            Some((11, 1000))
        );
        assert!(within(|| big / Unreduced::zero()).is_none());
        // The flag is cleared for the next computation.
        assert_eq!(within(|| (big / big).to_q()), Some(q(1, 1)));
    }
}
