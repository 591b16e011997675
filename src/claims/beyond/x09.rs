use crate::claims::dsl::*;
use crate::scene::{Motion, linear_momentum};

pub(super) const ENTRY: Entry = Entry {
    id: "X9",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Elastic, at a*: v = V = m v0/(M+m), the CM velocity of the system. The rotational KE is mu v0^2/2, all of the CM-frame energy, which is a fraction M/(M+m) of K0. König's theorem gives I omega^2/2 = mu v0^2/2 - [m(v - v_cm)^2 + M(V - v_cm)^2]/2, an energy proof that omega <= v0/a*",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Stated(Statement::new(
    Setting::new(Rod::Free, ExportLaw::Elastic),
    &[
        Check::holds("at a*: v = V = m v0/(M + m), the CM velocity", "v_s = m*v0/(M + m) and V_s = m*v0/(M + m)"),
        Check::holds("at a* the rotational energy is mu v0^2/2, a fraction M/(M+m) of K0", "I*omega_s^2 = (m*M/(M + m))*v0^2 and (m*M/(M + m))*v0^2 = M/(M + m)*(m*v0^2)"),
        Check::holds("König: I omega^2/2 = mu v0^2/2 - [m (v - v_cm)^2 + M (V - v_cm)^2]/2", "I*omega^2 = (m*M/(M + m))*v0^2 - (m*(v - m*v0/(M + m))^2 + M*(V - m*v0/(M + m))^2)"),
        Check::holds("hence omega <= v0/a* for a >= 0", "a >= 0 => omega <= v0/s"),
    ],
)
.at(&[StrikePoint { at: "a", tag: "" }, StrikePoint { at: "s", tag: "s" }])
.given(&["s > 0", "s^2 = (M + m)*I/(m*M)"]));

fn formalise(paper: &Paper) -> Formalised {
    let (m, big_m, i, v0) = (sym("m"), sym("M"), sym("I"), sym("v0"));
    let p = free_rod(i.clone(), k(1, 1));
    let el = motion(&p);
    let total = m.clone() + &big_m;
    let v_cm = linear_momentum(&p, &Motion::before(v0.clone())) / total.clone();
    let two = Formula::int(2);
    let v_cm_f = n("v_cm", v_cm.clone());
    let omega_f = n("omega", el.omega.clone());
    let cm_energy_f = mu_f() * &f("v0").pow(2) / &two;
    let bound_form = quot(
        sum([
            prod([ps("m"), PosExpr::Square(el.v.clone() - &v_cm)]),
            prod([ps("M"), PosExpr::Square(el.rod_v.clone() - &v_cm)]),
        ]),
        ps("I"),
    );
    proved(
        "e = 1, m, M, I, v0 > 0. At a = a* (I = A^2 mM/(M+m), a = A) the solver's v and V both equal \
         v_cm = (m v0)/(M+m) (total momentum over total mass), and I omega^2/2 = mu v0^2/2 = K0 - \
         (M+m) v_cm^2/2 = M/(M+m) K0. For every a, König's decomposition of the conserved energy \
         gives I omega^2/2 = mu v0^2/2 - [m(v - v_cm)^2 + M(V - v_cm)^2]/2, hence \
         v0^2/a*^2 - omega^2 = [m(v - v_cm)^2 + M(V - v_cm)^2]/I >= 0, i.e. |omega| <= v0/a*.",
        "at a* the solver gives v = V = v_cm, and König's identity bounds omega^2 by v0^2/a*^2 with a sum of squares",
        vec![
            id_at_star(
                paper,
                "v at a* (solver, e = 1) = v_cm",
                n("v", el.v.clone()),
                v_cm_f.clone(),
            ),
            id_at_star(
                paper,
                "V at a* (solver, e = 1) = v_cm",
                n("V", el.rod_v.clone()),
                v_cm_f.clone(),
            ),
            id(
                "v_cm = (total momentum)/(M + m) = m v0/(M+m)",
                v_cm_f.clone(),
                f("m") * &f("v0") / &(f("M") + &f("m")),
            ),
            id_at_star(
                paper,
                "rotational KE at a* (solver) = mu v0^2/2",
                f("I") * &omega_f.pow(2) / &two,
                cm_energy_f.clone(),
            ),
            id(
                "CM-frame energy K0 - (M+m) v_cm^2/2 = mu v0^2/2",
                k0_f() - &((f("M") + &f("m")) * &v_cm_f.pow(2) / &two),
                cm_energy_f.clone(),
            ),
            id(
                "(mu v0^2/2)/K0 = M/(M+m)",
                cm_energy_f.clone() / &k0_f(),
                f("M") / &(f("M") + &f("m")),
            ),
            id(
                "König, every a (solver, e = 1): I omega^2/2 = mu v0^2/2 - [m(v - v_cm)^2 + M(V - v_cm)^2]/2",
                f("I") * &omega_f.pow(2) / &two,
                cm_energy_f
                    - &((f("m") * &(n("v", el.v.clone()) - &v_cm_f).pow(2)
                        + &(f("M") * &(n("V", el.rod_v.clone()) - &v_cm_f).pow(2)))
                        / &two),
            ),
            positive(
                "v0^2/a*^2 - omega^2 >= 0 for every a (a*^2 = Eq. (maximal-a-general) squared)",
                sq(&v0) / paper.a_star_squared.clone() - &sq(&el.omega),
                false,
                &[],
                &["m", "M", "I"],
                &[],
                bound_form,
            ),
        ],
    )
}
