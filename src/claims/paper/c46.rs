use crate::claims::dsl::*;

pub(super) const ENTRY: Entry = Entry {
    id: "C46",
    location: "§inhomogeneous",
    group: Group::Inhomogeneous,
    statement: "A symmetric mass distribution puts the CM at the centre",
    formalise,
    export: EXPORT,
};

const EXPORT: Export = Export::Unstated(
    "an integral over a symmetric mass density (the centre of mass), not a statement about finitely many reals",
);

fn formalise(_paper: &Paper) -> Formalised {
    let even = [("c0", 0), ("c2", 2), ("c4", 4), ("c6", 6)];
    let with_odd = [("c0", 0), ("c1", 1), ("c2", 2)];
    Formalised {
        formal: "A mass distribution on [-l, l] symmetric about the centre (dm(-y) = dm(y)) has first \
                 moment integral y dm = 0, since y is odd, so its CM is the centre. Checked exactly for \
                 the even polynomial densities c0 + c2 y^2 + c4 y^4 + c6 y^6 with arbitrary \
                 coefficients; the general argument (odd integrand) is stated, not machine-checked. An \
                 odd term c1 y moves the first moment to 2 c1 l^3/3, so symmetry is what is used."
            .into(),
        reason: "the first moment of an even density over [-l, l] is 0 (odd integrand); exact for the even polynomial family".into(),
        decision: Decision::Proved(vec![
            integral(
                "even density c0 + c2 y^2 + c4 y^4 + c6 y^6: first moment over [-l, l] is 0",
                density(&even),
                1,
                whole_rod(),
                k(0, 1),
            ),
            integral(
                "contrast: with an odd term, c0 + c1 y + c2 y^2 has first moment 2 c1 l^3/3",
                density(&with_odd),
                1,
                whole_rod(),
                symmetric_moment(&with_odd, 1),
            ),
        ]),
    }
}
