use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X7",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Universal curve: omega(a)/omega(a*) = 2s/(1+s^2) with s = a/a*; reciprocity omega(a) = omega(a*^2/a)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution),
        &[
            Check::holds(
                "omega(a)/omega(a*) = 2s/(1+s^2) with s = a/a*",
                "omega/omega_s = 2*(a/s)/(1 + (a/s)^2)",
            ),
            Check::holds("reciprocity omega(a) = omega(a*^2/a)", "omega = omega_r"),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
        StrikePoint {
            at: "s^2/a",
            tag: "r",
        },
    ])
    .given(&["a > 0", "s > 0", "s^2 = (M + m)*I/(m*M)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let (a, big_a) = (sym("a"), sym("A"));
    let omega = after(&sym("I"), sym("e")).omega;
    let s_f = n("s", a.clone() / big_a.clone());
    let mirrored = subs(&omega, &[("a", paper.a_star_squared.value().clone() / a)]);
    proved(
        "For m, M, I, v0 > 0, e >= 0 and a > 0: with I = A^2 mM/(M+m) (A = a*) the solver's \
         omega(a)/omega(A) equals 2s/(1+s^2), s = a/A, for every e and masses; and omega(a) = \
         omega(a*^2/a) identically (a*^2 from Eq. (maximal-a-general); the partner a*^2/a may lie \
         off the rod).",
        "the ratio reduces identically to 2s/(1+s^2), which is invariant under s -> 1/s",
        vec![
            Certificate::identity_at(
                "omega(a)/omega(a*) from the solver (I = A^2 mM/(M+m)) = 2s/(1+s^2), s = a/A",
                n("omega", omega.clone()) / &n("omega(A)", subs(&omega, &[("a", big_a)])),
                Formula::int(2) * &s_f / &(Formula::int(1) + &s_f.pow(2)),
                &[("I", inertia_of_a_star(paper))],
            ),
            id(
                "omega(a*^2/a) = omega(a) (solver's omega, a*^2 = Eq. (maximal-a-general) squared)",
                n("omega(a*^2/a)", mirrored),
                n("omega", omega),
            ),
        ],
    )
}
