use crate::claims::dsl::*;
use crate::field::ratfunc::Point;
use crate::field::{RatFn, Sym};

pub(super) const ENTRY: Entry = Entry {
    id: "C18",
    location: "case (iii)",
    group: Group::LimitingCases,
    statement: "M -> oo (I -> oo) gives v -> -v0, V -> 0, omega -> 0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Elastic),
    &[Check::holds(
        "bounds vanishing as M -> oo with r fixed: |v + v0| <= 2 v0 (m/M)(1 + a^2/r^2), |V| <= 2 m v0/M, |omega| <= 2 m |a| v0/(M r^2); hence v -> -v0, V -> 0, omega -> 0",
        "(v + v0)^2 <= (2*v0*(m/M)*(1 + a^2/r^2))^2 and V^2 <= (2*m*v0/M)^2 and omega^2 <= (2*m*a*v0/(M*r^2))^2",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    let gyration = |x: &RatFn| subs(x, &[("I", gyration_inertia())]);
    let solver = motion(&free_rod(gyration_inertia(), k(1, 1)));
    let mut certificates = heavy_rod_limits(
        "Eqs. (v), (V), (omega)",
        [
            gyration(&paper.v),
            gyration(&paper.big_v),
            gyration(&paper.omega),
        ],
    );
    certificates.extend(heavy_rod_limits(
        "generic solver (e = 1)",
        [solver.v, solver.rod_v, solver.omega],
    ));
    let (m, a, inertia) = (sym("m"), sym("a"), sym("I"));
    let m_a2 = m * &a * &a;
    certificates.push(Certificate::Limit(Limit {
        title: "why I -> oo matters: with I held fixed, Eq. (v) tends to -(I - m a^2)/(I + m a^2) v0, not -v0 (a rod pivoted at its centre)".into(),
        expr: paper.v.value().clone(),
        sym: Sym::new("M"),
        at: Point::Infinity,
        expected: Expected::Finite(
            -((inertia.clone() - &m_a2) / (inertia + &m_a2)) * &sym("v0"),
        ),
    }));
    Formalised {
        formal: "Elastic impact, m, v0 > 0, any a, and a rod of fixed shape: I = M r_G^2 with r_G > 0 \
                 fixed, so I -> oo with M (the paper's \"consequently\"). Then, as M -> oo, Eqs. (v), \
                 (V), (omega) and the generic solver give v -> -v0, V -> 0, omega -> 0: reflection \
                 as from a wall. The parenthesis is load-bearing: if I stayed fixed while M -> oo, \
                 v would tend to -(I - m a^2)/(I + m a^2) v0 and omega to 2 m a v0/(I + m a^2) (a \
                 rod pivoted at its centre). More generally v, V, omega depend on M and I only \
                 through m/M and m a^2/I and are continuous where both vanish, so any joint limit \
                 M, I -> oo gives the same result (argument by hand, not machine-checked)."
            .into(),
        reason: "with I = M r_G^2, the exact limits M -> oo of Eqs. (v), (V), (omega) and of the solver are -v0, 0, 0".into(),
        decision: Decision::Proved(certificates),
    }
}

/// The three limits M -> oo of (v, V, omega) = `values`, expected (-v0, 0, 0).
fn heavy_rod_limits(source: &str, values: [RatFn; 3]) -> Vec<Certificate> {
    let expected = [-sym("v0"), k(0, 1), k(0, 1)];
    ["v", "V", "omega"]
        .into_iter()
        .zip(values)
        .zip(expected)
        .map(|((name, value), target)| {
            Certificate::limit(
                format!("{source}: {name} -> {target} as M -> oo with I = M r_G^2 (r_G fixed)"),
                value,
                "M",
                Point::Infinity,
                target,
            )
        })
        .collect()
}
