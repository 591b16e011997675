use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C35",
    location: "Eq. (impulse-linear)",
    group: Group::Intuition,
    statement: "I_lin = MV = 2m v0/(1 + m/M + 3ma^2/(Ml^2)) (uniform rod)",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Uniform, ExportLaw::Elastic),
    &[Check::holds(
        "Eq. (impulse-linear)",
        "M*V = 2*m*v0/(1 + m/M + 3*m*a^2/(M*l^2))",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    let p = free_rod(uniform_inertia(), one());
    let out = solved(&p);
    Formalised {
        formal: "Uniform rod (I = M l^2/3), elastic impact: the rod (at rest before) gains momentum \
                 ΔP = M V, which equals the impulse m (v0 - v) the projectile loses, and both equal \
                 Eq. (impulse-linear)."
            .into(),
        reason: "M V and m (v0 - v) from the solver both equal Eq. (impulse-linear) identically".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "M V from the solver (uniform rod, e = 1) equals Eq. (impulse-linear)",
                f("M") * &Formula::named("V", out.after.rod_v.clone()),
                paper.impulse_linear.clone(),
            ),
            Certificate::identity(
                "the projectile's loss of momentum m (v0 - v) (solver, uniform rod, e = 1) equals Eq. (impulse-linear)",
                f("m") * &(f("v0") - &Formula::named("v", out.after.v.clone())),
                paper.impulse_linear.clone(),
            ),
        ]),
    }
}
