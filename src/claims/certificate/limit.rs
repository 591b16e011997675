//! The limit certificate: the exact limit of an expression as a symbol tends to 0+ or infinity.

use super::CertificateError;
use crate::field::ratfunc::{LimitValue, Point};
use crate::field::{RatFn, Sym};

/// What a [`Limit`] certificate expects.
#[derive(Debug, Clone, PartialEq)]
pub enum Expected {
    /// A finite limit.
    Finite(RatFn),
    /// Divergence like `coefficient * sym^order`.
    Infinite {
        /// Leading coefficient.
        coefficient: RatFn,
        /// Exponent of the symbol.
        order: i64,
    },
}

/// `lim expr` as `sym` tends to `at`, checked from the exact leading terms in `sym` of the
/// numerator and denominator.
#[derive(Debug, Clone, PartialEq)]
pub struct Limit {
    /// What the limit says, in words.
    pub title: String,
    /// The expression.
    pub expr: RatFn,
    /// The symbol that moves.
    pub sym: Sym,
    /// Where it goes.
    pub at: Point,
    /// The expected limit.
    pub expected: Expected,
}

impl Limit {
    /// Re-verifies the limit.
    ///
    /// # Errors
    /// [`CertificateError::WrongLimit`] with the limit actually found.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Certificate;
    /// use rodimpact::field::{RatFn, ratfunc::Point};
    /// let x = RatFn::symbol("x");
    /// let Certificate::Limit(c) = Certificate::limit("1/(1 + x) -> 1", RatFn::from(1) / (RatFn::from(1) + &x),
    ///     "x", Point::Zero, RatFn::from(1)) else { unreachable!() };
    /// assert!(c.check().is_ok());
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        let found = self.expr.limit(self.sym, self.at);
        let ok = match (&found, &self.expected) {
            (LimitValue::Finite(x), Expected::Finite(y)) => x == y,
            (
                LimitValue::Infinite { coefficient, order },
                Expected::Infinite {
                    coefficient: c,
                    order: k,
                },
            ) => coefficient == c && order == k,
            _ => false,
        };
        if ok {
            Ok(())
        } else {
            Err(CertificateError::WrongLimit {
                found,
                sym: self.sym,
                at: self.at,
            })
        }
    }
}

/// Where a symbol goes, as certificates write it: `0+`, `infinity`.
pub(crate) fn point_name(at: Point) -> &'static str {
    match at {
        Point::Zero => "0+",
        Point::Infinity => "infinity",
    }
}

/// The limit found, in words: `2 as M -> 0+`, `infinite, ~ (v0) * M^1 as M -> infinity`.
pub(super) fn describe(found: &LimitValue, sym: Sym, at: Point) -> String {
    match found {
        LimitValue::Finite(x) => format!("{x} as {sym} -> {}", point_name(at)),
        LimitValue::Infinite { coefficient, order } => {
            format!(
                "infinite, ~ ({coefficient}) * {sym}^{order} as {sym} -> {}",
                point_name(at)
            )
        }
    }
}
