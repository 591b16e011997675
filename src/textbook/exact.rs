//! An exact numeric answer: a rational, or x + y sqrt(d) for `a_star` and `omega_max`.

use crate::field::{Q, QSqrt, TrySqrt};

/// An exact numeric answer: rational, or in Q(sqrt d) (`a_star`, `omega_max`).
#[derive(Debug, Clone, PartialEq)]
pub enum Exact {
    /// A rational.
    Rational(Q),
    /// x + y sqrt(d).
    Surd(QSqrt),
}

impl Exact {
    /// `c * sqrt(r)` (`r >= 0`), rational when the root is.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::radical(q(2, 1), q(9, 4)), Exact::Rational(q(3, 1)));
    /// assert!(matches!(Exact::radical(q(1, 1), q(2, 1)), Exact::Surd(_)));
    /// ```
    pub fn radical(c: Q, r: Q) -> Exact {
        match r.try_sqrt() {
            Some(root) => Exact::Rational(c * root),
            None => Exact::Surd(QSqrt::new(Q::default(), c, r)),
        }
    }

    /// Correctly rounded to `digits` significant digits.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::Rational(q(36, 19)).decimal(6), "1.89474");
    /// ```
    pub fn decimal(&self, digits: usize) -> String {
        match self {
            Exact::Rational(x) => crate::field::decimal::decimal(x, digits),
            Exact::Surd(s) => s.decimal(digits),
        }
    }

    /// For a text report: the exact form, or a decimal when the fraction is very long
    /// ([`crate::field::decimal::compact`]).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::Rational(q(36, 19)).compact(), "36/19");
    /// ```
    pub fn compact(&self) -> String {
        match self {
            Exact::Rational(x) => crate::field::decimal::compact(x),
            Exact::Surd(s) => {
                let text = s.to_string();
                if text.chars().count() <= crate::field::decimal::COMPACT_CHARS {
                    text
                } else {
                    format!("≈ {}", s.decimal(6))
                }
            }
        }
    }
}

impl std::fmt::Display for Exact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Exact::Rational(x) => write!(f, "{x}"),
            Exact::Surd(s) => write!(f, "{s}"),
        }
    }
}
