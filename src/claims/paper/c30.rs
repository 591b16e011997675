use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C30",
    location: "§optimum ¶2",
    group: Group::Inelastic,
    statement: "\"Exactly the same behaviour\" for a totally inelastic (sticking) collision",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Sticking),
        &[Check::holds(
            "sticking: omega = m a v0/(I + mu a^2) is maximal at the same a* over a >= 0",
            "a >= 0 and a != s => omega < omega_s",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let stuck = sticking(sym("I"));
    let halved = Certificate::identity(
        "sticking (composite body: CM y_c = m a/(M + m), I_c by parallel axes, angular momentum about y_c) \
         gives omega_inel = omega_el/2 for every a, with omega_el from the generic solver (e = 1)",
        Formula::named("omega_inel", stuck.omega.clone()),
        Formula::named("omega_el", elastic_omega(sym("I"))) / &Formula::int(2),
    );
    let link = a_star_link(
        "a*^2 = (M + m) I/(m M)",
        &paper.a_star_squared,
        ("I", inertia_through_a_star()),
    );
    let peak = omega_peak(stuck.omega, ps("v0"));
    let uniform_stuck = sticking(uniform_inertia()).omega;
    let mut certs = vec![halved, link];
    certs.extend(peak.certificates());
    certs.push(increasing_on_rod(
        paper,
        &uniform_stuck,
        3,
        "sticking omega (uniform rod)",
    ));
    Formalised {
        formal: "Behaviour = how omega depends on a: its maximiser and the threshold M = 2m. Sticking: the \
                 projectile stays at y = a; the pair is one rigid body with CM y_c = m a/(M + m) and \
                 I_c = I + M y_c^2 + m (a - y_c)^2; omega_inel = (angular momentum about y_c)/I_c. For all \
                 m, M, I, v0 > 0 and every a, omega_inel = omega_el/2, a positive multiple, so the \
                 maximiser and monotonicity are the same; checked directly: with I = A^2 m M/(M + m), \
                 omega_inel(A) - omega_inel(a) > 0 for a != A (same a*, hence the same threshold, a* = l \
                 at M = 2m, sqrt(2/3) l at M = m, l/sqrt3 as M -> 0), and on the uniform rod with M > 2m \
                 omega_inel increases strictly on [0, l]. omega itself is half the elastic value (and \
                 energy is lost), which the paper's 'behaviour' does not concern."
            .into(),
        reason: "omega_inel(a) = omega_el(a)/2 for every a: the same a* and threshold, only the scale halves"
            .into(),
        decision: Decision::Proved(certs),
    }
}
