use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C29",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M << m gives a* close to l/sqrt3",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[
            Check::holds(
                "a*^2 - l^2/3 = (M/m) l^2/3, which tends to 0 as M/m -> 0",
                "s^2 - l^2/3 = (M/m)*l^2/3",
            ),
            Check::holds(
                "and a* is the maximiser of omega over a >= 0",
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
    let l2 = sq(&sym("l"));
    let third = l2.clone() / k(3, 1);
    let excess = positive(
        "a*^2 - l^2/3 = (M/m) l^2/3 > 0: a* > l/sqrt3 always, with relative excess M/m in a*^2",
        paper.a_star_uniform_squared.clone() - &third,
        true,
        &[],
        &["m", "M", "l"],
        &[],
        PosExpr::quotient(prod([ps("M"), ps("l"), ps("l")]), prod([pc(3, 1), ps("m")])),
    );
    Formalised {
        formal: "Uniform rod, m, l, v0 > 0: as M -> 0+ (M/m -> 0) the printed a*^2 tends to l^2/3, and the \
                 solver's d omega/da tends to 2 v0 (l^2/3 - a^2)/(l^2/3 + a^2)^2, whose zero is a = l/sqrt3. \
                 Precisely, a*^2 = (1 + M/m) l^2/3 > l^2/3: a* approaches l/sqrt3 from above and never \
                 reaches it (the paper's 'nearly as small as')."
            .into(),
        reason: "a*^2 = (1 + M/m) l^2/3 -> l^2/3 as M/m -> 0, from above".into(),
        decision: Decision::Proved(vec![
            Certificate::limit(
                "the printed a*^2 = (M + m) l^2/(3m) tends to l^2/3 as M -> 0+",
                paper.a_star_uniform_squared.clone(),
                "M",
                crate::field::ratfunc::Point::Zero,
                third.clone(),
            ),
            Certificate::limit(
                "the solver's d omega/da (uniform rod) tends to 2 v0 (l^2/3 - a^2)/(l^2/3 + a^2)^2 as M -> 0+",
                uniform_slope(&sym("M")),
                "M",
                crate::field::ratfunc::Point::Zero,
                slope_with_peak_at(&third),
            ),
            excess,
        ]),
    }
}
