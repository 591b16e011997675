//! Units on printed values, converted exactly to SI.
//!
//! Every unit is an exact rational multiple of its SI unit except `rpm` (`2 pi / 60` rad/s):
//! values in rpm are compared with exact rational bounds on pi ([`pi_bounds`]).

use crate::error::Error;
use crate::field::Q;
use crate::field::decimal::pow10;
use crate::textbook::sigfig::Printed;
use crate::units::split_unit;
pub use crate::units::{Dimension, Scale, Unit};
use num_bigint::BigInt;

/// A printed value with its optional unit.
///
/// # Examples
/// ```
/// use rodimpact::textbook::units::{Measured, Dimension};
/// let x = Measured::parse("v0", "36 km/h", Dimension::Speed).unwrap();
/// assert_eq!(x.si().unwrap().to_string(), "10");
/// assert_eq!(x.unit.unwrap().name, "km/h");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The number as written, in its own unit.
    pub printed: Printed,
    /// The unit, if one was written (SI otherwise).
    pub unit: Option<Unit>,
}

impl Measured {
    /// Parses `number [unit]` and checks that the unit measures `dimension`.
    ///
    /// # Errors
    /// The number's parse error, an unknown unit, or a unit of another dimension, naming
    /// `field`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::units::{Measured, Dimension};
    /// assert!(Measured::parse("m", "100 g", Dimension::Mass).is_ok());
    /// let err = Measured::parse("m", "2 m/s", Dimension::Mass).unwrap_err();
    /// assert_eq!(err.to_string(), "m: unit 'm/s' is a speed, expected a mass");
    /// ```
    pub fn parse(field: &str, text: &str, dimension: Dimension) -> Result<Measured, Error> {
        let (number, unit) = split_unit(field, text, dimension)?;
        Ok(Measured {
            printed: Printed::parse(field, number)?,
            unit,
        })
    }

    /// The scale of the written unit (1 when none was written).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::units::{Measured, Dimension, Scale};
    /// use rodimpact::field::q;
    /// let x = Measured::parse("a", "5 cm", Dimension::Length).unwrap();
    /// assert_eq!(x.scale(), Scale::Rational(q(1, 100)));
    /// ```
    pub fn scale(&self) -> Scale {
        self.unit
            .as_ref()
            .map_or(Scale::Rational(Q::from_integer(1.into())), Unit::scale)
    }

    /// The exact SI value; `None` for a unit with a factor of pi (rpm).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::units::{Measured, Dimension};
    /// let x = Measured::parse("a", "2.5 mm", Dimension::Length).unwrap();
    /// assert_eq!(x.si().unwrap().to_string(), "1/400");
    /// assert!(Measured::parse("w", "30 rpm", Dimension::AngularSpeed).unwrap().si().is_none());
    /// ```
    pub fn si(&self) -> Option<Q> {
        match self.scale() {
            Scale::Rational(f) => Some(&self.printed.value * f),
            Scale::Pi(_) => None,
        }
    }
}

/// pi to 100 decimals (a fixed constant, used only to bound pi from both sides).
const PI_DIGITS: &str = "31415926535897932384626433832795028841971693993751058209749445923078164062862089986280348253421170679";

/// The most decimals of pi [`pi_bounds`] can give.
pub const PI_MAX_DECIMALS: u32 = 100;

/// Exact rational bounds `lo < pi < hi` with `hi - lo = 10^-decimals` (at most
/// [`PI_MAX_DECIMALS`]).
///
/// # Examples
/// ```
/// use rodimpact::textbook::units::pi_bounds;
/// let (lo, hi) = pi_bounds(4);
/// assert_eq!(lo.to_string(), "6283/2000"); // 3.1415
/// assert_eq!(hi.to_string(), "3927/1250"); // 3.1416
/// ```
pub fn pi_bounds(decimals: u32) -> (Q, Q) {
    let decimals = decimals.min(PI_MAX_DECIMALS);
    let digits = &PI_DIGITS[..=decimals as usize];
    let lo = Q::from_integer(BigInt::parse_bytes(digits.as_bytes(), 10).expect("digits"))
        * pow10(-i64::from(decimals));
    let hi = &lo + pow10(-i64::from(decimals));
    (lo, hi)
}
