use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X34",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Newton's law with Coulomb friction never gains energy in one planar contact",
    formalise,
    export: EXPORT,
};

// The witness for z3 and SymPy: the contact matrix W = [a, b; b, c] and the velocity before
// (-vn, ut) of a tilted rod's end; the slip stops (at lam_s) and sticks, so Newton's law leaves
// the contact at (e vn, 0) and the impulse is W^-1 of the change; the energy change, the work
// of that impulse, P.(u_before + u_after)/2, is positive.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[Check::exists(
            "a tilted rod (length 2, mass 1, axis (3, 4)/5) landing on its end at 1 while sliding at 1 on a floor with mu = 1, e = 1: the slip stops before the impact ends, sticks, and the kinetic energy rises by 1/10",
            "lam_s < lf and mu*c >= b and dK = 1/10 and dK > 0",
        )
        .given(&[
            "a = 52/25",
            "b = 36/25",
            "c = 73/25",
            "vn = 1",
            "ut = -1",
            "e = 1",
            "mu = 1",
            "lam_s = -ut/(b + mu*c)",
            "lf = (c*(1 + e)*vn + b*ut)/(a*c - b^2)",
            "tf = (-b*(1 + e)*vn - a*ut)/(a*c - b^2)",
            "dK = (lf*(e - 1)*vn + tf*ut)/2",
        ])],
    )
    .at(&[]),
);

fn formalise(_paper: &Paper) -> Formalised {
    // The contact matrix of a free body of mass m, inertia I, struck at the arm (rx, ry) from
    // its centre along n = (0, 1): K = Id/m + r_perp r_perp^T/I, r_perp = (-ry, rx), t = (-1, 0).
    let (m, i, rx, ry) = (sym("m"), sym("I"), sym("rx"), sym("ry"));
    let a = one() / &m + &(sq(&rx) / &i);
    let b = rx.clone() * &ry / &i;
    let c = one() / &m + &(sq(&ry) / &i);
    let (vn, ut, e, mu) = (sym("vn"), sym("ut"), sym("e"), sym("mu"));
    // Sliding back (u_t < 0): du_t/dlam = b + mu c; the slip stops at lam_s = -ut/(b + mu c).
    let lam_s = -ut.clone() / &(b.clone() + &(mu.clone() * &c));
    // Sticking to the end, Newton's law leaves (e vn, 0): P = W^-1 ((1 + e) vn, -ut).
    let det = a.clone() * &c - &sq(&b);
    let lam_f = (c.clone() * &(one() + &e) * &vn + &(b.clone() * &ut)) / &det;
    let tau_f = (-(b.clone() * &(one() + &e) * &vn) - &(a.clone() * &ut)) / &det;
    let gain = (lam_f.clone() * &(e.clone() - &one()) * &vn + &(tau_f.clone() * &ut)) / &k(2, 1);
    let scene = at(&[
        ("m", rational(1, 1)),
        ("I", rational(1, 3)),
        ("rx", rational(-3, 5)),
        ("ry", rational(-4, 5)),
        ("vn", rational(1, 1)),
        ("ut", rational(-1, 1)),
        ("e", rational(1, 1)),
        ("mu", rational(1, 1)),
    ]);
    let witness = |title: &str, lhs: RatFn, relation: Relation, rhs: RatFn| {
        Certificate::witness(title, scene.clone(), lhs, relation, rhs)
    };
    Formalised {
        formal: "Natural reading: for every planar contact with Coulomb friction (mu >= 0) and \
                 every 0 <= e <= 1, Newton's law (the normal relative velocity after is -e times \
                 before), with the slip followed through the impact, leaves the kinetic energy no \
                 higher than before. Refuted by a uniform rod (length 2, mass 1, I = 1/3) tilted \
                 with axis (3, 4)/5, its lower end at the arm (-3/5, -4/5) from the centre on a \
                 floor (n = (0, 1)), falling at 1 and sliding at 1 (u = (-1, -1) in (n, t), \
                 t = (-1, 0)), mu = 1, e = 1: W = [52/25, 36/25; 36/25, 73/25]; the slip stops at \
                 lam_s = 25/109, sticking is possible (mu W_tt >= W_nt), so the contact leaves at \
                 (e vn, 0) and the impulse is W^-1 ((1 + e) vn, -ut) = (11/10, -1/5), after \
                 lam_s; the kinetic energy rises from 1 to 11/10. (examples/impacts/newton-gains-energy.toml; \
                 the independent oracle gives the same; Poisson's and Stronge's laws lose 25/146 and 25/218 \
                 in the same scene.)"
            .into(),
        reason: "a tilted rod landing on a rough floor gains exactly 1/10 of its kinetic energy under Newton's law once its slip stops and sticks".into(),
        decision: Decision::Refuted(vec![
            witness(
                "the contact matrix of the rod's end: W_nn = 1/m + rx^2/I = 52/25",
                a.clone(),
                Relation::Eq,
                k(52, 25),
            ),
            witness(
                "W_nt = rx ry/I = 36/25 (coupled) and W_tt = 73/25: sticking is possible, mu W_tt >= W_nt",
                mu.clone() * &c - &b,
                Relation::Ge,
                k(0, 1),
            ),
            witness(
                "the slip stops at lam_s = 25/109, before the impact ends at lam_f = 11/10",
                lam_s,
                Relation::Lt,
                lam_f.clone(),
            ),
            witness(
                "the impulse ends at lam_f = 11/10, tau_f = -1/5",
                lam_f * &k(10, 1) + &(tau_f * &k(5, 1)),
                Relation::Eq,
                k(10, 1),
            ),
            witness(
                "the kinetic energy change, the impulse's work P.(u_before + u_after)/2, is +1/10",
                gain,
                Relation::Eq,
                k(1, 10),
            ),
        ]),
    }
}
