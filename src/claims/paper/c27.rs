use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "C27",
    location: "§optimum ¶2",
    group: Group::Optimum,
    statement: "M < 2m: the unique maximiser on [0,l] is a* < l, and omega(a*) > omega(l)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds(
            "M < 2m: a* < l, omega(a*) > omega(l), and a* is the only maximiser on [0, l]",
            "s < l and omega_s > omega_l and (0 <= a and a <= l and a != s => omega < omega_s)",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
        StrikePoint { at: "l", tag: "l" },
    ])
    .given(&["M < 2*m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let omega = uniform_omega();
    let model = ("M", mass_through_a_star());
    let peak = Peak {
        model: vec![model.clone()],
        positive: vec!["m", "v0"],
        ..omega_peak(omega.clone(), prod([pc(2, 1), ps("v0")]))
    };
    // omega(a*) - omega(l) with l = A + t: the right-of-peak form at a = l.
    let at_end = subs(&omega, &[("a", sym("l"))]);
    let end_gap = positive(
        "omega(a*) - omega(l) > 0 when a* < l: l = A + t, t > 0",
        subs(&omega, &[("a", sym("A"))]) - &at_end,
        true,
        &compose(std::slice::from_ref(&model), &[("l", sym("A") + &sym("t"))]),
        &["m", "v0", "A", "t"],
        &[],
        PosExpr::quotient(
            prod([pc(2, 1), ps("v0"), ps("t"), ps("t")]),
            prod([
                pc(2, 1),
                ps("A"),
                sum([
                    prod([ps("A"), ps("A")]),
                    prod([sum([ps("A"), ps("t")]), sum([ps("A"), ps("t")])]),
                ]),
            ]),
        ),
    );
    let root = sqrt(&crate::field::q(2, 3));
    let witness = Certificate::witness(
        "M = m = l = v0 = 1: omega(sqrt(2/3)) = sqrt(3/2) > omega(1) = 6/5",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
            ("a", root),
        ]),
        omega,
        Relation::Gt,
        at_end,
    );
    let link = a_star_link(
        "a*^2 = (M + m) l^2/(3m)",
        &paper.a_star_uniform_squared,
        model,
    );
    let mut certs = vec![room_at_the_end(paper, true), link];
    certs.extend(peak.certificates());
    certs.extend([end_gap, witness]);
    Formalised {
        formal: "Uniform rod (I = M l^2/3), m, M, l, v0 > 0, elastic omega from the generic solver. If \
                 M < 2m (2m = M + q, q > 0) then a* < l. Writing M = 3 m A^2/l^2 - m with A > 0 (every \
                 M > 0 is reached; the printed a*^2 is then A^2), omega(A) - omega(a) >= 0 for every a, \
                 strictly for every a >= 0 other than A: A = a* is the unique maximiser on [0, l], and \
                 omega(a*) - omega(l) > 0 (l = A + t). Example: M = m, a* = sqrt(2/3) l."
            .into(),
        reason: "2m = M + q gives l^2 - a*^2 = 2ql^2/(3(M + q)) > 0, and omega(a*) - omega(a) = \
                 v0 (a - a*)^2/(a*(a*^2 + a^2)) > 0 for a != a*"
            .into(),
        decision: Decision::Proved(certs),
    }
}

/// `M = 3 m A^2/l^2 - m`: the uniform rod's mass written through A, a positive symbol for a*.
/// Every m, M, l > 0 is reached, with A = sqrt((M + m)/(3m)) l.
fn mass_through_a_star() -> RatFn {
    let (m, l) = (sym("m"), sym("l"));
    k(3, 1) * &m * &sq(&sym("A")) / sq(&l) - &m
}
