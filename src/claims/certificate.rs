//! Certificates: data that a small checker re-verifies by exact computation.
//!
//! A claim's verdict comes only from [`Certificate::check`]. The kinds:
//!
//! - [`Certificate::Identity`]: `lhs = rhs` for all values of the symbols (after an optional
//!   substitution `at`): the numerator of `lhs - rhs` expands to the zero polynomial. The sides
//!   are [`Formula`]s: they keep the expression as it was built (the solver's output, the
//!   paper's formula as printed), which the certificate shows before the form both reduce to.
//! - [`Certificate::Positive`]: `expr > 0` (or `>= 0`) on a domain: after the stated
//!   substitutions (slack symbols that parametrise the domain, e.g. `M = 2m + q`), `expr`
//!   equals, identically, a [`PosExpr`] built only from positive symbols, positive constants,
//!   sums, products, quotients and squares, so its sign is visible.
//! - [`Certificate::Limit`]: the exact limit of an expression as a symbol tends to 0+ or infinity.
//! - [`Certificate::Witness`]: a relation evaluated exactly at one instance, in Q(sqrt d).
//! - [`Certificate::Integral`]: an exact polynomial integral (mass, centre of mass, moment of
//!   inertia of a density along the rod).

use super::Formula;
use crate::field::ratfunc::{Limit, Point};
use crate::field::{Field, Q, QSqrt, RatFn, Sym};
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::collections::BTreeSet;
use std::fmt;
use std::fmt::Write as _;

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

/// The relation a [`Certificate::Witness`] asserts.
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

    fn symbol(self) -> &'static str {
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

/// What a [`Certificate::Limit`] expects.
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

/// A piece of evidence that a checker re-verifies.
#[derive(Debug, Clone, PartialEq)]
pub enum Certificate {
    /// `lhs = rhs` identically, after the simultaneous substitution `at` (none: for all values).
    Identity {
        /// What the identity says, in words.
        title: String,
        /// Left-hand side, as built.
        lhs: Formula,
        /// Right-hand side, as built.
        rhs: Formula,
        /// Symbols replaced in both sides before they are compared (`I = m M a^2/(M + m)`).
        at: Vec<(Sym, RatFn)>,
    },
    /// `expr > 0` (strict) or `>= 0` on a domain parametrised by the substitutions.
    Positive {
        /// What the inequality says, in words.
        title: String,
        /// The expression whose sign is claimed.
        expr: RatFn,
        /// `true` for `> 0`, `false` for `>= 0`.
        strict: bool,
        /// Domain parametrisation: each symbol replaced by an expression in slack symbols.
        substitutions: Vec<(Sym, RatFn)>,
        /// Symbols positive on the domain.
        positive: Vec<Sym>,
        /// Symbols nonnegative on the domain.
        nonnegative: Vec<Sym>,
        /// The visibly signed form that `expr` equals after the substitutions.
        form: PosExpr,
    },
    /// `lim expr` as `sym` tends to `at`.
    Limit {
        /// What the limit says, in words.
        title: String,
        /// The expression.
        expr: RatFn,
        /// The symbol that moves.
        sym: Sym,
        /// Where it goes.
        at: Point,
        /// The expected limit.
        expected: Expected,
    },
    /// `lhs rel rhs` at one exact instance (values in Q or Q(sqrt d)).
    Witness {
        /// What the instance shows, in words.
        title: String,
        /// Symbol values.
        instance: Vec<(Sym, QSqrt)>,
        /// Left-hand side.
        lhs: RatFn,
        /// The relation.
        relation: Relation,
        /// Right-hand side.
        rhs: RatFn,
    },
    /// `integral over [lower, upper] of density * var^power d var = expected`.
    Integral {
        /// What the integral computes, in words.
        title: String,
        /// The density, a polynomial in `var` (coefficients may involve other symbols).
        density: RatFn,
        /// The integration variable.
        var: Sym,
        /// The power of `var` in the integrand (0 mass, 1 first moment, 2 moment of inertia).
        power: u32,
        /// Lower limit.
        lower: RatFn,
        /// Upper limit.
        upper: RatFn,
        /// The expected value.
        expected: RatFn,
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
    /// assert!(c.to_markdown().contains("lhs     = (x + 1)^2\nrhs     = x^2 + 2*x + 1\n"));
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
    /// assert!(c.to_markdown().contains("at        a = 2\n"));
    /// ```
    pub fn identity_at(
        title: impl Into<String>,
        lhs: impl Into<Formula>,
        rhs: impl Into<Formula>,
        at: &[(&str, RatFn)],
    ) -> Certificate {
        Certificate::Identity {
            title: title.into(),
            lhs: lhs.into(),
            rhs: rhs.into(),
            at: at.iter().map(|(s, v)| (Sym::new(s), v.clone())).collect(),
        }
    }

    /// A witness certificate.
    pub fn witness(
        title: impl Into<String>,
        instance: Vec<(Sym, QSqrt)>,
        lhs: impl Into<RatFn>,
        relation: Relation,
        rhs: impl Into<RatFn>,
    ) -> Certificate {
        Certificate::Witness {
            title: title.into(),
            instance,
            lhs: lhs.into(),
            relation,
            rhs: rhs.into(),
        }
    }

    /// A finite-limit certificate.
    pub fn limit(
        title: impl Into<String>,
        expr: impl Into<RatFn>,
        sym: &str,
        at: Point,
        expected: impl Into<RatFn>,
    ) -> Certificate {
        Certificate::Limit {
            title: title.into(),
            expr: expr.into(),
            sym: Sym::new(sym),
            at,
            expected: Expected::Finite(expected.into()),
        }
    }

    /// The certificate's title.
    pub fn title(&self) -> &str {
        match self {
            Certificate::Identity { title, .. }
            | Certificate::Positive { title, .. }
            | Certificate::Limit { title, .. }
            | Certificate::Witness { title, .. }
            | Certificate::Integral { title, .. } => title,
        }
    }

    /// The kind, as a method name: `identity`, `positivity`, `limit`, `witness`, `integral`.
    pub fn kind(&self) -> &'static str {
        match self {
            Certificate::Identity { .. } => "identity",
            Certificate::Positive { .. } => "positivity",
            Certificate::Limit { .. } => "limit",
            Certificate::Witness { .. } => "witness",
            Certificate::Integral { .. } => "integral",
        }
    }

    /// Re-verifies the certificate by exact computation.
    ///
    /// # Errors
    /// A sentence saying what did not check (the nonzero residual, the shape without a visible
    /// sign, the limit actually found, the relation that fails at the instance).
    pub fn check(&self) -> Result<(), String> {
        match self {
            Certificate::Identity { lhs, rhs, at, .. } => {
                let (l, r) = reduced_sides(lhs, rhs, at)?;
                let diff = l - &r;
                if diff.is_identically_zero() {
                    Ok(())
                } else {
                    Err(format!("lhs - rhs = {diff}, not identically 0"))
                }
            }
            Certificate::Positive {
                expr,
                strict,
                substitutions,
                positive,
                nonnegative,
                form,
                ..
            } => {
                let target = expr
                    .subs_all(substitutions)
                    .ok_or("a substitution makes a denominator vanish")?;
                let diff = target.clone() - &form.value();
                if !diff.is_identically_zero() {
                    return Err(format!(
                        "expression after substitution minus the form = {diff}, not 0"
                    ));
                }
                let leftover: BTreeSet<Sym> = form
                    .value()
                    .symbols()
                    .into_iter()
                    .filter(|s| !positive.contains(s) && !nonnegative.contains(s))
                    .collect();
                let class = form.sign_class(positive, nonnegative);
                match class {
                    Some(SignClass::Positive) => Ok(()),
                    Some(SignClass::NonNegative) if !strict => Ok(()),
                    Some(SignClass::NonNegative) => Err("the form shows only >= 0, not > 0".into()),
                    None if !leftover.is_empty() => Err(format!(
                        "the form uses symbols of undeclared sign: {:?}",
                        leftover.iter().map(|s| s.name()).collect::<Vec<_>>()
                    )),
                    None => Err("the form's shape shows no sign".into()),
                }
            }
            Certificate::Limit {
                expr,
                sym,
                at,
                expected,
                ..
            } => {
                let found = expr.limit(*sym, *at);
                let ok = match (&found, expected) {
                    (Limit::Finite(x), Expected::Finite(y)) => x == y,
                    (
                        Limit::Infinite { coefficient, order },
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
                    Err(format!(
                        "the limit is {}",
                        describe_limit(&found, *sym, *at)
                    ))
                }
            }
            Certificate::Witness {
                instance,
                lhs,
                relation,
                rhs,
                ..
            } => {
                let radicands: BTreeSet<String> = instance
                    .iter()
                    .filter_map(|(_, v)| v.d().map(|d| d.to_string()))
                    .collect();
                if radicands.len() > 1 {
                    return Err(format!("instance mixes square roots of {radicands:?}"));
                }
                let l = evaluate_at(instance, lhs).ok_or("lhs is undefined at the instance")?;
                let r = evaluate_at(instance, rhs).ok_or("rhs is undefined at the instance")?;
                let order = (l.clone() - &r).sign().ok_or("the sign is undecided")?;
                if relation.holds(order) {
                    Ok(())
                } else {
                    Err(format!(
                        "at the instance lhs = {l}, rhs = {r}: {} fails",
                        relation.symbol()
                    ))
                }
            }
            Certificate::Integral {
                density,
                var,
                power,
                lower,
                upper,
                expected,
                ..
            } => {
                let value = integrate(density, *var, *power, lower, upper)?;
                let diff = value.clone() - expected;
                if diff.is_identically_zero() {
                    Ok(())
                } else {
                    Err(format!("the integral is {value}"))
                }
            }
        }
    }

    /// The certificate in Markdown: what it says, its data, and what the checker verified.
    pub fn to_markdown(&self) -> String {
        match self {
            Certificate::Identity { lhs, rhs, at, .. } => {
                let mut block = format!("lhs     = {lhs}\nrhs     = {rhs}\n");
                let mut names: Vec<&(String, Formula)> = lhs.names().iter().collect();
                for n in rhs.names() {
                    if !names.iter().any(|(k, _)| *k == n.0) {
                        names.push(n);
                    }
                }
                for (i, (name, value)) in names.iter().enumerate() {
                    let head = if i == 0 { "where" } else { "" };
                    let _ = writeln!(block, "{head:<9} {name} = {value}");
                }
                if !at.is_empty() {
                    let _ = writeln!(block, "at        {}", substitution_text(at));
                }
                let checked = match reduced_sides(lhs, rhs, at) {
                    Ok((l, r)) if l == r => {
                        let _ = writeln!(block, "reduced = {l}   (both sides)");
                        "the numerator of lhs - rhs expands to the zero polynomial"
                    }
                    Ok((l, r)) => {
                        let _ = writeln!(block, "reduced : lhs = {l}, rhs = {r}");
                        "lhs - rhs is compared with 0"
                    }
                    Err(_) => "the substitution makes a denominator vanish",
                };
                let at_words = if at.is_empty() {
                    ""
                } else {
                    "after the substitution in both sides, "
                };
                format!(
                    "*Identity certificate.*\n\n```text\n{block}```\n\nChecked: {at_words}{checked}; the sides are shown as they were built.\n"
                )
            }
            Certificate::Positive {
                expr,
                strict,
                substitutions,
                positive,
                nonnegative,
                form,
                ..
            } => {
                let subs = if substitutions.is_empty() {
                    "(none)".to_string()
                } else {
                    substitution_text(substitutions)
                };
                let names = |v: &[Sym]| {
                    if v.is_empty() {
                        "(none)".to_string()
                    } else {
                        v.iter().map(|s| s.name()).collect::<Vec<_>>().join(", ")
                    }
                };
                format!(
                    "*Positivity certificate.*\n\n```text\nexpression   = {expr}\nclaim        = expression {} 0\ndomain       : positive {}; nonnegative {}\nsubstitution : {subs}\nform         = {form}\n```\n\nChecked: after the substitution the expression equals the form identically, and the form is built only from positive symbols and constants, sums, products, quotients by positive terms and squares, so it is {}.\n",
                    if *strict { ">" } else { ">=" },
                    names(positive),
                    names(nonnegative),
                    if *strict { "> 0" } else { ">= 0" }
                )
            }
            Certificate::Limit {
                expr,
                sym,
                at,
                expected,
                ..
            } => {
                let target = match expected {
                    Expected::Finite(x) => x.to_string(),
                    Expected::Infinite { coefficient, order } => {
                        format!("~ ({coefficient}) * {sym}^{order}")
                    }
                };
                format!(
                    "*Limit certificate.*\n\n```text\nexpression = {expr}\n{sym} -> {}\nlimit      = {target}\n```\n\nChecked: exact leading terms in {sym} of numerator and denominator.\n",
                    point_name(*at)
                )
            }
            Certificate::Witness {
                instance,
                lhs,
                relation,
                rhs,
                ..
            } => {
                let inst = instance
                    .iter()
                    .map(|(s, v)| format!("{s} = {v}"))
                    .collect::<Vec<_>>()
                    .join(", ");
                let show = |x: &RatFn| {
                    evaluate_at(instance, x)
                        .map(|v| format!("{v} (~ {})", v.decimal(12)))
                        .unwrap_or_else(|| "undefined".into())
                };
                format!(
                    "*Witness certificate.*\n\n```text\ninstance : {inst}\nlhs      = {lhs}\n         = {}\nrhs      = {rhs}\n         = {}\nrelation : lhs {} rhs\n```\n\nChecked: both sides evaluated exactly in Q(sqrt d); the sign of lhs - rhs decided exactly.\n",
                    show(lhs),
                    show(rhs),
                    relation.symbol()
                )
            }
            Certificate::Integral {
                density,
                var,
                power,
                lower,
                upper,
                expected,
                ..
            } => format!(
                "*Integral certificate.*\n\n```text\nintegral from {lower} to {upper} of ({density}) * {var}^{power} d{var}\n  = {expected}\n```\n\nChecked: exact polynomial antiderivative in {var}, evaluated at the limits.\n"
            ),
        }
    }
}

/// Both sides of an identity after its substitution, in canonical form.
fn reduced_sides(
    lhs: &Formula,
    rhs: &Formula,
    at: &[(Sym, RatFn)],
) -> Result<(RatFn, RatFn), String> {
    if at.is_empty() {
        return Ok((lhs.value().clone(), rhs.value().clone()));
    }
    let vanishing = || "the substitution makes a denominator vanish".to_string();
    let l = lhs.value().subs_all(at).ok_or_else(vanishing)?;
    let r = rhs.value().subs_all(at).ok_or_else(vanishing)?;
    Ok((l, r))
}

/// `I = m*M*a^2/(M + m), e = 1`.
fn substitution_text(at: &[(Sym, RatFn)]) -> String {
    at.iter()
        .map(|(s, v)| format!("{s} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// `x` evaluated exactly at a witness instance; `None` where a denominator vanishes or a symbol
/// has no value.
fn evaluate_at(instance: &[(Sym, QSqrt)], x: &RatFn) -> Option<QSqrt> {
    x.eval(&|s: Sym| {
        instance
            .iter()
            .find(|(k, _)| *k == s)
            .map(|(_, v)| v.clone())
    })
}

/// `integral_{lower}^{upper} density(var) * var^power d var`, for a density polynomial in `var`.
fn integrate(
    density: &RatFn,
    var: Sym,
    power: u32,
    lower: &RatFn,
    upper: &RatFn,
) -> Result<RatFn, String> {
    if density.den().degree_in(var) > 0 {
        return Err(format!("the density is not a polynomial in {var}"));
    }
    let x = RatFn::symbol(var.name());
    let num = density.num();
    let den = RatFn::from(density.den().clone());
    let mut antiderivative = RatFn::zero();
    for k in 0..=num.degree_in(var) {
        let coefficient = RatFn::from(num.coeff_in(var, k));
        let exponent = k + power + 1;
        let term = coefficient * &pow(&x, exponent) / RatFn::from(i64::from(exponent));
        antiderivative = antiderivative + &term;
    }
    let at = |value: &RatFn| {
        antiderivative
            .subs(var, value)
            .ok_or("the limits make a denominator vanish")
    };
    Ok((at(upper)? - &at(lower)?) / den)
}

fn pow(x: &RatFn, n: u32) -> RatFn {
    (0..n).fold(RatFn::one(), |acc, _| acc * x)
}

fn point_name(at: Point) -> &'static str {
    match at {
        Point::Zero => "0+",
        Point::Infinity => "infinity",
    }
}

fn describe_limit(l: &Limit, sym: Sym, at: Point) -> String {
    match l {
        Limit::Finite(x) => format!("{x} as {sym} -> {}", point_name(at)),
        Limit::Infinite { coefficient, order } => {
            format!(
                "infinite, ~ ({coefficient}) * {sym}^{order} as {sym} -> {}",
                point_name(at)
            )
        }
    }
}
