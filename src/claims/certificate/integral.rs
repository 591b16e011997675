//! The integral certificate: an exact polynomial integral (mass, centre of mass, moment of
//! inertia of a density along the rod).

use super::CertificateError;
use crate::field::{RatFn, Sym};
use num_traits::{One, Zero};

/// `integral over [lower, upper] of density * var^power d var = expected`, checked with the
/// exact polynomial antiderivative in `var`.
#[derive(Debug, Clone, PartialEq)]
pub struct Integral {
    /// What the integral computes, in words.
    pub title: String,
    /// The density, a polynomial in `var` (coefficients may involve other symbols).
    pub density: RatFn,
    /// The integration variable.
    pub var: Sym,
    /// The power of `var` in the integrand (0 mass, 1 first moment, 2 moment of inertia).
    pub power: u32,
    /// Lower limit.
    pub lower: RatFn,
    /// Upper limit.
    pub upper: RatFn,
    /// The expected value.
    pub expected: RatFn,
}

impl Integral {
    /// Re-verifies the integral.
    ///
    /// # Errors
    /// [`CertificateError::WrongIntegral`] with the value found,
    /// [`CertificateError::DensityNotPolynomial`] or [`CertificateError::LimitsVanish`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::certificate::Integral;
    /// use rodimpact::field::{RatFn, Sym};
    /// let l = RatFn::symbol("l");
    /// // The mass of a unit density on [-l, l] is 2 l.
    /// let mass = Integral { title: "mass".into(), density: RatFn::from(1), var: Sym::new("y"),
    ///     power: 0, lower: -l.clone(), upper: l.clone(), expected: RatFn::from(2) * &l };
    /// assert!(mass.check().is_ok());
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        let value = self.value()?;
        if (value.clone() - &self.expected).is_identically_zero() {
            Ok(())
        } else {
            Err(CertificateError::WrongIntegral { value })
        }
    }

    /// `integral_{lower}^{upper} density(var) * var^power d var`, for a density polynomial in
    /// `var`.
    fn value(&self) -> Result<RatFn, CertificateError> {
        let var = self.var;
        if self.density.den().degree_in(var) > 0 {
            return Err(CertificateError::DensityNotPolynomial { var });
        }
        let x = RatFn::symbol(var.name());
        let num = self.density.num();
        let den = RatFn::from(self.density.den().clone());
        let mut antiderivative = RatFn::zero();
        for k in 0..=num.degree_in(var) {
            let coefficient = RatFn::from(num.coeff_in(var, k));
            let exponent = k + self.power + 1;
            let power = (0..exponent).fold(RatFn::one(), |acc, _| acc * &x);
            let term = coefficient * &power / RatFn::from(i64::from(exponent));
            antiderivative = antiderivative + &term;
        }
        let at = |value: &RatFn| {
            antiderivative
                .subs(var, value)
                .ok_or(CertificateError::LimitsVanish)
        };
        Ok((at(&self.upper)? - &at(&self.lower)?) / den)
    }
}
