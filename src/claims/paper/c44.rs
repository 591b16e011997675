use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C44",
    location: "§inhomogeneous",
    group: Group::Inhomogeneous,
    statement: "Ideal dumbbell (r_G = l): a* is always unphysical and the maximum is at a = l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Dumbbell, ExportLaw::Elastic),
        &[Check::holds(
            "a* > l always, and the maximum on [0, l] is at a = l",
            "s > l and (0 <= a and a < l => omega < omega_l)",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "l", tag: "l" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*l^2/m"]),
);

fn formalise(paper: &Paper) -> Formalised {
    Formalised {
        formal: "Ideal dumbbell (point masses M/2 at +-l, so I = M l^2, r_G = l), any m, M > 0, \
                 e in [0, 1]: a*^2 - l^2 = M l^2/m > 0, and omega(l) > omega(a) for every 0 <= a < l."
            .into(),
        reason: "a*^2 - l^2 = M l^2/m > 0 for all masses, and omega(l) - omega(a) is a visibly positive fraction for a < l".into(),
        decision: Decision::Proved(vec![dumbbell_a_star(paper), dumbbell_end_wins()]),
    }
}
