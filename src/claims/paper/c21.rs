use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "C21",
    location: "Eq. (inertia-homogeneous)",
    group: Group::Optimum,
    statement: "I = M(2l)^2/12 = Ml^2/3",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Unstated(
    "an integral over the rod's mass density (the moment of inertia of the uniform rod), not a statement about finitely many reals",
);

fn formalise(paper: &Paper) -> Formalised {
    let (big_m, l) = (sym("M"), sym("l"));
    let density = big_m.clone() / (k(2, 1) * &l);
    let along = |title: &str, power: u32, expected: RatFn| {
        integral(title, density.clone(), power, whole_rod(), expected)
    };
    Formalised {
        formal: "A homogeneous thin rod of mass M on -l <= y <= l has the linear density M/(2l); its moment \
                 of inertia about the perpendicular axis through the centre is the integral of \
                 (M/(2l)) y^2 over [-l, l], which equals the printed M (2l)^2/12, and that is M l^2/3."
            .into(),
        reason: "the integral of (M/(2l)) y^2 over [-l, l] is M l^2/3 = M(2l)^2/12, and the density has mass M"
            .into(),
        decision: Decision::Proved(vec![
            along("the density M/(2l) on [-l, l] has total mass M", 0, big_m.clone()),
            along(
                "moment of inertia about the centre: integral of (M/(2l)) y^2 = the printed M (2l)^2/12",
                2,
                paper.uniform_inertia.value().clone(),
            ),
            Certificate::identity(
                "the printed M (2l)^2/12 equals M l^2/3",
                paper.uniform_inertia.clone(),
                Formula::from(big_m) * &Formula::from(l).pow(2) / &Formula::int(3),
            ),
        ]),
    }
}
