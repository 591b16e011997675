//! Small builders of certificates and visibly signed forms ([`PosExpr`]), shared by the claim
//! files.

use crate::claims::certificate::Positive;
use crate::claims::{Certificate, Formula, PosExpr};
use crate::field::{RatFn, Sym};

/// An identity certificate: `lhs = rhs` for all values of the symbols.
pub(crate) fn id(title: &str, lhs: impl Into<Formula>, rhs: impl Into<Formula>) -> Certificate {
    Certificate::identity(title, lhs, rhs)
}

/// The symbols with the given names.
pub(crate) fn syms(names: &[&str]) -> Vec<Sym> {
    names.iter().map(|n| Sym::new(n)).collect()
}

/// The positive (or nonnegative) symbol `name` as a [`PosExpr`].
pub(crate) fn ps(name: &str) -> PosExpr {
    PosExpr::sym(name)
}

/// The constant `n/d` as a [`PosExpr`].
pub(crate) fn pc(n: i64, d: i64) -> PosExpr {
    PosExpr::constant(n, d)
}

/// The product of the factors.
pub(crate) fn prod(factors: impl IntoIterator<Item = PosExpr>) -> PosExpr {
    PosExpr::product(factors)
}

/// The sum of the terms.
pub(crate) fn sum(terms: impl IntoIterator<Item = PosExpr>) -> PosExpr {
    PosExpr::sum(terms)
}

/// The quotient `num / den`.
pub(crate) fn quot(num: PosExpr, den: PosExpr) -> PosExpr {
    PosExpr::quotient(num, den)
}

/// `1 + e`, positive for a restitution e >= 0.
pub(crate) fn one_plus_e() -> PosExpr {
    sum([pc(1, 1), ps("e")])
}

/// `D(x) = 1 + m/M + m x^2/I` as a visibly positive form (x may be any real).
pub(crate) fn d_form(x: RatFn) -> PosExpr {
    sum([
        pc(1, 1),
        quot(ps("m"), ps("M")),
        quot(prod([ps("m"), PosExpr::Square(x)]), ps("I")),
    ])
}

/// `M I + m I + m M a^2` (= M I D, and m M I/m_eff) as a visibly positive form (a may be any
/// real).
pub(crate) fn m_i_d_form() -> PosExpr {
    sum([
        prod([ps("M"), ps("I")]),
        prod([ps("m"), ps("I")]),
        prod([ps("m"), ps("M"), PosExpr::Square(RatFn::symbol("a"))]),
    ])
}

/// A positivity certificate: `expr` (> 0 if `strict`, else >= 0) after the simultaneous
/// `substitutions` (which parametrise the domain), equal to the visibly signed `form`, with the
/// symbols `positive` > 0 and `nonnegative` >= 0.
pub(crate) fn positive(
    title: impl Into<String>,
    expr: impl Into<RatFn>,
    strict: bool,
    substitutions: &[(&str, RatFn)],
    positive: &[&str],
    nonnegative: &[&str],
    form: PosExpr,
) -> Certificate {
    Certificate::Positive(Positive {
        title: title.into(),
        expr: expr.into(),
        strict,
        substitutions: substitutions
            .iter()
            .map(|(s, v)| (Sym::new(s), v.clone()))
            .collect(),
        positive: syms(positive),
        nonnegative: syms(nonnegative),
        form,
    })
}
