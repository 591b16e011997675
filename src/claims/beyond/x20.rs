use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X20",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The rod's share of the angular momentum, I omega/(m v0 a) = (1+e)/D, decreases strictly with a",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution),
        &[
            Check::holds(
                "the rod's share I omega/(m v0 a) = (1+e)/D",
                "I*omega/(m*v0*a) = (1 + e)/(1 + m/M + m*a^2/I)",
            )
            .given(&["a > 0"]),
            Check::holds(
                "the share decreases strictly with a > 0",
                "0 < a1 and a1 < a2 => I*omega_2/(m*v0*a2) < I*omega_1/(m*v0*a1)",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (m, a, t, v0, inertia) = (sym("m"), sym("a"), sym("t"), sym("v0"), sym("I"));
    let after = motion(&free_rod(inertia.clone(), sym("e")));
    let share = inertia.clone() * &after.omega / (m * &v0 * &a);
    let shifted = subs(&share, &[("a", a.clone() + &t)]);
    let certs = vec![
        Certificate::identity(
            "rod's share of the angular momentum I omega/(m v0 a) (generic solver, any e) = (1+e)/D",
            f("I") * &n("omega", after.omega.clone()) / &(f("m") * &f("v0") * &f("a")),
            (Formula::int(1) + &f("e"))
                / &(Formula::int(1) + &(f("m") / &f("M")) + &(f("m") * &f("a").pow(2) / &f("I"))),
        ),
        positive(
            "a >= 0, t > 0: share(a) - share(a + t) = (1+e) m t (2a + t)/(I D(a) D(a + t)) > 0",
            share - &shifted,
            true,
            &[],
            &["m", "M", "I", "t"],
            &["a", "e"],
            PosExpr::quotient(
                PosExpr::product([
                    one_plus_e(),
                    ps("m"),
                    ps("t"),
                    PosExpr::sum([PosExpr::product([pc(2, 1), ps("a")]), ps("t")]),
                ]),
                PosExpr::product([ps("I"), d_form(a.clone()), d_form(a + &t)]),
            ),
        ),
    ];
    Formalised {
        formal: "Free rod, m, M, I, v0 > 0, e in [0, 1], a > 0 (at a = 0 the share is 0/0 and is read as its limit \
                 (1+e)/(1 + m/M) = J/(m v0)). The rod's angular momentum about the centre divided by the total \
                 m v0 a is (1+e)/D with D = 1 + m/M + m a^2/I; for 0 <= a < a + t it drops by \
                 (1+e) m t (2a + t)/(I D(a) D(a+t)) > 0: strictly decreasing on a >= 0."
            .into(),
        reason: "the share is (1+e)/D identically and D grows strictly with a^2".into(),
        decision: Decision::Proved(certs),
    }
}
