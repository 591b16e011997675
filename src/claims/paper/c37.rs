use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C37",
    location: "Eq. (impulse-angular)",
    group: Group::Intuition,
    statement: "(Ml^2/3) omega = a ΔP = M a V",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Uniform, ExportLaw::Elastic),
    &[Check::holds(
        "Eq. (impulse-angular)",
        "(M*l^2/3)*omega = a*M*V",
    )],
));

fn formalise(paper: &Paper) -> Formalised {
    let general = motion(&free_rod(uniform_inertia(), sym("e")));
    let elastic = motion(&free_rod(uniform_inertia(), one()));
    let a = f("a");
    Formalised {
        formal: "Uniform rod: the angular impulse about the rod's centre, I omega with I = M l^2/3, equals \
                 a times the linear impulse ΔP = M V (for any restitution e), and for e = 1 equals \
                 a I_lin with I_lin from Eq. (impulse-linear)."
            .into(),
        reason: "Eq. (inertia-homogeneous) times the solver's omega equals a M V identically (any e), and a I_lin for e = 1".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "Eq. (inertia-homogeneous) I times the solver's omega equals M a V (any e)",
                paper.uniform_inertia.clone() * &Formula::named("omega", general.omega),
                f("M") * &a * &Formula::named("V", general.rod_v),
            ),
            Certificate::identity(
                "Eq. (inertia-homogeneous) I times the solver's omega (e = 1) equals a I_lin of Eq. (impulse-linear)",
                paper.uniform_inertia.clone() * &Formula::named("omega", elastic.omega),
                a * &paper.impulse_linear,
            ),
        ]),
    }
}
