use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X18",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Pivoted rod (fixed axis): omega = (1+e) m d v0/(I_p + m d^2), maximal at d* = sqrt(I_p/m) (inside a door iff M < 3m). The pivot impulse vanishes at d = I_p/(M h), the centre of percussion (2L/3 for a door)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Pivot, ExportLaw::Restitution).impulses(),
        &[
            Check::holds(
                "omega = (1+e) m d v0/(I_p + m d^2)",
                "omega = (1 + e)*m*d*v0/(Ip + m*d^2)",
            ),
            Check::holds(
                "the unique maximum over d >= 0 is at d* = sqrt(I_p/m)",
                "d >= 0 and d != ds => omega < omega_s",
            ),
            Check::holds(
                "door (I_p = M L^2/3): d* < L iff M < 3m",
                "(ds < L => M < 3*m) and (M < 3*m => ds < L)",
            )
            .given(&["L > 0", "Ip = M*L^2/3"]),
            Check::holds(
                "the pivot's impulse vanishes iff d = I_p/(M h), the centre of percussion",
                "(P = 0 => d*M*h = Ip) and (d*M*h = Ip => P = 0)",
            )
            .given(&["h > 0", "d > 0"]),
            Check::fails(
                "reading: a wrong centre of percussion, d = I_p/(2 M h), where the impulse would vanish; refuted",
                "2*d*M*h = Ip => P = 0",
            )
            .given(&["h > 0", "d > 0"]),
            Check::fails(
                "reading: the impulse vanishes only at d = I_p/(2 M h); refuted",
                "P = 0 => 2*d*M*h = Ip",
            )
            .given(&["h > 0", "d > 0"]),
            Check::holds("door: at 2L/3 from the hinge", "P = 0").given(&[
                "L > 0",
                "Ip = M*L^2/3",
                "h = L/2",
                "d = 2*L/3",
            ]),
        ],
    )
    .at(&[StrikePoint { at: "d", tag: "" }, StrikePoint { at: "ds", tag: "s" }])
    .given(&["ds > 0", "ds^2 = Ip/m"]),
);

fn formalise(paper: &Paper) -> Formalised {
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
    Formalised {
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
