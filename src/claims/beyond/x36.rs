use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X36",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Projected Gauss-Seidel on Newton's cradle of three equal balls (e = 1): one sweep from zero impulses loses exactly half the energy, and each further sweep shrinks the impulses' error from the simultaneous Newton answer by exactly 1/4",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy: one sweep, l1' = l1 - ((2 l1 - l2)/m - 2v) m/2, then
// l2' = l2 - ((2 l2 - l1')/m) m/2, with the error from (4mv/3, 2mv/3).
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::holds(
                "from lam = (4mv/3, 2mv/3 + d): one sweep gives (4mv/3 + d/2, 2mv/3 + d/4)",
                "a = 4*m*v/3 + d/2 and b = 2*m*v/3 + d/4",
            )
            .given(&["a = (2*m*v + (2*m*v/3 + d))/2", "b = a/2"]),
            Check::holds(
                "one sweep from zero: lam = (m v, m v/2), the balls at (0, v/2, v/2), energy m v^2/4",
                "m*((v - a/m)^2 + ((a - b)/m)^2 + (b/m)^2)/2 = m*v^2/4",
            )
            .given(&["a = m*v", "b = a/2"]),
        ],
    )
    .at(&[])
    .given(&["m > 0", "v > 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (m, v, d) = (sym("m"), sym("v"), sym("d"));
    // One Gauss-Seidel update of each contact (both stay pushing near the answer).
    let sweep = |l1: &RatFn, l2: &RatFn| {
        let a = l1.clone() - &(((k(2, 1) * l1 - l2) / &m - &(k(2, 1) * &v)) * &m / &k(2, 1));
        let b = l2.clone() - &((k(2, 1) * l2 - &a) / &m * &m / &k(2, 1));
        (a, b)
    };
    let (star1, star2) = (k(4, 3) * &m * &v, k(2, 3) * &m * &v);
    let (a, b) = sweep(&star1, &(star2.clone() + &d));
    let (z1, z2) = sweep(&k(0, 1), &k(0, 1));
    let balls = [
        v.clone() - &(z1.clone() / &m),
        (z1.clone() - &z2) / &m,
        z2.clone() / &m,
    ];
    let energy = balls
        .iter()
        .fold(k(0, 1), |t, x| t + &(m.clone() * &sq(x) / &k(2, 1)));
    proved(
        "Three equal balls of mass m > 0, e = 1, the first at v > 0 (W = (1/m) [2, -1; -1, 2], \
         u0 = (-v, 0), simultaneous Newton answer lam* = (4mv/3, 2mv/3)). A sweep of projected \
         Gauss-Seidel updates contact 1 then contact 2, lam_i <- max(0, lam_i - (u_i + e u0_i^-)/W_ii). \
         Near lam* both updates stay positive (the projection does nothing), so a sweep is the affine \
         map written in the certificates: from lam = (lam*_1 + c, lam*_2 + d) it gives \
         (lam*_1 + d/2, lam*_2 + d/4), whatever c: after the first sweep every error is a quarter of \
         the one before. From zero the first sweep gives (mv, mv/2), the balls at (0, v/2, v/2), \
         energy mv^2/4: half of mv^2/2 lost. (rodimpact's pgs:K runs this exactly; tests compare eight \
         sweeps with the oracle.)",
        "a sweep maps the error d of lam_2 to d/4 (and lam_1's to d/2), and the first sweep from zero keeps half the energy",
        vec![
            id(
                "one sweep: lam_1' - lam*_1 = d/2",
                n("lam_1'", a) - &star1,
                d.clone() / &k(2, 1),
            ),
            id(
                "one sweep: lam_2' - lam*_2 = d/4",
                n("lam_2'", b) - &star2,
                d.clone() / &k(4, 1),
            ),
            id(
                "the first sweep from zero: lam = (m v, m v/2)",
                n("lam_1", z1) + &n("lam_2", z2),
                k(3, 2) * &m * &v,
            ),
            id(
                "its energy after = m v^2/4, half of m v^2/2",
                n("K", energy),
                m.clone() * &sq(&v) / &k(4, 1),
            ),
        ],
    )
}
