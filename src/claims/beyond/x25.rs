use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X25",
    location: BEYOND,
    group: Group::Beyond,
    statement: "After the impact the rod's K_rot/K_trans = a^2/r_G^2 for any m and e (uniform rod hit at the end: 3)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Restitution),
    &[
        Check::holds("K_rot/K_trans = a^2/r_G^2", "I*omega^2 = (a^2/r^2)*M*V^2"),
        Check::holds("uniform rod hit at the end: 3", "I*omega^2 = 3*M*V^2")
            .given(&["3*r^2 = l^2", "a = l"]),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
    let l = sym("l");
    let ratio = |inertia: Formula| {
        let after = motion(&free_rod(inertia.clone(), sym("e")));
        (n("I", inertia) * &n("omega", after.omega).pow(2) / &Formula::int(2))
            / &(f("M") * &n("V", after.rod_v).pow(2) / &Formula::int(2))
    };
    let certs = vec![
        Certificate::identity(
            "K_rot/K_trans = (I omega^2/2)/(M V^2/2) (generic solver, I = M r_G^2, any m, e) = a^2/r_G^2",
            ratio(gyration_inertia().into()),
            f("a").pow(2) / &f("r_G").pow(2),
        ),
        Certificate::identity_at(
            "uniform rod (Eq. (inertia-homogeneous)) hit at the end a = l: K_rot/K_trans = 3",
            ratio(paper.uniform_inertia.clone()),
            int(3),
            &[("a", l)],
        ),
    ];
    Formalised {
        formal: "Free rod, I = M r_G^2, m, M, r_G, v0 > 0, e in [0, 1] (so V = J/M > 0 and the ratio is defined), \
                 any a: (I omega^2/2)/(M V^2/2) = a^2/r_G^2, independent of m, v0 and e (omega = J a/I and \
                 V = J/M share the impulse J). Uniform rod hit at a = l: 3."
            .into(),
        reason: "omega/V = M a/I, so I omega^2/(M V^2) = M a^2/I = a^2/r_G^2 identically".into(),
        decision: Decision::Proved(certs),
    }
}
