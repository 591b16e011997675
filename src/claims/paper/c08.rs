use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C8",
    location: "after Eq. (kinetic)",
    group: Group::Equations,
    statement: "\"v and V are the speeds\"; omega is a magnitude",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[
        Check::fails(
            "reading: v and V are speeds (>= 0); refuted at M = 3m, a = 0",
            "v >= 0 and V >= 0",
        )
        .given(&["m = 1", "M = 3", "I = 1", "a = 0", "v0 = 1"]),
        Check::holds("V > 0 always", "V > 0"),
        Check::holds("omega >= 0 for a >= 0", "a >= 0 => omega >= 0"),
    ],
));

fn formalise(paper: &Paper) -> Formalised {
    let after = elastic();
    let bounce = || {
        at(&[
            ("m", rational(1, 1)),
            ("M", rational(3, 1)),
            ("I", rational(1, 1)),
            ("a", rational(0, 1)),
            ("v0", rational(1, 1)),
        ])
    };
    Formalised {
        formal: "Natural reading: v >= 0 and V >= 0 are speeds. Refuted: at M = 3m, a = 0 (any I) \
                 the elastic solution has v = -v0/2 < 0, and the paper's own Eq. (v) gives a \
                 negative v there: the projectile bounces back. Correct statement: v and V are the \
                 x-components of the velocities (positive along v0), with V > 0 always, and the \
                 signed omega (docs/conventions.md) is >= 0 on the paper's domain 0 <= a <= l, so it equals \
                 its magnitude there."
            .into(),
        reason: "Eq. (v) is signed: at M = 3m, a = 0 it gives v = -v0/2 (the projectile bounces back); V > 0 and omega >= 0 for a >= 0".into(),
        decision: Decision::Qualified {
            qualification: "v and V are the signed x-velocity components (v < 0 when the projectile \
                            bounces back); V > 0 is a speed, and omega >= 0 for 0 <= a <= l is the \
                            magnitude of the angular velocity"
                .into(),
            counterexample: vec![
                Certificate::witness(
                    "M = 3m, a = 0: the solver's v is -v0/2 (the projectile bounces back)",
                    bounce(),
                    after.v.clone(),
                    Relation::Eq,
                    -(sym("v0") / k(2, 1)),
                ),
                Certificate::witness(
                    "M = 3m, a = 0: the paper's Eq. (v) itself gives v < 0, so v is not a speed",
                    bounce(),
                    paper.v.clone(),
                    Relation::Lt,
                    k(0, 1),
                ),
            ],
            proof: vec![
                positive("V > 0 (generic solver, e = 1): V = 2 m v0 I/(MI + mI + mMa^2)", after.rod_v, true, &[], &["m", "M", "I", "v0"], &[], PosExpr::quotient(
                        prod([pc(2, 1), ps("m"), ps("v0"), ps("I")]),
                        m_i_d_form(),
                    )),
                positive("omega >= 0 for a >= 0 (generic solver, e = 1): omega = 2 m M a v0/(MI + mI + mMa^2)", after.omega, false, &[], &["m", "M", "I", "v0"], &["a"], PosExpr::quotient(
                        prod([pc(2, 1), ps("m"), ps("M"), ps("a"), ps("v0")]),
                        m_i_d_form(),
                    )),
            ],
        },
    }
}
