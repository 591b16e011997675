use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X24",
    location: BEYOND,
    group: Group::Beyond,
    statement: "For every e, the b^2 of the paper's f(x) argument is I(1/m + 1/M), with c = 1",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[Check::holds(
        "omega = (1+e) v0 f(a), f(x) = x/(b^2 + x^2), b^2 = I (1/m + 1/M)",
        "omega = (1 + e)*v0*a/(I*(1/m + 1/M) + a^2)",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    let after = motion(&free_rod(sym("I"), sym("e")));
    let one = Formula::int(1);
    let b2_f = n("b^2", f("I") * &(one.clone() / &f("m") + &(one / &f("M"))));
    let certs = vec![
        Certificate::identity(
            "omega (generic solver, any e) = (1+e) v0 * a/(b^2 + 1^2 a^2), b^2 = I (1/m + 1/M)",
            n("omega", after.omega),
            (Formula::int(1) + &f("e")) * &f("v0") * &f("a")
                / &(b2_f.clone() + &(Formula::int(1).pow(2) * &f("a").pow(2))),
        ),
        Certificate::identity(
            "b^2/c^2 with c = 1 is the paper's a*^2 (Eq. (maximal-a-general)): the maximiser x = b/c is a*",
            b2_f / &Formula::int(1).pow(2),
            paper.a_star_squared.clone(),
        ),
    ];
    Formalised {
        formal: "Free rod, m, M, I, v0 > 0, restitution e in [0, 1]: omega(a) = K f(a) with f(x) = x/(b^2 + c^2 x^2), \
                 K = (1+e) v0, c = 1 and b^2 = I (1/m + 1/M), independent of e and v0. (The split of omega into \
                 K, b, c is unique only up to K f = (lambda K) x/(lambda b^2 + lambda c^2 x^2); normalising c = 1 \
                 fixes b^2 as stated, and the maximiser b/c = a* is invariant.)"
            .into(),
        reason: "omega = (1+e) v0 a/(I(1/m + 1/M) + a^2) identically, and I(1/m + 1/M) is the paper's a*^2".into(),
        decision: Decision::Proved(certs),
    }
}
