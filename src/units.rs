//! Units on input numbers, converted exactly to SI.
//!
//! Every command reads scene numbers through [`parse_si`]: a plain number is taken as it is
//! (in SI: kg, m, m/s), and a number followed by a unit (`100 g`, `120cm`, `36 km/h`) is
//! converted exactly. Every unit here is an exact rational multiple of its SI unit, except
//! `rpm` (`pi/30` rad/s), which only claims may carry (`textbook::units` bounds pi).

use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::number;
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
    /// kg m^2.
    MomentOfInertia,
    /// A pure number (the coefficient of restitution).
    Pure,
}

impl Dimension {
    /// The SI unit as printed after a value (`m/s`); empty for a pure number.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::units::Dimension;
    /// assert_eq!(Dimension::AngularSpeed.si_unit(), "rad/s");
    /// assert_eq!(Dimension::Pure.si_unit(), "");
    /// ```
    pub fn si_unit(self) -> &'static str {
        match self {
            Dimension::Mass => "kg",
            Dimension::Length => "m",
            Dimension::Speed => "m/s",
            Dimension::AngularSpeed => "rad/s",
            Dimension::Energy => "J",
            Dimension::Impulse => "N s",
            Dimension::MomentOfInertia => "kg m^2",
            Dimension::Pure => "",
        }
    }

    /// The units a value of this dimension may carry, for messages (`kg, g`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::units::Dimension;
    /// assert_eq!(Dimension::Mass.accepted(), "kg, lb, g");
    /// assert_eq!(Dimension::Pure.accepted(), "none");
    /// ```
    pub fn accepted(self) -> String {
        let names: Vec<&str> = UNITS
            .iter()
            .filter(|u| u.dimension == self)
            .map(|u| u.name)
            .collect();
        if names.is_empty() {
            "none".into()
        } else {
            names.join(", ")
        }
    }
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
            Dimension::MomentOfInertia => "a moment of inertia",
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

/// A unit a value may carry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// As written (`km/h`).
    pub name: &'static str,
    /// What it measures.
    pub dimension: Dimension,
    /// Its size in SI units, as `numerator / denominator`.
    factor: (u32, u32),
    /// Whether the size carries a factor of pi (rpm).
    times_pi: bool,
}

impl Unit {
    /// Its size in SI units.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::units::{find_unit, Scale};
    /// use rodimpact::field::q;
    /// assert_eq!(find_unit("km/h").unwrap().scale(), Scale::Rational(q(5, 18)));
    /// assert_eq!(find_unit("rpm").unwrap().scale(), Scale::Pi(q(1, 30)));
    /// ```
    pub fn scale(&self) -> Scale {
        let f = Q::new(self.factor.0.into(), self.factor.1.into());
        if self.times_pi {
            Scale::Pi(f)
        } else {
            Scale::Rational(f)
        }
    }
}

const fn unit(name: &'static str, dimension: Dimension, num: u32, den: u32) -> Unit {
    Unit {
        name,
        dimension,
        factor: (num, den),
        times_pi: false,
    }
}

/// An angular unit whose size in rad/s is `num/den` times pi.
const fn angular(name: &'static str, num: u32, den: u32) -> Unit {
    Unit {
        name,
        dimension: Dimension::AngularSpeed,
        factor: (num, den),
        times_pi: true,
    }
}

/// The accepted units, longest spelling first so that `cm/s` is not read as `s`. The
/// imperial ones are exact by definition (1 lb = 0.45359237 kg, 1 ft = 0.3048 m, 1 mph =
/// 0.44704 m/s).
const UNITS: [Unit; 25] = [
    unit("kg*m^2", Dimension::MomentOfInertia, 1, 1),
    unit("kg m^2", Dimension::MomentOfInertia, 1, 1),
    unit("kg*m/s", Dimension::Impulse, 1, 1),
    unit("kg m/s", Dimension::Impulse, 1, 1),
    unit("rad/s", Dimension::AngularSpeed, 1, 1),
    angular("deg/s", 1, 180),
    angular("rev/s", 2, 1),
    unit("km/h", Dimension::Speed, 5, 18),
    unit("cm/s", Dimension::Speed, 1, 100),
    unit("ft/s", Dimension::Speed, 381, 1250),
    unit("m/s", Dimension::Speed, 1, 1),
    unit("mph", Dimension::Speed, 1397, 3125),
    angular("rpm", 1, 30),
    unit("N*s", Dimension::Impulse, 1, 1),
    unit("N s", Dimension::Impulse, 1, 1),
    unit("kg", Dimension::Mass, 1, 1),
    unit("kJ", Dimension::Energy, 1000, 1),
    unit("lb", Dimension::Mass, 45_359_237, 100_000_000),
    unit("cm", Dimension::Length, 1, 100),
    unit("mm", Dimension::Length, 1, 1000),
    unit("ft", Dimension::Length, 381, 1250),
    unit("g", Dimension::Mass, 1, 1000),
    unit("m", Dimension::Length, 1, 1),
    unit("J", Dimension::Energy, 1, 1),
    // Written after a space only (`1.2 1/s`): `11/s` is no number with a unit.
    unit("1/s", Dimension::AngularSpeed, 1, 1),
];

/// The unit spelled `name`, if it is one.
///
/// # Examples
/// ```
/// use rodimpact::units::{find_unit, Dimension};
/// assert_eq!(find_unit("cm/s").unwrap().dimension, Dimension::Speed);
/// assert!(find_unit("furlong").is_none());
/// ```
pub fn find_unit(name: &str) -> Option<Unit> {
    UNITS.iter().find(|u| u.name == name).copied()
}

/// Splits `number [unit]` into the number's text and its unit, checking that the unit
/// measures `dimension`. Text without a known unit comes back whole (with `None`), for the
/// number parser to judge; a space followed by an unknown word is an unknown unit.
///
/// # Errors
/// An unknown unit, or a unit of another dimension, naming `field`.
///
/// # Examples
/// ```
/// use rodimpact::units::{split_unit, Dimension};
/// let (number, unit) = split_unit("m", "100 g", Dimension::Mass).unwrap();
/// assert_eq!((number, unit.unwrap().name), ("100", "g"));
/// assert_eq!(split_unit("a", "1/2", Dimension::Length).unwrap(), ("1/2", None));
/// assert_eq!(split_unit("m", "2 m/s", Dimension::Mass).unwrap_err().to_string(),
///     "m: unit 'm/s' is a speed, expected a mass");
/// ```
pub fn split_unit<'t>(
    field: &str,
    text: &'t str,
    dimension: Dimension,
) -> Result<(&'t str, Option<Unit>), Error> {
    let text = text.trim();
    let found = UNITS.iter().find(|u| {
        text.strip_suffix(u.name).is_some_and(|rest| {
            let joined = !u.name.starts_with(|c: char| c.is_ascii_digit());
            rest.ends_with(|c: char| (joined && (c.is_ascii_digit() || c == '.')) || c == ' ')
        })
    });
    let Some(u) = found else {
        // `2 oz`, or `2oz` written against the number: the word after the number.
        let unit_chars = |c: char| c.is_alphabetic() || "/^*".contains(c);
        let joined_tail = text
            .find(|c: char| c.is_alphabetic())
            .filter(|&k| k > 0)
            .map(|k| text.split_at(k))
            .filter(|(number, tail)| {
                tail.chars().all(unit_chars)
                    && !tail.starts_with(['e', 'E'])
                    && number::parse(number).is_ok()
            })
            .map(|(_, tail)| tail);
        let spaced_tail = text
            .rsplit_once(' ')
            .map(|(_, tail)| tail)
            .filter(|tail| tail.starts_with(|c: char| c.is_alphabetic()));
        if let Some(tail) = spaced_tail.or(joined_tail) {
            return Err(Error::new(
                field,
                ErrorKind::Invalid(format!(
                    "unknown unit '{}' ({} takes {})",
                    crate::echo::echo(tail),
                    dimension,
                    dimension.accepted()
                )),
            ));
        }
        return Ok((text, None));
    };
    if u.dimension != dimension {
        return Err(Error::new(
            field,
            ErrorKind::Invalid(format!(
                "unit '{}' is {}, expected {dimension}",
                u.name, u.dimension
            )),
        ));
    }
    Ok((text[..text.len() - u.name.len()].trim_end(), Some(*u)))
}

/// An exact number with an optional unit, in SI: `"100 g"` is `1/10` (kg). A plain number is
/// read as it is (already in SI), without looking for a unit.
///
/// # Errors
/// The number's own error, an unknown unit, a unit of another dimension, or rpm (not a
/// rational multiple of rad/s), naming `field`.
///
/// # Examples
/// ```
/// use rodimpact::units::{parse_si, Dimension};
/// use rodimpact::field::q;
/// assert_eq!(parse_si("v0", "36 km/h", Dimension::Speed).unwrap(), q(10, 1));
/// assert_eq!(parse_si("a", "120cm", Dimension::Length).unwrap(), q(6, 5));
/// assert_eq!(parse_si("m", "0.25", Dimension::Mass).unwrap(), q(1, 4));
/// assert_eq!(parse_si("e", "1 kg", Dimension::Pure).unwrap_err().to_string(),
///     "e: unit 'kg' is a mass, expected a pure number");
/// ```
pub fn parse_si(field: &str, text: &str, dimension: Dimension) -> Result<Q, Error> {
    let plain = match number::parse(text) {
        Ok(x) => return Ok(x),
        Err(kind) => Error::new(field, kind),
    };
    let (digits, unit) = split_unit(field, text, dimension)?;
    let Some(unit) = unit else {
        return Err(plain);
    };
    let value = number::parse(digits).map_err(|kind| Error::new(field, kind))?;
    match unit.scale() {
        Scale::Rational(f) => Ok(value * f),
        Scale::Pi(_) => Err(Error::new(
            field,
            ErrorKind::Invalid(format!(
                "{} is not a rational multiple of {}: give it in {}",
                unit.name,
                dimension.si_unit(),
                dimension.si_unit()
            )),
        )),
    }
}
