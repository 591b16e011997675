use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "X37",
    location: BEYOND,
    group: Group::Beyond,
    statement: "A frictionless w x h box (h^2 < 2 w^2) falling flat at v > 0 onto both bottom corners while spinning at omega > 0, 0 <= e <= 1: under simultaneous Newton and Poisson the rising corner takes no impulse exactly when omega >= omega_s = (2v/w) ((6 + 2e) w^2 - e h^2)/((2 - 2e) w^2 + (2 + e) h^2), a threshold above the kinematic 2v/w at which that corner starts to rise; for the 2 x 1 box falling at 1 with e = 1/2, omega_s = 55/13",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy, in pure algebra: c = omega w/2 (the corners' speed from the
// spin), w2 = w^2, h2 = h^2; a = W_11 = W_22, b = W_12; the one-corner impulse l1.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::holds(
                "the rising corner moving up (c >= v): after the leading corner's impulse it leaves (Newton's condition) iff c >= cs",
                "(c - v + b*l1 >= 0 => c >= cs) and (c >= cs => c - v + b*l1 >= 0)",
            )
            .given(&["c >= v"]),
            Check::holds(
                "the rising corner still approaching (c < v): Newton's condition fails, so that corner pushes",
                "(1 + e)*(c - v) + b*l1 < 0",
            )
            .given(&["c < v"]),
            Check::holds(
                "the threshold is above the kinematic one (c = v)",
                "cs > v",
            ),
            Check::holds(
                "Poisson's compression condition (e = 0) is weaker than Newton's",
                "v*6*w2/(2*w2 + 2*h2) <= cs",
            ),
            Check::holds("the 2 x 1 box at v = 1, e = 1/2: omega_s = cs = 55/13", "cs = 55/13")
                .given(&["w2 = 4", "h2 = 1", "v = 1", "e = 1/2"]),
        ],
    )
    .at(&[])
    .given(&[
        "m > 0",
        "v > 0",
        "c > 0",
        "w2 > 0",
        "h2 > 0",
        "h2 < 2*w2",
        "0 <= e",
        "e <= 1",
        "a = (4*w2 + h2)/(m*(w2 + h2))",
        "b = (h2 - 2*w2)/(m*(w2 + h2))",
        "l1 = (1 + e)*(v + c)/a",
        "cs = v*((6 + 2*e)*w2 - e*h2)/((2 - 2*e)*w2 + (2 + e)*h2)",
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (m, v, c, e) = (sym("m"), sym("v"), sym("c"), sym("e"));
    let (w2, h2) = (sym("w2"), sym("h2"));
    let inertia = m.clone() * &(w2.clone() + &h2) / &k(12, 1);
    let arm = w2.clone() / &k(4, 1);
    let a = one() / &m + &(arm.clone() / &inertia);
    let b = one() / &m - &(arm / &inertia);
    let lam1 = (one() + &e) * &(v.clone() + &c) / &a;
    let numerator = (k(6, 1) + &(k(2, 1) * &e)) * &w2 - &(e.clone() * &h2);
    let denominator = (k(2, 1) - &(k(2, 1) * &e)) * &w2 + &((k(2, 1) + &e) * &h2);
    let threshold = |e: &RatFn| {
        v.clone() * &((k(6, 1) + &(k(2, 1) * e)) * &w2 - &(e.clone() * &h2))
            / &((k(2, 1) - &(k(2, 1) * e)) * &w2 + &((k(2, 1) + e) * &h2))
    };
    let c_s = threshold(&e);
    let rising_after = c.clone() - &v + &(b.clone() * &lam1);
    let approaching_after = (one() + &e) * &(c.clone() - &v) + &(b.clone() * &lam1);
    // e in [0, 1] as s/(s + t) (s >= 0, t > 0); a wide box h^2 = 2 w^2 r/(1 + r) (r > 0).
    let (s, t, r, p) = (sym("s"), sym("t"), sym("r"), sym("p"));
    let e_in_0_1 = ("e", s.clone() / &(s.clone() + &t));
    let wide = ("h2", k(2, 1) * &w2 * &r / &(one() + &r));
    let three = |x: PosExpr, y: PosExpr| prod([pc(3, 1), x, y]);
    let t_3tr_3sr = sum([ps("t"), three(ps("t"), ps("r")), three(ps("s"), ps("r"))]);
    let one_3r = sum([pc(1, 1), prod([pc(3, 1), ps("r")])]);
    let at_scene = |x: &RatFn| {
        subs(
            x,
            &[
                ("w2", k(4, 1)),
                ("h2", k(1, 1)),
                ("v", k(1, 1)),
                ("e", k(1, 2)),
            ],
        )
    };
    proved(
        "A uniform box of width w and height h (h^2 < 2 w^2), mass m, inertia I = m (w^2 + h^2)/12, \
         falls at v > 0 with both bottom corners on a fixed floor, spinning counterclockwise at \
         omega > 0, frictionless, the same 0 <= e <= 1 at both corners. With c = omega w/2 the \
         leading (left) corner approaches at u1 = -(v + c) and the other moves at u2 = c - v. The \
         Delassus matrix has W_11 = W_22 = a = 1/m + (w/2)^2/I and W_12 = b = 1/m - (w/2)^2/I < 0 \
         (a push at one corner drives the other down). W is positive definite, so simultaneous \
         Newton has one answer; the rising corner takes none (lam_2 = 0) iff the one-corner \
         impulse lam_1 = (1 + e)(v + c)/a leaves Newton's condition at corner 2 satisfied: \
         u2 + b lam_1 + e min(u2, 0) >= 0. If c < v that quantity is negative (certificate), so \
         corner 2 pushes. If c >= v it is D (c - c_s)/(4 w^2 + h^2) with D > 0, so it holds iff \
         c >= c_s, i.e. omega >= omega_s = 2 c_s/w; and c_s > v. Simultaneous Poisson (a step argued by \
         hand from its definition, not machine-checked): lam_2 = 0 needs the compression problem (Newton's with e = 0) \
         to leave corner 2 alone, c >= c_s(0), and the expansion's e lam_C1 to keep it from \
         sinking, c >= c_s(e); c_s(e) >= c_s(0) for a wide box (certificate), so Poisson's \
         threshold is Newton's. Past it sequential impacts (corner 2 rises, so only corner 1 \
         fires, once) and projected Gauss-Seidel at every K (sweep 1 is the one-corner impulse, \
         sweep 2 changes nothing) give the same one-corner answer; rodimpact's solvers and the \
         independent oracle agree on the scenes box-lands-flat-spinning (omega = 5) and \
         box-lands-flat-spin-window (omega = 3).",
        "after the leading corner's impulse the rising corner moves at D (c - c_s)/(4 w^2 + h^2) with D > 0, and it is pushed down whenever it still approached",
        vec![
            id(
                "W_11 = 1/m + (w/2)^2/I with I = m (w^2 + h^2)/12",
                n("a", a.clone()),
                (k(4, 1) * &w2 + &h2) / &(m.clone() * &(w2.clone() + &h2)),
            ),
            id(
                "W_12 = 1/m - (w/2)^2/I",
                n("b", b.clone()),
                (h2.clone() - &(k(2, 1) * &w2)) / &(m.clone() * &(w2.clone() + &h2)),
            ),
            id(
                "c >= v: corner 2 after the one-corner impulse, u2 + b lam_1 = D (c - c_s)/(4 w^2 + h^2)",
                n("u2+", rising_after),
                denominator.clone() * &(c.clone() - &c_s) / &(k(4, 1) * &w2 + &h2),
            ),
            id(
                "c_s = v N/D",
                n("c_s", c_s.clone()),
                v.clone() * &numerator / &denominator,
            ),
            positive(
                "D = (2 - 2e) w^2 + (2 + e) h^2 > 0 for e in [0, 1] (e = s/(s + t))",
                denominator.clone(),
                true,
                std::slice::from_ref(&e_in_0_1),
                &["t", "w2", "h2"],
                &["s"],
                quot(
                    sum([
                        prod([pc(2, 1), ps("t"), ps("w2")]),
                        prod([
                            sum([prod([pc(3, 1), ps("s")]), prod([pc(2, 1), ps("t")])]),
                            ps("h2"),
                        ]),
                    ]),
                    sum([ps("s"), ps("t")]),
                ),
            ),
            positive(
                "c < v (c = v - p): corner 2's Newton velocity after the one-corner impulse, negated, is > 0 for a wide box (h^2 = 2 w^2 r/(1 + r))",
                -subs(&approaching_after, &[("c", v.clone() - &p)]),
                true,
                std::slice::from_ref(&wide),
                &["v", "r", "p", "m", "w2"],
                &["e"],
                quot(
                    prod([
                        pc(2, 1),
                        sum([pc(1, 1), ps("e")]),
                        sum([prod([pc(2, 1), ps("v")]), prod([one_3r.clone(), ps("p")])]),
                    ]),
                    sum([pc(4, 1), prod([pc(6, 1), ps("r")])]),
                ),
            ),
            positive(
                "c_s - v > 0 for a wide box: the threshold lies above the kinematic c = v",
                c_s.clone() - &v,
                true,
                &[e_in_0_1.clone(), wide.clone()],
                &["v", "t", "r", "w2"],
                &["s"],
                quot(
                    prod([pc(2, 1), ps("v"), sum([prod([pc(2, 1), ps("s")]), ps("t")])]),
                    t_3tr_3sr.clone(),
                ),
            ),
            positive(
                "c_s(e) - c_s(0) >= 0 for a wide box: Poisson's compression condition is implied by the expansion's",
                c_s.clone() - &threshold(&k(0, 1)),
                false,
                &[e_in_0_1, wide],
                &["v", "t", "r", "w2"],
                &["s"],
                quot(
                    prod([ps("v"), ps("s"), sum([pc(4, 1), prod([pc(6, 1), ps("r")])])]),
                    prod([t_3tr_3sr, one_3r]),
                ),
            ),
            id(
                "the 2 x 1 box at v = 1, e = 1/2: omega_s = 2 c_s/w = c_s = 55/13",
                n("omega_s", at_scene(&c_s)),
                k(55, 13),
            ),
        ],
    )
}
