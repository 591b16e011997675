use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X31",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The paper's a* is unchanged by the projectile's slide along the rod, by friction, by a disc's spin and by the rod's drift: omega(a) = (1+e) u_n a/(a*^2 + a^2) with the paper's a*^2 = I (M + m)/(m M) in every contact case",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: no friction law (any tangential impulse) and the rod drifting,
// so the shape of omega(a) holds in every contact case.
const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution)
        .oblique(Friction::Any)
        .moving(),
    &[Check::holds(
        "whatever the tangential impulse: omega (a*^2 + a^2) = (1+e) (v0 - V0) a with the paper's a*^2 = I (M + m)/(m M)",
        "omega*(s^2 + a^2) = (1 + e)*(v0 - V0)*a",
    )
    .given(&["s > 0", "s^2 = (M + m)*I/(m*M)"])],
));

fn formalise(paper: &Paper) -> Formalised {
    let rod = oblique_rod();
    let shape = |approach: Formula| {
        (Formula::int(1) + &f("e")) * &approach * &f("a")
            / &(paper.a_star_squared.clone() + &f("a").pow(2))
    };
    let mut certs = Vec::new();
    for contact in CONTACTS {
        let out = oblique_solved(&rod, &oblique(true), contact);
        certs.push(Certificate::identity(
            format!(
                "{}: omega (oblique solver, disc, v0t, mu_f) = (1+e) v0 a/(a*^2 + a^2), a* the paper's",
                case(contact)
            ),
            n("omega", out.after.rod.omega.clone()),
            shape(f("v0")),
        ));
    }
    let drifting = ObliqueParams {
        rod_before: RodMotion {
            v: sym("V0"),
            vt: sym("Vt0"),
            omega: int(0),
        },
        ..oblique(true)
    };
    let out = oblique_solved(&rod, &drifting, Mode::Slide { forward: true });
    certs.push(Certificate::identity(
        "rod drifting with (V0, Vt0), sliding: omega = (1+e) (v0 - V0) a/(a*^2 + a^2)",
        n("omega", out.after.rod.omega.clone()),
        shape(f("v0") - &f("V0")),
    ));
    proved(
        "Free rod (m, M, I > 0, any a, e), solid disc projectile (radius r, spin w) with velocity \
         (v0, v0t), friction mu_f, the rod at rest or drifting with (V0, Vt0) without turning: for every \
         contact case the solver's omega as a function of a is (1+e) u_n a/(a*^2 + a^2), u_n = v0 - V0, \
         with the paper's a*^2 = I (M + m)/(m M) (Eq. (maximal-a-general)); this is the paper's omega(a) \
         with v0 replaced by u_n, so |omega| is largest at the same a* (the paper's maximisation, C20).",
        "the solver's omega(a) has the paper's shape with the paper's a* in every contact case, independent of v0t, mu_f, r, w, Vt0",
        certs,
    )
}
