use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C15",
    location: "Eq. (omega)",
    group: Group::Equations,
    statement: "omega = (2ma/I)/D v0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[Check::holds(
        "Eq. (omega) as printed, D = 1 + m/M + m a^2/I",
        "omega = (2*m*a/I)/(1 + m/M + m*a^2/I)*v0",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    elastic_formula(&ENTRY, "omega", elastic().omega, &paper.omega)
}
