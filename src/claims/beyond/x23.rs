use crate::claims::dsl::*;
use crate::scene::{Motion, angular_momentum};

pub(super) const ENTRY: Entry = Entry {
    id: "X23",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Sticking loses (mu v0^2/2) I/(I + mu a^2) = K0/D; at a*, I_c = 2I and omega = v0/(2a*)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Sticking),
    &[
        Check::holds("sticking loses (mu v0^2/2) I/(I + mu a^2) = K0/D", "m*v0^2 - (m*v^2 + M*V^2 + I*omega^2) = (m*M/(M + m))*v0^2*I/(I + (m*M/(M + m))*a^2) and (m*M/(M + m))*v0^2*I/(I + (m*M/(M + m))*a^2) = m*v0^2/(1 + m/M + m*a^2/I)"),
        Check::holds("at a*: I_c = 2I and omega = v0/(2a*)", "I + (m*M/(M + m))*s^2 = 2*I and omega_s = v0/(2*s)"),
    ],
)
.at(&[StrikePoint { at: "a", tag: "" }, StrikePoint { at: "s", tag: "s" }])
.given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]));

fn formalise(paper: &Paper) -> Formalised {
    let (m, big_m, a, v0, inertia) = (sym("m"), sym("M"), sym("a"), sym("v0"), sym("I"));
    let total = big_m.clone() + &m;
    let mu = m.clone() * &big_m / total.clone();
    // The composite body (rod + stuck projectile): CM at y_c, I_c by the parallel-axis theorem.
    let y_c = m.clone() * &a / total.clone();
    let arm = a.clone() - &y_c;
    let i_c = inertia.clone() + &(big_m.clone() * &y_c * &y_c) + &(m.clone() * &arm * &arm);
    let p = free_rod(inertia.clone(), int(0));
    let l_c = angular_momentum(&p, &Motion::before(v0.clone()), &y_c);
    let omega_c = l_c / i_c.clone();
    let v_c = m.clone() * &v0 / total.clone();
    let k0 = m.clone() * &v0 * &v0 / k(2, 1);
    let after = (total * &v_c * &v_c + &(i_c.clone() * &omega_c * &omega_c)) / k(2, 1);
    let loss = k0.clone() - &after;
    let newton_zero = solved(&p);
    let two = Formula::int(2);
    let mu_f = n("mu", mu.clone());
    let y_c_f = n("y_c", y_c.clone());
    let i_c_f = n("I_c", i_c.clone());
    let omega_c_f = n("omega_c", omega_c.clone());
    let k0_f = f("m") * &f("v0").pow(2) / &two;
    let stated_f = mu_f.clone() * &f("v0").pow(2) / &two * &f("I")
        / &(f("I") + &(mu_f.clone() * &f("a").pow(2)));
    let certs = vec![
        Certificate::identity(
            "composite body: I_c = I + M y_c^2 + m (a - y_c)^2 = I + mu a^2, y_c = m a/(M + m)",
            f("I") + &(f("M") * &y_c_f.pow(2)) + &(f("m") * &(f("a") - &y_c_f).pow(2)),
            f("I") + &(mu_f.clone() * &f("a").pow(2)),
        ),
        Certificate::identity(
            "sticking loss K0 - ((M + m) V_c^2 + I_c omega^2)/2 = (mu v0^2/2) I/(I + mu a^2)",
            k0_f.clone()
                - &(((f("M") + &f("m")) * &n("V_c", v_c.clone()).pow(2)
                    + &(i_c_f.clone() * &omega_c_f.pow(2)))
                    / &two),
            stated_f.clone(),
        ),
        Certificate::identity(
            "(mu v0^2/2) I/(I + mu a^2) = K0/D",
            stated_f,
            k0_f.clone()
                / &(Formula::int(1) + &(f("m") / &f("M")) + &(f("m") * &f("a").pow(2) / &f("I"))),
        ),
        Certificate::identity(
            "the generic solver with e = 0 loses the same energy",
            n("K_lost", newton_zero.energy.lost()),
            n("K_lost_c", loss),
        ),
        a_star_substitution_cert(paper),
        id_optimal_at_a("at a*: I_c = 2I", i_c_f.clone(), Formula::int(2) * &f("I")),
        id_optimal_at_a(
            "at a*: omega (composite body, L about its CM / I_c) times 2a* = v0",
            omega_c_f * &f("a") * &two,
            f("v0"),
        ),
    ];
    Formalised {
        formal: "Free rod, m, M, I, v0 > 0, any a; the projectile sticks (the composite body has its CM at \
                 y_c = m a/(M + m), moves with V_c = m v0/(M + m) and turns at omega = L_c/I_c, L_c the angular \
                 momentum about the point y_c, I_c by the parallel-axis theorem). The energy lost is \
                 (mu v0^2/2) I/(I + mu a^2) = K0/D, also the loss of the Newton e = 0 impact (generic solver). \
                 At a = a* (I = m M a^2/(M + m)): I_c = 2I and omega = v0/(2 a*)."
            .into(),
        reason: "the composite body's energy balance gives (mu v0^2/2) I/(I + mu a^2) = K0/D identically; at a* the substitution gives I_c = 2I".into(),
        decision: Decision::Proved(certs),
    }
}
