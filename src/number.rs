//! Exact numbers in: parsing.
//!
//! Every number enters the library through [`parse`], which builds the exact rational from the
//! digit string and the decimal exponent with big integers (never through a float), after an
//! O(n) scan that enforces the resource limits [`MAX_DIGITS`] and [`MAX_EXPONENT`]. Printing
//! them is [`crate::field::decimal`]'s job.

use crate::echo::echo;
use crate::error::ErrorKind;
use crate::field::Q;
use crate::field::decimal::ten_to;
use crate::field::int::{POWERS_OF_TEN, U256, reduce};
use num_bigint::BigInt;
use num_traits::Zero;

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
    match WordRatio::parse(text) {
        Some(word) => Ok(word.value()),
        None => parse_general(text),
    }
}

/// [`parse`] without its machine-word shortcut: every form, in big integers (`text` trimmed,
/// not empty).
fn parse_general(text: &str) -> Result<Q, ErrorKind> {
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
                Ok(reduce(p, q))
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
        WordRatio::parse_bytes(text.as_bytes())
    }

    /// [`WordRatio::parse`] of a cell's bytes, as a row reads them (no UTF-8 check: anything
    /// but ASCII digits, signs, `/`, `.` and `e` is refused).
    pub(crate) fn parse_bytes(text: &[u8]) -> Option<WordRatio> {
        let scaled = ScaledRatio::parse(text)?;
        Some(WordRatio {
            negative: scaled.negative,
            numer: scaled.numer,
            denom: scaled.denominator()?,
        })
    }

    /// `digits[.digits][(e|E)[+-]digits]` (at least one mantissa digit, at most 77 in all, an
    /// exponent of at most 3 digits) as `mantissa/10^k` or `mantissa 10^k/1`, both below
    /// 2^256: `0.05` is 5/100, unreduced (an engine's 17-digit cells are compared on words).
    pub(crate) fn decimal(text: &[u8]) -> Option<(U256, U256)> {
        let (mantissa, shift) = decimal_parts(text)?;
        let power = U256::pow10(u32::try_from(shift.unsigned_abs()).ok()?)?;
        if shift >= 0 {
            Some((mantissa.checked_mul_wide(power)?, U256::ONE))
        } else {
            Some((mantissa, power))
        }
    }

    /// Sign, numerator and denominator as written (not reduced; the denominator nonzero).
    pub(crate) fn parts(&self) -> (bool, U256, U256) {
        (self.negative, self.numer, self.denom)
    }

    /// The value, reduced (one GCD on machine words).
    pub(crate) fn value(&self) -> Q {
        U256::ratio(self.negative, self.numer, self.denom)
    }

    /// Whether the value equals `q`, decided by cross-multiplication on machine words without
    /// reducing; `None` when `q`'s numerator or denominator exceeds 256 bits.
    pub(crate) fn equals(&self, q: &Q) -> Option<bool> {
        let (negative, n, d) = U256::parts_of(q)?;
        if self.numer == U256::ZERO || n == U256::ZERO {
            return Some(self.numer == n);
        }
        let same_sign = self.negative == negative;
        Some(same_sign && U256::cross_equal(self.numer, d, n, self.denom))
    }
}

/// A cell on machine words with its power of ten apart: the value is
/// `numer / (denom 10^tens)`, unreduced, with `denom > 0`. A fraction has `tens = 0`; a decimal
/// whose point or negative exponent moves its digits is its digits over `10^tens` (`denom = 1`),
/// with `tens` up to 1,076, past what 256 bits hold: an engine's `5.0579153677743847e-107`
/// for a zero is `50579153677743847 / 10^123`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ScaledRatio {
    /// The sign (a zero may carry either).
    pub(crate) negative: bool,
    /// The numerator as written (a decimal's digits).
    pub(crate) numer: U256,
    /// The denominator as written (1 for a decimal).
    pub(crate) denom: U256,
    /// The power of ten the denominator is multiplied by.
    pub(crate) tens: u32,
}

impl ScaledRatio {
    /// A cell's bytes (already trimmed) as a fraction of words, integers or a decimal (see
    /// [`WordRatio::decimal`] for the forms taken); `None` for anything else and for a zero
    /// denominator.
    pub(crate) fn parse(text: &[u8]) -> Option<ScaledRatio> {
        let (negative, unsigned) = match text.first()? {
            b'-' => (true, &text[1..]),
            b'+' => (false, &text[1..]),
            _ => (false, text),
        };
        // A fraction has a '/' (memchr's search: a fraction's cell runs to 70 bytes), anything
        // else is read as a decimal, digits alone too; a parse as digits first, failing at a
        // decimal's '.', cost an engine's row 100 instructions a claim. (78 digits are past a
        // decimal's 77 and may still be below 2^256 with leading zeros.)
        let (numer, denom, tens) = match memchr::memchr(b'/', unsigned) {
            Some(at) => (
                U256::parse_decimal(&unsigned[..at])?,
                U256::parse_decimal(&unsigned[at + 1..])?,
                0,
            ),
            None => match decimal_parts(unsigned) {
                Some((mantissa, shift)) => match u32::try_from(shift) {
                    Ok(up) => (mantissa.checked_mul_wide(U256::pow10(up)?)?, U256::ONE, 0),
                    Err(_) => (mantissa, U256::ONE, shift.unsigned_abs() as u32),
                },
                None => (U256::parse_decimal(unsigned)?, U256::ONE, 0),
            },
        };
        (denom != U256::ZERO).then_some(ScaledRatio {
            negative,
            numer,
            denom,
            tens,
        })
    }

    /// The denominator with its power of ten multiplied in, if that fits 256 bits.
    pub(crate) fn denominator(&self) -> Option<U256> {
        match self.tens {
            0 => Some(self.denom),
            // Only a decimal has a power of ten, over a denominator of 1.
            k => U256::pow10(k),
        }
    }
}

/// A decimal (see [`WordRatio::decimal`]) as its digits below 2^256 and the power of ten they
/// are multiplied by: `0.05` is `(5, -2)`, `1.5e3` is `(15, 2)`.
fn decimal_parts(text: &[u8]) -> Option<(U256, i64)> {
    // One pass: the mantissa's digits (accumulated while they fit 38: the first 19 in a u64,
    // whose products are one instruction, the rest in a u128), the fraction's length, then the
    // exponent.
    let (mut at, mut count, mut places) = (0, 0usize, 0i64);
    let (mut head, mut tail, mut tail_digits) = (0u64, 0u128, 0usize);
    let mut digit = |b: u8, count: &mut usize| {
        let d = b - b'0';
        if *count < 19 {
            head = head * 10 + u64::from(d);
        } else if *count < 38 {
            tail = tail * 10 + u128::from(d);
            tail_digits += 1;
        }
        *count += 1;
    };
    while let Some(&b) = text.get(at).filter(|b| b.is_ascii_digit()) {
        digit(b, &mut count);
        at += 1;
    }
    if text.get(at) == Some(&b'.') {
        at += 1;
        while let Some(&b) = text.get(at).filter(|b| b.is_ascii_digit()) {
            digit(b, &mut count);
            places += 1;
            at += 1;
        }
    }
    let exponent: i64 = match &text[at..] {
        [] => 0,
        [b'e' | b'E', tail @ ..] => {
            let (negative, digits) = match tail {
                [b'-', rest @ ..] => (true, rest),
                [b'+', rest @ ..] => (false, rest),
                _ => (false, tail),
            };
            if digits.is_empty() || digits.len() > 3 || !digits.iter().all(u8::is_ascii_digit) {
                return None;
            }
            let magnitude = digits
                .iter()
                .fold(0i64, |n, b| n * 10 + i64::from(b - b'0'));
            if negative { -magnitude } else { magnitude }
        }
        _ => return None,
    };
    let mantissa = match count {
        0 => return None,
        1..=38 => U256 {
            hi: 0,
            lo: u128::from(head) * u128::from(POWERS_OF_TEN[tail_digits]) + tail,
        },
        39..=77 => {
            let digits: Vec<u8> = text[..at]
                .iter()
                .copied()
                .filter(u8::is_ascii_digit)
                .collect();
            U256::parse_decimal(&digits)?
        }
        _ => return None,
    };
    Some((mantissa, exponent - places))
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
            Q::from_integer(mantissa * ten_to(shift.unsigned_abs()))
        } else {
            over_power_of_ten(mantissa, shift.unsigned_abs())
        })
    }
}

/// `mantissa / 10^k` in lowest terms without a GCD: the only common factors are 2s and 5s, so
/// they are counted and divided out (num-bigint's binary GCD on a 300-digit power of ten was
/// most of the cost of reading an engine's `2.3e-91`).
fn over_power_of_ten(mantissa: BigInt, k: u64) -> Q {
    if mantissa.is_zero() {
        return Q::zero();
    }
    let twos = mantissa.trailing_zeros().unwrap_or(0).min(k);
    let mut m = mantissa >> twos;
    let mut fives = 0;
    // Five at a time in chunks of 5^13 (below 2^32), then one by one.
    for (chunk, count) in [(1_220_703_125u32, 13), (5, 1)] {
        while fives + count <= k && (&m % chunk).is_zero() {
            m /= chunk;
            fives += count;
        }
    }
    let denominator = (BigInt::from(1) << (k - twos))
        * BigInt::from(5).pow(
            u32::try_from(k - fives).expect("an exponent is at most MAX_EXPONENT + MAX_DIGITS"),
        );
    Q::new_raw(m, denominator)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scaled_ratio_keeps_a_decimals_power_of_ten_apart() {
        let parts = |text: &str| {
            ScaledRatio::parse(text.as_bytes()).map(|s| (s.negative, s.numer, s.denom, s.tens))
        };
        let word = |x: u128| U256 { hi: 0, lo: x };
        assert_eq!(parts("-2.5e-3"), Some((true, word(25), U256::ONE, 4)));
        assert_eq!(parts("1.5e3"), Some((false, word(1500), U256::ONE, 0)));
        assert_eq!(parts("+3/7"), Some((false, word(3), word(7), 0)));
        assert_eq!(parts("12"), Some((false, word(12), U256::ONE, 0)));
        // Rapier's V at a centre pivot: 10^123 is past 256 bits.
        assert_eq!(
            parts("5.0579153677743847e-107"),
            Some((false, word(50579153677743847), U256::ONE, 123))
        );
        assert_eq!(parts("1/0"), None);
        assert_eq!(parts("1.5e1000"), None);
        assert_eq!(parts("nan"), None);
        // A fraction's parts are digits alone, and a decimal has no '/'.
        for refused in [
            "", "-", "/3", "3/", "1.5/2", "3/1.5", "3//4", "1e", ".", "1.2.3", "12a",
        ] {
            assert_eq!(parts(refused), None, "{refused}");
        }
        assert_eq!(parts(".5"), Some((false, word(5), U256::ONE, 1)));
        assert_eq!(parts("7e2"), Some((false, word(700), U256::ONE, 0)));
        // 78 digits: past 2^256 as digits alone, and past a decimal's 77; below with a
        // leading zero.
        assert_eq!(parts(&"9".repeat(78)), None);
        assert_eq!(
            parts(&format!("0{}", "9".repeat(77))),
            parts(&"9".repeat(77))
        );
        assert_eq!(
            parts(&"9".repeat(77)),
            U256::parse_decimal("9".repeat(77).as_bytes()).map(|n| (false, n, U256::ONE, 0))
        );
        // The word ratio folds the power in, where it fits.
        assert_eq!(
            WordRatio::parse("0.05").map(|w| w.parts()),
            Some((false, word(5), word(100)))
        );
        assert!(WordRatio::parse("5.0579153677743847e-107").is_none());
    }
    use crate::field::decimal::decimal;
    use crate::field::q;
    use proptest::prelude::*;

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
        assert_eq!(big_exp.numer(), &ten_to(10_000));
        assert_eq!(
            parse("1e-10000").expect("inclusive").denom(),
            &ten_to(10_000)
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

    /// Refused by their length before any arithmetic (that this is quick is bounded by CPU time in
    /// `crates/rodimpact-cli/tests/cli/bad_input.rs`, never by a clock here).
    #[test]
    fn huge_inputs_are_refused() {
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

        /// Law: a decimal read on machine words (`0.05` as 5/100) has the general parser's
        /// value, and every form of the general grammar the words leave alone still parses.
        #[test]
        fn decimals_on_words_are_the_general_values(
            sign in "[-+]?",
            whole in "[0-9]{0,40}",
            point in proptest::bool::ANY,
            fraction in "[0-9]{0,40}",
            exponent in proptest::option::of(("[eE]", "[-+]?", "[0-9]{1,4}")),
        ) {
            let mut text = format!("{sign}{whole}");
            if point {
                text.push('.');
                text.push_str(&fraction);
            }
            if let Some((e, s, digits)) = &exponent {
                text.push_str(&format!("{e}{s}{digits}"));
            }
            let general = parse_general(&text);
            match WordRatio::parse(&text) {
                Some(word) => {
                    prop_assert_eq!(Ok(word.value()), general.clone());
                    prop_assert_eq!(word.equals(general.as_ref().unwrap()), Some(true));
                }
                // Too long or too large for words, or not a number at all.
                None => prop_assert!(
                    general.is_err() || whole.len() + fraction.len() > 38
                        || exponent.is_some(),
                    "{text}: {general:?}"
                ),
            }
        }

        /// Law: a mantissa over a power of ten is reduced as `Q::new` reduces it.
        #[test]
        fn a_mantissa_over_a_power_of_ten_is_in_lowest_terms(
            m in proptest::prelude::any::<i64>(), twos in 0u32..40, fives in 0u32..30, k in 0u64..60,
        ) {
            let mantissa = BigInt::from(m) * (BigInt::from(1) << twos) * BigInt::from(5).pow(fives);
            let got = over_power_of_ten(mantissa.clone(), k);
            let want = Q::new(mantissa, ten_to(k));
            prop_assert_eq!((got.numer(), got.denom()), (want.numer(), want.denom()));
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

        /// Law: `compact` (which decides exactness from the rounding remainder) prints the first
        /// of `decimal(x, 1..=15)` that parses back to `x`, as it was first defined.
        #[test]
        fn compact_prints_the_first_decimal_that_parses_back(n in -10i64.pow(9)..10i64.pow(9), d in prop::sample::select(vec![1i64, 3, 7, 8]), k in 0u64..70, tiny in any::<bool>()) {
            prop_assume!(n != 0);
            let scale = Q::from_integer(ten_to(k));
            let x = if tiny { q(n, d) / scale } else { q(n, d) * scale };
            let by_parsing = if x.to_string().chars().count() <= crate::field::decimal::COMPACT_CHARS {
                x.to_string()
            } else {
                (1..=15)
                    .map(|digits| decimal(&x, digits))
                    .find(|text| parse(text).is_ok_and(|y| y == x))
                    .unwrap_or_else(|| format!("≈ {}", decimal(&x, 6)))
            };
            prop_assert_eq!(crate::field::decimal::compact(&x), by_parsing);
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
    }
}
