use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::scene::kinetic_energy;

pub(super) const ENTRY: Entry = Entry {
    id: "C31",
    location: "§optimum ¶2",
    group: Group::Inelastic,
    statement: "The inelastic case needs the shifted CM and the modified I",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Sticking),
    &[
        Check::holds(
            "the reading that omega after sticking needs the composite's CM and I_c is refuted: the momentum balances about the rod's centre with the rod's own I give the composite's omega = mu a v0/(I + mu a^2), mu = m M/(M + m), for every a",
            "omega = m*M*a*v0/(M + m)/(I + m*M*a^2/(M + m))",
        ),
        Check::holds(
            "what is true: the pair's CM y_c = m a/(M + m) moves at V_c = m v0/(M + m), and the energy after is (M + m) V_c^2/2 + I_c omega^2/2 with I_c = I + mu a^2",
            "(m*v + M*V)/(M + m) = m*v0/(M + m) and m*v^2 + M*V^2 + I*omega^2 = (M + m)*(m*v0/(M + m))^2 + (I + m*M*a^2/(M + m))*omega^2",
        ),
    ],
));

fn formalise(_paper: &Paper) -> Formalised {
    let inertia = sym("I");
    let stuck = sticking(inertia.clone());
    let p = free_rod(inertia.clone(), k(0, 1));
    let after = motion(&p);
    let without = Certificate::identity(
        "omega from the rod-centre equations with the rod's own I (momentum, Eq. (angular) about the \
         rod's centre, sticking v = V + omega a: the generic solver at e = 0) equals omega of the composite \
         body (CM y_c, I_c)",
        Formula::named("omega", after.omega.clone()),
        Formula::named("omega_c", stuck.omega.clone()),
    );
    let mu = Formula::named("mu", reduced_mass());
    let parallel_axes = Certificate::identity(
        "the composite's moment of inertia about y_c = m a/(M + m) is I_c = I + mu a^2, mu = m M/(M + m)",
        Formula::named("I_c", stuck.i_c.clone()),
        Formula::from(inertia) + &(mu * &Formula::sym("a").pow(2)),
    );
    let (omega, y_c) = (
        Formula::named("omega", after.omega.clone()),
        Formula::named("y_c", stuck.y_c.clone()),
    );
    let cm_moves_uniformly = Certificate::identity(
        "after the impact the rod point at y_c moves with V + omega y_c = V_c = m v0/(M + m): the stuck \
         pair's CM is y_c, not the rod's centre",
        Formula::named("V", after.rod_v.clone()) + &(omega.clone() * &y_c),
        Formula::named("V_c", stuck.v_c.clone()),
    );
    let v_c = Formula::named("V_c", stuck.v_c.clone());
    let energy = Certificate::identity(
        "kinetic energy after the impact (rod and projectile) = (M + m) V_c^2/2 + I_c omega^2/2: I_c is \
         the stuck pair's rotational inertia",
        Formula::named("K", kinetic_energy(&p, &after)),
        (Formula::sym("M") + &Formula::sym("m")) * &v_c.pow(2) / &Formula::int(2)
            + &(Formula::named("I_c", stuck.i_c) * &omega.pow(2) / &Formula::int(2)),
    );
    Formalised {
        formal: "Natural reading: finding omega after a sticking impact requires the composite's CM \
                 y_c = m a/(M + m) and its I_c. Refuted: the paper's own Eqs. (linear) and (angular) about \
                 the fixed point at the rod's centre, with the rod's own I, plus the sticking condition \
                 v = V + omega a in place of Eq. (kinetic), give the same omega as the composite body, for \
                 all m, M, I, v0 > 0 and every a. What is true: y_c and I_c (= I + mu a^2) describe the \
                 stuck pair as one rigid body after the impact: its CM is y_c moving at V_c = m v0/(M + m), \
                 and its kinetic energy is (M + m) V_c^2/2 + I_c omega^2/2."
            .into(),
        reason: "the rod-centre equations with the rod's own I and v = V + omega a give the composite body's \
                 omega exactly; y_c and I_c only describe the stuck pair afterwards"
            .into(),
        decision: Decision::Qualified {
            qualification: "y_c and I_c are needed only to describe the stuck pair as one rigid body after \
                            the impact (its CM y_c moving at V_c, its rotational energy I_c omega^2/2); omega \
                            itself needs only the sticking condition v = V + omega a in place of energy \
                            conservation"
                .into(),
            counterexample: vec![without],
            proof: vec![parallel_axes, cm_moves_uniformly, energy],
        },
    }
}

/// `mu = m M/(M + m)`.
fn reduced_mass() -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    m.clone() * &big_m / (big_m + &m)
}
