//! Word-sized and wide integers: exact integer arithmetic that avoids num-bigint's heap digits
//! (and its quadratic binary GCD) wherever the numbers fit.
//!
//! - `words`: binary GCDs on `u64` and `u128`, and a 256-bit unsigned integer (`U256`) that
//!   reduces, compares and prints fractions of up to 256-bit parts on machine words;
//! - `quotient`: small quotients of 256-bit integers and the nearest f64 to a fraction of them;
//! - `wide`: checked signed integers of 512 bits (`Wide`), 1024 (`Wider`) and 2560 (`Widest`);
//! - `signed`: a checked 256-bit signed integer (`I256`);
//! - `frac`: unreduced fractions of `i128`, `I256` or `Wide`, a field whose overflow is
//!   reported (`Unreduced`);
//! - `ring`: fixed-width integers that wrap (`Ring<N>`), for values proven in range in advance;
//! - `dashu`: dashu's `IBig` as the unbounded width (the default);
//! - `malachite` (cargo feature `malachite`): malachite's `Integer` instead;
//! - the `Int` kit: the checked operations of the fraction-free route
//!   ([`crate::solve::fast::fraction_free`]), written once for `i128`, `Wide` and big integers;
//! - [`reduce`] and `write_ratio`: a fraction reduced, or written, on machine words when it fits.

use crate::field::Q;
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};
pub(crate) use ring::Ring;
pub(crate) use signed::I256;
pub(crate) use unreduced::{Unreduced, UnreducedInt, within};
pub(crate) use wide::{Wide, Wider, Widest};
pub(crate) use words::{POWERS_OF_TEN, U256, gcd, gcd_u64, powers};

/// The [`Int`] operations of an integer type that never overflows (every result `Some`),
/// written once for dashu's `IBig` and, with the feature, malachite's `Integer` (defined before
/// the modules, which see it by textual scope).
macro_rules! unbounded_arithmetic {
    () => {
        fn add(&self, o: &Self) -> Option<Self> {
            Some(self + o)
        }
        fn sub(&self, o: &Self) -> Option<Self> {
            Some(self - o)
        }
        fn mul(&self, o: &Self) -> Option<Self> {
            Some(self * o)
        }
        fn squares_balance(lhs: [(&Self, &Self); 3], (c, x): (&Self, &Self)) -> Option<bool> {
            let sum: Self = lhs.iter().map(|(c, x)| *c * &(*x * *x)).sum();
            Some(sum == c * &(x * x))
        }
    };
}

#[cfg(not(feature = "malachite"))]
mod dashu;
#[cfg(feature = "malachite")]
mod malachite;
mod quotient;
mod ring;
mod signed;
mod unreduced;
mod wide;
mod words;

/// The big-integer type of the fraction-free fallback: dashu's `IBig` by default (Karatsuba
/// and Toom multiplication, Lehmer GCD), malachite's `Integer` with the feature `malachite`
/// (subquadratic GCD too). Results are returned as [`Q`] either way, identical.
#[cfg(not(feature = "malachite"))]
pub(crate) type Big = dashu_int::IBig;
/// The big-integer type of the fraction-free fallback: malachite's `Integer` (feature
/// `malachite`; subquadratic GCD and multiplication) instead of num-bigint's [`BigInt`].
/// Results are returned as [`Q`] either way, identical.
#[cfg(feature = "malachite")]
pub(crate) type Big = malachite_nz::integer::Integer;

/// The decimal digits of `q`'s numerator and denominator together, to within one each (from
/// their bit lengths): the size measure of the limits that bound exact work by the size of the
/// numbers (figures, T6).
///
/// # Examples
/// ```
/// use rodimpact::field::{int::decimal_digits, q};
/// assert_eq!(decimal_digits(&q(1, 1)), 2);
/// assert_eq!(decimal_digits(&rodimpact::number::parse("1e-300").unwrap()), 302);
/// ```
pub fn decimal_digits(q: &Q) -> u64 {
    let digits = |bits: u64| bits * 30_103 / 100_000 + 1;
    digits(q.numer().bits()) + digits(q.denom().bits())
}

/// `n/d` reduced to lowest terms with a positive denominator: the same value and
/// representation as `Q::new(n, d)`, but a GCD of numbers up to 256 bits runs on two machine
/// words instead of num-bigint's heap digits.
///
/// # Panics
/// If `d` is zero (as `Q::new`).
///
/// # Examples
/// ```
/// use rodimpact::field::int::reduce;
/// use rodimpact::field::Q;
/// let (n, d) = (num_bigint::BigInt::from(-84), num_bigint::BigInt::from(-36));
/// assert_eq!(reduce(n.clone(), d.clone()), Q::new(n.clone(), d));
/// assert_eq!(reduce(n, 1.into()).to_string(), "-84");
/// ```
pub fn reduce(n: BigInt, d: BigInt) -> Q {
    assert!(!d.is_zero(), "denominator == 0");
    if d.is_negative() {
        word_ratio(-n, -d)
    } else {
        word_ratio(n, d)
    }
}

/// `n/d` reduced, `d > 0`: up to 256 bits the GCD runs on two machine words, far faster than
/// num-bigint's binary GCD on heap digits; beyond, `Q::new` reduces.
fn word_ratio(n: BigInt, d: BigInt) -> Q {
    match (U256::from_big(n.magnitude()), U256::from_big(d.magnitude())) {
        (Some(a), Some(b)) => U256::ratio(n.is_negative(), a, b),
        _ => Q::new(n, d),
    }
}

/// Writes `q` as `n` or `n/d` when both fit 256 bits (else `None`, nothing written).
pub(crate) fn write_ratio(out: &mut String, q: &Q) -> Option<()> {
    let (negative, n, d) = U256::parts_of(q)?;
    write_parts(out, negative, n, d);
    Some(())
}

/// Writes `-n/d` (when `negative`) or `n/d`, reduced, as [`Q`]'s `Display` writes it: `n`
/// alone when `d` is 1.
pub(crate) fn write_parts(out: &mut String, negative: bool, n: U256, d: U256) {
    if negative {
        out.push('-');
    }
    n.write_decimal(out);
    if d != U256::ONE {
        out.push('/');
        d.write_decimal(out);
    }
}

/// The integer operations of the fraction-free route, written once for every width;
/// `None` means "does not fit" (the caller retries in the next width).
pub(crate) trait Int: Sized + Clone + PartialEq {
    /// `x` in this width.
    fn lift(x: &BigInt) -> Option<Self>;
    /// A small constant.
    fn small(x: u8) -> Self;
    /// `self + o`.
    fn add(&self, o: &Self) -> Option<Self>;
    /// `self - o`.
    fn sub(&self, o: &Self) -> Option<Self>;
    /// `self * o`.
    fn mul(&self, o: &Self) -> Option<Self>;
    /// Decides `sum c_i x_i^2 == c x^2` for non-negative weights.
    fn squares_balance(lhs: [(&Self, &Self); 3], rhs: (&Self, &Self)) -> Option<bool>;
    /// `n/d` reduced, `d > 0`.
    fn ratio(n: Self, d: Self) -> Q;
}

impl Int for i128 {
    fn lift(x: &BigInt) -> Option<Self> {
        x.to_i128()
    }
    fn small(x: u8) -> Self {
        x.into()
    }
    fn add(&self, o: &Self) -> Option<Self> {
        self.checked_add(*o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        self.checked_sub(*o)
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        self.checked_mul(*o)
    }
    fn squares_balance(lhs: [(&Self, &Self); 3], (c, x): (&Self, &Self)) -> Option<bool> {
        let term = |c: &i128, x: &i128| {
            let c = u128::try_from(*c).ok()?;
            U256::square(x.unsigned_abs()).checked_mul(c)
        };
        let mut sum = U256::ZERO;
        for (c, x) in lhs {
            sum = sum.checked_add(term(c, x)?)?;
        }
        Some(sum == term(c, x)?)
    }
    fn ratio(n: Self, d: Self) -> Q {
        let g = gcd(n.unsigned_abs(), d.unsigned_abs());
        // g divides both, and g >= 1 because d > 0; n/g and d/g stay in range.
        let g = g as i128;
        Q::new_raw(BigInt::from(n / g), BigInt::from(d / g))
    }
}

/// The fixed widths a batch row's word route computes in (`i128`, `I256`, `Wide`): numbers
/// enter from machine words and leave as 256-bit magnitudes, with no big integer between.
pub(crate) trait FixedInt: UnreducedInt {
    /// The magnitudes held: below `2^BITS`.
    const BITS: u32;
    /// `-x` (when `negative`) or `x`, if it fits.
    fn of_words(negative: bool, x: U256) -> Option<Self>;
    /// Sign and magnitude, if the magnitude fits 256 bits.
    fn to_words(&self) -> Option<(bool, U256)>;
    /// The value as a big integer (for what leaves the words).
    fn to_big(&self) -> BigInt;
}

impl FixedInt for i128 {
    const BITS: u32 = 127;
    fn of_words(negative: bool, x: U256) -> Option<Self> {
        let magnitude = i128::try_from(x.lo).ok().filter(|_| x.hi == 0)?;
        Some(if negative { -magnitude } else { magnitude })
    }
    fn to_words(&self) -> Option<(bool, U256)> {
        Some((
            *self < 0,
            U256 {
                hi: 0,
                lo: self.unsigned_abs(),
            },
        ))
    }
    fn to_big(&self) -> BigInt {
        BigInt::from(*self)
    }
}

/// `n/d` (`d > 0`) reduced on words (one binary GCD, no big integer): its sign (a zero is
/// not negative), numerator and denominator; `None` when a part passes 256 bits.
pub(crate) fn reduced_words<T: FixedInt>(n: &T, d: &T) -> Option<(bool, U256, U256)> {
    let ((negative, n), (_, d)) = (n.to_words()?, d.to_words()?);
    let (n, d) = U256::reduced(n, d);
    Some((negative && n != U256::ZERO, n, d))
}

/// Numerator and denominator of a rational, lifted into `T`.
pub(crate) fn split<T: Int>(x: &Q) -> Option<(T, T)> {
    Some((T::lift(x.numer())?, T::lift(x.denom())?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn energy_balance_is_decided_alike_in_the_fixed_and_the_unbounded_width() {
        // 2*3^2 + 1*4^2 + 0*7^2 = 34 = 34*1^2; off by one it is not.
        for (c, want) in [(34i128, true), (35, false)] {
            let (two, three, one, four, zero, seven) = (2i128, 3, 1, 4, 0, 7);
            let fixed =
                i128::squares_balance([(&two, &three), (&one, &four), (&zero, &seven)], (&c, &one));
            let big = |x: i128| Big::lift(&BigInt::from(x)).unwrap();
            let (b2, b3, b1, b4, b0, b7, bc) =
                (big(2), big(3), big(1), big(4), big(0), big(7), big(c));
            let wide = Big::squares_balance([(&b2, &b3), (&b1, &b4), (&b0, &b7)], (&bc, &b1));
            assert_eq!((fixed, wide), (Some(want), Some(want)));
        }
        let max = i128::MAX;
        assert_eq!(
            i128::squares_balance([(&max, &max), (&0, &0), (&0, &0)], (&1, &1)),
            None
        );
    }
}
