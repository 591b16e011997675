//! Builders shared by the claims on the abstract, the introduction, the impulse equations and
//! the limiting cases (C1-C18).
//!
//! The independent derivation is the generic solver run over rational functions
//! ([`motion()`]): its v, V, omega are compared with the paper's printed formulas ([`Paper`]) and
//! with the algebraic steps the paper takes between Eq. (linear) and Eq. (omega).

use super::*;
use crate::field::RatFn;
use crate::scene::Motion;

/// The free rod with a symbolic I.
pub(crate) fn rod(e: RatFn) -> crate::scene::Params<RatFn> {
    free_rod(sym("I"), e)
}

/// The elastic solution from the generic solver, I symbolic.
pub(crate) fn elastic() -> Motion<RatFn> {
    motion(&rod(k(1, 1)))
}

/// D = 1 + m/M + m a^2/I > 0.
pub(crate) fn d_positive() -> Certificate {
    positive(
        "D = 1 + m/M + m a^2/I > 0 (m, M, I > 0, a any real)",
        paper_d(&sym("I")),
        true,
        &[],
        &["m", "M", "I"],
        &[],
        d_form(sym("a")),
    )
}

/// Eq. (linear-angular): V and omega as functions of the projectile's velocity `v`.
pub(crate) fn momentum_split(v: &Formula) -> (Formula, Formula) {
    let dv = f("v0") - v;
    (f("m") / &f("M") * &dv, f("m") * &f("a") / &f("I") * &dv)
}

/// `m/M + m a^2/I`, the coefficient in Eqs. (kinetic2) and (kinetic-divided) divided by m.
pub(crate) fn compliance_ratio() -> Formula {
    f("m") / &f("M") + &(f("m") * &f("a").pow(2) / &f("I"))
}

/// Eq. (kinetic2) as printed, left side minus right side, at projectile velocity `v`:
/// `m(v0^2 - v^2) - ((m^2/M)(v0 - v)^2 + (m^2 a^2/I)(v0 - v)^2)`.
pub(crate) fn kinetic2(v: &Formula) -> Formula {
    let (m, v0) = (f("m"), f("v0"));
    let dv2 = (v0.clone() - v).pow(2);
    m.clone() * &(v0.pow(2) - &v.pow(2))
        - &(m.pow(2) / &f("M") * &dv2 + &(m.pow(2) * &f("a").pow(2) / &f("I") * &dv2))
}

/// Uniform rod, M = m (= l = v0 = 1): omega at a* = sqrt(2/3) l exceeds omega at the end.
pub(crate) fn equal_masses_beat_the_end() -> Vec<Certificate> {
    let omega = uniform_omega();
    let at_end = subs(&omega, &[("a", sym("l"))]);
    let at_star = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("l", rational(1, 1)),
        ("v0", rational(1, 1)),
        ("a", sqrt(&crate::field::q(2, 3))),
    ]);
    vec![
        Certificate::witness(
            "uniform rod, M = m: the impact point a = sqrt(2/3) l lies on the rod (a < l)",
            at_star.clone(),
            sym("a"),
            Relation::Lt,
            sym("l"),
        ),
        Certificate::witness(
            "uniform rod, M = m: omega (generic solver, e = 1) at a = sqrt(2/3) l exceeds omega at the end a = l",
            at_star,
            omega,
            Relation::Gt,
            at_end,
        ),
    ]
}

/// C13-C15: an elastic closed form of the paper against the generic solver, with D > 0; the
/// claim's place and statement come from its `entry`.
pub(crate) fn elastic_formula(
    entry: &Entry,
    quantity: &str,
    solver: RatFn,
    printed: &Formula,
) -> Formalised {
    let (location, statement) = (entry.location, entry.statement);
    Formalised {
        formal: format!(
            "For m, M, I > 0 and any a, v0, the elastic (e = 1) solution of the impulse equations \
             has {statement}, where D = 1 + m/M + m a^2/I > 0 (velocities are signed x-components \
             and omega is signed as in docs/conventions.md: the struck point moves forward for a > 0)."
        ),
        reason: format!(
            "the generic solver's {quantity} equals {location} identically, and D is visibly positive"
        ),
        decision: Decision::Proved(vec![
            Certificate::identity(
                format!("{quantity} from the impulse equations (e = 1) equals {location}"),
                Formula::named(quantity, solver),
                printed.clone(),
            ),
            d_positive(),
        ]),
    }
}
