use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X26",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Second impact (outside the paper's single-impulse model). In the rod-centre frame the projectile meets the rod's line when tan tau = kappa tau, where tau = omega t and kappa = (v - V)/(a omega) = (s^2 - e)/((1+e)s^2), s = a/a*. The root tau1 in (pi/2, 3pi/2) is unique because 1 - kappa >= 0. The impact recurs iff a <= l|cos tau1| (kappa = 0 gives tau1 = pi)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Unstated(
    "the second impact is decided by the root of tan tau = kappa tau, a transcendental equation outside real arithmetic",
);

fn formalise(paper: &Paper) -> Formalised {
    let (m, big_m, a, e, inertia) = (sym("m"), sym("M"), sym("a"), sym("e"), sym("I"));
    let after = motion(&free_rod(inertia.clone(), e.clone()));
    let kappa = (after.v.clone() - &after.rod_v) / (a.clone() * &after.omega);
    let kappa_f = (n("v", after.v.clone()) - &n("V", after.rod_v.clone()))
        / &(f("a") * &n("omega", after.omega.clone()));
    let s2_f = n("s^2", f("a").pow(2) / &paper.a_star_squared);
    let s2_form = || {
        PosExpr::quotient(
            PosExpr::product([ps("m"), ps("M"), ps("a"), ps("a")]),
            PosExpr::product([ps("I"), PosExpr::sum([ps("M"), ps("m")])]),
        )
    };
    let e_at_kappa_zero = a.clone() * &a * &m * &big_m / (inertia * &(big_m.clone() + &m));
    let certs = vec![
        Certificate::identity(
            "kappa = (v - V)/(a omega) (generic solver, any e) = (s^2 - e)/((1+e) s^2), s^2 = a^2/a*^2 (Eq. (maximal-a-general))",
            kappa_f.clone(),
            (s2_f.clone() - &f("e")) / &((Formula::int(1) + &f("e")) * &s2_f),
        ),
        positive(
            "1 - kappa = e (1 + s^2)/((1+e) s^2) >= 0 (a > 0): no root of tan tau = kappa tau in (0, pi/2], g' >= 1 - kappa >= 0",
            int(1) - &kappa,
            false,
            &[],
            &["m", "M", "I", "a"],
            &["e"],
            PosExpr::quotient(
                PosExpr::product([ps("e"), PosExpr::sum([pc(1, 1), s2_form()])]),
                PosExpr::product([one_plus_e(), s2_form()]),
            ),
        ),
        Certificate::identity_at(
            "e = s^2 = a^2/a*^2 gives kappa = 0 (then tan tau1 = 0 in (pi/2, 3pi/2): tau1 = pi)",
            kappa_f,
            int(0),
            &[("e", e_at_kappa_zero)],
        ),
    ];
    Formalised {
        formal: "Free rod, m, M, I, v0 > 0, e in [0, 1], 0 < a <= l (so omega > 0); after the single impulse both bodies \
                 move freely. Certified: kappa = (v - V)/(a omega) = (s^2 - e)/((1+e) s^2) with s = a/a*, \
                 1 - kappa = e (1 + s^2)/((1+e) s^2) >= 0, and kappa = 0 exactly when s^2 = e. Analytic steps \
                 (not machine-checked): in the frame of the rod's centre (uniform motion) the projectile is at \
                 ((v - V) t, a) and the rod's line has direction (sin tau, cos tau), tau = omega t (the point at y \
                 moves with omega y along x); they meet when (v - V) t cos tau = a sin tau, i.e. tan tau = kappa tau \
                 (cos tau = 0 is no solution as a > 0). On (0, pi/2) tan tau > tau >= kappa tau (kappa <= 1), so \
                 there is no earlier meeting. On (pi/2, 3pi/2) g = tan tau - kappa tau runs from -oo to +oo with \
                 g' = sec^2 tau - kappa >= 1 - kappa >= 0, vanishing at most at tau = pi: g is strictly increasing, \
                 one root tau1 (tau1 = pi when kappa = 0). There cos tau1 < 0, so it is the other arm, and the \
                 meeting point lies at distance a/|cos tau1| = sqrt(a^2 + ((v - V) t)^2) from the centre; this \
                 distance grows with t, so later meetings of the line are farther out. Hence a second impact \
                 happens iff a/|cos tau1| <= l, i.e. a <= l |cos tau1|."
            .into(),
        reason: "the solver gives kappa = (s^2 - e)/((1+e)s^2) and 1 - kappa = e(1 + s^2)/((1+e)s^2) >= 0; the root's uniqueness and the recurrence test follow analytically".into(),
        decision: Decision::Proved(certs),
    }
}
