//! Numbers as printed: the significant figures a written value carries, and rounding an exact
//! value to them.
//!
//! Rules (the usual textbook ones): leading zeros never count; every digit after the first
//! nonzero one counts when the number has a decimal point (`2.0` has 2, `0.0500` has 3); in
//! scientific notation only the mantissa counts (`1.50e3` has 3); trailing zeros of an integer
//! without a point are ambiguous (`1500` has 2, 3 or 4), and the most lenient reading, the fewest
//! figures, is used unless `--sig` says otherwise. A fraction (`36/19`) is exact; so is a bare
//! integer zero.

use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::field::decimal::{self, Rounding, magnitude};
use crate::number;
use num_traits::Zero;

/// The most significant figures a claim may carry or `--sig` may ask for.
pub const MAX_SIG: u32 = 1_000;

/// How precise a printed number is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Precision {
    /// Exact: a fraction such as `36/19`, or the integer `0`.
    Exact,
    /// A nonzero decimal with `figures` significant figures; `ambiguous` is the range of
    /// readings of an integer with trailing zeros (`1500`: `Some((2, 4))`).
    Figures {
        /// The figures used for the verdict.
        figures: u32,
        /// The possible readings when the written form does not decide them.
        ambiguous: Option<(u32, u32)>,
    },
    /// A written zero with decimals (`0.00`): the exact value must round to zero at
    /// `10^place`.
    ZeroAt {
        /// The decimal exponent of the last written digit (`0.00`: -2).
        place: i64,
    },
}

/// A number exactly as printed: its value and its precision.
///
/// # Examples
/// ```
/// use rodimpact::textbook::sigfig::{Printed, Precision};
/// let p = Printed::parse("x", "0.0500").unwrap();
/// assert_eq!(p.precision, Precision::Figures { figures: 3, ambiguous: None });
/// assert_eq!(p.value.to_string(), "1/20");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Printed {
    /// The exact value of the written digits.
    pub value: Q,
    /// Significant figures, or exact.
    pub precision: Precision,
}

impl Printed {
    /// Parses a written number (no unit) and infers its precision.
    ///
    /// # Errors
    /// The number's own parse error, naming `field`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::sigfig::{Printed, Precision};
    /// let fig = |s| Printed::parse("v", s).unwrap().precision;
    /// assert_eq!(fig("2.0"), Precision::Figures { figures: 2, ambiguous: None });
    /// assert_eq!(fig("1.50e3"), Precision::Figures { figures: 3, ambiguous: None });
    /// assert_eq!(fig("1500"), Precision::Figures { figures: 2, ambiguous: Some((2, 4)) });
    /// assert_eq!(fig("36/19"), Precision::Exact);
    /// ```
    pub fn parse(field: &str, text: &str) -> Result<Printed, Error> {
        let value = number::parse(text).map_err(|kind| Error::new(field, kind))?;
        let text = text.trim();
        let precision = if text.contains('/') {
            Precision::Exact
        } else {
            infer(text, &value)
        };
        Ok(Printed { value, precision })
    }

    /// The same number read with `figures` significant figures (`--sig`); exact numbers and
    /// zeros keep their own precision.
    ///
    /// # Errors
    /// `sig` out of range (1 to [`MAX_SIG`]).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::sigfig::{Printed, Precision};
    /// let p = Printed::parse("v", "1500").unwrap().with_sig(4).unwrap();
    /// assert_eq!(p.precision, Precision::Figures { figures: 4, ambiguous: None });
    /// ```
    pub fn with_sig(mut self, figures: u32) -> Result<Printed, Error> {
        check_sig(figures)?;
        if let Precision::Figures { .. } = self.precision {
            self.precision = Precision::Figures {
                figures,
                ambiguous: None,
            };
        }
        Ok(self)
    }

    /// The decimal exponent of the last significant digit (`2.0`: -1, `1500` read with 2
    /// figures: 2); `None` for exact numbers.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::sigfig::Printed;
    /// assert_eq!(Printed::parse("v", "2.0").unwrap().place(), Some(-1));
    /// assert_eq!(Printed::parse("v", "1500").unwrap().place(), Some(2));
    /// ```
    pub fn place(&self) -> Option<i64> {
        match &self.precision {
            Precision::Exact => None,
            Precision::ZeroAt { place } => Some(*place),
            Precision::Figures { figures, .. } => {
                Some(magnitude(&self.value) - i64::from(*figures) + 1)
            }
        }
    }
}

/// Checks a `--sig` / `sig =` value.
///
/// # Errors
/// `sig: must be a whole number from 1 to 1000`.
///
/// # Examples
/// ```
/// use rodimpact::textbook::sigfig::check_sig;
/// assert!(check_sig(3).is_ok());
/// assert!(check_sig(0).is_err());
/// ```
pub fn check_sig(figures: u32) -> Result<(), Error> {
    if (1..=MAX_SIG).contains(&figures) {
        Ok(())
    } else {
        Err(Error::new(
            "sig",
            ErrorKind::OutOfRange(format!(
                "must be a whole number from 1 to {MAX_SIG}, got {figures}"
            )),
        ))
    }
}

fn infer(text: &str, value: &Q) -> Precision {
    let unsigned = text.trim_start_matches(['+', '-']);
    let (mantissa, scientific) = match unsigned.find(['e', 'E']) {
        Some(i) => (&unsigned[..i], true),
        None => (unsigned, false),
    };
    let exponent: i64 = unsigned
        .find(['e', 'E'])
        .and_then(|i| unsigned[i + 1..].parse().ok())
        .unwrap_or(0);
    let has_point = mantissa.contains('.');
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let significant = digits.trim_start_matches('0');
    if value.is_zero() {
        let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i64;
        return if has_point || scientific {
            Precision::ZeroAt {
                place: exponent - decimals,
            }
        } else {
            Precision::Exact
        };
    }
    let all = significant.len() as u32;
    if has_point || (scientific && !significant.ends_with('0')) {
        return Precision::Figures {
            figures: all.min(MAX_SIG),
            ambiguous: None,
        };
    }
    let fewest = significant.trim_end_matches('0').len() as u32;
    Precision::Figures {
        figures: fewest.min(MAX_SIG),
        ambiguous: (fewest < all).then_some((fewest, all)),
    }
}

/// Which way an exact half rounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tie {
    /// Away from zero (the schoolbook rule).
    Up,
    /// Toward zero.
    Down,
}

impl Tie {
    /// The rounding of [`crate::field::decimal`] this tie rule is.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::decimal::Rounding, textbook::sigfig::Tie};
    /// assert_eq!(Tie::Up.rounding(), Rounding::HalfAwayFromZero);
    /// ```
    pub fn rounding(self) -> Rounding {
        match self {
            Tie::Up => Rounding::HalfAwayFromZero,
            Tie::Down => Rounding::HalfTowardZero,
        }
    }
}

/// `x` rounded to a multiple of `10^place` ([`decimal::round_at`] with the tie rule).
///
/// # Examples
/// ```
/// use rodimpact::textbook::sigfig::{round_at, Tie};
/// use rodimpact::field::q;
/// assert_eq!(round_at(&q(9, 4), -1, Tie::Up), q(23, 10));
/// assert_eq!(round_at(&q(9, 4), -1, Tie::Down), q(22, 10));
/// assert_eq!(round_at(&q(-36, 19), -2, Tie::Up), q(-189, 100));
/// ```
pub fn round_at(x: &Q, place: i64, tie: Tie) -> Q {
    decimal::round_at(x, place, tie.rounding())
}

/// `x` rounded to `figures` significant figures.
///
/// # Examples
/// ```
/// use rodimpact::textbook::sigfig::{round_sig, Tie};
/// use rodimpact::field::q;
/// assert_eq!(round_sig(&q(36, 19), 3, Tie::Up), q(189, 100));
/// assert_eq!(round_sig(&q(9996, 1000), 3, Tie::Up), q(10, 1));
/// ```
pub fn round_sig(x: &Q, figures: u32, tie: Tie) -> Q {
    if x.is_zero() {
        return Q::zero();
    }
    round_at(x, magnitude(x) - i64::from(figures) + 1, tie)
}
