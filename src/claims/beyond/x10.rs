use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X10",
    location: BEYOND,
    group: Group::Beyond,
    statement: "General e, at a*: v - V = (1-e) v0/2, V = (1+e) m v0/(2(M+m)), K_rot = ((1+e)/2)^2 mu v0^2/2",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[
        Check::holds("at a*: v - V, V and the rotational energy", "v_s - V_s = (1 - e)*v0/2 and V_s = (1 + e)*m*v0/(2*(M + m)) and I*omega_s^2 = ((1 + e)/2)^2*(m*M/(M + m))*v0^2"),
    ],
)
.at(&[StrikePoint { at: "s", tag: "s" }])
.given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]));

fn formalise(paper: &Paper) -> Formalised {
    let (i, e) = (sym("I"), sym("e"));
    let mo = after(&i, e.clone());
    let two = Formula::int(2);
    proved(
        "For m, M, I, v0 > 0 and any e: at a = a* (I = A^2 mM/(M+m), a = A) the solver's solution \
         has v - V = (1-e) v0/2, V = (1+e) m v0/(2(M+m)) and I omega^2/2 = ((1+e)/2)^2 mu v0^2/2.",
        "the solver's velocities at a* reduce identically to the stated forms",
        vec![
            id_at_star(
                paper,
                "v - V at a* (solver) = (1-e) v0/2",
                n("v", mo.v.clone()) - &n("V", mo.rod_v.clone()),
                (Formula::int(1) - &f("e")) * &f("v0") / &two,
            ),
            id_at_star(
                paper,
                "V at a* (solver) = (1+e) m v0/(2(M+m))",
                n("V", mo.rod_v.clone()),
                one_plus_e_f() * &f("m") * &f("v0") / &(two.clone() * &(f("M") + &f("m"))),
            ),
            id_at_star(
                paper,
                "I omega^2/2 at a* (solver) = ((1+e)/2)^2 mu v0^2/2",
                f("I") * &n("omega", mo.omega).pow(2) / &two,
                (one_plus_e_f() / &two).pow(2) * &mu_f() * &f("v0").pow(2) / &two,
            ),
        ],
    )
}
