use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X4",
    location: BEYOND,
    group: Group::Beyond,
    statement: "omega_e(a) = (1+e)/2 omega_el(a) for every a; omega_el = 2 omega_inel",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[
        Check::holds(
            "omega_e = (1+e)/2 Eq. (omega)",
            "omega = (1 + e)/2*(2*m*a/I)/(1 + m/M + m*a^2/I)*v0",
        ),
        Check::holds(
            "e = 0: Eq. (omega) = 2 omega_inel",
            "2*omega = (2*m*a/I)/(1 + m/M + m*a^2/I)*v0",
        )
        .given(&["e = 0"]),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
    let i = sym("I");
    proved(
        "For m, M, I > 0, any a, v0 and any e: the solver's omega for restitution e equals (1+e)/2 \
         times Eq. (omega) (the elastic omega), and Eq. (omega) is twice the solver's e = 0 omega, which is the sticking body's omega mu a v0/(I + mu a^2) (X3).",
        "omega is linear in (1+e): the solver's omega_e = (1+e)/2 Eq. (omega) identically",
        vec![
            id(
                "omega_e from the solver = (1+e)/2 * Eq. (omega)",
                n("omega_e", after(&i, sym("e")).omega),
                one_plus_e_f() / &Formula::int(2) * &paper.omega,
            ),
            id(
                "Eq. (omega) = 2 * omega of the solver's e = 0 solution",
                paper.omega.clone(),
                Formula::int(2) * &n("omega_0", after(&i, k(0, 1)).omega),
            ),
            id(
                "Eq. (omega) = 2 * omega of the sticking body, mu a v0/(I + mu a^2) (X3)",
                paper.omega.clone(),
                Formula::int(2) * &mu_f() * &f("a") * &f("v0")
                    / &(f("I") + &(mu_f() * &f("a").pow(2))),
            ),
        ],
    )
}
