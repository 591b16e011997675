use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C17",
    location: "case (ii)",
    group: Group::LimitingCases,
    statement: "a = 0 and m = M give v = 0, V = v0",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[Check::holds("a = 0, M = m: v = 0, V = v0", "v = 0 and V = v0").given(&["a = 0", "M = m"])],
));

fn formalise(paper: &Paper) -> Formalised {
    let head_on = [("a", k(0, 1)), ("M", sym("m"))];
    let after = elastic();
    let v0 = sym("v0");
    Formalised {
        formal: "Elastic impact (as the paper assumes), a = 0, M = m, any I > 0 and v0: Eqs. (v) and \
                 (V) give v = 0 and V = v0, and so does the generic solver: the head-on elastic \
                 collision of equal masses exchanges the velocities. (With restitution e the solver \
                 gives v = (1 - e) v0/2 instead: the exchange is the elastic case only.)"
            .into(),
        reason: "Eqs. (v), (V) and the solver's elastic v, V reduce identically to 0 and v0 at a = 0, M = m".into(),
        decision: Decision::Proved(vec![
            Certificate::identity_at("Eq. (v) at a = 0, M = m is 0", paper.v.clone(), k(0, 1), &head_on),
            Certificate::identity_at(
                "Eq. (V) at a = 0, M = m is v0",
                paper.big_v.clone(),
                v0.clone(),
                &head_on,
            ),
            Certificate::identity_at(
                "the generic solver's v (e = 1) at a = 0, M = m is 0",
                Formula::named("v", after.v),
                k(0, 1),
                &head_on,
            ),
            Certificate::identity_at(
                "the generic solver's V (e = 1) at a = 0, M = m is v0",
                Formula::named("V", after.rod_v),
                v0,
                &head_on,
            ),
        ]),
    }
}
