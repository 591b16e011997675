use crate::claims::dsl::*;
use crate::field::RatFn;
use num_traits::Zero;

pub(super) const ENTRY: Entry = Entry {
    id: "X12",
    location: BEYOND,
    group: Group::Beyond,
    statement: "v = v0 (m - e M_eff)/(m + M_eff) with M_eff = M r_G^2/(r_G^2 + a^2): the projectile bounces back iff m < e M_eff, stops iff m = e M_eff, goes on iff m > e M_eff. Uniform rod, e = 1: M_eff runs over [M/4, M] and the projectile stops at a0 = l sqrt((M - m)/(3m)), which lies on the rod for m <= M <= 4m. It always goes on for e = 0, and at a* for e = 1",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Restitution),
    &[
        Check::holds("v = v0 (m - e M_eff)/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)", "v = v0*(m - e*Me)/(m + Me)"),
        Check::holds("bounces back iff m < e M_eff, stops iff m = e M_eff", "(v < 0 => m < e*Me) and (m < e*Me => v < 0) and (v = 0 => m = e*Me) and (m = e*Me => v = 0)"),
        Check::holds("uniform rod: M_eff in [M/4, M] on the rod", "M/4 <= Me and Me <= M").given(&["3*r^2 = l^2", "0 <= a", "a <= l"]),
        Check::holds("uniform rod, e = 1: the projectile stops at a0 = l sqrt((M - m)/(3m)), on the rod iff M <= 4m", "v = 0 and (a <= l => M <= 4*m) and (M <= 4*m => a <= l)").given(&["e = 1", "3*r^2 = l^2", "M >= m", "a >= 0", "a^2 = l^2*(M - m)/(3*m)"]),
        Check::holds("e = 0: it always goes on", "v > 0").given(&["e = 0"]),
        Check::holds("e = 1 at a*: it goes on", "v_s > 0").given(&["e = 1"]),
    ],
)
.at(&[StrikePoint { at: "a", tag: "" }, StrikePoint { at: "s", tag: "s" }])
.given(&["l > 0", "Me = M*r^2/(r^2 + a^2)", "s > 0", "s^2 = (M + m)*r^2/m"]));

fn formalise(paper: &Paper) -> Formalised {
    let (m, e, v0) = (sym("m"), sym("e"), sym("v0"));
    let gyr = gyration_inertia();
    let m_eff_g = effective_mass(&gyr);
    let m_eff_named = n("M_eff", m_eff_g.clone());
    let mut certs = vec![
        id(
            "v from the solver (I = M r_G^2) = v0 (m - e M_eff)/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)",
            n("v", after(&gyr, e.clone()).v),
            f("v0") * &(f("m") - &(f("e") * &m_eff_named)) / &(f("m") + &m_eff_named),
        ),
        positive(
            "v0/(m + M_eff) > 0, so sign(v) = sign(m - e M_eff)",
            v0.clone() / (m.clone() + &m_eff_g),
            true,
            &[],
            &["m", "M", "r_G", "v0"],
            &[],
            quot(
                prod([
                    ps("v0"),
                    sum([prod([ps("r_G"), ps("r_G")]), PosExpr::Square(sym("a"))]),
                ]),
                sum([
                    prod([
                        ps("m"),
                        sum([prod([ps("r_G"), ps("r_G")]), PosExpr::Square(sym("a"))]),
                    ]),
                    prod([ps("M"), ps("r_G"), ps("r_G")]),
                ]),
            ),
        ),
    ];
    certs.extend(x12_uniform_range());
    certs.extend(x12_stop_point());
    certs.extend(x12_goes_on(paper));
    proved(
        "I = M r_G^2, m, M, r_G, v0 > 0, any a, e: the solver's v equals v0 (m - e M_eff)/(m + M_eff) \
         with a positive factor v0/(m + M_eff), so v < 0, = 0, > 0 as m - e M_eff is. Uniform rod \
         (r_G^2 = l^2/3), e = 1, 0 <= a <= l: M_eff is M at a = 0, M/4 at a = l, and M/4 < M_eff <= M \
         on [0, l) (continuous, so every value of [M/4, M] is taken: the intermediate-value step is \
         not machine-checked). v = 0 at a0^2 = l^2 (M - m)/(3m); a0 is real iff M >= m and a0 <= l \
         iff M <= 4m (for M < m, a0^2 < 0; for M > 4m, a0 > l). For e = 0, v > 0 at every a; for \
         e = 1 at a = a* (Eq. (maximal-a-gyration)) v = m v0/(M+m) > 0.",
        "the solver's v factors as v0 (m - e M_eff)/(m + M_eff); the range, a0 and the signs are visible after slack substitutions",
        certs,
    )
}

/// `M_eff = M I/(I + M a^2)` (= M r_G^2/(r_G^2 + a^2) for I = M r_G^2).
fn effective_mass(inertia: &RatFn) -> RatFn {
    sym("M") * inertia / (inertia.clone() + &(sym("M") * &sq(&sym("a"))))
}

/// Uniform rod, e = 1: M_eff over [M/4, M].
fn x12_uniform_range() -> Vec<Certificate> {
    let meff = effective_mass(&uniform_inertia());
    let (big_m, l) = (sym("M"), sym("l"));
    let l2_3a2 = sum([
        prod([ps("l"), ps("l")]),
        prod([pc(3, 1), PosExpr::Square(sym("a"))]),
    ]);
    vec![
        Certificate::identity_at(
            "uniform rod: M_eff(0) = M",
            n("M_eff", meff.clone()),
            big_m.clone(),
            &[("a", k(0, 1))],
        ),
        Certificate::identity_at(
            "uniform rod: M_eff(l) = M/4",
            n("M_eff", meff.clone()),
            f("M") / &Formula::int(4),
            &[("a", l)],
        ),
        positive(
            "uniform rod: M - M_eff = 3 M a^2/(l^2 + 3a^2) >= 0",
            sym("M") - &meff,
            false,
            &[],
            &["M", "l"],
            &[],
            quot(prod([pc(3, 1), ps("M"), PosExpr::Square(sym("a"))]), l2_3a2),
        ),
        positive(
            "uniform rod: M_eff - M/4 > 0 for 0 <= a < l (l = a + s, s > 0)",
            meff - &(sym("M") / k(4, 1)),
            true,
            &[("l", sym("a") + &sym("s"))],
            &["M", "s"],
            &["a"],
            quot(
                prod([
                    pc(3, 1),
                    ps("M"),
                    ps("s"),
                    sum([prod([pc(2, 1), ps("a")]), ps("s")]),
                ]),
                prod([
                    pc(4, 1),
                    sum([
                        prod([pc(4, 1), ps("a"), ps("a")]),
                        prod([pc(2, 1), ps("a"), ps("s")]),
                        prod([ps("s"), ps("s")]),
                    ]),
                ]),
            ),
        ),
    ]
}

/// Uniform rod, e = 1: v(a0) = 0, a0 real iff M >= m, on the rod iff M <= 4m.
fn x12_stop_point() -> Vec<Certificate> {
    let (m, big_m, l) = (sym("m"), sym("M"), sym("l"));
    let a0_sq = sq(&l) * &(big_m.clone() - &m) / (k(3, 1) * &m);
    let v = after(&uniform_inertia(), k(1, 1)).v;
    let pos = |title: &str, expr: RatFn, strict, sub: (&str, RatFn), nonneg: &[&str], form| {
        let subs = [sub];
        let positive_syms: Vec<&str> = ["m", "M", "l", "s"]
            .into_iter()
            .filter(|x| *x != subs[0].0 && !nonneg.contains(x))
            .collect();
        positive(title, expr, strict, &subs, &positive_syms, nonneg, form)
    };
    let l2s = |c: i64, den: PosExpr| {
        let lls = [ps("l"), ps("l"), ps("s")];
        let num = if c == 1 {
            prod(lls)
        } else {
            prod([pc(c, 1), prod(lls)])
        };
        quot(num, den)
    };
    vec![
        id(
            "uniform rod, e = 1: v (solver) at a^2 = a0^2 = l^2 (M - m)/(3m) is 0",
            n("v(a0)", even_at(&v, &a0_sq)),
            RatFn::zero(),
        ),
        pos(
            "a0^2 >= 0 for M >= m (M = m + s, s >= 0)",
            a0_sq.clone(),
            false,
            ("M", m.clone() + &sym("s")),
            &["s"],
            l2s(1, prod([pc(3, 1), ps("m")])),
        ),
        pos(
            "l^2 - a0^2 >= 0 for M <= 4m (m = (M + s)/4, s >= 0)",
            sq(&l) - &a0_sq,
            false,
            ("m", (big_m.clone() + &sym("s")) / k(4, 1)),
            &["s"],
            l2s(4, prod([pc(3, 1), sum([ps("M"), ps("s")])])),
        ),
        pos(
            "M < m: a0^2 < 0, no stop point (m = M + s, s > 0)",
            -a0_sq.clone(),
            true,
            ("m", big_m.clone() + &sym("s")),
            &[],
            l2s(1, prod([pc(3, 1), sum([ps("M"), ps("s")])])),
        ),
        pos(
            "M > 4m: a0^2 - l^2 > 0, the stop point is beyond the end (M = 4m + s, s > 0)",
            a0_sq - &sq(&l),
            true,
            ("M", k(4, 1) * &m + &sym("s")),
            &[],
            l2s(1, prod([pc(3, 1), ps("m")])),
        ),
    ]
}

/// The projectile goes on for e = 0 (any a), and for e = 1 at a*.
fn x12_goes_on(paper: &Paper) -> Vec<Certificate> {
    let gyr = gyration_inertia();
    let masses = ["m", "M", "r_G", "v0"];
    let r2_a2 = sum([prod([ps("r_G"), ps("r_G")]), PosExpr::Square(sym("a"))]);
    vec![
        positive(
            "e = 0: v (solver, I = M r_G^2) = v0 m/(m + M_eff) > 0 for every a",
            after(&gyr, k(0, 1)).v,
            true,
            &[],
            &masses,
            &[],
            quot(
                prod([ps("v0"), ps("m"), r2_a2.clone()]),
                sum([
                    prod([ps("m"), r2_a2]),
                    prod([ps("M"), ps("r_G"), ps("r_G")]),
                ]),
            ),
        ),
        positive(
            "e = 1 at a* (a^2 = Eq. (maximal-a-gyration) squared): v (solver) = m v0/(M + m) > 0",
            even_at(&after(&gyr, k(1, 1)).v, &paper.a_star_gyration_squared),
            true,
            &[],
            &masses,
            &[],
            quot(prod([ps("m"), ps("v0")]), sum([ps("m"), ps("M")])),
        ),
    ]
}
