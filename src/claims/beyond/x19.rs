use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X19",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Elastic, at a*: the projectile is at rest relative to the rod's centre, so half a turn later (t = pi a*/v0) the other arm hits it from behind at closing speed v0. A second impact is unavoidable",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[
        Check::holds("at a*: v = V = m v0/(M + m) and omega a* = v0 (the projectile rests relative to the rod's centre, which meets it again after half a turn with closing speed omega a* = v0)", "v_s = m*v0/(M + m) and V_s = m*v0/(M + m) and omega_s*s = v0"),
    ],
)
.at(&[StrikePoint { at: "s", tag: "s" }])
.given(&["s > 0", "s^2 = (M + m)*I/(m*M)"])
.partly("the kinematic step after the impact (the rod turns by pi in time pi a*/v0), argued by hand as in the certificate"));

fn formalise(paper: &Paper) -> Formalised {
    let after = motion(&free_rod(sym("I"), int(1)));
    let certs = vec![
        a_star_substitution_cert(paper),
        id_optimal_at_a(
            "elastic at a* (generic solver): v - V = 0, the projectile is at rest relative to the rod's centre",
            n("v", after.v.clone()) - &n("V", after.rod_v.clone()),
            int(0),
        ),
        id_optimal_at_a(
            "elastic at a*: v = m v0/(M + m)",
            n("v", after.v.clone()),
            f("m") * &f("v0") / &(f("M") + &f("m")),
        ),
        id_optimal_at_a(
            "elastic at a*: omega a* = v0, so half a turn takes t = pi/omega = pi a*/v0 and the arm at -a* arrives with speed omega a* = v0 relative to the centre",
            n("omega", after.omega.clone()) * &f("a"),
            f("v0"),
        ),
    ];
    Formalised {
        formal: "Elastic impact (e = 1) at a = a* <= l (so the impact at a* is possible: a point of the rod is \
                 there), m, M, I, v0 > 0. Certified algebra (generic solver, I = m M a^2/(M + m), which makes a \
                 the paper's a*): v = V = m v0/(M + m) and omega a* = v0. Kinematic argument (not machine-checked): \
                 after the impact no force acts, so the rod's centre moves uniformly with V and the rod turns \
                 uniformly at omega; in the centre's frame the projectile rests at (0, a*) while the rod's line \
                 rotates (the point at y moves with omega y along x). The line passes through (0, a*) again only \
                 when it has turned by pi, at t = pi/omega = pi a*/v0; then the material point that was at \
                 y = -a* (on the rod, since a* <= l) is at (0, a*) moving with velocity +omega a* = +v0 along x, \
                 i.e. it comes from the -x side (behind the projectile) and closes at speed v0 > 0. So the \
                 single-impulse model's outcome is followed by a second impact: unavoidable."
            .into(),
        reason: "at a* the solver gives v = V and omega a* = v0; a half turn then brings the other arm to the resting projectile at speed v0".into(),
        decision: Decision::Proved(certs),
    }
}
