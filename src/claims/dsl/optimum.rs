//! Certificates and model quantities shared by the claims on the optimum and the totally
//! inelastic collision (C19-C31).

use super::*;
use crate::field::{RatFn, Sym};
use crate::scene::{Motion, angular_momentum, linear_momentum};

/// `I = A^2 m M/(M + m)`: the general rod written through A, a positive symbol for a*.
pub(crate) fn inertia_through_a_star() -> RatFn {
    let (m, big_m) = (sym("m"), sym("M"));
    sq(&sym("A")) * &m * &big_m / (big_m.clone() + &m)
}

/// The claim `printed = A^2` once the model is written through A: A is the paper's a*.
pub(crate) fn a_star_link(what: &str, printed: &Formula, model: (&str, RatFn)) -> Certificate {
    let (name, value) = model;
    Certificate::identity_at(
        format!("the printed {what} equals A^2 when {name} = {value}, so A is the paper's a*"),
        printed.clone(),
        Formula::sym("A").pow(2),
        &[(name, value.clone())],
    )
}

/// `2 v0 a/(a*^2 + a^2)`, the paper's shape of omega, for the given `a*^2`.
pub(crate) fn peak_shape(a_star_squared: Formula) -> Formula {
    let a = Formula::sym("a");
    Formula::int(2) * &Formula::sym("v0") * &a / &(a_star_squared + &a.pow(2))
}

/// The composite body of the sticking model, from first principles (rod centre at y = 0,
/// projectile stuck at y = a).
pub(crate) struct Sticking {
    /// The composite's centre of mass.
    pub(crate) y_c: RatFn,
    /// Its velocity: total momentum over total mass.
    pub(crate) v_c: RatFn,
    /// Moment of inertia about y_c (parallel axes).
    pub(crate) i_c: RatFn,
    /// Angular momentum about y_c (taken before the impact) over I_c.
    pub(crate) omega: RatFn,
}

/// The composite body of the sticking model for a rod of moment of inertia `inertia`.
pub(crate) fn sticking(inertia: RatFn) -> Sticking {
    let p = free_rod(inertia.clone(), k(0, 1));
    let (m, big_m, a) = (sym("m"), sym("M"), sym("a"));
    let total = big_m.clone() + &m;
    let y_c = m.clone() * &a / total.clone();
    let before = Motion::before(sym("v0"));
    let v_c = linear_momentum(&p, &before) / total;
    let i_c = inertia + &(big_m * &sq(&y_c)) + &(m * &sq(&(a - &y_c)));
    let omega = angular_momentum(&p, &before, &y_c) / i_c.clone();
    Sticking {
        y_c,
        v_c,
        i_c,
        omega,
    }
}

/// omega(a + t) - omega(a) > 0 for 0 <= a < a + t <= l when M = threshold m + q, q > 0, for
/// omega = scale m a v0/((M + m) l^2 + 3 m a^2) (scale 6 elastic, 3 sticking).
pub(crate) fn increasing_on_rod(
    paper: &Paper,
    omega: &RatFn,
    scale: i64,
    what: &str,
) -> Certificate {
    let (a, t, s) = (sym("a"), sym("t"), sym("s"));
    let expr = subs(omega, &[("a", a.clone() + &t)]) - omega;
    let l = sum([ps("a"), ps("t"), ps("s")]);
    let three_m = prod([pc(3, 1), ps("m")]);
    let slack = sum([
        prod([ps("t"), ps("t")]),
        prod([ps("s"), ps("s")]),
        prod([ps("a"), ps("t")]),
        prod([pc(2, 1), ps("a"), ps("s")]),
        prod([pc(2, 1), ps("t"), ps("s")]),
    ]);
    let denominator = |x: PosExpr| {
        sum([
            prod([sum([three_m.clone(), ps("q")]), l.clone(), l.clone()]),
            prod([three_m.clone(), x.clone(), x]),
        ])
    };
    let form = PosExpr::quotient(
        prod([
            pc(scale, 1),
            ps("m"),
            ps("v0"),
            ps("t"),
            sum([
                prod([three_m.clone(), slack]),
                prod([ps("q"), l.clone(), l.clone()]),
            ]),
        ]),
        prod([denominator(ps("a")), denominator(sum([ps("a"), ps("t")]))]),
    );
    positive(
        format!(
            "{what}: omega(a + t) - omega(a) > 0 for 0 <= a < a + t <= l (l = a + t + s, s >= 0) \
             when M = 2m + q, q > 0"
        ),
        expr,
        true,
        &[
            ("l", a + &t + &s),
            ("M", paper.threshold.value().clone() * &sym("m") + &sym("q")),
        ],
        &["m", "q", "t", "v0"],
        &["a", "s"],
        form,
    )
}

/// l^2 - a*^2 (uniform rod) for M <= 2m written as 2m = M + q, i.e. m = (M + q)/threshold:
/// it equals 2 q l^2/(3 (M + q)), >= 0 for q >= 0 and > 0 for q > 0 (`strict`).
pub(crate) fn room_at_the_end(paper: &Paper, strict: bool) -> Certificate {
    let expr = sq(&sym("l")) - &a_star_squared(&uniform_inertia());
    let m = (sym("M") + &sym("q")) / paper.threshold.clone();
    let form = PosExpr::quotient(
        prod([pc(2, 1), ps("q"), ps("l"), ps("l")]),
        prod([pc(3, 1), sum([ps("M"), ps("q")])]),
    );
    let (relation, q_sign, domain): (&str, &str, (&[&str], &[&str])) = if strict {
        ("> 0", "q > 0", (&["M", "l", "q"], &[]))
    } else {
        (">= 0", "q >= 0", (&["M", "l"], &["q"]))
    };
    positive(
        format!("l^2 - a*^2 {relation} when 2m = M + q, {q_sign} (uniform rod)"),
        expr,
        strict,
        &[("m", m.into())],
        domain.0,
        domain.1,
        form,
    )
}

/// `2 v0 (X - a^2)/(X + a^2)^2`: the slope of 2 v0 a/(X + a^2), which vanishes at a^2 = X.
pub(crate) fn slope_with_peak_at(x2: &RatFn) -> Formula {
    let a2 = Formula::sym("a").pow(2);
    Formula::int(2) * &Formula::sym("v0") * &(Formula::from(x2) - &a2)
        / &(Formula::from(x2) + &a2).pow(2)
}

/// d omega/da of the elastic uniform rod (generic solver) with M = `mass`.
pub(crate) fn uniform_slope(mass: &RatFn) -> RatFn {
    subs(&uniform_omega(), &[("M", mass.clone())]).derivative(Sym::new("a"))
}

/// The solver's slope at M = `mass` vanishes exactly at a^2 = `x2` (and changes sign there).
pub(crate) fn stationary_at(mass: &RatFn, mass_name: &str, x2: &RatFn) -> Certificate {
    Certificate::identity_at(
        format!(
            "at M = {mass_name}, d omega/da of the solver's omega (uniform rod) = \
             2 v0 ({x2} - a^2)/({x2} + a^2)^2: positive below, zero at, negative above a^2 = {x2}"
        ),
        Formula::named("omega'", uniform_slope(&sym("M"))),
        slope_with_peak_at(x2),
        &[("M", mass.clone())],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sticking omega is half the elastic one (C30), so the identity with the elastic omega
    /// itself must fail.
    #[test]
    fn the_sticking_omega_is_not_the_elastic_one() {
        let stuck = sticking(sym("I")).omega;
        let elastic = elastic_omega(sym("I"));
        assert!(
            Certificate::identity("", stuck.clone(), elastic.clone())
                .check()
                .is_err()
        );
        assert!(
            Certificate::identity("", stuck * &k(2, 1), elastic)
                .check()
                .is_ok()
        );
    }
}
