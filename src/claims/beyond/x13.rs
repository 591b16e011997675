use crate::claims::dsl::*;
use crate::field::RatFn;
use num_traits::Zero;

pub(super) const ENTRY: Entry = Entry {
    id: "X13",
    location: BEYOND,
    group: Group::Beyond,
    statement: "The rod point momentarily at rest after the impact is at y0 = -r_G^2/a, whatever m, v0 and e are; a·|y0| = r_G^2 (centre-of-percussion conjugacy). Uniform rod: y0 is on the rod iff a >= l/3; an end hit gives y0 = -l/3",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Gyration, ExportLaw::Restitution),
        &[
            Check::holds(
                "the rod point y0 = -r_G^2/a is at rest after the impact",
                "V + omega*y0 = 0 and a*(-y0) = r^2",
            ),
            Check::holds(
                "uniform rod: y0 on the rod iff a >= l/3",
                "(-y0 <= l => a >= l/3) and (a >= l/3 => -y0 <= l)",
            )
            .given(&["3*r^2 = l^2", "l > 0"]),
            Check::holds("uniform rod hit at the end: y0 = -l/3", "y0 = -l/3").given(&[
                "3*r^2 = l^2",
                "l > 0",
                "a = l",
            ]),
        ],
    )
    .given(&["a > 0", "y0 = -r^2/a"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (a, l, e) = (sym("a"), sym("l"), sym("e"));
    let gyr = gyration_inertia();
    let mo = after(&gyr, e);
    let uniform = after(&uniform_inertia(), sym("e"));
    // The solver's rest point: V + omega y = 0.
    let y_rest = -(uniform.rod_v.clone() / uniform.omega.clone());
    let depth = -y_rest.clone();
    proved(
        "I = M r_G^2, m, M, r_G, v0 > 0, e >= 0, a > 0 (for a = 0 the rod only translates and no \
         point is at rest): the solver's velocity V + omega y of the rod point y vanishes at \
         y0 = -r_G^2/a, identically in m, v0, e; omega > 0, so this point is unique, and \
         a |y0| = r_G^2. Uniform rod (r_G^2 = l^2/3): with y0 = -V/omega from the solver, \
         l - |y0| >= 0 for a >= l/3 and |y0| - l > 0 for 0 < a < l/3; at a = l, y0 = -l/3.",
        "the solver's rod velocity vanishes at -r_G^2/a identically, and |y0| = l^2/(3a) for the uniform rod",
        vec![
            id(
                "velocity of the rod point y0 = -r_G^2/a (solver, I = M r_G^2, any m, v0, e) = 0",
                n("V", mo.rod_v.clone())
                    + &(n("omega", mo.omega.clone()) * &(-(f("r_G").pow(2) / &f("a")))),
                RatFn::zero(),
            ),
            positive(
                "omega > 0 for a > 0 (so the point at rest is unique)",
                mo.omega,
                true,
                &[],
                &["m", "M", "r_G", "v0", "a"],
                &["e"],
                quot(
                    prod([sum([pc(1, 1), ps("e")]), ps("v0"), ps("a"), ps("m")]),
                    sum([
                        prod([ps("M"), ps("r_G"), ps("r_G")]),
                        prod([ps("m"), ps("r_G"), ps("r_G")]),
                        prod([ps("m"), PosExpr::Square(a.clone())]),
                    ]),
                ),
            ),
            positive(
                "uniform rod: l - |y0| >= 0 for a >= l/3 (a = l/3 + s, s >= 0)",
                l.clone() - &depth,
                false,
                &[("a", l.clone() / k(3, 1) + &sym("s"))],
                &["l"],
                &["s"],
                quot(
                    prod([pc(3, 1), ps("l"), ps("s")]),
                    sum([ps("l"), prod([pc(3, 1), ps("s")])]),
                ),
            ),
            positive(
                "uniform rod: |y0| - l > 0 for 0 < a < l/3 (l = 3a + s, s > 0)",
                depth - &l,
                true,
                &[("l", k(3, 1) * &a + &sym("s"))],
                &["a", "s"],
                &[],
                quot(
                    prod([sum([prod([pc(3, 1), ps("a")]), ps("s")]), ps("s")]),
                    prod([pc(3, 1), ps("a")]),
                ),
            ),
            Certificate::identity_at(
                "uniform rod, end hit a = l: y0 = -V/omega (solver) = -l/3",
                -(n("V", uniform.rod_v.clone()) / &n("omega", uniform.omega.clone())),
                -(f("l") / &Formula::int(3)),
                &[("a", l.clone())],
            ),
        ],
    )
}
