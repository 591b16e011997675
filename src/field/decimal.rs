//! Printing exact numbers, and rounding them: the one rounding module.
//!
//! Printing is exact where possible (num-rational's `p/q`, [`write_exact`] on machine words,
//! [`surd`] for square roots) and otherwise correctly rounded: [`decimal`] and [`Decimal`] round
//! half to even to a number of significant digits, [`decimal_rounded`] in any [`Rounding`]
//! direction, [`sqrt_bounds`] encloses a square root between decimal rationals, and
//! [`decimal_sqrt`] rounds a square root correctly. [`round_at`] rounds an exact value to a
//! decimal place (the textbook's significant figures), [`magnitude`] is `floor(log10 |x|)`.
//! All of it is exact integer arithmetic, except that a value's nearest f64, where a caller
//! has it, may decide digits whose rounding its error bound makes certain; the decimal exponent
//! comes from bit lengths, so `1e-9000` costs about as much as `1`.

use super::int::{POWERS_OF_TEN, U256, write_ratio};
use super::{Q, TrySqrt};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

/// `10^k` as an integer.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::field::decimal::ten_to(3).to_string(), "1000");
/// ```
pub fn ten_to(k: u64) -> BigInt {
    num_traits::pow(BigInt::from(10u8), k as usize)
}

/// `10^k` exactly, for any integer `k`.
///
/// # Examples
/// ```
/// use rodimpact::field::decimal::pow10;
/// assert_eq!(pow10(-2).to_string(), "1/100");
/// assert_eq!(pow10(3).to_string(), "1000");
/// ```
pub fn pow10(k: i64) -> Q {
    let p = ten_to(k.unsigned_abs());
    if k >= 0 {
        Q::from_integer(p)
    } else {
        Q::new_raw(BigInt::one(), p)
    }
}

/// `floor(log10(n / d))` for positive `n`, `d`: an estimate from bit lengths, then exact
/// comparisons with powers of ten (at most a few).
fn floor_log10(n: &BigInt, d: &BigInt) -> i64 {
    let estimate = log10_estimate(n.bits(), d.bits());
    // Compare n/d with 10^e exactly.
    settle_log10(estimate, |e| {
        Some(if e >= 0 {
            n.cmp(&(d * ten_to(e.unsigned_abs())))
        } else {
            (n * ten_to(e.unsigned_abs())).cmp(d)
        })
    })
    .expect("big integers compare at every exponent")
}

/// An estimate of `floor(log10(n / d))` from the bit lengths of `n` and `d`, off by at most one.
fn log10_estimate(bits_n: u64, bits_d: u64) -> i64 {
    ((bits_n as f64 - bits_d as f64) * std::f64::consts::LOG10_2).floor() as i64
}

/// floor(log10 x) for a positive normal `x`, off by one at most: floor(e log10 2) for the
/// binary exponent e of `x` (in [2^e, 2^(e+1))), without a logarithm.
pub(crate) fn log10_of_float_estimate(x: f64) -> i64 {
    let binary = (x.to_bits() >> 52 & 0x7ff) as i64 - 1023;
    // 78913 / 2^18 is log10 2 to within 2^-23, exact in the floor for |e| < 1075.
    (binary * 78_913) >> 18
}

/// The exponent e with `10^e <= x < 10^(e+1)`, from a nearby estimate, where `compare(e)`
/// orders x against 10^e (`None`: it cannot tell, and neither can this).
fn settle_log10(mut e: i64, mut compare: impl FnMut(i64) -> Option<Ordering>) -> Option<i64> {
    loop {
        if compare(e)? == Ordering::Less {
            e -= 1;
        } else if compare(e + 1)? != Ordering::Less {
            e += 1;
        } else {
            return Some(e);
        }
    }
}

/// `floor(log10 |x|)`, the decimal exponent of `x`'s leading digit (0 for zero).
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::magnitude, q};
/// assert_eq!(magnitude(&q(1500, 1)), 3);
/// assert_eq!(magnitude(&q(-1, 20)), -2);
/// assert_eq!(magnitude(&q(1, 1)), 0);
/// ```
pub fn magnitude(x: &Q) -> i64 {
    if x.is_zero() {
        return 0;
    }
    floor_log10(&x.numer().abs(), x.denom())
}

/// Which way a value is rounded to the digits kept.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::{round_at, Rounding}, q};
/// let at = |rounding| round_at(&q(-5, 2), 0, rounding).to_string();
/// assert_eq!(at(Rounding::HalfEven), "-2");
/// assert_eq!(at(Rounding::HalfAwayFromZero), "-3");
/// assert_eq!(at(Rounding::HalfTowardZero), "-2");
/// assert_eq!(at(Rounding::Floor), "-3");
/// assert_eq!(at(Rounding::Ceiling), "-2");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rounding {
    /// To nearest, ties to even (correct rounding).
    HalfEven,
    /// To nearest, ties away from zero (the schoolbook rule).
    HalfAwayFromZero,
    /// To nearest, ties toward zero.
    HalfTowardZero,
    /// Toward minus infinity: the printed value is a lower bound.
    Floor,
    /// Toward plus infinity: the printed value is an upper bound.
    Ceiling,
}

/// `num / den` (both >= 0, `den > 0`), the magnitude of a value of sign `negative`, rounded to
/// an integer in the direction `rounding`; and whether that was exact (no remainder).
fn round_quotient(
    num: &BigInt,
    den: &BigInt,
    negative: bool,
    rounding: Rounding,
) -> (BigInt, bool) {
    let (quot, rem) = num.div_rem(den);
    if rem.is_zero() {
        return (quot, true);
    }
    let half = || (&rem * 2u8).cmp(den);
    let away = rounds_away(rounding, negative, quot.is_odd(), half);
    (if away { quot + 1u8 } else { quot }, false)
}

/// Whether a quotient that left a remainder rounds away from zero (up in magnitude), for a
/// value of sign `negative` whose truncated quotient is `odd`; `half` orders the remainder
/// against half the divisor.
fn rounds_away(rounding: Rounding, negative: bool, odd: bool, half: impl Fn() -> Ordering) -> bool {
    match rounding {
        Rounding::Floor => negative,
        Rounding::Ceiling => !negative,
        Rounding::HalfEven => match half() {
            Ordering::Equal => odd,
            other => other == Ordering::Greater,
        },
        Rounding::HalfAwayFromZero => half() != Ordering::Less,
        Rounding::HalfTowardZero => half() == Ordering::Greater,
    }
}

/// `x` rounded to a multiple of `10^place` in the direction `rounding`.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::{round_at, Rounding}, q};
/// assert_eq!(round_at(&q(9, 4), -1, Rounding::HalfAwayFromZero), q(23, 10));
/// assert_eq!(round_at(&q(9, 4), -1, Rounding::HalfTowardZero), q(22, 10));
/// assert_eq!(round_at(&q(-36, 19), -2, Rounding::HalfAwayFromZero), q(-189, 100));
/// ```
pub fn round_at(x: &Q, place: i64, rounding: Rounding) -> Q {
    let scale = ten_to(place.unsigned_abs());
    let n = x.numer().abs();
    let (num, den) = if place <= 0 {
        (n * &scale, x.denom().clone())
    } else {
        (n, x.denom() * &scale)
    };
    let (whole, _) = round_quotient(&num, &den, x.is_negative(), rounding);
    let whole = if x.is_negative() { -whole } else { whole };
    if place <= 0 {
        Q::new(whole, scale)
    } else {
        Q::from_integer(whole * scale)
    }
}

/// `value` correctly rounded (half to even) to `digits` significant digits.
///
/// Exactly `digits` significant digits are shown, trailing zeros included. With
/// `value = ±d.ddd × 10^E` after rounding, the notation is positional when
/// `-7 <= E < digits` and scientific (`1.23e5`, `-4.00e-300`) otherwise. Zero prints `"0"`.
/// `digits == 0` is treated as 1. Integer arithmetic only; the exponent is found from bit
/// lengths, so `1e-9000` is as fast as `1`.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::decimal, q};
/// assert_eq!(decimal(&q(-1, 5), 5), "-0.20000");
/// assert_eq!(decimal(&q(1, 8), 2), "0.12");
/// assert_eq!(decimal(&q(123456, 1), 3), "1.23e5");
/// assert_eq!(decimal(&q(1999, 200), 3), "10.0");
/// ```
pub fn decimal(value: &Q, digits: usize) -> String {
    decimal_rounded(value, digits, Rounding::HalfEven)
}

/// [`decimal`] of `n/d` (`d > 0`) given as big integers and not necessarily reduced: the same
/// text as the reduced [`Q`]'s, without its GCD (for numbers past the words, such as an
/// engine audit's energy change over a 1024-bit denominator).
pub(crate) fn decimal_unreduced(n: &BigInt, d: &BigInt, digits: usize) -> String {
    if n.is_zero() {
        return "0".to_string();
    }
    Significant::on_parts(
        n.is_negative(),
        n.abs(),
        d,
        digits.max(1),
        Rounding::HalfEven,
    )
    .text()
}

/// [`decimal`] of `-n/d` (when `negative`) or `n/d`, `d > 0`, given on machine words and not
/// necessarily reduced: the same text as the reduced [`Q`]'s, without its GCD, appended to
/// `out` (a batch row writes its cells into its line). `near`, the f64 nearest to `n/d` where
/// the caller has it, only saves work (see [`round_on_words`]).
pub(crate) fn push_decimal_words(
    out: &mut String,
    negative: bool,
    n: U256,
    d: U256,
    digits: usize,
    near: Option<f64>,
) {
    if n == U256::ZERO {
        out.push('0');
        return;
    }
    let digits = digits.max(1);
    match round_on_words(negative, n, d, digits, Rounding::HalfEven, near) {
        Some((m, exp, _)) => {
            write_significant(out, negative, itoa::Buffer::new().format(m), exp, digits)
        }
        None => out.push_str(&decimal(&U256::ratio(negative, n, d), digits)),
    }
}

/// [`decimal`], but a value that `digits` significant digits hold exactly is printed without
/// its trailing zeros: what a table shows beside an exact fraction (`1/25` is `0.04`, not
/// `0.0400000000000`; `1/3` keeps its digits).
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::decimal_short, q};
/// assert_eq!(decimal_short(&q(1, 25), 12), "0.04");
/// assert_eq!(decimal_short(&q(24, 625), 12), "0.0384");
/// assert_eq!(decimal_short(&q(6, 1), 12), "6");
/// assert_eq!(decimal_short(&q(1, 3), 12), "0.333333333333");
/// assert_eq!(decimal_short(&q(3, 20_000_000_000), 12), "1.5e-10");
/// ```
pub fn decimal_short(value: &Q, digits: usize) -> String {
    let rounded = Significant::of(value, digits, Rounding::HalfEven);
    let text = rounded.text();
    if !rounded.exact {
        return text;
    }
    let (mantissa, exponent) = match text.find('e') {
        Some(k) => text.split_at(k),
        None => (text.as_str(), ""),
    };
    let mantissa = if mantissa.contains('.') {
        mantissa.trim_end_matches('0').trim_end_matches('.')
    } else {
        mantissa
    };
    format!("{mantissa}{exponent}")
}

/// `value` rounded to `digits` significant digits in the given direction, printed as
/// [`decimal`] prints. `Floor` and `Ceiling` give printed bounds that enclose the exact value.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::{decimal_rounded, Rounding}, q};
/// assert_eq!(decimal_rounded(&q(2, 3), 3, Rounding::Floor), "0.666");
/// assert_eq!(decimal_rounded(&q(2, 3), 3, Rounding::Ceiling), "0.667");
/// assert_eq!(decimal_rounded(&q(-2, 3), 3, Rounding::Floor), "-0.667");
/// assert_eq!(decimal_rounded(&q(1, 2), 3, Rounding::Ceiling), "0.500");
/// ```
pub fn decimal_rounded(value: &Q, digits: usize, rounding: Rounding) -> String {
    Significant::of(value, digits, rounding).text()
}

/// A value rounded to a number of significant digits: `±m × 10^(exp - digits + 1)` with
/// `10^(digits-1) <= m < 10^digits` (or zero).
struct Significant {
    negative: bool,
    /// The decimal digits of m (`"0"` for zero).
    m: String,
    exp: i64,
    digits: usize,
    /// The rounding lost nothing: the printed text is the exact value.
    exact: bool,
}

/// A nonzero value `-n/d` (when `negative`) or `n/d`, not necessarily reduced, rounded to
/// `digits` significant digits (at most 18) on machine words: `(m, e, exact)` with `m` of
/// exactly `digits` digits and the value `m 10^(e + 1 - digits)`, `exact` when the rounding
/// lost nothing; `None` when a product on the way would pass 2^256 (the big integers then round
/// it, to the same result). `near`, the f64 nearest to `n/d` (correctly rounded) if the caller
/// has it, usually decides the digits alone ([`round_scaled`]), or a product on words
/// where it lands on an integer of the scale ([`on_an_integer`]); where it cannot, it guesses
/// the exponent and the digits, which the words then check.
pub(crate) fn round_on_words(
    negative: bool,
    n: U256,
    d: U256,
    digits: usize,
    rounding: Rounding,
    near: Option<f64>,
) -> Option<(u64, i64, bool)> {
    if digits > 18 {
        return None;
    }
    let near = near.filter(|x| x.is_normal() && *x > 0.0);
    if let Some(on_scale) = near.and_then(|x| scaled(x, digits)) {
        if let Some(rounded) = round_scaled(negative, on_scale, digits, rounding, NEAREST_ERROR) {
            return Some(rounded);
        }
        if let Some(exactly) = on_an_integer(n, d, on_scale, digits) {
            return Some(exactly);
        }
    }
    let ten = |k: i64| U256::pow10(u32::try_from(k.unsigned_abs()).ok()?);
    // n/d against 10^e, and n/d scaled by 10^k, as a fraction of words.
    let scaled = |k: i64| -> Option<(U256, U256)> {
        if k >= 0 {
            Some((n.checked_mul_wide(ten(k)?)?, d))
        } else {
            Some((n, d.checked_mul_wide(ten(k)?)?))
        }
    };
    let estimate = match near {
        Some(x) => log10_of_float_estimate(x),
        None => log10_estimate(n.bits().into(), d.bits().into()),
    };
    // The estimate is off by one at most. Up to 17 digits the quotient at it, below
    // 10^18 < 2^63 either way, says which way; 18 digits settle the exponent first.
    let mut exp = if digits < 18 {
        estimate
    } else {
        settle_log10(estimate, |e| {
            let (num, den) = scaled(-e)?;
            Some(num.cmp(&den))
        })?
    };
    let (low, high) = (POWERS_OF_TEN[digits - 1], POWERS_OF_TEN[digits]);
    let (quot, rem, den) = loop {
        let k = digits as i64 - 1 - exp;
        let (num, den) = scaled(k)?;
        // Truncated: the floor of a positive guess.
        let guess = near
            .map(|x| x * 10f64.powi(k as i32))
            .filter(|q| (0.0..4e18).contains(q));
        let (quot, rem) = guess
            .and_then(|q| num.div_small_guessed(den, q as u64))
            .unwrap_or_else(|| num.div_small(den));
        match quot {
            q if q < low => exp -= 1,
            q if q >= high => exp += 1,
            _ => break (quot, rem, den),
        }
    };
    let exact = rem == U256::ZERO;
    // 2 rem against den, as rem against den - rem (2 rem may pass 2^256).
    let half = || rem.cmp(&den.minus(rem));
    let away = !exact && rounds_away(rounding, negative, quot % 2 == 1, half);
    let (m, exp) = carried(quot + u64::from(away), exp, high);
    Some((m, exp, exact))
}

/// `m 10^exp` of `digits` digits as rounded, `high = 10^digits`: 9.995 -> 10.0 carries into a
/// new digit, which the exponent takes.
fn carried(m: u64, exp: i64, high: u64) -> (u64, i64) {
    if m == high {
        (m / 10, exp + 1)
    } else {
        (m, exp)
    }
}

/// The powers of ten an f64 holds exactly, 10^0 to 10^22.
pub(crate) const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// [`round_scaled`]'s bound for an f64 nearest to the value: `2^-50` of the scaled float.
const NEAREST_ERROR: f64 = 1.0 / (1u64 << 50) as f64;

/// The positive normal `x` itself rounded to `digits` significant digits to nearest, ties to
/// even, as [`round_on_words`] rounds it, where the float alone decides (`None` elsewhere: the
/// words decide): `(m, e)` with `x` near `m 10^(e + 1 - digits)`. Whether that lost anything
/// is not told: where `x` scaled lands on an integer, the scaling may have rounded, but by less
/// than half a unit, so the nearest is that integer either way.
pub(crate) fn round_float(x: f64, digits: usize) -> Option<(u64, i64)> {
    if !(x.is_normal() && x > 0.0) {
        return None;
    }
    let (y, exp) = scaled(x, digits)?;
    if y.fract() == 0.0 {
        return Some((y as u64, exp));
    }
    round_scaled(false, (y, exp), digits, Rounding::HalfEven, 0.0).map(|(m, e, _)| (m, e))
}

/// `y = x 10^k` with `digits` integer digits (`10^(digits - 1) <= y < 10^digits`, `digits` at
/// most 15), in one correctly rounded operation, and `e = digits - 1 - k`; `None` where `10^k`
/// is not an exact f64 (`|k| > 22`).
fn scaled(x: f64, digits: usize) -> Option<(f64, i64)> {
    if !(1..=15).contains(&digits) {
        return None;
    }
    let (low, high) = (EXACT_POWERS_OF_TEN[digits - 1], EXACT_POWERS_OF_TEN[digits]);
    let mut exp = log10_of_float_estimate(x);
    // The estimate is off by one at most, so two tries find the scale (and a third is spare).
    for _ in 0..3 {
        let k = digits as i64 - 1 - exp;
        let power = *EXACT_POWERS_OF_TEN.get(usize::try_from(k.unsigned_abs()).ok()?)?;
        let y = if k >= 0 { x * power } else { x / power };
        if y < low {
            exp -= 1;
        } else if y >= high {
            exp += 1;
        } else {
            return Some((y, exp));
        }
    }
    None
}

/// `(m, exp, true)` when `n/d` is exactly `m 10^(exp + 1 - digits)`, `m` the integer nearest
/// `y`, the value's nearest f64 at the scale of `digits` digits ([`scaled`]): the values a
/// float cannot certify because they sit on an integer of the scale (a relative error of
/// exactly 1, or 1/4), decided by a product on words each side instead of the division.
fn on_an_integer(
    n: U256,
    d: U256,
    (y, exp): (f64, i64),
    digits: usize,
) -> Option<(u64, i64, bool)> {
    let m = y.round();
    if !(EXACT_POWERS_OF_TEN[digits - 1]..EXACT_POWERS_OF_TEN[digits]).contains(&m) {
        return None;
    }
    // An integer below 10^15, exactly.
    let m = m as u64;
    let k = digits as i64 - 1 - exp;
    let ten = U256::pow10(u32::try_from(k.unsigned_abs()).ok()?)?;
    let m_d = d.checked_mul(u128::from(m))?;
    let equal = if k >= 0 {
        n.checked_mul_wide(ten)? == m_d
    } else {
        n == m_d.checked_mul_wide(ten)?
    };
    equal.then_some((m, exp, true))
}

/// [`round_on_words`] decided from a positive normal f64 `x`, given [`scaled`] (`y` and its
/// exponent), where that alone is certain.
/// `error` bounds the distance, relative to `y = x 10^k` (`k` giving `digits` integer digits),
/// from `y` to the value scaled alike: for `x` the f64 nearest to a real `r` (`|x - r| <= 2^-53
/// x`), `r 10^k` is within `2^-51.9 y` of `y` (one more rounding), and [`NEAREST_ERROR`] is
/// `2^-50`; for `x` the value itself it is 0, since rounding is monotone and the integers and
/// halves `y` is compared with are f64s, so the scaling may land on one but never crosses it.
/// Then `y`'s floor is the value's and which side of the half it lies on is settled whenever
/// `y` is further than `error y` from an integer and from a half, and the rounding is not exact.
/// `None` (the words decide) at or near those points, for more than 15 digits, and where `10^k`
/// is not an exact f64 (`|k| > 22`).
fn round_scaled(
    negative: bool,
    (y, exp): (f64, i64),
    digits: usize,
    rounding: Rounding,
    error: f64,
) -> Option<(u64, i64, bool)> {
    let (low, high) = (EXACT_POWERS_OF_TEN[digits - 1], EXACT_POWERS_OF_TEN[digits]);
    let margin = y * error;
    if y - margin < low || y + margin >= high {
        return None;
    }
    // The floor (y is positive and below 10^15), and the bits of y below its units.
    let quot = y as u64;
    let fraction = y - quot as f64;
    let near_point = |p: f64| (fraction - p).abs() <= margin;
    if near_point(0.0) || near_point(0.5) || near_point(1.0) {
        return None;
    }
    let half = || fraction.total_cmp(&0.5);
    let away = rounds_away(rounding, negative, quot % 2 == 1, half);
    let (m, exp) = carried(quot + u64::from(away), exp, high as u64);
    Some((m, exp, false))
}

impl Significant {
    fn of(value: &Q, digits: usize, rounding: Rounding) -> Significant {
        let digits = digits.max(1);
        if value.is_zero() {
            return Significant {
                negative: false,
                m: "0".to_string(),
                exp: 0,
                digits,
                exact: true,
            };
        }
        let words = U256::from_big(value.numer().magnitude())
            .zip(U256::from_big(value.denom().magnitude()));
        words
            .and_then(|(n, d)| Significant::on_words(value.is_negative(), n, d, digits, rounding))
            .unwrap_or_else(|| Significant::on_big(value, digits, rounding))
    }

    /// [`Significant::of`] in big integers, for a nonzero value.
    fn on_big(value: &Q, digits: usize, rounding: Rounding) -> Significant {
        let n = value.numer().abs();
        Significant::on_parts(value.is_negative(), n, value.denom(), digits, rounding)
    }

    /// [`Significant::on_big`] of `-n/d` (when `negative`) or `n/d`, `n > 0`, `d > 0`, not
    /// necessarily reduced.
    fn on_parts(
        negative: bool,
        n: BigInt,
        d: &BigInt,
        digits: usize,
        rounding: Rounding,
    ) -> Significant {
        let mut exp = floor_log10(&n, d);
        let shift = digits as i64 - 1 - exp;
        let (num, den) = if shift >= 0 {
            (n * ten_to(shift.unsigned_abs()), d.clone())
        } else {
            (n, d * ten_to(shift.unsigned_abs()))
        };
        let (mut m, exact) = round_quotient(&num, &den, negative, rounding);
        if m == ten_to(digits as u64) {
            // 9.995 -> 10.0: the rounding carried into a new digit.
            m = ten_to(digits as u64 - 1);
            exp += 1;
        }
        Significant {
            negative,
            m: m.to_string(),
            exp,
            digits,
            exact,
        }
    }

    /// [`Significant::of`] on machine words: [`round_on_words`] as digits and exponent.
    fn on_words(
        negative: bool,
        n: U256,
        d: U256,
        digits: usize,
        rounding: Rounding,
    ) -> Option<Significant> {
        let (m, exp, exact) = round_on_words(negative, n, d, digits, rounding, None)?;
        Some(Significant {
            negative,
            m: itoa::Buffer::new().format(m).to_string(),
            exp,
            digits,
            exact,
        })
    }

    /// The value as [`decimal`] prints it.
    fn text(&self) -> String {
        let mut out = String::with_capacity(self.m.len() + 8);
        self.write(&mut out);
        out
    }

    /// Appends the value as [`decimal`] prints it.
    fn write(&self, out: &mut String) {
        write_significant(out, self.negative, &self.m, self.exp, self.digits);
    }
}

/// Appends `±m × 10^(exp - digits + 1)` (`s` the digits of `m`, `"0"` for zero) as [`decimal`]
/// prints it: positional from 10^-7 up to `digits` integer digits, scientific beyond.
fn write_significant(out: &mut String, negative: bool, s: &str, exp: i64, digits: usize) {
    if s == "0" {
        out.push('0');
        return;
    }
    if negative {
        out.push('-');
    }
    if (-7..digits as i64).contains(&exp) {
        if exp >= 0 {
            let (int, frac) = s.split_at(exp as usize + 1);
            out.push_str(int);
            if !frac.is_empty() {
                out.push('.');
                out.push_str(frac);
            }
        } else {
            out.push_str("0.");
            out.extend(std::iter::repeat_n('0', (-exp - 1) as usize));
            out.push_str(s);
        }
    } else {
        let (lead, rest) = s.split_at(1);
        out.push_str(lead);
        if !rest.is_empty() {
            out.push('.');
            out.push_str(rest);
        }
        out.push('e');
        out.push_str(itoa::Buffer::new().format(exp));
    }
}

/// A rational printed as [`decimal`] prints it: `digits` significant digits, correctly rounded.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::Decimal, q};
/// let third = q(1, 3);
/// assert_eq!(Decimal { value: &third, digits: 4 }.to_string(), "0.3333");
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Decimal<'a> {
    /// The exact value.
    pub value: &'a Q,
    /// Significant digits to show.
    pub digits: usize,
}

impl fmt::Display for Decimal<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&decimal(self.value, self.digits))
    }
}

/// Appends `q` exactly as its `Display` (`n`, or `n/d`), on machine words when both fit 256
/// bits.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::write_exact, q};
/// let mut out = String::new();
/// write_exact(&mut out, &q(-6, 4));
/// out.push(',');
/// write_exact(&mut out, &q(7, 1));
/// assert_eq!(out, "-3/2,7");
/// ```
pub fn write_exact(out: &mut String, q: &Q) {
    if write_ratio(out, q).is_none() {
        use std::fmt::Write;
        write!(out, "{q}").expect("writing to a String cannot fail");
    }
}

/// Rational bounds `lo <= sqrt(x) <= hi` with `hi - lo <= 10^-digits * sqrt(x)`.
///
/// The bounds are decimal rationals (their denominators are powers of ten), except when `x` is
/// the square of a rational: then `lo == hi ==` the exact root (such as `2/3`). Computed with
/// exact integer square roots only.
///
/// Precondition: `x >= 0`. For `x <= 0` the result is `(0, 0)` (the exact root for `x = 0`).
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::field::decimal::sqrt_bounds;
/// assert_eq!(sqrt_bounds(&q(2, 1), 3), (q(1414, 1000), q(1415, 1000)));
/// assert_eq!(sqrt_bounds(&q(4, 9), 5), (q(2, 3), q(2, 3)));
/// ```
pub fn sqrt_bounds(x: &Q, digits: usize) -> (Q, Q) {
    if !x.is_positive() {
        return (Q::zero(), Q::zero());
    }
    if let Some(root) = x.try_sqrt() {
        return (root.clone(), root);
    }
    let (n, d) = (x.numer(), x.denom());
    // 10^e_s <= sqrt(x), so a step of 10^-k with k = digits - e_s is within the precision.
    let e_s = floor_log10(n, d).div_euclid(2);
    let k = digits as i64 - e_s;
    let floor_scaled = if k >= 0 {
        (n * ten_to(2 * k.unsigned_abs())) / d
    } else {
        n / (d * ten_to(2 * k.unsigned_abs()))
    };
    let m = floor_scaled.sqrt();
    let scale = |v: BigInt| {
        if k >= 0 {
            Q::new(v, ten_to(k.unsigned_abs()))
        } else {
            Q::from_integer(v * ten_to(k.unsigned_abs()))
        }
    };
    let hi = scale(&m + BigInt::one());
    (scale(m), hi)
}

/// The exact square root of `x >= 0` as text, in the one canonical ASCII form of every surd
/// ([`notation::root`](crate::field::notation::root)): the rational root when there is one
/// (`"2/3"`, `"2"`, `"0"`), otherwise square factors pulled out and no denominator under the
/// root (`"sqrt(6)/3"`, `"2*sqrt(2)"`).
///
/// # Panics
/// **Panics if `x < 0`** (no real root; a programming error).
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::field::decimal::surd;
/// assert_eq!(surd(&q(2, 3)), "sqrt(6)/3");
/// assert_eq!(surd(&q(4, 9)), "2/3");
/// assert_eq!(surd(&q(8, 1)), "2*sqrt(2)");
/// ```
pub fn surd(x: &Q) -> String {
    crate::field::notation::root(x, crate::field::notation::Notation::Ascii)
}

/// `sqrt(x)` correctly rounded to `digits` significant digits, formatted as [`decimal`] does.
///
/// Bounds with guard digits are refined until both round alike; an exact root is rounded
/// directly. Precondition `x >= 0`; `x < 0` gives `"0"`, as [`sqrt_bounds`] does.
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::field::decimal::decimal_sqrt;
/// assert_eq!(decimal_sqrt(&q(2, 1), 10), "1.414213562");
/// assert_eq!(decimal_sqrt(&q(1, 4), 3), "0.500");
/// ```
pub fn decimal_sqrt(x: &Q, digits: usize) -> String {
    let digits = digits.max(1);
    let mut guard = 4;
    loop {
        let (lo, hi) = sqrt_bounds(x, digits + guard);
        let (a, b) = (decimal(&lo, digits), decimal(&hi, digits));
        if a == b {
            return a;
        }
        // An irrational root is never a rounding tie, so this ends.
        guard *= 2;
    }
}

/// The longest exact fraction [`compact`] prints as it is.
pub const COMPACT_CHARS: usize = 40;

/// `x` for a reader: the exact fraction when it is short (at most [`COMPACT_CHARS`]
/// characters), else the shortest decimal (of at most 15 significant digits) that equals it
/// (`1e400`), else `≈` and its decimal to 6 significant digits. For text reports; JSON keeps the exact value.
///
/// # Examples
/// ```
/// use rodimpact::field::{decimal::compact, q, Q};
/// assert_eq!(compact(&q(36, 19)), "36/19");
/// let big = Q::from_integer(num_bigint::BigInt::from(10).pow(400));
/// assert_eq!(compact(&big), "1e400");
/// assert_eq!(compact(&(big + q(1, 3))), "≈ 1.00000e400");
/// ```
pub fn compact(x: &Q) -> String {
    let exact = x.to_string();
    if exact.chars().count() <= COMPACT_CHARS {
        return exact;
    }
    (1..=15)
        .map(|digits| Significant::of(x, digits, Rounding::HalfEven))
        .find(|rounded| rounded.exact)
        .map_or_else(|| format!("≈ {}", decimal(x, 6)), |exact| exact.text())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`round_scaled`] of `x` at its scale.
    fn round_certified(
        negative: bool,
        x: f64,
        digits: usize,
        rounding: Rounding,
        error: f64,
    ) -> Option<(u64, i64, bool)> {
        round_scaled(negative, scaled(x, digits)?, digits, rounding, error)
    }

    #[test]
    fn unreduced_big_parts_print_as_their_reduced_value() {
        let big = |s: &str| s.parse::<BigInt>().unwrap();
        // 10^200 times 2/3, -1/8, 0 and 999.5/1000 (a carry into a new digit).
        let scale = ten_to(200);
        for (n, d, want) in [
            (big("2"), big("3"), "0.667"),
            (big("-1"), big("8"), "-0.125"),
            (big("0"), big("7"), "0"),
            (big("19990"), big("20000"), "1.00"),
        ] {
            let (n, d) = (n * &scale, d * &scale);
            assert_eq!(decimal_unreduced(&n, &d, 3), want);
            assert_eq!(decimal(&Q::new(n, d), 3), want);
        }
    }
    use crate::field::q;
    use proptest::prelude::*;

    /// Every rounding direction, for the proptests to pick from.
    const DIRECTIONS: [Rounding; 5] = [
        Rounding::HalfEven,
        Rounding::HalfAwayFromZero,
        Rounding::HalfTowardZero,
        Rounding::Floor,
        Rounding::Ceiling,
    ];

    proptest! {
        /// Rounding on machine words gives the big integers' digits, exponent and exactness,
        /// in every direction, where it answers (parts up to 256 bits, values from about
        /// 10^-77 to 10^77, 1 to 18 digits).
        #[test]
        fn significant_digits_on_words_are_the_big_integers(
            n in prop::collection::vec(any::<u32>(), 1..9),
            d in prop::collection::vec(any::<u32>(), 1..9),
            negative: bool, digits in 1usize..=18, direction in 0usize..5,
        ) {
            use num_bigint::{BigInt, BigUint};
            let (n, d) = (BigUint::new(n), BigUint::new(d));
            prop_assume!(n.bits() > 0 && d.bits() > 0);
            let n = BigInt::from(n);
            let x = Q::new(if negative { -n } else { n }, d.into());
            let rounding = DIRECTIONS[direction];
            let big = Significant::on_big(&x, digits, rounding);
            if let Some(words) = on_words(&x, digits, rounding) {
                prop_assert_eq!(
                    (words.text(), words.exact, words.m, words.exp),
                    (big.text(), big.exact, big.m.clone(), big.exp)
                );
            }
            // Unreduced (both parts times 7): the same digits, from the value alone.
            let (n7, d7) = (U256::from_big(x.numer().magnitude()).and_then(|n| n.checked_mul(7)),
                U256::from_big(x.denom().magnitude()).and_then(|d| d.checked_mul(7)));
            if let (Some(n7), Some(d7)) = (n7, d7)
                && let Some(words) = Significant::on_words(x.is_negative(), n7, d7, digits, rounding)
            {
                prop_assert_eq!(words.text(), big.text());
            }
            // With the nearest f64, which decides most digits alone.
            let near = crate::field::Field::nearest_f64(&x).abs();
            let n = U256::from_big(x.numer().magnitude());
            let d = U256::from_big(x.denom().magnitude());
            if let (Some(n), Some(d)) = (n, d)
                && let Some((m, exp, exact)) = round_on_words(x.is_negative(), n, d, digits, rounding, Some(near))
            {
                prop_assert_eq!((m.to_string(), exp, exact), (big.m.clone(), big.exp, big.exact));
            }
        }

        /// Values on an integer of their scale (`m 10^j` exactly, in unreduced parts: a
        /// relative error of exactly 1 or 1/4), and their neighbours a part in 10^40 away:
        /// with the nearest f64, the words give the big integers' digits, exponent and
        /// exactness, in every direction.
        #[test]
        fn values_on_an_integer_of_their_scale(
            m in 1u64..1_000_000, j in -20i32..20, c in 1u64..1000, off in -1i64..=1,
            digits in 1usize..=15, direction in 0usize..5, negative: bool,
        ) {
            use num_bigint::BigInt;
            let ten = BigInt::from(10).pow(j.unsigned_abs());
            let (mut n, mut d) = if j >= 0 {
                (BigInt::from(m) * &ten * c, BigInt::from(c))
            } else {
                (BigInt::from(m) * c, ten * c)
            };
            if off != 0 {
                let part = BigInt::from(10).pow(40);
                n = n * &part + off;
                d *= part;
            }
            let x = Q::new(if negative { -n.clone() } else { n.clone() }, d.clone());
            let rounding = DIRECTIONS[direction];
            let big = Significant::on_big(&x, digits, rounding);
            let near = crate::field::Field::nearest_f64(&x).abs();
            let words = |b: &BigInt| U256::from_big(b.magnitude()).unwrap();
            if let Some((m, exp, exact)) =
                round_on_words(negative, words(&n), words(&d), digits, rounding, Some(near))
            {
                prop_assert_eq!((m.to_string(), exp, exact), (big.m.clone(), big.exp, big.exact));
            }
        }

        /// An f64's own digits decided from the f64 alone are its exact value's, in every
        /// direction, near ties and integers too (where the float declines).
        #[test]
        fn certified_digits_of_a_float_are_its_exact_values(
            bits in 1u64..0x7ff0_0000_0000_0000, tie in 0u64..100_000, k in -25i32..25,
            digits in 1usize..=15, direction in 0usize..5, negative: bool,
        ) {
            let rounding = DIRECTIONS[direction];
            // Any f64, one from 1e-25 to 1e25 (where the float decides), ties and integers.
            let moderate = f64::from_bits(0x3AC0_0000_0000_0000 + bits % 0x0A70_0000_0000_0000);
            let (tie, whole) = ((tie as f64 + 0.5) * 10f64.powi(k), tie as f64 * 10f64.powi(k));
            for x in [f64::from_bits(bits), moderate, tie, whole] {
                prop_assume!(x.is_normal());
                // The float as the value itself (no margin) and as the nearest to a value.
                for error in [0.0, NEAREST_ERROR] {
                    if let Some((m, exp, exact)) = round_certified(negative, x, digits, rounding, error) {
                        let value = crate::field::exact_float(x).expect("finite");
                        let value = if negative { -value } else { value };
                        let big = Significant::on_big(&value, digits, rounding);
                        prop_assert_eq!((m.to_string(), exp, exact), (big.m, big.exp, big.exact), "{}", x);
                    }
                }
            }
        }
    }

    #[test]
    fn certified_digits_decline_where_the_float_cannot_tell() {
        // Exact ties and exact values: the words decide them.
        for (x, digits) in [
            (0.125, 2),
            (2.5, 1),
            (0.5, 3),
            (100.0, 2),
            (1e-30, 3),
            (1e30, 3),
        ] {
            assert_eq!(
                round_certified(false, x, digits, Rounding::HalfEven, NEAREST_ERROR),
                None,
                "{x}"
            );
        }
        // Just past a tie whose nearest f64 is just short of it (0.145 + 10^-40, nearest
        // 0.14499999999999999): the float declines and the words round the value up.
        let ten_40 = num_traits::pow(BigInt::from(10), 40);
        for (tie, side, want) in [(145, 1, "0.15"), (275, -1, "0.27"), (285, 1, "0.29")] {
            let x = Q::new(BigInt::from(tie) * &ten_40 / 1000 + side, ten_40.clone());
            let near = crate::field::Field::nearest_f64(&x);
            assert_eq!(
                round_certified(false, near, 2, Rounding::HalfEven, NEAREST_ERROR),
                None,
                "{x}"
            );
            let n = U256::from_big(x.numer().magnitude()).unwrap();
            let d = U256::from_big(x.denom().magnitude()).unwrap();
            let mut text = String::new();
            push_decimal_words(&mut text, false, n, d, 2, Some(near));
            assert_eq!(text, want);
        }
        assert_eq!(
            round_certified(false, 1.0 / 60.0, 3, Rounding::HalfEven, NEAREST_ERROR),
            Some((167, -2, false))
        );
        assert_eq!(
            round_certified(true, 9.9996, 4, Rounding::HalfEven, NEAREST_ERROR),
            Some((1000, 1, false))
        );
    }

    /// [`Significant::on_words`] of a rational's own parts.
    fn on_words(x: &Q, digits: usize, rounding: Rounding) -> Option<Significant> {
        let n = U256::from_big(x.numer().magnitude())?;
        let d = U256::from_big(x.denom().magnitude())?;
        Significant::on_words(x.is_negative(), n, d, digits, rounding)
    }

    #[test]
    fn significant_digits_on_words_at_ties_and_carries() {
        // Exact ties in each direction, a carry into a new digit, and an exact value.
        for (x, digits, rounding, want) in [
            (q(25, 1000), 1, Rounding::HalfEven, "0.02"),
            (q(35, 1000), 1, Rounding::HalfEven, "0.04"),
            (q(-25, 1000), 1, Rounding::HalfAwayFromZero, "-0.03"),
            (q(25, 1000), 1, Rounding::HalfTowardZero, "0.02"),
            (q(9995, 1000), 3, Rounding::HalfEven, "10.0"),
            (q(-1, 3), 2, Rounding::Floor, "-0.34"),
            (q(1, 8), 3, Rounding::Ceiling, "0.125"),
        ] {
            let words = on_words(&x, digits, rounding).unwrap();
            assert_eq!(words.text(), want, "{x} {digits} {rounding:?}");
            assert_eq!(
                words.text(),
                Significant::on_big(&x, digits, rounding).text()
            );
        }
    }

    fn big(s: &str) -> BigInt {
        s.parse().expect("test literal")
    }

    #[test]
    fn decimal_table() {
        let table: &[(Q, usize, &str)] = &[
            (q(0, 1), 5, "0"),
            (q(-1, 5), 5, "-0.20000"),
            (q(6, 5), 3, "1.20"),
            (q(2, 1), 3, "2.00"),
            (q(123456, 1), 3, "1.23e5"),
            (q(123456, 1), 6, "123456"),
            (q(123456, 1), 7, "123456.0"),
            (q(100, 1), 3, "100"),
            (q(100, 1), 2, "1.0e2"),
            (q(1, 8), 2, "0.12"),
            (q(3, 8), 2, "0.38"),
            (q(-1, 8), 2, "-0.12"),
            (q(-3, 8), 2, "-0.38"),
            (q(5, 2), 1, "2"),
            (q(7, 2), 1, "4"),
            (q(25, 1), 1, "2e1"),
            (q(35, 1), 1, "4e1"),
            (q(1999, 200), 3, "10.0"),
            (q(-1999, 200), 3, "-10.0"),
            (q(99999, 1), 3, "1.00e5"),
            (q(9999, 10000), 3, "1.00"),
            (q(1, 3), 5, "0.33333"),
            (q(2, 3), 5, "0.66667"),
            (q(-2, 3), 1, "-0.7"),
            (q(1, 10_000_000), 3, "0.000000100"),
            (q(1, 100_000_000), 3, "1.00e-8"),
            (q(99_999_999, 1_000_000_000_000_000), 3, "0.000000100"),
            (q(99_999_999, 10_000_000_000_000_000), 3, "1.00e-8"),
            (q(1, 7), 0, "0.1"),
        ];
        for (value, digits, want) in table {
            assert_eq!(decimal(value, *digits), *want, "{value} at {digits}");
        }
        // 1.2e-4 is positional: -7 <= E.
        assert_eq!(decimal(&q(12345, 100_000_000), 2), "0.00012");
    }

    #[test]
    fn decimal_huge_and_tiny() {
        let tiny = Q::new(BigInt::from(-4), ten_to(300));
        assert_eq!(decimal(&tiny, 3), "-4.00e-300");
        let tiny9000 = Q::new(BigInt::one(), ten_to(9000));
        assert_eq!(
            decimal(&tiny9000, 30),
            format!("1.{}e-9000", "0".repeat(29))
        );
        let third = Q::new(BigInt::one(), BigInt::from(3) * ten_to(9000));
        assert_eq!(decimal(&third, 4), "3.333e-9001");
        let huge = Q::from_integer(BigInt::from(2) * ten_to(5000) / 3);
        assert_eq!(decimal(&huge, 4), "6.667e4999");
        assert_eq!(
            Decimal {
                value: &q(-7, 4),
                digits: 3
            }
            .to_string(),
            "-1.75"
        );
    }

    /// The invariant of `sqrt_bounds`: `lo^2 <= x <= hi^2`, decimal bounds (or the exact root),
    /// and `hi - lo <= 10^-digits * sqrt(x)`, checked as `(hi - lo)^2 * 10^(2 digits) <= x`.
    fn check_bounds(x: &Q, digits: usize) {
        let (lo, hi) = sqrt_bounds(x, digits);
        assert!(lo <= hi, "{x} {digits}");
        assert!(
            &lo * &lo <= *x && *x <= &hi * &hi,
            "{x} {digits}: {lo} {hi}"
        );
        let width = &hi - &lo;
        let scale = Q::from_integer(ten_to(2 * digits as u64));
        assert!(&width * &width * scale <= *x, "{x} {digits}: {lo} {hi}");
        if let Some(root) = x.try_sqrt() {
            assert_eq!((&lo, &hi), (&root, &root));
        } else {
            for b in [&lo, &hi] {
                let mut d2 = b.denom().clone();
                while (&d2 % 2u8).is_zero() {
                    d2 /= 2u8;
                }
                while (&d2 % 5u8).is_zero() {
                    d2 /= 5u8;
                }
                assert!(d2.is_one(), "{b} not decimal");
            }
        }
    }

    #[test]
    fn sqrt_bounds_invariants() {
        let mut xs = vec![
            q(2, 1),
            q(2, 3),
            q(3, 2),
            q(4, 9),
            q(1, 1),
            q(10, 1),
            q(1, 10),
            q(1, 1_000_000_007),
            q(999_999_999, 7),
        ];
        xs.push(Q::from_integer(ten_to(301)));
        xs.push(Q::new(BigInt::from(3), ten_to(401)));
        xs.push(Q::new(big("123456789123456789123456789"), big("987654321")));
        for n in 1..60 {
            for d in [1, 2, 3, 7, 10, 12] {
                xs.push(q(n, d));
            }
        }
        for x in &xs {
            for digits in [0, 1, 2, 5, 17, 40] {
                check_bounds(x, digits);
            }
        }
        assert_eq!(sqrt_bounds(&q(-2, 1), 5), (q(0, 1), q(0, 1)));
        assert_eq!(sqrt_bounds(&q(0, 1), 5), (q(0, 1), q(0, 1)));
        assert_eq!(sqrt_bounds(&q(2, 1), 3), (q(1414, 1000), q(1415, 1000)));
        // Huge x: the bounds are integers (multiples of a power of ten).
        let (lo, hi) = sqrt_bounds(&Q::from_integer(ten_to(301)), 3);
        assert!(lo.is_integer() && hi.is_integer());
    }

    #[test]
    fn surd_table() {
        let table = [
            (q(2, 3), "sqrt(6)/3"),
            (q(4, 9), "2/3"),
            (q(4, 1), "2"),
            (q(0, 1), "0"),
            (q(8, 1), "2*sqrt(2)"),
            (q(3, 2), "sqrt(6)/2"),
            (q(1, 4), "1/2"),
            (q(11, 400), "sqrt(11)/20"),
            (q(125, 1), "5*sqrt(5)"),
        ];
        for (x, want) in table {
            assert_eq!(surd(&x), want);
        }
    }

    #[test]
    fn decimal_sqrt_table() {
        let table = [
            (q(2, 1), 1, "1"),
            (q(2, 1), 3, "1.41"),
            (q(2, 1), 30, "1.41421356237309504880168872421"),
            (q(2, 3), 10, "0.8164965809"),
            (q(3, 2), 10, "1.224744871"),
            (q(4, 9), 4, "0.6667"),
            (q(1, 4), 3, "0.500"),
            (q(0, 1), 3, "0"),
            (q(99, 1), 2, "9.9"),
            (q(99, 1), 1, "1e1"),
            (q(10, 1), 5, "3.1623"),
        ];
        for (x, digits, want) in table {
            assert_eq!(decimal_sqrt(&x, digits), want, "sqrt({x}) at {digits}");
        }
        let big_x = Q::from_integer(BigInt::from(2) * ten_to(600));
        assert_eq!(decimal_sqrt(&big_x, 5), "1.4142e300");
    }

    /// The old textbook definition of the magnitude, by decimal string lengths: an independent
    /// derivation to hold [`magnitude`] (from bit lengths) to.
    fn magnitude_by_digits(x: &Q) -> i64 {
        let x = x.abs();
        let digits = |n: &BigInt| n.to_string().len() as i64;
        let mut e = digits(x.numer()) - digits(x.denom());
        while pow10(e) > x {
            e -= 1;
        }
        while pow10(e + 1) <= x {
            e += 1;
        }
        e
    }

    #[test]
    fn round_at_table() {
        use Rounding::*;
        let table = [
            (q(25, 10), 0, HalfEven, q(2, 1)),
            (q(35, 10), 0, HalfEven, q(4, 1)),
            (q(25, 10), 0, HalfAwayFromZero, q(3, 1)),
            (q(-25, 10), 0, HalfAwayFromZero, q(-3, 1)),
            (q(25, 10), 0, HalfTowardZero, q(2, 1)),
            (q(-25, 10), 0, HalfTowardZero, q(-2, 1)),
            (q(-21, 10), 0, Floor, q(-3, 1)),
            (q(-21, 10), 0, Ceiling, q(-2, 1)),
            (q(1551, 1), 2, HalfAwayFromZero, q(1600, 1)),
            (q(1549, 1), 2, HalfAwayFromZero, q(1500, 1)),
            (q(2, 3), -3, HalfEven, q(667, 1000)),
            (q(7, 1), -2, Floor, q(7, 1)),
        ];
        for (x, place, rounding, want) in table {
            assert_eq!(
                round_at(&x, place, rounding),
                want,
                "{x} at {place} {rounding:?}"
            );
        }
    }

    proptest! {
        /// `sqrt_bounds` encloses the root within the requested relative precision.
        #[test]
        fn sqrt_bounds_enclose(n in 1u64..u64::MAX, d in 1u64..u64::MAX, digits in 0usize..50) {
            check_bounds(&Q::new(BigInt::from(n), BigInt::from(d)), digits);
        }

        /// Law: the magnitude from bit lengths is the magnitude from decimal string lengths.
        #[test]
        fn magnitude_agrees_with_the_digit_count(n in -10i64.pow(15)..10i64.pow(15), d in 1i64..10i64.pow(15), k in 0u64..60) {
            prop_assume!(n != 0);
            let x = q(n, d) * Q::from_integer(ten_to(k));
            prop_assert_eq!(magnitude(&x), magnitude_by_digits(&x));
            let y = q(n, d) / Q::from_integer(ten_to(k));
            prop_assert_eq!(magnitude(&y), magnitude_by_digits(&y));
        }

        /// Law: `round_at` lands on a multiple of 10^place, no further than the rounding allows:
        /// within half a unit to nearest, within a unit toward minus or plus infinity, on the
        /// side the direction says.
        #[test]
        fn round_at_is_a_nearby_multiple(n in -10i64.pow(12)..10i64.pow(12), d in 1i64..10i64.pow(6), place in -8i64..8) {
            let x = q(n, d);
            let unit = pow10(place);
            for rounding in [Rounding::HalfEven, Rounding::HalfAwayFromZero, Rounding::HalfTowardZero, Rounding::Floor, Rounding::Ceiling] {
                let r = round_at(&x, place, rounding);
                prop_assert!((&r / &unit).is_integer(), "{} {:?}", r, rounding);
                let gap = &r - &x;
                match rounding {
                    Rounding::Floor => prop_assert!(!gap.is_positive() && -&gap < unit),
                    Rounding::Ceiling => prop_assert!(!gap.is_negative() && gap < unit),
                    _ => prop_assert!(gap.abs() * Q::from_integer(2.into()) <= unit),
                }
            }
        }
    }
}
