use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::field::ratfunc::Point;

pub(super) const ENTRY: Entry = Entry {
    id: "X17",
    location: BEYOND,
    group: Group::Beyond,
    statement: "M -> oo: omega ~ 2m a v0/(M r_G^2), v + v0 ~ 2m v0(1 + a^2/r_G^2)/M; with restitution, v -> -e v0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Restitution),
    &[
        Check::holds(
            "bounds vanishing as M -> oo: |v + e v0| <= (1+e) v0 m (r^2 + a^2)/(M r^2), |M omega - (1+e) m a v0/r^2| <= (1+e) m^2 |a| v0 (r^2 + a^2)/(M r^4)",
            "(v + e*v0)^2 <= ((1 + e)*v0*m*(r^2 + a^2)/(M*r^2))^2 and (M*omega - (1 + e)*m*a*v0/r^2)^2 <= ((1 + e)*m^2*a*v0*(r^2 + a^2)/(M*r^4))^2",
        ),
        Check::holds(
            "elastic: |M (v + v0) - 2 m v0 (1 + a^2/r^2)| <= 2 m^2 v0 (r^2 + a^2)^2/(M r^4)",
            "(M*(v + v0) - 2*m*v0*(1 + a^2/r^2))^2 <= (2*m^2*v0*(r^2 + a^2)^2/(M*r^4))^2",
        )
        .given(&["e = 1"]),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
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
    Formalised {
        formal: "I = M r_G^2 with r_G > 0 fixed (so I -> oo with M), m, v0 > 0, any a. 'x ~ c/M' is certified as \
                 the exact finite limit M x -> c as M -> oo (equivalent for c != 0). Elastic (the paper's \
                 formulas): M omega -> 2 m a v0/r_G^2 and M (v + v0) -> 2 m v0 (1 + a^2/r_G^2). Restitution e \
                 (generic solver): v -> -e v0 and M omega -> (1+e) m a v0/r_G^2."
            .into(),
        reason: "exact limits as M -> oo of M omega, M (v + v0) and v, with I = M r_G^2".into(),
        decision: Decision::Proved(certs),
    }
}
