//! The symbolic model the claims are decided in: the scene with every parameter a symbol, solved
//! by the same generic solver as the numbers, over rational functions.

use super::algebra::{k, sym};
use crate::field::RatFn;
use crate::scene::Motion;
use crate::scene::{Params, RodInertia, Support, gyration_moment};
use crate::solve::Outcome;
use crate::solve::fast::linear::solve;
use num_traits::One;

/// The general free-rod scene in symbols: m, M, I, a, v0 and restitution `e`.
pub(crate) fn free_rod(inertia: impl Into<RatFn>, e: RatFn) -> Params<RatFn> {
    Params::symbolic(inertia.into(), e)
}

/// The pivoted-rod scene in symbols: pivot at p, moment of inertia `inertia` about the centre.
pub(crate) fn pivoted_rod(inertia: impl Into<RatFn>, e: RatFn) -> Params<RatFn> {
    Params {
        support: Support::Pivot(sym("p")),
        ..free_rod(inertia, e)
    }
}

/// Solves a symbolic scene with the generic solver (the same code as for numbers).
pub(crate) fn solved(p: &Params<RatFn>) -> Outcome<RatFn> {
    solve(p).expect("the symbolic impulse system is nonsingular")
}

/// The velocities after the impact of a symbolic scene.
pub(crate) fn motion(p: &Params<RatFn>) -> Motion<RatFn> {
    solved(p).after
}

/// Elastic omega of the free rod from the generic solver, moment of inertia `inertia`.
pub(crate) fn elastic_omega(inertia: RatFn) -> RatFn {
    motion(&free_rod(inertia, k(1, 1))).omega
}

/// Elastic omega of the uniform rod (I = M l^2/3) from the generic solver.
pub(crate) fn uniform_omega() -> RatFn {
    elastic_omega(uniform_inertia())
}

/// `a*^2 = I (M + m)/(m M)`.
pub(crate) fn a_star_squared(inertia: &RatFn) -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    inertia.clone() * &(big_m.clone() + &m) / (m * &big_m)
}

/// Uniform rod: `I = M l^2 / 3`.
pub(crate) fn uniform_inertia() -> RatFn {
    RodInertia::Uniform.moment(&sym("M"), &sym("l"))
}

/// Radius of gyration: `I = M r_G^2`.
pub(crate) fn gyration_inertia() -> RatFn {
    gyration_moment(&sym("M"), &sym("r_G"))
}

/// `D = 1 + m/M + m a^2/I`.
pub(crate) fn paper_d(inertia: &RatFn) -> RatFn {
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    RatFn::one() + &(m.clone() / big_m) + &(m * &a * &a / inertia.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_symbolic_scene_solves_with_zero_residuals() {
        let p = free_rod(sym("I"), k(1, 1));
        assert_eq!(p.inertia.to_string(), "I");
        assert!(solved(&p).residuals.all_zero());
        assert_eq!(a_star_squared(&sym("I")).to_string(), "(I*M + I*m)/(M*m)");
        assert_eq!(
            elastic_omega(sym("I")).to_string(),
            "2*M*a*m*v0/(M*a^2*m + I*M + I*m)"
        );
    }
}
