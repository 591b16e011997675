use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::scene::{Motion, angular_momentum, linear_momentum};
use num_traits::Zero;

pub(super) const ENTRY: Entry = Entry {
    id: "X3",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Sticking model: y_c = ma/(M+m), V_c = m v0/(M+m), I_c = I + mu a^2, omega = mu a v0/(I + mu a^2). It is identical to Newton e = 0 at the impact instant",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Sticking),
    &[
        Check::holds(
            "omega = mu a v0/(I + mu a^2), mu = m M/(M + m)",
            "omega = (m*M/(M + m))*a*v0/(I + (m*M/(M + m))*a^2)",
        ),
        Check::holds(
            "the pair moves as one rigid body: its CM y_c = m a/(M + m) at V_c = m v0/(M + m), each point y at V_c + omega (y - y_c)",
            "(m*v + M*V)/(M + m) = m*v0/(M + m) and v = m*v0/(M + m) + omega*(a - m*a/(M + m)) and V = m*v0/(M + m) + omega*(0 - m*a/(M + m))",
        ),
    ],
));

fn formalise(_paper: &Paper) -> Formalised {
    let (m, big_m, a, i, v0) = (sym("m"), sym("M"), sym("a"), sym("I"), sym("v0"));
    let total = m.clone() + &big_m;
    let p = free_rod(i.clone(), k(0, 1));
    let before = Motion::before(v0.clone());
    // The claimed composite body.
    let y_c = m.clone() * &a / total.clone();
    let v_c = m.clone() * &v0 / total.clone();
    let inel = motion(&p);
    let (mu, y_c_f, v_c_f) = (mu_f(), n("y_c", y_c.clone()), n("V_c", v_c.clone()));
    let i_c_f = n("I_c", f("I") + &(mu.clone() * &f("a").pow(2)));
    let omega_f = n("omega_c", mu.clone() * &f("a") * &f("v0") / &i_c_f);
    proved(
        "For m, M, I > 0, any a, v0: the projectile stuck at y = a and the rod form one rigid body \
         with centre of mass y_c (first moment zero about it), momentum m v0, moment of inertia \
         I + M y_c^2 + m (a - y_c)^2 (parallel axes) and angular momentum about y_c equal to the \
         projectile's before the impact; its velocity field right after the impact (rod centre \
         V_c - omega y_c, projectile V_c + omega (a - y_c), omega) equals the solver's Newton e = 0 \
         solution. (Afterwards the two models differ: the stuck projectile follows the rotating \
         rod, the e = 0 projectile moves straight on; the claim is about the impact instant.)",
        "the composite body's quantities match the formulas, and its velocities equal the solver's e = 0 solution identically",
        vec![
            id(
                "first moment of the masses about y_c = ma/(M+m) vanishes: M (0 - y_c) + m (a - y_c) = 0",
                f("M") * &(Formula::int(0) - &y_c_f) + &(f("m") * &(f("a") - &y_c_f)),
                RatFn::zero(),
            ),
            id(
                "(M + m) V_c = momentum before (mechanics::linear_momentum)",
                (f("M") + &f("m")) * &v_c_f,
                n("p_before", linear_momentum(&p, &before)),
            ),
            id(
                "parallel axes: I + M y_c^2 + m (a - y_c)^2 = I + mu a^2",
                f("I") + &(f("M") * &y_c_f.pow(2)) + &(f("m") * &(f("a") - &y_c_f).pow(2)),
                i_c_f.clone(),
            ),
            id(
                "angular momentum about y_c before the impact (mechanics::angular_momentum) = I_c omega",
                n("L_before", angular_momentum(&p, &before, &y_c)),
                i_c_f * &omega_f,
            ),
            id(
                "omega of the solver's e = 0 solution = mu a v0/(I + mu a^2)",
                n("omega", inel.omega),
                omega_f.clone(),
            ),
            id(
                "rod-centre velocity of the solver's e = 0 solution = V_c - omega y_c",
                n("V", inel.rod_v),
                v_c_f.clone() - &(omega_f.clone() * &y_c_f),
            ),
            id(
                "projectile velocity of the solver's e = 0 solution = V_c + omega (a - y_c)",
                n("v", inel.v),
                v_c_f + &(omega_f * &(f("a") - &y_c_f)),
            ),
        ],
    )
}
