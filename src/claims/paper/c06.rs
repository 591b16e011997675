use crate::claims::dsl::*;
use crate::scene::{Motion, angular_momentum};

pub(super) const ENTRY: Entry = Entry {
    id: "C6",
    location: "Eq. (angular)",
    group: Group::Equations,
    statement: "m v0 a = m v a + I omega about the fixed point at the rod's centre",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution).impulses(),
    &[Check::holds(
        "Eq. (angular) about the fixed point at the rod's centre, from each body's impulse law",
        "m*v0*a = m*v*a + I*omega",
    )],
));

fn formalise(_paper: &Paper) -> Formalised {
    let p = rod(sym("e"));
    let after = motion(&p);
    let printed = f("m") * &Formula::named("v", after.v.clone()) * &f("a")
        + &(f("I") * &Formula::named("omega", after.omega.clone()));
    let y = sym("y");
    let before = Motion::before(sym("v0"));
    Formalised {
        formal: "For all m, M, I > 0, any a, v0 and any restitution e: the solution of the impulse \
                 equations satisfies m v a + I omega = m v0 a, the angular momentum about the fixed \
                 point of the table where the rod's centre is at the impact (the rod's part is \
                 I omega because its centre is at that point and positions do not change during an \
                 instantaneous impact). Since linear momentum is conserved too, the balance holds \
                 about every fixed point (0, y) of the rod's line: the choice of the centre is a \
                 convenience."
            .into(),
        reason: "m v a + I omega of the symbolic solution equals m v0 a identically, for every e; the same holds about any fixed point y".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "m v a + I omega after the impact equals m v0 a (generic solver, any e)",
                printed,
                f("m") * &f("v0") * &f("a"),
            ),
            Certificate::identity(
                "angular momentum about an arbitrary fixed point (0, y) is the same after as before (generic solver, any e)",
                Formula::named("L_after", angular_momentum(&p, &after, &y)),
                Formula::named("L_before", angular_momentum(&p, &before, &y)),
            ),
        ]),
    }
}
