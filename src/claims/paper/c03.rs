use crate::claims::dsl::*;
use crate::field::Sym;

pub(super) const ENTRY: Entry = Entry {
    id: "C3",
    location: "intro ¶2; §optimum ¶1",
    group: Group::Introduction,
    statement: "Intuition: \"omega increases with a, maximum at a = l whatever the masses\"",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::fails(
            "the intuition, refuted at M = m = l = v0 = 1 between a1 = a* (a1^2 = 2/3) and a2 = l",
            "0 <= a1 and a1 < a2 and a2 <= l => omega_1 < omega_2",
        )
        .given(&["m = 1", "M = 1", "l = 1", "v0 = 1", "a1^2 = 2/3", "a2 = 1"])],
    )
    .at(&[
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ])
    .given(&["a1 >= 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let slope = uniform_omega().derivative(Sym::new("a"));
    let slope_at_end = subs(&slope, &[("a", sym("l"))]);
    let mut counterexample = vec![Certificate::witness(
        "uniform rod, M = m = l = v0 = 1: d omega/da at the end a = l is negative, so omega decreases towards the end",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
        ]),
        slope_at_end,
        Relation::Lt,
        k(0, 1),
    )];
    counterexample.extend(equal_masses_beat_the_end());
    Formalised {
        formal: "Natural reading: for every m, M > 0 (uniform rod, I = M l^2/3, elastic impact), \
                 omega is increasing on [0, l] and its maximum over [0, l] is at a = l. Refuted at \
                 M = m: there d omega/da < 0 at a = l, and omega(sqrt(2/3) l) > omega(l) exactly. \
                 (It holds for the uniform rod exactly when M >= 2m: see C23-C27.)"
            .into(),
        reason: "at M = m omega decreases at a = l and omega(sqrt(2/3) l) > omega(l); the intuition holds only for M >= 2m (uniform rod)".into(),
        decision: Decision::Refuted(counterexample),
    }
}
