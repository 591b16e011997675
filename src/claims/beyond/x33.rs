use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X33",
    location: BEYOND,
    group: Group::Beyond,
    statement: "Stronge's energetic law never gains energy in one planar contact with Coulomb friction, whatever the slip does; neither does Poisson's law while the slip keeps its mode through the impact",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy, in pure algebra: the normal work of compression Wc <= 0, of
// restitution Wr, friction's Wf <= 0, and the energy change Wc + Wr + Wf.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::holds(
                "energetic: Wr = -e^2 Wc, so the energy change Wc + Wr + Wf <= 0",
                "Wc + Wr + Wf <= 0",
            )
            .given(&["Wr = -e^2*Wc"]),
            Check::holds(
                "Poisson with one slope k through the impact: Wc = -vn^2/(2k), Wr = k (e lam_c)^2/2 = -e^2 Wc",
                "Wr = -e^2*Wc",
            )
            .given(&["k > 0", "lc = vn/k", "Wc = -vn*lc + k*lc^2/2", "Wr = k*(e*lc)^2/2"]),
        ],
    )
    .at(&[])
    .given(&["vn > 0", "0 <= e", "e <= 1", "Wc <= 0", "Wf <= 0"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let e = sym("e");
    let s = sym("s");
    let e_of_s = k(2, 1) * &s / (one() + &sq(&s));
    let one_s2 = sum([pc(1, 1), PosExpr::Square(s.clone())]);
    // With Wc = -C, C >= 0 (u_n <= 0 throughout compression) and Wf = -F, F >= 0.
    let (c, f_loss) = (sym("C"), sym("F"));
    let energetic_change = -c.clone() + &(sq(&e) * &c) - &f_loss;
    let (vn, slope) = (sym("vn"), sym("k"));
    let lam_c = vn.clone() / &slope;
    let poisson_wc = -(vn.clone() * &lam_c) + &(slope.clone() * &sq(&lam_c) / &k(2, 1));
    let poisson_wr = slope.clone() * &sq(&(e.clone() * &lam_c)) / &k(2, 1);
    proved(
        "One contact between planar rigid bodies with Coulomb friction, followed in the normal \
         impulse lam as Routh's construction does. The kinetic energy changes by the work of the \
         contact impulse, the normal work Wc (compression, u_n <= 0 there so Wc = -C, C >= 0) plus \
         Wr (restitution) plus friction's work Wf = -F, F >= 0 (Coulomb's force opposes the slip; \
         these three facts are argued by hand, not machine-checked; the solver checks energy = work \
         exactly on every scene it answers). Stronge's law sets Wr = -e^2 Wc, so the change is \
         -(1 - e^2) C - F <= 0 for e in [0, 1]. Poisson's law with the slope k = du_n/dlam the same \
         through the impact (the slip keeps its mode, or W_nt = 0) gives Wr = -e^2 Wc too, hence \
         the same. Where the slip changes mode during the impact Poisson's normal work can be \
         positive (a steeper slope after the change); that case is not certified here, and an exact \
         search of 15,000 random rational scenes (tests/oracles/sweep_energy.py: tilted rods, box \
         corners, pinned rods) found no energy gain under Poisson's law, against 811 under \
         Newton's.",
        "the energetic law's energy change is -(1 - e^2) C - F <= 0, and Poisson's equals it while the slip keeps its mode",
        vec![
            positive(
                "Stronge: -(energy change) = (1 - e^2) C + F >= 0 for e in [0, 1] (e = 2s/(1+s^2))",
                -energetic_change,
                false,
                &[("e", e_of_s)],
                &[],
                &["s", "C", "F"],
                sum([
                    quot(
                        prod([PosExpr::Square((one() - &s) * &(one() + &s)), ps("C")]),
                        prod([one_s2.clone(), one_s2]),
                    ),
                    ps("F"),
                ]),
            ),
            id(
                "Poisson, one slope k: the restitution work k (e lam_c)^2/2 equals -e^2 times the compression work -vn lam_c + k lam_c^2/2, lam_c = vn/k",
                n("W_r", poisson_wr),
                -(sq(&e) * &poisson_wc),
            ),
            id(
                "the compression work with one slope is -vn^2/(2k) (so C = vn^2/(2k))",
                n("W_c", poisson_wc.clone()),
                -(sq(&vn) / &(k(2, 1) * &slope)),
            ),
        ],
    )
}
