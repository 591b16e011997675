use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C34",
    location: "§intuition ¶1",
    group: Group::Intuition,
    statement: "The impulse depends on a",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Uniform, ExportLaw::Elastic).impulses(),
        &[Check::exists(
            "the impulse differs between a = 0 and a = l (M = m = l = v0 = 1)",
            "J_1 != J_2",
        )
        .given(&["m = 1", "M = 1", "l = 1", "v0 = 1", "a1 = 0", "a2 = 1"])],
    )
    .at(&[
        StrikePoint { at: "a1", tag: "1" },
        StrikePoint { at: "a2", tag: "2" },
    ]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let inertia = sym("I");
    let one = Formula::int(1);
    let closed = (one.clone() + &f("e")) * &f("v0")
        / &(one.clone() / &f("m") + &(one / &f("M")) + &(f("a").pow(2) / &f("I")));
    Formalised {
        formal: "Free rod, any I, restitution e in [0, 1]: the impulse J(a) = m (v0 - v) delivered by the \
                 projectile is J(a) = (1+e) v0/(1/m + 1/M + a^2/I), strictly decreasing on a >= 0 (so it is \
                 not constant in a)."
            .into(),
        reason: "J(a) = (1+e) v0/(1/m + 1/M + a^2/I) from the solver, and J(a) - J(a + t) > 0 for a >= 0, t > 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "the solver's impulse m (v0 - v) equals (1+e) v0/(1/m + 1/M + a^2/I)",
                Formula::named("J", free_impulse(inertia)),
                closed,
            ),
            impulse_decreasing(),
        ]),
    }
}
