//! Builders shared by the results beyond the paper on the motion after the impact (far end,
//! energy shares, limits, fixed axis, second impact, asymmetric rod: X14-X26).

use super::*;
use crate::field::RatFn;
use crate::scene::Motion;

/// `r_G^2`.
pub(crate) fn r2() -> RatFn {
    sym("r_G") * &sym("r_G")
}

/// The general free-rod solution with I = M r_G^2 and restitution e, from the generic solver.
pub(crate) fn gyration_motion() -> Motion<RatFn> {
    motion(&free_rod(gyration_inertia(), sym("e")))
}

/// `I = m M a^2/(M + m)`: the value of I for which the impact point a is the optimum a*.
pub(crate) fn inertia_at_a_star() -> RatFn {
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    m.clone() * &big_m * &a * &a / (big_m + &m)
}

/// `I = m M a^2/(M + m)`: the substitution that puts the impact point at a*.
pub(crate) fn optimal_at_a() -> [(&'static str, RatFn); 1] {
    [("I", inertia_at_a_star())]
}

/// An identity where the impact point a is the optimum a* (see [`optimal_at_a`]).
pub(crate) fn id_optimal_at_a(
    title: &str,
    lhs: impl Into<Formula>,
    rhs: impl Into<Formula>,
) -> Certificate {
    Certificate::identity_at(title, lhs, rhs, &optimal_at_a())
}

/// The velocity `V + omega y` of the rod point at `y`, with the solver's V and omega named.
pub(crate) fn point_velocity(motion: &Motion<RatFn>, y: Formula) -> Formula {
    n("V", motion.rod_v.clone()) + &(n("omega", motion.omega.clone()) * &y)
}

/// The substitution `I = m M a^2/(M + m)` puts the impact point at the paper's a*.
pub(crate) fn a_star_substitution_cert(paper: &Paper) -> Certificate {
    id_optimal_at_a(
        "with I = m M a^2/(M + m) the paper's a*^2 = (M + m) I/(m M) equals a^2: the impact is at a*",
        paper.a_star_squared.clone(),
        f("a").pow(2),
    )
}

/// The paper's closed form with I = M r_G^2 substituted.
pub(crate) fn with_gyration(x: &RatFn) -> RatFn {
    subs(x, &[("I", gyration_inertia())])
}
