use crate::claims::dsl::*;
use crate::field::ratfunc::Point;

pub(super) const ENTRY: Entry = Entry {
    id: "C43",
    location: "§inhomogeneous",
    group: Group::Inhomogeneous,
    statement: "Mass concentrated near the ends (r_G close to l): a* < l only for M << m",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Elastic),
    &[
        Check::holds("a* < l iff M/m < l^2/r_G^2 - 1 = u (2l - u)/(l - u)^2 for r_G = l - u, a bound that vanishes as u -> 0+", "(s < l => M/m < u*(2*l - u)/(l - u)^2) and (M/m < u*(2*l - u)/(l - u)^2 => s < l)"),
    ],
)
.at(&[])
.given(&["l > 0", "u > 0", "u < l", "r = l - u", "s > 0", "s^2 = (M + m)*r^2/m"]));

fn formalise(paper: &Paper) -> Formalised {
    let (l, rg) = (sym("l"), sym("r_G"));
    let bound = sq(&l) / sq(&rg) - &one();
    let bound_near_end = subs(&bound, &[("r_G", l - &sym("u"))]);
    Formalised {
        formal: "Symmetric rod with I = M r_G^2, 0 < r_G < l: a* < l iff M/m < beta(r_G) = l^2/r_G^2 - 1, \
                 and beta(r_G) -> 0 as r_G -> l- (r_G = l - u, u -> 0+). So for r_G close to l an \
                 interior optimum needs M/m below a bound that vanishes: 'M << m' made exact. (At r_G = l \
                 it never happens, C44.)"
            .into(),
        reason: "a* < l iff M < m (l^2/r_G^2 - 1), and the bound l^2/r_G^2 - 1 tends to 0 as r_G -> l".into(),
        decision: Decision::Proved(vec![
            gyration_end_optimal(paper),
            gyration_interior_optimal(paper),
            Certificate::limit(
                "the mass-ratio bound l^2/r_G^2 - 1 at r_G = l - u tends to 0 as u -> 0+",
                bound_near_end,
                "u",
                Point::Zero,
                k(0, 1),
            ),
        ]),
    }
}
