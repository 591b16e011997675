//! A claimed answer (`omega=1.89 rad/s`, `V=2*m*v0/(M+4*m)`): the quantity it is about and its
//! value, a printed number with its unit or a formula.

use super::expr::{self, Budget, Radical};
use super::quantity::Quantity;
use super::units::{Dimension, Measured};
use crate::error::{Error, ErrorKind};

/// What a claim says: a printed number (with its unit) or a formula.
#[derive(Debug, Clone, PartialEq)]
pub enum ClaimedValue {
    /// A number as printed, judged by its significant figures.
    Printed(Measured),
    /// An exact formula, possibly in the scene's symbols.
    Formula(Radical),
}

/// One claimed answer.
///
/// # Examples
/// ```
/// use rodimpact::textbook::{ClaimedAnswer, ClaimedValue, Quantity};
/// let c = ClaimedAnswer::parse("omega = 1.89 rad/s").unwrap();
/// assert_eq!(c.quantity, Quantity::Omega);
/// assert!(matches!(c.value, ClaimedValue::Printed(_)));
/// assert!(ClaimedAnswer::parse("omega=2*m").unwrap().is_symbolic());
/// assert!(ClaimedAnswer::parse("omegaa=2").is_err());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimedAnswer {
    /// What is claimed.
    pub quantity: Quantity,
    /// The value as written.
    pub text: String,
    /// The parsed value.
    pub value: ClaimedValue,
}

impl ClaimedAnswer {
    /// Parses `NAME=VALUE`.
    ///
    /// # Errors
    /// `claim: ...` for a missing `=` or an unknown name, or the value's own error.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::ClaimedAnswer;
    /// assert_eq!(ClaimedAnswer::parse("v=2.3 m/s").unwrap().text, "2.3 m/s");
    /// assert_eq!(ClaimedAnswer::parse("v").unwrap_err().to_string(), "claim: expected NAME=VALUE, got 'v'");
    /// ```
    pub fn parse(spec: &str) -> Result<ClaimedAnswer, Error> {
        ClaimedAnswer::parse_within(spec, &mut Budget::new(expr::MAX_WORK))
    }

    /// [`ClaimedAnswer::parse`], charging a formula's work to a run's `budget`.
    ///
    /// # Errors
    /// Those of [`ClaimedAnswer::parse`], and an exhausted budget.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{ClaimedAnswer, expr::Budget};
    /// let mut budget = Budget::run();
    /// assert!(ClaimedAnswer::parse_within("v=m/(m+M)", &mut budget).unwrap().is_symbolic());
    /// assert!(budget.spent() > 0);
    /// ```
    pub fn parse_within(spec: &str, budget: &mut Budget) -> Result<ClaimedAnswer, Error> {
        let Some((name, value)) = spec.split_once('=') else {
            return Err(Error::new(
                "claim",
                ErrorKind::Invalid(format!(
                    "expected NAME=VALUE, got '{}'",
                    crate::echo::echo(spec)
                )),
            ));
        };
        ClaimedAnswer::new_within(name.trim(), value, budget)
    }

    /// A claim from its name and value text.
    ///
    /// # Errors
    /// An unknown name (listing the accepted ones) or a value that is neither a printed number
    /// nor a formula.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::ClaimedAnswer;
    /// assert!(ClaimedAnswer::new("V", "1.3 m/s").is_ok());
    /// assert_eq!(ClaimedAnswer::new("V", "1.3 J").unwrap_err().to_string(),
    ///     "claim V: unit 'J' is an energy, expected a speed");
    /// ```
    pub fn new(name: &str, text: &str) -> Result<ClaimedAnswer, Error> {
        ClaimedAnswer::new_within(name, text, &mut Budget::new(expr::MAX_WORK))
    }

    /// [`ClaimedAnswer::new`], charging a formula's work to a run's `budget`.
    ///
    /// # Errors
    /// Those of [`ClaimedAnswer::new`], and an exhausted budget.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{ClaimedAnswer, expr::Budget};
    /// assert!(ClaimedAnswer::new_within("V", "2*m", &mut Budget::run()).is_ok());
    /// ```
    pub fn new_within(name: &str, text: &str, budget: &mut Budget) -> Result<ClaimedAnswer, Error> {
        let quantity = Quantity::parse(name).ok_or_else(|| {
            Error::new(
                "claim",
                ErrorKind::Invalid(format!(
                    "unknown name '{}' (accepted: {})",
                    crate::echo::echo(name),
                    Quantity::all_names()
                )),
            )
        })?;
        let field = format!("claim {name}");
        let value = read_value(&field, text, quantity.dimension(), budget)?;
        Ok(ClaimedAnswer {
            quantity,
            text: text.trim().to_string(),
            value,
        })
    }

    /// Whether the value mentions a symbol.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::ClaimedAnswer;
    /// assert!(!ClaimedAnswer::parse("a_star=sqrt(2/3)").unwrap().is_symbolic());
    /// assert!(ClaimedAnswer::parse("V=2*m*v0/(M+4*m)").unwrap().is_symbolic());
    /// ```
    pub fn is_symbolic(&self) -> bool {
        matches!(&self.value, ClaimedValue::Formula(r) if r.constant().is_none())
    }
}

/// A claimed value as written: a printed number with an optional unit of `dimension`, or a
/// constant formula; `name` names it in errors.
///
/// # Errors
/// A value that is neither, or a unit of another dimension.
///
/// # Examples
/// ```
/// use rodimpact::{textbook::read_claimed, units::Dimension};
/// assert!(read_claimed("rod.omega", "3.2 rad/s", Dimension::AngularSpeed).is_ok());
/// assert!(read_claimed("rod.omega", "3.2 kg", Dimension::AngularSpeed).is_err());
/// ```
pub fn read_claimed(name: &str, text: &str, dimension: Dimension) -> Result<ClaimedValue, Error> {
    read_value(name, text, dimension, &mut Budget::new(expr::MAX_WORK))
}

/// A printed number with an optional unit, or else a formula (charged to `budget`); when
/// neither reads, the error of the form the text looks like.
pub(crate) fn read_value(
    field: &str,
    text: &str,
    dimension: Dimension,
    budget: &mut Budget,
) -> Result<ClaimedValue, Error> {
    match Measured::parse(field, text, dimension) {
        Ok(m) => Ok(ClaimedValue::Printed(m)),
        Err(numeric) => match expr::parse_within(field, text, budget) {
            Ok(r) => Ok(ClaimedValue::Formula(r)),
            Err(formula) => {
                let looks_formula = text.trim_start().starts_with(|c: char| c.is_alphabetic())
                    || text.contains(['*', '(', '^']);
                Err(if looks_formula { formula } else { numeric })
            }
        },
    }
}
