use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X11",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Energy lost ΔK = (1 - e^2) m_eff v0^2/2 >= 0; for e = 0, ΔK/K0 = 1/D; at a*, ΔK/K0 = (1 - e^2) M/(2(M+m))",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution),
        &[
            Check::holds(
                "energy lost: 2 dK = (1 - e^2) m_eff v0^2, m_eff = 1/(1/m + 1/M + a^2/I)",
                "m*v0^2 - (m*v^2 + M*V^2 + I*omega^2) = (1 - e^2)*v0^2/(1/m + 1/M + a^2/I)",
            ),
            Check::holds("dK >= 0", "m*v^2 + M*V^2 + I*omega^2 <= m*v0^2"),
            Check::holds(
                "e = 0: dK/K0 = 1/D",
                "(m*v0^2 - (m*v^2 + M*V^2 + I*omega^2))/(m*v0^2) = 1/(1 + m/M + m*a^2/I)",
            )
            .given(&["e = 0"]),
            Check::holds(
                "at a*: dK/K0 = (1 - e^2) M/(2(M+m))",
                "(m*v0^2 - (m*v_s^2 + M*V_s^2 + I*omega_s^2))/(m*v0^2) = (1 - e^2)*M/(2*(M + m))",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let (i, e) = (sym("I"), sym("e"));
    let u = sym("u");
    // e = 2u/(1+u^2), u >= 0, runs over exactly [0, 1]; then 1 - e^2 = ((1-u)(1+u))^2/(1+u^2)^2.
    let e_of_u = k(2, 1) * &u / (one() + &sq(&u));
    let one_u2 = sum([pc(1, 1), PosExpr::Square(u.clone())]);
    let loss_form = quot(
        prod([
            PosExpr::Square((one() - &u) * &(one() + &u)),
            ps("m"),
            ps("M"),
            ps("I"),
            ps("v0"),
            ps("v0"),
        ]),
        prod([pc(2, 1), one_u2.clone(), one_u2, m_i_d_form()]),
    );
    proved(
        "For m, M, I, v0 > 0, any a and e in [0,1] (parametrised as e = 2u/(1+u^2), u >= 0, which \
         covers [0,1] exactly): the solver's energy loss is (1 - e^2) m_eff v0^2/2 >= 0; with e = 0 \
         it is K0/D; at a = a* (I = A^2 mM/(M+m), a = A) it is (1 - e^2) M/(2(M+m)) K0.",
        "the solver's energy loss equals (1 - e^2) m_eff v0^2/2 identically, a visible square times positives on e in [0,1]",
        vec![
            energy_loss_identity(),
            positive(
                "energy lost >= 0 for e in [0,1] (e = 2u/(1+u^2), u >= 0)",
                energy_lost(&i, e.clone()),
                false,
                &[("e", e_of_u)],
                &["m", "M", "I", "v0"],
                &["u"],
                loss_form,
            ),
            id(
                "e = 0: energy lost/K0 (solver) = 1/D",
                n("K_lost", energy_lost(&i, k(0, 1))) / &k0_f(),
                Formula::int(1)
                    / &(Formula::int(1)
                        + &(f("m") / &f("M"))
                        + &(f("m") * &f("a").pow(2) / &f("I"))),
            ),
            id_at_star(
                paper,
                "at a*: energy lost/K0 (solver) = (1 - e^2) M/(2(M+m))",
                n("K_lost", energy_lost(&i, e.clone())) / &k0_f(),
                (Formula::int(1) - &f("e").pow(2)) * &f("M")
                    / &(Formula::int(2) * &(f("M") + &f("m"))),
            ),
        ],
    )
}
