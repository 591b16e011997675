use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X30",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The frictional energy loss: the kinetic energy lost is (1 - e^2) u_n^2/(2 k_n) to restitution plus u_t^2/(2 k_t) when the contact sticks or mu_f J (|u_t| - mu_f J k_t/2) when it slides; the sliding loss is positive",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: a sliding contact (Coulomb, slip forward); the energy lost by
// the states the physics gives, disc spin included.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution).oblique(Friction::Slide),
        &[
            Check::holds(
                "the normal impulse: J k_n = (1 + e) v0, k_n = 1/m + 1/M + a^2/I",
                "J*(1/m + 1/M + a^2/I) = (1 + e)*v0",
            ),
            Check::holds(
                "sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (u_t - mu_f J k_t/2), u_t = v0t + w rd, k_t = 3/m + 1/M",
                "(m*(v0^2 + v0t^2)/2 + m*rd^2*w^2/4 - (m*(v^2 + vt^2)/2 + M*(V^2 + Vt^2)/2 + I*omega^2/2 + m*rd^2*spin^2/4)) = (1 - e^2)*v0^2/(2*(1/m + 1/M + a^2/I)) + mu_f*J*(v0t + w*rd - mu_f*J*(3/m + 1/M)/2)",
            )
            .given(&["rd > 0"])
            .using(&[0]),
            Check::holds(
                "the normal motion's part of the loss: (1 - e^2) v0^2/(2 k_n)",
                "m*v0^2/2 - (m*v^2/2 + M*V^2/2 + I*omega^2/2) = (1 - e^2)*v0^2/(2*(1/m + 1/M + a^2/I))",
            )
            .using(&[0]),
            Check::holds(
                "the translation along the rod's part: Jt (v0t - Jt (1/m + 1/M)/2)",
                "m*v0t^2/2 - (m*vt^2/2 + M*Vt^2/2) = Jt*(v0t - Jt*(1/m + 1/M)/2)",
            ),
            Check::holds(
                "point (rd = 0), sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (v0t - mu_f J k_t/2), k_t = 1/m + 1/M",
                "(m*(v0^2 + v0t^2)/2 - (m*(v^2 + vt^2)/2 + M*(V^2 + Vt^2)/2 + I*omega^2/2)) = (1 - e^2)*v0^2/(2*(1/m + 1/M + a^2/I)) + mu_f*J*(v0t - mu_f*J*(1/m + 1/M)/2)",
            )
            .given(&["rd = 0"])
            .using(&[2, 3]),
            Check::holds(
                "point, still sliding at the end (v0t > mu_f J k_t): the frictional loss is positive",
                "(m*(v0^2 + v0t^2)/2 - (m*(v^2 + vt^2)/2 + M*(V^2 + Vt^2)/2 + I*omega^2/2)) - (1 - e^2)*v0^2/(2*(1/m + 1/M + a^2/I)) > 0",
            )
            .given(&["rd = 0", "mu_f > 0", "v0t - mu_f*J*(1/m + 1/M) > 0"])
            .using(&[0, 4]),
            Check::holds(
                "disc, still sliding at the end (u_t > mu_f J k_t): the frictional loss is positive",
                "(m*(v0^2 + v0t^2)/2 + m*rd^2*w^2/4 - (m*(v^2 + vt^2)/2 + M*(V^2 + Vt^2)/2 + I*omega^2/2 + m*rd^2*spin^2/4)) - (1 - e^2)*v0^2/(2*(1/m + 1/M + a^2/I)) > 0",
            )
            .given(&["rd > 0", "mu_f > 0", "v0t + w*rd - mu_f*J*(3/m + 1/M) > 0"])
            .using(&[0, 1]),
        ],
    )
    .partly("the sticking loss u_t^2/(2 k_t) is certified by rodimpact only: one scene per exported statement"),
);

fn formalise(_paper: &Paper) -> Formalised {
    let rod = oblique_rod();
    let o = oblique(true);
    let one_plus_e_v0 = (Formula::int(1) + &f("e")) * &f("v0");
    let k_n = Formula::int(1) / &f("m") + &(Formula::int(1) / &f("M")) + &(f("a").pow(2) / &f("I"));
    let k_t = Formula::int(3) / &f("m") + &(Formula::int(1) / &f("M"));
    let slip = f("v0t") + &(f("w") * &f("r"));
    let restitution =
        (Formula::int(1) - &f("e").pow(2)) * &f("v0").pow(2) / &(Formula::int(2) * &k_n);
    let mu_j = f("mu_f") * &one_plus_e_v0 / &k_n;
    let sliding =
        |speed: Formula| mu_j.clone() * &(speed - &(mu_j.clone() * &k_t / &Formula::int(2)));
    let mut certs = Vec::new();
    for contact in CONTACTS {
        let friction = match contact {
            Mode::Stick => slip.pow(2) / &(Formula::int(2) * &k_t),
            Mode::Slide { forward: true } => sliding(slip.clone()),
            Mode::Slide { forward: false } => sliding(-slip.clone()),
            Mode::Frictionless => unreachable!("CONTACTS are stick and slide"),
        };
        let out = oblique_solved(&rod, &o, contact);
        certs.push(Certificate::identity(
            format!(
                "{}: energy lost (K0 - K1 of the solver's states, disc spin included) = restitution + friction closed forms",
                case(contact)
            ),
            n("K_lost", out.energy.lost()),
            restitution.clone() + &friction,
        ));
    }
    // Sliding forward means u_t > mu_f J k_t: write u_t = mu_f J k_t + x with x > 0.
    let slide = oblique_solved(&rod, &o, Mode::Slide { forward: true });
    let (mu_j_value, k_t_value) = (mu_j.value().clone(), k_t.value().clone());
    let excess = sym("x") + &(mu_j_value * &k_t_value) - &(sym("w") * &sym("r"));
    let k_n_form = sum([
        quot(pc(1, 1), ps("m")),
        quot(pc(1, 1), ps("M")),
        quot(PosExpr::Square(sym("a")), ps("I")),
    ]);
    let mu_j_form = || quot(prod([ps("mu_f"), one_plus_e(), ps("v0")]), k_n_form.clone());
    let k_t_form = sum([quot(pc(3, 1), ps("m")), quot(pc(1, 1), ps("M"))]);
    certs.push(positive(
        "sliding (u_t = mu_f J k_t + x, x > 0): energy lost (solver) - restitution = mu_f J (mu_f J k_t/2 + x) > 0",
        slide.energy.lost() - restitution.value(),
        true,
        &[("v0t", excess)],
        &["m", "M", "I", "v0", "mu_f", "x"],
        &["e"],
        prod([
            mu_j_form(),
            sum([quot(prod([mu_j_form(), k_t_form]), pc(2, 1)), ps("x")]),
        ]),
    ));
    proved(
        "Free rod (m, M, I, v0 > 0, e in [0, 1], any a) at rest, solid disc projectile (radius r, spin w, \
         velocity (v0, v0t)), friction mu_f > 0; u_n = v0, u_t = v0t + w r, k_n = 1/m + 1/M + a^2/I, \
         k_t = 3/m + 1/M, J = (1+e) v0/k_n. For each way the contact ends, the kinetic energy lost by \
         the solver's states (translation along both axes, the rod's turn and the disc's spin) equals \
         (1 - e^2) v0^2/(2 k_n) plus u_t^2/(2 k_t) (stick) or mu_f J (|u_t| - mu_f J k_t/2) (slide); when \
         sliding, |u_t| > mu_f J k_t, and the frictional part is mu_f J (mu_f J k_t/2 + x) > 0 with \
         x = |u_t| - mu_f J k_t (shown for u_t > 0; u_t < 0 is its mirror image).",
        "the solver's energy loss equals the closed forms in every contact case, and the sliding part is a visibly positive product",
        certs,
    )
}
