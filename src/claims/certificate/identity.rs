//! The identity certificate: `lhs = rhs` for all values of the symbols, after an optional
//! substitution.

use super::CertificateError;
use crate::claims::Formula;
use crate::field::{RatFn, Sym};

/// `lhs = rhs` identically, after the simultaneous substitution `at` (none: for all values):
/// the numerator of `lhs - rhs` expands to the zero polynomial. The sides are [`Formula`]s: they
/// keep the expression as it was built (the solver's output, the paper's formula as printed),
/// which the certificate shows before the form both reduce to.
#[derive(Debug, Clone, PartialEq)]
pub struct Identity {
    /// What the identity says, in words.
    pub title: String,
    /// Left-hand side, as built.
    pub lhs: Formula,
    /// Right-hand side, as built.
    pub rhs: Formula,
    /// Symbols replaced in both sides before they are compared (`I = m M a^2/(M + m)`).
    pub at: Vec<(Sym, RatFn)>,
}

impl Identity {
    /// Re-verifies the identity: both sides, after the substitution, are the same rational
    /// function.
    ///
    /// # Errors
    /// [`CertificateError::NotIdentical`] with the nonzero residual, or
    /// [`CertificateError::SubstitutionVanishes`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// let x = Formula::sym("x");
    /// let Certificate::Identity(c) = Certificate::identity("x + x = 2x", x.clone() + &x,
    ///     Formula::int(2) * &x) else { unreachable!() };
    /// assert!(c.check().is_ok());
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        let (l, r) = self.reduced_sides()?;
        let residual = l - &r;
        if residual.is_identically_zero() {
            Ok(())
        } else {
            Err(CertificateError::NotIdentical { residual })
        }
    }

    /// Both sides after the substitution, in canonical form.
    ///
    /// # Errors
    /// [`CertificateError::SubstitutionVanishes`] when the substitution makes a denominator
    /// vanish.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// use rodimpact::field::RatFn;
    /// let a = Formula::sym("a");
    /// let Certificate::Identity(c) = Certificate::identity_at("a^2 = 4 at a = 2", a.pow(2),
    ///     Formula::int(4), &[("a", RatFn::from(2))]) else { unreachable!() };
    /// let (l, r) = c.reduced_sides().unwrap();
    /// assert_eq!((l.to_string(), r.to_string()), ("4".into(), "4".into()));
    /// ```
    pub fn reduced_sides(&self) -> Result<(RatFn, RatFn), CertificateError> {
        if self.at.is_empty() {
            return Ok((self.lhs.value().clone(), self.rhs.value().clone()));
        }
        let side = |x: &Formula| {
            x.value()
                .subs_all(&self.at)
                .ok_or(CertificateError::SubstitutionVanishes)
        };
        Ok((side(&self.lhs)?, side(&self.rhs)?))
    }
}
