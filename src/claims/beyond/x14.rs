use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X14",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The far end moves with V(1 - a l/r_G^2): it moves backwards iff a > r_G^2/l (uniform rod: a > l/3)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Gyration, ExportLaw::Restitution),
        &[
            Check::holds(
                "the far end moves with V (1 - a l/r_G^2)",
                "V - omega*l = V*(1 - a*l/r^2)",
            ),
            Check::holds(
                "backwards iff a > r_G^2/l",
                "(V - omega*l < 0 => a*l > r^2) and (a*l > r^2 => V - omega*l < 0)",
            ),
            Check::holds(
                "uniform rod: iff a > l/3",
                "(V - omega*l < 0 => a > l/3) and (a > l/3 => V - omega*l < 0)",
            )
            .given(&["3*r^2 = l^2"]),
        ],
    )
    .given(&["a > 0", "l > 0"]),
);

fn formalise(paper: &Paper) -> Formalised {
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
    Formalised {
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
