use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C16",
    location: "case (i)",
    group: Group::LimitingCases,
    statement: "a = 0 gives omega = 0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[Check::holds("a = 0: omega = 0, any restitution", "omega = 0").given(&["a = 0"])],
));

fn formalise(paper: &Paper) -> Formalised {
    let centre = [("a", k(0, 1))];
    Formalised {
        formal: "For m, M, I > 0 and any v0: Eq. (omega) at a = 0 is 0, and so is the generic \
                 solver's omega at a = 0 for every restitution e (a central impulse exerts no torque \
                 about the centre)."
            .into(),
        reason: "Eq. (omega) and the solver's omega (any e) vanish identically at a = 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at("Eq. (omega) at a = 0 is 0", paper.omega.clone(), k(0, 1), &centre),
            Certificate::identity_at(
                "the generic solver's omega at a = 0 is 0 for every e",
                Formula::named("omega", motion(&rod(sym("e"))).omega),
                k(0, 1),
                &centre,
            ),
        ]),
    }
}
