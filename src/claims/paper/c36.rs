use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C36",
    location: "after (impulse-linear)",
    group: Group::Intuition,
    statement: "I_lin decreases as a increases",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds(
            "I_lin = M V decreases as a increases (a >= 0)",
            "0 <= a1 and a1 < a2 => M*V_2 < M*V_1",
        )],
    )
    .at(&[
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ]),
);

fn formalise(paper: &Paper) -> Formalised {
    let lin = &paper.impulse_linear;
    let expr = lin.clone() - &at_a(lin, sym("a") + &sym("t"));
    let den = |x: PosExpr| {
        sum([
            prod([ps("M"), ps("l"), ps("l")]),
            prod([ps("m"), ps("l"), ps("l")]),
            prod([pc(3, 1), ps("m"), x.clone(), x]),
        ])
    };
    let form = quot(
        prod([
            pc(6, 1),
            ps("m"),
            ps("m"),
            ps("M"),
            ps("l"),
            ps("l"),
            ps("v0"),
            ps("t"),
            sum([prod([pc(2, 1), ps("a")]), ps("t")]),
        ]),
        prod([den(ps("a")), den(plus("a", "t"))]),
    );
    Formalised {
        formal: "On the physical domain a >= 0 (I_lin is even in a): I_lin(a) - I_lin(a + t) > 0 for all \
                 a >= 0, t > 0, for Eq. (impulse-linear) (uniform rod, elastic) and for the solver's \
                 impulse with any I and any e."
            .into(),
        reason: "I_lin(a) - I_lin(a + t) = 6 m^2 M l^2 v0 t (2a + t)/(D1 D2) > 0 with D1, D2 visibly positive".into(),
        decision: Decision::Proved(vec![
            positive("Eq. (impulse-linear): I_lin(a) - I_lin(a + t) > 0 for a >= 0, t > 0", expr, true, &[], &["m", "M", "l", "v0", "t"], &["a"], form),
            impulse_decreasing(),
        ]),
    }
}
