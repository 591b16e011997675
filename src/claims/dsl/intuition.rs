//! Certificates shared by the claims on why intuition fails (fixed axes, impulses) and on the
//! inhomogeneous rod (C32-C46).

use super::*;
use crate::field::{RatFn, Sym};

/// `x + y` for two symbols.
pub(crate) fn plus(x: &str, y: &str) -> PosExpr {
    sum([ps(x), ps(y)])
}

/// `x` at the impact point `a = value`.
pub(crate) fn at_a(x: &RatFn, value: RatFn) -> RatFn {
    subs(x, &[("a", value)])
}

/// omega of the free rod after the impact, from the generic solver, restitution e.
pub(crate) fn free_omega(inertia: RatFn) -> RatFn {
    motion(&free_rod(inertia, sym("e"))).omega
}

/// The impulse J = m (v0 - v) the projectile gives the free rod, from the generic solver.
pub(crate) fn free_impulse(inertia: RatFn) -> RatFn {
    let p = free_rod(inertia, sym("e"));
    solved(&p).impulse(&p)
}

/// J(a) - J(a + t) > 0 for a >= 0, t > 0: the solver's impulse falls as a grows (any I, any e).
pub(crate) fn impulse_decreasing() -> Certificate {
    let j = free_impulse(sym("I"));
    let expr = j.clone() - &at_a(&j, sym("a") + &sym("t"));
    // J = (1+e) v0 m M I/(MI + mI + mM a^2); the difference of the denominators is mM t(2a + t).
    let den = |x: PosExpr| {
        sum([
            prod([ps("M"), ps("I")]),
            prod([ps("m"), ps("I")]),
            prod([ps("m"), ps("M"), x.clone(), x]),
        ])
    };
    let form = quot(
        prod([
            one_plus_e(),
            ps("v0"),
            ps("m"),
            ps("m"),
            ps("M"),
            ps("M"),
            ps("I"),
            ps("t"),
            sum([prod([pc(2, 1), ps("a")]), ps("t")]),
        ]),
        prod([den(ps("a")), den(plus("a", "t"))]),
    );
    positive(
        "the impulse J(a) = m (v0 - v) from the solver falls strictly: J(a) - J(a + t) > 0 for a >= 0, t > 0 (any I, any e >= 0)",
        expr,
        true,
        &[],
        &["m", "M", "I", "v0", "t"],
        &["a", "e"],
        form,
    )
}

/// omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s, s > 0), omega from the solver with the
/// given inertia; `mass_subs`, `pos` and `nonneg` give the
/// mass domain.
pub(crate) fn end_beats_interior(
    title: &str,
    inertia: RatFn,
    mass_subs: &[(&str, RatFn)],
    pos: &[&str],
    nonneg: &[&str],
    form: PosExpr,
) -> Certificate {
    let omega = free_omega(inertia);
    let expr = at_a(&omega, sym("l")) - &omega;
    let mut substitutions = mass_subs.to_vec();
    substitutions.push(("l", sym("a") + &sym("s")));
    positive(title, expr, true, &substitutions, pos, nonneg, form)
}

/// a* >= l whenever M >= m (l^2/r_G^2 - 1): with l = r_G + u and
/// M = m u (2 r_G + u)/r_G^2 + q, the paper's a*^2 - l^2 = q r_G^2/m.
pub(crate) fn gyration_end_optimal(paper: &Paper) -> Certificate {
    let (m, rg, u) = (sym("m"), sym("r_G"), sym("u"));
    let big_m = m * &u * &(k(2, 1) * &rg + &u) / sq(&rg) + &sym("q");
    positive(
        "Eq. (maximal-a-gyration): a*^2 - l^2 >= 0 when M >= m (l^2/r_G^2 - 1) (l = r_G + u, M = m u (2 r_G + u)/r_G^2 + q; u, q >= 0)",
        paper.a_star_gyration_squared.clone() - &sq(&sym("l")),
        false,
        &[("l", rg.clone() + &u), ("M", big_m)],
        &["m", "r_G"],
        &["u", "q"],
        quot(prod([ps("q"), ps("r_G"), ps("r_G")]), ps("m")),
    )
}

/// a* < l whenever M < m (l^2/r_G^2 - 1), r_G < l: with l = r_G + u and
/// m = (M r_G^2 + q)/(u (2 r_G + u)), l^2 - a*^2 = q u (2 r_G + u)/(M r_G^2 + q).
pub(crate) fn gyration_interior_optimal(paper: &Paper) -> Certificate {
    let (big_m, rg, u) = (sym("M"), sym("r_G"), sym("u"));
    let two_r_u = k(2, 1) * &rg + &u;
    let m = (big_m * &sq(&rg) + &sym("q")) / (u.clone() * &two_r_u);
    let two_r_plus_u = sum([prod([pc(2, 1), ps("r_G")]), ps("u")]);
    positive(
        "Eq. (maximal-a-gyration): l^2 - a*^2 > 0 when M < m (l^2/r_G^2 - 1) (l = r_G + u, m = (M r_G^2 + q)/(u (2 r_G + u)); u, q > 0)",
        sq(&sym("l")) - &paper.a_star_gyration_squared,
        true,
        &[("l", rg + &u), ("m", m)],
        &["M", "r_G", "u", "q"],
        &[],
        quot(
            prod([ps("q"), ps("u"), two_r_plus_u]),
            sum([prod([ps("M"), ps("r_G"), ps("r_G")]), ps("q")]),
        ),
    )
}

/// Dumbbell (I = M l^2, r_G = l): a*^2 - l^2 = M l^2/m > 0 for all masses.
pub(crate) fn dumbbell_a_star(paper: &Paper) -> Certificate {
    let a_star_sq = subs(&paper.a_star_gyration_squared, &[("r_G", sym("l"))]);
    positive(
        "dumbbell (r_G = l): Eq. (maximal-a-gyration) gives a*^2 - l^2 = M l^2/m > 0 for all m, M > 0",
        a_star_sq - &sq(&sym("l")),
        true,
        &[],
        &["m", "M", "l"],
        &[],
        quot(prod([ps("M"), ps("l"), ps("l")]), ps("m")),
    )
}

/// Dumbbell: omega(l) - omega(a) > 0 for every 0 <= a < l and all masses.
pub(crate) fn dumbbell_end_wins() -> Certificate {
    let inertia = subs(&gyration_inertia(), &[("r_G", sym("l"))]);
    let l = plus("a", "s");
    let form = quot(
        prod([
            one_plus_e(),
            ps("v0"),
            ps("s"),
            ps("m"),
            sum([prod([ps("M"), l.clone()]), prod([ps("m"), ps("s")])]),
        ]),
        prod([
            sum([ps("M"), prod([pc(2, 1), ps("m")])]),
            l.clone(),
            sum([
                prod([plus("M", "m"), l.clone(), l]),
                prod([ps("m"), ps("a"), ps("a")]),
            ]),
        ]),
    );
    end_beats_interior(
        "dumbbell (I = M l^2): omega(l) - omega(a) > 0 for 0 <= a < l (l = a + s, s > 0), all m, M > 0, e >= 0; omega from the solver",
        inertia,
        &[],
        &["m", "M", "v0", "s"],
        &["a", "e"],
        form,
    )
}

/// `sum c_i y^i` over the named coefficients `(name, i)`.
pub(crate) fn density(coefficients: &[(&str, u32)]) -> RatFn {
    coefficients.iter().fold(RatFn::from(0), |acc, (c, i)| {
        acc + &(sym(c) * &pow(&sym("y"), *i))
    })
}

/// `integral_{-l}^{l} sum c_i y^i * y^power dy`, term by term: odd integrands give 0, even
/// ones 2 c_i l^(n+1)/(n+1) with n = i + power.
pub(crate) fn symmetric_moment(coefficients: &[(&str, u32)], power: u32) -> RatFn {
    coefficients
        .iter()
        .fold(RatFn::from(0), |acc, (c, i)| match (i + power) % 2 {
            0 => {
                let n = i + power + 1;
                acc + &(k(2, i64::from(n)) * &sym(c) * &pow(&sym("l"), n))
            }
            _ => acc,
        })
}

/// An integral certificate along the rod (variable `y`): `density * y^power` from `lower` to
/// `upper` equals `expected`.
pub(crate) fn integral(
    title: &str,
    density: RatFn,
    power: u32,
    (lower, upper): (RatFn, RatFn),
    expected: RatFn,
) -> Certificate {
    Certificate::Integral(Integral {
        title: title.into(),
        density,
        var: Sym::new("y"),
        power,
        lower,
        upper,
        expected,
    })
}

/// The limits of the whole rod, `-l` to `l`.
pub(crate) fn whole_rod() -> (RatFn, RatFn) {
    (-sym("l"), sym("l"))
}
