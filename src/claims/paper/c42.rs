use crate::claims::dsl::*;
use crate::field::q;

pub(super) const ENTRY: Entry = Entry {
    id: "C42",
    location: "§inhomogeneous",
    group: Group::Inhomogeneous,
    statement: "Mass concentrated near the middle (r_G << l) gives a* < l \"even for M >> m\"",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Elastic),
    &[
        Check::fails("reading: a small r_G/l gives a* < l even for M >> m; refuted at r_G = l/20, M = 1000 m", "s < l").given(&["m = 1", "M = 1000", "l = 20", "r = 1"]),
        Check::holds("qualified: M < m (l^2/r_G^2 - 1) gives a* < l", "s < l").given(&["M < m*(l^2/r^2 - 1)"]),
        Check::holds("and only it", "s >= l").given(&["M >= m*(l^2/r^2 - 1)"]),
    ],
)
.at(&[])
.given(&["l > 0", "r < l", "s > 0", "s^2 = (M + m)*r^2/m"]));

fn formalise(paper: &Paper) -> Formalised {
    let omega = free_omega(gyration_inertia());
    let proof = vec![
        gyration_interior_optimal(paper),
        gyration_end_optimal(paper),
        Certificate::witness(
            "M = 100 m, r_G = l/20: a* = sqrt(101) l/20 < l, and omega(a*) > omega(l) (solver, e = 1)",
            at(&[
                ("m", rational(1, 1)),
                ("M", rational(100, 1)),
                ("r_G", rational(1, 20)),
                ("l", rational(1, 1)),
                ("v0", rational(1, 1)),
                ("e", rational(1, 1)),
                ("a", sqrt(&q(101, 400))),
            ]),
            omega.clone(),
            Relation::Gt,
            at_a(&omega, sym("l")),
        ),
    ];
    let counterexample = vec![Certificate::witness(
        "r_G = l/20 (mass near the middle) but M = 1000 m: Eq. (maximal-a-gyration) gives a*^2 = (1001/400) l^2 > l^2, so a = l is the optimum",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1000, 1)),
            ("r_G", rational(1, 20)),
            ("l", rational(1, 1)),
        ]),
        paper.a_star_gyration_squared.clone(),
        Relation::Gt,
        sq(&sym("l")),
    )];
    Formalised {
        formal: "Symmetric rod with I = M r_G^2, 0 < r_G < l. Natural reading: a small r_G/l makes a* < l \
                 even when M >> m. Exactly: a* < l iff r_G^2/l^2 < m/(M + m), i.e. iff \
                 M < m (l^2/r_G^2 - 1). How concentrated the rod must be depends on M/m: for every M/m, \
                 however large, r_G/l < sqrt(m/(M + m)) qualifies (M = 100 m, r_G = l/20), but no fixed \
                 r_G/l works for all M >> m (r_G = l/20, M = 1000 m gives a* > l)."
            .into(),
        reason: "a* < l iff r_G/l < sqrt(m/(M + m)): any M/m allows it for r_G small enough (M = 100 m, r_G = l/20), but a given r_G << l fails once M/m > l^2/r_G^2 - 1 (r_G = l/20, M = 1000 m)".into(),
        decision: Decision::Qualified {
            qualification: "for M >> m the concentration must grow with M/m: a* < l iff r_G/l < sqrt(m/(M + m)), i.e. M < m (l^2/r_G^2 - 1)".into(),
            counterexample,
            proof,
        },
    }
}
