//! Exact numbers: parsing and printing.
//!
//! Every number enters the library through [`parse`], which builds the exact rational from the
//! digit string and the decimal exponent with big integers (never through a float), after an
//! O(n) scan that enforces the resource limits [`MAX_DIGITS`] and [`MAX_EXPONENT`].
//!
//! Printing is exact where possible (num-rational's `p/q`, and [`surd`] for square roots) and
//! otherwise correctly rounded: [`decimal`] and [`Decimal`] round half to even to a number of
//! significant digits, [`sqrt_bounds`] encloses a square root between decimal rationals, and
//! [`decimal_sqrt`] rounds a square root correctly. All of it uses integer arithmetic only.

use crate::echo::echo;
use crate::error::ErrorKind;
use crate::fast::U256;
use crate::field::{Q, TrySqrt};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

/// The most decimal digits one input number may contain (mantissas and exponents together).
pub const MAX_DIGITS: usize = 10_000;

/// The largest accepted magnitude of a written decimal exponent (`1e10000` is accepted,
/// `1e10001` is not).
pub const MAX_EXPONENT: u64 = 10_000;

/// Parses an exact rational number.
///
/// Accepted forms, after trimming outer whitespace: integers (`2`, `+3`, `-7`), decimals
/// (`-0.25`, `.5`, `5.`), scientific notation (`1.5e-3`, `2E+2`) and the quotient of two such
/// numbers (`3/7`, `75/9.8`, `1e-3/4`). The value is built exactly from the digits.
///
/// # Errors
/// - [`ErrorKind::Empty`] for an empty or all-whitespace text;
/// - [`ErrorKind::NotFinite`] for NaN and infinities (`nan`, `inf`, `-Infinity`, any case);
/// - [`ErrorKind::DivisionByZero`] for a zero denominator (`1/0`, `3/0.0`);
/// - [`ErrorKind::TooManyDigits`] for more than [`MAX_DIGITS`] digits in total;
/// - [`ErrorKind::ExponentTooLarge`] for a written exponent beyond +-[`MAX_EXPONENT`];
/// - [`ErrorKind::Malformed`] for anything else, with a one-line reason.
///
/// # Examples
/// ```
/// use rodimpact::number::parse;
/// use rodimpact::ErrorKind;
/// assert_eq!(parse("75/9.8").unwrap().to_string(), "375/49");
/// assert_eq!(parse(" 1.5e-3 ").unwrap().to_string(), "3/2000");
/// assert_eq!(parse("1/0"), Err(ErrorKind::DivisionByZero));
/// assert!(matches!(parse("1..2"), Err(ErrorKind::Malformed(_))));
/// ```
pub fn parse(text: &str) -> Result<Q, ErrorKind> {
    let text = text.trim();
    if text.is_empty() {
        return Err(ErrorKind::Empty);
    }
    if let Some(word) = WordRatio::parse(text) {
        return Ok(word.value());
    }
    let parts: Vec<&str> = text.split('/').collect();
    if parts.iter().any(|part| is_non_finite_word(part)) {
        return Err(ErrorKind::NotFinite(echo(text)));
    }
    // O(n) resource check before any structural or big-integer work.
    if text.bytes().filter(u8::is_ascii_digit).count() > MAX_DIGITS {
        return Err(ErrorKind::TooManyDigits { limit: MAX_DIGITS });
    }
    if parts.len() > 2 {
        return Err(malformed(text, "more than one '/'"));
    }
    let mut offset = 0;
    let mut lexed = Vec::with_capacity(2);
    for (i, part) in parts.iter().enumerate() {
        let what = if i == 0 { "numerator" } else { "denominator" };
        lexed.push(lex_decimal(part, offset, text, what, parts.len() == 2)?);
        offset += part.chars().count() + 1;
    }
    let mut values = lexed.iter().map(Lexed::value);
    let numerator = values
        .next()
        .ok_or_else(|| malformed(text, "no number"))??;
    match values.next() {
        None => Ok(numerator),
        Some(denominator) => {
            let denominator = denominator?;
            if denominator.is_zero() {
                Err(ErrorKind::DivisionByZero)
            } else if numerator.is_integer() && denominator.is_integer() {
                // `p/q`, the form of every batch cell: one reduction, on machine words when
                // it fits (`Ratio`'s division would take three GCDs on heap digits).
                let (p, q) = (numerator.into_raw().0, denominator.into_raw().0);
                Ok(crate::fast::reduce(p, q))
            } else {
                Ok(numerator / denominator)
            }
        }
    }
}

/// A number in one of the commonest forms, `[+-]digits` or `[+-]digits/digits` with each part
/// below 2^256 (every cell of a typical batch), read on machine words and not yet reduced:
/// `±numer/denom`, `denom > 0`. [`parse`] reduces it once; a batch compares a claimed value
/// with it by cross-multiplication, without reducing at all.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct WordRatio {
    negative: bool,
    numer: U256,
    denom: U256,
}

impl WordRatio {
    /// The machine-word form of `text` (already trimmed), or `None` when it is not one; the
    /// general parser gives the same value for these forms (and the error for `/0`).
    pub(crate) fn parse(text: &str) -> Option<WordRatio> {
        let (negative, unsigned) = match text.as_bytes().first()? {
            b'-' => (true, &text[1..]),
            b'+' => (false, &text[1..]),
            _ => (false, text),
        };
        let (numer, denom) = match unsigned.split_once('/') {
            Some((n, d)) => (U256::parse_decimal(n)?, U256::parse_decimal(d)?),
            None => (U256::parse_decimal(unsigned)?, U256::ONE),
        };
        (denom != U256::ZERO).then_some(WordRatio {
            negative,
            numer,
            denom,
        })
    }

    /// The value, reduced (one GCD on machine words).
    pub(crate) fn value(&self) -> Q {
        U256::ratio(self.negative, self.numer, self.denom)
    }

    /// Whether the value equals `q`, decided by cross-multiplication on machine words without
    /// reducing; `None` when `q`'s numerator or denominator exceeds 256 bits.
    pub(crate) fn equals(&self, q: &Q) -> Option<bool> {
        let n = U256::from_big(q.numer().magnitude())?;
        let d = U256::from_big(q.denom().magnitude())?;
        if self.numer == U256::ZERO || n == U256::ZERO {
            return Some(self.numer == n);
        }
        let same_sign = self.negative == q.is_negative();
        Some(same_sign && U256::cross_equal(self.numer, d, n, self.denom))
    }
}

/// Appends `q` exactly as its `Display` (`n`, or `n/d`), on machine words when both fit 256
/// bits.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, number::write_exact};
/// let mut out = String::new();
/// write_exact(&mut out, &q(-6, 4));
/// out.push(',');
/// write_exact(&mut out, &q(7, 1));
/// assert_eq!(out, "-3/2,7");
/// ```
pub fn write_exact(out: &mut String, q: &Q) {
    if crate::fast::write_ratio(out, q).is_none() {
        use std::fmt::Write;
        write!(out, "{q}").expect("writing to a String cannot fail");
    }
}

/// `nan`, `inf`, `infinity` in any case, with an optional sign.
fn is_non_finite_word(part: &str) -> bool {
    let word = part.trim().trim_start_matches(['+', '-']);
    ["nan", "inf", "infinity"]
        .iter()
        .any(|w| word.eq_ignore_ascii_case(w))
}

fn malformed(text: &str, why: &str) -> ErrorKind {
    ErrorKind::Malformed(format!("{why} in \"{}\"", echo(text)))
}

/// One side of a quotient, split into its digit strings and written exponent.
struct Lexed<'a> {
    negative: bool,
    int_digits: &'a str,
    frac_digits: &'a str,
    exponent: i64,
    text: &'a str,
}

impl Lexed<'_> {
    /// The exact value `±(int_digits.frac_digits) * 10^exponent`.
    fn value(&self) -> Result<Q, ErrorKind> {
        let mut digits = String::with_capacity(self.int_digits.len() + self.frac_digits.len());
        digits.push_str(self.int_digits);
        digits.push_str(self.frac_digits);
        let mantissa = BigInt::parse_bytes(digits.as_bytes(), 10)
            .ok_or_else(|| malformed(self.text, "no digits"))?;
        let mantissa = if self.negative { -mantissa } else { mantissa };
        // |exponent| <= MAX_EXPONENT and frac_digits.len() <= MAX_DIGITS: no overflow.
        let shift = self.exponent - self.frac_digits.len() as i64;
        Ok(if shift >= 0 {
            Q::from_integer(mantissa * pow10(shift.unsigned_abs()))
        } else {
            Q::new(mantissa, pow10(shift.unsigned_abs()))
        })
    }
}

/// Splits `[sign] digits [. digits] [(e|E) [sign] digits]` (at least one mantissa digit).
///
/// `offset` is the character position of `part` in `whole`, for messages.
fn lex_decimal<'a>(
    part: &'a str,
    offset: usize,
    whole: &'a str,
    what: &str,
    quotient: bool,
) -> Result<Lexed<'a>, ErrorKind> {
    let bytes = part.as_bytes();
    let unexpected = |i: usize| {
        let c = part[i..].chars().next().unwrap_or(' ');
        let pos = offset + part[..i].chars().count() + 1;
        malformed(
            whole,
            &format!(
                "unexpected character '{}' at position {pos}",
                c.escape_debug()
            ),
        )
    };
    let digits_from = |start: usize| {
        start
            + bytes[start..]
                .iter()
                .take_while(|b| b.is_ascii_digit())
                .count()
    };
    let no_digits = || {
        let why = if quotient {
            format!("no digits in the {what}")
        } else {
            "no digits".to_string()
        };
        malformed(whole, &why)
    };
    let mut i = 0;
    let negative = match bytes.first() {
        Some(b'-') => {
            i = 1;
            true
        }
        Some(b'+') => {
            i = 1;
            false
        }
        _ => false,
    };
    let int_end = digits_from(i);
    let int_digits = &part[i..int_end];
    i = int_end;
    let mut frac_digits = "";
    if bytes.get(i) == Some(&b'.') {
        let frac_end = digits_from(i + 1);
        frac_digits = &part[i + 1..frac_end];
        i = frac_end;
    }
    if int_digits.is_empty() && frac_digits.is_empty() {
        return Err(match bytes.get(i) {
            None => no_digits(),
            Some(b'.') if i > 0 && bytes[i - 1] == b'.' => unexpected(i),
            Some(b'e' | b'E') => malformed(whole, "no digits before the exponent"),
            Some(_) => unexpected(i),
        });
    }
    let mut exponent = 0;
    if matches!(bytes.get(i), Some(b'e' | b'E')) {
        i += 1;
        let exp_negative = match bytes.get(i) {
            Some(b'-') => {
                i += 1;
                true
            }
            Some(b'+') => {
                i += 1;
                false
            }
            _ => false,
        };
        let exp_end = digits_from(i);
        if exp_end == i {
            return Err(match bytes.get(i) {
                None => malformed(whole, "missing exponent digits"),
                Some(_) => unexpected(i),
            });
        }
        let magnitude = exponent_magnitude(&part[i..exp_end])?;
        // magnitude <= MAX_EXPONENT, which fits an i64.
        exponent = if exp_negative {
            -(magnitude as i64)
        } else {
            magnitude as i64
        };
        i = exp_end;
    }
    if i < bytes.len() {
        return Err(unexpected(i));
    }
    Ok(Lexed {
        negative,
        int_digits,
        frac_digits,
        exponent,
        text: whole,
    })
}

/// The value of an exponent's digit string, refused beyond [`MAX_EXPONENT`] without ever
/// building a large integer.
fn exponent_magnitude(digits: &str) -> Result<u64, ErrorKind> {
    let significant = digits.trim_start_matches('0');
    let too_large = ErrorKind::ExponentTooLarge {
        limit: MAX_EXPONENT,
    };
    if significant.len() > 6 {
        return Err(too_large);
    }
    let value = significant
        .bytes()
        .fold(0u64, |acc, b| acc * 10 + u64::from(b - b'0'));
    if value > MAX_EXPONENT {
        Err(too_large)
    } else {
        Ok(value)
    }
}

/// `10^k`.
fn pow10(k: u64) -> BigInt {
    num_traits::pow(BigInt::from(10u8), k as usize)
}

/// `floor(log10(n / d))` for positive `n`, `d`: an estimate from bit lengths, then exact
/// comparisons with powers of ten (at most a few).
fn floor_log10(n: &BigInt, d: &BigInt) -> i64 {
    const LOG10_2: f64 = std::f64::consts::LOG10_2;
    let bits_diff = n.bits() as f64 - d.bits() as f64;
    let mut e = (bits_diff * LOG10_2).floor() as i64;
    // Compare n/d with 10^e exactly.
    let cmp = |e: i64| {
        if e >= 0 {
            n.cmp(&(d * pow10(e.unsigned_abs())))
        } else {
            (n * pow10(e.unsigned_abs())).cmp(d)
        }
    };
    loop {
        if cmp(e) == Ordering::Less {
            e -= 1;
        } else if cmp(e + 1) != Ordering::Less {
            e += 1;
        } else {
            return e;
        }
    }
}

/// `n / d` rounded to the nearest integer, ties to even (`n >= 0`, `d > 0`).
fn round_half_even(n: &BigInt, d: &BigInt) -> BigInt {
    let (quot, rem) = n.div_rem(d);
    match (rem * 2u8).cmp(d) {
        Ordering::Less => quot,
        Ordering::Greater => quot + 1u8,
        Ordering::Equal if quot.is_odd() => quot + 1u8,
        Ordering::Equal => quot,
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
/// use rodimpact::field::q;
/// use rodimpact::number::decimal;
/// assert_eq!(decimal(&q(-1, 5), 5), "-0.20000");
/// assert_eq!(decimal(&q(1, 8), 2), "0.12");
/// assert_eq!(decimal(&q(123456, 1), 3), "1.23e5");
/// assert_eq!(decimal(&q(1999, 200), 3), "10.0");
/// ```
pub fn decimal(value: &Q, digits: usize) -> String {
    decimal_rounded(value, digits, Rounding::HalfEven)
}

/// How [`decimal_rounded`] rounds to the requested number of significant digits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rounding {
    /// To nearest, ties to even (correct rounding).
    HalfEven,
    /// Toward minus infinity: the printed value is a lower bound.
    Floor,
    /// Toward plus infinity: the printed value is an upper bound.
    Ceiling,
}

/// `value` rounded to `digits` significant digits in the given direction, printed as
/// [`decimal`] prints. `Floor` and `Ceiling` give printed bounds that enclose the exact value.
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::number::{decimal_rounded, Rounding};
/// assert_eq!(decimal_rounded(&q(2, 3), 3, Rounding::Floor), "0.666");
/// assert_eq!(decimal_rounded(&q(2, 3), 3, Rounding::Ceiling), "0.667");
/// assert_eq!(decimal_rounded(&q(-2, 3), 3, Rounding::Floor), "-0.667");
/// assert_eq!(decimal_rounded(&q(1, 2), 3, Rounding::Ceiling), "0.500");
/// ```
pub fn decimal_rounded(value: &Q, digits: usize, rounding: Rounding) -> String {
    if value.is_zero() {
        return "0".to_string();
    }
    let digits = digits.max(1);
    let n = value.numer().abs();
    let d = value.denom();
    let mut exp = floor_log10(&n, d);
    let shift = digits as i64 - 1 - exp;
    let (num, den) = if shift >= 0 {
        (n * pow10(shift.unsigned_abs()), d.clone())
    } else {
        (n, d * pow10(shift.unsigned_abs()))
    };
    let away_from_zero = match rounding {
        Rounding::HalfEven => None,
        Rounding::Floor => Some(value.is_negative()),
        Rounding::Ceiling => Some(value.is_positive()),
    };
    let mut m = match away_from_zero {
        None => round_half_even(&num, &den),
        Some(away) => {
            let (quot, rem) = num.div_rem(&den);
            if away && !rem.is_zero() {
                quot + 1u8
            } else {
                quot
            }
        }
    };
    if m == pow10(digits as u64) {
        // 9.995 -> 10.0: the rounding carried into a new digit.
        m = pow10(digits as u64 - 1);
        exp += 1;
    }
    let s = m.to_string();
    let sign = if value.is_negative() { "-" } else { "" };
    if (-7..digits as i64).contains(&exp) {
        if exp >= 0 {
            let (int, frac) = s.split_at(exp as usize + 1);
            if frac.is_empty() {
                format!("{sign}{int}")
            } else {
                format!("{sign}{int}.{frac}")
            }
        } else {
            let zeros = "0".repeat((-exp - 1) as usize);
            format!("{sign}0.{zeros}{s}")
        }
    } else {
        let (lead, rest) = s.split_at(1);
        if rest.is_empty() {
            format!("{sign}{lead}e{exp}")
        } else {
            format!("{sign}{lead}.{rest}e{exp}")
        }
    }
}

/// A rational printed as [`decimal`] prints it: `digits` significant digits, correctly rounded.
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::number::Decimal;
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
/// use rodimpact::number::sqrt_bounds;
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
        (n * pow10(2 * k.unsigned_abs())) / d
    } else {
        n / (d * pow10(2 * k.unsigned_abs()))
    };
    let m = floor_scaled.sqrt();
    let scale = |v: BigInt| {
        if k >= 0 {
            Q::new(v, pow10(k.unsigned_abs()))
        } else {
            Q::from_integer(v * pow10(k.unsigned_abs()))
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
/// use rodimpact::number::surd;
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
/// use rodimpact::number::decimal_sqrt;
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
/// characters), else the shortest decimal that equals it (`1e400`), else `≈` and its decimal
/// to 6 significant digits. For text reports; JSON keeps the exact value.
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, Q}, number::compact};
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
        .map(|digits| decimal(x, digits))
        .find(|text| parse(text).is_ok_and(|y| y == *x))
        .unwrap_or_else(|| format!("≈ {}", decimal(x, 6)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use proptest::prelude::*;

    fn big(s: &str) -> BigInt {
        s.parse().expect("test literal")
    }

    /// Strings in, exact value out.
    #[test]
    fn parse_accepts() {
        let table = [
            ("2", "2"),
            ("-0.25", "-1/4"),
            ("+3", "3"),
            (".5", "1/2"),
            ("5.", "5"),
            ("3/7", "3/7"),
            ("1.5e-3", "3/2000"),
            ("2E+2", "200"),
            ("75/9.8", "375/49"),
            ("-1/2", "-1/2"),
            ("1e-3/4", "1/4000"),
            ("  0.1\t\n", "1/10"),
            ("-0", "0"),
            ("0/5", "0"),
            ("6/-4", "-3/2"),
            ("-6/-4", "3/2"),
            ("007", "7"),
            ("1e0", "1"),
            ("1e-0", "1"),
            ("1e0010", "10000000000"),
            ("2.50e1", "25"),
            ("1/3e1", "1/30"),
            ("0.000125", "1/8000"),
            (
                "123456789012345678901234567890",
                "123456789012345678901234567890",
            ),
        ];
        for (text, want) in table {
            assert_eq!(
                parse(text).map(|v| v.to_string()),
                Ok(want.to_string()),
                "{text:?}"
            );
        }
        let big_exp = parse("1e10000").expect("limit is inclusive");
        assert_eq!(big_exp.numer(), &pow10(10_000));
        assert_eq!(
            parse("1e-10000").expect("inclusive").denom(),
            &pow10(10_000)
        );
    }

    /// Strings in, error kind (and for malformed input, the reason) out.
    #[test]
    fn parse_rejects() {
        use ErrorKind::*;
        let too_many = TooManyDigits { limit: MAX_DIGITS };
        let exp = ExponentTooLarge {
            limit: MAX_EXPONENT,
        };
        let nf = |s: &str| NotFinite(s.to_string());
        let mal = |s: &str| Malformed(s.to_string());
        let table = [
            ("", Empty),
            ("  \t\n", Empty),
            ("NaN", nf("NaN")),
            ("nan", nf("nan")),
            ("inf", nf("inf")),
            ("-inf", nf("-inf")),
            ("Infinity", nf("Infinity")),
            ("1/inf", nf("1/inf")),
            ("1/0", DivisionByZero),
            ("0/0", DivisionByZero),
            ("3/0.0", DivisionByZero),
            ("3/0e5", DivisionByZero),
            (
                "abc",
                mal("unexpected character 'a' at position 1 in \"abc\""),
            ),
            (
                "1..2",
                mal("unexpected character '.' at position 3 in \"1..2\""),
            ),
            ("1e", mal("missing exponent digits in \"1e\"")),
            ("1e+", mal("missing exponent digits in \"1e+\"")),
            ("e5", mal("no digits before the exponent in \"e5\"")),
            (
                "--1",
                mal("unexpected character '-' at position 2 in \"--1\""),
            ),
            ("1/2/3", mal("more than one '/' in \"1/2/3\"")),
            (
                "0x10",
                mal("unexpected character 'x' at position 2 in \"0x10\""),
            ),
            (
                "1 2",
                mal("unexpected character ' ' at position 2 in \"1 2\""),
            ),
            ("½", mal("unexpected character '½' at position 1 in \"½\"")),
            (
                "3/½",
                mal("unexpected character '½' at position 3 in \"3/½\""),
            ),
            ("-", mal("no digits in \"-\"")),
            (".", mal("no digits in \".\"")),
            ("/2", mal("no digits in the numerator in \"/2\"")),
            ("2/", mal("no digits in the denominator in \"2/\"")),
            (
                "1/ 2",
                mal("unexpected character ' ' at position 3 in \"1/ 2\""),
            ),
            (
                "1e5.5",
                mal("unexpected character '.' at position 4 in \"1e5.5\""),
            ),
            (
                "1,5",
                mal("unexpected character ',' at position 2 in \"1,5\""),
            ),
            (
                "1\n2",
                mal("unexpected character '\\n' at position 2 in \"1\\n2\""),
            ),
            ("1e10001", exp.clone()),
            ("1e-10001", exp.clone()),
            ("1e999999999999999999999", exp.clone()),
            ("1/1e-99999", exp.clone()),
        ];
        for (text, want) in table {
            assert_eq!(parse(text), Err(want), "{text:?}");
        }
        let many = "1".repeat(MAX_DIGITS + 1);
        assert_eq!(parse(&many), Err(too_many.clone()));
        let split = format!("{}/{}", "1".repeat(6_000), "1".repeat(6_000));
        assert_eq!(parse(&split), Err(too_many.clone()));
        assert!(parse(&"7".repeat(MAX_DIGITS)).is_ok());
    }

    #[test]
    fn malformed_messages_are_short_single_lines() {
        let long = format!("x{}", "y\n".repeat(500));
        let Err(ErrorKind::Malformed(msg)) = parse(&long) else {
            panic!("expected malformed");
        };
        assert!(!msg.contains('\n'), "{msg}");
        assert!(msg.len() < 150, "{msg}");
        assert!(
            msg.starts_with("unexpected character 'x' at position 1"),
            "{msg}"
        );
    }

    #[test]
    fn huge_inputs_are_refused_fast() {
        let start = std::time::Instant::now();
        let million = "9".repeat(1_000_000);
        assert_eq!(
            parse(&million),
            Err(ErrorKind::TooManyDigits { limit: MAX_DIGITS })
        );
        let garbage = "x".repeat(1_000_000);
        assert!(matches!(parse(&garbage), Err(ErrorKind::Malformed(_))));
        let exp = format!("1e{}", "9".repeat(5_000));
        assert!(matches!(
            parse(&exp),
            Err(ErrorKind::ExponentTooLarge { .. })
        ));
        let zero_padded_exp = format!("1e{}1", "0".repeat(5_000));
        assert_eq!(parse(&zero_padded_exp), Ok(q(10, 1)));
        assert!(start.elapsed().as_secs_f64() < 2.0);
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
        let tiny = Q::new(BigInt::from(-4), pow10(300));
        assert_eq!(decimal(&tiny, 3), "-4.00e-300");
        let tiny9000 = Q::new(BigInt::one(), pow10(9000));
        let start = std::time::Instant::now();
        assert_eq!(
            decimal(&tiny9000, 30),
            format!("1.{}e-9000", "0".repeat(29))
        );
        let third = Q::new(BigInt::one(), BigInt::from(3) * pow10(9000));
        assert_eq!(decimal(&third, 4), "3.333e-9001");
        let huge = Q::from_integer(BigInt::from(2) * pow10(5000) / 3);
        assert_eq!(decimal(&huge, 4), "6.667e4999");
        assert!(start.elapsed().as_secs_f64() < 1.0);
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
        let scale = Q::from_integer(pow10(2 * digits as u64));
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
        xs.push(Q::from_integer(pow10(301)));
        xs.push(Q::new(BigInt::from(3), pow10(401)));
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
        let (lo, hi) = sqrt_bounds(&Q::from_integer(pow10(301)), 3);
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
        let big_x = Q::from_integer(BigInt::from(2) * pow10(600));
        assert_eq!(decimal_sqrt(&big_x, 5), "1.4142e300");
    }

    /// The exact decimal expansion of `p / (2^k 5^j)`, written positionally.
    fn exact_expansion(p: i64, k: u32, j: u32) -> String {
        let m = k.max(j);
        let n = BigInt::from(p.unsigned_abs())
            * num_traits::pow(BigInt::from(2), (m - k) as usize)
            * num_traits::pow(BigInt::from(5), (m - j) as usize);
        let s = format!("{:0>width$}", n.to_string(), width = m as usize + 1);
        let (int, frac) = s.split_at(s.len() - m as usize);
        let sign = if p < 0 { "-" } else { "" };
        format!("{sign}{int}.{frac}")
    }

    proptest! {
        /// Law: the machine-word forms give the value of the big-integer construction (and
        /// the general parser's: the same text with `.0` after the numerator).
        #[test]
        fn word_sized_forms_parse_exactly(
            sign in "[-+]?",
            n in "[0-9]{1,77}",
            d in proptest::option::of("[0-9]{0,76}[1-9]"),
        ) {
            let text = match &d {
                Some(d) => format!("{sign}{n}/{d}"),
                None => format!("{sign}{n}"),
            };
            let num: BigInt = n.parse().unwrap();
            let den: BigInt = d.as_deref().unwrap_or("1").parse().unwrap();
            let want = Q::new(if sign == "-" { -num } else { num }, den);
            prop_assert_eq!(WordRatio::parse(&text).map(|w| w.value()), Some(want.clone()));
            prop_assert_eq!(WordRatio::parse(&text).and_then(|w| w.equals(&want)), Some(true));
            prop_assert_eq!(parse(&text), Ok(want.clone()));
            let general = text.replacen('/', ".0/", 1) + if d.is_none() { ".0" } else { "" };
            prop_assert_eq!(parse(&general), Ok(want));
        }

        /// `parse` never panics, whatever the input.
        #[test]
        fn parse_never_panics(text in any::<String>()) {
            let _ = parse(&text);
        }

        /// ... including inputs made of the characters a number is built from.
        #[test]
        fn parse_never_panics_on_number_like(text in "[-+0-9eE./ \u{bd}nai]{0,24}") {
            let _ = parse(&text);
        }

        /// A terminating decimal expansion parses back to its exact value, and `decimal` with
        /// enough digits prints a string that parses back to the same value.
        #[test]
        fn terminating_decimals_round_trip(p in -10_000_000_000i64..10_000_000_000, k in 0u32..30, j in 0u32..30) {
            let den = num_traits::pow(BigInt::from(2), k as usize) * num_traits::pow(BigInt::from(5), j as usize);
            let value = Q::new(BigInt::from(p), den);
            prop_assert_eq!(parse(&exact_expansion(p, k, j)), Ok(value.clone()));
            prop_assert_eq!(parse(&decimal(&value, 60)), Ok(value.clone()));
        }

        /// `decimal` agrees with Rust's own correctly rounded float formatting in scientific form.
        #[test]
        fn decimal_matches_float_formatting(x in -1e12f64..1e12, digits in 1usize..17) {
            prop_assume!(x != 0.0);
            let exact = Q::from_float(x).expect("finite");
            let ours = decimal(&exact, digits);
            let theirs = format!("{:.*e}", digits - 1, x);
            prop_assert_eq!(parse(&ours), parse(&theirs));
        }

        /// `sqrt_bounds` encloses the root within the requested relative precision.
        #[test]
        fn sqrt_bounds_enclose(n in 1u64..u64::MAX, d in 1u64..u64::MAX, digits in 0usize..50) {
            check_bounds(&Q::new(BigInt::from(n), BigInt::from(d)), digits);
        }
    }
}
