use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::solve::fast::linear::impulse_equations;

pub(super) const ENTRY: Entry = Entry {
    id: "X1",
    location: BEYOND,
    group: Group::Beyond,
    statement: "General restitution e in [0,1] (Newton's law at the contact): the solution is unique (det = -(mI + MI + Mma^2)), with J = (1+e) v0/(1/m + 1/M + a^2/I), v = v0 - J/m, V = J/M, omega = J a/I",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution).impulses(),
        &[
            Check::holds(
                "the impulse and the velocities",
                "J = (1 + e)*v0/(1/m + 1/M + a^2/I) and v = v0 - J/m and V = J/M and omega = J*a/I",
            ),
            Check::holds(
                "the solution is unique: two solutions of the same equations agree",
                "v = v_2 and V = V_2 and omega = omega_2 and J = J_2",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "a", tag: "2" },
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let i = sym("I");
    let p = free_rod(i.clone(), sym("e"));
    let (matrix, _) = impulse_equations(&p);
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    let gram = m.clone() * &i + &(big_m.clone() * &i) + &(big_m.clone() * &m * &sq(&a));
    let mo = motion(&p);
    let j = n("J", one_plus_e_f() * &f("v0") * &m_eff_f(&i));
    let gram_f = f("m") * &f("I") + &(f("M") * &f("I")) + &(f("M") * &f("m") * &f("a").pow(2));
    proved(
        "For m, M, I > 0, any a, v0 and any e (in particular e in [0,1]): the impulse equations \
         (linear momentum, angular momentum about the rod's centre, Newton's restitution \
         (V + omega a) - v = e v0) form a 3x3 linear system in (v, V, omega) whose determinant is \
         -(m I + M I + M m a^2) < 0, so the solution exists and is unique; the solver's solution \
         satisfies J := m (v0 - v) = (1+e) v0/(1/m + 1/M + a^2/I), V = J/M, omega = J a/I.",
        "the determinant of the solver's matrix is -(mI + MI + Mma^2), visibly nonzero, and the solution matches the closed forms identically",
        vec![
            id(
                "determinant of the impulse-equation matrix (solve::impulse_equations) = -(mI + MI + Mma^2)",
                n("det", det3(&matrix)),
                -gram_f,
            ),
            positive(
                "mI + MI + Mma^2 > 0 for m, M, I > 0 and any a",
                gram,
                true,
                &[],
                &["m", "M", "I"],
                &[],
                sum([
                    prod([ps("m"), ps("I")]),
                    prod([ps("M"), ps("I")]),
                    prod([ps("M"), ps("m"), PosExpr::Square(a.clone())]),
                ]),
            ),
            id(
                "J = m (v0 - v) from the solver = (1+e) v0/(1/m + 1/M + a^2/I)",
                f("m") * &(f("v0") - &n("v", mo.v.clone())),
                j.clone(),
            ),
            id(
                "v from the solver = v0 - J/m",
                n("v", mo.v),
                f("v0") - &(j.clone() / &f("m")),
            ),
            id(
                "V from the solver = J/M",
                n("V", mo.rod_v),
                j.clone() / &f("M"),
            ),
            id(
                "omega from the solver = J a/I",
                n("omega", mo.omega),
                j * &f("a") / &f("I"),
            ),
        ],
    )
}

/// 3x3 determinant by cofactors.
fn det3(m: &[Vec<RatFn>]) -> RatFn {
    let minor = |r1: usize, r2: usize, c1: usize, c2: usize| {
        m[r1][c1].clone() * &m[r2][c2] - &(m[r1][c2].clone() * &m[r2][c1])
    };
    m[0][0].clone() * &minor(1, 2, 1, 2) - &(m[0][1].clone() * &minor(1, 2, 0, 2))
        + &(m[0][2].clone() * &minor(1, 2, 0, 1))
}
