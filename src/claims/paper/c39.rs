use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C39",
    location: "after (impulse-angular)",
    group: Group::Intuition,
    statement: "For M large enough, a = l wins",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds(
            "M >= 2m: a = l wins on [0, l]",
            "0 <= a and a < l => omega < omega_l",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "l", tag: "l" },
    ])
    .given(&["M >= 2*m"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let big_m = paper.threshold.clone() * &sym("m") + &sym("q");
    let l = plus("a", "s");
    let form = quot(
        prod([
            pc(3, 1),
            ps("m"),
            one_plus_e(),
            ps("v0"),
            ps("s"),
            sum([
                prod([pc(3, 1), ps("m"), ps("s")]),
                prod([ps("q"), l.clone()]),
            ]),
        ]),
        prod([
            l.clone(),
            sum([prod([pc(6, 1), ps("m")]), ps("q")]),
            sum([
                prod([sum([prod([pc(3, 1), ps("m")]), ps("q")]), l.clone(), l]),
                prod([pc(3, 1), ps("m"), ps("a"), ps("a")]),
            ]),
        ]),
    );
    Formalised {
        formal: "Uniform rod (I = M l^2/3), any e in [0, 1]: for M >= 2m (the paper's threshold) \
                 omega(l) > omega(a) for every 0 <= a < l, so the maximum over [0, l] is at a = l, \
                 uniquely. The threshold is sharp (for M < 2m the maximum is inside, C27)."
            .into(),
        reason: "with M = 2m + q (q >= 0) and l = a + s (s > 0), omega(l) - omega(a) is a visibly positive fraction".into(),
        decision: Decision::Proved(vec![end_beats_interior("uniform rod, M = 2m + q (q >= 0, the paper's threshold): omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s); omega from the solver", uniform_inertia(), &[("M", big_m.into())], &["m", "v0", "s"], &["a", "q", "e"], form)]),
    }
}
