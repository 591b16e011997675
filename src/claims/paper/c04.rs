use crate::claims::dsl::*;
use crate::field::Sym;

pub(super) const ENTRY: Entry = Entry {
    id: "C4",
    location: "intro ¶2",
    group: Group::Introduction,
    statement: "A rod light compared with the projectile has its optimum at a < l",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic),
        &[Check::holds(
            "M < 2m: a* < l and omega(a*) > omega(l)",
            "s < l and omega_s > omega_l",
        )],
    )
    .at(&[
        StrikePoint { at: "s", tag: "s" },
        StrikePoint { at: "l", tag: "l" },
    ])
    .given(&["M < 2*m", "s > 0", "s^2 = (M + m)*l^2/(3*m)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    // "Light": M < 2m, parametrised as m = (M + q)/2 with M, q > 0.
    let light = || [("m", (sym("M") + &sym("q")) / k(2, 1))];
    let l = sym("l");
    let gap = l.clone() * &l - &paper.a_star_uniform_squared;
    // omega = 6 m a v0/((M + m) l^2 + 3 m a^2), so omega'(l) = 6 m v0 (M - 2m)/(l^2 (M + 4m)^2).
    let slope_at_end = subs(
        &uniform_omega().derivative(Sym::new("a")),
        &[("a", l.clone())],
    );
    let three_m_plus_two_q = PosExpr::sum([prod([pc(3, 1), ps("M")]), prod([pc(2, 1), ps("q")])]);
    Formalised {
        formal: "The paper's rod is homogeneous: I = M l^2/3, elastic impact. \"Light compared with \
                 the projectile\" is made precise as M < 2m (the paper's own threshold; it includes \
                 M < m and M << m), parametrised as m = (M + q)/2 with M, q > 0. Then (i) a* of Eq. \
                 (maximal-a-homogeneous) satisfies a*^2 < l^2, and (ii) the solver's omega has \
                 d omega/da < 0 at a = l, so the maximum of omega over [0, l] is not at the end but \
                 at some a < l (at a*, C27). For an inhomogeneous rod the threshold moves (a* < l \
                 iff M < m (l^2 - r_G^2)/r_G^2), and the ideal dumbbell never has a* < l (C43, C44)."
            .into(),
        reason: "with m = (M + q)/2, l^2 - a*^2 = 2 q l^2/(3(M + q)) > 0 and -omega'(l) = 3 q (M + q) v0/(l^2 (3M + 2q)^2) > 0".into(),
        decision: Decision::Proved(vec![
            positive("l^2 - a*^2 > 0 for M < 2m (a*^2 of Eq. (maximal-a-homogeneous), m = (M + q)/2)", gap, true, &light(), &["M", "q", "l"], &[], PosExpr::quotient(
                    prod([pc(2, 1), ps("q"), ps("l"), ps("l")]),
                    prod([pc(3, 1), PosExpr::sum([ps("M"), ps("q")])]),
                )),
            positive("-d omega/da at a = l is > 0 for M < 2m (uniform rod, solver's omega, m = (M + q)/2): omega decreases at the end", -slope_at_end, true, &light(), &["M", "q", "l", "v0"], &[], PosExpr::quotient(
                    prod([pc(3, 1), ps("q"), PosExpr::sum([ps("M"), ps("q")]), ps("v0")]),
                    prod([ps("l"), ps("l"), three_m_plus_two_q.clone(), three_m_plus_two_q]),
                )),
        ]),
    }
}
