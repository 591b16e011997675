use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C5",
    location: "Eq. (linear)",
    group: Group::Equations,
    statement: "m v0 = m v + M V",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution).impulses(),
    &[Check::holds(
        "Eq. (linear) from each body's impulse law",
        "m*v0 = m*v + M*V",
    )],
));

fn formalise(_paper: &Paper) -> Formalised {
    let p = rod(sym("e"));
    let after = motion(&p);
    let lhs =
        f("m") * &Formula::named("v", after.v) + &(f("M") * &Formula::named("V", after.rod_v));
    Formalised {
        formal: "For all m, M, I > 0, any a, v0 and any restitution e, the solution of the impulse \
                 equations (momentum, angular momentum about the rod's centre, Newton's restitution) \
                 satisfies m v + M V = m v0: the table is frictionless, so no external impulse acts \
                 along x."
            .into(),
        reason: "the momentum residual of the symbolic solution is identically 0, for every e".into(),
        decision: Decision::Proved(vec![Certificate::identity(
            "linear momentum after the impact equals m v0 (v, V from the generic solver over Q(m, M, I, a, v0, e))",
            lhs,
            f("m") * &f("v0"),
        )]),
    }
}
