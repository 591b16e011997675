use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C22",
    location: "Eq. (maximal-a-homogeneous)",
    group: Group::Optimum,
    statement: "a* = sqrt((M+m)/(3m)) l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[
            Check::holds(
                "a* = sqrt((M+m)/(3m)) l is the a*^2 = (M+m) I/(mM) of C20 for I = M l^2/3",
                "s^2 = (M + m)*I/(m*M)",
            ),
            Check::holds(
                "and the maximiser of omega over a >= 0",
                "a >= 0 and a != s => omega < omega_s",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let shape = peak_shape(Formula::named("a*^2", paper.a_star_uniform_squared.clone()));
    Formalised {
        formal: "For the uniform rod (I = M l^2/3) with m, M, l, v0 > 0: the printed a*^2 = (M + m) l^2/(3m) \
                 is Eq. (maximal-a-general) with Eq. (inertia-homogeneous) substituted, and the solver's \
                 elastic omega is 2 v0 a/(a*^2 + a^2) with exactly this a*^2, so (C20) the maximiser over \
                 a > 0 is a* = sqrt((M + m)/(3m)) l (l > 0)."
            .into(),
        reason: "the printed a*^2 = (M + m) l^2/(3m) is (M + m) I/(m M) at I = M l^2/3, and the solver's omega \
                 is 2 v0 a/(a*^2 + a^2) with it"
            .into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "the printed (M + m) I/(m M) at the printed I = M (2l)^2/12 equals the printed (M + m) l^2/(3m)",
                paper.a_star_squared.clone(),
                paper.a_star_uniform_squared.clone(),
                &[("I", paper.uniform_inertia.value().clone())],
            ),
            Certificate::identity(
                "the solver's elastic omega for I = M l^2/3 equals 2 v0 a/(a*^2 + a^2) with the printed \
                 a*^2 = (M + m) l^2/(3m)",
                Formula::named("omega", uniform_omega()),
                shape,
            ),
        ]),
    }
}
