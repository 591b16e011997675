use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "C2",
    location: "intro ¶2",
    group: Group::Introduction,
    statement: "a = 0 gives pure translation: omega = 0, V = 2m v0/(M+m) > 0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Free, ExportLaw::Elastic),
        &[
            Check::holds("pure translation and V", "omega = 0 and V = 2*m*v0/(M + m)"),
            Check::holds("V > 0", "V > 0"),
        ],
    )
    .given(&["a = 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let after = elastic();
    let at_centre = |x: &RatFn| subs(x, &[("a", k(0, 1))]);
    let big_v = at_centre(&after.rod_v);
    Formalised {
        formal: "Elastic impact (e = 1) at the centre (a = 0), any I > 0, m, M, v0 > 0: the generic \
                 solver gives omega = 0 (every rod point moves with V: pure translation) and \
                 V = 2 m v0/(M + m) > 0. (For restitution e the rod still only translates, with \
                 V = (1 + e) m v0/(M + m).)"
            .into(),
        reason: "at a = 0 the solver's omega is identically 0 and its V equals 2m v0/(M+m), visibly positive".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at(
                "omega at a = 0 (generic solver, e = 1) is 0",
                Formula::named("omega", after.omega),
                k(0, 1),
                &[("a", k(0, 1))],
            ),
            Certificate::identity_at(
                "V at a = 0 (generic solver, e = 1) equals 2 m v0/(M + m)",
                Formula::named("V", after.rod_v.clone()),
                Formula::int(2) * &f("m") * &f("v0") / &(f("M") + &f("m")),
                &[("a", k(0, 1))],
            ),
            positive("V at a = 0 is > 0", big_v, true, &[], &["m", "M", "v0"], &[], PosExpr::quotient(
                    prod([pc(2, 1), ps("m"), ps("v0")]),
                    PosExpr::sum([ps("M"), ps("m")]),
                )),
        ]),
    }
}
