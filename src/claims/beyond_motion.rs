//! Results beyond the paper, X14-X26: the motion after the impact (far end, energy shares,
//! limits, fixed axis, second impact, asymmetric rod).

use super::build::*;
use super::model::*;
use super::{Certificate, Claim, Decision, Entry, Formula, Group, Paper, PosExpr, Relation};
use crate::field::RatFn;
use crate::field::ratfunc::Point;
use crate::mechanics::{Motion, angular_momentum};
use crate::solve::solve_linear;

/// The registered claims of this part.
pub(super) const ENTRIES: &[Entry] = &[
    Entry {
        id: "X14",
        build: x14,
    },
    Entry {
        id: "X15",
        build: x15,
    },
    Entry {
        id: "X16",
        build: x16,
    },
    Entry {
        id: "X17",
        build: x17,
    },
    Entry {
        id: "X18",
        build: x18,
    },
    Entry {
        id: "X19",
        build: x19,
    },
    Entry {
        id: "X20",
        build: x20,
    },
    Entry {
        id: "X21",
        build: x21,
    },
    Entry {
        id: "X22",
        build: x22,
    },
    Entry {
        id: "X23",
        build: x23,
    },
    Entry {
        id: "X24",
        build: x24,
    },
    Entry {
        id: "X25",
        build: x25,
    },
    Entry {
        id: "X26",
        build: x26,
    },
];

const WHERE: &str = "beyond the paper";

// ---------------------------------------------------------------------------------------------
// Shared builders.

/// `r_G^2`.
fn r2() -> RatFn {
    sym("r_G") * &sym("r_G")
}

/// The general free-rod solution with I = M r_G^2 and restitution e, from the generic solver.
fn gyration_motion() -> Motion<RatFn> {
    motion(&free_rod(gyration_inertia(), sym("e")))
}

/// `I = m M a^2/(M + m)`: the value of I for which the impact point a is the optimum a*.
fn inertia_at_a_star() -> RatFn {
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    m.clone() * &big_m * &a * &a / (big_m + &m)
}

/// `I = m M a^2/(M + m)`: the substitution that puts the impact point at a*.
fn a_star_at() -> [(&'static str, RatFn); 1] {
    [("I", inertia_at_a_star())]
}

/// An identity at a* (see [`a_star_at`]).
fn id_at_star(title: &str, lhs: impl Into<Formula>, rhs: impl Into<Formula>) -> Certificate {
    Certificate::identity_at(title, lhs, rhs, &a_star_at())
}

/// A symbol as a [`Formula`].
fn f(name: &str) -> Formula {
    Formula::sym(name)
}

/// A computed value under a name (the solver's `omega`, ...).
fn n(name: &str, value: impl Into<Formula>) -> Formula {
    Formula::named(name, value)
}

/// The velocity `V + omega y` of the rod point at `y`, with the solver's V and omega named.
fn point_velocity(motion: &Motion<RatFn>, y: Formula) -> Formula {
    n("V", motion.rod_v.clone()) + &(n("omega", motion.omega.clone()) * &y)
}

/// The substitution `I = m M a^2/(M + m)` puts the impact point at the paper's a*.
fn a_star_substitution_cert(paper: &Paper) -> Certificate {
    id_at_star(
        "with I = m M a^2/(M + m) the paper's a*^2 = (M + m) I/(m M) equals a^2: the impact is at a*",
        paper.a_star_squared.clone(),
        f("a").pow(2),
    )
}

/// The paper's closed form with I = M r_G^2 substituted.
fn with_gyration(x: &RatFn) -> RatFn {
    subs(x, &[("I", gyration_inertia())])
}

// ---------------------------------------------------------------------------------------------
// X14: the far end.

fn x14(paper: &Paper) -> Claim {
    let l = sym("l");
    let after = gyration_motion();
    let far = after.rod_point_velocity(&-l.clone());
    let elastic = motion(&free_rod(gyration_inertia(), int(1)));
    let factor_f = Formula::int(1) - &(f("a") * &f("l") / &f("r_G").pow(2));
    let denominator = |x: RatFn| {
        PosExpr::sum([
            PosExpr::product([ps("M"), ps("r_G"), ps("r_G")]),
            PosExpr::product([ps("m"), ps("r_G"), ps("r_G")]),
            PosExpr::product([ps("m"), PosExpr::Square(x)]),
        ])
    };
    let domain: (&[&str], &[&str]) = (&["m", "M", "r_G", "l", "v0", "s"], &["e"]);
    let beyond = (r2() + &sym("s")) / l.clone();
    let before = (r2() - &sym("s")) / l.clone();
    let numerator = PosExpr::product([one_plus_e(), ps("v0"), ps("m"), ps("s")]);
    let uniform_far =
        motion(&free_rod(paper.uniform_inertia.clone(), sym("e"))).rod_point_velocity(&-l.clone());
    let uniform_beyond = l.clone() / k(3, 1) + &sym("s");
    let certs = vec![
        Certificate::identity(
            "velocity of the far end y = -l (generic solver, any e) = V (1 - a l/r_G^2)",
            point_velocity(&after, -f("l")),
            n("V", after.rod_v.clone()) * &factor_f,
        ),
        Certificate::identity(
            "elastic: velocity of the far end = the paper's Eq. (V) times (1 - a l/r_G^2)",
            point_velocity(&elastic, -f("l")),
            paper.big_v.subs(&[("I", gyration_inertia())]) * &factor_f,
        ),
        positive(
            "a l = r_G^2 + s, s > 0: minus the far end's velocity = (1+e) m v0 s/(M r_G^2 + m r_G^2 + m a^2) > 0 (backwards)",
            -far.clone(),
            true,
            &[("a", beyond.clone())],
            domain.0,
            domain.1,
            PosExpr::quotient(numerator.clone(), denominator(beyond)),
        ),
        positive(
            "a l = r_G^2 - s, s >= 0: the far end's velocity = (1+e) m v0 s/(M r_G^2 + m r_G^2 + m a^2) >= 0 (not backwards)",
            far,
            false,
            &[("a", before.clone())],
            &["m", "M", "r_G", "l", "v0"],
            &["e", "s"],
            PosExpr::quotient(numerator, denominator(before)),
        ),
        positive(
            "uniform rod (Eq. (inertia-homogeneous)), a = l/3 + s, s > 0: minus the far end's velocity > 0",
            -uniform_far,
            true,
            &[("a", uniform_beyond.clone())],
            &["m", "M", "l", "v0", "s"],
            &["e"],
            PosExpr::quotient(
                PosExpr::product([one_plus_e(), ps("v0"), ps("m"), ps("s"), ps("l")]),
                PosExpr::sum([
                    PosExpr::quotient(
                        PosExpr::product([PosExpr::sum([ps("M"), ps("m")]), ps("l"), ps("l")]),
                        pc(3, 1),
                    ),
                    PosExpr::product([ps("m"), PosExpr::Square(uniform_beyond)]),
                ]),
            ),
        ),
    ];
    Claim {
        id: "X14",
        location: WHERE,
        group: Group::Beyond,
        statement: "The far end moves with V(1 - a l/r_G^2): it moves backwards iff a > r_G^2/l (uniform rod: a > l/3)",
        formal: "Free rod, I = M r_G^2, m, M, r_G, l, v0 > 0, any restitution e in [0, 1], impact at a > 0 (so the \
                 far end is the end at y = -l; at a = 0 both ends move with V). The far end's velocity right after \
                 the impact, V - omega l from the generic solver, equals V (1 - a l/r_G^2); since V = (1+e) m v0 \
                 r_G^2/(M r_G^2 + m r_G^2 + m a^2) > 0, it is negative (backwards) iff a l > r_G^2, zero at \
                 a = r_G^2/l. For the uniform rod r_G^2 = l^2/3, so the threshold is a = l/3."
            .into(),
        reason: "the far end's velocity is V (1 - a l/r_G^2) identically, and its sign is that of r_G^2 - a l".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X15: the elastic rod takes all of K0 where the projectile stops.

fn x15(paper: &Paper) -> Claim {
    let (m, big_m, l, a, v0) = (sym("m"), sym("M"), sym("l"), sym("a"), sym("v0"));
    let p = free_rod(uniform_inertia(), int(1));
    let after = motion(&p);
    let a0_squared = l.clone() * &l * &(big_m.clone() - &m) / (k(3, 1) * &m);
    let a2 = a.clone() * &a;
    let k0 = m.clone() * &v0 * &v0 / k(2, 1);
    let rod_energy = (big_m.clone() * &after.rod_v * &after.rod_v
        + &(p.inertia.clone() * &after.omega * &after.omega))
        / k(2, 1);
    let two = Formula::int(2);
    let (a0_f, a_star2_f) = (
        n("a0^2", a0_squared.clone()),
        n("a*^2", paper.a_star_uniform_squared.clone()),
    );
    let ratio_f = (f("a").pow(2) - &a0_f) / &(f("a").pow(2) + &a_star2_f);
    // a = a*, i.e. M = 3 m a^2/l^2 - m.
    let mass_at_a_star = k(3, 1) * &m * &a2 / (l.clone() * &l) - &m;
    let certs = vec![
        Certificate::identity(
            "elastic uniform rod: v (generic solver) = v0 (a^2 - a0^2)/(a^2 + a*^2), a0^2 = l^2 (M - m)/(3m), a*^2 of Eq. (maximal-a-homogeneous)",
            n("v", after.v.clone()),
            f("v0") * &ratio_f,
        ),
        Certificate::identity(
            "the rod's energy M V^2/2 + I omega^2/2 = K0 (1 - ((a^2 - a0^2)/(a^2 + a*^2))^2): all of K0 iff a^2 = a0^2",
            f("M") * &n("V", after.rod_v.clone()).pow(2) / &two
                + &(n("I", p.inertia.clone()) * &n("omega", after.omega.clone()).pow(2) / &two),
            f("m") * &f("v0").pow(2) / &two * &(Formula::int(1) - &ratio_f.pow(2)),
        ),
        Certificate::identity(
            "a*^2 - a0^2 = 2 l^2/3 (a* from Eq. (maximal-a-homogeneous))",
            a_star2_f.clone() - &a0_f,
            Formula::int(2) * &f("l").pow(2) / &Formula::int(3),
        ),
        Certificate::identity_at(
            "with M = 3 m a^2/l^2 - m the impact point a is the paper's a*",
            paper.a_star_uniform_squared.clone(),
            f("a").pow(2),
            &[("M", mass_at_a_star.clone())],
        ),
        positive(
            "at a = a* (M = 3 m a^2/l^2 - m): K0 - rod energy = m v0^2 l^4/(18 a^4) > 0, so not all of K0",
            k0 - &rod_energy,
            true,
            &[("M", mass_at_a_star)],
            &["m", "v0", "l", "a"],
            &[],
            PosExpr::quotient(
                PosExpr::product([
                    ps("m"),
                    ps("v0"),
                    ps("v0"),
                    ps("l"),
                    ps("l"),
                    ps("l"),
                    ps("l"),
                ]),
                PosExpr::product([pc(18, 1), ps("a"), ps("a"), ps("a"), ps("a")]),
            ),
        ),
    ];
    Claim {
        id: "X15",
        location: WHERE,
        group: Group::Beyond,
        statement: "The elastic rod takes all of K0 where the projectile stops (a0), not at a*: a*^2 - a0^2 = 2l^2/3",
        formal: "Uniform rod (I = M l^2/3), e = 1, m, M, l, v0 > 0, 0 <= a <= l. The generic solver gives \
                 v = v0 (a^2 - a0^2)/(a^2 + a*^2) with a0^2 = l^2 (M - m)/(3m), and the rod's kinetic energy is \
                 K0 (1 - (v/v0)^2): it equals K0 exactly where v = 0, i.e. at a = a0. Such a point exists on the \
                 rod only when 0 <= a0^2 <= l^2, i.e. m <= M <= 4m; otherwise no impact point gives the rod all \
                 of K0. a*^2 - a0^2 = 2 l^2/3 > 0 identically, so a0 != a*; at a = a* the projectile keeps \
                 v = v0 l^2/(3 a*^2) > 0 and the rod's energy falls short of K0 by m v0^2 l^4/(18 a*^4)."
            .into(),
        reason: "v = v0 (a^2 - a0^2)/(a^2 + a*^2) vanishes only at a0, and a*^2 - a0^2 = 2l^2/3 identically".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X16, X17: limits of the rod's mass.

fn x16(paper: &Paper) -> Claim {
    let (a, v0) = (sym("a"), sym("v0"));
    let (v, big_v, omega) = (
        with_gyration(&paper.v),
        with_gyration(&paper.big_v),
        with_gyration(&paper.omega),
    );
    let r2a2 = r2() + &(a.clone() * &a);
    let struck = big_v.clone() + &(omega.clone() * &a);
    let general = gyration_motion();
    let lim = |title: &str, expr: RatFn, expected: RatFn| {
        Certificate::limit(title, expr, "M", Point::Zero, expected)
    };
    let certs = vec![
        lim("Eq. (v) with I = M r_G^2: v -> v0 as M -> 0", v, v0.clone()),
        lim(
            "Eq. (V) with I = M r_G^2: V -> 2 v0 r_G^2/(r_G^2 + a^2) as M -> 0",
            big_v,
            k(2, 1) * &v0 * &r2() / r2a2.clone(),
        ),
        lim(
            "Eq. (omega) with I = M r_G^2: omega -> 2 v0 a/(r_G^2 + a^2) as M -> 0",
            omega,
            k(2, 1) * &v0 * &a / r2a2,
        ),
        lim(
            "struck point V + omega a (Eqs. (V), (omega)) -> 2 v0 as M -> 0",
            struck,
            k(2, 1) * &v0,
        ),
        lim(
            "Eq. (maximal-a-gyration): a*^2 -> r_G^2 as M -> 0",
            paper.a_star_gyration_squared.value().clone(),
            r2(),
        ),
        lim(
            "any e (generic solver): struck point -> (1+e) v0 as M -> 0",
            general.rod_point_velocity(&a),
            (int(1) + &sym("e")) * &v0,
        ),
    ];
    Claim {
        id: "X16",
        location: WHERE,
        group: Group::Beyond,
        statement: "M -> 0 with r_G fixed: v -> v0, V -> 2v0 r^2/(r^2 + a^2), omega -> 2v0 a/(r^2 + a^2), the struck point -> 2v0, a* -> r_G",
        formal: "Elastic impact (the paper's Eqs. (v), (V), (omega)), I = M r_G^2 with r = r_G > 0 fixed, m, v0 > 0, \
                 any a: the exact limits as M -> 0+ are v -> v0, V -> 2 v0 r^2/(r^2 + a^2), \
                 omega -> 2 v0 a/(r^2 + a^2), the struck point's velocity V + omega a -> 2 v0, and \
                 a*^2 = (M + m) r^2/m -> r^2 (so a* -> r_G, a* being positive). With restitution e the struck \
                 point tends to (1+e) v0 (generic solver)."
            .into(),
        reason: "exact limits M -> 0+ of the paper's formulas with I = M r_G^2".into(),
        decision: Decision::Proved(certs),
    }
}

fn x17(paper: &Paper) -> Claim {
    let (m, big_m, a, v0) = (sym("m"), sym("M"), sym("a"), sym("v0"));
    let omega = with_gyration(&paper.omega);
    let v = with_gyration(&paper.v);
    let general = gyration_motion();
    let one_plus_a2 = int(1) + &(a.clone() * &a / r2());
    let lim = |title: &str, expr: RatFn, expected: RatFn| {
        Certificate::limit(title, expr, "M", Point::Infinity, expected)
    };
    let certs = vec![
        lim(
            "Eq. (omega), I = M r_G^2: M omega -> 2 m a v0/r_G^2 as M -> infinity, i.e. omega ~ 2 m a v0/(M r_G^2)",
            big_m.clone() * &omega,
            k(2, 1) * &m * &a * &v0 / r2(),
        ),
        lim(
            "Eq. (v), I = M r_G^2: M (v + v0) -> 2 m v0 (1 + a^2/r_G^2), i.e. v + v0 ~ 2 m v0 (1 + a^2/r_G^2)/M",
            big_m.clone() * &(v + &v0),
            k(2, 1) * &m * &v0 * &one_plus_a2,
        ),
        lim(
            "any e (generic solver): v -> -e v0 as M -> infinity",
            general.v.clone(),
            -(sym("e") * &v0),
        ),
        lim(
            "any e (generic solver): M omega -> (1+e) m a v0/r_G^2",
            big_m * &general.omega,
            (int(1) + &sym("e")) * &m * &a * &v0 / r2(),
        ),
    ];
    Claim {
        id: "X17",
        location: WHERE,
        group: Group::Beyond,
        statement: "M -> oo: omega ~ 2m a v0/(M r_G^2), v + v0 ~ 2m v0(1 + a^2/r_G^2)/M; with restitution, v -> -e v0",
        formal: "I = M r_G^2 with r_G > 0 fixed (so I -> oo with M), m, v0 > 0, any a. 'x ~ c/M' is certified as \
                 the exact finite limit M x -> c as M -> oo (equivalent for c != 0). Elastic (the paper's \
                 formulas): M omega -> 2 m a v0/r_G^2 and M (v + v0) -> 2 m v0 (1 + a^2/r_G^2). Restitution e \
                 (generic solver): v -> -e v0 and M omega -> (1+e) m a v0/r_G^2."
            .into(),
        reason: "exact limits as M -> oo of M omega, M (v + v0) and v, with I = M r_G^2".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X18: the pivoted rod.

fn x18(paper: &Paper) -> Claim {
    let (m, big_m, a, p) = (sym("m"), sym("M"), sym("a"), sym("p"));
    let params = pivoted_rod(sym("I"), sym("e"));
    let out = solved(&params);
    let omega = out.after.omega.clone();
    let pivot_impulse = out
        .pivot_impulse
        .clone()
        .expect("a pivoted scene reports its pivot impulse");
    let d = a.clone() - &p;
    let i_p = params.inertia_about_axis();
    let (d_f, i_p_f) = (n("d", d.clone()), n("I_p", i_p.clone()));
    let fixed_axis_f = i_p_f.clone() + &(f("m") * &d_f.pow(2));
    let omega_at = |x: RatFn| subs(&omega, &[("a", p.clone() + &x)]);
    let (u, dd) = (sym("u"), sym("d"));
    // Door: width L = 2l, pivot at the edge p = -l, uniform (Eq. (inertia-homogeneous)).
    let door = door(paper);
    let door_i_p = door.inertia_about_axis();
    let h = sym("h");
    let certs = vec![
        Certificate::identity(
            "generic solver, pivot at p: omega = (1+e) m d v0/(I_p + m d^2), d = a - p, I_p = I + M p^2",
            n("omega", omega.clone()),
            (Formula::int(1) + &f("e")) * &f("m") * &d_f * &f("v0") / &fixed_axis_f,
        ),
        positive(
            "I_p = m d*^2 (I = m u^2 - M p^2, u = d*): omega(d*) - omega(d) = (1+e) v0 (d* - d)^2/(2 d* (d*^2 + d^2)) >= 0, zero only at d = d*",
            omega_at(u.clone()) - &omega_at(dd.clone()),
            false,
            &[("I", m.clone() * &u * &u - &(big_m.clone() * &p * &p))],
            &["u", "v0"],
            &["e"],
            PosExpr::quotient(
                PosExpr::product([one_plus_e(), ps("v0"), PosExpr::Square(u - &dd)]),
                PosExpr::product([
                    pc(2, 1),
                    ps("u"),
                    PosExpr::sum([PosExpr::product([ps("u"), ps("u")]), PosExpr::Square(dd)]),
                ]),
            ),
        ),
        door_cert(&door_i_p, true),
        door_cert(&door_i_p, false),
        Certificate::identity(
            "pivot impulse M V - J (generic solver) = -(1+e) m v0 (I_p + M p d)/(I_p + m d^2): zero iff d = -I_p/(M p)",
            n("P_pivot", pivot_impulse.clone()),
            -((Formula::int(1) + &f("e"))
                * &f("m")
                * &f("v0")
                * &(i_p_f.clone() + &(f("M") * &f("p") * &d_f))
                / &fixed_axis_f),
        ),
        Certificate::identity_at(
            "pivot at p = -h (h > 0), impact at d = I_p/(M h) from the pivot (beyond the centre): the pivot impulse is 0",
            n("P_pivot", pivot_impulse),
            int(0),
            &[
                ("p", -h.clone()),
                ("a", -h.clone() + &(i_p_at(&h) / (big_m.clone() * &h))),
            ],
        ),
        Certificate::identity(
            "door (uniform, width L = 2l, pivot at the edge, h = l): I_p/(M h) = 2L/3",
            n("I_p", door_i_p) / &(f("M") * &f("l")),
            Formula::int(2) * &(Formula::int(2) * &f("l")) / &Formula::int(3),
        ),
    ];
    Claim {
        id: "X18",
        location: WHERE,
        group: Group::Beyond,
        statement: "Pivoted rod (fixed axis): omega = (1+e) m d v0/(I_p + m d^2), maximal at d* = sqrt(I_p/m) (inside a door iff M < 3m). The pivot impulse vanishes at d = I_p/(M h), the centre of percussion (2L/3 for a door)",
        formal: "Rod on a fixed frictionless pivot at p (|p| <= l), I about the centre, I_p = I + M p^2, restitution \
                 e in [0, 1], m, M, v0 > 0; d = a - p is the signed offset of the impact from the pivot. The generic \
                 solver (angular momentum about the pivot + restitution) gives omega = (1+e) m d v0/(I_p + m d^2). \
                 For fixed pivot, omega as a function of d > 0 has its unique maximum at d* = sqrt(I_p/m) \
                 (omega(d*) - omega(d) is (1+e) v0 (d* - d)^2/(2 d*(d*^2 + d^2))); on the rod the best impact is \
                 at min(d*, the far end). Door = uniform rod of width L = 2l pivoted at an edge: \
                 I_p = M L^2/3 and d* < L iff M < 3m (d* = L at M = 3m). The pivot's impulse M V - J is \
                 -(1+e) m v0 (I_p + M p d)/(I_p + m d^2); it vanishes iff I_p + M p d = 0: with the pivot at \
                 distance h = |p| > 0 from the centre that is the point at distance d = I_p/(M h) from the pivot \
                 on the far side of the centre (it lies on the rod iff r_G^2 <= h l; for a pivot at the centre, \
                 h = 0, the pivot impulse never vanishes). For a door, 2L/3 from the hinge."
            .into(),
        reason: "the solver's omega and pivot impulse equal the fixed-axis formulas; the maximum and the door's bounds are visible squares and slacks".into(),
        decision: Decision::Proved(certs),
    }
}

/// `I + M h^2` for a pivot at distance h from the centre.
fn i_p_at(h: &RatFn) -> RatFn {
    sym("I") + &(sym("M") * h * h)
}

/// Door, d*^2 = I_p/m against L^2 = (2l)^2: with M = 3m + q, q >= 0, d*^2 - L^2 >= 0 (`outside`:
/// not inside); with M = 3m - q, q > 0, L^2 - d*^2 > 0 (inside). Both equal 4 l^2 q/(3m).
fn door_cert(door_i_p: &RatFn, outside: bool) -> Certificate {
    let (m, l, q) = (sym("m"), sym("l"), sym("q"));
    let width2 = k(4, 1) * &l * &l;
    let excess = door_i_p.clone() / m.clone() - &width2;
    let (title, expr, mass, domain): (_, _, _, (&[&str], &[&str])) = if outside {
        (
            "door, M = 3m + q, q >= 0: d*^2 - L^2 = I_p/m - (2l)^2 = 4 l^2 q/(3m) >= 0 (d* not inside)",
            excess,
            k(3, 1) * &m + &q,
            (&["m", "l"], &["q"]),
        )
    } else {
        (
            "door, M = 3m - q, q > 0: L^2 - d*^2 = 4 l^2 q/(3m) > 0 (d* inside)",
            -excess,
            k(3, 1) * &m - &q,
            (&["m", "l", "q"], &[]),
        )
    };
    positive(
        title,
        expr,
        !outside,
        &[("M", mass)],
        domain.0,
        domain.1,
        PosExpr::quotient(
            PosExpr::product([pc(4, 1), ps("l"), ps("l"), ps("q")]),
            PosExpr::product([pc(3, 1), ps("m")]),
        ),
    )
}

/// The door of X18: the paper's uniform rod (Eq. (inertia-homogeneous)) pivoted at its end p = -l.
fn door(paper: &Paper) -> crate::scene::Params<RatFn> {
    crate::scene::Params {
        support: crate::scene::Support::Pivot(-sym("l")),
        ..pivoted_rod(paper.uniform_inertia.clone(), sym("e"))
    }
}

// ---------------------------------------------------------------------------------------------
// X19: elastic at a*, the second impact.

fn x19(paper: &Paper) -> Claim {
    let after = motion(&free_rod(sym("I"), int(1)));
    let certs = vec![
        a_star_substitution_cert(paper),
        id_at_star(
            "elastic at a* (generic solver): v - V = 0, the projectile is at rest relative to the rod's centre",
            n("v", after.v.clone()) - &n("V", after.rod_v.clone()),
            int(0),
        ),
        id_at_star(
            "elastic at a*: v = m v0/(M + m)",
            n("v", after.v.clone()),
            f("m") * &f("v0") / &(f("M") + &f("m")),
        ),
        id_at_star(
            "elastic at a*: omega a* = v0, so half a turn takes t = pi/omega = pi a*/v0 and the arm at -a* arrives with speed omega a* = v0 relative to the centre",
            n("omega", after.omega.clone()) * &f("a"),
            f("v0"),
        ),
    ];
    Claim {
        id: "X19",
        location: WHERE,
        group: Group::Beyond,
        statement: "Elastic, at a*: the projectile is at rest relative to the rod's centre, so half a turn later (t = pi a*/v0) the other arm hits it from behind at closing speed v0. A second impact is unavoidable",
        formal: "Elastic impact (e = 1) at a = a* <= l (so the impact at a* is possible: a point of the rod is \
                 there), m, M, I, v0 > 0. Certified algebra (generic solver, I = m M a^2/(M + m), which makes a \
                 the paper's a*): v = V = m v0/(M + m) and omega a* = v0. Kinematic argument (not machine-checked): \
                 after the impact no force acts, so the rod's centre moves uniformly with V and the rod turns \
                 uniformly at omega; in the centre's frame the projectile rests at (0, a*) while the rod's line \
                 rotates (the point at y moves with omega y along x). The line passes through (0, a*) again only \
                 when it has turned by pi, at t = pi/omega = pi a*/v0; then the material point that was at \
                 y = -a* (on the rod, since a* <= l) is at (0, a*) moving with velocity +omega a* = +v0 along x, \
                 i.e. it comes from the -x side (behind the projectile) and closes at speed v0 > 0. So the \
                 single-impulse model's outcome is followed by a second impact: unavoidable."
            .into(),
        reason: "at a* the solver gives v = V and omega a* = v0; a half turn then brings the other arm to the resting projectile at speed v0".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X20, X21: what does increase and what decreases with a.

fn x20(_paper: &Paper) -> Claim {
    let (m, a, t, v0, inertia) = (sym("m"), sym("a"), sym("t"), sym("v0"), sym("I"));
    let after = motion(&free_rod(inertia.clone(), sym("e")));
    let share = inertia.clone() * &after.omega / (m * &v0 * &a);
    let shifted = subs(&share, &[("a", a.clone() + &t)]);
    let certs = vec![
        Certificate::identity(
            "rod's share of the angular momentum I omega/(m v0 a) (generic solver, any e) = (1+e)/D",
            f("I") * &n("omega", after.omega.clone()) / &(f("m") * &f("v0") * &f("a")),
            (Formula::int(1) + &f("e"))
                / &(Formula::int(1) + &(f("m") / &f("M")) + &(f("m") * &f("a").pow(2) / &f("I"))),
        ),
        positive(
            "a >= 0, t > 0: share(a) - share(a + t) = (1+e) m t (2a + t)/(I D(a) D(a + t)) > 0",
            share - &shifted,
            true,
            &[],
            &["m", "M", "I", "t"],
            &["a", "e"],
            PosExpr::quotient(
                PosExpr::product([
                    one_plus_e(),
                    ps("m"),
                    ps("t"),
                    PosExpr::sum([PosExpr::product([pc(2, 1), ps("a")]), ps("t")]),
                ]),
                PosExpr::product([ps("I"), d_form(a.clone()), d_form(a + &t)]),
            ),
        ),
    ];
    Claim {
        id: "X20",
        location: WHERE,
        group: Group::Beyond,
        statement: "The rod's share of the angular momentum, I omega/(m v0 a) = (1+e)/D, decreases strictly with a",
        formal: "Free rod, m, M, I, v0 > 0, e in [0, 1], a > 0 (at a = 0 the share is 0/0 and is read as its limit \
                 (1+e)/(1 + m/M) = J/(m v0)). The rod's angular momentum about the centre divided by the total \
                 m v0 a is (1+e)/D with D = 1 + m/M + m a^2/I; for 0 <= a < a + t it drops by \
                 (1+e) m t (2a + t)/(I D(a) D(a+t)) > 0: strictly decreasing on a >= 0."
            .into(),
        reason: "the share is (1+e)/D identically and D grows strictly with a^2".into(),
        decision: Decision::Proved(certs),
    }
}

fn x21(_paper: &Paper) -> Claim {
    let (big_m, a, t) = (sym("M"), sym("a"), sym("t"));
    let after = gyration_motion();
    let struck = after.rod_point_velocity(&a);
    let shifted = subs(&struck, &[("a", a.clone() + &t)]);
    let m_eff = big_m * &r2() / (r2() + &(a.clone() * &a));
    let rr = || PosExpr::product([ps("r_G"), ps("r_G")]);
    let den = |x: RatFn| {
        PosExpr::sum([
            PosExpr::product([ps("m"), PosExpr::sum([rr(), PosExpr::Square(x)])]),
            PosExpr::product([ps("M"), ps("r_G"), ps("r_G")]),
        ])
    };
    let omega = after.omega.clone();
    let omega_shifted = subs(&omega, &[("a", a.clone() + &t)]);
    let instance = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("r_G", rational(1, 2)),
        ("v0", rational(1, 1)),
        ("e", rational(1, 1)),
        ("a", rational(7, 10)),
        ("t", rational(3, 10)),
    ]);
    let certs = vec![
        Certificate::identity(
            "struck point V + omega a (generic solver, I = M r_G^2, any e) = (1+e) v0 m/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)",
            point_velocity(&after, f("a")),
            (Formula::int(1) + &f("e")) * &f("v0") * &f("m") / &(f("m") + &n("M_eff", m_eff)),
        ),
        positive(
            "a >= 0, t > 0: speed(a + t) - speed(a) = (1+e) v0 m M r_G^2 t (2a + t)/(den(a) den(a + t)) > 0",
            shifted - &struck,
            true,
            &[],
            &["m", "M", "r_G", "v0", "t"],
            &["a", "e"],
            PosExpr::quotient(
                PosExpr::product([
                    one_plus_e(),
                    ps("v0"),
                    ps("m"),
                    ps("M"),
                    ps("r_G"),
                    ps("r_G"),
                    ps("t"),
                    PosExpr::sum([PosExpr::product([pc(2, 1), ps("a")]), ps("t")]),
                ]),
                PosExpr::product([den(a.clone()), den(a + &t)]),
            ),
        ),
        Certificate::witness(
            "but not omega: M = m, r_G = 1/2, l = 1, e = 1: omega(7/10) > omega(1) (a* = sqrt(1/2) < 1)",
            instance,
            omega,
            Relation::Gt,
            omega_shifted,
        ),
    ];
    Claim {
        id: "X21",
        location: WHERE,
        group: Group::Beyond,
        statement: "The struck point's speed after the impact, (1+e) v0 m/(m + M_eff(a)), increases strictly with a: intuition holds for the struck point but not for omega",
        formal: "Free rod, I = M r_G^2, m, M, r_G, v0 > 0, e in [0, 1], a >= 0. The struck point's velocity \
                 V + omega a (generic solver) equals (1+e) v0 m/(m + M_eff) with M_eff = M r_G^2/(r_G^2 + a^2); \
                 for 0 <= a < a + t it grows by a visibly positive amount: strictly increasing. omega itself is \
                 not monotone on [0, l] in general: a rational instance (M = m, r_G = l/2) has omega(0.7 l) > \
                 omega(l)."
            .into(),
        reason: "the struck point's speed is (1+e) v0 m/(m + M_eff) with M_eff strictly decreasing in a; omega is not monotone (witness)".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X22: the rod not symmetric.

/// The impulse equations for a rod whose CM sits at y = c, angular momentum taken about the
/// geometric centre (y = 0), solved by the generic linear solver: (v, V_cm, omega).
fn asymmetric_motion(e: RatFn) -> Motion<RatFn> {
    let (m, big_m, inertia, a, c, v0) =
        (sym("m"), sym("M"), sym("I"), sym("a"), sym("c"), sym("v0"));
    let matrix = vec![
        vec![m.clone(), big_m.clone(), int(0)],
        vec![m.clone() * &a, big_m * &c, inertia],
        vec![int(-1), int(1), a.clone() - &c],
    ];
    let rhs = vec![m.clone() * &v0, m * &a * &v0, e * &v0];
    let x = solve_linear(matrix, rhs).expect("the asymmetric impulse system is nonsingular");
    Motion {
        v: x[0].clone(),
        rod_v: x[1].clone(),
        omega: x[2].clone(),
    }
}

fn x22(paper: &Paper) -> Claim {
    let (a, c, l) = (sym("a"), sym("c"), sym("l"));
    let shifted = a.clone() - &c;
    let shift = [("a", shifted.clone())];
    let general = asymmetric_motion(sym("e"));
    let symmetric = motion(&free_rod(sym("I"), sym("e")));
    let elastic = asymmetric_motion(int(1));
    // The end at y = -l (geometric), i.e. at -(l + c) from the CM.
    let far_end = general.rod_v.clone() - &(general.omega.clone() * &(l.clone() + &c));
    let gyr = |x: &RatFn| subs(x, &[("I", gyration_inertia())]);
    let naive = gyr(&general.rod_v) * &(int(1) - &(shifted.clone() * &l / r2()));
    let instance = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("r_G", rational(1, 2)),
        ("l", rational(1, 1)),
        ("c", rational(1, 4)),
        ("a", rational(1, 1)),
        ("v0", rational(1, 1)),
        ("e", rational(1, 1)),
    ]);
    let counterexample = vec![Certificate::witness(
        "X14's far-end formula with only a -> a - c fails: two equal masses at y = -1/4 and 3/4 on a massless rod of half-length 1 (c = 1/4, r_G = 1/2), m = M, e = 1, end hit: true far-end velocity != V (1 - (a - c) l/r_G^2)",
        instance,
        gyr(&far_end),
        Relation::Ne,
        naive,
    )];
    let proof = vec![
        Certificate::identity(
            "v from the equations about the geometric centre (CM at c) = v of the symmetric solver at a - c (any e)",
            n("v_c", general.v.clone()),
            n("v", symmetric.v.clone()).subs(&shift),
        ),
        Certificate::identity(
            "V_cm from the equations about the geometric centre = V of the symmetric solver at a - c (any e)",
            n("V_c", general.rod_v.clone()),
            n("V", symmetric.rod_v.clone()).subs(&shift),
        ),
        Certificate::identity(
            "omega from the equations about the geometric centre = omega of the symmetric solver at a - c (any e)",
            n("omega_c", general.omega.clone()),
            n("omega", symmetric.omega.clone()).subs(&shift),
        ),
        Certificate::identity(
            "elastic: omega about the geometric centre = the paper's Eq. (omega) with a -> a - c",
            n("omega_c", elastic.omega),
            paper.omega.subs(&shift),
        ),
        Certificate::identity(
            "elastic: v = the paper's Eq. (v) with a -> a - c",
            n("v_c", elastic.v),
            paper.v.subs(&shift),
        ),
        Certificate::identity_at(
            "positions measured from the CM: the end at y = -l moves with V (1 - (a - c)(l + c)/r_G^2)",
            n("V_c", general.rod_v.clone())
                - &(n("omega_c", general.omega.clone()) * &(f("l") + &f("c"))),
            n("V_c", general.rod_v.clone())
                * &(Formula::int(1)
                    - &((f("a") - &f("c")) * &(f("l") + &f("c")) / &f("r_G").pow(2))),
            &[("I", gyration_inertia())],
        ),
    ];
    Claim {
        id: "X22",
        location: WHERE,
        group: Group::Beyond,
        statement: "Rod not symmetric: every formula holds with a replaced by a - c (c the CM offset; I taken about the CM)",
        formal: "Rod of half-length l whose CM is at y = c (geometric centre at 0), mass M, I about the CM, impact at \
                 y = a, restitution e. Independent equations: m v + M V = m v0; angular momentum about the fixed \
                 point at the geometric centre, m a v + M c V + I omega = m a v0 (V the CM's velocity); restitution \
                 V + omega (a - c) - v = e v0. Their solution equals the symmetric rod's solution with a -> a - c \
                 (so v, V, omega, J, D, the energies, and a* as a distance from the CM all carry over). The \
                 natural reading 'every formula' also covers formulas with other positions along the rod (the \
                 ends at +-l, the far end of X14, y0 of X13, the domain 0 <= a <= l): those need every position \
                 measured from the CM (the ends at l - c and -(l + c)), not just a -> a - c."
            .into(),
        reason: "the impulse system about the CM is the symmetric one at a - c, but formulas that involve the rod's ends need l shifted too".into(),
        decision: Decision::Qualified {
            qualification: "true for every formula in which the impact point is the only position (v, V of the CM, omega, J, D, energies, a* measured from the CM); positions such as the ends must also be measured from the CM (y -> y - c)".into(),
            counterexample,
            proof,
        },
    }
}

// ---------------------------------------------------------------------------------------------
// X23: the sticking loss.

fn x23(paper: &Paper) -> Claim {
    let (m, big_m, a, v0, inertia) = (sym("m"), sym("M"), sym("a"), sym("v0"), sym("I"));
    let total = big_m.clone() + &m;
    let mu = m.clone() * &big_m / total.clone();
    // The composite body (rod + stuck projectile): CM at y_c, I_c by the parallel-axis theorem.
    let y_c = m.clone() * &a / total.clone();
    let arm = a.clone() - &y_c;
    let i_c = inertia.clone() + &(big_m.clone() * &y_c * &y_c) + &(m.clone() * &arm * &arm);
    let p = free_rod(inertia.clone(), int(0));
    let l_c = angular_momentum(&p, &Motion::before(v0.clone()), &y_c);
    let omega_c = l_c / i_c.clone();
    let v_c = m.clone() * &v0 / total.clone();
    let k0 = m.clone() * &v0 * &v0 / k(2, 1);
    let after = (total * &v_c * &v_c + &(i_c.clone() * &omega_c * &omega_c)) / k(2, 1);
    let loss = k0.clone() - &after;
    let newton_zero = solved(&p);
    let two = Formula::int(2);
    let mu_f = n("mu", mu.clone());
    let y_c_f = n("y_c", y_c.clone());
    let i_c_f = n("I_c", i_c.clone());
    let omega_c_f = n("omega_c", omega_c.clone());
    let k0_f = f("m") * &f("v0").pow(2) / &two;
    let stated_f = mu_f.clone() * &f("v0").pow(2) / &two * &f("I")
        / &(f("I") + &(mu_f.clone() * &f("a").pow(2)));
    let certs = vec![
        Certificate::identity(
            "composite body: I_c = I + M y_c^2 + m (a - y_c)^2 = I + mu a^2, y_c = m a/(M + m)",
            f("I") + &(f("M") * &y_c_f.pow(2)) + &(f("m") * &(f("a") - &y_c_f).pow(2)),
            f("I") + &(mu_f.clone() * &f("a").pow(2)),
        ),
        Certificate::identity(
            "sticking loss K0 - ((M + m) V_c^2 + I_c omega^2)/2 = (mu v0^2/2) I/(I + mu a^2)",
            k0_f.clone()
                - &(((f("M") + &f("m")) * &n("V_c", v_c.clone()).pow(2)
                    + &(i_c_f.clone() * &omega_c_f.pow(2)))
                    / &two),
            stated_f.clone(),
        ),
        Certificate::identity(
            "(mu v0^2/2) I/(I + mu a^2) = K0/D",
            stated_f,
            k0_f.clone()
                / &(Formula::int(1) + &(f("m") / &f("M")) + &(f("m") * &f("a").pow(2) / &f("I"))),
        ),
        Certificate::identity(
            "the generic solver with e = 0 loses the same energy",
            n("K_lost", newton_zero.energy.lost),
            n("K_lost_c", loss),
        ),
        a_star_substitution_cert(paper),
        id_at_star("at a*: I_c = 2I", i_c_f.clone(), Formula::int(2) * &f("I")),
        id_at_star(
            "at a*: omega (composite body, L about its CM / I_c) times 2a* = v0",
            omega_c_f * &f("a") * &two,
            f("v0"),
        ),
    ];
    Claim {
        id: "X23",
        location: WHERE,
        group: Group::Beyond,
        statement: "Sticking loses (mu v0^2/2) I/(I + mu a^2) = K0/D; at a*, I_c = 2I and omega = v0/(2a*)",
        formal: "Free rod, m, M, I, v0 > 0, any a; the projectile sticks (the composite body has its CM at \
                 y_c = m a/(M + m), moves with V_c = m v0/(M + m) and turns at omega = L_c/I_c, L_c the angular \
                 momentum about the point y_c, I_c by the parallel-axis theorem). The energy lost is \
                 (mu v0^2/2) I/(I + mu a^2) = K0/D, also the loss of the Newton e = 0 impact (generic solver). \
                 At a = a* (I = m M a^2/(M + m)): I_c = 2I and omega = v0/(2 a*)."
            .into(),
        reason: "the composite body's energy balance gives (mu v0^2/2) I/(I + mu a^2) = K0/D identically; at a* the substitution gives I_c = 2I".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X24, X25.

fn x24(paper: &Paper) -> Claim {
    let after = motion(&free_rod(sym("I"), sym("e")));
    let one = Formula::int(1);
    let b2_f = n("b^2", f("I") * &(one.clone() / &f("m") + &(one / &f("M"))));
    let certs = vec![
        Certificate::identity(
            "omega (generic solver, any e) = (1+e) v0 * a/(b^2 + 1^2 a^2), b^2 = I (1/m + 1/M)",
            n("omega", after.omega),
            (Formula::int(1) + &f("e")) * &f("v0") * &f("a")
                / &(b2_f.clone() + &(Formula::int(1).pow(2) * &f("a").pow(2))),
        ),
        Certificate::identity(
            "b^2/c^2 with c = 1 is the paper's a*^2 (Eq. (maximal-a-general)): the maximiser x = b/c is a*",
            b2_f / &Formula::int(1).pow(2),
            paper.a_star_squared.clone(),
        ),
    ];
    Claim {
        id: "X24",
        location: WHERE,
        group: Group::Beyond,
        statement: "For every e, the b^2 of the paper's f(x) argument is I(1/m + 1/M), with c = 1",
        formal: "Free rod, m, M, I, v0 > 0, restitution e in [0, 1]: omega(a) = K f(a) with f(x) = x/(b^2 + c^2 x^2), \
                 K = (1+e) v0, c = 1 and b^2 = I (1/m + 1/M), independent of e and v0. (The split of omega into \
                 K, b, c is unique only up to K f = (lambda K) x/(lambda b^2 + lambda c^2 x^2); normalising c = 1 \
                 fixes b^2 as stated, and the maximiser b/c = a* is invariant.)"
            .into(),
        reason: "omega = (1+e) v0 a/(I(1/m + 1/M) + a^2) identically, and I(1/m + 1/M) is the paper's a*^2".into(),
        decision: Decision::Proved(certs),
    }
}

fn x25(paper: &Paper) -> Claim {
    let l = sym("l");
    let ratio = |inertia: Formula| {
        let after = motion(&free_rod(inertia.clone(), sym("e")));
        (n("I", inertia) * &n("omega", after.omega).pow(2) / &Formula::int(2))
            / &(f("M") * &n("V", after.rod_v).pow(2) / &Formula::int(2))
    };
    let certs = vec![
        Certificate::identity(
            "K_rot/K_trans = (I omega^2/2)/(M V^2/2) (generic solver, I = M r_G^2, any m, e) = a^2/r_G^2",
            ratio(gyration_inertia().into()),
            f("a").pow(2) / &f("r_G").pow(2),
        ),
        Certificate::identity_at(
            "uniform rod (Eq. (inertia-homogeneous)) hit at the end a = l: K_rot/K_trans = 3",
            ratio(paper.uniform_inertia.clone()),
            int(3),
            &[("a", l)],
        ),
    ];
    Claim {
        id: "X25",
        location: WHERE,
        group: Group::Beyond,
        statement: "After the impact the rod's K_rot/K_trans = a^2/r_G^2 for any m and e (uniform rod hit at the end: 3)",
        formal: "Free rod, I = M r_G^2, m, M, r_G, v0 > 0, e in [0, 1] (so V = J/M > 0 and the ratio is defined), \
                 any a: (I omega^2/2)/(M V^2/2) = a^2/r_G^2, independent of m, v0 and e (omega = J a/I and \
                 V = J/M share the impulse J). Uniform rod hit at a = l: 3."
            .into(),
        reason: "omega/V = M a/I, so I omega^2/(M V^2) = M a^2/I = a^2/r_G^2 identically".into(),
        decision: Decision::Proved(certs),
    }
}

// ---------------------------------------------------------------------------------------------
// X26: the second impact in general.

fn x26(paper: &Paper) -> Claim {
    let (m, big_m, a, e, inertia) = (sym("m"), sym("M"), sym("a"), sym("e"), sym("I"));
    let after = motion(&free_rod(inertia.clone(), e.clone()));
    let kappa = (after.v.clone() - &after.rod_v) / (a.clone() * &after.omega);
    let kappa_f = (n("v", after.v.clone()) - &n("V", after.rod_v.clone()))
        / &(f("a") * &n("omega", after.omega.clone()));
    let s2_f = n("s^2", f("a").pow(2) / &paper.a_star_squared);
    let s2_form = || {
        PosExpr::quotient(
            PosExpr::product([ps("m"), ps("M"), ps("a"), ps("a")]),
            PosExpr::product([ps("I"), PosExpr::sum([ps("M"), ps("m")])]),
        )
    };
    let e_at_kappa_zero = a.clone() * &a * &m * &big_m / (inertia * &(big_m.clone() + &m));
    let certs = vec![
        Certificate::identity(
            "kappa = (v - V)/(a omega) (generic solver, any e) = (s^2 - e)/((1+e) s^2), s^2 = a^2/a*^2 (Eq. (maximal-a-general))",
            kappa_f.clone(),
            (s2_f.clone() - &f("e")) / &((Formula::int(1) + &f("e")) * &s2_f),
        ),
        positive(
            "1 - kappa = e (1 + s^2)/((1+e) s^2) >= 0 (a > 0): no root of tan tau = kappa tau in (0, pi/2], g' >= 1 - kappa >= 0",
            int(1) - &kappa,
            false,
            &[],
            &["m", "M", "I", "a"],
            &["e"],
            PosExpr::quotient(
                PosExpr::product([ps("e"), PosExpr::sum([pc(1, 1), s2_form()])]),
                PosExpr::product([one_plus_e(), s2_form()]),
            ),
        ),
        Certificate::identity_at(
            "e = s^2 = a^2/a*^2 gives kappa = 0 (then tan tau1 = 0 in (pi/2, 3pi/2): tau1 = pi)",
            kappa_f,
            int(0),
            &[("e", e_at_kappa_zero)],
        ),
    ];
    Claim {
        id: "X26",
        location: WHERE,
        group: Group::Beyond,
        statement: "Second impact (outside the paper's single-impulse model). In the rod-centre frame the projectile meets the rod's line when tan tau = kappa tau, where tau = omega t and kappa = (v - V)/(a omega) = (s^2 - e)/((1+e)s^2), s = a/a*. The root tau1 in (pi/2, 3pi/2) is unique because 1 - kappa >= 0. The impact recurs iff a <= l|cos tau1| (kappa = 0 gives tau1 = pi)",
        formal: "Free rod, m, M, I, v0 > 0, e in [0, 1], 0 < a <= l (so omega > 0); after the single impulse both bodies \
                 move freely. Certified: kappa = (v - V)/(a omega) = (s^2 - e)/((1+e) s^2) with s = a/a*, \
                 1 - kappa = e (1 + s^2)/((1+e) s^2) >= 0, and kappa = 0 exactly when s^2 = e. Analytic steps \
                 (not machine-checked): in the frame of the rod's centre (uniform motion) the projectile is at \
                 ((v - V) t, a) and the rod's line has direction (sin tau, cos tau), tau = omega t (the point at y \
                 moves with omega y along x); they meet when (v - V) t cos tau = a sin tau, i.e. tan tau = kappa tau \
                 (cos tau = 0 is no solution as a > 0). On (0, pi/2) tan tau > tau >= kappa tau (kappa <= 1), so \
                 there is no earlier meeting. On (pi/2, 3pi/2) g = tan tau - kappa tau runs from -oo to +oo with \
                 g' = sec^2 tau - kappa >= 1 - kappa >= 0, vanishing at most at tau = pi: g is strictly increasing, \
                 one root tau1 (tau1 = pi when kappa = 0). There cos tau1 < 0, so it is the other arm, and the \
                 meeting point lies at distance a/|cos tau1| = sqrt(a^2 + ((v - V) t)^2) from the centre; this \
                 distance grows with t, so later meetings of the line are farther out. Hence a second impact \
                 happens iff a/|cos tau1| <= l, i.e. a <= l |cos tau1|."
            .into(),
        reason: "the solver gives kappa = (s^2 - e)/((1+e)s^2) and 1 - kappa = e(1 + s^2)/((1+e)s^2) >= 0; the root's uniqueness and the recurrence test follow analytically".into(),
        decision: Decision::Proved(certs),
    }
}

#[cfg(test)]
mod tests {
    use super::super::Verdict;
    use super::*;

    use super::super::test_support::verdict;

    #[test]
    fn verdicts() {
        let paper = Paper::as_printed();
        let expected = [
            ("X14", Verdict::Proved),
            ("X15", Verdict::Proved),
            ("X16", Verdict::Proved),
            ("X17", Verdict::Proved),
            ("X18", Verdict::Proved),
            ("X19", Verdict::Proved),
            ("X20", Verdict::Proved),
            ("X21", Verdict::Proved),
            ("X22", Verdict::Qualified),
            ("X23", Verdict::Proved),
            ("X24", Verdict::Proved),
            ("X25", Verdict::Proved),
            ("X26", Verdict::Proved),
        ];
        for (id, v) in expected {
            assert_eq!(verdict(id, &paper), Ok(v), "{id}");
        }
        let ids: Vec<_> = ENTRIES.iter().map(|e| e.id).collect();
        let wanted: Vec<String> = (14..=26).map(|n| format!("X{n}")).collect();
        assert_eq!(ids, wanted);
    }

    fn fails_with(mutate: impl Fn(&mut Paper), ids: &[&str]) {
        let mut paper = Paper::as_printed();
        mutate(&mut paper);
        for id in ids {
            assert!(verdict(id, &paper).is_err(), "{id} should fail");
        }
    }

    #[test]
    fn a_wrong_a_star_is_caught() {
        fails_with(
            |p| {
                p.a_star_squared =
                    (sym("I") * &(sym("M") - &sym("m")) / (sym("m") * &sym("M"))).into()
            },
            &["X19", "X23", "X24", "X26"],
        );
    }

    #[test]
    fn wrong_closed_forms_are_caught() {
        fails_with(|p| p.big_v = p.big_v.clone() * &k(2, 1), &["X14"]);
        fails_with(
            |p| p.omega = p.omega.clone() * &k(1, 2),
            &["X16", "X17", "X22"],
        );
        fails_with(|p| p.v = -p.v.clone(), &["X16", "X17", "X22"]);
        fails_with(
            |p| p.a_star_uniform_squared = p.a_star_uniform_squared.clone() * &k(2, 1),
            &["X15"],
        );
        fails_with(
            |p| p.uniform_inertia = (sym("M") * &sym("l") * &sym("l") / k(12, 1)).into(),
            &["X14", "X18", "X25"],
        );
        fails_with(
            |p| p.a_star_gyration_squared = (sym("r_G") * &sym("r_G") * &k(2, 1)).into(),
            &["X16"],
        );
    }

    #[test]
    fn tampered_certificates_are_caught() {
        let paper = Paper::as_printed();
        // A nonnegative form claimed strict.
        let mut claim = x14(&paper);
        if let Decision::Proved(certs) = &mut claim.decision {
            for c in certs.iter_mut() {
                if let Certificate::Positive(crate::claims::certificate::Positive {
                    strict, ..
                }) = c
                {
                    *strict = true;
                }
            }
        }
        assert!(claim.check().is_err());
        // The monotonicity reversed: share(a + t) - share(a) is not positive.
        let mut claim = x20(&paper);
        if let Decision::Proved(certs) = &mut claim.decision {
            for c in certs.iter_mut() {
                if let Certificate::Positive(crate::claims::certificate::Positive {
                    expr, ..
                }) = c
                {
                    *expr = -expr.clone();
                }
            }
        }
        assert!(claim.check().is_err());
        // The asymmetric-rod counterexample at c = 0 is no counterexample.
        let mut claim = x22(&paper);
        if let Decision::Qualified { counterexample, .. } = &mut claim.decision {
            for c in counterexample.iter_mut() {
                if let Certificate::Witness(crate::claims::certificate::Witness {
                    instance, ..
                }) = c
                {
                    for (s, v) in instance.iter_mut() {
                        if s.name() == "c" {
                            *v = rational(0, 1);
                        }
                    }
                }
            }
        }
        assert!(claim.check().is_err());
    }
}
