use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X6",
    location: BEYOND,
    group: Group::Beyond,
    statement: "omega(a*) = (1+e) v0/(2a*) = (1+e)(v0/2) sqrt(mu/I); uniform rod: (1+e)(v0/2l) sqrt(3m/(M+m)); maximum on [0,l] is omega(min(a*, l))",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Restitution),
    &[
        Check::holds("omega(a*) = (1+e) v0/(2a*)", "omega_s = (1 + e)*v0/(2*s)"),
        Check::holds("omega(a*)^2 = ((1+e) v0/2)^2 mu/I", "omega_s^2 = ((1 + e)*v0/2)^2*(m*M/(M + m))/I"),
        Check::holds("the maximum on [0, l] is omega(min(a*, l))", "(s <= l and 0 <= a and a <= l => omega <= omega_s) and (s > l and 0 <= a and a <= l => omega <= omega_l)").given(&["l > 0"]),
        Check::holds("uniform rod: omega(a*) = (1+e)(v0/2l) sqrt(3m/(M+m))", "omega_s^2 = ((1 + e)*v0/(2*l))^2*3*m/(M + m)").given(&["I = M*l^2/3"]),
    ],
)
.at(&[StrikePoint { at: "a", tag: "" }, StrikePoint { at: "s", tag: "s" }, StrikePoint { at: "l", tag: "l" }])
.given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]));

fn formalise(paper: &Paper) -> Formalised {
    let half_kick = one_plus_e_f() * &f("v0") / &Formula::int(2);
    let omega = after(&sym("I"), sym("e")).omega;
    let uniform = after(&uniform_inertia(), sym("e")).omega;
    let mut certs = vec![
        id_at_star(
            paper,
            "omega_e (solver) at a = a* (I = A^2 mM/(M+m), a = A) = (1+e) v0/(2A)",
            n("omega_e", omega),
            half_kick.clone() / &f("A"),
        ),
        Certificate::identity_at(
            "((1+e) v0/(2a*))^2 = ((1+e) v0/2)^2 mu/I at I = A^2 mM/(M+m), so 1/a* = sqrt(mu/I)",
            (half_kick.clone() / &f("A")).pow(2),
            half_kick.pow(2) * &mu_f() / &f("I"),
            &[("I", inertia_of_a_star(paper))],
        ),
        id(
            "uniform rod: omega_e(a*)^2 (solver, a^2 = Eq. (maximal-a-homogeneous) squared) = ((1+e) v0/(2l))^2 3m/(M+m)",
            n(
                "omega_e(a*)^2",
                even_at(&sq(&uniform), &paper.a_star_uniform_squared),
            ),
            (half_kick / &f("l")).pow(2) * &Formula::int(3) * &f("m") / &(f("M") + &f("m")),
        ),
    ];
    certs.extend(omega_monotonicity(paper));
    proved(
        "For m, M, I, v0 > 0, e >= 0: the solver's omega_e at a = a* equals (1+e) v0/(2a*), whose \
         square is ((1+e) v0/2)^2 mu/I (both sides positive, so the square roots agree); for the \
         uniform rod (I = Ml^2/3) its square is ((1+e) v0/(2l))^2 3m/(M+m). omega_e increases \
         strictly on [0, a*) and decreases strictly on (a*, oo), so on [0, l] its maximum is at \
         min(a*, l).",
        "the solver's omega at a* is (1+e) v0/(2a*) identically, and omega rises up to a* and falls beyond it",
        certs,
    )
}
