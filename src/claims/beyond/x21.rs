use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X21",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The struck point's speed after the impact, (1+e) v0 m/(m + M_eff(a)), increases strictly with a: intuition holds for the struck point but not for omega",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Gyration, ExportLaw::Restitution),
        &[
            Check::holds(
                "the struck point's speed is (1+e) v0 m/(m + M_eff)",
                "V + omega*a = (1 + e)*v0*m/(m + M*r^2/(r^2 + a^2))",
            ),
            Check::holds(
                "it increases strictly with a >= 0",
                "0 <= a1 and a1 < a2 => V_1 + omega_1*a1 < V_2 + omega_2*a2",
            ),
            Check::exists(
                "omega does not: M = m, r_G = l/2, omega(0.7 l) > omega(l)",
                "omega_1 > omega_2",
            )
            .given(&[
                "m = 1",
                "M = 1",
                "r = 1/2",
                "v0 = 1",
                "e = 1",
                "a1 = 7/10",
                "a2 = 1",
            ]),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
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
    Formalised {
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
