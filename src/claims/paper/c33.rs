use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C33",
    location: "§intuition ¶1",
    group: Group::Intuition,
    statement: "A given impulse J gives the largest omega at a = l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Elastic),
        &[Check::holds(
            "for a given impulse J > 0, omega = J a/I is largest at a = l",
            "0 <= a and a < l => omega < omega_l",
        )],
    )
    .at(&[])
    .given(&[
        "M > 0",
        "l > 0",
        "J > 0",
        "I = M*l^2/3",
        "I*omega = J*a",
        "I*omega_l = J*l",
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let p = free_rod(sym("I"), sym("e"));
    let out = solved(&p);
    let (a, inertia, j) = (sym("a"), sym("I"), sym("J"));
    let given = j * &a / inertia.clone();
    Formalised {
        formal: "Free rod (mass M, inertia I about its centre), an impulse J > 0 applied perpendicularly at a \
                 (0 <= a <= l), J fixed independently of a: the angular impulse about the centre gives \
                 I omega = a J, so omega = J a/I, strictly largest at a = l. The first certificate checks \
                 I omega = a J on the solver's own collision (any e), the second the maximum."
            .into(),
        reason: "omega = J a/I (angular impulse about the centre), and omega(l) - omega(a) = J (l - a)/I > 0 for a < l".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "the solver's omega equals J a/I with J = m (v0 - v) its own impulse (any I, any e)",
                Formula::named("omega", out.after.omega.clone()),
                Formula::named("J", out.impulse(&p)) * &f("a") / &Formula::from(inertia),
            ),
            positive("a given impulse J > 0: omega(l) - omega(a) = J (l - a)/I > 0 for a < l (l = a + s, s > 0)", at_a(&given, sym("l")) - &given, true, &[("l", a + &sym("s"))], &["J", "I", "s"], &[], quot(prod([ps("J"), ps("s")]), ps("I"))),
        ]),
    }
}
