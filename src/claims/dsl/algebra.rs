//! Rational functions and formulas in named symbols: the arithmetic the claims are written in.

use crate::claims::Formula;
use crate::field::{Field, Q, QSqrt, RatFn, Sym};
use num_traits::One;

/// A symbol as a rational function.
pub(crate) fn sym(name: &str) -> RatFn {
    RatFn::symbol(name)
}

/// The rational constant n/d as a rational function.
pub(crate) fn k(n: i64, d: i64) -> RatFn {
    RatFn::constant(crate::field::q(n, d))
}

/// `F::from_i64` for rational functions.
pub(crate) fn int(n: i64) -> RatFn {
    RatFn::from_i64(n)
}

/// The constant 1.
pub(crate) fn one() -> RatFn {
    RatFn::one()
}

/// `x^n`.
pub(crate) fn pow(x: &RatFn, n: u32) -> RatFn {
    (0..n).fold(RatFn::one(), |acc, _| acc * x)
}

/// `x^2` (as `x * x`).
pub(crate) fn sq(x: &RatFn) -> RatFn {
    x.clone() * x
}

/// Substitutes `(name, value)` pairs into `x` (the substitution must keep denominators nonzero,
/// which the claims guarantee by construction).
pub(crate) fn subs(x: &RatFn, pairs: &[(&str, RatFn)]) -> RatFn {
    let pairs: Vec<(Sym, RatFn)> = pairs
        .iter()
        .map(|(s, v)| (Sym::new(s), v.clone()))
        .collect();
    x.subs_all(&pairs)
        .expect("a claim's substitution keeps denominators nonzero")
}

/// The reduced value of a constant rational function, if it is one.
pub(crate) fn constant(x: &RatFn) -> Option<Q> {
    x.as_constant()
}

/// An exact instance value in Q(sqrt d) from a rational.
pub(crate) fn rational(n: i64, d: i64) -> QSqrt {
    QSqrt::rational(crate::field::q(n, d))
}

/// The element sqrt(x) of Q(sqrt d) for a rational x >= 0.
pub(crate) fn sqrt(x: &Q) -> QSqrt {
    QSqrt::sqrt_of(x)
}

/// `(symbol, value)` pairs for a witness instance.
pub(crate) fn at(pairs: &[(&str, QSqrt)]) -> Vec<(Sym, QSqrt)> {
    pairs
        .iter()
        .map(|(s, v)| (Sym::new(s), v.clone()))
        .collect()
}

/// A symbol as a [`Formula`].
pub(crate) fn f(name: &str) -> Formula {
    Formula::sym(name)
}

/// A computed value under a name (the solver's `omega`, ...).
pub(crate) fn n(name: &str, value: impl Into<Formula>) -> Formula {
    Formula::named(name, value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shorthands_build_what_they_name() {
        assert_eq!(sym("m").to_string(), "m");
        assert_eq!(k(2, 4).to_string(), "1/2");
        assert_eq!(pow(&sym("a"), 3).to_string(), "a^3");
        assert_eq!(sq(&sym("a")).to_string(), "a^2");
        assert_eq!(
            subs(&(sym("a") * &sym("m")), &[("a", k(0, 1))]).to_string(),
            "0"
        );
        assert_eq!(constant(&k(6, 4)), Some(crate::field::q(3, 2)));
        assert_eq!(sqrt(&crate::field::q(8, 1)).to_string(), "2*sqrt(2)");
        assert_eq!(n("omega", sym("a") * &sym("a")).to_string(), "omega");
    }
}
