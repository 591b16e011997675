//! Builders shared by the results beyond the paper on restitution, the optimum a* for every e,
//! energy, the projectile's fate and the rod point at rest (X1-X13).
//!
//! Conventions: `A` is a symbol for a* itself; a claim "at a*" is checked by substituting
//! `I := A^2 I / a*^2` (with the paper's a*^2, which is linear in I, so this is
//! `I = A^2 m M/(M + m)`) and then `a := A`.

use super::*;
use crate::field::{RatFn, Sym};
use crate::scene::Motion;
use num_traits::Zero;

/// An identity at a* (see [`a_star_at`]).
pub(crate) fn id_at_star(
    paper: &Paper,
    title: &str,
    lhs: impl Into<Formula>,
    rhs: impl Into<Formula>,
) -> Certificate {
    Certificate::identity_at(title, lhs, rhs, &a_star_at(paper))
}

/// `(1 + e)` as a [`Formula`].
pub(crate) fn one_plus_e_f() -> Formula {
    Formula::int(1) + &f("e")
}

/// `mu` (= m M/(M + m)) under its name.
pub(crate) fn mu_f() -> Formula {
    n("mu", mu())
}

/// `m_eff` (= 1/(1/m + 1/M + a^2/I)) under its name, for moment of inertia `inertia`.
pub(crate) fn m_eff_f(inertia: &RatFn) -> Formula {
    let one = Formula::int(1);
    n(
        "m_eff",
        one.clone()
            / &(one.clone() / &f("m")
                + &(one / &f("M"))
                + &(f("a").pow(2) / &Formula::from(inertia))),
    )
}

/// `m v0^2/2`.
pub(crate) fn k0_f() -> Formula {
    f("m") * &f("v0").pow(2) / &Formula::int(2)
}

/// `mu = m M/(M + m)`.
pub(crate) fn mu() -> RatFn {
    sym("m") * &sym("M") / (sym("M") + &sym("m"))
}

/// The solver's velocities after the impact for moment of inertia `inertia`, restitution `e`.
pub(crate) fn after(inertia: &RatFn, e: RatFn) -> Motion<RatFn> {
    motion(&free_rod(inertia.clone(), e))
}

/// The energy the solver's motion loses, for inertia I and restitution e.
pub(crate) fn energy_lost(inertia: &RatFn, e: RatFn) -> RatFn {
    solved(&free_rod(inertia.clone(), e)).energy.lost()
}

/// `I` in terms of `A` = a*, from the paper's a*^2 (linear in I): `I = A^2 I / a*^2`.
pub(crate) fn inertia_of_a_star(paper: &Paper) -> RatFn {
    sq(&sym("A")) * &sym("I") / paper.a_star_squared.value().clone()
}

/// The substitution that puts the impact at a*: `I := A^2 m M/(M + m)` (from the paper's
/// a*^2, free of `a` and `I`) and `a := A`, simultaneously.
pub(crate) fn a_star_at(paper: &Paper) -> Vec<(&'static str, RatFn)> {
    vec![("I", inertia_of_a_star(paper)), ("a", sym("A"))]
}

/// `x`, a rational function even in `a`, with `a^2` replaced by `a2` (used to evaluate at an
/// irrational a = sqrt(a2)); `None` if `x` is not even in `a`.
pub(crate) fn even_subs(x: &RatFn, a2: &RatFn) -> Option<RatFn> {
    let a = Sym::new("a");
    let half = |p: &crate::field::Poly| -> Option<RatFn> {
        let mut acc = RatFn::zero();
        for j in 0..=p.degree_in(a) {
            let c = RatFn::from(p.coeff_in(a, j));
            if j % 2 == 1 {
                if !c.is_identically_zero() {
                    return None;
                }
            } else {
                acc = acc + &(c * &pow(a2, j / 2));
            }
        }
        Some(acc)
    };
    Some(half(x.num())? / half(x.den())?)
}

/// [`even_subs`], for a quantity known to depend on `a` only through `a^2`.
pub(crate) fn even_at(x: &RatFn, a2: &RatFn) -> RatFn {
    even_subs(x, a2).expect("the quantity depends on a only through a^2")
}

/// `d omega/da` > 0 below A and < 0 above A, for every e >= 0 (omega at I = A^2 m M/(M + m)).
pub(crate) fn omega_monotonicity(paper: &Paper) -> Vec<Certificate> {
    let omega = subs(
        &after(&sym("I"), sym("e")).omega,
        &[("I", inertia_of_a_star(paper))],
    );
    let slope = omega.derivative(Sym::new("a"));
    let up = (ps("a"), ps("s"));
    // A^2 + a^2 with A = a + s: 2a^2 + 2as + s^2.
    let below_den = sum([
        prod([pc(2, 1), up.0.clone(), ps("a")]),
        prod([pc(2, 1), ps("a"), ps("s")]),
        prod([ps("s"), ps("s")]),
    ]);
    // a^2 + A^2 with a = A + s: 2A^2 + 2As + s^2.
    let above_den = sum([
        prod([pc(2, 1), ps("A"), ps("A")]),
        prod([pc(2, 1), ps("A"), ps("s")]),
        prod([ps("s"), ps("s")]),
    ]);
    let e1 = sum([pc(1, 1), ps("e")]);
    vec![
        positive(
            "d omega/da > 0 for 0 <= a < a* (A = a + s, s > 0; any e >= 0, v0 > 0)",
            slope.clone(),
            true,
            &[("A", sym("a") + &sym("s"))],
            &["s", "v0"],
            &["a", "e"],
            quot(
                prod([
                    e1.clone(),
                    ps("v0"),
                    ps("s"),
                    sum([prod([pc(2, 1), up.0]), up.1]),
                ]),
                prod([below_den.clone(), below_den]),
            ),
        ),
        positive(
            "-d omega/da > 0 for a > a* (a = A + s, s > 0; any e >= 0, v0 > 0)",
            -slope,
            true,
            &[("a", sym("A") + &sym("s"))],
            &["s", "v0", "A"],
            &["e"],
            quot(
                prod([
                    e1,
                    ps("v0"),
                    ps("s"),
                    sum([prod([pc(2, 1), ps("A")]), ps("s")]),
                ]),
                prod([above_den.clone(), above_den]),
            ),
        ),
    ]
}

/// The energy lost, from the solver, equals `(1 - e^2) m_eff v0^2/2` for every e.
pub(crate) fn energy_loss_identity() -> Certificate {
    let i = sym("I");
    let e = sym("e");
    id(
        "energy lost (K0 minus the kinetic energy of the solver's motion) = (1 - e^2) m_eff v0^2/2, m_eff = 1/(1/m + 1/M + a^2/I)",
        n("K_lost", energy_lost(&i, e)),
        (Formula::int(1) - &f("e").pow(2)) * &m_eff_f(&i) * &f("v0").pow(2) / &Formula::int(2),
    )
}

/// A result proved by `certificates`, with its formalisation and the reason for the verdict.
pub(crate) fn proved(formal: &str, reason: &str, certificates: Vec<Certificate>) -> Formalised {
    Formalised {
        formal: formal.into(),
        reason: reason.into(),
        decision: Decision::Proved(certificates),
    }
}
