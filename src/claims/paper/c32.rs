use crate::claims::dsl::*;
use crate::field::{Sym, q};

pub(super) const ENTRY: Entry = Entry {
    id: "C32",
    location: "§intuition ¶1",
    group: Group::Intuition,
    statement: "About a fixed axis (doors, levers), the farther from the axis one strikes, the bigger the angular velocity (decide it in this paper's setting: a projectile of mass m, speed v0, striking a rod on a fixed pivot)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Pivot, ExportLaw::Restitution),
    &[
        Check::fails("reading: omega grows with the arm d; refuted for a door (Ip = M (2l)^2/3) with M = m = l = v0 = 1, e = 1 between d1 = 1 and d2 = 2", "0 < d1 and d1 < d2 => omega_1 < omega_2").given(&["m = 1", "M = 1", "Ip = 4/3", "v0 = 1", "e = 1", "d1 = 1", "d2 = 2"]),
        Check::holds("qualified: it grows on every arm up to d* = sqrt(Ip/m)", "0 <= d1 and d1 < d2 and d2 <= ds => omega_1 < omega_2").given(&["ds > 0", "ds^2 = Ip/m"]),
    ],
)
.at(&[StrikePoint { at: "d1", tag: "1" }, StrikePoint { at: "d2", tag: "2" }]));

fn formalise(_paper: &Paper) -> Formalised {
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
    Formalised {
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
