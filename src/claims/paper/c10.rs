use crate::claims::dsl::*;
use crate::scene::{Motion, kinetic_energy};

pub(super) const ENTRY: Entry = Entry {
    id: "C10",
    location: "Eq. (kinetic2)",
    group: Group::Equations,
    statement: "m(v0^2 - v^2) = (m^2/M)(v0 - v)^2 + (m^2 a^2/I)(v0 - v)^2",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Energy),
    &[Check::holds(
        "Eq. (kinetic2)",
        "m*(v0^2 - v^2) = (m^2/M)*(v0 - v)^2 + (m^2*a^2/I)*(v0 - v)^2",
    )],
));

fn formalise(_paper: &Paper) -> Formalised {
    let p = rod(k(1, 1));
    let v = f("v");
    let (big_v, omega) = momentum_split(&v);
    let trial = Motion {
        v: sym("v"),
        rod_v: big_v.value().clone(),
        omega: omega.value().clone(),
    };
    let before = Motion::before(sym("v0"));
    let twice_lost = Formula::int(2)
        * &(Formula::named("K0", kinetic_energy(&p, &before))
            - &Formula::named("K", kinetic_energy(&p, &trial)));
    Formalised {
        formal: "Substituting Eq. (linear-angular) into Eq. (kinetic): for a free symbol v, \
                 2 (m v0^2/2 - (m v^2 + M V^2 + I omega^2)/2) with V = (m/M)(v0 - v), \
                 omega = (ma/I)(v0 - v) equals the left side minus the right side of Eq. (kinetic2) \
                 identically. So (kinetic2) is (kinetic) restricted to the momentum laws; it holds \
                 for the elastic solution (e = 1)."
            .into(),
        reason: "twice the energy balance with V, omega of Eq. (linear-angular) is the (kinetic2) difference identically in v; the elastic v satisfies it".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "2 (K0 - K after) with Eq. (linear-angular), v free, equals lhs - rhs of Eq. (kinetic2)",
                twice_lost,
                kinetic2(&v),
            ),
            Certificate::identity(
                "the elastic v of the generic solver satisfies Eq. (kinetic2)",
                kinetic2(&Formula::named("v", elastic().v)),
                k(0, 1),
            ),
        ]),
    }
}
