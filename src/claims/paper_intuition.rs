//! Claims C32-C46: why intuition fails (fixed axes, impulses) and the inhomogeneous rod.

use super::build::*;
use super::model::*;
use super::{Certificate, Claim, Decision, Entry, Formula, Group, Paper, PosExpr, Relation};
use crate::field::ratfunc::Point;
use crate::field::{QSqrt, RatFn, Sym, q};

/// The registered claims of this part of the paper.
pub(super) const ENTRIES: &[Entry] = &[
    Entry {
        id: "C32",
        build: c32,
    },
    Entry {
        id: "C33",
        build: c33,
    },
    Entry {
        id: "C34",
        build: c34,
    },
    Entry {
        id: "C35",
        build: c35,
    },
    Entry {
        id: "C36",
        build: c36,
    },
    Entry {
        id: "C37",
        build: c37,
    },
    Entry {
        id: "C38",
        build: c38,
    },
    Entry {
        id: "C39",
        build: c39,
    },
    Entry {
        id: "C40",
        build: c40,
    },
    Entry {
        id: "C41",
        build: c41,
    },
    Entry {
        id: "C42",
        build: c42,
    },
    Entry {
        id: "C43",
        build: c43,
    },
    Entry {
        id: "C44",
        build: c44,
    },
    Entry {
        id: "C45",
        build: c45,
    },
    Entry {
        id: "C46",
        build: c46,
    },
];

// ---------------------------------------------------------------------------------------------
// Small builders: the solver's quantities.

/// `x + y` for two symbols.
fn plus(x: &str, y: &str) -> PosExpr {
    sum([ps(x), ps(y)])
}

/// A symbol as a [`Formula`].
fn f(name: &str) -> Formula {
    Formula::sym(name)
}

fn at_a(x: &RatFn, value: RatFn) -> RatFn {
    subs(x, &[("a", value)])
}

/// omega of the free rod after the impact, from the generic solver, restitution e.
fn free_omega(inertia: RatFn) -> RatFn {
    motion(&free_rod(inertia, sym("e"))).omega
}

/// The impulse J = m (v0 - v) the projectile gives the free rod, from the generic solver.
fn free_impulse(inertia: RatFn) -> RatFn {
    let p = free_rod(inertia, sym("e"));
    solved(&p).impulse(&p)
}

// ---------------------------------------------------------------------------------------------
// Certificates shared by several claims.

/// J(a) - J(a + t) > 0 for a >= 0, t > 0: the solver's impulse falls as a grows (any I, any e).
fn impulse_decreasing() -> Certificate {
    let j = free_impulse(sym("I"));
    let expr = j.clone() - &at_a(&j, sym("a") + &sym("t"));
    // J = (1+e) v0 m M I/(MI + mI + mM a^2); the difference of the denominators is mM t(2a + t).
    let den = |x: PosExpr| {
        sum([
            prod([ps("M"), ps("I")]),
            prod([ps("m"), ps("I")]),
            prod([ps("m"), ps("M"), x.clone(), x]),
        ])
    };
    let form = quot(
        prod([
            one_plus_e(),
            ps("v0"),
            ps("m"),
            ps("m"),
            ps("M"),
            ps("M"),
            ps("I"),
            ps("t"),
            sum([prod([pc(2, 1), ps("a")]), ps("t")]),
        ]),
        prod([den(ps("a")), den(plus("a", "t"))]),
    );
    positive(
        "the impulse J(a) = m (v0 - v) from the solver falls strictly: J(a) - J(a + t) > 0 for a >= 0, t > 0 (any I, any e >= 0)",
        expr,
        true,
        &[],
        &["m", "M", "I", "v0", "t"],
        &["a", "e"],
        form,
    )
}

/// omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s, s > 0), omega from the solver with the
/// given inertia; `mass_subs`, `pos` and `nonneg` give the
/// mass domain.
fn end_beats_interior(
    title: &str,
    inertia: RatFn,
    mass_subs: &[(&str, RatFn)],
    pos: &[&str],
    nonneg: &[&str],
    form: PosExpr,
) -> Certificate {
    let omega = free_omega(inertia);
    let expr = at_a(&omega, sym("l")) - &omega;
    let mut substitutions = mass_subs.to_vec();
    substitutions.push(("l", sym("a") + &sym("s")));
    positive(title, expr, true, &substitutions, pos, nonneg, form)
}

/// a* >= l whenever M >= m (l^2/r_G^2 - 1): with l = r_G + u and
/// M = m u (2 r_G + u)/r_G^2 + q, the paper's a*^2 - l^2 = q r_G^2/m.
fn gyration_end_optimal(paper: &Paper) -> Certificate {
    let (m, rg, u) = (sym("m"), sym("r_G"), sym("u"));
    let big_m = m * &u * &(k(2, 1) * &rg + &u) / sq(&rg) + &sym("q");
    positive(
        "Eq. (maximal-a-gyration): a*^2 - l^2 >= 0 when M >= m (l^2/r_G^2 - 1) (l = r_G + u, M = m u (2 r_G + u)/r_G^2 + q; u, q >= 0)",
        paper.a_star_gyration_squared.clone() - &sq(&sym("l")),
        false,
        &[("l", rg.clone() + &u), ("M", big_m)],
        &["m", "r_G"],
        &["u", "q"],
        quot(prod([ps("q"), ps("r_G"), ps("r_G")]), ps("m")),
    )
}

/// a* < l whenever M < m (l^2/r_G^2 - 1), r_G < l: with l = r_G + u and
/// m = (M r_G^2 + q)/(u (2 r_G + u)), l^2 - a*^2 = q u (2 r_G + u)/(M r_G^2 + q).
fn gyration_interior_optimal(paper: &Paper) -> Certificate {
    let (big_m, rg, u) = (sym("M"), sym("r_G"), sym("u"));
    let two_r_u = k(2, 1) * &rg + &u;
    let m = (big_m * &sq(&rg) + &sym("q")) / (u.clone() * &two_r_u);
    let two_r_plus_u = sum([prod([pc(2, 1), ps("r_G")]), ps("u")]);
    positive(
        "Eq. (maximal-a-gyration): l^2 - a*^2 > 0 when M < m (l^2/r_G^2 - 1) (l = r_G + u, m = (M r_G^2 + q)/(u (2 r_G + u)); u, q > 0)",
        sq(&sym("l")) - &paper.a_star_gyration_squared,
        true,
        &[("l", rg + &u), ("m", m)],
        &["M", "r_G", "u", "q"],
        &[],
        quot(
            prod([ps("q"), ps("u"), two_r_plus_u]),
            sum([prod([ps("M"), ps("r_G"), ps("r_G")]), ps("q")]),
        ),
    )
}

/// Whenever a* < l, omega(a*) > omega(l): I parametrised by a* = w (I = m M w^2/(M + m)),
/// l = w + s; omega(w) - omega(l) = (1+e) v0 s^2/(2 w (w^2 + l^2)).
fn optimum_beats_end() -> Certificate {
    let (m, big_m, w) = (sym("m"), sym("M"), sym("w"));
    let inertia_of_w = m.clone() * &big_m * &sq(&w) / (big_m + &m);
    let omega = free_omega(sym("I"));
    let expr = at_a(&omega, w.clone()) - &at_a(&omega, sym("l"));
    let ws = plus("w", "s");
    positive(
        "omega(a*) - omega(l) > 0 whenever a* < l (I = m M a*^2/(M + m) with a* = w, l = w + s, s > 0; omega from the solver)",
        expr,
        true,
        &[("I", inertia_of_w), ("l", w + &sym("s"))],
        &["m", "M", "v0", "w", "s"],
        &["e"],
        quot(
            prod([one_plus_e(), ps("v0"), ps("s"), ps("s")]),
            prod([
                pc(2, 1),
                ps("w"),
                sum([prod([ps("w"), ps("w")]), prod([ws.clone(), ws])]),
            ]),
        ),
    )
}

/// Dumbbell (I = M l^2, r_G = l): a*^2 - l^2 = M l^2/m > 0 for all masses.
fn dumbbell_a_star(paper: &Paper) -> Certificate {
    let a_star_sq = subs(&paper.a_star_gyration_squared, &[("r_G", sym("l"))]);
    positive(
        "dumbbell (r_G = l): Eq. (maximal-a-gyration) gives a*^2 - l^2 = M l^2/m > 0 for all m, M > 0",
        a_star_sq - &sq(&sym("l")),
        true,
        &[],
        &["m", "M", "l"],
        &[],
        quot(prod([ps("M"), ps("l"), ps("l")]), ps("m")),
    )
}

/// Dumbbell: omega(l) - omega(a) > 0 for every 0 <= a < l and all masses.
fn dumbbell_end_wins() -> Certificate {
    let inertia = subs(&gyration_inertia(), &[("r_G", sym("l"))]);
    let l = plus("a", "s");
    let form = quot(
        prod([
            one_plus_e(),
            ps("v0"),
            ps("s"),
            ps("m"),
            sum([prod([ps("M"), l.clone()]), prod([ps("m"), ps("s")])]),
        ]),
        prod([
            sum([ps("M"), prod([pc(2, 1), ps("m")])]),
            l.clone(),
            sum([
                prod([plus("M", "m"), l.clone(), l]),
                prod([ps("m"), ps("a"), ps("a")]),
            ]),
        ]),
    );
    end_beats_interior(
        "dumbbell (I = M l^2): omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s, s > 0), all m, M > 0, e >= 0; omega from the solver",
        inertia,
        &[],
        &["m", "M", "v0", "s"],
        &["a", "e"],
        form,
    )
}

/// `sum c_i y^i` over the named coefficients `(name, i)`.
fn density(coefficients: &[(&str, u32)]) -> RatFn {
    coefficients.iter().fold(RatFn::from(0), |acc, (c, i)| {
        acc + &(sym(c) * &pow(&sym("y"), *i))
    })
}

/// `integral_{-l}^{l} sum c_i y^i * y^power dy`, term by term: odd integrands give 0, even
/// ones 2 c_i l^(n+1)/(n+1) with n = i + power.
fn symmetric_moment(coefficients: &[(&str, u32)], power: u32) -> RatFn {
    coefficients
        .iter()
        .fold(RatFn::from(0), |acc, (c, i)| match (i + power) % 2 {
            0 => {
                let n = i + power + 1;
                acc + &(k(2, i64::from(n)) * &sym(c) * &pow(&sym("l"), n))
            }
            _ => acc,
        })
}

fn integral(
    title: &str,
    density: RatFn,
    power: u32,
    (lower, upper): (RatFn, RatFn),
    expected: RatFn,
) -> Certificate {
    Certificate::Integral(crate::claims::certificate::Integral {
        title: title.into(),
        density,
        var: Sym::new("y"),
        power,
        lower,
        upper,
        expected,
    })
}

fn whole_rod() -> (RatFn, RatFn) {
    (-sym("l"), sym("l"))
}

// ---------------------------------------------------------------------------------------------
// C32-C39: fixed axes, impulses, the competition.

fn c32(_paper: &Paper) -> Claim {
    let general = pivoted_rod(sym("I"), sym("e"));
    let out = solved(&general);
    let omega = out.after.omega.clone();
    let i_p = general.inertia_about_axis();
    let (m, p, a) = (sym("m"), sym("p"), sym("a"));
    let arm = a.clone() - &p;
    let (d, i_p_named) = (
        Formula::named("d", arm.clone()),
        Formula::named("I_p", i_p.clone()),
    );
    let closed = (Formula::int(1) + &f("e")) * &f("m") * &d * &f("v0")
        / &(i_p_named.clone() + &(f("m") * &d.pow(2)));
    let (x, t, w) = (sym("x"), sym("t"), sym("w"));
    let below = at_a(&omega, p.clone() + &x + &t) - &at_a(&omega, p.clone() + &x);
    let beyond = at_a(&omega, p.clone() + &w + &x) - &at_a(&omega, p.clone() + &w + &x + &t);
    let big_m_p2 = sym("M") * &sq(&p);
    let xt = plus("x", "t");
    let wx = plus("w", "x");
    let wxt = sum([ps("w"), ps("x"), ps("t")]);
    let door = pivoted_rod(uniform_inertia(), sym("e"));
    let door_omega = motion(&door).omega;
    let given = sym("J") * &arm / i_p.clone();
    let proof = vec![
        Certificate::identity(
            "pivot at p, arm d = a - p: the solver's omega equals (1+e) m d v0/(I_p + m d^2), I_p = I + M p^2",
            Formula::named("omega", omega.clone()),
            closed,
        ),
        positive(
            "omega grows with the arm up to d* = sqrt(I_p/m): omega(d + t) - omega(d) > 0 for 0 <= d < d + t <= d* (I_p = m ((d + t)^2 + s), d = x)",
            below,
            true,
            &[(
                "I",
                m.clone() * &(sq(&(x.clone() + &t)) + &sym("s")) - &big_m_p2,
            )],
            &["m", "v0", "t"],
            &["x", "s", "e"],
            quot(
                prod([
                    one_plus_e(),
                    ps("v0"),
                    ps("t"),
                    sum([prod([xt.clone(), ps("t")]), ps("s")]),
                ]),
                prod([
                    sum([
                        prod([xt.clone(), xt.clone()]),
                        prod([ps("x"), ps("x")]),
                        ps("s"),
                    ]),
                    sum([prod([pc(2, 1), xt.clone(), xt]), ps("s")]),
                ]),
            ),
        ),
        positive(
            "omega falls with the arm beyond d*: omega(d) - omega(d + t) > 0 for d* <= d (I_p = m d*^2, d* = w, d = w + x)",
            beyond,
            true,
            &[("I", m.clone() * &sq(&w) - &big_m_p2)],
            &["m", "v0", "t", "w"],
            &["x", "e"],
            quot(
                prod([
                    one_plus_e(),
                    ps("v0"),
                    ps("t"),
                    sum([
                        prod([ps("w"), ps("t")]),
                        prod([ps("x"), sum([prod([pc(2, 1), ps("w")]), ps("x"), ps("t")])]),
                    ]),
                ]),
                prod([
                    sum([prod([ps("w"), ps("w")]), prod([wx.clone(), wx])]),
                    sum([prod([ps("w"), ps("w")]), prod([wxt.clone(), wxt])]),
                ]),
            ),
        ),
        positive(
            "door (uniform rod hinged at its end, p = -l, arms up to 2l): d*^2 - (2l)^2 = I_p/m - 4 l^2 >= 0 when M = 3m + q, q >= 0",
            door.inertia_about_axis() / m.clone() - &(k(4, 1) * &sq(&sym("l"))),
            false,
            &[("p", -sym("l")), ("M", k(3, 1) * &m + &sym("q"))],
            &["m", "l"],
            &["q"],
            quot(
                prod([pc(4, 1), ps("q"), ps("l"), ps("l")]),
                prod([pc(3, 1), ps("m")]),
            ),
        ),
        Certificate::identity(
            "angular impulse about the pivot: the solver's omega equals J d/I_p with J = m (v0 - v)",
            Formula::named("omega", omega),
            Formula::named("J", out.impulse(&general)) * &d / &i_p_named,
        ),
        positive(
            "for a given impulse J > 0, omega = J d/I_p grows with the arm: d omega/da = J/(I + M p^2) > 0",
            given.derivative(Sym::new("a")),
            true,
            &[],
            &["J", "I", "M"],
            &[],
            quot(
                ps("J"),
                sum([ps("I"), prod([ps("M"), PosExpr::Square(p.clone())])]),
            ),
        ),
    ];
    let d_star = sqrt(&q(4, 3)) - &rational(1, 1);
    let counterexample = vec![Certificate::witness(
        "door hinged at one end (p = -l, I = M l^2/3) with M = m: striking at the arm d* = 2l/sqrt3 (a = d* - l) beats striking the far end (a = l)",
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("p", rational(-1, 1)),
            ("v0", rational(1, 1)),
            ("e", rational(1, 1)),
            ("a", d_star),
        ]),
        door_omega.clone(),
        Relation::Gt,
        at_a(&door_omega, sym("l")),
    )];
    Claim {
        id: "C32",
        location: "§intuition ¶1",
        group: Group::Intuition,
        statement: "About a fixed axis (doors, levers), the farther from the axis one strikes, the bigger the angular velocity (decide it in this paper's setting: a projectile of mass m, speed v0, striking a rod on a fixed pivot)",
        formal: "Rod of mass M, moment of inertia I about its centre, on a fixed frictionless pivot at p; a \
                 projectile m, v0 strikes it at a with arm d = a - p > 0; Newton restitution e in [0, 1]. \
                 Natural reading: omega increases with d over every arm the rod offers. The solver gives \
                 omega = (1+e) m d v0/(I_p + m d^2), I_p = I + M p^2, which increases on [0, d*] and \
                 decreases on [d*, oo), d* = sqrt(I_p/m). So the reading holds iff the largest arm is <= d*. \
                 Door (uniform rod, p = -l, arms in [0, 2l]): d* >= 2l iff M >= 3m. For a given impulse J \
                 (a force of given strength and duration, as with levers) omega = J d/I_p always grows with d."
            .into(),
        reason: "a projectile's omega = (1+e) m d v0/(I_p + m d^2) peaks at d* = sqrt(I_p/m), inside a door hinged at its end when M < 3m (M = m: d* = 2l/sqrt3 beats the far end); for a given impulse omega = J d/I_p does grow with d".into(),
        decision: Decision::Qualified {
            qualification: "true for a given impulse (omega = J d/I_p), and for a projectile iff every arm on the rod is at most d* = sqrt(I_p/m); for a door hinged at one end iff M >= 3m".into(),
            counterexample,
            proof,
        },
    }
}

fn c33(_paper: &Paper) -> Claim {
    let p = free_rod(sym("I"), sym("e"));
    let out = solved(&p);
    let (a, inertia, j) = (sym("a"), sym("I"), sym("J"));
    let given = j * &a / inertia.clone();
    Claim {
        id: "C33",
        location: "§intuition ¶1",
        group: Group::Intuition,
        statement: "A given impulse J gives the largest omega at a = l",
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

fn c34(_paper: &Paper) -> Claim {
    let inertia = sym("I");
    let one = Formula::int(1);
    let closed = (one.clone() + &f("e")) * &f("v0")
        / &(one.clone() / &f("m") + &(one / &f("M")) + &(f("a").pow(2) / &f("I")));
    Claim {
        id: "C34",
        location: "§intuition ¶1",
        group: Group::Intuition,
        statement: "The impulse depends on a",
        formal: "Free rod, any I, restitution e in [0, 1]: the impulse J(a) = m (v0 - v) delivered by the \
                 projectile is J(a) = (1+e) v0/(1/m + 1/M + a^2/I), strictly decreasing on a >= 0 (so it is \
                 not constant in a)."
            .into(),
        reason: "J(a) = (1+e) v0/(1/m + 1/M + a^2/I) from the solver, and J(a) - J(a + t) > 0 for a >= 0, t > 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "the solver's impulse m (v0 - v) equals (1+e) v0/(1/m + 1/M + a^2/I)",
                Formula::named("J", free_impulse(inertia)),
                closed,
            ),
            impulse_decreasing(),
        ]),
    }
}

fn c35(paper: &Paper) -> Claim {
    let p = free_rod(uniform_inertia(), one());
    let out = solved(&p);
    Claim {
        id: "C35",
        location: "Eq. (impulse-linear)",
        group: Group::Intuition,
        statement: "I_lin = MV = 2m v0/(1 + m/M + 3ma^2/(Ml^2)) (uniform rod)",
        formal: "Uniform rod (I = M l^2/3), elastic impact: the rod (at rest before) gains momentum \
                 ΔP = M V, which equals the impulse m (v0 - v) the projectile loses, and both equal \
                 Eq. (impulse-linear)."
            .into(),
        reason: "M V and m (v0 - v) from the solver both equal Eq. (impulse-linear) identically".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "M V from the solver (uniform rod, e = 1) equals Eq. (impulse-linear)",
                f("M") * &Formula::named("V", out.after.rod_v.clone()),
                paper.impulse_linear.clone(),
            ),
            Certificate::identity(
                "the projectile's loss of momentum m (v0 - v) (solver, uniform rod, e = 1) equals Eq. (impulse-linear)",
                f("m") * &(f("v0") - &Formula::named("v", out.after.v.clone())),
                paper.impulse_linear.clone(),
            ),
        ]),
    }
}

fn c36(paper: &Paper) -> Claim {
    let lin = &paper.impulse_linear;
    let expr = lin.clone() - &at_a(lin, sym("a") + &sym("t"));
    let den = |x: PosExpr| {
        sum([
            prod([ps("M"), ps("l"), ps("l")]),
            prod([ps("m"), ps("l"), ps("l")]),
            prod([pc(3, 1), ps("m"), x.clone(), x]),
        ])
    };
    let form = quot(
        prod([
            pc(6, 1),
            ps("m"),
            ps("m"),
            ps("M"),
            ps("l"),
            ps("l"),
            ps("v0"),
            ps("t"),
            sum([prod([pc(2, 1), ps("a")]), ps("t")]),
        ]),
        prod([den(ps("a")), den(plus("a", "t"))]),
    );
    Claim {
        id: "C36",
        location: "after (impulse-linear)",
        group: Group::Intuition,
        statement: "I_lin decreases as a increases",
        formal: "On the physical domain a >= 0 (I_lin is even in a): I_lin(a) - I_lin(a + t) > 0 for all \
                 a >= 0, t > 0, for Eq. (impulse-linear) (uniform rod, elastic) and for the solver's \
                 impulse with any I and any e."
            .into(),
        reason: "I_lin(a) - I_lin(a + t) = 6 m^2 M l^2 v0 t (2a + t)/(D1 D2) > 0 with D1, D2 visibly positive".into(),
        decision: Decision::Proved(vec![
            positive("Eq. (impulse-linear): I_lin(a) - I_lin(a + t) > 0 for a >= 0, t > 0", expr, true, &[], &["m", "M", "l", "v0", "t"], &["a"], form),
            impulse_decreasing(),
        ]),
    }
}

fn c37(paper: &Paper) -> Claim {
    let general = motion(&free_rod(uniform_inertia(), sym("e")));
    let elastic = motion(&free_rod(uniform_inertia(), one()));
    let a = f("a");
    Claim {
        id: "C37",
        location: "Eq. (impulse-angular)",
        group: Group::Intuition,
        statement: "(Ml^2/3) omega = a ΔP = M a V",
        formal: "Uniform rod: the angular impulse about the rod's centre, I omega with I = M l^2/3, equals \
                 a times the linear impulse ΔP = M V (for any restitution e), and for e = 1 equals \
                 a I_lin with I_lin from Eq. (impulse-linear)."
            .into(),
        reason: "Eq. (inertia-homogeneous) times the solver's omega equals a M V identically (any e), and a I_lin for e = 1".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "Eq. (inertia-homogeneous) I times the solver's omega equals M a V (any e)",
                paper.uniform_inertia.clone() * &Formula::named("omega", general.omega),
                f("M") * &a * &Formula::named("V", general.rod_v),
            ),
            Certificate::identity(
                "Eq. (inertia-homogeneous) I times the solver's omega (e = 1) equals a I_lin of Eq. (impulse-linear)",
                paper.uniform_inertia.clone() * &Formula::named("omega", elastic.omega),
                a * &paper.impulse_linear,
            ),
        ]),
    }
}

fn c38(_paper: &Paper) -> Claim {
    let after = motion(&free_rod(sym("I"), sym("e")));
    let uniform = free_omega(uniform_inertia());
    let slope = uniform.derivative(Sym::new("a"));
    let at_m_equal_big_m = |a: QSqrt| {
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
            ("e", rational(1, 1)),
            ("a", a),
        ])
    };
    Claim {
        id: "C38",
        location: "after (impulse-angular)",
        group: Group::Intuition,
        statement: "A competition between increasing a and decreasing V",
        formal: "Free rod, any I and e in [0, 1]: I omega = a M V(a) with M V(a) = J(a) > 0 strictly \
                 decreasing on a >= 0, so omega is the product of the increasing a and the decreasing J. \
                 Neither factor wins everywhere: for a uniform rod with M = m, d omega/da > 0 at a = 0 \
                 and < 0 at a = l."
            .into(),
        reason: "I omega = a M V identically, M V = J(a) falls strictly, and d omega/da changes sign on [0, l] (uniform rod, M = m)".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "I omega = a M V for the solver's velocities (any I, any e)",
                f("I") * &Formula::named("omega", after.omega.clone()),
                f("a") * &f("M") * &Formula::named("V", after.rod_v.clone()),
            ),
            impulse_decreasing(),
            Certificate::witness(
                "uniform rod, M = m, e = 1: at a = 0 the growing arm wins (d omega/da > 0)",
                at_m_equal_big_m(rational(0, 1)),
                slope.clone(),
                Relation::Gt,
                k(0, 1),
            ),
            Certificate::witness(
                "uniform rod, M = m, e = 1: at a = l the falling impulse wins (d omega/da < 0)",
                at_m_equal_big_m(rational(1, 1)),
                slope,
                Relation::Lt,
                k(0, 1),
            ),
        ]),
    }
}

fn c39(paper: &Paper) -> Claim {
    let big_m = paper.threshold.clone() * &sym("m") + &sym("q");
    let l = plus("a", "s");
    let form = quot(
        prod([
            pc(3, 1),
            ps("m"),
            one_plus_e(),
            ps("v0"),
            ps("s"),
            sum([
                prod([pc(3, 1), ps("m"), ps("s")]),
                prod([ps("q"), l.clone()]),
            ]),
        ]),
        prod([
            l.clone(),
            sum([prod([pc(6, 1), ps("m")]), ps("q")]),
            sum([
                prod([sum([prod([pc(3, 1), ps("m")]), ps("q")]), l.clone(), l]),
                prod([pc(3, 1), ps("m"), ps("a"), ps("a")]),
            ]),
        ]),
    );
    Claim {
        id: "C39",
        location: "after (impulse-angular)",
        group: Group::Intuition,
        statement: "For M large enough, a = l wins",
        formal: "Uniform rod (I = M l^2/3), any e in [0, 1]: for M >= 2m (the paper's threshold) \
                 omega(l) > omega(a) for every 0 <= a < l, so the maximum over [0, l] is at a = l, \
                 uniquely. The threshold is sharp (for M < 2m the maximum is inside, C27)."
            .into(),
        reason: "with M = 2m + q (q >= 0) and l = a + s (s > 0), omega(l) - omega(a) is a visibly positive fraction".into(),
        decision: Decision::Proved(vec![end_beats_interior("uniform rod, M = 2m + q (q >= 0, the paper's threshold): omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s); omega from the solver", uniform_inertia(), &[("M", big_m.into())], &["m", "v0", "s"], &["a", "q", "e"], form)]),
    }
}

// ---------------------------------------------------------------------------------------------
// C40-C46: the inhomogeneous rod.

fn c40(_paper: &Paper) -> Claim {
    // A symmetric polynomial density c0 + c2 y^2 + c4 y^4 (c_i >= 0).
    let poly = [("c0", 0), ("c2", 2), ("c4", 4)];
    let lambda = density(&poly);
    let (mass, inertia) = (symmetric_moment(&poly, 0), symmetric_moment(&poly, 2));
    let l2 = sq(&sym("l"));
    let (l, h) = (sym("l"), sym("h"));
    // Uniform density c on the two end segments of width h.
    let end_mass = sym("c") * &h;
    let end_inertia =
        sym("c") * &(l2.clone() * &h - &(l.clone() * &sq(&h)) + &(pow(&h, 3) / k(3, 1)));
    let right = (l.clone() - &h, l.clone());
    let left = (-l.clone(), h.clone() - &l);
    let end_rg2 = end_inertia.clone() / end_mass.clone();
    Claim {
        id: "C40",
        location: "Eq. (inertia-general)",
        group: Group::Inhomogeneous,
        statement: "I = M r_G^2; hidden: r_G <= l, with equality only when all the mass is at the ends",
        formal: "For any mass distribution dm on [-l, l] of total mass M > 0, r_G is defined by I = M r_G^2 \
                 with I = integral y^2 dm; then M l^2 - I = integral (l^2 - y^2) dm >= 0, and since \
                 l^2 - y^2 > 0 on (-l, l), equality holds iff all the mass sits at y = +-l (the ideal \
                 dumbbell). This measure argument is stated, not machine-checked in general; the \
                 certificates check it for two families: the polynomial densities c0 + c2 y^2 + c4 y^4 \
                 (c_i >= 0), where r_G^2 <= (5/7) l^2, and a uniform density on the end segments of \
                 width h in (0, l], where l^2 - r_G^2 = l h - h^2/3 > 0 tends to 0 as h -> 0 (the \
                 dumbbell, which the point masses M/2 at +-l attain)."
            .into(),
        reason: "M l^2 - I = integral (l^2 - y^2) dm >= 0, zero only for mass at y = +-l; checked exactly for a polynomial family and for end-loaded rods tending to the dumbbell".into(),
        decision: Decision::Proved(vec![
            integral(
                "polynomial density c0 + c2 y^2 + c4 y^4: mass M",
                lambda.clone(),
                0,
                whole_rod(),
                mass.clone(),
            ),
            integral(
                "polynomial density: moment of inertia I about the centre",
                lambda.clone(),
                2,
                whole_rod(),
                inertia.clone(),
            ),
            integral(
                "polynomial density: integral of (l^2 - y^2) dm equals M l^2 - I",
                lambda * &(l2.clone() - &sq(&sym("y"))),
                0,
                whole_rod(),
                l2.clone() * &mass - &inertia,
            ),
            positive("polynomial density (c_i >= 0): (5/7) l^2 M - I >= 0, i.e. M l^2 - I >= (2/7) M l^2 > 0, so r_G^2 <= (5/7) l^2 < l^2", k(5, 7) * &l2 * &mass - &inertia, false, &[], &["l"], &["c0", "c2", "c4"], sum([
                    prod([pc(16, 21), ps("c0"), ps("l"), ps("l"), ps("l")]),
                    prod([pc(8, 105), ps("c2"), ps("l"), ps("l"), ps("l"), ps("l"), ps("l")]),
                ])),
            integral(
                "end-loaded rod (density c on [l - h, l]): mass of the right segment",
                sym("c"),
                0,
                right.clone(),
                end_mass.clone(),
            ),
            integral(
                "end-loaded rod (density c on [-l, -l + h]): mass of the left segment",
                sym("c"),
                0,
                left.clone(),
                end_mass,
            ),
            integral(
                "end-loaded rod: moment of inertia of the right segment",
                sym("c"),
                2,
                right,
                end_inertia.clone(),
            ),
            integral(
                "end-loaded rod: moment of inertia of the left segment",
                sym("c"),
                2,
                left,
                end_inertia,
            ),
            positive("end-loaded rod, 0 < h <= l: l^2 - r_G^2 = l h - h^2/3 > 0 (l = h + s, s >= 0)", l2.clone() - &end_rg2, true, &[("l", h.clone() + &sym("s"))], &["c", "h"], &["s"], sum([prod([pc(2, 3), ps("h"), ps("h")]), prod([ps("h"), ps("s")])])),
            Certificate::limit(
                "end-loaded rod: r_G^2 -> l^2 as the end segments shrink (h -> 0+), the dumbbell limit",
                end_rg2,
                "h",
                Point::Zero,
                l2.clone(),
            ),
            Certificate::identity_at(
                "dumbbell (point masses M/2 at y = -l and y = l): I = sum of (M/2) y^2 equals M r_G^2 with r_G = l",
                f("M") / &Formula::int(2) * &(-f("l")).pow(2) + &(f("M") / &Formula::int(2) * &f("l").pow(2)),
                f("M") * &f("r_G").pow(2),
                &[("r_G", l)],
            ),
        ]),
    }
}

fn c41(paper: &Paper) -> Claim {
    let omega = free_omega(gyration_inertia());
    let a_star_sq = Formula::named("a*^2", paper.a_star_gyration_squared.clone());
    let a2 = f("a").pow(2);
    let slope = (Formula::int(1) + &f("e")) * &f("v0") * &(a_star_sq.clone() - &a2)
        / &(a_star_sq + &a2).pow(2);
    Claim {
        id: "C41",
        location: "Eq. (maximal-a-gyration)",
        group: Group::Inhomogeneous,
        statement: "a* = sqrt((M+m)/m) r_G",
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

fn c42(paper: &Paper) -> Claim {
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
    Claim {
        id: "C42",
        location: "§inhomogeneous",
        group: Group::Inhomogeneous,
        statement: "Mass concentrated near the middle (r_G << l) gives a* < l \"even for M >> m\"",
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

fn c43(paper: &Paper) -> Claim {
    let (l, rg) = (sym("l"), sym("r_G"));
    let bound = sq(&l) / sq(&rg) - &one();
    let bound_near_end = subs(&bound, &[("r_G", l - &sym("u"))]);
    Claim {
        id: "C43",
        location: "§inhomogeneous",
        group: Group::Inhomogeneous,
        statement: "Mass concentrated near the ends (r_G close to l): a* < l only for M << m",
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

fn c44(paper: &Paper) -> Claim {
    Claim {
        id: "C44",
        location: "§inhomogeneous",
        group: Group::Inhomogeneous,
        statement: "Ideal dumbbell (r_G = l): a* is always unphysical and the maximum is at a = l",
        formal: "Ideal dumbbell (point masses M/2 at +-l, so I = M l^2, r_G = l), any m, M > 0, \
                 e in [0, 1]: a*^2 - l^2 = M l^2/m > 0, and omega(l) > omega(a) for every 0 <= a < l."
            .into(),
        reason: "a*^2 - l^2 = M l^2/m > 0 for all masses, and omega(l) - omega(a) is a visibly positive fraction for a < l".into(),
        decision: Decision::Proved(vec![dumbbell_a_star(paper), dumbbell_end_wins()]),
    }
}

fn c45(paper: &Paper) -> Claim {
    Claim {
        id: "C45",
        location: "§inhomogeneous",
        group: Group::Inhomogeneous,
        statement: "Intuition is fully vindicated only for the ideal dumbbell",
        formal: "Symmetric rod, I = M r_G^2 with 0 < r_G <= l. 'Fully vindicated': for all m, M > 0 the \
                 maximum of omega over [0, l] is at a = l. If r_G < l, the masses with \
                 M < m (l^2/r_G^2 - 1) (a nonempty range) give a* < l and then omega(a*) > omega(l): \
                 not vindicated. If r_G = l it is vindicated for all masses (C44). And r_G = l holds only \
                 when all the mass is at the ends, the ideal dumbbell (C40)."
            .into(),
        reason: "every r_G < l admits masses with a* < l and omega(a*) > omega(l); r_G = l (the dumbbell, C40) has the maximum at a = l for all masses".into(),
        decision: Decision::Proved(vec![
            gyration_interior_optimal(paper),
            optimum_beats_end(),
            dumbbell_a_star(paper),
            dumbbell_end_wins(),
        ]),
    }
}

fn c46(_paper: &Paper) -> Claim {
    let even = [("c0", 0), ("c2", 2), ("c4", 4), ("c6", 6)];
    let with_odd = [("c0", 0), ("c1", 1), ("c2", 2)];
    Claim {
        id: "C46",
        location: "§inhomogeneous",
        group: Group::Inhomogeneous,
        statement: "A symmetric mass distribution puts the CM at the centre",
        formal: "A mass distribution on [-l, l] symmetric about the centre (dm(-y) = dm(y)) has first \
                 moment integral y dm = 0, since y is odd, so its CM is the centre. Checked exactly for \
                 the even polynomial densities c0 + c2 y^2 + c4 y^4 + c6 y^6 with arbitrary \
                 coefficients; the general argument (odd integrand) is stated, not machine-checked. An \
                 odd term c1 y moves the first moment to 2 c1 l^3/3, so symmetry is what is used."
            .into(),
        reason: "the first moment of an even density over [-l, l] is 0 (odd integrand); exact for the even polynomial family".into(),
        decision: Decision::Proved(vec![
            integral(
                "even density c0 + c2 y^2 + c4 y^4 + c6 y^6: first moment over [-l, l] is 0",
                density(&even),
                1,
                whole_rod(),
                k(0, 1),
            ),
            integral(
                "contrast: with an odd term, c0 + c1 y + c2 y^2 has first moment 2 c1 l^3/3",
                density(&with_odd),
                1,
                whole_rod(),
                symmetric_moment(&with_odd, 1),
            ),
        ]),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Expected, Verdict, decide};
    use super::*;

    const VERDICTS: &[(&str, Verdict)] = &[
        ("C32", Verdict::Qualified),
        ("C33", Verdict::Proved),
        ("C34", Verdict::Proved),
        ("C35", Verdict::Proved),
        ("C36", Verdict::Proved),
        ("C37", Verdict::Proved),
        ("C38", Verdict::Proved),
        ("C39", Verdict::Proved),
        ("C40", Verdict::Proved),
        ("C41", Verdict::Proved),
        ("C42", Verdict::Qualified),
        ("C43", Verdict::Proved),
        ("C44", Verdict::Proved),
        ("C45", Verdict::Proved),
        ("C46", Verdict::Proved),
    ];

    #[test]
    fn verdicts() {
        let paper = Paper::as_printed();
        for (id, verdict) in VERDICTS {
            let d = decide(id, &paper).expect("registered");
            assert_eq!(d.verdict, Ok(*verdict), "{id}");
        }
    }

    #[test]
    fn registered_in_claims_md_order() {
        let ids: Vec<_> = ENTRIES.iter().map(|e| e.id).collect();
        let expected: Vec<_> = VERDICTS.iter().map(|(id, _)| *id).collect();
        assert_eq!(ids, expected);
    }

    fn failing(paper: &Paper) -> Vec<&'static str> {
        ENTRIES
            .iter()
            .filter(|e| super::super::decide_entry(e, paper).verdict.is_err())
            .map(|e| e.id)
            .collect()
    }

    #[test]
    fn a_wrong_impulse_formula_is_caught() {
        let mut paper = Paper::as_printed();
        // 3 m a^2/(M l^2) printed as m a^2/(M l^2).
        let (m, big_m, a, l) = (sym("m"), sym("M"), sym("a"), sym("l"));
        paper.impulse_linear = (k(2, 1) * &m * &sym("v0")
            / (one() + &(m.clone() / big_m.clone()) + &(m * &a * &a / (big_m * &l * &l))))
            .into();
        assert_eq!(failing(&paper), ["C35", "C36", "C37"]);
    }

    #[test]
    fn a_wrong_threshold_is_caught() {
        let mut paper = Paper::as_printed();
        paper.threshold = k(1, 1).into();
        assert_eq!(failing(&paper), ["C39"]);
    }

    #[test]
    fn a_wrong_gyration_optimum_is_caught() {
        let mut paper = Paper::as_printed();
        // (M + m)/M instead of (M + m)/m.
        paper.a_star_gyration_squared =
            ((sym("M") + &sym("m")) / sym("M") * &sym("r_G") * &sym("r_G")).into();
        assert_eq!(failing(&paper), ["C41", "C42", "C43", "C44", "C45"]);
    }

    #[test]
    fn a_wrong_uniform_inertia_is_caught() {
        let mut paper = Paper::as_printed();
        paper.uniform_inertia = (sym("M") * &sym("l") * &sym("l") / k(12, 1)).into();
        assert_eq!(failing(&paper), ["C37"]);
    }

    #[test]
    fn a_wrong_general_optimum_is_caught() {
        let mut paper = Paper::as_printed();
        paper.a_star_squared = (sym("I") * &(sym("M") + &sym("m")) / sym("m")).into();
        assert_eq!(failing(&paper), ["C41"]);
    }

    /// Every certificate of the range carries weight: perturbing it by a constant (or flipping
    /// a witness relation) must make it fail.
    fn perturbed(c: &Certificate) -> Certificate {
        let mut c = c.clone();
        match &mut c {
            Certificate::Identity(crate::claims::certificate::Identity { rhs, .. }) => {
                *rhs = rhs.clone() + &one()
            }
            Certificate::Positive(crate::claims::certificate::Positive { form, .. }) => {
                *form = sum([form.clone(), pc(1, 1)])
            }
            Certificate::Limit(crate::claims::certificate::Limit { expected, .. }) => {
                if let Expected::Finite(x) = expected {
                    *x = x.clone() + &one();
                }
            }
            Certificate::Witness(crate::claims::certificate::Witness { relation, .. }) => {
                *relation = match relation {
                    Relation::Gt => Relation::Le,
                    Relation::Lt => Relation::Ge,
                    _ => Relation::Ne,
                }
            }
            Certificate::Integral(crate::claims::certificate::Integral { expected, .. }) => {
                *expected = expected.clone() + &one()
            }
        }
        c
    }

    #[test]
    fn every_perturbed_certificate_fails() {
        let paper = Paper::as_printed();
        for e in ENTRIES {
            let claim = (e.build)(&paper);
            for c in claim.certificates() {
                assert!(c.check().is_ok(), "{}: {}", e.id, c.title());
                assert!(perturbed(c).check().is_err(), "{}: {}", e.id, c.title());
            }
        }
    }

    #[test]
    fn a_sign_flipped_form_is_rejected() {
        let paper = Paper::as_printed();
        let mut claim = c39(&paper);
        let Decision::Proved(certs) = &mut claim.decision else {
            panic!("C39 is proved");
        };
        let Certificate::Positive(crate::claims::certificate::Positive { form, .. }) =
            &mut certs[0]
        else {
            panic!("C39 is a positivity certificate");
        };
        // The same value, but a negative constant in the shape: no visible sign.
        *form = sum([form.clone(), pc(1, 1), pc(-1, 1)]);
        assert!(claim.check().is_err());
    }
}
