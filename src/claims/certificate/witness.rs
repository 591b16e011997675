//! The witness certificate: a relation evaluated exactly at one instance, in Q(sqrt d).

use super::CertificateError;
use crate::field::{Field, QSqrt, RatFn, Sym};
use std::cmp::Ordering;
use std::collections::BTreeSet;

/// The relation a [`Witness`] asserts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    /// `lhs = rhs`.
    Eq,
    /// `lhs != rhs`.
    Ne,
    /// `lhs < rhs`.
    Lt,
    /// `lhs <= rhs`.
    Le,
    /// `lhs > rhs`.
    Gt,
    /// `lhs >= rhs`.
    Ge,
}

impl Relation {
    fn holds(self, o: Ordering) -> bool {
        match self {
            Relation::Eq => o == Ordering::Equal,
            Relation::Ne => o != Ordering::Equal,
            Relation::Lt => o == Ordering::Less,
            Relation::Le => o != Ordering::Greater,
            Relation::Gt => o == Ordering::Greater,
            Relation::Ge => o != Ordering::Less,
        }
    }

    /// The relation as certificates write it: `=`, `!=`, `<`, `<=`, `>`, `>=`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Relation;
    /// assert_eq!(Relation::Ge.symbol(), ">=");
    /// ```
    pub fn symbol(self) -> &'static str {
        match self {
            Relation::Eq => "=",
            Relation::Ne => "!=",
            Relation::Lt => "<",
            Relation::Le => "<=",
            Relation::Gt => ">",
            Relation::Ge => ">=",
        }
    }
}

/// `lhs rel rhs` at one exact instance (values in Q or Q(sqrt d), one d for the whole
/// instance): both sides evaluated exactly, the sign of `lhs - rhs` decided exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Witness {
    /// What the instance shows, in words.
    pub title: String,
    /// Symbol values.
    pub instance: Vec<(Sym, QSqrt)>,
    /// Left-hand side.
    pub lhs: RatFn,
    /// The relation.
    pub relation: Relation,
    /// Right-hand side.
    pub rhs: RatFn,
}

impl Witness {
    /// Re-verifies the relation at the instance.
    ///
    /// # Errors
    /// [`CertificateError::MixedRadicands`], [`CertificateError::LhsUndefined`],
    /// [`CertificateError::RhsUndefined`], [`CertificateError::SignUndecided`] or
    /// [`CertificateError::RelationFails`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Relation};
    /// use rodimpact::field::{QSqrt, RatFn, Sym, q};
    /// let at_two = vec![(Sym::new("x"), QSqrt::sqrt_of(&q(2, 1)))];
    /// let x = RatFn::symbol("x");
    /// let Certificate::Witness(c) = Certificate::witness("sqrt 2 < 3/2", at_two, x, Relation::Lt,
    ///     RatFn::constant(q(3, 2))) else { unreachable!() };
    /// assert!(c.check().is_ok());
    /// ```
    pub fn check(&self) -> Result<(), CertificateError> {
        let radicands: BTreeSet<String> = self
            .instance
            .iter()
            .filter_map(|(_, v)| v.d().map(|d| d.to_string()))
            .collect();
        if radicands.len() > 1 {
            return Err(CertificateError::MixedRadicands(radicands));
        }
        let l = self
            .evaluate(&self.lhs)
            .ok_or(CertificateError::LhsUndefined)?;
        let r = self
            .evaluate(&self.rhs)
            .ok_or(CertificateError::RhsUndefined)?;
        let order = (l.clone() - &r)
            .sign()
            .ok_or(CertificateError::SignUndecided)?;
        if self.relation.holds(order) {
            Ok(())
        } else {
            Err(CertificateError::RelationFails {
                lhs: Box::new(l),
                rhs: Box::new(r),
                relation: self.relation,
            })
        }
    }

    /// `x` evaluated exactly at the instance; `None` where a denominator vanishes or a symbol
    /// has no value.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Certificate, Relation};
    /// use rodimpact::field::{QSqrt, RatFn, Sym, q};
    /// let at_two = vec![(Sym::new("x"), QSqrt::rational(q(2, 1)))];
    /// let x = RatFn::symbol("x");
    /// let Certificate::Witness(c) = Certificate::witness("", at_two, x.clone(), Relation::Eq,
    ///     x.clone()) else { unreachable!() };
    /// assert_eq!(c.evaluate(&(x.clone() * &x)).unwrap().to_string(), "4");
    /// assert_eq!(c.evaluate(&RatFn::symbol("y")), None);
    /// ```
    pub fn evaluate(&self, x: &RatFn) -> Option<QSqrt> {
        x.eval(&|s: Sym| {
            self.instance
                .iter()
                .find(|(k, _)| *k == s)
                .map(|(_, v)| v.clone())
        })
    }
}
