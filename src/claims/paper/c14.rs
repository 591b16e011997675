use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C14",
    location: "Eq. (V)",
    group: Group::Equations,
    statement: "V = (2m/M)/D v0",
    formalise,
};

fn formalise(paper: &Paper) -> Formalised {
    elastic_formula(&ENTRY, "V", elastic().rod_v, &paper.big_v)
}
