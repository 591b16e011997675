//! The positivity certificate: `expr > 0` (or `>= 0`) on a domain, shown by a form whose sign
//! is visible from its shape ([`PosExpr`]).

use super::CertificateError;
use crate::field::{Field, Q, RatFn, Sym};
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::collections::BTreeSet;
use std::fmt;

/// An expression whose sign is visible from its shape.
#[derive(Debug, Clone, PartialEq)]
pub enum PosExpr {
    /// A symbol declared positive (or nonnegative) by the certificate's domain.
    Sym(Sym),
    /// A rational constant (positive, or zero for a nonnegative form).
    Const(Q),
    /// A sum of signed-visible terms.
    Sum(Vec<PosExpr>),
    /// A product of signed-visible factors.
    Product(Vec<PosExpr>),
    /// A quotient; the denominator must be strictly positive.
    Quotient(Box<PosExpr>, Box<PosExpr>),
    /// The square of any expression: nonnegative, zero exactly where the expression vanishes.
    Square(RatFn),
}

/// How sure the sign of a [`PosExpr`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum SignClass {
    /// `>= 0` everywhere on the domain.
    NonNegative,
    /// `> 0` everywhere on the domain.
    Positive,
}

impl PosExpr {
    /// A symbol by name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::PosExpr;
    /// assert_eq!(PosExpr::sym("m").to_string(), "m");
    /// ```
    pub fn sym(name: &str) -> PosExpr {
        PosExpr::Sym(Sym::new(name))
    }

    /// A constant n/d.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::PosExpr;
    /// assert_eq!(PosExpr::constant(1, 3).to_string(), "1/3");
    /// ```
    pub fn constant(n: i64, d: i64) -> PosExpr {
        PosExpr::Const(crate::field::q(n, d))
    }

    /// The product of the factors.
    pub fn product(factors: impl IntoIterator<Item = PosExpr>) -> PosExpr {
        PosExpr::Product(factors.into_iter().collect())
    }

    /// The sum of the terms.
    pub fn sum(terms: impl IntoIterator<Item = PosExpr>) -> PosExpr {
        PosExpr::Sum(terms.into_iter().collect())
    }

    /// `num / den`.
    pub fn quotient(num: PosExpr, den: PosExpr) -> PosExpr {
        PosExpr::Quotient(Box::new(num), Box::new(den))
    }

    /// The value as a rational function.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::PosExpr;
    /// let e = PosExpr::quotient(PosExpr::sym("q"), PosExpr::constant(3, 1));
    /// assert_eq!(e.value().to_string(), "1/3*q");
    /// ```
    pub fn value(&self) -> RatFn {
        match self {
            PosExpr::Sym(s) => RatFn::symbol(s.name()),
            PosExpr::Const(c) => RatFn::constant(c.clone()),
            PosExpr::Sum(ts) => ts.iter().fold(RatFn::zero(), |acc, t| acc + &t.value()),
            PosExpr::Product(fs) => fs.iter().fold(RatFn::one(), |acc, f| acc * &f.value()),
            PosExpr::Quotient(n, d) => n.value() / d.value(),
            PosExpr::Square(x) => x.clone() * x,
        }
    }

    /// The sign visible from the shape, given the symbols declared positive and nonnegative;
    /// `None` when the shape shows no sign (an undeclared symbol, a negative constant, a
    /// denominator that is not strictly positive, an empty sum).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{PosExpr, SignClass};
    /// use rodimpact::field::Sym;
    /// let pos = [Sym::new("m")];
    /// let e = PosExpr::sum([PosExpr::sym("m"), PosExpr::Square(rodimpact::field::RatFn::symbol("x"))]);
    /// assert_eq!(e.sign_class(&pos, &[]), Some(SignClass::Positive));
    /// assert_eq!(PosExpr::sym("x").sign_class(&pos, &[]), None);
    /// ```
    pub fn sign_class(&self, positive: &[Sym], nonnegative: &[Sym]) -> Option<SignClass> {
        use SignClass::*;
        match self {
            PosExpr::Sym(s) if positive.contains(s) => Some(Positive),
            PosExpr::Sym(s) if nonnegative.contains(s) => Some(NonNegative),
            PosExpr::Sym(_) => None,
            PosExpr::Const(c) => match c.sign() {
                Some(Ordering::Greater) => Some(Positive),
                Some(Ordering::Equal) => Some(NonNegative),
                _ => None,
            },
            PosExpr::Square(_) => Some(NonNegative),
            PosExpr::Sum(ts) => {
                let classes: Option<Vec<_>> = ts
                    .iter()
                    .map(|t| t.sign_class(positive, nonnegative))
                    .collect();
                classes?.into_iter().max()
            }
            PosExpr::Product(fs) => {
                let classes: Option<Vec<_>> = fs
                    .iter()
                    .map(|f| f.sign_class(positive, nonnegative))
                    .collect();
                Some(classes?.into_iter().min().unwrap_or(Positive))
            }
            PosExpr::Quotient(n, d) => match d.sign_class(positive, nonnegative)? {
                Positive => n.sign_class(positive, nonnegative),
                NonNegative => None,
            },
        }
    }
}

impl PosExpr {
    /// True for shapes that print without parentheses inside a product or quotient.
    fn is_atom(&self) -> bool {
        match self {
            PosExpr::Sym(_) | PosExpr::Square(_) => true,
            PosExpr::Const(c) => c.is_integer(),
            PosExpr::Sum(ts) => ts.len() == 1 && ts[0].is_atom(),
            PosExpr::Product(fs) => fs.len() == 1 && fs[0].is_atom(),
            PosExpr::Quotient(..) => false,
        }
    }

    fn factor(&self) -> String {
        if self.is_atom() || matches!(self, PosExpr::Product(_)) {
            self.to_string()
        } else {
            format!("({self})")
        }
    }
}

impl fmt::Display for PosExpr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PosExpr::Sym(s) => write!(f, "{s}"),
            PosExpr::Const(c) => write!(f, "{c}"),
            PosExpr::Sum(ts) => {
                let terms: Vec<String> = ts.iter().map(|t| t.to_string()).collect();
                write!(f, "{}", terms.join(" + "))
            }
            PosExpr::Product(fs) => {
                let factors: Vec<String> = fs.iter().map(|x| x.factor()).collect();
                write!(f, "{}", factors.join("*"))
            }
            PosExpr::Quotient(n, d) => {
                let den = if d.is_atom() {
                    d.to_string()
                } else {
                    format!("({d})")
                };
                write!(f, "{}/{den}", n.factor())
            }
            PosExpr::Square(x) => {
                let inner = x.to_string();
                if inner.chars().all(|c| c.is_alphanumeric() || c == '_') {
                    write!(f, "{inner}^2")
                } else {
                    write!(f, "({inner})^2")
                }
            }
        }
    }
}

/// `expr > 0` (strict) or `>= 0` on a domain parametrised by the substitutions: after the
/// substitutions (slack symbols that parametrise the domain, e.g. `M = 2m + q`), `expr` equals,
/// identically, a [`PosExpr`] built only from positive symbols, positive constants, sums,
/// products, quotients and squares, so its sign is visible.
#[derive(Debug, Clone, PartialEq)]
pub struct Positive {
    /// What the inequality says, in words.
    pub title: String,
    /// The expression whose sign is claimed.
    pub expr: RatFn,
    /// `true` for `> 0`, `false` for `>= 0`.
    pub strict: bool,
    /// Domain parametrisation: each symbol replaced by an expression in slack symbols.
    pub substitutions: Vec<(Sym, RatFn)>,
    /// Symbols positive on the domain.
    pub positive: Vec<Sym>,
    /// Symbols nonnegative on the domain.
    pub nonnegative: Vec<Sym>,
    /// The visibly signed form that `expr` equals after the substitutions.
    pub form: PosExpr,
}

impl Positive {
    /// Re-verifies the inequality: the expression after the substitutions equals the form, and
    /// the form's shape shows the claimed sign.
    ///
    /// # Errors
    /// [`CertificateError::DomainVanishes`], [`CertificateError::FormDiffers`],
    /// [`CertificateError::OnlyNonNegative`], [`CertificateError::UndeclaredSigns`] or
    /// [`CertificateError::NoVisibleSign`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{PosExpr, certificate::Positive};
    /// use rodimpact::field::{RatFn, Sym};
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// let mut c = Positive { title: "m + M > 0".into(), expr: m + &big_m, strict: true,
    ///     substitutions: vec![], positive: vec![Sym::new("m"), Sym::new("M")], nonnegative: vec![],
    ///     form: PosExpr::sum([PosExpr::sym("m"), PosExpr::sym("M")]) };
    /// assert!(c.check().is_ok());
    /// c.positive.pop(); // M of unknown sign: the shape shows nothing
    /// assert!(c.check().is_err());
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        let target = self
            .expr
            .subs_all(&self.substitutions)
            .ok_or(CertificateError::DomainVanishes)?;
        let difference = target - &self.form.value();
        if !difference.is_identically_zero() {
            return Err(CertificateError::FormDiffers { difference });
        }
        let (positive, nonnegative) = (&self.positive, &self.nonnegative);
        let undeclared: BTreeSet<Sym> = self
            .form
            .value()
            .symbols()
            .into_iter()
            .filter(|s| !positive.contains(s) && !nonnegative.contains(s))
            .collect();
        match self.form.sign_class(positive, nonnegative) {
            Some(SignClass::Positive) => Ok(()),
            Some(SignClass::NonNegative) if !self.strict => Ok(()),
            Some(SignClass::NonNegative) => Err(CertificateError::OnlyNonNegative),
            None if !undeclared.is_empty() => Err(CertificateError::UndeclaredSigns(
                undeclared.iter().map(|s| s.name()).collect(),
            )),
            None => Err(CertificateError::NoVisibleSign),
        }
    }
}
