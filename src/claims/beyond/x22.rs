use crate::claims::dsl::*;
use crate::field::RatFn;
use crate::field::linear::solve_linear;
use crate::scene::Motion;

pub(super) const ENTRY: Entry = Entry {
    id: "X22",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Rod not symmetric: every formula holds with a replaced by a - c (c the CM offset; I taken about the CM)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Nothing, ExportLaw::Restitution),
    &[
        Check::holds("the solution is the symmetric rod's with a -> a - c", "v = v0 - (1 + e)*v0/(1/m + 1/M + (a - c)^2/I)/m and V = (1 + e)*v0/(1/m + 1/M + (a - c)^2/I)/M and omega = (1 + e)*v0*(a - c)/I/(1/m + 1/M + (a - c)^2/I)"),
        Check::fails("reading: every formula, e.g. the far end's velocity V (1 - a l/r_G^2) of X14, with a -> a - c; refuted at m = M = I = v0 = e = l = 1, a = 1, c = 1/2 (the far end is at -(l + c) from the CM)", "V - omega*(l + c) = V*(1 - (a - c)*l*M/I)").given(&["m = 1", "M = 1", "I = 1", "v0 = 1", "e = 1", "l = 1", "a = 1", "c = 1/2"]),
    ],
)
.at(&[])
.given(&["m > 0", "M > 0", "I > 0", "v0 > 0", "0 <= e", "e <= 1", "l > 0", "m*v + M*V = m*v0", "m*a*v + M*c*V + I*omega = m*a*v0", "V + omega*(a - c) - v = e*v0"]));

fn formalise(paper: &Paper) -> Formalised {
    let (a, c, l) = (sym("a"), sym("c"), sym("l"));
    let shifted = a.clone() - &c;
    let shift = [("a", shifted.clone())];
    let general = asymmetric_motion(sym("e"));
    let symmetric = motion(&free_rod(sym("I"), sym("e")));
    let elastic = asymmetric_motion(int(1));
    // The end at y = -l (geometric), i.e. at -(l + c) from the CM.
    let far_end = general.rod_v.clone() - &(general.omega.clone() * &(l.clone() + &c));
    let gyr = |x: &RatFn| subs(x, &[("I", gyration_inertia())]);
    let naive = gyr(&general.rod_v) * &(int(1) - &(shifted.clone() * &l / r2()));
    let instance = at(&[
        ("m", rational(1, 1)),
        ("M", rational(1, 1)),
        ("r_G", rational(1, 2)),
        ("l", rational(1, 1)),
        ("c", rational(1, 4)),
        ("a", rational(1, 1)),
        ("v0", rational(1, 1)),
        ("e", rational(1, 1)),
    ]);
    let counterexample = vec![Certificate::witness(
        "X14's far-end formula with only a -> a - c fails: two equal masses at y = -1/4 and 3/4 on a massless rod of half-length 1 (c = 1/4, r_G = 1/2), m = M, e = 1, end hit: true far-end velocity != V (1 - (a - c) l/r_G^2)",
        instance,
        gyr(&far_end),
        Relation::Ne,
        naive,
    )];
    let proof = vec![
        Certificate::identity(
            "v from the equations about the geometric centre (CM at c) = v of the symmetric solver at a - c (any e)",
            n("v_c", general.v.clone()),
            n("v", symmetric.v.clone()).subs(&shift),
        ),
        Certificate::identity(
            "V_cm from the equations about the geometric centre = V of the symmetric solver at a - c (any e)",
            n("V_c", general.rod_v.clone()),
            n("V", symmetric.rod_v.clone()).subs(&shift),
        ),
        Certificate::identity(
            "omega from the equations about the geometric centre = omega of the symmetric solver at a - c (any e)",
            n("omega_c", general.omega.clone()),
            n("omega", symmetric.omega.clone()).subs(&shift),
        ),
        Certificate::identity(
            "elastic: omega about the geometric centre = the paper's Eq. (omega) with a -> a - c",
            n("omega_c", elastic.omega),
            paper.omega.subs(&shift),
        ),
        Certificate::identity(
            "elastic: v = the paper's Eq. (v) with a -> a - c",
            n("v_c", elastic.v),
            paper.v.subs(&shift),
        ),
        Certificate::identity_at(
            "positions measured from the CM: the end at y = -l moves with V (1 - (a - c)(l + c)/r_G^2)",
            n("V_c", general.rod_v.clone())
                - &(n("omega_c", general.omega.clone()) * &(f("l") + &f("c"))),
            n("V_c", general.rod_v.clone())
                * &(Formula::int(1)
                    - &((f("a") - &f("c")) * &(f("l") + &f("c")) / &f("r_G").pow(2))),
            &[("I", gyration_inertia())],
        ),
    ];
    Formalised {
        formal: "Rod of half-length l whose CM is at y = c (geometric centre at 0), mass M, I about the CM, impact at \
                 y = a, restitution e. Independent equations: m v + M V = m v0; angular momentum about the fixed \
                 point at the geometric centre, m a v + M c V + I omega = m a v0 (V the CM's velocity); restitution \
                 V + omega (a - c) - v = e v0. Their solution equals the symmetric rod's solution with a -> a - c \
                 (so v, V, omega, J, D, the energies, and a* as a distance from the CM all carry over). The \
                 natural reading 'every formula' also covers formulas with other positions along the rod (the \
                 ends at +-l, the far end of X14, y0 of X13, the domain 0 <= a <= l): those need every position \
                 measured from the CM (the ends at l - c and -(l + c)), not just a -> a - c."
            .into(),
        reason: "the impulse system about the CM is the symmetric one at a - c, but formulas that involve the rod's ends need l shifted too".into(),
        decision: Decision::Qualified {
            qualification: "true for every formula in which the impact point is the only position (v, V of the CM, omega, J, D, energies, a* measured from the CM); positions such as the ends must also be measured from the CM (y -> y - c)".into(),
            counterexample,
            proof,
        },
    }
}

/// The impulse equations for a rod whose CM sits at y = c, angular momentum taken about the
/// geometric centre (y = 0), solved by the generic linear solver: (v, V_cm, omega).
fn asymmetric_motion(e: RatFn) -> Motion<RatFn> {
    let (m, big_m, inertia, a, c, v0) =
        (sym("m"), sym("M"), sym("I"), sym("a"), sym("c"), sym("v0"));
    let matrix = vec![
        vec![m.clone(), big_m.clone(), int(0)],
        vec![m.clone() * &a, big_m * &c, inertia],
        vec![int(-1), int(1), a.clone() - &c],
    ];
    let rhs = vec![m.clone() * &v0, m * &a * &v0, e * &v0];
    let x = solve_linear(matrix, rhs).expect("the asymmetric impulse system is nonsingular");
    Motion {
        v: x[0].clone(),
        rod_v: x[1].clone(),
        omega: x[2].clone(),
    }
}
