//! The symbolic model the claims are decided in: the scene with every parameter a symbol, solved
//! by the same generic solver as the numbers, over rational functions.

use crate::field::{Field, Q, QSqrt, RatFn, Sym};
use crate::mechanics::Motion;
use crate::scene::{Params, Support};
use crate::solve::Outcome;
use crate::solve::linear::solve;
use num_traits::One;

/// A symbol as a rational function.
///
/// # Examples
/// ```
/// use rodimpact::claims::model::sym;
/// assert_eq!(sym("m").to_string(), "m");
/// ```
pub fn sym(name: &str) -> RatFn {
    RatFn::symbol(name)
}

/// The rational constant n/d as a rational function.
///
/// # Examples
/// ```
/// use rodimpact::claims::model::k;
/// assert_eq!(k(2, 4).to_string(), "1/2");
/// ```
pub fn k(n: i64, d: i64) -> RatFn {
    RatFn::constant(crate::field::q(n, d))
}

/// `x^n`.
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{pow, sym};
/// assert_eq!(pow(&sym("a"), 3).to_string(), "a^3");
/// ```
pub fn pow(x: &RatFn, n: u32) -> RatFn {
    (0..n).fold(RatFn::one(), |acc, _| acc * x)
}

/// The constant 1.
pub fn one() -> RatFn {
    RatFn::one()
}

/// `x^2` (as `x * x`).
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{sq, sym};
/// assert_eq!(sq(&sym("a")).to_string(), "a^2");
/// ```
pub fn sq(x: &RatFn) -> RatFn {
    x.clone() * x
}

/// An exact instance value in Q(sqrt d) from a rational.
pub fn rational(n: i64, d: i64) -> QSqrt {
    QSqrt::rational(crate::field::q(n, d))
}

/// `(symbol, value)` pairs for a witness instance.
pub fn at(pairs: &[(&str, QSqrt)]) -> Vec<(Sym, QSqrt)> {
    pairs
        .iter()
        .map(|(s, v)| (Sym::new(s), v.clone()))
        .collect()
}

/// Substitutes `(name, value)` pairs into `x` (the substitution must keep denominators nonzero,
/// which the claims guarantee by construction).
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{subs, sym, k};
/// assert_eq!(subs(&(sym("a") * &sym("m")), &[("a", k(0, 1))]).to_string(), "0");
/// ```
pub fn subs(x: &RatFn, pairs: &[(&str, RatFn)]) -> RatFn {
    let pairs: Vec<(Sym, RatFn)> = pairs
        .iter()
        .map(|(s, v)| (Sym::new(s), v.clone()))
        .collect();
    x.subs_all(&pairs)
        .expect("a claim's substitution keeps denominators nonzero")
}

/// The general free-rod scene in symbols: m, M, I, a, v0 and restitution `e`.
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{free_rod, sym};
/// let p = free_rod(sym("I"), sym("e"));
/// assert_eq!(p.inertia.to_string(), "I");
/// ```
pub fn free_rod(inertia: impl Into<RatFn>, e: RatFn) -> Params<RatFn> {
    Params {
        m: sym("m"),
        rod_mass: sym("M"),
        half_length: sym("l"),
        inertia: inertia.into(),
        a: sym("a"),
        v0: sym("v0"),
        e,
        support: Support::Free,
    }
}

/// The pivoted-rod scene in symbols: pivot at p, moment of inertia `inertia` about the centre.
pub fn pivoted_rod(inertia: impl Into<RatFn>, e: RatFn) -> Params<RatFn> {
    Params {
        support: Support::Pivot(sym("p")),
        ..free_rod(inertia, e)
    }
}

/// Solves a symbolic scene with the generic solver (the same code as for numbers).
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{free_rod, solved, sym, k};
/// let out = solved(&free_rod(sym("I"), k(1, 1)));
/// assert!(out.residuals.all_zero());
/// ```
pub fn solved(p: &Params<RatFn>) -> Outcome<RatFn> {
    solve(p).expect("the symbolic impulse system is nonsingular")
}

/// The velocities after the impact of a symbolic scene.
pub fn motion(p: &Params<RatFn>) -> Motion<RatFn> {
    solved(p).after
}

/// `a*^2 = I (M + m)/(m M)`.
///
/// # Examples
/// ```
/// use rodimpact::claims::model::{a_star_squared, sym};
/// assert_eq!(a_star_squared(&sym("I")).to_string(), "(I*M + I*m)/(M*m)");
/// ```
pub fn a_star_squared(inertia: &RatFn) -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    inertia.clone() * &(big_m.clone() + &m) / (m * &big_m)
}

/// Uniform rod: `I = M l^2 / 3`.
pub fn uniform_inertia() -> RatFn {
    sym("M") * &sym("l") * &sym("l") / k(3, 1)
}

/// Radius of gyration: `I = M r_G^2`.
pub fn gyration_inertia() -> RatFn {
    sym("M") * &sym("r_G") * &sym("r_G")
}

/// The element sqrt(x) of Q(sqrt d) for a rational x >= 0.
pub fn sqrt(x: &Q) -> QSqrt {
    QSqrt::sqrt_of(x)
}

/// `D = 1 + m/M + m a^2/I`.
pub fn paper_d(inertia: &RatFn) -> RatFn {
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    RatFn::one() + &(m.clone() / big_m) + &(m * &a * &a / inertia.clone())
}

/// The reduced value of a constant rational function, if it is one.
pub fn constant(x: &RatFn) -> Option<Q> {
    x.as_constant()
}

/// `F::from_i64` for rational functions.
pub fn int(n: i64) -> RatFn {
    RatFn::from_i64(n)
}
