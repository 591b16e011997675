use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X28",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The stick/slide threshold in closed form (mu_f the Coulomb friction coefficient): the contact sticks iff mu_f >= mu_f* = |u_t| k_n/((1+e) u_n k_t), u_t the slip, u_n the approach speed, k_n = 1/m + 1/M + a^2/I and k_t = 1/m + 1/M (+ 2/m for a solid disc); at mu_f = mu_f* sliding and sticking give the same impulse",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: the physics of a sticking contact (the disc's contact point ends
// moving with the rod's) and the threshold in closed form; u_t = v0t + w rd.
const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution).oblique(Friction::Stick),
    &[
        Check::holds(
            "disc: the sticking impulse over the normal one is u_t k_n/((1+e) v0 k_t), k_t = 3/m + 1/M",
            "Jt*(1 + e)*v0*(3/m + 1/M) = J*(v0t + w*rd)*(1/m + 1/M + a^2/I)",
        )
        .given(&["rd > 0"]),
        Check::holds(
            "point (rd = 0): the sticking impulse over the normal one is v0t k_n/((1+e) v0 k_t), k_t = 1/m + 1/M",
            "Jt*(1 + e)*v0*(1/m + 1/M) = J*v0t*(1/m + 1/M + a^2/I)",
        )
        .given(&["rd = 0"]),
        Check::holds(
            "disc, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*",
            "((Jt <= mu_f*J and -Jt <= mu_f*J) => mu_f*(1 + e)*v0*(3/m + 1/M) >= (v0t + w*rd)*(1/m + 1/M + a^2/I)) and (mu_f*(1 + e)*v0*(3/m + 1/M) >= (v0t + w*rd)*(1/m + 1/M + a^2/I) => (Jt <= mu_f*J and -Jt <= mu_f*J))",
        )
        .given(&["rd > 0", "mu_f >= 0", "v0t + w*rd >= 0"]),
        Check::holds(
            "disc, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J, so slide and stick coincide",
            "Jt = mu_f*J",
        )
        .given(&["rd > 0", "mu_f*(1 + e)*v0*(3/m + 1/M) = (v0t + w*rd)*(1/m + 1/M + a^2/I)"]),
        Check::holds(
            "point, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*",
            "((Jt <= mu_f*J and -Jt <= mu_f*J) => mu_f*(1 + e)*v0*(1/m + 1/M) >= v0t*(1/m + 1/M + a^2/I)) and (mu_f*(1 + e)*v0*(1/m + 1/M) >= v0t*(1/m + 1/M + a^2/I) => (Jt <= mu_f*J and -Jt <= mu_f*J))",
        )
        .given(&["rd = 0", "mu_f >= 0", "v0t >= 0"]),
        Check::holds(
            "point, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J",
            "Jt = mu_f*J",
        )
        .given(&["rd = 0", "mu_f*(1 + e)*v0*(1/m + 1/M) = v0t*(1/m + 1/M + a^2/I)"]),
        Check::fails(
            "reading: the disc's moment of inertia taken as m rd^2/4 (k_t = 5/m + 1/M), it sticks once mu_f reaches that lower threshold; refuted",
            "mu_f*(1 + e)*v0*(5/m + 1/M) >= (v0t + w*rd)*(1/m + 1/M + a^2/I) => (Jt <= mu_f*J and -Jt <= mu_f*J)",
        )
        .given(&["rd > 0", "mu_f >= 0", "v0t + w*rd >= 0"]),
        Check::fails(
            "reading: a disc sticks only above the point's threshold (k_t = 1/m + 1/M); refuted",
            "(Jt <= mu_f*J and -Jt <= mu_f*J) => mu_f*(1 + e)*v0*(1/m + 1/M) >= (v0t + w*rd)*(1/m + 1/M + a^2/I)",
        )
        .given(&["rd > 0", "mu_f >= 0", "v0t + w*rd >= 0"]),
    ],
));

fn formalise(_paper: &Paper) -> Formalised {
    let rod = oblique_rod();
    let k_n =
        || Formula::int(1) / &f("m") + &(Formula::int(1) / &f("M")) + &(f("a").pow(2) / &f("I"));
    let mut certs = Vec::new();
    for disc in [false, true] {
        let o = oblique(disc);
        let (slip, k_t, projectile) = if disc {
            (
                f("v0t") + &(f("w") * &f("r")),
                Formula::int(3) / &f("m") + &(Formula::int(1) / &f("M")),
                "disc (u_t = v0t + w r, k_t = 3/m + 1/M)",
            )
        } else {
            (
                f("v0t"),
                Formula::int(1) / &f("m") + &(Formula::int(1) / &f("M")),
                "point (u_t = v0t, k_t = 1/m + 1/M)",
            )
        };
        let mu_star = slip.clone() * &k_n() / &((Formula::int(1) + &f("e")) * &f("v0") * &k_t);
        let stick = oblique_solved(&rod, &o, Mode::Stick);
        let slide = oblique_solved(&rod, &o, Mode::Slide { forward: true });
        certs.push(Certificate::identity(
            format!("{projectile}: stick impulse / normal impulse (solver) = u_t k_n/((1+e) v0 k_t), so |Jt_stick| <= mu_f J iff mu_f >= mu_f*"),
            n("Jt_stick", stick.tangential_impulse.clone()) / &n("J", stick.impulse.clone()),
            mu_star.clone(),
        ));
        certs.push(Certificate::identity_at(
            format!("{projectile}: at mu_f = mu_f* (u_t > 0) the sliding impulse (solver) equals the sticking one"),
            n("Jt_slide", slide.tangential_impulse.clone()),
            n("Jt_stick", stick.tangential_impulse.clone()),
            &[("mu_f", mu_star.value().clone())],
        ));
    }
    proved(
        "Free rod (m, M, I, v0 > 0, e in [0, 1], any a) at rest, struck by a point or a solid disc \
         (radius r, spin w) with v0 across and v0t along the rod: the solver's stick impulse over its \
         normal impulse is u_t k_n/((1+e) v0 k_t); as both impulses' signs are fixed (J > 0, the stick \
         impulse has the slip's sign), the contact sticks (|Jt_stick| <= mu_f J) exactly when mu_f >= mu_f* \
         = |u_t| k_n/((1+e) v0 k_t), and at mu_f = mu_f* the solver's sliding impulse mu_f J equals the \
         sticking one (the answer is continuous across the threshold).",
        "the solver's Jt_stick/J is the closed form mu_f* for a point and for a disc, and at mu_f = mu_f* slide and stick coincide",
        certs,
    )
}
