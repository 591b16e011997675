//! Claims C1-C18: the abstract, the introduction, the impulse equations and the limiting cases.
//!
//! The independent derivation is the generic solver run over rational functions
//! ([`motion`]): its v, V, omega are compared with the paper's printed formulas ([`Paper`]) and
//! with the algebraic steps the paper takes between Eq. (linear) and Eq. (omega).

use super::build::*;
use super::model::*;
use super::{
    Certificate, Claim, Decision, Entry, Expected, Formula, Group, Paper, PosExpr, Relation,
};
use crate::field::ratfunc::Point;
use crate::field::{RatFn, Sym};
use crate::mechanics::{Motion, angular_momentum, kinetic_energy};

/// The registered claims of this part of the paper.
pub(super) const ENTRIES: &[Entry] = &[
    Entry {
        id: "C1",
        build: c1,
    },
    Entry {
        id: "C2",
        build: c2,
    },
    Entry {
        id: "C3",
        build: c3,
    },
    Entry {
        id: "C4",
        build: c4,
    },
    Entry {
        id: "C5",
        build: c5,
    },
    Entry {
        id: "C6",
        build: c6,
    },
    Entry {
        id: "C7",
        build: c7,
    },
    Entry {
        id: "C8",
        build: c8,
    },
    Entry {
        id: "C9",
        build: c9,
    },
    Entry {
        id: "C10",
        build: c10,
    },
    Entry {
        id: "C11",
        build: c11,
    },
    Entry {
        id: "C12",
        build: c12,
    },
    Entry {
        id: "C13",
        build: c13,
    },
    Entry {
        id: "C14",
        build: c14,
    },
    Entry {
        id: "C15",
        build: c15,
    },
    Entry {
        id: "C16",
        build: c16,
    },
    Entry {
        id: "C17",
        build: c17,
    },
    Entry {
        id: "C18",
        build: c18,
    },
];

// ---------------------------------------------------------------------------------------------
// Shared pieces of the derivation.

/// The free rod with a symbolic I.
fn rod(e: RatFn) -> crate::scene::Params<RatFn> {
    free_rod(sym("I"), e)
}

/// The elastic solution from the generic solver, I symbolic.
fn elastic() -> Motion<RatFn> {
    motion(&rod(k(1, 1)))
}

/// The elastic omega of the uniform rod (I = M l^2/3) from the generic solver.
fn uniform_omega() -> RatFn {
    motion(&free_rod(uniform_inertia(), k(1, 1))).omega
}

/// D = 1 + m/M + m a^2/I > 0.
fn d_positive() -> Certificate {
    positive(
        "D = 1 + m/M + m a^2/I > 0 (m, M, I > 0, a any real)",
        paper_d(&sym("I")),
        true,
        &[],
        &["m", "M", "I"],
        &[],
        d_form(sym("a")),
    )
}

/// A symbol as a [`Formula`].
fn f(name: &str) -> Formula {
    Formula::sym(name)
}

/// Eq. (linear-angular): V and omega as functions of the projectile's velocity `v`.
fn momentum_split(v: &Formula) -> (Formula, Formula) {
    let dv = f("v0") - v;
    (f("m") / &f("M") * &dv, f("m") * &f("a") / &f("I") * &dv)
}

/// `m/M + m a^2/I`, the coefficient in Eqs. (kinetic2) and (kinetic-divided) divided by m.
fn compliance_ratio() -> Formula {
    f("m") / &f("M") + &(f("m") * &f("a").pow(2) / &f("I"))
}

/// Eq. (kinetic2) as printed, left side minus right side, at projectile velocity `v`:
/// `m(v0^2 - v^2) - ((m^2/M)(v0 - v)^2 + (m^2 a^2/I)(v0 - v)^2)`.
fn kinetic2(v: &Formula) -> Formula {
    let (m, v0) = (f("m"), f("v0"));
    let dv2 = (v0.clone() - v).pow(2);
    m.clone() * &(v0.pow(2) - &v.pow(2))
        - &(m.pow(2) / &f("M") * &dv2 + &(m.pow(2) * &f("a").pow(2) / &f("I") * &dv2))
}

/// Eq. (kinetic-divided) as printed, left side minus right side, at projectile velocity `v`.
fn kinetic_divided(v: &Formula) -> Formula {
    let (m, v0) = (f("m"), f("v0"));
    m.clone() * &(v0.clone() + v) - &(m * &compliance_ratio() * &(v0 - v))
}

/// Uniform rod, M = m (= l = v0 = 1): omega at a* = sqrt(2/3) l exceeds omega at the end.
fn equal_masses_beat_the_end() -> Vec<Certificate> {
    let omega = uniform_omega();
    let at_end = subs(&omega, &[("a", sym("l"))]);
    let at_star = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("l", rational(1, 1)),
        ("v0", rational(1, 1)),
        ("a", sqrt(&crate::field::q(2, 3))),
    ]);
    vec![
        Certificate::witness(
            "uniform rod, M = m: the impact point a = sqrt(2/3) l lies on the rod (a < l)",
            at_star.clone(),
            sym("a"),
            Relation::Lt,
            sym("l"),
        ),
        Certificate::witness(
            "uniform rod, M = m: omega (generic solver, e = 1) at a = sqrt(2/3) l exceeds omega at the end a = l",
            at_star,
            omega,
            Relation::Gt,
            at_end,
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// Abstract and introduction.

fn c1(_paper: &Paper) -> Claim {
    Claim {
        id: "C1",
        location: "abstract",
        group: Group::Introduction,
        statement: "There exist masses for which the maximum of omega over [0,l] is not at a = l (witness M = m)",
        formal: "Uniform rod (I = M l^2/3), elastic impact (e = 1), omega from the generic solver: \
                 there are m, M, l, v0 > 0 and a point a in [0, l) with omega(a) > omega(l), so the \
                 maximum of omega over [0, l] is not attained at a = l. Witness: m = M = l = v0 = 1, \
                 a = sqrt(2/3) (evaluated exactly in Q(sqrt 6))."
            .into(),
        reason: "at M = m, omega(sqrt(2/3) l) = sqrt(6)/2 v0/l > omega(l) = 6/5 v0/l, exactly in Q(sqrt 6)".into(),
        decision: Decision::Proved(equal_masses_beat_the_end()),
    }
}

fn c2(_paper: &Paper) -> Claim {
    let after = elastic();
    let at_centre = |x: &RatFn| subs(x, &[("a", k(0, 1))]);
    let big_v = at_centre(&after.rod_v);
    Claim {
        id: "C2",
        location: "intro ¶2",
        group: Group::Introduction,
        statement: "a = 0 gives pure translation: omega = 0, V = 2m v0/(M+m) > 0",
        formal: "Elastic impact (e = 1) at the centre (a = 0), any I > 0, m, M, v0 > 0: the generic \
                 solver gives omega = 0 (every rod point moves with V: pure translation) and \
                 V = 2 m v0/(M + m) > 0. (For restitution e the rod still only translates, with \
                 V = (1 + e) m v0/(M + m).)"
            .into(),
        reason: "at a = 0 the solver's omega is identically 0 and its V equals 2m v0/(M+m), visibly positive".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "omega at a = 0 (generic solver, e = 1) is 0",
                Formula::named("omega", after.omega),
                k(0, 1),
                &[("a", k(0, 1))],
            ),
            Certificate::identity_at(
                "V at a = 0 (generic solver, e = 1) equals 2 m v0/(M + m)",
                Formula::named("V", after.rod_v.clone()),
                Formula::int(2) * &f("m") * &f("v0") / &(f("M") + &f("m")),
                &[("a", k(0, 1))],
            ),
            positive("V at a = 0 is > 0", big_v, true, &[], &["m", "M", "v0"], &[], PosExpr::quotient(
                    prod([pc(2, 1), ps("m"), ps("v0")]),
                    PosExpr::sum([ps("M"), ps("m")]),
                )),
        ]),
    }
}

fn c3(_paper: &Paper) -> Claim {
    let slope = uniform_omega().derivative(Sym::new("a"));
    let slope_at_end = subs(&slope, &[("a", sym("l"))]);
    let mut counterexample = vec![Certificate::witness(
        "uniform rod, M = m = l = v0 = 1: d omega/da at the end a = l is negative, so omega decreases towards the end",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
        ]),
        slope_at_end,
        Relation::Lt,
        k(0, 1),
    )];
    counterexample.extend(equal_masses_beat_the_end());
    Claim {
        id: "C3",
        location: "intro ¶2; §optimum ¶1",
        group: Group::Introduction,
        statement: "Intuition: \"omega increases with a, maximum at a = l whatever the masses\"",
        formal: "Natural reading: for every m, M > 0 (uniform rod, I = M l^2/3, elastic impact), \
                 omega is increasing on [0, l] and its maximum over [0, l] is at a = l. Refuted at \
                 M = m: there d omega/da < 0 at a = l, and omega(sqrt(2/3) l) > omega(l) exactly. \
                 (It holds for the uniform rod exactly when M >= 2m: see C23-C27.)"
            .into(),
        reason: "at M = m omega decreases at a = l and omega(sqrt(2/3) l) > omega(l); the intuition holds only for M >= 2m (uniform rod)".into(),
        decision: Decision::Refuted(counterexample),
    }
}

fn c4(paper: &Paper) -> Claim {
    // "Light": M < 2m, parametrised as m = (M + q)/2 with M, q > 0.
    let light = || [("m", (sym("M") + &sym("q")) / k(2, 1))];
    let l = sym("l");
    let gap = l.clone() * &l - &paper.a_star_uniform_squared;
    // omega = 6 m a v0/((M + m) l^2 + 3 m a^2), so omega'(l) = 6 m v0 (M - 2m)/(l^2 (M + 4m)^2).
    let slope_at_end = subs(
        &uniform_omega().derivative(Sym::new("a")),
        &[("a", l.clone())],
    );
    let three_m_plus_two_q = PosExpr::sum([prod([pc(3, 1), ps("M")]), prod([pc(2, 1), ps("q")])]);
    Claim {
        id: "C4",
        location: "intro ¶2",
        group: Group::Introduction,
        statement: "A rod light compared with the projectile has its optimum at a < l",
        formal: "The paper's rod is homogeneous: I = M l^2/3, elastic impact. \"Light compared with \
                 the projectile\" is made precise as M < 2m (the paper's own threshold; it includes \
                 M < m and M << m), parametrised as m = (M + q)/2 with M, q > 0. Then (i) a* of Eq. \
                 (maximal-a-homogeneous) satisfies a*^2 < l^2, and (ii) the solver's omega has \
                 d omega/da < 0 at a = l, so the maximum of omega over [0, l] is not at the end but \
                 at some a < l (at a*, C27). For an inhomogeneous rod the threshold moves (a* < l \
                 iff M < m (l^2 - r_G^2)/r_G^2), and the ideal dumbbell never has a* < l (C43, C44)."
            .into(),
        reason: "with m = (M + q)/2, l^2 - a*^2 = 2 q l^2/(3(M + q)) > 0 and -omega'(l) = 3 q (M + q) v0/(l^2 (3M + 2q)^2) > 0".into(),
        decision: Decision::Proved(vec![
            positive("l^2 - a*^2 > 0 for M < 2m (a*^2 of Eq. (maximal-a-homogeneous), m = (M + q)/2)", gap, true, &light(), &["M", "q", "l"], &[], PosExpr::quotient(
                    prod([pc(2, 1), ps("q"), ps("l"), ps("l")]),
                    prod([pc(3, 1), PosExpr::sum([ps("M"), ps("q")])]),
                )),
            positive("-d omega/da at a = l is > 0 for M < 2m (uniform rod, solver's omega, m = (M + q)/2): omega decreases at the end", -slope_at_end, true, &light(), &["M", "q", "l", "v0"], &[], PosExpr::quotient(
                    prod([pc(3, 1), ps("q"), PosExpr::sum([ps("M"), ps("q")]), ps("v0")]),
                    prod([ps("l"), ps("l"), three_m_plus_two_q.clone(), three_m_plus_two_q]),
                )),
        ]),
    }
}

// ---------------------------------------------------------------------------------------------
// The impulse equations.

fn c5(_paper: &Paper) -> Claim {
    let p = rod(sym("e"));
    let after = motion(&p);
    let lhs =
        f("m") * &Formula::named("v", after.v) + &(f("M") * &Formula::named("V", after.rod_v));
    Claim {
        id: "C5",
        location: "Eq. (linear)",
        group: Group::Equations,
        statement: "m v0 = m v + M V",
        formal: "For all m, M, I > 0, any a, v0 and any restitution e, the solution of the impulse \
                 equations (momentum, angular momentum about the rod's centre, Newton's restitution) \
                 satisfies m v + M V = m v0: the table is frictionless, so no external impulse acts \
                 along x."
            .into(),
        reason: "the momentum residual of the symbolic solution is identically 0, for every e".into(),
        decision: Decision::Proved(vec![Certificate::identity(
            "linear momentum after the impact equals m v0 (v, V from the generic solver over Q(m, M, I, a, v0, e))",
            lhs,
            f("m") * &f("v0"),
        )]),
    }
}

fn c6(_paper: &Paper) -> Claim {
    let p = rod(sym("e"));
    let after = motion(&p);
    let printed = f("m") * &Formula::named("v", after.v.clone()) * &f("a")
        + &(f("I") * &Formula::named("omega", after.omega.clone()));
    let y = sym("y");
    let before = Motion::before(sym("v0"));
    Claim {
        id: "C6",
        location: "Eq. (angular)",
        group: Group::Equations,
        statement: "m v0 a = m v a + I omega about the fixed point at the rod's centre",
        formal: "For all m, M, I > 0, any a, v0 and any restitution e: the solution of the impulse \
                 equations satisfies m v a + I omega = m v0 a, the angular momentum about the fixed \
                 point of the table where the rod's centre is at the impact (the rod's part is \
                 I omega because its centre is at that point and positions do not change during an \
                 instantaneous impact). Since linear momentum is conserved too, the balance holds \
                 about every fixed point (0, y) of the rod's line: the choice of the centre is a \
                 convenience."
            .into(),
        reason: "m v a + I omega of the symbolic solution equals m v0 a identically, for every e; the same holds about any fixed point y".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "m v a + I omega after the impact equals m v0 a (generic solver, any e)",
                printed,
                f("m") * &f("v0") * &f("a"),
            ),
            Certificate::identity(
                "angular momentum about an arbitrary fixed point (0, y) is the same after as before (generic solver, any e)",
                Formula::named("L_after", angular_momentum(&p, &after, &y)),
                Formula::named("L_before", angular_momentum(&p, &before, &y)),
            ),
        ]),
    }
}

fn c7(_paper: &Paper) -> Claim {
    let lost = |e: RatFn| solved(&rod(e)).energy.lost;
    // 0 <= e < 1 parametrised as e = s/(s + t) with s >= 0, t > 0.
    let inelastic = [("e", sym("s") / (sym("s") + &sym("t")))];
    let s_plus_t = PosExpr::sum([ps("s"), ps("t")]);
    Claim {
        id: "C7",
        location: "Eq. (kinetic)",
        group: Group::Equations,
        statement: "Kinetic energy is conserved",
        formal: "Eq. (kinetic) is the paper's hypothesis that the collision is elastic. Modelled \
                 by Newton's restitution law at the contact, it holds exactly for e = 1: the kinetic \
                 energy after the impact equals m v0^2/2 for all m, M, I > 0, a, v0. For every \
                 0 <= e < 1 (v0 != 0) energy is strictly lost, so conservation is exactly the elastic \
                 case, not a consequence of the momentum laws."
            .into(),
        reason: "for e = 1 the solver's kinetic energy after the impact is m v0^2/2 identically; for 0 <= e < 1 it is (1 - e^2) m M I v0^2/(2(MI + mI + mMa^2)) > 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "kinetic energy after the impact (generic solver, e = 1) equals m v0^2/2",
                Formula::named("K_after", solved(&rod(k(1, 1))).energy.after),
                f("m") * &f("v0").pow(2) / &Formula::int(2),
            ),
            positive("energy lost for 0 <= e < 1 (e = s/(s + t), s >= 0, t > 0) is > 0: conservation singles out e = 1", lost(sym("e")), true, &inelastic, &["t", "m", "M", "I", "v0"], &["s"], PosExpr::quotient(
                    prod([
                        ps("t"),
                        PosExpr::sum([prod([pc(2, 1), ps("s")]), ps("t")]),
                        ps("m"),
                        ps("M"),
                        ps("I"),
                        ps("v0"),
                        ps("v0"),
                    ]),
                    prod([pc(2, 1), s_plus_t.clone(), s_plus_t, m_i_d_form()]),
                )),
        ]),
    }
}

fn c8(paper: &Paper) -> Claim {
    let after = elastic();
    let bounce = || {
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(3, 1)),
            ("I", rational(1, 1)),
            ("a", rational(0, 1)),
            ("v0", rational(1, 1)),
        ])
    };
    Claim {
        id: "C8",
        location: "after Eq. (kinetic)",
        group: Group::Equations,
        statement: "\"v and V are the speeds\"; omega is a magnitude",
        formal: "Natural reading: v >= 0 and V >= 0 are speeds. Refuted: at M = 3m, a = 0 (any I) \
                 the elastic solution has v = -v0/2 < 0, and the paper's own Eq. (v) gives a \
                 negative v there: the projectile bounces back. Correct statement: v and V are the \
                 x-components of the velocities (positive along v0), with V > 0 always, and the \
                 signed omega (docs/conventions.md) is >= 0 on the paper's domain 0 <= a <= l, so it equals \
                 its magnitude there."
            .into(),
        reason: "Eq. (v) is signed: at M = 3m, a = 0 it gives v = -v0/2 (the projectile bounces back); V > 0 and omega >= 0 for a >= 0".into(),
        decision: Decision::Qualified {
            qualification: "v and V are the signed x-velocity components (v < 0 when the projectile \
                            bounces back); V > 0 is a speed, and omega >= 0 for 0 <= a <= l is the \
                            magnitude of the angular velocity"
                .into(),
            counterexample: vec![
                Certificate::witness(
                    "M = 3m, a = 0: the solver's v is -v0/2 (the projectile bounces back)",
                    bounce(),
                    after.v.clone(),
                    Relation::Eq,
                    -(sym("v0") / k(2, 1)),
                ),
                Certificate::witness(
                    "M = 3m, a = 0: the paper's Eq. (v) itself gives v < 0, so v is not a speed",
                    bounce(),
                    paper.v.clone(),
                    Relation::Lt,
                    k(0, 1),
                ),
            ],
            proof: vec![
                positive("V > 0 (generic solver, e = 1): V = 2 m v0 I/(MI + mI + mMa^2)", after.rod_v, true, &[], &["m", "M", "I", "v0"], &[], PosExpr::quotient(
                        prod([pc(2, 1), ps("m"), ps("v0"), ps("I")]),
                        m_i_d_form(),
                    )),
                positive("omega >= 0 for a >= 0 (generic solver, e = 1): omega = 2 m M a v0/(MI + mI + mMa^2)", after.omega, false, &[], &["m", "M", "I", "v0"], &["a"], PosExpr::quotient(
                        prod([pc(2, 1), ps("m"), ps("M"), ps("a"), ps("v0")]),
                        m_i_d_form(),
                    )),
            ],
        },
    }
}

fn c9(_paper: &Paper) -> Claim {
    let p = rod(sym("e"));
    let (big_v, omega) = momentum_split(&f("v"));
    let after = motion(&p);
    let solver_v = Formula::named("v", after.v.clone());
    let (solver_big_v, solver_omega) = momentum_split(&solver_v);
    Claim {
        id: "C9",
        location: "Eq. (linear-angular)",
        group: Group::Equations,
        statement: "V = (m/M)(v0 - v), omega = (ma/I)(v0 - v)",
        formal: "Eqs. (linear) and (angular) alone (no energy law, so any restitution e) determine \
                 V and omega from v: they are linear in (V, omega) with coefficients M and I != 0, \
                 and V = (m/M)(v0 - v), omega = (ma/I)(v0 - v) satisfy both for every v (v a free \
                 symbol). The generic solver's solution obeys these relations for every e."
            .into(),
        reason: "with v free, (m/M)(v0 - v) and (ma/I)(v0 - v) satisfy both momentum laws identically; the solver's V, omega match for every e".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "linear momentum with V = (m/M)(v0 - v), v free, equals m v0",
                f("m") * &f("v") + &(f("M") * &Formula::named("V", big_v)),
                f("m") * &f("v0"),
            ),
            Certificate::identity(
                "angular momentum about the centre with omega = (ma/I)(v0 - v), v free, equals m v0 a",
                f("m") * &f("v") * &f("a") + &(f("I") * &Formula::named("omega", omega)),
                f("m") * &f("v0") * &f("a"),
            ),
            Certificate::identity(
                "the solver's V (any e) equals (m/M)(v0 - v) at the solver's v",
                Formula::named("V", after.rod_v),
                solver_big_v,
            ),
            Certificate::identity(
                "the solver's omega (any e) equals (ma/I)(v0 - v) at the solver's v",
                Formula::named("omega", after.omega),
                solver_omega,
            ),
        ]),
    }
}

fn c10(_paper: &Paper) -> Claim {
    let p = rod(k(1, 1));
    let v = f("v");
    let (big_v, omega) = momentum_split(&v);
    let trial = Motion {
        v: sym("v"),
        rod_v: big_v.value().clone(),
        omega: omega.value().clone(),
    };
    let before = Motion::before(sym("v0"));
    let twice_lost = Formula::int(2)
        * &(Formula::named("K0", kinetic_energy(&p, &before))
            - &Formula::named("K", kinetic_energy(&p, &trial)));
    Claim {
        id: "C10",
        location: "Eq. (kinetic2)",
        group: Group::Equations,
        statement: "m(v0^2 - v^2) = (m^2/M)(v0 - v)^2 + (m^2 a^2/I)(v0 - v)^2",
        formal: "Substituting Eq. (linear-angular) into Eq. (kinetic): for a free symbol v, \
                 2 (m v0^2/2 - (m v^2 + M V^2 + I omega^2)/2) with V = (m/M)(v0 - v), \
                 omega = (ma/I)(v0 - v) equals the left side minus the right side of Eq. (kinetic2) \
                 identically. So (kinetic2) is (kinetic) restricted to the momentum laws; it holds \
                 for the elastic solution (e = 1)."
            .into(),
        reason: "twice the energy balance with V, omega of Eq. (linear-angular) is the (kinetic2) difference identically in v; the elastic v satisfies it".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "2 (K0 - K after) with Eq. (linear-angular), v free, equals lhs - rhs of Eq. (kinetic2)",
                twice_lost,
                kinetic2(&v),
            ),
            Certificate::identity(
                "the elastic v of the generic solver satisfies Eq. (kinetic2)",
                kinetic2(&Formula::named("v", elastic().v)),
                k(0, 1),
            ),
        ]),
    }
}

fn c11(paper: &Paper) -> Claim {
    let (v, v0) = (f("v"), f("v0"));
    let v_paper = Formula::named("v_paper", paper.v.clone());
    let d = Formula::int(1) + &compliance_ratio();
    let factored = -(f("m") * &d * &(v.clone() - &v0) * &(v.clone() - &v_paper));
    let (big_v, omega) = momentum_split(&v0);
    Claim {
        id: "C11",
        location: "before (kinetic-divided)",
        group: Group::Equations,
        statement: "(kinetic2) is quadratic in v with roots exactly v0 and Eq. (v); v = v0 gives V = omega = 0 (no collision)",
        formal: "For m, M, I > 0 and any a, v0: lhs - rhs of Eq. (kinetic2) equals \
                 -m D (v - v0)(v - v_paper), with v_paper the paper's Eq. (v); the leading \
                 coefficient -m D is nonzero (D > 0), so it is a genuine quadratic and its roots are \
                 exactly v0 and v_paper, distinct when v0 > 0 (v0 - v_paper = 2 v0/D > 0). At v = v0 \
                 Eq. (linear-angular) gives V = omega = 0: the state before the impact, i.e. no \
                 collision (the projectile would pass through the rod)."
            .into(),
        reason: "(kinetic2) = -m D (v - v0)(v - Eq. (v)) identically with D > 0; the roots differ by 2v0/D; V(v0) = omega(v0) = 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic2) = -m D (v - v0)(v - v_paper), v free, v_paper from Eq. (v)",
                kinetic2(&v),
                factored,
            ),
            d_positive(),
            positive("the two roots differ: v0 - v (Eq. (v)) = 2 v0/D > 0", v0.clone() - &v_paper, true, &[], &["m", "M", "I", "v0"], &[], PosExpr::quotient(prod([pc(2, 1), ps("v0"), ps("M"), ps("I")]), m_i_d_form())),
            Certificate::identity("v = v0 in Eq. (linear-angular) gives V = 0", big_v, k(0, 1)),
            Certificate::identity(
                "v = v0 in Eq. (linear-angular) gives omega = 0",
                omega,
                k(0, 1),
            ),
        ]),
    }
}

fn c12(paper: &Paper) -> Claim {
    let (v, v0) = (f("v"), f("v0"));
    let linear = f("m")
        * &(Formula::int(1) + &compliance_ratio())
        * &(v.clone() - &Formula::named("v_paper", paper.v.clone()));
    Claim {
        id: "C12",
        location: "Eq. (kinetic-divided)",
        group: Group::Equations,
        statement: "(kinetic2) = (v0 - v) x (kinetic-divided); dividing is valid for v != v0",
        formal: "For a free symbol v: lhs - rhs of Eq. (kinetic2) equals (v0 - v) times lhs - rhs \
                 of Eq. (kinetic-divided), identically; so for v != v0 the two equations are \
                 equivalent. Nothing else is lost: (kinetic-divided) is linear, \
                 m D (v - v_paper) with D > 0, whose only root is the paper's Eq. (v), and it does \
                 not vanish at v = v0 (value 2 m v0 > 0)."
            .into(),
        reason: "(kinetic2) = (v0 - v)(kinetic-divided) identically; (kinetic-divided) = m D (v - Eq. (v)) and is 2 m v0 > 0 at v = v0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic2) = (v0 - v) (lhs - rhs of Eq. (kinetic-divided)), v free",
                kinetic2(&v),
                (v0.clone() - &v) * &kinetic_divided(&v),
            ),
            Certificate::identity(
                "lhs - rhs of Eq. (kinetic-divided) = m D (v - v of Eq. (v)): its only root is Eq. (v)",
                kinetic_divided(&v),
                linear,
            ),
            d_positive(),
            positive("at v = v0, lhs - rhs of Eq. (kinetic-divided) is 2 m v0 > 0: the division drops only the root v0", kinetic_divided(&v0), true, &[], &["m", "v0"], &[], prod([pc(2, 1), ps("m"), ps("v0")])),
        ]),
    }
}

/// C13-C15: an elastic closed form of the paper against the generic solver, with D > 0.
fn elastic_formula(
    id: &'static str,
    location: &'static str,
    statement: &'static str,
    quantity: &str,
    solver: RatFn,
    printed: &Formula,
) -> Claim {
    Claim {
        id,
        location,
        group: Group::Equations,
        statement,
        formal: format!(
            "For m, M, I > 0 and any a, v0, the elastic (e = 1) solution of the impulse equations \
             has {statement}, where D = 1 + m/M + m a^2/I > 0 (velocities are signed x-components \
             and omega is signed as in docs/conventions.md: the struck point moves forward for a > 0)."
        ),
        reason: format!(
            "the generic solver's {quantity} equals {location} identically, and D is visibly positive"
        ),
        decision: Decision::Proved(vec![
            Certificate::identity(
                format!("{quantity} from the impulse equations (e = 1) equals {location}"),
                Formula::named(quantity, solver),
                printed.clone(),
            ),
            d_positive(),
        ]),
    }
}

fn c13(paper: &Paper) -> Claim {
    elastic_formula(
        "C13",
        "Eq. (v)",
        "v = -(1 - m/M - ma^2/I)/D v0, with D > 0",
        "v",
        elastic().v,
        &paper.v,
    )
}

fn c14(paper: &Paper) -> Claim {
    elastic_formula(
        "C14",
        "Eq. (V)",
        "V = (2m/M)/D v0",
        "V",
        elastic().rod_v,
        &paper.big_v,
    )
}

fn c15(paper: &Paper) -> Claim {
    elastic_formula(
        "C15",
        "Eq. (omega)",
        "omega = (2ma/I)/D v0",
        "omega",
        elastic().omega,
        &paper.omega,
    )
}

// ---------------------------------------------------------------------------------------------
// The limiting cases.

fn c16(paper: &Paper) -> Claim {
    let centre = [("a", k(0, 1))];
    Claim {
        id: "C16",
        location: "case (i)",
        group: Group::LimitingCases,
        statement: "a = 0 gives omega = 0",
        formal: "For m, M, I > 0 and any v0: Eq. (omega) at a = 0 is 0, and so is the generic \
                 solver's omega at a = 0 for every restitution e (a central impulse exerts no torque \
                 about the centre)."
            .into(),
        reason: "Eq. (omega) and the solver's omega (any e) vanish identically at a = 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at("Eq. (omega) at a = 0 is 0", paper.omega.clone(), k(0, 1), &centre),
            Certificate::identity_at(
                "the generic solver's omega at a = 0 is 0 for every e",
                Formula::named("omega", motion(&rod(sym("e"))).omega),
                k(0, 1),
                &centre,
            ),
        ]),
    }
}

fn c17(paper: &Paper) -> Claim {
    let head_on = [("a", k(0, 1)), ("M", sym("m"))];
    let after = elastic();
    let v0 = sym("v0");
    Claim {
        id: "C17",
        location: "case (ii)",
        group: Group::LimitingCases,
        statement: "a = 0 and m = M give v = 0, V = v0",
        formal: "Elastic impact (as the paper assumes), a = 0, M = m, any I > 0 and v0: Eqs. (v) and \
                 (V) give v = 0 and V = v0, and so does the generic solver: the head-on elastic \
                 collision of equal masses exchanges the velocities. (With restitution e the solver \
                 gives v = (1 - e) v0/2 instead: the exchange is the elastic case only.)"
            .into(),
        reason: "Eqs. (v), (V) and the solver's elastic v, V reduce identically to 0 and v0 at a = 0, M = m".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at("Eq. (v) at a = 0, M = m is 0", paper.v.clone(), k(0, 1), &head_on),
            Certificate::identity_at(
                "Eq. (V) at a = 0, M = m is v0",
                paper.big_v.clone(),
                v0.clone(),
                &head_on,
            ),
            Certificate::identity_at(
                "the generic solver's v (e = 1) at a = 0, M = m is 0",
                Formula::named("v", after.v),
                k(0, 1),
                &head_on,
            ),
            Certificate::identity_at(
                "the generic solver's V (e = 1) at a = 0, M = m is v0",
                Formula::named("V", after.rod_v),
                v0,
                &head_on,
            ),
        ]),
    }
}

/// The three limits M -> oo of (v, V, omega) = `values`, expected (-v0, 0, 0).
fn heavy_rod_limits(source: &str, values: [RatFn; 3]) -> Vec<Certificate> {
    let expected = [-sym("v0"), k(0, 1), k(0, 1)];
    ["v", "V", "omega"]
        .into_iter()
        .zip(values)
        .zip(expected)
        .map(|((name, value), target)| {
            Certificate::limit(
                format!("{source}: {name} -> {target} as M -> oo with I = M r_G^2 (r_G fixed)"),
                value,
                "M",
                Point::Infinity,
                target,
            )
        })
        .collect()
}

fn c18(paper: &Paper) -> Claim {
    let gyration = |x: &RatFn| subs(x, &[("I", gyration_inertia())]);
    let solver = motion(&free_rod(gyration_inertia(), k(1, 1)));
    let mut certificates = heavy_rod_limits(
        "Eqs. (v), (V), (omega)",
        [
            gyration(&paper.v),
            gyration(&paper.big_v),
            gyration(&paper.omega),
        ],
    );
    certificates.extend(heavy_rod_limits(
        "generic solver (e = 1)",
        [solver.v, solver.rod_v, solver.omega],
    ));
    let (m, a, inertia) = (sym("m"), sym("a"), sym("I"));
    let m_a2 = m * &a * &a;
    certificates.push(Certificate::Limit(crate::claims::certificate::Limit {
        title: "why I -> oo matters: with I held fixed, Eq. (v) tends to -(I - m a^2)/(I + m a^2) v0, not -v0 (a rod pivoted at its centre)".into(),
        expr: paper.v.value().clone(),
        sym: Sym::new("M"),
        at: Point::Infinity,
        expected: Expected::Finite(
            -((inertia.clone() - &m_a2) / (inertia + &m_a2)) * &sym("v0"),
        ),
    }));
    Claim {
        id: "C18",
        location: "case (iii)",
        group: Group::LimitingCases,
        statement: "M -> oo (I -> oo) gives v -> -v0, V -> 0, omega -> 0",
        formal: "Elastic impact, m, v0 > 0, any a, and a rod of fixed shape: I = M r_G^2 with r_G > 0 \
                 fixed, so I -> oo with M (the paper's \"consequently\"). Then, as M -> oo, Eqs. (v), \
                 (V), (omega) and the generic solver give v -> -v0, V -> 0, omega -> 0: reflection \
                 as from a wall. The parenthesis is load-bearing: if I stayed fixed while M -> oo, \
                 v would tend to -(I - m a^2)/(I + m a^2) v0 and omega to 2 m a v0/(I + m a^2) (a \
                 rod pivoted at its centre). More generally v, V, omega depend on M and I only \
                 through m/M and m a^2/I and are continuous where both vanish, so any joint limit \
                 M, I -> oo gives the same result (argument by hand, not machine-checked)."
            .into(),
        reason: "with I = M r_G^2, the exact limits M -> oo of Eqs. (v), (V), (omega) and of the solver are -v0, 0, 0".into(),
        decision: Decision::Proved(certificates),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Verdict, decide};
    use super::*;

    const EXPECTED: &[(&str, Verdict)] = &[
        ("C1", Verdict::Proved),
        ("C2", Verdict::Proved),
        ("C3", Verdict::Refuted),
        ("C4", Verdict::Proved),
        ("C5", Verdict::Proved),
        ("C6", Verdict::Proved),
        ("C7", Verdict::Proved),
        ("C8", Verdict::Qualified),
        ("C9", Verdict::Proved),
        ("C10", Verdict::Proved),
        ("C11", Verdict::Proved),
        ("C12", Verdict::Proved),
        ("C13", Verdict::Proved),
        ("C14", Verdict::Proved),
        ("C15", Verdict::Proved),
        ("C16", Verdict::Proved),
        ("C17", Verdict::Proved),
        ("C18", Verdict::Proved),
    ];

    #[test]
    fn verdicts_as_printed() {
        let paper = Paper::as_printed();
        for (id, verdict) in EXPECTED {
            let d = decide(id, &paper).expect("registered");
            assert_eq!(d.verdict, Ok(*verdict), "{id}");
        }
    }

    #[test]
    fn entries_in_claims_order() {
        let ids: Vec<_> = ENTRIES.iter().map(|e| e.id).collect();
        let expected: Vec<_> = EXPECTED.iter().map(|(id, _)| *id).collect();
        assert_eq!(ids, expected);
    }

    /// The claims of this file that fail under `paper`.
    fn failing(paper: &Paper) -> Vec<&'static str> {
        ENTRIES
            .iter()
            .filter(|e| (e.build)(paper).check().is_err())
            .map(|e| e.id)
            .collect()
    }

    #[test]
    fn a_wrong_sign_in_eq_v_is_caught() {
        let mut paper = Paper::as_printed();
        paper.v = -paper.v;
        assert_eq!(failing(&paper), ["C8", "C11", "C12", "C13", "C18"]);
    }

    #[test]
    fn eq_v_without_the_a_term_is_caught() {
        // v = -(1 - m/M)/D v0: wrong only for a != 0.
        let mut paper = Paper::as_printed();
        let d = paper_d(&sym("I"));
        paper.v = (-((k(1, 1) - &(sym("m") / sym("M"))) / d) * &sym("v0")).into();
        assert_eq!(failing(&paper), ["C11", "C12", "C13", "C18"]);
    }

    #[test]
    fn a_wrong_eq_big_v_is_caught() {
        let mut paper = Paper::as_printed();
        paper.big_v = paper.big_v / k(2, 1);
        assert_eq!(failing(&paper), ["C14", "C17"]);
    }

    #[test]
    fn an_offset_eq_omega_is_caught() {
        let mut paper = Paper::as_printed();
        paper.omega = paper.omega + &(sym("v0") / sym("l"));
        assert_eq!(failing(&paper), ["C15", "C16", "C18"]);
    }

    #[test]
    fn a_wrong_uniform_a_star_is_caught() {
        let mut paper = Paper::as_printed();
        paper.a_star_uniform_squared =
            ((sym("M") + &sym("m")) / (k(2, 1) * &sym("m")) * &sym("l") * &sym("l")).into();
        assert_eq!(failing(&paper), ["C4"]);
    }

    /// The `index`-th certificate of a claim, counterexamples first.
    fn certificate(claim: &mut Claim, index: usize) -> &mut Certificate {
        claim
            .certificates_mut()
            .into_iter()
            .nth(index)
            .expect("the claim has that certificate")
    }

    #[test]
    fn omega_is_not_strictly_positive_at_the_centre() {
        let mut claim = c8(&Paper::as_printed());
        let Certificate::Positive(crate::claims::certificate::Positive { strict, .. }) =
            certificate(&mut claim, 3)
        else {
            panic!("C8's fourth certificate is omega >= 0");
        };
        *strict = true;
        assert!(claim.check().is_err());
    }

    #[test]
    fn the_end_beats_nothing_at_equal_masses() {
        let mut claim = c1(&Paper::as_printed());
        let Certificate::Witness(crate::claims::certificate::Witness { relation, .. }) =
            certificate(&mut claim, 1)
        else {
            panic!("C1's second certificate is the omega comparison");
        };
        *relation = Relation::Le;
        assert!(claim.check().is_err());
    }

    #[test]
    fn a_negated_form_is_caught() {
        let mut claim = c4(&Paper::as_printed());
        let Certificate::Positive(crate::claims::certificate::Positive { form, .. }) =
            certificate(&mut claim, 0)
        else {
            panic!("C4's first certificate is a positivity");
        };
        *form = PosExpr::product([PosExpr::constant(-1, 1), form.clone()]);
        assert!(claim.check().is_err());
    }

    #[test]
    fn the_elastic_case_is_outside_the_loss_domain() {
        // Declaring t >= 0 admits e = 1, where nothing is lost: the strict claim must fail.
        let mut claim = c7(&Paper::as_printed());
        let Certificate::Positive(crate::claims::certificate::Positive {
            positive,
            nonnegative,
            ..
        }) = certificate(&mut claim, 1)
        else {
            panic!("C7's second certificate is the energy loss");
        };
        positive.retain(|s| s.name() != "t");
        nonnegative.push(Sym::new("t"));
        assert!(claim.check().is_err());
    }
}
