use crate::claims::dsl::*;
use crate::field::Sym;

pub(super) const ENTRY: Entry = Entry {
    id: "C41",
    location: "Eq. (maximal-a-gyration)",
    group: Group::Inhomogeneous,
    statement: "a* = sqrt((M+m)/m) r_G",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Gyration, ExportLaw::Elastic),
        &[Check::holds(
            "a* = sqrt((M+m)/m) r_G maximises omega over a >= 0",
            "a >= 0 and a != s => omega < omega_s",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*r^2/m"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let omega = free_omega(gyration_inertia());
    let a_star_sq = Formula::named("a*^2", paper.a_star_gyration_squared.clone());
    let a2 = f("a").pow(2);
    let slope = (Formula::int(1) + &f("e")) * &f("v0") * &(a_star_sq.clone() - &a2)
        / &(a_star_sq + &a2).pow(2);
    Formalised {
        formal: "I = M r_G^2 (r_G > 0), any e in [0, 1]: the solver's omega has d omega/da = \
                 (1+e) v0 (a*^2 - a^2)/(a*^2 + a^2)^2 with a*^2 = (M + m) r_G^2/m, so omega increases \
                 for 0 <= a < a* and decreases beyond: a* = sqrt((M + m)/m) r_G (the positive root) is \
                 the unconstrained maximiser. It agrees with Eq. (maximal-a-general) at I = M r_G^2."
            .into(),
        reason: "the solver's d omega/da is (1+e) v0 (a*^2 - a^2)/(a*^2 + a^2)^2 with Eq. (maximal-a-gyration)'s a*^2, and Eq. (maximal-a-general) agrees".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "d omega/da of the solver's omega (I = M r_G^2, any e) equals (1+e) v0 (a*^2 - a^2)/(a*^2 + a^2)^2 with a*^2 from Eq. (maximal-a-gyration)",
                Formula::named("omega'", omega.derivative(Sym::new("a"))),
                slope,
            ),
            Certificate::identity_at(
                "Eq. (maximal-a-general) at I = M r_G^2 equals Eq. (maximal-a-gyration)",
                paper.a_star_squared.clone(),
                paper.a_star_gyration_squared.clone(),
                &[("I", gyration_inertia())],
            ),
        ]),
    }
}
