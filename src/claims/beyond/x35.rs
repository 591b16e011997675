use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X35",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Newton's cradle of three equal balls (e = 1), the first striking the two at rest: simultaneous Newton and Poisson both conserve momentum and energy yet send the first ball back at -v/3 and the others on at 2v/3; sequential impacts, in either order, conserve both too and leave only the last ball moving, at v",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy, in pure algebra: W = (1/m) [2, -1; -1, 2], u0 = (-v, 0).
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::holds(
                "simultaneous Newton, both contacts pushing (l1, l2 > 0) and leaving at v and 0: the velocities are (-v/3, 2v/3, 2v/3), momentum and energy kept",
                "l1 > 0 and l2 > 0 and v - l1/m = -v/3 and (l1 - l2)/m = 2*v/3 and l2/m = 2*v/3 and m*(v - l1/m) + m*(l1 - l2)/m + m*l2/m = m*v and m*((v - l1/m)^2 + ((l1 - l2)/m)^2 + (l2/m)^2)/2 = m*v^2/2",
            )
            .given(&["(2*l1 - l2)/m = 2*v", "(-l1 + 2*l2)/m = 0"]),
            Check::holds(
                "sequential, contact 1 then 2: each fires the single-contact impulse (1 + e) |u|/W_ii = m |u|, leaving (0, 0, v)",
                "v - s1/m = 0 and s1/m - s2/m = 0 and s2/m = v",
            )
            .given(&["s1 = 2*v/(2/m)", "s2 = 2*(s1/m)/(2/m)"]),
        ],
    )
    .at(&[])
    .given(&["m > 0", "v > 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (m, v) = (sym("m"), sym("v"));
    let (l1, l2) = (k(4, 3) * &m * &v, k(2, 3) * &m * &v);
    let balls = [
        v.clone() - &(l1.clone() / &m),
        (l1.clone() - &l2) / &m,
        l2.clone() / &m,
    ];
    let energy = |vs: &[RatFn]| {
        vs.iter()
            .fold(k(0, 1), |t, x| t + &(m.clone() * &sq(x) / &k(2, 1)))
    };
    let momentum = |vs: &[RatFn]| vs.iter().fold(k(0, 1), |t, x| t + &(m.clone() * x));
    // Sequential 1 then 2 (and 2 then 1: contact 2 does not approach first, so the same).
    let (s1, s2) = (m.clone() * &v, m.clone() * &v);
    let sequential = [v.clone() - &(s1.clone() / &m), (s1 - &s2) / &m, s2 / &m];
    proved(
        "Three equal balls of mass m > 0 in a row, touching, frictionless, e = 1; the first moves at \
         v > 0 into the others. The Delassus matrix is W = (1/m) [2, -1; -1, 2] and u0 = (-v, 0). \
         Simultaneous Newton: with both contacts pushing, W lam = (2v, 0) gives lam = (4mv/3, 2mv/3) > 0, \
         and the velocities after are (-v/3, 2v/3, 2v/3): the normal velocities after are v and 0, so \
         every complementarity condition holds (rodimpact enumerates every active set and finds this \
         one only); simultaneous Poisson gives the same (no contact separates before, equal e). \
         Sequential: contact 1 fires m v (ball 1 stops, ball 2 takes v), then contact 2 fires m v, \
         leaving (0, 0, v); starting with contact 2 fires nothing first, so both orders agree. \
         Both answers keep momentum m v and energy m v^2/2, and they differ.",
        "the simultaneous answer (-v/3, 2v/3, 2v/3) and the sequential (0, 0, v) both keep momentum and energy",
        vec![
            id(
                "simultaneous Newton: W lam = (2v, 0) at lam = (4mv/3, 2mv/3), first row",
                n("(W lam)_1", (k(2, 1) * &l1 - &l2) / &m),
                k(2, 1) * &v,
            ),
            id(
                "second row",
                n("(W lam)_2", (-l1.clone() + &(k(2, 1) * &l2)) / &m),
                k(0, 1),
            ),
            positive(
                "lam_2 = 2mv/3 > 0 (and lam_1 = 2 lam_2): both contacts push",
                l2.clone(),
                true,
                &[],
                &["m", "v"],
                &[],
                prod([pc(2, 3), ps("m"), ps("v")]),
            ),
            id(
                "the first ball after (simultaneous) = -v/3",
                n("v_1", balls[0].clone()),
                -(v.clone() / &k(3, 1)),
            ),
            id(
                "momentum after (simultaneous) = m v",
                n("p", momentum(&balls)),
                m.clone() * &v,
            ),
            id(
                "energy after (simultaneous) = m v^2/2",
                n("K", energy(&balls)),
                m.clone() * &sq(&v) / &k(2, 1),
            ),
            id(
                "the first ball after (sequential) = 0",
                n("v_1", sequential[0].clone()),
                k(0, 1),
            ),
            id(
                "the last ball after (sequential) = v",
                n("v_3", sequential[2].clone()),
                v.clone(),
            ),
            id(
                "energy after (sequential) = m v^2/2",
                n("K", energy(&sequential)),
                m.clone() * &sq(&v) / &k(2, 1),
            ),
            id(
                "momentum after (sequential) = m v",
                n("p", momentum(&sequential)),
                m.clone() * &v,
            ),
        ],
    )
}
