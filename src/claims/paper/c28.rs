use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C28",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M = m gives a* = sqrt(2/3) l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds("M = m: a*^2 = 2 l^2/3", "s^2 = 2*l^2/3")],
    )
    .at(&[])
    .given(&["M = m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let m = sym("m");
    let target = k(2, 3) * &sq(&sym("l"));
    Formalised {
        formal: "Uniform rod, m, l, v0 > 0, M = m: the printed a*^2 = (M + m) l^2/(3m) equals 2 l^2/3, so \
                 a* = sqrt(2/3) l (l > 0); independently, the solver's d omega/da vanishes on a > 0 only \
                 at a^2 = 2 l^2/3."
            .into(),
        reason: "at M = m the printed a*^2 is 2 l^2/3, where the solver's slope vanishes".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed a*^2 = (M + m) l^2/(3m) at M = m equals 2 l^2/3",
                paper.a_star_uniform_squared.clone(),
                target.clone(),
                &[("M", m.clone())],
            ),
            stationary_at(&m, "m", &target),
        ]),
    }
}
