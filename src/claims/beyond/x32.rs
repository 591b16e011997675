use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "X32",
    location: BEYOND,
    group: Group::Beyond,
    statement: "One planar contact whose contact matrix W is diagonal (W_nt = 0: every scene of the paper's family): Newton's, Poisson's and Stronge's energetic laws end the impact at the same normal impulse lam_f = (1 + e) v_n/W_nn, and no law gains energy; the normal impulse's work is -(1 - e^2) v_n^2/(2 W_nn)",
    formalise,
    export: EXPORT,
};

// The claim for z3 and SymPy, in pure algebra: with W_nt = 0 the normal relative velocity is
// u_n = -vn + w lam whatever friction does; each law's end, and the normal work there.
const EXPORT: Export = Export::Stated(
    Statement::new(
        Setting::new(Rod::Nothing, ExportLaw::Restitution),
        &[
            Check::holds(
                "Newton's end (u_n = e vn) is Poisson's (1 + e) lam_c, lam_c = vn/w",
                "ln = (1 + e)*vn/w",
            )
            .given(&["w*ln - vn = e*vn"]),
            Check::holds(
                "the energetic end (restitution work e^2 times the compression work vn^2/(2 w), after lam_c) is Poisson's too",
                "lg = (1 + e)*vn/w",
            )
            .given(&["w*(lg - vn/w)^2/2 = e^2*vn^2/(2*w)", "lg >= vn/w"]),
            Check::holds(
                "the normal work at lam_f = (1 + e) vn/w is -(1 - e^2) vn^2/(2 w), never positive",
                "-vn*lf + w*lf^2/2 = -(1 - e^2)*vn^2/(2*w) and -vn*lf + w*lf^2/2 <= 0",
            )
            .given(&["lf = (1 + e)*vn/w"]),
        ],
    )
    .at(&[])
    .given(&["w > 0", "vn > 0", "0 <= e", "e <= 1"]),
);

fn formalise(_paper: &Paper) -> Formalised {
    let (w, vn, e) = (sym("w"), sym("vn"), sym("e"));
    let lam_c = vn.clone() / &w;
    let lam_f = (one() + &e) * &lam_c;
    let s = sym("s");
    // e = 2s/(1+s^2), s >= 0, runs over exactly [0, 1]; 1 - e^2 = ((1-s)(1+s))^2/(1+s^2)^2.
    let e_of_s = k(2, 1) * &s / (one() + &sq(&s));
    let one_s2 = sum([pc(1, 1), PosExpr::Square(s.clone())]);
    let normal_work = -(vn.clone() * &lam_f) + &(w.clone() * &sq(&lam_f) / &k(2, 1));
    proved(
        "One contact between planar rigid bodies, with Coulomb friction mu >= 0 and a contact \
         matrix W with W_nt = 0 (W_nn = w > 0), the bodies approaching at vn > 0, 0 <= e <= 1. The \
         normal relative velocity is u_n = -vn + w lam whatever the tangential impulse does, since \
         du_n = w dlam + W_nt dtau (a step argued by hand from the definition of W, not \
         machine-checked). Compression ends at lam_c = vn/w. Newton's law ends where u_n = e vn, \
         Poisson's at (1 + e) lam_c, Stronge's where the restitution work w (lam - lam_c)^2/2 is e^2 \
         times the compression work vn^2/(2w); u_n and the restitution work increase with lam, so \
         each end is unique, and all three are lam_f = (1 + e) vn/w. The normal work there is \
         -(1 - e^2) vn^2/(2w) <= 0; friction's work is <= 0 (Coulomb's force opposes the slip: \
         u_t dtau = -mu |u_t| dlam sliding, 0 sticking; argued by hand, not machine-checked), so the \
         kinetic energy never rises. rodimpact's general solver gives exactly the paper's routes on \
         every scene of the family (property tests).",
        "with W_nt = 0 every law ends at lam_f = (1 + e) vn/w, where the normal work is -(1 - e^2) vn^2/(2w) <= 0",
        vec![
            id(
                "Newton's law: u_n = -vn + w lam at lam = (1 + e) vn/w equals e vn",
                n("u_n", -vn.clone() + &(w.clone() * &lam_f)),
                e.clone() * &vn,
            ),
            id(
                "Stronge's law: the restitution work w (lam_f - lam_c)^2/2 equals e^2 times the compression work vn^2/(2w)",
                n("W_r", w.clone() * &sq(&(lam_f.clone() - &lam_c)) / &k(2, 1)),
                sq(&e) * &sq(&vn) / &(k(2, 1) * &w),
            ),
            id(
                "the normal work -vn lam_f + w lam_f^2/2 = -(1 - e^2) vn^2/(2w)",
                n("W_n", normal_work.clone()),
                -((one() - &sq(&e)) * &sq(&vn) / &(k(2, 1) * &w)),
            ),
            positive(
                "-(normal work) >= 0 for e in [0, 1] (e = 2s/(1+s^2), s >= 0)",
                -normal_work,
                false,
                &[("e", e_of_s)],
                &["w", "vn"],
                &["s"],
                quot(
                    prod([
                        PosExpr::Square((one() - &s) * &(one() + &s)),
                        ps("vn"),
                        ps("vn"),
                    ]),
                    prod([pc(2, 1), one_s2.clone(), one_s2, ps("w")]),
                ),
            ),
        ],
    )
}
