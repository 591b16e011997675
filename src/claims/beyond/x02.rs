use crate::claims::dsl::*;
use crate::scene::kinetic_energy;

pub(super) const ENTRY: Entry = Entry {
    id: "X2",
    location: BEYOND,
    group: Group::Beyond,
    statement: "e = 1 reproduces Eqs. (v), (V), (omega) and conserves energy exactly; with C7, energy conservation is equivalent to e = 1",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[
        Check::holds("e = 1 gives Eqs. (v), (V), (omega)", "v = -(1 - m/M - m*a^2/I)/(1 + m/M + m*a^2/I)*v0 and V = (2*m/M)/(1 + m/M + m*a^2/I)*v0 and omega = (2*m*a/I)/(1 + m/M + m*a^2/I)*v0").given(&["e = 1"]),
        Check::holds("e = 1 conserves kinetic energy", "m*v0^2 = m*v^2 + M*V^2 + I*omega^2").given(&["e = 1"]),
        Check::holds("conserved kinetic energy forces e = 1", "e = 1").given(&["m*v0^2 = m*v^2 + M*V^2 + I*omega^2"]),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
    let i = sym("I");
    let el = after(&i, k(1, 1));
    let t = sym("t");
    let lost_form = quot(
        prod([
            sum([pc(1, 1), prod([pc(2, 1), ps("t")])]),
            ps("m"),
            ps("M"),
            ps("I"),
            ps("v0"),
            ps("v0"),
        ]),
        prod([
            pc(2, 1),
            sum([pc(1, 1), ps("t")]),
            sum([pc(1, 1), ps("t")]),
            m_i_d_form(),
        ]),
    );
    proved(
        "For m, M, I, v0 > 0 and any a: with e = 1 the solver's (v, V, omega) equal Eqs. (v), (V), \
         (omega) identically and the kinetic energy after equals m v0^2/2 (energy is a consequence, \
         not an assumption). For every e the energy lost is (1 - e^2) m_eff v0^2/2; for e in [0,1) \
         (e = t/(1+t), t >= 0) it is > 0, so among e in [0,1] energy is conserved (C7) iff e = 1.",
        "e = 1 reproduces the paper identically, and the energy lost (1 - e^2) m_eff v0^2/2 is > 0 for every e in [0,1)",
        vec![
            id(
                "v from the solver (e = 1) = Eq. (v)",
                n("v", el.v.clone()),
                paper.v.clone(),
            ),
            id(
                "V from the solver (e = 1) = Eq. (V)",
                n("V", el.rod_v.clone()),
                paper.big_v.clone(),
            ),
            id(
                "omega from the solver (e = 1) = Eq. (omega)",
                n("omega", el.omega.clone()),
                paper.omega.clone(),
            ),
            id(
                "kinetic energy after the elastic impact (solver) = m v0^2/2",
                n(
                    "K_after",
                    kinetic_energy(&free_rod(i.clone(), k(1, 1)), &el),
                ),
                k0_f(),
            ),
            energy_loss_identity(),
            positive(
                "energy lost > 0 for e in [0,1): e = t/(1+t), t >= 0",
                energy_lost(&i, sym("e")),
                true,
                &[("e", t.clone() / (one() + &t))],
                &["m", "M", "I", "v0"],
                &["t"],
                lost_form,
            ),
        ],
    )
}
