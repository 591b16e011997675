use crate::claims::dsl::*;
use crate::field::ratfunc::Point;
use crate::field::{RatFn, Sym};
use num_traits::Zero;

pub(super) const ENTRY: Entry = Entry {
    id: "X8",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Uniform rod with k = M/m <= 2: (omega(l)/omega_max)^2 = 12(1+k)/(4+k)^2, which lies in (3/4, 1]; at M = m the ratio is 2sqrt6/5 = 0.9798. Aiming at a* therefore gains less than 2/sqrt3 - 1 = 15.5% over hitting the end. For a general r_G the gain is unbounded",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Restitution),
        &[
            Check::holds(
                "(omega(l)/omega(a*))^2 = 12(1+k)/(4+k)^2, k = M/m",
                "(omega_l/omega_s)^2 = 12*(1 + M/m)/(4 + M/m)^2",
            ),
            Check::holds(
                "which lies in (3/4, 1] for k <= 2",
                "3/4 < (omega_l/omega_s)^2 and (omega_l/omega_s)^2 <= 1",
            )
            .given(&["M <= 2*m"]),
            Check::holds(
                "at M = m the ratio is 2 sqrt6/5, so the gain is below 2/sqrt3 - 1",
                "(omega_l/omega_s)^2 = 24/25 and omega_s/omega_l < 2*q/3",
            )
            .given(&["M = m", "q > 0", "q^2 = 3"]),
        ],
    )
    .at(&[
        StrikePoint { at: "s", tag: "s" },
        StrikePoint { at: "l", tag: "l" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*l^2/(3*m)"])
    .partly("the unbounded gain for a general r_G (a statement about a limit over rods)"),
);

fn formalise(paper: &Paper) -> Formalised {
    let (m, big_m) = (sym("m"), sym("M"));
    let ratio = uniform_ratio_squared(paper);
    let kk = big_m.clone() / m.clone();
    let kk_f = n("k", kk.clone());
    let half_m = (big_m.clone() / k(2, 1) + &sym("s"), "M/2 + s");
    let light = [("m", half_m.0)];
    let four_m = sum([prod([pc(4, 1), ps("m")]), ps("M")]);
    let s3m4s = sum([prod([pc(3, 1), ps("M")]), prod([pc(4, 1), ps("s")])]);
    let mut certs = vec![
        id(
            "uniform rod, any e: (omega(l)/omega(a*))^2 from the solver (a*^2 = Eq. (maximal-a-homogeneous) squared) = 12(1+k)/(4+k)^2, k = M/m",
            n("(omega(l)/omega(a*))^2", ratio.clone()),
            Formula::int(12) * &(Formula::int(1) + &kk_f) / &(Formula::int(4) + &kk_f).pow(2),
        ),
        positive(
            "1 - ratio^2 = (M - 2m)^2/(M + 4m)^2 >= 0 (so ratio <= 1, = 1 only at M = 2m)",
            one() - &ratio,
            false,
            &[],
            &["m", "M"],
            &[],
            quot(
                PosExpr::Square(big_m.clone() - &(k(2, 1) * &m)),
                prod([four_m.clone(), four_m]),
            ),
        ),
        positive(
            format!("ratio^2 - 3/4 > 0 for M <= 2m (m = {})", half_m.1),
            ratio.clone() - &k(3, 4),
            true,
            &light,
            &["M"],
            &["s"],
            quot(
                prod([
                    pc(3, 1),
                    ps("M"),
                    sum([prod([pc(3, 1), ps("M")]), prod([pc(8, 1), ps("s")])]),
                ]),
                prod([pc(4, 1), s3m4s.clone(), s3m4s]),
            ),
        ),
        Certificate::witness(
            "M = 2m: ratio^2 = 1 (the upper end 1 is attained)",
            at(&[("m", rational(1, 1)), ("M", rational(2, 1))]),
            ratio.clone(),
            Relation::Eq,
            one(),
        ),
        Certificate::limit(
            "ratio^2 -> 3/4 as M -> 0+ (k -> 0): 3/4 is the infimum, not attained for k > 0",
            ratio.clone(),
            "M",
            Point::Zero,
            k(3, 4),
        ),
        positive(
            format!(
                "gain: (omega_max/omega(l))^2 < 4/3 = (2/sqrt3)^2 for M <= 2m (m = {}), i.e. the gain < 2/sqrt3 - 1",
                half_m.1
            ),
            k(4, 3) - &(one() / ratio),
            true,
            &light,
            &["M"],
            &["s"],
            quot(
                prod([
                    ps("M"),
                    sum([prod([pc(3, 1), ps("M")]), prod([pc(8, 1), ps("s")])]),
                ]),
                prod([
                    pc(3, 1),
                    sum([prod([pc(3, 1), ps("M")]), prod([pc(2, 1), ps("s")])]),
                    sum([ps("M"), prod([pc(2, 1), ps("s")])]),
                ]),
            ),
        ),
    ];
    certs.extend(x8_witnesses(paper));
    certs.push(x8_general_rod(paper));
    proved(
        "Uniform rod (I = Ml^2/3), m, M, l, v0 > 0, any e >= 0, 0 < k = M/m <= 2 (so a* <= l and \
         omega_max = omega(a*), X6): the solver's (omega(l)/omega(a*))^2 equals 12(1+k)/(4+k)^2, \
         which is > 3/4 and <= 1 on (0, 2] (1 at k = 2; 3/4 only as k -> 0, never attained). At \
         M = m the ratio is 2 sqrt6/5 in (0.97975, 0.97985). The gain omega_max/omega(l) - 1 is \
         < 2/sqrt3 - 1 in (0.1545, 0.1555). For I = M r_G^2 with a* <= l, (omega(a*)/omega(l))^2 \
         -> oo as r_G -> 0+, so the gain is unbounded.",
        "the ratio reduces to 12(1+k)/(4+k)^2, and with m = M/2 + s both 1 - ratio^2 and ratio^2 - 3/4 have visible signs",
        certs,
    )
}

/// Uniform rod: `(omega(l)/omega(a*))^2` from the solver, a*^2 as the paper prints it.
fn uniform_ratio_squared(paper: &Paper) -> RatFn {
    let omega_sq = sq(&after(&uniform_inertia(), sym("e")).omega);
    subs(&omega_sq, &[("a", sym("l"))]) / even_at(&omega_sq, &paper.a_star_uniform_squared)
}

/// M = m: the ratio is 2 sqrt6/5 ~ 0.9798, and 2/sqrt3 - 1 ~ 15.5%.
fn x8_witnesses(paper: &Paper) -> Vec<Certificate> {
    let omega = after(&uniform_inertia(), sym("e")).omega;
    let unit = [("m", k(1, 1)), ("M", k(1, 1)), ("l", k(1, 1))];
    let a2 = constant(&subs(&paper.a_star_uniform_squared, &unit))
        .expect("a*^2 is a number once m, M, l are");
    let ratio = subs(&omega, &[("a", sym("l"))]) / omega;
    let instance = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("l", rational(1, 1)),
        ("v0", rational(1, 1)),
        ("e", rational(1, 1)),
        ("a", sqrt(&a2)),
        ("r6", sqrt(&crate::field::q(6, 1))),
    ]);
    let gain = k(2, 1) * &sym("r3") / k(3, 1) - &one();
    let dev = |x: RatFn, centre: (i64, i64), half: (i64, i64)| {
        sq(&(x - &k(centre.0, centre.1))) - &sq(&k(half.0, half.1))
    };
    vec![
        Certificate::witness(
            "M = m = l = 1, a = a* (Eq. (maximal-a-homogeneous)): omega(l)/omega(a*) = 2 sqrt6/5",
            instance.clone(),
            ratio.clone(),
            Relation::Eq,
            k(2, 5) * &sym("r6"),
        ),
        Certificate::witness(
            "M = m: |omega(l)/omega(a*) - 0.9798| < 0.00005",
            instance.clone(),
            dev(ratio, (9798, 10000), (1, 20000)),
            Relation::Lt,
            RatFn::zero(),
        ),
        Certificate::witness(
            "2/sqrt3 - 1 = 2 sqrt3/3 - 1 = 15.5% to the stated precision: |2 sqrt3/3 - 1 - 0.155| < 0.0005",
            at(&[("r3", sqrt(&crate::field::q(3, 1)))]),
            dev(gain, (155, 1000), (5, 10000)),
            Relation::Lt,
            RatFn::zero(),
        ),
    ]
}

/// General r_G: (omega(a*)/omega(l))^2 diverges as r_G -> 0+.
fn x8_general_rod(paper: &Paper) -> Certificate {
    let omega_sq = sq(&after(&gyration_inertia(), sym("e")).omega);
    let inverse =
        even_at(&omega_sq, &paper.a_star_gyration_squared) / subs(&omega_sq, &[("a", sym("l"))]);
    let (m, big_m, l) = (sym("m"), sym("M"), sym("l"));
    Certificate::Limit(Limit {
        title: "I = M r_G^2: (omega(a*)/omega(l))^2 ~ m l^2/(4(M+m) r_G^2) -> oo as r_G -> 0+ (a* = Eq. (maximal-a-gyration))".into(),
        expr: inverse,
        sym: Sym::new("r_G"),
        at: Point::Zero,
        expected: Expected::Infinite {
            coefficient: m.clone() * &sq(&l) / (k(4, 1) * &(big_m + &m)),
            order: -2,
        },
    })
}
