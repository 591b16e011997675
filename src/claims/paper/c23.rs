use crate::claims::dsl::*;
use crate::field::Sym;

pub(super) const ENTRY: Entry = Entry {
    id: "C23",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M > 2m implies a* > l (unphysical)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds("M > 2m: a* > l", "s > l")],
    )
    .at(&[])
    .given(&["M > 2*m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    // Independent derivation: a*^2 = I (M + m)/(m M) with I = M l^2/3.
    let expr = a_star_squared(&uniform_inertia()) - &(sym("l") * &sym("l"));
    let threshold_mass = paper.threshold.clone() * &sym("m") + &sym("q");
    Formalised {
        formal: "Uniform rod (I = M l^2/3), m, l > 0: if M > 2m then a*^2 - l^2 > 0, i.e. the stationary \
                 point a* = sqrt((M + m)/(3m)) l lies beyond the end of the rod."
            .into(),
        reason: "with M = 2m + q (q > 0), a*^2 - l^2 = q l^2/(3m) > 0".into(),
        decision: Decision::Proved(vec![Certificate::Positive(Positive {
            title: "a*^2 - l^2 > 0 for M = 2m + q, q > 0".into(),
            expr,
            strict: true,
            substitutions: vec![(Sym::new("M"), threshold_mass.into())],
            positive: vec![Sym::new("m"), Sym::new("q"), Sym::new("l")],
            nonnegative: vec![],
            form: PosExpr::quotient(
                PosExpr::product([PosExpr::sym("q"), PosExpr::sym("l"), PosExpr::sym("l")]),
                PosExpr::product([PosExpr::constant(3, 1), PosExpr::sym("m")]),
            ),
        })]),
    }
}
