use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C11",
    location: "before (kinetic-divided)",
    group: Group::Equations,
    statement: "(kinetic2) is quadratic in v with roots exactly v0 and Eq. (v); v = v0 gives V = omega = 0 (no collision)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Energy),
    &[Check::holds(
        "the roots of (kinetic2): v = v0 with V = omega = 0 (no collision), or Eq. (v)",
        "(v = v0 and V = 0 and omega = 0) or v = -(1 - m/M - m*a^2/I)/(1 + m/M + m*a^2/I)*v0",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    let (v, v0) = (f("v"), f("v0"));
    let v_paper = Formula::named("v_paper", paper.v.clone());
    let d = Formula::int(1) + &compliance_ratio();
    let factored = -(f("m") * &d * &(v.clone() - &v0) * &(v.clone() - &v_paper));
    let (big_v, omega) = momentum_split(&v0);
    Formalised {
        formal: "For m, M, I > 0 and any a, v0: lhs - rhs of Eq. (kinetic2) equals \
                 -m D (v - v0)(v - v_paper), with v_paper the paper's Eq. (v); the leading \
                 coefficient -m D is nonzero (D > 0), so it is a genuine quadratic and its roots are \
                 exactly v0 and v_paper, distinct when v0 > 0 (v0 - v_paper = 2 v0/D > 0). At v = v0 \
                 Eq. (linear-angular) gives V = omega = 0: the state before the impact, i.e. no \
                 collision (the projectile would pass through the rod)."
            .into(),
        reason: "(kinetic2) = -m D (v - v0)(v - Eq. (v)) identically with D > 0; the roots differ by 2v0/D; V(v0) = omega(v0) = 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic2) = -m D (v - v0)(v - v_paper), v free, v_paper from Eq. (v)",
                kinetic2(&v),
                factored,
            ),
            d_positive(),
            positive("the two roots differ: v0 - v (Eq. (v)) = 2 v0/D > 0", v0.clone() - &v_paper, true, &[], &["m", "M", "I", "v0"], &[], PosExpr::quotient(prod([pc(2, 1), ps("v0"), ps("M"), ps("I")]), m_i_d_form())),
            Certificate::identity("v = v0 in Eq. (linear-angular) gives V = 0", big_v, k(0, 1)),
            Certificate::identity(
                "v = v0 in Eq. (linear-angular) gives omega = 0",
                omega,
                k(0, 1),
            ),
        ]),
    }
}
