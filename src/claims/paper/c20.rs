use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C20",
    location: "Eq. (maximal-a-general)",
    group: Group::Optimum,
    statement: "omega = 2 v0 a/(a*^2 + a^2), so the unconstrained maximum over a > 0 is at a* = sqrt((M+m)I/(mM))",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Elastic),
        &[
            Check::holds("omega = 2 v0 a/(a*^2 + a^2)", "omega = 2*v0*a/(s^2 + a^2)"),
            Check::holds(
                "the maximum over a >= 0 is at a* and only there",
                "a >= 0 and a != s => omega < omega_s",
            ),
        ],
    )
    .at(&[
        StrikePoint { at: "a", tag: "" },
        StrikePoint { at: "s", tag: "s" },
    ])
    .given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]),
);

fn formalise(paper: &Paper) -> Formalised {
    let shape = peak_shape(Formula::named("a*^2", paper.a_star_squared.clone()));
    let rewritten = Certificate::identity(
        "Eq. (omega) as printed equals 2 v0 a/(a*^2 + a^2) with the printed a*^2 = (M + m) I/(m M)",
        paper.omega.clone(),
        shape,
    );
    let link = a_star_link(
        "a*^2 = (M + m) I/(m M)",
        &paper.a_star_squared,
        ("I", inertia_through_a_star()),
    );
    let peak = omega_peak(elastic_omega(sym("I")), prod([pc(2, 1), ps("v0")]));
    let mut certs = vec![rewritten, link];
    certs.extend(peak.certificates());
    Formalised {
        formal: "For m, M, I, v0 > 0: the printed Eq. (omega) equals 2 v0 a/(a*^2 + a^2) with the printed \
                 a*^2 = (M + m) I/(m M). Writing I = A^2 m M/(M + m) with A > 0 (every I > 0 is reached; \
                 the printed a*^2 is then A^2), the solver's elastic omega satisfies omega(A) - omega(a) = \
                 v0 (a - A)^2/(A (A^2 + a^2)) >= 0, strictly for every a >= 0 other than A: the maximum \
                 over a > 0 is at a = a* and nowhere else (C19 with b = a*, c = 1)."
            .into(),
        reason: "with I written through A = a*, omega(a*) - omega(a) = v0 (a - a*)^2/(a* (a*^2 + a^2)) > 0 \
                 for a != a*"
            .into(),
        decision: Decision::Proved(certs),
    }
}
