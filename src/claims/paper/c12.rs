use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C12",
    location: "Eq. (kinetic-divided)",
    group: Group::Equations,
    statement: "(kinetic2) = (v0 - v) x (kinetic-divided); dividing is valid for v != v0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Energy),
    &[Check::holds(
        "for v != v0, Eq. (kinetic-divided)",
        "m*(v0 + v) = (m^2/M)*(v0 - v) + (m^2*a^2/I)*(v0 - v)",
    )
    .given(&["v != v0"])],
));

fn formalise(paper: &Paper) -> Formalised {
    let (v, v0) = (f("v"), f("v0"));
    let linear = f("m")
        * &(Formula::int(1) + &compliance_ratio())
        * &(v.clone() - &Formula::named("v_paper", paper.v.clone()));
    Formalised {
        formal: "For a free symbol v: lhs - rhs of Eq. (kinetic2) equals (v0 - v) times lhs - rhs \
                 of Eq. (kinetic-divided), identically; so for v != v0 the two equations are \
                 equivalent. Nothing else is lost: (kinetic-divided) is linear, \
                 m D (v - v_paper) with D > 0, whose only root is the paper's Eq. (v), and it does \
                 not vanish at v = v0 (value 2 m v0 > 0)."
            .into(),
        reason: "(kinetic2) = (v0 - v)(kinetic-divided) identically; (kinetic-divided) = m D (v - Eq. (v)) and is 2 m v0 > 0 at v = v0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic2) = (v0 - v) (lhs - rhs of Eq. (kinetic-divided)), v free",
                kinetic2(&v),
                (v0.clone() - &v) * &kinetic_divided(&v),
            ),
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic-divided) = m D (v - v of Eq. (v)): its only root is Eq. (v)",
                kinetic_divided(&v),
                linear,
            ),
            d_positive(),
            positive("at v = v0, lhs - rhs of Eq. (kinetic-divided) is 2 m v0 > 0: the division drops only the root v0", kinetic_divided(&v0), true, &[], &["m", "v0"], &[], prod([pc(2, 1), ps("m"), ps("v0")])),
        ]),
    }
}

/// Eq. (kinetic-divided) as printed, left side minus right side, at projectile velocity `v`.
fn kinetic_divided(v: &Formula) -> Formula {
    let (m, v0) = (f("m"), f("v0"));
    m.clone() * &(v0.clone() + v) - &(m * &compliance_ratio() * &(v0 - v))
}
