use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C45",
    location: "§inhomogeneous",
    group: Group::Inhomogeneous,
    statement: "Intuition is fully vindicated only for the ideal dumbbell",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Gyration, ExportLaw::Elastic),
    &[
        Check::holds("every r_G < l has masses with an interior optimum: M = m (l^2 - r_G^2)/(2 r_G^2) gives a* < l and omega(a*) > omega(l)", "s < l and omega_s > omega_l").given(&["r < l", "M = m*(l^2 - r^2)/(2*r^2)"]),
        Check::holds("r_G = l (the dumbbell): a* > l for all masses", "s > l").given(&["r = l"]),
    ],
)
.at(&[StrikePoint { at: "s", tag: "s" }, StrikePoint { at: "l", tag: "l" }])
.given(&["l > 0", "s > 0", "s^2 = (M + m)*r^2/m"]));

fn formalise(paper: &Paper) -> Formalised {
    Formalised {
        formal: "Symmetric rod, I = M r_G^2 with 0 < r_G <= l. 'Fully vindicated': for all m, M > 0 the \
                 maximum of omega over [0, l] is at a = l. If r_G < l, the masses with \
                 M < m (l^2/r_G^2 - 1) (a nonempty range) give a* < l and then omega(a*) > omega(l): \
                 not vindicated. If r_G = l it is vindicated for all masses (C44). And r_G = l holds only \
                 when all the mass is at the ends, the ideal dumbbell (C40)."
            .into(),
        reason: "every r_G < l admits masses with a* < l and omega(a*) > omega(l); r_G = l (the dumbbell, C40) has the maximum at a = l for all masses".into(),
        decision: Decision::Proved(vec![
            gyration_interior_optimal(paper),
            optimum_beats_end(),
            dumbbell_a_star(paper),
            dumbbell_end_wins(),
        ]),
    }
}

/// Whenever a* < l, omega(a*) > omega(l): I parametrised by a* = w (I = m M w^2/(M + m)),
/// l = w + s; omega(w) - omega(l) = (1+e) v0 s^2/(2 w (w^2 + l^2)).
fn optimum_beats_end() -> Certificate {
    let (m, big_m, w) = (sym("m"), sym("M"), sym("w"));
    let inertia_of_w = m.clone() * &big_m * &sq(&w) / (big_m + &m);
    let omega = free_omega(sym("I"));
    let expr = at_a(&omega, w.clone()) - &at_a(&omega, sym("l"));
    let ws = plus("w", "s");
    positive(
        "omega(a*) - omega(l) > 0 whenever a* < l (I = m M a*^2/(M + m) with a* = w, l = w + s, s > 0; omega from the solver)",
        expr,
        true,
        &[("I", inertia_of_w), ("l", w + &sym("s"))],
        &["m", "M", "v0", "w", "s"],
        &["e"],
        quot(
            prod([one_plus_e(), ps("v0"), ps("s"), ps("s")]),
            prod([
                pc(2, 1),
                ps("w"),
                sum([prod([ps("w"), ps("w")]), prod([ws.clone(), ws])]),
            ]),
        ),
    )
}
