use crate::claims::dsl::*;
use crate::field::RatFn;

pub(super) const ENTRY: Entry = Entry {
    id: "C7",
    location: "Eq. (kinetic)",
    group: Group::Equations,
    statement: "Kinetic energy is conserved",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[
        Check::holds(
            "e = 1: kinetic energy conserved",
            "m*v0^2 = m*v^2 + M*V^2 + I*omega^2",
        )
        .given(&["e = 1"]),
        Check::holds(
            "e < 1: kinetic energy strictly lost",
            "m*v^2 + M*V^2 + I*omega^2 < m*v0^2",
        )
        .given(&["e < 1"]),
    ],
));

fn formalise(_paper: &Paper) -> Formalised {
    let lost = |e: RatFn| solved(&rod(e)).energy.lost();
    // 0 <= e < 1 parametrised as e = s/(s + t) with s >= 0, t > 0.
    let inelastic = [("e", sym("s") / (sym("s") + &sym("t")))];
    let s_plus_t = PosExpr::sum([ps("s"), ps("t")]);
    Formalised {
        formal: "Eq. (kinetic) is the paper's hypothesis that the collision is elastic. Modelled \
                 by Newton's restitution law at the contact, it holds exactly for e = 1: the kinetic \
                 energy after the impact equals m v0^2/2 for all m, M, I > 0, a, v0. For every \
                 0 <= e < 1 (v0 != 0) energy is strictly lost, so conservation is exactly the elastic \
                 case, not a consequence of the momentum laws."
            .into(),
        reason: "for e = 1 the solver's kinetic energy after the impact is m v0^2/2 identically; for 0 <= e < 1 it is (1 - e^2) m M I v0^2/(2(MI + mI + mMa^2)) > 0".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "kinetic energy after the impact (generic solver, e = 1) equals m v0^2/2",
                Formula::named("K_after", solved(&rod(k(1, 1))).energy.after),
                f("m") * &f("v0").pow(2) / &Formula::int(2),
            ),
            positive("energy lost for 0 <= e < 1 (e = s/(s + t), s >= 0, t > 0) is > 0: conservation singles out e = 1", lost(sym("e")), true, &inelastic, &["t", "m", "M", "I", "v0"], &["s"], PosExpr::quotient(
                    prod([
                        ps("t"),
                        PosExpr::sum([prod([pc(2, 1), ps("s")]), ps("t")]),
                        ps("m"),
                        ps("M"),
                        ps("I"),
                        ps("v0"),
                        ps("v0"),
                    ]),
                    prod([pc(2, 1), s_plus_t.clone(), s_plus_t, m_i_d_form()]),
                )),
        ]),
    }
}
