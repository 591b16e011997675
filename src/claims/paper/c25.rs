use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C25",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M <= 2m implies 0 < a* <= l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds("M <= 2m: 0 < a* <= l", "0 < s and s <= l")],
    )
    .at(&[])
    .given(&["M <= 2*m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let a2 = a_star_squared(&uniform_inertia());
    let a2_positive = positive(
        "a*^2 = (M + m) l^2/(3m) > 0, so a* = sqrt(a*^2) > 0",
        a2,
        true,
        &[],
        &["m", "M", "l"],
        &[],
        PosExpr::quotient(
            prod([sum([ps("M"), ps("m")]), ps("l"), ps("l")]),
            prod([pc(3, 1), ps("m")]),
        ),
    );
    Formalised {
        formal: "Uniform rod (I = M l^2/3), m, M, l > 0: a*^2 = (M + m) l^2/(3m) > 0, and if M <= 2m, \
                 written 2m = M + q with q >= 0, then l^2 - a*^2 >= 0; as a*, l > 0 this is 0 < a* <= l, \
                 so a* lies on the rod (it is the maximiser over [0, l] by C20)."
            .into(),
        reason: "with 2m = M + q (q >= 0), l^2 - a*^2 = 2 q l^2/(3(M + q)) >= 0, and a*^2 > 0".into(),
        decision: Decision::Proved(vec![a2_positive, room_at_the_end(paper, false)]),
    }
}
