use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X27",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Friction never changes the spin of a thin rod struck on its axis: with the projectile sliding along the rod (v0t), Coulomb friction mu_f and a spinning disc projectile, omega, V and v are those of the frictionless perpendicular impact, whether the contact sticks or slides; on a pivot too",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: the physics (the impulses across and along the rod, the disc's
// spin, Newton's law) with no friction law at all, so it holds whatever the tangential impulse.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution).oblique(Friction::Any),
        &[Check::holds(
            "whatever the tangential impulse Jt (stick, slide, any mu_f): omega, V and v are the frictionless impact's, J = (1+e) v0/k_n, k_n = 1/m + 1/M + a^2/I",
            "omega = (1 + e)*v0*a/(I*(1/m + 1/M + a^2/I)) and V = (1 + e)*v0/(M*(1/m + 1/M + a^2/I)) and v = v0 - (1 + e)*v0/(m*(1/m + 1/M + a^2/I))",
        )],
    )
    .partly("the rod on a pivot (its Jt acts through the pivot too) is certified by rodimpact only: one scene per exported statement"),
);

fn formalise(_paper: &Paper) -> Formalised {
    let rod = oblique_rod();
    let paper = motion(&rod);
    let pivoted = pivoted_rod(sym("I"), sym("e"));
    let paper_pivoted = motion(&pivoted);
    let mut certs = Vec::new();
    for disc in [false, true] {
        let projectile = if disc { "disc" } else { "point" };
        for contact in CONTACTS {
            let out = oblique_solved(&rod, &oblique(disc), contact);
            let title = |what: &str| {
                format!(
                    "free rod, {projectile} projectile, {}: {what}",
                    case(contact)
                )
            };
            certs.push(Certificate::identity(
                title("omega (oblique solver) = omega (frictionless solver)"),
                n("omega", out.after.rod.omega.clone()),
                n("omega_0", paper.omega.clone()),
            ));
            certs.push(Certificate::identity(
                title("V (oblique solver) = V (frictionless solver)"),
                n("V", out.after.rod.v.clone()),
                n("V_0", paper.rod_v.clone()),
            ));
            certs.push(Certificate::identity(
                title("v (oblique solver) = v (frictionless solver)"),
                n("v", out.after.v.clone()),
                n("v_0", paper.v.clone()),
            ));
        }
    }
    for contact in CONTACTS {
        let out = oblique_solved(&pivoted, &oblique(true), contact);
        certs.push(Certificate::identity(
            format!(
                "rod on a pivot at p, disc projectile, {}: omega (oblique solver) = omega (frictionless solver)",
                case(contact)
            ),
            n("omega", out.after.rod.omega.clone()),
            n("omega_0", paper_pivoted.omega.clone()),
        ));
    }
    proved(
        "Thin rod (m, M, I > 0, any a, v0, e; free, or on a pivot at p) struck at distance a from its \
         centre by a point or a solid disc (radius r, spin w) moving with v0 across and v0t along the \
         rod, Coulomb friction mu_f at the contact; for each way the contact can end (stick; slide with \
         the slip along +y; slide along -y) the oblique solver's omega, V and v equal the frictionless \
         perpendicular solver's, identically in v0t, mu_f, r and w. The tangential impulse acts along \
         the rod's axis, through its centre (and the pivot), so it has no moment about either.",
        "omega, V and v from the oblique solver equal the frictionless ones identically in every contact case",
        certs,
    )
}
