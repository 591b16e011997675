use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C9",
    location: "Eq. (linear-angular)",
    group: Group::Equations,
    statement: "V = (m/M)(v0 - v), omega = (ma/I)(v0 - v)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[Check::holds(
        "Eq. (linear-angular), any restitution",
        "V = (m/M)*(v0 - v) and omega = (m*a/I)*(v0 - v)",
    )],
));

fn formalise(_paper: &Paper) -> Formalised {
    let p = rod(sym("e"));
    let (big_v, omega) = momentum_split(&f("v"));
    let after = motion(&p);
    let solver_v = Formula::named("v", after.v.clone());
    let (solver_big_v, solver_omega) = momentum_split(&solver_v);
    Formalised {
        formal: "Eqs. (linear) and (angular) alone (no energy law, so any restitution e) determine \
                 V and omega from v: they are linear in (V, omega) with coefficients M and I != 0, \
                 and V = (m/M)(v0 - v), omega = (ma/I)(v0 - v) satisfy both for every v (v a free \
                 symbol). The generic solver's solution obeys these relations for every e."
            .into(),
        reason: "with v free, (m/M)(v0 - v) and (ma/I)(v0 - v) satisfy both momentum laws identically; the solver's V, omega match for every e".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "linear momentum with V = (m/M)(v0 - v), v free, equals m v0",
                f("m") * &f("v") + &(f("M") * &Formula::named("V", big_v)),
                f("m") * &f("v0"),
            ),
            Certificate::identity(
                "angular momentum about the centre with omega = (ma/I)(v0 - v), v free, equals m v0 a",
                f("m") * &f("v") * &f("a") + &(f("I") * &Formula::named("omega", omega)),
                f("m") * &f("v0") * &f("a"),
            ),
            Certificate::identity(
                "the solver's V (any e) equals (m/M)(v0 - v) at the solver's v",
                Formula::named("V", after.rod_v),
                solver_big_v,
            ),
            Certificate::identity(
                "the solver's omega (any e) equals (ma/I)(v0 - v) at the solver's v",
                Formula::named("omega", after.omega),
                solver_omega,
            ),
        ]),
    }
}
