use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C24",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "If M > 2m, omega is strictly increasing on [0,l], so the maximum is at a = l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds(
            "M > 2m: omega strictly increasing on [0, l]",
            "0 <= a1 and a1 < a2 and a2 <= l => omega_1 < omega_2",
        )],
    )
    .at(&[
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ])
    .given(&["M > 2*m"]),
);

fn formalise(paper: &Paper) -> Formalised {
    Formalised {
        formal: "Uniform rod (I = M l^2/3), m, v0, l > 0, M = 2m + q with q > 0, elastic omega from the \
                 generic solver: for all 0 <= a1 < a2 <= l (a2 = a1 + t, l = a1 + t + s, t > 0, s >= 0), \
                 omega(a2) - omega(a1) > 0. Hence the maximum over [0, l] is at a = l and only there."
            .into(),
        reason: "with M = 2m + q and l = a + t + s, omega(a + t) - omega(a) = 6 m v0 t (3m(t^2 + s^2 + at + \
                 2as + 2ts) + q l^2)/(positive) > 0"
            .into(),
        decision: Decision::Proved(vec![increasing_on_rod(
            paper,
            &uniform_omega(),
            6,
            "elastic omega (generic solver, uniform rod)",
        )]),
    }
}
