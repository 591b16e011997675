use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C19",
    location: "§optimum ¶1",
    group: Group::Optimum,
    statement: "For b, c > 0, f(x) = x/(b^2 + c^2 x^2) has its unique maximum on x > 0 at x = b/c, with value 1/(2bc)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Elastic),
        &[
            Check::holds("f(b/c) = 1/(2bc)", "(b/c)/(b^2 + c^2*(b/c)^2) = 1/(2*b*c)"),
            Check::holds(
                "b/c is the unique maximiser of f on x >= 0",
                "x >= 0 and x != b/c => x/(b^2 + c^2*x^2) < 1/(2*b*c)",
            ),
        ],
    )
    .given(&["b > 0", "c > 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (b, c, x) = (sym("b"), sym("c"), sym("x"));
    let f = x.clone() / (sq(&b) + &(sq(&c) * &sq(&x)));
    let peak = Peak {
        name: "f",
        f: f.clone(),
        x: "x",
        peak_name: "b/c",
        b: "b",
        c: Some("c"),
        k: pc(1, 1),
        model: vec![],
        positive: vec![],
    };
    let value = Certificate::identity_at(
        "f(b/c) = 1/(2bc)",
        Formula::named("f", f.clone()),
        Formula::int(1) / &(Formula::int(2) * &b * &c),
        &[("x", b.clone() / c.clone())],
    );
    let mut certs = vec![value];
    certs.extend(peak.certificates());
    Formalised {
        formal: "For b, c > 0 and f(x) = x/(b^2 + c^2 x^2): f(b/c) = 1/(2bc); f(b/c) - f(x) = \
                 (c x - b)^2/(2bc(b^2 + c^2 x^2)) >= 0 for every real x; and f(b/c) - f(x) > 0 both for \
                 x = b/c + t and for 0 <= x = b/c - t (t > 0). So b/c is the unique maximiser on x >= 0, \
                 a fortiori on x > 0."
            .into(),
        reason: "f(b/c) - f(x) = (cx - b)^2/(2bc(b^2 + c^2x^2)), a square over a positive denominator, \
                 strictly positive off x = b/c"
            .into(),
        decision: Decision::Proved(certs),
    }
}
