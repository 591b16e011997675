//! Units on printed values, converted exactly to SI.
//!
//! Every unit is an exact rational multiple of its SI unit except `rpm` (`2 pi / 60` rad/s):
//! values in rpm are compared with exact rational bounds on pi ([`pi_bounds`]).

use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::textbook::sigfig::{Printed, pow10};
use num_bigint::BigInt;
use std::fmt;

/// What a quantity measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    /// kg.
    Mass,
    /// m.
    Length,
    /// m/s.
    Speed,
    /// rad/s.
    AngularSpeed,
    /// J.
    Energy,
    /// N s = kg m/s.
    Impulse,
    /// A pure number (the coefficient of restitution).
    Pure,
}

impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Dimension::Mass => "a mass",
            Dimension::Length => "a length",
            Dimension::Speed => "a speed",
            Dimension::AngularSpeed => "an angular speed",
            Dimension::Energy => "an energy",
            Dimension::Impulse => "an impulse",
            Dimension::Pure => "a pure number",
        })
    }
}

/// The SI value of one unit: a rational factor, or a rational multiple of pi.
#[derive(Debug, Clone, PartialEq)]
pub enum Scale {
    /// `factor` SI units.
    Rational(Q),
    /// `factor * pi` SI units.
    Pi(Q),
}

/// A unit a printed value may carry.
#[derive(Debug, Clone, PartialEq)]
pub struct Unit {
    /// As written (`km/h`).
    pub name: &'static str,
    /// What it measures.
    pub dimension: Dimension,
    /// Its size in SI units.
    pub scale: Scale,
}

/// The accepted units, longest spelling first so that `cm/s` is not read as `s`.
fn units() -> Vec<Unit> {
    use Dimension::*;
    let r = |n: i64, d: i64| Scale::Rational(Q::new(n.into(), d.into()));
    let u = |name, dimension, scale| Unit {
        name,
        dimension,
        scale,
    };
    vec![
        u("kg*m/s", Impulse, r(1, 1)),
        u("kg m/s", Impulse, r(1, 1)),
        u("rad/s", AngularSpeed, r(1, 1)),
        u("km/h", Speed, r(5, 18)),
        u("cm/s", Speed, r(1, 100)),
        u("m/s", Speed, r(1, 1)),
        u("rpm", AngularSpeed, Scale::Pi(Q::new(1.into(), 30.into()))),
        u("N*s", Impulse, r(1, 1)),
        u("N s", Impulse, r(1, 1)),
        u("kg", Mass, r(1, 1)),
        u("cm", Length, r(1, 100)),
        u("mm", Length, r(1, 1000)),
        u("g", Mass, r(1, 1000)),
        u("m", Length, r(1, 1)),
        u("J", Energy, r(1, 1)),
    ]
}

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
        let text = text.trim();
        let found = units().into_iter().find(|u| {
            text.strip_suffix(u.name).is_some_and(|rest| {
                rest.ends_with(|c: char| c.is_ascii_digit() || c == '.' || c == ' ')
            })
        });
        let (number, unit) = match found {
            Some(u) => (text[..text.len() - u.name.len()].trim_end(), Some(u)),
            None => {
                if let Some((_, tail)) = text.rsplit_once(' ') {
                    return Err(Error::new(
                        field,
                        ErrorKind::Invalid(format!(
                            "unknown unit '{}' (accepted: kg, g, m, cm, mm, m/s, cm/s, km/h, rad/s, rpm, J, N*s)",
                            crate::echo::echo(tail)
                        )),
                    ));
                }
                (text, None)
            }
        };
        if let Some(u) = &unit
            && u.dimension != dimension
        {
            return Err(Error::new(
                field,
                ErrorKind::Invalid(format!(
                    "unit '{}' is {}, expected {dimension}",
                    u.name, u.dimension
                )),
            ));
        }
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
            .map_or(Scale::Rational(Q::from_integer(1.into())), |u| {
                u.scale.clone()
            })
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
