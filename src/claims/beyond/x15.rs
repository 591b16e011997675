use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X15",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The elastic rod takes all of K0 where the projectile stops (a0), not at a*: a*^2 - a0^2 = 2l^2/3",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[
            Check::holds(
                "v = v0 (a^2 - a0^2)/(a^2 + a*^2), a0^2 = l^2 (M - m)/(3m)",
                "v = v0*(a^2 - z)/(a^2 + s^2)",
            ),
            Check::holds(
                "the rod's energy is K0 (1 - (v/v0)^2): all of K0 exactly where v = 0",
                "M*V^2 + I*omega^2 = m*v0^2*(1 - (v/v0)^2)",
            ),
            Check::holds("a*^2 - a0^2 = 2 l^2/3", "s^2 - z = 2*l^2/3"),
            Check::holds(
                "at a* the projectile keeps v = v0 l^2/(3 a*^2) > 0",
                "v_s = v0*l^2/(3*s^2) and v_s > 0",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["z = l^2*(M - m)/(3*m)", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let (m, big_m, l, a, v0) = (sym("m"), sym("M"), sym("l"), sym("a"), sym("v0"));
    let p = free_rod(uniform_inertia(), int(1));
    let after = motion(&p);
    let a0_squared = l.clone() * &l * &(big_m.clone() - &m) / (k(3, 1) * &m);
    let a2 = a.clone() * &a;
    let k0 = m.clone() * &v0 * &v0 / k(2, 1);
    let rod_energy = (big_m.clone() * &after.rod_v * &after.rod_v
        + &(p.inertia.clone() * &after.omega * &after.omega))
        / k(2, 1);
    let two = Formula::int(2);
    let (a0_f, a_star2_f) = (
        n("a0^2", a0_squared.clone()),
        n("a*^2", paper.a_star_uniform_squared.clone()),
    );
    let ratio_f = (f("a").pow(2) - &a0_f) / &(f("a").pow(2) + &a_star2_f);
    // a = a*, i.e. M = 3 m a^2/l^2 - m.
    let mass_at_a_star = k(3, 1) * &m * &a2 / (l.clone() * &l) - &m;
    let certs = vec![
        Certificate::identity(
            "elastic uniform rod: v (generic solver) = v0 (a^2 - a0^2)/(a^2 + a*^2), a0^2 = l^2 (M - m)/(3m), a*^2 of Eq. (maximal-a-homogeneous)",
            n("v", after.v.clone()),
            f("v0") * &ratio_f,
        ),
        Certificate::identity(
            "the rod's energy M V^2/2 + I omega^2/2 = K0 (1 - ((a^2 - a0^2)/(a^2 + a*^2))^2): all of K0 iff a^2 = a0^2",
            f("M") * &n("V", after.rod_v.clone()).pow(2) / &two
                + &(n("I", p.inertia.clone()) * &n("omega", after.omega.clone()).pow(2) / &two),
            f("m") * &f("v0").pow(2) / &two * &(Formula::int(1) - &ratio_f.pow(2)),
        ),
        Certificate::identity(
            "a*^2 - a0^2 = 2 l^2/3 (a* from Eq. (maximal-a-homogeneous))",
            a_star2_f.clone() - &a0_f,
            Formula::int(2) * &f("l").pow(2) / &Formula::int(3),
        ),
        Certificate::identity_at(
            "with M = 3 m a^2/l^2 - m the impact point a is the paper's a*",
            paper.a_star_uniform_squared.clone(),
            f("a").pow(2),
            &[("M", mass_at_a_star.clone())],
        ),
        positive(
            "at a = a* (M = 3 m a^2/l^2 - m): K0 - rod energy = m v0^2 l^4/(18 a^4) > 0, so not all of K0",
            k0 - &rod_energy,
            true,
            &[("M", mass_at_a_star)],
            &["m", "v0", "l", "a"],
            &[],
            PosExpr::quotient(
                PosExpr::product([
                    ps("m"),
                    ps("v0"),
                    ps("v0"),
                    ps("l"),
                    ps("l"),
                    ps("l"),
                    ps("l"),
                ]),
                PosExpr::product([pc(18, 1), ps("a"), ps("a"), ps("a"), ps("a")]),
            ),
        ),
    ];
    Formalised {
        formal: "Uniform rod (I = M l^2/3), e = 1, m, M, l, v0 > 0, 0 <= a <= l. The generic solver gives \
                 v = v0 (a^2 - a0^2)/(a^2 + a*^2) with a0^2 = l^2 (M - m)/(3m), and the rod's kinetic energy is \
                 K0 (1 - (v/v0)^2): it equals K0 exactly where v = 0, i.e. at a = a0. Such a point exists on the \
                 rod only when 0 <= a0^2 <= l^2, i.e. m <= M <= 4m; otherwise no impact point gives the rod all \
                 of K0. a*^2 - a0^2 = 2 l^2/3 > 0 identically, so a0 != a*; at a = a* the projectile keeps \
                 v = v0 l^2/(3 a*^2) > 0 and the rod's energy falls short of K0 by m v0^2 l^4/(18 a*^4)."
            .into(),
        reason: "v = v0 (a^2 - a0^2)/(a^2 + a*^2) vanishes only at a0, and a*^2 - a0^2 = 2l^2/3 identically".into(),
        decision: Decision::Proved(certs),
    }
}
