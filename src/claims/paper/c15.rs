use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C15",
    location: "Eq. (omega)",
    group: Group::Equations,
    statement: "omega = (2ma/I)/D v0",
    formalise,
};

fn formalise(paper: &Paper) -> Formalised {
    elastic_formula(&ENTRY, "omega", elastic().omega, &paper.omega)
}
