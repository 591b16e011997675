use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C26",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M = 2m gives a* = l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds("M = 2m: a* = l", "s = l")],
    )
    .at(&[])
    .given(&["M = 2*m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let mass = paper.threshold.clone() * &sym("m");
    let l2 = sq(&sym("l"));
    Formalised {
        formal: "Uniform rod, m, l, v0 > 0, M = 2m: the printed a*^2 = (M + m) l^2/(3m) equals l^2, so \
                 a* = l; independently, the solver's d omega/da is 2 v0 (l^2 - a^2)/(l^2 + a^2)^2, which \
                 vanishes on a > 0 only at a = l."
            .into(),
        reason: "at M = 2m the printed a*^2 is l^2, and the solver's slope 2 v0 (l^2 - a^2)/(l^2 + a^2)^2 \
                 vanishes at a = l"
            .into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed a*^2 = (M + m) l^2/(3m) at M = 2m equals l^2",
                paper.a_star_uniform_squared.clone(),
                l2.clone(),
                &[("M", mass.clone().into())],
            ),
            stationary_at(&mass, "2m", &l2),
        ]),
    }
}
