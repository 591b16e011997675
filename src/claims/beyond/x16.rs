use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::field::ratfunc::Point;

pub(super) const ENTRY: Entry = Entry {
    id: "X16",
    location: BEYOND,
    group: Group::Beyond,
    statement: "M -> 0 with r_G fixed: v -> v0, V -> 2v0 r^2/(r^2 + a^2), omega -> 2v0 a/(r^2 + a^2), the struck point -> 2v0, a* -> r_G",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Elastic),
    &[
        Check::holds("bounds vanishing as M -> 0+: |v - v0|, |V - 2 v0 r^2/(r^2 + a^2)| and |V + omega a - 2 v0| are at most 2 v0 M/m, |omega - 2 v0 a/(r^2 + a^2)| at most 2 v0 |a| M/(m (r^2 + a^2))", "(v - v0)^2 <= (2*v0*M/m)^2 and (V - 2*v0*r^2/(r^2 + a^2))^2 <= (2*v0*M/m)^2 and (omega - 2*v0*a/(r^2 + a^2))^2 <= (2*v0*a*M/(m*(r^2 + a^2)))^2 and (V + omega*a - 2*v0)^2 <= (2*v0*M/m)^2"),
        Check::holds("a*^2 - r_G^2 = (M/m) r_G^2", "s^2 - r^2 = (M/m)*r^2"),
    ],
)
.given(&["s > 0", "s^2 = (M + m)*r^2/m"])
.partly("the struck point's limit (1+e) v0 with restitution (the elastic case is stated)"));

fn formalise(paper: &Paper) -> Formalised {
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
    Formalised {
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
