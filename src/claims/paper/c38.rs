use crate::claims::dsl::*;
use crate::field::{QSqrt, Sym};

pub(super) const ENTRY: Entry = Entry {
    id: "C38",
    location: "after (impulse-angular)",
    group: Group::Intuition,
    statement: "A competition between increasing a and decreasing V",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Restitution),
        &[Check::holds(
            "I omega = a (M V) with M V > 0 strictly decreasing on a >= 0",
            "I*omega = a*M*V and M*V > 0 and (0 <= a1 and a1 < a2 => M*V_2 < M*V_1)",
        )],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let after = motion(&free_rod(sym("I"), sym("e")));
    let uniform = free_omega(uniform_inertia());
    let slope = uniform.derivative(Sym::new("a"));
    let at_m_equal_big_m = |a: QSqrt| {
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(1, 1)),
            ("l", rational(1, 1)),
            ("v0", rational(1, 1)),
            ("e", rational(1, 1)),
            ("a", a),
        ])
    };
    Formalised {
        formal: "Free rod, any I and e in [0, 1]: I omega = a M V(a) with M V(a) = J(a) > 0 strictly \
                 decreasing on a >= 0, so omega is the product of the increasing a and the decreasing J. \
                 Neither factor wins everywhere: for a uniform rod with M = m, d omega/da > 0 at a = 0 \
                 and < 0 at a = l."
            .into(),
        reason: "I omega = a M V identically, M V = J(a) falls strictly, and d omega/da changes sign on [0, l] (uniform rod, M = m)".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "I omega = a M V for the solver's velocities (any I, any e)",
                f("I") * &Formula::named("omega", after.omega.clone()),
                f("a") * &f("M") * &Formula::named("V", after.rod_v.clone()),
            ),
            impulse_decreasing(),
            Certificate::witness(
                "uniform rod, M = m, e = 1: at a = 0 the growing arm wins (d omega/da > 0)",
                at_m_equal_big_m(rational(0, 1)),
                slope.clone(),
                Relation::Gt,
                k(0, 1),
            ),
            Certificate::witness(
                "uniform rod, M = m, e = 1: at a = l the falling impulse wins (d omega/da < 0)",
                at_m_equal_big_m(rational(1, 1)),
                slope,
                Relation::Lt,
                k(0, 1),
            ),
        ]),
    }
}
