//! Certificates: data that a small checker re-verifies by exact computation.
//!
//! A claim's verdict comes only from [`Certificate::check`]. One kind per file, each with its
//! data and its check:
//!
//! - [`Identity`]: `lhs = rhs` for all values of the symbols (after an optional substitution);
//! - [`Positive`]: `expr > 0` (or `>= 0`) on a domain, equal to a visibly signed [`PosExpr`];
//! - [`Limit`]: the exact limit of an expression as a symbol tends to 0+ or infinity;
//! - [`Witness`]: a relation evaluated exactly at one instance, in Q(sqrt d);
//! - [`Integral`]: an exact polynomial integral (mass, centre of mass, moment of inertia of a
//!   density along the rod).
//!
//! How a certificate reads in Markdown is the report's business
//! ([`crate::report::certificate_markdown`]).

mod identity;
mod integral;
mod limit;
mod positive;
mod witness;

pub use identity::Identity;
pub use integral::Integral;
pub(crate) use limit::point_name;
pub use limit::{Expected, Limit};
pub use positive::{PosExpr, Positive, SignClass};
pub use witness::{Relation, Witness};

use super::Formula;
use crate::field::ratfunc::{LimitValue, Point};
use crate::field::{QSqrt, RatFn, Sym};
use std::collections::BTreeSet;

/// A piece of evidence that a checker re-verifies.
#[derive(Debug, Clone, PartialEq)]
pub enum Certificate {
    /// `lhs = rhs` identically, after an optional substitution.
    Identity(Identity),
    /// `expr > 0` (strict) or `>= 0` on a domain parametrised by substitutions.
    Positive(Positive),
    /// `lim expr` as a symbol tends to 0+ or infinity.
    Limit(Limit),
    /// `lhs rel rhs` at one exact instance (values in Q or Q(sqrt d)).
    Witness(Witness),
    /// `integral over [lower, upper] of density * var^power d var = expected`.
    Integral(Integral),
}

/// Why a certificate does not check: what the exact computation found instead.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CertificateError {
    /// Identity: the two sides differ.
    #[error("lhs - rhs = {residual}, not identically 0")]
    NotIdentical {
        /// `lhs - rhs`, after the substitution.
        residual: RatFn,
    },
    /// Identity: the substitution makes a denominator vanish.
    #[error("the substitution makes a denominator vanish")]
    SubstitutionVanishes,
    /// Positivity: a substitution of the domain makes a denominator vanish.
    #[error("a substitution makes a denominator vanish")]
    DomainVanishes,
    /// Positivity: the expression, after the substitutions, is not the form.
    #[error("expression after substitution minus the form = {difference}, not 0")]
    FormDiffers {
        /// The expression after the substitutions minus the form's value.
        difference: RatFn,
    },
    /// Positivity: the form shows `>= 0` where `> 0` is claimed.
    #[error("the form shows only >= 0, not > 0")]
    OnlyNonNegative,
    /// Positivity: the form uses symbols the domain does not sign.
    #[error("the form uses symbols of undeclared sign: {0:?}")]
    UndeclaredSigns(Vec<&'static str>),
    /// Positivity: the form's shape shows no sign (a negative constant, a denominator not
    /// strictly positive, an empty sum).
    #[error("the form's shape shows no sign")]
    NoVisibleSign,
    /// Limit: another limit was found.
    #[error("the limit is {}", limit::describe(found, *sym, *at))]
    WrongLimit {
        /// The limit found.
        found: LimitValue,
        /// The symbol that moves.
        sym: Sym,
        /// Where it goes.
        at: Point,
    },
    /// Witness: the instance mixes square roots of several radicands.
    #[error("instance mixes square roots of {0:?}")]
    MixedRadicands(BTreeSet<String>),
    /// Witness: the left-hand side is undefined at the instance.
    #[error("lhs is undefined at the instance")]
    LhsUndefined,
    /// Witness: the right-hand side is undefined at the instance.
    #[error("rhs is undefined at the instance")]
    RhsUndefined,
    /// Witness: the sign of `lhs - rhs` could not be decided.
    #[error("the sign is undecided")]
    SignUndecided,
    /// Witness: the relation fails at the instance.
    #[error("at the instance lhs = {lhs}, rhs = {rhs}: {} fails", relation.symbol())]
    RelationFails {
        /// The left-hand side's value.
        lhs: Box<QSqrt>,
        /// The right-hand side's value.
        rhs: Box<QSqrt>,
        /// The relation claimed.
        relation: Relation,
    },
    /// Integral: the density has the variable in its denominator.
    #[error("the density is not a polynomial in {var}")]
    DensityNotPolynomial {
        /// The integration variable.
        var: Sym,
    },
    /// Integral: the limits make a denominator vanish.
    #[error("the limits make a denominator vanish")]
    LimitsVanish,
    /// Integral: the integral has another value.
    #[error("the integral is {value}")]
    WrongIntegral {
        /// The value found.
        value: RatFn,
    },
}

impl Certificate {
    /// An identity certificate: `lhs = rhs` for all values of the symbols.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// let x = Formula::sym("x");
    /// let one = Formula::int(1);
    /// let c = Certificate::identity("(x+1)^2 expands", (x.clone() + &one).pow(2),
    ///     x.pow(2) + &(Formula::int(2) * &x) + &one);
    /// assert!(c.check().is_ok());
    /// ```
    pub fn identity(
        title: impl Into<String>,
        lhs: impl Into<Formula>,
        rhs: impl Into<Formula>,
    ) -> Certificate {
        Certificate::identity_at(title, lhs, rhs, &[])
    }

    /// An identity certificate after a substitution: `lhs = rhs` once the symbols of `at` are
    /// replaced (simultaneously) in both sides. The sides are shown as built, then the
    /// substitution, then the form both reduce to.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// use rodimpact::field::RatFn;
    /// let a = Formula::sym("a");
    /// let c = Certificate::identity_at("a^2 = 4 at a = 2", a.pow(2), Formula::int(4),
    ///     &[("a", RatFn::from(2))]);
    /// assert!(c.check().is_ok());
    /// ```
    pub fn identity_at(
        title: impl Into<String>,
        lhs: impl Into<Formula>,
        rhs: impl Into<Formula>,
        at: &[(&str, RatFn)],
    ) -> Certificate {
        Certificate::Identity(Identity {
            title: title.into(),
            lhs: lhs.into(),
            rhs: rhs.into(),
            at: at.iter().map(|(s, v)| (Sym::new(s), v.clone())).collect(),
        })
    }

    /// A witness certificate.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Relation};
    /// use rodimpact::field::{QSqrt, RatFn, Sym, q};
    /// let at = vec![(Sym::new("x"), QSqrt::rational(q(1, 2)))];
    /// let c = Certificate::witness("x < 1 at x = 1/2", at, RatFn::symbol("x"), Relation::Lt, RatFn::from(1));
    /// assert!(c.check().is_ok());
    /// ```
    pub fn witness(
        title: impl Into<String>,
        instance: Vec<(Sym, QSqrt)>,
        lhs: impl Into<RatFn>,
        relation: Relation,
        rhs: impl Into<RatFn>,
    ) -> Certificate {
        Certificate::Witness(Witness {
            title: title.into(),
            instance,
            lhs: lhs.into(),
            relation,
            rhs: rhs.into(),
        })
    }

    /// A finite-limit certificate.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Certificate;
    /// use rodimpact::field::{RatFn, ratfunc::Point};
    /// let x = RatFn::symbol("x");
    /// let c = Certificate::limit("x/(1 + x) -> 1", x.clone() / (RatFn::from(1) + &x), "x",
    ///     Point::Infinity, RatFn::from(1));
    /// assert!(c.check().is_ok());
    /// ```
    pub fn limit(
        title: impl Into<String>,
        expr: impl Into<RatFn>,
        sym: &str,
        at: Point,
        expected: impl Into<RatFn>,
    ) -> Certificate {
        Certificate::Limit(Limit {
            title: title.into(),
            expr: expr.into(),
            sym: Sym::new(sym),
            at,
            expected: Expected::Finite(expected.into()),
        })
    }

    /// The certificate's title.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// let c = Certificate::identity("1 = 1", Formula::int(1), Formula::int(1));
    /// assert_eq!(c.title(), "1 = 1");
    /// ```
    pub fn title(&self) -> &str {
        match self {
            Certificate::Identity(c) => &c.title,
            Certificate::Positive(c) => &c.title,
            Certificate::Limit(c) => &c.title,
            Certificate::Witness(c) => &c.title,
            Certificate::Integral(c) => &c.title,
        }
    }

    /// The kind, as a method name: `identity`, `positivity`, `limit`, `witness`, `integral`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// let c = Certificate::identity("1 = 1", Formula::int(1), Formula::int(1));
    /// assert_eq!(c.kind(), "identity");
    /// ```
    pub fn kind(&self) -> &'static str {
        match self {
            Certificate::Identity(_) => "identity",
            Certificate::Positive(_) => "positivity",
            Certificate::Limit(_) => "limit",
            Certificate::Witness(_) => "witness",
            Certificate::Integral(_) => "integral",
        }
    }

    /// Re-verifies the certificate by exact computation.
    ///
    /// # Errors
    /// What did not check ([`CertificateError`]): the nonzero residual, the shape without a
    /// visible sign, the limit actually found, the relation that fails at the instance.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Formula};
    /// let x = Formula::sym("x");
    /// let wrong = Certificate::identity("x = 2x", x.clone(), Formula::int(2) * &x);
    /// assert_eq!(wrong.check().unwrap_err().to_string(), "lhs - rhs = -x, not identically 0");
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        match self {
            Certificate::Identity(c) => c.check(),
            Certificate::Positive(c) => c.check(),
            Certificate::Limit(c) => c.check(),
            Certificate::Witness(c) => c.check(),
            Certificate::Integral(c) => c.check(),
        }
    }
}
