use crate::claims::dsl::*;
use crate::field::{RatFn, Sym};
use crate::scene::Motion;

pub(super) const ENTRY: Entry = Entry {
    id: "X5",
    location: BEYOND,
    group: Group::Beyond,
    statement: "omega_e = (1+e) v0 a/(a*^2 + a^2): a* does not depend on e or v0. At a* the rotational compliance a^2/I equals the translational compliance 1/m + 1/M, and J(a*) = J(0)/2",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution).impulses(),
        &[
            Check::holds(
                "omega_e = (1+e) v0 a/(a*^2 + a^2)",
                "omega = (1 + e)*v0*a/(s^2 + a^2)",
            ),
            Check::holds(
                "a* maximises omega_e over a >= 0 for every e and v0",
                "a >= 0 and a != s => omega < omega_s",
            ),
            Check::holds(
                "at a* the rotational compliance equals the translational one",
                "s^2/I = 1/m + 1/M",
            ),
            Check::holds("J(a*) = J(0)/2", "J_s = J_0/2"),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
        StrikePoint { at: "0", tag: "0" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let i = sym("I");
    let omega = after(&i, sym("e")).omega;
    let j = impulse(&after(&i, sym("e")));
    let (a2, big_a2) = (f("a").pow(2), f("A").pow(2));
    let mut certs = vec![
        id(
            "omega_e from the solver = (1+e) v0 a/(a*^2 + a^2), a*^2 = Eq. (maximal-a-general) squared",
            n("omega_e", omega.clone()),
            one_plus_e_f() * &f("v0") * &f("a") / &(n("a*^2", paper.a_star_squared.clone()) + &a2),
        ),
        Certificate::identity_at(
            "with I = A^2 mM/(M+m): d omega_e/da = (1+e) v0 (A^2 - a^2)/(A^2 + a^2)^2 (no m, M; the sign does not involve e or v0)",
            n("omega_e'", omega.derivative(Sym::new("a"))),
            one_plus_e_f() * &f("v0") * &(big_a2.clone() - &a2) / &(big_a2 + &a2).pow(2),
            &[("I", inertia_of_a_star(paper))],
        ),
    ];
    certs.extend(omega_monotonicity(paper));
    let one_f = Formula::int(1);
    certs.push(id(
        "rotational compliance at a*: a*^2/I = 1/m + 1/M",
        paper.a_star_squared.clone() / &f("I"),
        one_f.clone() / &f("m") + &(one_f / &f("M")),
    ));
    certs.push(id_at_star(
        paper,
        "J(a*) from the solver = J(0)/2",
        n("J", j.clone()),
        n("J_0", subs(&j, &[("a", k(0, 1))])) / &Formula::int(2),
    ));
    proved(
        "For m, M, I, v0 > 0, e >= 0 and a >= 0: the solver's omega_e equals (1+e) v0 a/(a*^2 + a^2) \
         with a*^2 = (M+m) I/(mM); writing I = A^2 mM/(M+m) (A = a* > 0), d omega_e/da is > 0 on \
         [0, A) and < 0 on (A, oo) whatever e and v0, so a* is the unique maximiser over a >= 0 for \
         every e, v0. At a = a*, a^2/I = 1/m + 1/M and J(a*) = J(0)/2 (J = m (v0 - v) from the solver).",
        "omega_e = (1+e) v0 a/(a*^2 + a^2) identically; its slope has the sign of a*^2 - a^2 for all e, v0",
        certs,
    )
}

/// The impulse on the rod from the solver, `J = m (v0 - v)`.
fn impulse(m: &Motion<RatFn>) -> RatFn {
    sym("m") * &(sym("v0") - &m.v)
}
