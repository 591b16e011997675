use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C1",
    location: "abstract",
    group: Group::Introduction,
    statement: "There exist masses for which the maximum of omega over [0,l] is not at a = l (witness M = m)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Uniform, ExportLaw::Elastic),
    &[
        Check::exists("a point a < l where omega exceeds omega(l): the witness M = m = l = v0 = 1, a = a* (a^2 = 2/3)", "0 <= a and a < l and omega > omega_l").given(&["m = 1", "M = 1", "l = 1", "v0 = 1", "a^2 = 2/3"]),
    ],
)
.at(&[StrikePoint { at: "a", tag: "" }, StrikePoint { at: "l", tag: "l" }])
.given(&["a >= 0"]));

fn formalise(_paper: &Paper) -> Formalised {
    Formalised {
        formal: "Uniform rod (I = M l^2/3), elastic impact (e = 1), omega from the generic solver: \
                 there are m, M, l, v0 > 0 and a point a in [0, l) with omega(a) > omega(l), so the \
                 maximum of omega over [0, l] is not attained at a = l. Witness: m = M = l = v0 = 1, \
                 a = sqrt(2/3) (evaluated exactly in Q(sqrt 6))."
            .into(),
        reason: "at M = m, omega(sqrt(2/3) l) = sqrt(6)/2 v0/l > omega(l) = 6/5 v0/l, exactly in Q(sqrt 6)".into(),
        decision: Decision::Proved(equal_masses_beat_the_end()),
    }
}
