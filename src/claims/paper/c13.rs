use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C13",
    location: "Eq. (v)",
    group: Group::Equations,
    statement: "v = -(1 - m/M - ma^2/I)/D v0, with D > 0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[
        Check::holds("Eq. (v)", "v = -(1 - m/M - m*a^2/I)/(1 + m/M + m*a^2/I)*v0"),
        Check::holds("D > 0", "1 + m/M + m*a^2/I > 0"),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
    elastic_formula(&ENTRY, "v", elastic().v, &paper.v)
}
