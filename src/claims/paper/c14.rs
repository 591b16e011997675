use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C14",
    location: "Eq. (V)",
    group: Group::Equations,
    statement: "V = (2m/M)/D v0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[Check::holds(
        "Eq. (V)",
        "V = (2*m/M)/(1 + m/M + m*a^2/I)*v0",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    elastic_formula(&ENTRY, "V", elastic().rod_v, &paper.big_v)
}
